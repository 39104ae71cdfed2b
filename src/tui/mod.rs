//! The interactive lab (ratatui + crossterm) and its headless twin. `app` holds the
//! state, `keys` the one key table, `view` draws; this module only wires a real
//! terminal to them: events in, frames out, the terminal restored on every exit
//! (quit, error, panic, and SIGINT, SIGTERM, SIGHUP or SIGQUIT from outside), and
//! given back while Ctrl-Z holds the app stopped.

pub mod app;
pub mod canvas;
pub mod chart;
pub mod component;
pub mod hide;
pub mod interact;
pub mod jobs;
pub mod keys;
pub mod layer;
pub mod layout;
pub mod line;
pub mod look;
pub mod plot;
pub mod screen;
pub mod theme;
pub mod view;
pub mod view_cache;
pub mod vocabulary;

use std::io::{self, Write};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc::{self, Receiver, RecvTimeoutError, Sender};
use std::sync::{Mutex, PoisonError};
use std::time::{Duration, Instant};

use ratatui::crossterm::event::{
    self, DisableMouseCapture, EnableMouseCapture, Event, KeyCode, KeyEvent, KeyEventKind,
    KeyModifiers, MouseButton, MouseEvent, MouseEventKind,
};
use ratatui::crossterm::{cursor, execute};

use app::{Action, App, FPS};
use jobs::Notice;
use screen::Screen;
use theme::{Glyphs, Theme, ThemeChoice};
use view::video_image::{self, Switch};

/// The dark theme, or the monochrome one under NO_COLOR (any value), without asking
/// the terminal anything.
pub fn theme(ascii: bool) -> Theme {
    Theme::new(Glyphs::new(ascii), look::no_color())
}

fn set_mouse(on: bool) {
    let mut out = io::stdout();
    let _ = if on {
        execute!(out, EnableMouseCapture)
    } else {
        execute!(out, DisableMouseCapture)
    };
    let _ = out.flush();
}

/// Whether the terminal is ours (raw, alternate screen, cursor hidden) right now.
static ACTIVE: AtomicBool = AtomicBool::new(false);

/// Puts the terminal back as it was: mouse off, raw mode off, main screen, cursor shown.
fn restore() {
    ACTIVE.store(false, Ordering::SeqCst);
    set_mouse(false);
    ratatui::restore();
    let mut out = io::stdout();
    let _ = execute!(out, cursor::Show);
    let _ = out.flush();
}

/// Restores the terminal and exits with 128 + the signal's number, as a shell reports
/// a process ended by it: the app's listener of the ending signals (`signals`). In raw
/// mode the terminal sends no signals for keys (Ctrl-C is a key the app reads), so
/// these come from `kill`, a closed terminal (SIGHUP) or a service manager. It holds
/// the stdout lock from the first write on, so the event loop cannot draw a frame onto
/// the restored screen; the app is the last thing the process does.
fn restore_and_exit(signal: i32) {
    let stdout = io::stdout();
    let _no_more_frames = stdout.lock();
    if ACTIVE.load(Ordering::SeqCst) {
        restore();
    }
    std::process::exit(128 + signal);
}

/// Ctrl-Z: in raw mode the terminal sends no SIGTSTP for it, so the app reads the key
/// and suspends itself as a shell's job: the terminal back as it was, then stopped
/// until `fg`.
fn is_suspend(event: &Event) -> bool {
    matches!(event, Event::Key(k) if k.kind == KeyEventKind::Press
        && k.code == KeyCode::Char('z')
        && k.modifiers.contains(KeyModifiers::CONTROL))
}

