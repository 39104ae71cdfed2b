//! The app's UI state and what every action does to it: selection, popups, playback,
//! which view is shown. Everything computed about the scene is asked of the [`Lab`].
//! No terminal here: keys arrive as [`Action`]s, so the whole app is testable without one.

use std::path::PathBuf;
use std::sync::LazyLock;

use crate::input::params::{Key, PARAMS, Param};
use crate::input::preset::Preset;
use crate::input::units::{parse_quantity, show, significant};
use crate::lab::{Lab, OVERLAY_LEVELS, SaveError};
use crate::methods::Method;

/// The rows of the parameters panel, top to bottom: the table's rows that have steps.
pub static ROWS: LazyLock<Vec<&'static Param>> =
    LazyLock::new(|| PARAMS.iter().filter(|p| p.steps.is_some()).collect());

/// Which ball the velocity chart shows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ChartBall {
    Left,
    Right,
    Both,
}

/// What the middle of the screen shows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum View {
    Charts,
    /// Work–precision of the methods instead of the charts.
    Methods,
    /// The regime map and the paper's figure instead of the charts.
    Map,
}

/// A popup or prompt over the main screen, which takes the keys while open.
#[derive(Clone, Debug, PartialEq)]
pub enum Mode {
    Normal,
    Help,
    /// Preset picker with the highlighted row.
    Picker(usize),
    /// Typing a value for the selected parameter.
    Edit(String),
    /// Typing a name to save the scene as a user preset.
    SaveName(String),
    /// The file exists: overwrite it?
    ConfirmOverwrite(String),
}

/// Everything a key can do.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Action {
    Quit,
    Up,
    Down,
    NextParam,
    Increase,
    Decrease,
    IncreaseCoarse,
    DecreaseCoarse,
    Edit,
    Confirm,
    Cancel,
    Backspace,
    Type(char),
    PlayPause,
    Faster,
    Slower,
    StepForward,
    StepBack,
    Start,
    End,
    Restart,
    Presets,
    Save,
    Help,
    SwitchBall,
    TogglePositions,
    /// The energy chart instead of the velocities.
    ToggleEnergy,
    /// The span key: auto, ×2, ×½ (see [`crate::lab::SpanEnd`]).
    CycleSpan,
    NextEvent,
    PrevEvent,
    /// Pin the current run for an A/B comparison, or unpin it.
    TogglePin,
    ToggleMethods,
    ToggleMap,
    ToggleFit,
    FitStartEarlier,
    FitStartLater,
    FitEndEarlier,
    FitEndLater,
    CycleOverlay,
    OverlayFiner,
    OverlayCoarser,
    ToggleMouse,
    Select(usize),
    /// Scroll on parameter row `i`: up increases.
    ScrollParam(usize, bool),
}

/// Playback speeds (simulated seconds per real second); slow motion by default, as
/// the whole event lasts under a second.
pub const SPEEDS: [f64; 7] = [1.0 / 32.0, 1.0 / 16.0, 1.0 / 8.0, 0.25, 0.5, 1.0, 2.0];
const DEFAULT_SPEED: usize = 3;

/// Frames per second while animating.
pub const FPS: f64 = 30.0;

/// Status line contents.
#[derive(Clone, Debug, PartialEq)]
pub enum Status {
    None,
    Info(String),
    Error(String),
}

/// The presets the picker offers and the folder the app saves to.
#[derive(Clone, Debug, PartialEq)]
pub struct Library {
    pub dir: Option<PathBuf>,
    pub presets: Vec<Preset>,
}

impl Library {
    /// Built-in presets and those in `dir`, where the app also saves.
    pub fn at(dir: Option<PathBuf>) -> Library {
        let presets = Preset::all_in(dir.as_deref()).0;
        Library { dir, presets }
    }

    /// The user's preset folder ([`crate::input::preset::user_dir`]).
    pub fn user() -> Library {
        Library::at(crate::input::preset::user_dir())
    }
}

#[derive(Clone, Debug)]
pub struct App {
    pub lab: Lab,
    /// Simulated time shown, s.
    pub t: f64,
    pub playing: bool,
    pub speed: usize,
    pub selected: usize,
    pub mode: Mode,
    pub chart_ball: ChartBall,
    pub show_positions: bool,
    /// The energy chart (instead of velocities or positions).
    pub show_energy: bool,
    pub mouse: bool,
    pub status: Status,
    pub quit: bool,
    pub library: Library,
    pub view: View,
    /// The Fit panel instead of the info panel.
    pub fit_view: bool,
    /// The overlay's level when one is switched on.
    pub overlay_level: u8,
}

