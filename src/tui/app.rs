//! The app's UI state and what every action does to it: selection, popups, playback,
//! which view is shown. Everything computed about the scene is asked of the [`Lab`].
//! No terminal here: keys arrive as [`Action`]s, so the whole app is testable without one.
//! The types it speaks in live in [`super::vocabulary`]; what the main screen's keys do in
//! `normal`, what the popups ask when they answer in `prompts` (the popups themselves
//! are layers, [`super::layer`]: a key goes to them first).

mod access;
pub mod export;
mod normal;
mod predict;
mod prompts;
mod stops;
mod video;

use std::path::PathBuf;
use std::sync::{Arc, LazyLock};

use crate::lab::Lab;
use crate::lab::jobs::Pool;
use crate::settings::params::{Key, PARAMS, Param};
use crate::settings::spec::SceneError;
use crate::settings::units::{Dimension, show, significant};

pub use super::vocabulary::{
    Action, ChartBall, Export, FPS, Field, Library, Mode, Prediction, SPEEDS, Status, View,
};
pub use stops::{EventStop, event_stops};

use super::interact::{Input, Interactive};
use super::jobs::{ExportRun, FitRuns, Jobs, MethodRows, Notice, OverlayRun, VideoRun};
use super::layer::{Compositor, Histories, Layer, LayerCx};
use super::view::charts::state::{ChartState, Moment};
use super::view::forces::state::ForcesState;
use super::view::methods::state::MethodsState;
use super::vocabulary::{DEFAULT_SPEED, Handled, WorkAxis};
use ratatui::crossterm::event::MouseEvent;
use ratatui::layout::Rect;

/// The rows of the parameters panel, top to bottom: the table's rows that have steps.
pub static ROWS: LazyLock<Vec<&'static Param>> =
    LazyLock::new(|| PARAMS.iter().filter(|p| p.steps.is_some()).collect());

/// The app: playback, the view shown and its components' state, the popups open
/// (a stack of layers), and the lab. The lab, the time, playing and the status line
/// are open to the edges (the runner, `render` and the tests set scenes, times and
/// read messages); everything else is read through accessors and changed by actions.
#[derive(Clone, Debug)]
pub struct App {
    pub lab: Lab,
    /// Simulated time shown, s.
    pub t: f64,
    pub playing: bool,
    speed: usize,
    selected: usize,
    /// The popups open over the main screen, top last: they take input first.
    layers: Compositor,
    /// The Charts view's own state: which chart, which ball, the time zoom.
    charts: ChartState,
    mouse: bool,
    pub status: Status,
    quit: bool,
    library: Library,
    view: View,
    /// The charts' time-stepping overlay: which run, and its job.
    overlay: OverlayRun,
    /// The Methods view's rows (its job).
    methods: MethodRows,
    /// The Fit view's fits and window (their jobs).
    fit: FitRuns,
    /// The file being written (its job).
    export: ExportRun,
    /// The `--data` video: its tracking (a job), its pictures, and whether the Scene
    /// panel shows it.
    video: VideoRun,
    /// The app's jobs on its worker pool.
    jobs: Jobs,
    /// What the Methods view puts on its work axis.
    methods_state: MethodsState,
    /// Where `w`/`W` write a bare file name.
    export_dir: PathBuf,
    /// The ball the Forces view's front view shows: 0 left, 1 right.
    forces: ForcesState,
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
            selected: 1,
            layers: Compositor::default(),
            charts: ChartState::default(),
            mouse: true,
            status: Status::None,
            quit: false,
            library,
            view: View::Charts,
            overlay: OverlayRun::default(),
            methods: MethodRows::default(),
            fit: FitRuns::default(),
            export: ExportRun::default(),
            video: VideoRun::default(),
            jobs: Jobs::new(pool),
            methods_state: MethodsState::default(),
            export_dir: PathBuf::from("."),
            forces: ForcesState::default(),
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