/// Restores the terminal, stops the process (SIGTSTP's default action, as Ctrl-Z does
/// to any job), and when the shell continues it (`fg`, SIGCONT) takes the terminal
/// again and clears it, so the next frame is drawn whole.
#[cfg(unix)]
fn suspend(terminal: &mut ratatui::DefaultTerminal, mouse: bool) -> io::Result<()> {
    use ratatui::crossterm::terminal::{EnterAlternateScreen, enable_raw_mode};
    restore();
    signal_hook::low_level::raise(signal_hook::consts::SIGTSTP)?;
    // Here again after `fg`.
    ACTIVE.store(true, Ordering::SeqCst);
    enable_raw_mode()?;
    execute!(io::stdout(), EnterAlternateScreen, cursor::Hide)?;
    set_mouse(mouse);
    // Not `clear()`: it asks the terminal for the cursor, whose answer the input
    // thread would read. A resize to the present size (it may have changed meanwhile)
    // clears the screen and the back buffer without asking.
    let size = terminal.size()?;
    terminal.resize(ratatui::layout::Rect::new(0, 0, size.width, size.height))
}

#[cfg(not(unix))]
fn suspend(_: &mut ratatui::DefaultTerminal, _: bool) -> io::Result<()> {
    Ok(())
}

/// Runs the app on the real terminal until the user quits.
pub fn run(mut app: App, ascii: bool, choice: ThemeChoice) -> io::Result<()> {
    // Asked before the terminal is ours (the query takes raw mode for itself).
    let theme = Theme::with(Glyphs::new(ascii), look::detect(choice));
    let switch = Switch::from_env().map_err(|e| io::Error::new(io::ErrorKind::InvalidInput, e))?;
    // Before the terminal changes, so that no moment is left unguarded.
    crate::signals::on_signal(restore_and_exit)?;
    ACTIVE.store(true, Ordering::SeqCst);
    let mut terminal = match ratatui::try_init() {
        Ok(t) => t,
        Err(e) => {
            restore();
            return Err(e);
        }
    };
    // ratatui's hook restores raw mode and the screen; ours also turns the mouse off
    // first and shows the cursor.
    let ratatui_hook = std::panic::take_hook();
    std::panic::set_hook(Box::new(move |info| {
        ACTIVE.store(false, Ordering::SeqCst);
        set_mouse(false);
        ratatui_hook(info);
        let _ = execute!(io::stdout(), cursor::Show);
    }));
    if std::env::var_os("GROOVELAB_TEST_PANIC").is_some() {
        terminal.draw(|f| screen::draw(&app, f.area(), f.buffer_mut(), &theme))?;
        panic!("GROOVELAB_TEST_PANIC is set: panicking to test that the terminal is restored");
    }
    // Once, on the real terminal, before its events are read (bounded by a timeout).
    let picker = video_image::detect(switch);
    set_mouse(app.mouse());
    let result = event_loop(&mut terminal, &mut app, &theme, picker);
    restore();
    result
}

/// What wakes the event loop: a terminal event, or a job that finished or moved on.
enum Incoming {
    Terminal(Event),
    /// Reading the terminal failed: the app ends with this error.
    Failed(io::Error),
    Job(Notice),
    /// The video's picture is ready: draw again.
    Picture,
}

/// Starts the thread that reads terminal events (blocked, no CPU, until one comes)
/// into the event loop's channel, and points the lab's jobs at the same channel:
/// keys and job results arrive in one queue, and the loop sleeps until either comes.
fn inputs(app: &App) -> io::Result<(Sender<Incoming>, Receiver<Incoming>)> {
    let (tx, rx) = mpsc::channel();
    let wake = tx.clone();
    let jobs = Mutex::new(tx.clone());
    app.listen(move |notice| {
        let _ = jobs
            .lock()
            .unwrap_or_else(PoisonError::into_inner)
            .send(Incoming::Job(notice));
    });
    std::thread::Builder::new()
        .name("groovelab-terminal".into())
        .spawn(move || {
            loop {
                let input = match event::read() {
                    Ok(e) => Incoming::Terminal(e),
                    Err(e) => Incoming::Failed(e),
                };
                let failed = matches!(input, Incoming::Failed(_));
                if tx.send(input).is_err() || failed {
                    break;
                }
            }
        })?;
    Ok((wake, rx))
}

