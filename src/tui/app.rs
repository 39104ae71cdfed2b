//! The app: the lab, the layer stack (the main screen's views at the bottom, the
//! popups over them) and the job pool, and what is the whole app's: playback, the
//! parameter selected, the status line. Everything computed about the scene is asked
//! of the [`Lab`]. No terminal here: keys arrive as [`Action`]s, so the whole app is
//! testable without one. A key goes to the popups first, then to the views
//! ([`super::layer::main`], each owning its state, keys and jobs), then to the app's
//! own keys (`normal`); what the popups and views ask of the app is done in `prompts`.

mod access;
pub mod export;
mod normal;
mod playback;
mod predict;
mod prompts;
mod stops;
mod video;

use std::path::PathBuf;
use std::sync::Arc;

use crate::lab::Lab;
use crate::lab::jobs::Pool;
use crate::settings::params::Key;
use crate::settings::spec::SceneError;
use crate::settings::units::{Dimension, show, show_below};

pub use super::vocabulary::{
    Action, ChartBall, Export, FPS, Field, Library, Mode, Prediction, SPEEDS, Status, View,
};
pub use stops::{EventStop, event_stops};

use super::interact::Input;
use super::jobs::{ExportRun, Jobs, Notice};
use super::layer::main::{PaneCx, Pointer};
use super::layer::{Compositor, Histories, Layer, LayerCx};
use super::vocabulary::{DEFAULT_SPEED, Handled};
use ratatui::crossterm::event::MouseEvent;
use ratatui::layout::Rect;

pub use super::layer::main::params::ROWS;

/// The app: the lab, the layers (the main screen's views, the popups open over them)
/// and the jobs; playback, the parameter selected and the status line. The lab, the time, playing and the status line
/// are open to the edges (the runner, `render` and the tests set scenes, times and
/// read messages); everything else is read through accessors and changed by actions.
#[derive(Clone, Debug)]
pub struct App {
    pub lab: Lab,
    /// Simulated time shown, s.
    pub t: f64,
    pub playing: bool,
    speed: usize,
    /// The main screen's views at the bottom, the popups open over them, top last:
    /// they take input first.
    layers: Compositor,
    mouse: bool,
    pub status: Status,
    quit: bool,
    /// `q` pressed once with changes not saved: the next `q` quits (any other key
    /// takes it back).
    quit_asked: bool,
    /// The scene when it was last saved as a preset (`s`) or written with its run
    /// (`w`): changes made after that are lost on quitting.
    kept: Option<crate::physics::scene::Scene>,
    library: Library,
    /// The file being written (its job).
    export: ExportRun,
    /// The app's jobs on its worker pool.
    jobs: Jobs,
    /// Where `w`/`W` write a bare file name.
    export_dir: PathBuf,
    /// What the screen hides while b is hidden (a class predicts from the picture
    /// alone): the one rule.
    hide: super::hide::Hide,
    /// The last prediction (predict, observe, explain).
    prediction: Option<Prediction>,
    /// What was typed into each kind of prompt this session (↑/↓ bring it back).
    histories: Histories,
    /// False in `render`, the headless twin: a screen dump writes no files, so the
    /// export and save keys say what they would write and write nothing.
    writes_files: bool,
}

/// What the export and save keys say where files are not written.
pub const NO_FILES: &str = "render writes no files";

impl App {
    /// The app on a worker pool of its own.
    pub fn new(lab: Lab, library: Library) -> App {
        App::with_pool(lab, library, Arc::new(Pool::default()))
    }

    /// The app whose analyses run on `pool`.
    pub fn with_pool(lab: Lab, library: Library, pool: Arc<Pool>) -> App {
        App {
            t: lab.solution.t_start,
            lab,
            playing: false,
            speed: DEFAULT_SPEED,
            layers: Compositor::default(),
            mouse: true,
            status: Status::None,
            quit: false,
            quit_asked: false,
            kept: None,
            library,
            export: ExportRun::default(),
            jobs: Jobs::new(pool),
            export_dir: PathBuf::from("."),
            hide: super::hide::Hide::default(),
            prediction: None,
            histories: Histories::default(),
            writes_files: true,
        }
    }

    /// What the screen laid out for the next frame that the keys need: how far the
    /// open popup scrolls at this size.
    pub fn laid_out(&mut self, scroll_max: usize) {
        self.layers.laid_out(scroll_max);
    }

    /// The popups open, top last (the screen draws them over the panels).
    pub fn layers(&self) -> &Compositor {
        &self.layers
    }