impl App {
    pub fn new(lab: Lab, library: Library) -> App {
        App {
            t: lab.solution.t_start,
            lab,
            playing: false,
            speed: DEFAULT_SPEED,
            selected: 1,
            mode: Mode::Normal,
            chart_ball: ChartBall::Left,
            show_positions: false,
            show_energy: false,
            mouse: true,
            status: Status::None,
            quit: false,
            library,
            view: View::Charts,
            fit_view: false,
            overlay_level: 2,
        }
    }

    pub fn speed_factor(&self) -> f64 {
        SPEEDS[self.speed]
    }

    /// Sets a parameter if the scene stays valid; otherwise says why in the status line.
    pub fn set_value(&mut self, key: Key, value: f64) {
        match self.lab.set(key, value) {
            Ok(()) => {
                let sol = &self.lab.solution;
                self.t = self.t.clamp(sol.t_start, sol.t_end);
                let label = ROWS
                    .iter()
                    .find(|p| p.key == key)
                    .map_or(key.name(), |p| p.label);
                self.status = Status::Info(format!(
                    "{label} = {}",
                    show(self.lab.value(key), key.dimension())
                ));
            }
            Err(e) => self.status = Status::Error(format!("not applied: {e}")),
        }
    }

    fn nudge(&mut self, up: bool, coarse: bool) {
        let p = ROWS[self.selected];
        let Some(steps) = p.steps else { return };
        let step = if coarse { steps.coarse } else { steps.fine };
        let current = self.lab.value(p.key);
        // Snap to the step grid so repeated presses give round numbers.
        let next = ((current / step).round() + if up { 1.0 } else { -1.0 }) * step;
        self.set_value(p.key, next);
    }

    /// How far one animation frame moves the simulated time.
    pub fn frame_step(&self) -> f64 {
        self.speed_factor() / FPS
    }

    /// The time one `.` (`later`) or `,` moves to: the next or previous measured frame
    /// when the preset carries measured data and there is one, else one animation frame.
    pub fn step_target(&self, later: bool) -> f64 {
        let (t0, t1) = (self.lab.solution.t_start, self.lab.solution.t_end);
        // Times within a nanosecond of the cursor are where it is, not a step away.
        let eps = 1e-9;
        let frame = self.lab.measured().and_then(|m| {
            if later {
                m.t.iter().copied().find(|&x| x > self.t + eps)
            } else {
                m.t.iter().rev().copied().find(|&x| x < self.t - eps)
            }
        });
        let t = frame.unwrap_or(if later {
            self.t + self.frame_step()
        } else {
            self.t - self.frame_step()
        });
        t.clamp(t0, t1)
    }

    /// The next (or previous) marked event's time in the span: impact, rolling, gliding,
    /// slipping, rest, T∞ (what the charts draw as lines).
    pub fn event_target(&self, later: bool) -> Option<f64> {
        let eps = 1e-9;
        let mut times = self
            .lab
            .solution
            .visible_events()
            .filter(|e| e.kind.label().is_some())
            .map(|e| e.t);
        if later {
            times.find(|&x| x > self.t + eps)
        } else {
            times.filter(|&x| x < self.t - eps).last()
        }
    }

    /// Moves the cursor to `t` (a click on the chart), paused.
    pub fn seek(&mut self, t: f64) {
        let sol = &self.lab.solution;
        self.playing = false;
        self.t = t.clamp(sol.t_start, sol.t_end);
    }

    /// Advances playback by `wall` real seconds; stops at the end.
    pub fn tick(&mut self, wall: f64) {
        if !self.playing {
            return;
        }
        self.t += wall * self.speed_factor();
        if self.t >= self.lab.solution.t_end {
            self.t = self.lab.solution.t_end;
            self.playing = false;
        }
    }

    pub fn apply(&mut self, action: Action) {
        if action == Action::Quit {
            // q (outside typing) and Ctrl-C quit from anywhere.
            self.quit = true;
            return;
        }
        match self.mode.clone() {
            Mode::Normal => self.apply_normal(action),
            // Any key closes the help.
            Mode::Help => self.mode = Mode::Normal,
            Mode::Picker(i) => self.apply_picker(i, action),
            Mode::Edit(text) => self.apply_text(text, action, TextTarget::Value),
            Mode::SaveName(text) => self.apply_text(text, action, TextTarget::Name),
            Mode::ConfirmOverwrite(name) => {
                self.mode = Mode::Normal;
                match action {
                    Action::Type('y' | 'Y') => self.save(&name, true),
                    _ => self.status = Status::Info("not saved".into()),
                }
            }
        }
    }