fn event_loop(
    terminal: &mut ratatui::DefaultTerminal,
    app: &mut App,
    theme: &Theme,
    picker: Option<ratatui_image::picker::Picker>,
) -> io::Result<()> {
    let frame = Duration::from_secs_f64(1.0 / FPS);
    let (wake, rx) = inputs(app)?;
    let mut screen = Screen::with_graphics(
        picker,
        Box::new(move || {
            let _ = wake.send(Incoming::Picture);
        }),
    );
    let mut dirty = true;
    let mut last_tick = Instant::now();
    let mut mouse = app.mouse();
    while !app.quitting() {
        if dirty {
            // Laid out once, before drawing: the drawing, the keys (a popup's scroll
            // limit) and the mouse read this one frame.
            terminal.draw(|f| {
                screen.prepare(app, f.area(), theme);
                screen.render(app, f.buffer_mut(), theme);
            })?;
            if let Some(frame) = screen.frame() {
                app.laid_out(frame.scroll_max);
            }
            dirty = false;
        }
        // Paused: sleep until a key or a job's result comes (no CPU). Playing: wake for
        // the next frame too; the time step comes from the clock, not from how fast we
        // drew.
        let first = if app.playing {
            match rx.recv_timeout(frame.saturating_sub(last_tick.elapsed())) {
                Ok(input) => Some(input),
                Err(RecvTimeoutError::Timeout) => None,
                Err(RecvTimeoutError::Disconnected) => return Err(io::ErrorKind::BrokenPipe.into()),
            }
        } else {
            Some(
                rx.recv()
                    .map_err(|_| io::Error::from(io::ErrorKind::BrokenPipe))?,
            )
        };
        // Everything that came meanwhile, before the next frame: one frame for many
        // job wakes.
        for input in first.into_iter().chain(rx.try_iter()) {
            let was_playing = app.playing;
            dirty |= match input {
                Incoming::Terminal(e) if is_suspend(&e) => {
                    suspend(terminal, app.mouse())?;
                    // The stopped time is not played through.
                    last_tick = Instant::now();
                    true
                }
                Incoming::Terminal(e) => {
                    // A click after a key of this batch hits the frame that key made.
                    if dirty
                        && matches!(e, Event::Mouse(_))
                        && let Some(area) = screen.frame().map(|f| f.area)
                    {
                        screen.prepare(app, area, theme);
                    }
                    on_terminal(app, &screen, e)
                }
                Incoming::Failed(e) => return Err(e),
                Incoming::Job(notice) => app.on_job(notice),
                Incoming::Picture => true,
            };
            if app.playing && !was_playing {
                last_tick = Instant::now();
            }
            if app.quitting() {
                return Ok(());
            }
        }
        if app.mouse() != mouse {
            mouse = app.mouse();
            set_mouse(mouse);
        }
        if app.playing && last_tick.elapsed() >= frame {
            let now = Instant::now();
            app.tick((now - last_tick).as_secs_f64());
            last_tick = now;
            dirty = true;
        }
    }
    Ok(())
}

/// What a terminal event does (the mouse hit-tests the frame on screen); true if the
/// screen needs a redraw.
fn on_terminal(app: &mut App, screen: &Screen, event: Event) -> bool {
    match event {
        Event::Key(key) if key.kind == KeyEventKind::Press => {
            match keys::action(&app.mode(), key) {
                Some(action) => {
                    said_no_key_gone(app);
                    app.apply(action);
                    true
                }
                None => no_such_key(app, key),
            }
        }
        Event::Mouse(m) if app.mouse() => on_mouse_in(app, screen, m),
        Event::Resize(..) => true,
        _ => false,
    }
}

/// What the mouse does: over an open popup, only the popup's part (a click on a
/// preset selects it and a click on the selected one loads it, a click on an answer
/// answers, the wheel moves through the list or scrolls); on the main screen a click
/// or drag on the chart seeks there, a click on a parameter selects it, the wheel over
/// one nudges it. True if anything changed.
pub fn on_mouse(app: &mut App, area: ratatui::layout::Rect, theme: &Theme, m: MouseEvent) -> bool {
    let mut screen = Screen::default();
    screen.prepare(app, area, theme);
    on_mouse_in(app, &screen, m)
}