    /// True in the Fit view (charts with fit lines, the Fit panel).
    pub fn fit_view(&self) -> bool {
        self.view == View::Fit
    }

    pub fn speed_factor(&self) -> f64 {
        SPEEDS[self.speed]
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
        if self.hide.value(key) {
            "(hidden)".to_string()
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

    /// The next (or previous) stop of `>` (`<`) in the span: see [`event_stops`].
    pub fn event_target(&self, later: bool) -> Option<EventStop> {
        let eps = 1e-9;
        let mut stops = event_stops(&self.lab.solution).into_iter();
        if later {
            stops.find(|s| s.t > self.t + eps)
        } else {
            stops.rev().find(|s| s.t < self.t - eps)
        }
    }

    /// Moves the cursor to `t` (a click on the chart), paused.
    pub fn seek(&mut self, t: f64) {
        let sol = &self.lab.solution;
        self.playing = false;
        self.t = t.clamp(sol.t_start, sol.t_end);
    }

    /// Advances playback by `wall` real seconds; stops at the end. A zoomed chart
    /// follows the cursor.
    pub fn tick(&mut self, wall: f64) {
        if !self.playing {
            return;
        }
        let before = self.t;
        self.t += wall * self.speed_factor();
        if !self.pause_at_outcome(before) && self.t >= self.lab.solution.t_end {
            self.t = self.lab.solution.t_end;
            self.playing = false;
        }
        self.charts.follow(self.t, self.chart_span());
    }

    /// The Charts view's state.
    pub fn charts(&self) -> &ChartState {
        &self.charts
    }

    /// The Forces view's state.
    pub fn forces(&self) -> &ForcesState {
        &self.forces
    }

    /// The Methods view's state.
    pub fn methods_state(&self) -> &MethodsState {
        &self.methods_state
    }

    /// Where the charts' keys act now.
    fn moment(&self) -> Moment {
        Moment {
            t: self.t,
            span: self.chart_span(),
            shown: matches!(self.view, View::Charts | View::Fit),
            pointer: None,
        }
    }

    /// A component's answer to a key: true if it was its key (a message goes to the
    /// status line).
    fn handled(&mut self, answer: Handled) -> bool {
        match answer {
            Handled::Ignored => return false,
            Handled::Consumed => {}
            Handled::Say(message) => self.status = Status::Info(message),
            Handled::Close(then) | Handled::Ask(then) => self.then(then),
        }
        true
    }

    /// The time span the charts' x axis covers unzoomed: the run's span, or while
    /// the outcome is hidden one that does not tell it ([`super::hide::neutral_span`]).
    pub fn chart_span(&self) -> (f64, f64) {
        let sol = &self.lab.solution;
        if self.hidden().derived() {
            super::hide::neutral_span(sol.t_start, self.t)
        } else {
            (sol.t_start, sol.t_end)
        }
    }

    /// The time range the charts show: the span, or the zoomed window of it.
    pub fn chart_range(&self) -> (f64, f64) {
        self.charts.zoom().range(self.chart_span())
    }

    /// A mouse event on the main screen offered to the view shown (the wheel over
    /// the chart zooms its time axis): `pointer` is the time under it if it is over
    /// the chart's plot of the frame on screen. True if the view took it.
    pub fn mouse_on_view(&mut self, m: MouseEvent, area: Rect, pointer: Option<f64>) -> bool {
        let moment = Moment {
            pointer,
            ..self.moment()
        };
        let answer = self.charts.handle(&Input::Mouse(m, area), moment);
        self.handled(answer)
    }

    /// Offers `action` to the component of the view shown that owns it (the Forces
    /// view's ball key is its own); true if one took it.
    pub(super) fn offer(&mut self, action: Action) -> bool {
        let key = Input::Key(action);
        let answer = match self.view {
            View::Forces => self.forces.handle(&key, ()),
            View::Charts | View::Methods | View::Map | View::Fit => Handled::Ignored,
        };
        if self.handled(answer) {
            return true;
        }
        let answer = self.methods_state.handle(&key, ());
        if self.handled(answer) {
            return true;
        }
        let moment = self.moment();
        let answer = self.charts.handle(&key, moment);
        self.handled(answer)
    }

    /// Offers `input` to the popups open, top first; true if one took it (what it
    /// asks of the app done).
    fn offer_layers(&mut self, input: &Input) -> bool {
        let cx = LayerCx {
            presets: self.library.presets.len(),
            histories: &self.histories,
        };
        match self.layers.handle(input, &cx) {
            Handled::Ignored => false,
            Handled::Consumed => true,
            Handled::Say(message) => {
                self.status = Status::Info(message);
                true
            }
            Handled::Close(then) | Handled::Ask(then) => {
                self.then(then);
                true
            }
        }
    }

    /// What a key's `action` does: the popups open take it first, top first; what
    /// none takes reaches the view shown and the main screen's keys. (Ctrl-C falls
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
        match (self.offer_layers(input), input) {
            (true, _) => {}
            // What no popup took reaches the view shown and the main screen's keys.
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
            self.charts.follow(self.t, self.chart_span());
        }
        self.sync_jobs();
        true
    }

    /// Requests what the views shown want of this scene (a request already made for
    /// it runs on; one made for an earlier scene is superseded, its result dropped).
    pub fn sync_jobs(&mut self) {
        let timed = self.methods_state.axis() == WorkAxis::Time;
        let methods = self.view == View::Methods;
        self.methods.sync(methods, timed, &self.lab, &self.jobs);
        self.overlay.sync(&self.lab, &self.jobs);
        self.fit.sync(self.fit_view(), &self.lab, &self.jobs);
    }

    /// Whom a finished job notifies (the event loop, on its one channel).
    pub fn listen(&self, listener: impl Fn(Notice) + Send + Sync + 'static) {
        self.jobs.listen(listener);
    }

    /// True while an analysis or an export is queued or runs.
    pub fn busy(&self) -> bool {
        self.jobs.busy()
    }

    /// A job's notice: a finished export's message goes to the status line; true if
    /// the screen changes (every notice: a result or a new percent to show).
    pub fn on_job(&mut self, notice: Notice) -> bool {
        match notice {
            Notice::Export => {
                self.take_export();
            }
            Notice::Video => {
                self.take_video();
            }
            _ => {}
        }
        true
    }

    /// Waits for every analysis the views shown want and every export (headless
    /// output is deterministic).
    pub fn wait(&mut self) {
        self.sync_jobs();
        self.jobs.wait();
        self.take_export();
        // A video's data arrived: the views' analyses of the scene with them.
        if self.take_video() {
            self.sync_jobs();
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

    /// Playback in few words, for a status line that also holds a message: the time,
    /// playing or paused, and the speed if `with_speed`.
    pub fn playback_short(&self, with_speed: bool) -> String {
        let state = if self.playing { "playing" } else { "paused" };
        if with_speed {
            format!("t = {:.3} s  {state}  ×{}", self.t, self.speed_text())
        } else {
            format!("t = {:.3} s  {state}", self.t)
        }
    }

    fn speed_text(&self) -> String {
        let speed = self.speed_factor();
        if speed < 1.0 {
            format!("1/{}", (1.0 / speed).round())
        } else {
            significant(speed, 2)
        }
    }

    /// A one-line summary of playback for the status line (without the span's end
    /// while the outcome is hidden: it would tell it).
    pub fn playback(&self) -> String {
        let speed = self.speed_text();
        let sol = &self.lab.solution;
        if self.hidden().derived() {
            let state = if self.playing { "playing" } else { "paused" };
            return format!("t = {:.3} s   {state}  speed ×{speed}", self.t);
        }
        format!(
            "t = {:.3} s of {:.3} … {:.3} s   {}  speed ×{speed}",
            self.t,
            sol.t_start,
            sol.t_end,
            if self.playing { "playing" } else { "paused" },
        )
    }
}