    /// What is open, as plain data: [`Mode::Normal`] if no popup is.
    pub fn mode(&self) -> Mode {
        self.layers.top().map_or(Mode::Normal, Layer::mode)
    }

    /// The line of the value prompt while a value is typed (on the status line and
    /// in the selected parameter's row).
    pub fn editing(&self) -> Option<&Field> {
        match self.layers.top() {
            Some(Layer::Prompt(p)) => p.editing_value(),
            _ => None,
        }
    }

    /// Opens `layer` over the screen.
    fn open(&mut self, layer: Layer) {
        self.layers.push(layer);
    }

    /// Sets a parameter if the scene stays valid; otherwise says why in the status line.
    pub fn set_value(&mut self, key: Key, value: f64) {
        let edits = self.lab.settings().edits().len();
        match self.lab.set(key, value) {
            Ok(()) => {
                self.applied(key);
                // The same value again is no change (and nothing for `u` to undo).
                if let Status::Info(done) = &self.status
                    && self.lab.settings().edits().len() == edits
                {
                    self.status = Status::Info(format!("{done} (unchanged)"));
                }
            }
            // A smaller R that the groove's b no longer fits: b is what to change first.
            Err(SceneError::OutOfRange {
                key: Key::Width, ..
            }) if key == Key::Radius => {
                self.status = Status::Error(format!(
                    "not applied: R = {} needs b < 2R = {}, and b = {}: set b first",
                    show(value, Dimension::Length),
                    show(2.0 * value, Dimension::Length),
                    self.shown_value(Key::Width)
                ));
            }
            Err(e) => self.status = Status::Error(format!("not applied: {e}")),
        }
        self.sync_jobs();
    }

    /// What the screen hides now: b if hidden, and what follows from it while a
    /// prediction is asked or its outcome has not shown yet (the one rule every view
    /// asks).
    pub fn hidden(&self) -> super::hide::Hide {
        let made = self
            .prediction
            .as_ref()
            .filter(|p| p.scene == self.lab.scene);
        let asking = matches!(self.layers.top(), Some(Layer::Question(_)));
        let pending = asking || made.is_some_and(|p| self.t < p.reveal_at);
        self.hide.with_pending(pending)
    }

    /// A parameter's current value as the status line shows it (b hidden if it is).
    pub(super) fn shown_value(&self, key: Key) -> String {
        if self.hidden().value(key) {
            "(hidden)".to_string()
        } else if key == Key::Width {
            let limit = 2.0 * self.lab.scene.radius;
            show_below(self.lab.value(key), limit, key.dimension())
        } else {
            show(self.lab.value(key), key.dimension()).to_string()
        }
    }

    /// After the lab took a new value of `key`: the cursor kept in the span, the new
    /// value in the status line.
    fn applied(&mut self, key: Key) {
        let sol = &self.lab.solution;
        self.t = self.t.clamp(sol.t_start, sol.t_end);
        let label = key.param().screen_label();
        self.status = Status::Info(format!("{label} = {}", self.shown_value(key)));
        let s = &self.lab.scene;
        if key == Key::V0 && s.left.v0 == s.right.v0 {
            self.status = Status::Info(format!(
                "v0 of both balls = {}",
                show(s.left.v0, Dimension::Speed)
            ));
        }
    }

    /// What the views need of the app to handle an input or ask for their work.
    fn pane_cx(&mut self, pointer: Pointer) -> (&mut super::layer::main::MainScreen, PaneCx<'_>) {
        let span = self.chart_span();
        let derived = self.hidden().derived();
        let main = self.layers.main_mut();
        let video = main.get::<super::layer::main::video::VideoRun>().data();
        let cx = PaneCx {
            lab: &mut self.lab,
            jobs: &self.jobs,
            t: self.t,
            span,
            derived,
            shown: main.shown(),
            charts_shown: main.charts_shown(),
            pointer,
            video,
        };
        (main, cx)
    }

    /// A component's answer: true if it took the input (a message goes to the status
    /// line, what a popup asks is done).
    fn handled(&mut self, answer: Handled) -> bool {
        match answer {
            Handled::Ignored => return false,
            Handled::Consumed => {}
            Handled::Say(message) => self.status = Status::Info(message),
            Handled::Refused(message) => self.status = Status::Error(message),
            Handled::Close(then) | Handled::Ask(then) => self.then(then),
        }
        true
    }

    /// A mouse event on the main screen offered to the views (the wheel over the
    /// chart zooms its time axis, a click on the video's picture seeds its tracking):
    /// `pointer` says what lies under it on the frame on screen. True if one took it.
    pub fn mouse_on_view(&mut self, m: MouseEvent, area: Rect, pointer: Pointer) -> bool {
        let (main, mut cx) = self.pane_cx(pointer);
        let answer = main.handle(&Input::Mouse(m, area), &mut cx);
        let took = self.handled(answer);
        self.settled();
        took
    }