/// [`on_mouse`] over the frame `screen` prepared last (the one on the terminal).
pub fn on_mouse_in(app: &mut App, screen: &Screen, m: MouseEvent) -> bool {
    let Some(frame) = screen.frame() else {
        return false;
    };
    if app.layers().is_empty() {
        on_mouse_main(app, screen, m)
    } else {
        app.mouse_on_layers(m, frame.area)
    }
}

fn on_mouse_main(app: &mut App, screen: &Screen, m: MouseEvent) -> bool {
    let seek = match m.kind {
        MouseEventKind::Down(MouseButton::Left) | MouseEventKind::Drag(MouseButton::Left) => {
            screen.chart_time_at(app, m.column, m.row)
        }
        _ => None,
    };
    if let Some(t) = seek {
        app.seek(t);
        return true;
    }
    let Some(frame) = screen.frame() else {
        return false;
    };
    // The views take their mouse events (the wheel over the chart zooms its time
    // axis around the pointer's time, a click on the video's picture seeds its
    // tracking there).
    let pointer = screen.pointer_at(app, m.column, m.row);
    if app.mouse_on_view(m, frame.area, pointer) {
        return true;
    }
    let Some(panels) = frame.panels else {
        return false;
    };
    let hit = view::param_at(panels.params, app.selected(), m.column, m.row);
    let action = match (m.kind, hit) {
        (MouseEventKind::Down(MouseButton::Left), Some(i)) => Action::Select(i),
        (MouseEventKind::ScrollUp, Some(i)) => Action::ScrollParam(i, true),
        (MouseEventKind::ScrollDown, Some(i)) => Action::ScrollParam(i, false),
        _ => return false,
    };
    app.apply(action);
    true
}

/// Replays `keys` on `app` as the terminal would.
pub fn replay(app: &mut App, keys: &[KeyEvent]) {
    for &key in keys {
        if app.quitting() {
            break;
        }
        match keys::action(&app.mode(), key) {
            Some(action) => {
                said_no_key_gone(app);
                app.apply(action);
            }
            None => {
                no_such_key(app, key);
            }
        }
    }
}

/// A key that means nothing here says so on the status line, with where the keys
/// are listed (a new user pressing `j` or F5 saw nothing happen); true if it did.
/// Not while a line is typed: the line's editor takes or drops keys itself.
fn no_such_key(app: &mut App, key: KeyEvent) -> bool {
    use ratatui::crossterm::event::{KeyCode, KeyModifiers};
    if app.mode().is_typing() || matches!(key.code, KeyCode::Modifier(_)) {
        return false;
    }
    let name = match key.code {
        KeyCode::Char(c) if key.modifiers.contains(KeyModifiers::CONTROL) => format!("Ctrl-{c}"),
        KeyCode::Char(c) if key.modifiers.contains(KeyModifiers::ALT) => format!("Alt-{c}"),
        code => code.to_string(),
    };
    app.status = app::Status::Info(format!("{NO_KEY}{name} here: ? lists the keys"));
    true
}

/// How [`no_such_key`]'s message begins.
const NO_KEY: &str = "no key ";

/// [`no_such_key`]'s message cleared once a key that means something is pressed: it
/// was about that one key.
fn said_no_key_gone(app: &mut App) {
    if matches!(&app.status, app::Status::Info(m) if m.starts_with(NO_KEY)) {
        app.status = app::Status::None;
    }
}

/// Replays `keys` on `app` as `render`, the headless twin, does: before each key and at
/// the end, every analysis already asked for finishes and its result is taken in, as if
/// the user waited for the screen to settle. A key that acts on a result (`a` applies the
/// fit, `W` exports the Methods diagram) then finds it, and the same keys give the same
/// bytes on every run. The interactive app never waits ([`replay`] is its keys).
pub fn replay_settled(app: &mut App, keys: &[KeyEvent]) {
    for &key in keys {
        app.wait();
        replay(app, &[key]);
    }
    app.wait();
}