    fn apply_normal(&mut self, action: Action) {
        let n = ROWS.len();
        let (t0, t1) = (self.lab.solution.t_start, self.lab.solution.t_end);
        match action {
            Action::Quit | Action::Cancel => self.quit = true,
            Action::Up => self.selected = (self.selected + n - 1) % n,
            Action::Down | Action::NextParam => self.selected = (self.selected + 1) % n,
            Action::Increase => self.nudge(true, false),
            Action::Decrease => self.nudge(false, false),
            Action::IncreaseCoarse => self.nudge(true, true),
            Action::DecreaseCoarse => self.nudge(false, true),
            Action::Edit | Action::Confirm => self.mode = Mode::Edit(String::new()),
            Action::PlayPause => {
                if !self.playing && self.t >= t1 {
                    self.t = t0;
                }
                self.playing = !self.playing;
            }
            Action::Faster => self.speed = (self.speed + 1).min(SPEEDS.len() - 1),
            Action::Slower => self.speed = self.speed.saturating_sub(1),
            Action::StepForward | Action::StepBack => {
                self.playing = false;
                self.t = self.step_target(action == Action::StepForward);
            }
            Action::NextEvent | Action::PrevEvent => {
                self.playing = false;
                match self.event_target(action == Action::NextEvent) {
                    Some(t) => {
                        self.t = t;
                        let e = self
                            .lab
                            .solution
                            .visible_events()
                            .find(|e| e.t == t && e.kind.label().is_some());
                        let name = e.and_then(|e| e.kind.label()).unwrap_or("event");
                        self.status = Status::Info(format!("{name} at t = {t:.4} s"));
                    }
                    None => {
                        self.status = Status::Info(
                            if action == Action::NextEvent {
                                "no later event in the span"
                            } else {
                                "no earlier event in the span"
                            }
                            .into(),
                        )
                    }
                }
            }
            Action::CycleSpan => {
                let next = self.lab.span_end.next();
                match self.lab.set_span_end(next) {
                    Ok(()) => {
                        let sol = &self.lab.solution;
                        self.t = self.t.clamp(sol.t_start, sol.t_end);
                        self.status = Status::Info(format!(
                            "span {}: {:.3} … {:.3} s",
                            next.describe(),
                            sol.t_start,
                            sol.t_end
                        ));
                    }
                    Err(e) => self.status = Status::Error(format!("span not changed: {e}")),
                }
            }
            Action::ToggleEnergy => {
                self.show_energy = !self.show_energy;
                self.show_positions = false;
            }
            Action::TogglePin => {
                let pinned = self.lab.toggle_pin();
                self.status = Status::Info(if pinned {
                    "pinned this run: change a parameter to compare (P unpins)".into()
                } else {
                    "unpinned".into()
                });
            }
            Action::Start => self.t = t0,
            Action::End => {
                self.playing = false;
                self.t = t1;
            }
            Action::Restart => {
                self.t = t0;
                self.playing = true;
            }
            Action::Presets => {
                let i = self
                    .library
                    .presets
                    .iter()
                    .position(|p| p.name == self.lab.preset.name)
                    .unwrap_or(0);
                self.mode = Mode::Picker(i);
            }
            Action::Save => self.mode = Mode::SaveName(format!("my-{}", self.lab.preset.name)),
            Action::Help => self.mode = Mode::Help,
            Action::SwitchBall => {
                self.chart_ball = match self.chart_ball {
                    ChartBall::Left => ChartBall::Right,
                    ChartBall::Right => ChartBall::Both,
                    ChartBall::Both => ChartBall::Left,
                }
            }
            Action::TogglePositions => {
                self.show_positions = !self.show_positions;
                self.show_energy = false;
            }
            Action::ToggleMethods => self.toggle_view(View::Methods),
            Action::ToggleMap => self.toggle_view(View::Map),
            Action::ToggleFit => {
                self.fit_view = !self.fit_view;
                self.lab.want_fits(self.fit_view);
                if self.fit_view && self.lab.measured().is_none() {
                    self.status = Status::Error(format!(
                        "preset {} has no measured data to fit (the paper-b* presets have)",
                        self.lab.preset.name
                    ));
                }
            }
            Action::FitStartEarlier => self.move_window(false, false),
            Action::FitStartLater => self.move_window(false, true),
            Action::FitEndEarlier => self.move_window(true, false),
            Action::FitEndLater => self.move_window(true, true),
            Action::CycleOverlay => {
                let all = Method::TIME_STEPPING;
                let next = match self.lab.overlay_choice() {
                    None => Some(all[0]),
                    Some((m, _)) => all
                        .iter()
                        .position(|x| *x == m)
                        .and_then(|i| all.get(i + 1))
                        .copied(),
                };
                self.lab.set_overlay(next.map(|m| (m, self.overlay_level)));
                self.status = Status::Info(match next {
                    Some(m) => format!("overlay {}", m.name()),
                    None => "overlay off".into(),
                });
            }
            Action::OverlayFiner | Action::OverlayCoarser => {
                self.overlay_level = if action == Action::OverlayFiner {
                    (self.overlay_level + 1).min(OVERLAY_LEVELS - 1)
                } else {
                    self.overlay_level.saturating_sub(1)
                };
                if let Some((m, _)) = self.lab.overlay_choice() {
                    self.lab.set_overlay(Some((m, self.overlay_level)));
                }
            }
            Action::ToggleMouse => {
                self.mouse = !self.mouse;
                self.status = Status::Info(format!(
                    "mouse {}",
                    if self.mouse {
                        "on"
                    } else {
                        "off (terminal selection works)"
                    }
                ));
            }
            Action::Select(i) if i < n => self.selected = i,
            Action::ScrollParam(i, up) if i < n => {
                self.selected = i;
                self.nudge(up, false);
            }
            Action::Select(_) | Action::ScrollParam(..) | Action::Backspace | Action::Type(_) => {}
        }
    }