    /// Offers `action` to the views, the one shown first; true if one took it.
    pub(super) fn offer(&mut self, action: Action) -> bool {
        let (main, mut cx) = self.pane_cx(Pointer::default());
        let answer = main.handle(&Input::Key(action), &mut cx);
        self.handled(answer)
    }

    /// Offers `input` to the popups open, top first; true if one took it (what it
    /// asks of the app done).
    fn offer_layers(&mut self, input: &Input) -> bool {
        let cx = LayerCx {
            presets: self.library.presets.len(),
            histories: &self.histories,
        };
        let answer = self.layers.handle(input, &cx);
        self.handled(answer)
    }

    /// What a key's `action` does: the popups open take it first, top first; what
    /// none takes reaches the views and then the app's own keys. (Ctrl-C falls
    /// through every popup and quits; `q` quits only from the main screen: in a
    /// popup the key table makes it close the popup, in a prompt it types.)
    pub fn apply(&mut self, action: Action) {
        self.dispatch(&Input::Key(action));
    }

    /// A mouse event over the open popups, on a frame of `area` (they hold the mouse:
    /// nothing under a popup is clicked); true if one took it.
    pub fn mouse_on_layers(&mut self, m: MouseEvent, area: Rect) -> bool {
        self.dispatch(&Input::Mouse(m, area))
    }

    fn dispatch(&mut self, input: &Input) -> bool {
        let t = self.t;
        if matches!(input, Input::Key(a) if *a != Action::Quit) {
            self.quit_asked = false;
        }
        match (self.offer_layers(input), input) {
            (true, _) => {}
            // What no popup took reaches the views and the app's own keys.
            (false, Input::Key(action)) => self.apply_normal(*action),
            // A popup holds the mouse (the main screen's is offered only when none is
            // open: `crate::tui::on_mouse_in`).
            (false, Input::Mouse(..)) => return false,
        }
        if self.quit {
            return true;
        }
        // A cursor moved by a key (a step, a jump, the start) takes a zoomed chart along.
        if self.t != t {
            let span = self.chart_span();
            self.layers.main_mut().moved(self.t, span);
        }
        self.settled();
        true
    }

    /// After an input: the cursor kept in the span (a view may have changed the
    /// scene) and the views' work asked for.
    fn settled(&mut self) {
        let sol = &self.lab.solution;
        self.t = self.t.clamp(sol.t_start, sol.t_end);
        self.sync_jobs();
    }

    /// Requests what the views want of this scene (a request already made for it
    /// runs on; one made for an earlier scene is superseded, its result dropped).
    pub fn sync_jobs(&mut self) {
        let (main, cx) = self.pane_cx(Pointer::default());
        main.sync(&cx);
    }

    /// Whom a finished job notifies (the event loop, on its one channel).
    pub fn listen(&self, listener: impl Fn(Notice) + Send + Sync + 'static) {
        self.jobs.listen(listener);
    }

    /// True while an analysis or an export is queued or runs.
    pub fn busy(&self) -> bool {
        self.jobs.busy()
    }

    /// A job's notice: a finished export's message goes to the status line, a view's
    /// finished job is its own to take; true if the screen changes (every notice: a
    /// result or a new percent to show).
    pub fn on_job(&mut self, notice: Notice) -> bool {
        self.take(notice);
        true
    }

    /// Takes a finished job's result where one is taken (the export's, a view's);
    /// true if one was.
    fn take(&mut self, notice: Notice) -> bool {
        if notice == Notice::Export {
            return self.take_export();
        }
        let (main, mut cx) = self.pane_cx(Pointer::default());
        let answer = main.notice(notice, &mut cx);
        let took = self.handled(answer);
        if took {
            self.settled();
        }
        took
    }

    /// Waits for every analysis the views want and every export (headless output is
    /// deterministic).
    pub fn wait(&mut self) {
        self.sync_jobs();
        self.jobs.wait();
        self.take_export();
        // A video's data arrived: the views' analyses of the scene with them.
        if self.take(Notice::Video) {
            self.jobs.wait();
        }
    }

    fn take_export(&mut self) -> bool {
        match self.export.take() {
            Some(Ok(done)) => {
                self.status =
                    Status::Info(format!("wrote {} ({})", done.path.display(), done.what));
            }
            Some(Err(e)) => self.status = Status::Error(format!("not written: {e}")),
            None => return false,
        }
        true
    }
}