    fn toggle_view(&mut self, view: View) {
        self.view = if self.view == view {
            View::Charts
        } else {
            view
        };
        self.lab.want_methods(self.view == View::Methods);
    }

    fn move_window(&mut self, end: bool, later: bool) {
        if let Err(e) = self.lab.move_fit_window(end, later) {
            self.status = Status::Error(e);
        }
    }

    fn apply_picker(&mut self, i: usize, action: Action) {
        let n = self.library.presets.len().max(1);
        match action {
            Action::Up => self.mode = Mode::Picker((i + n - 1) % n),
            Action::Down | Action::NextParam => self.mode = Mode::Picker((i + 1) % n),
            Action::Confirm | Action::Edit => {
                self.mode = Mode::Normal;
                if let Some(p) = self.library.presets.get(i).cloned() {
                    let (name, description) = (p.name.clone(), p.description.clone());
                    match self.lab.load_preset(p) {
                        Ok(()) => {
                            self.t = self.lab.solution.t_start;
                            self.status = Status::Info(description);
                        }
                        Err(e) => self.status = Status::Error(format!("preset {name}: {e}")),
                    }
                }
            }
            Action::Cancel | Action::Presets => self.mode = Mode::Normal,
            _ => {}
        }
    }

    fn apply_text(&mut self, mut text: String, action: Action, target: TextTarget) {
        let reopen = |text: String| match target {
            TextTarget::Value => Mode::Edit(text),
            TextTarget::Name => Mode::SaveName(text),
        };
        match action {
            Action::Type(c) => {
                text.push(c);
                self.mode = reopen(text);
            }
            Action::Backspace => {
                text.pop();
                self.mode = reopen(text);
            }
            Action::Cancel => {
                self.mode = Mode::Normal;
                self.status = Status::Info("cancelled".into());
            }
            Action::Confirm | Action::Edit => {
                self.mode = Mode::Normal;
                match target {
                    TextTarget::Value => self.typed_value(&text),
                    TextTarget::Name => self.save(&text, false),
                }
            }
            _ => self.mode = reopen(text),
        }
    }

    fn typed_value(&mut self, text: &str) {
        let p = ROWS[self.selected];
        match parse_quantity(text, p.dim) {
            Ok(v) => self.set_value(p.key, v),
            Err(e) => self.status = Status::Error(format!("not applied: {} {e}", p.label)),
        }
    }

    /// Saves the scene as a user preset, asking before it replaces a file.
    fn save(&mut self, name: &str, overwrite: bool) {
        match self.lab.save(self.library.dir.as_deref(), name, overwrite) {
            Ok(path) => {
                self.library = Library::at(self.library.dir.clone());
                self.status = Status::Info(format!("saved {}", path.display()));
            }
            Err(SaveError::Exists(_)) => self.mode = Mode::ConfirmOverwrite(name.trim().into()),
            Err(e) => self.status = Status::Error(format!("not saved: {e}")),
        }
    }

    /// A one-line summary of playback for the status line.
    pub fn playback(&self) -> String {
        let speed = self.speed_factor();
        let speed = if speed < 1.0 {
            format!("1/{}", (1.0 / speed).round())
        } else {
            significant(speed, 2)
        };
        let sol = &self.lab.solution;
        format!(
            "t = {:.3} s of {:.3} … {:.3} s   {}  speed ×{speed}",
            self.t,
            sol.t_start,
            sol.t_end,
            if self.playing { "playing" } else { "paused" },
        )
    }
}

#[derive(Clone, Copy)]
enum TextTarget {
    Value,
    Name,
}
