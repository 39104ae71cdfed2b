//! What the edges read of the app (the screen, the runner, `render`, the tests), and
//! the few settings they make before the first key: the app's fields stay private.
//! The views' states are read through here from the main screen that owns them.

use std::path::{Path, PathBuf};

use super::{App, Library, Prediction, View};
use crate::tui::hide::Hide;
use crate::tui::layer::main::charts::{ChartState, Charts, OverlayRun};
use crate::tui::layer::main::fit::FitRuns;
use crate::tui::layer::main::forces::ForcesState;
use crate::tui::layer::main::methods::{MethodRows, Methods, MethodsState};
use crate::tui::layer::main::video::VideoRun;

impl App {
    /// The playback speed's index in [`super::SPEEDS`].
    pub fn speed(&self) -> usize {
        self.speed
    }

    /// The parameter row selected (an index in [`super::ROWS`]).
    pub fn selected(&self) -> usize {
        self.params().selected()
    }

    /// The parameters panel (its row selected).
    pub fn params(&self) -> &crate::tui::layer::main::params::ParamsState {
        self.layers.main().get()
    }

    /// True while the app takes the mouse.
    pub fn mouse(&self) -> bool {
        self.mouse
    }

    /// True once the user quit.
    pub fn quitting(&self) -> bool {
        self.quit
    }

    /// The presets the picker offers and the folder the app saves to.
    pub fn library(&self) -> &Library {
        &self.library
    }

    /// Offers the presets of `library` and saves into its folder.
    pub fn set_library(&mut self, library: Library) {
        self.library = library;
    }

    /// The view shown.
    pub fn view(&self) -> View {
        self.layers.main().shown()
    }

    /// The Charts view's state.
    pub fn charts(&self) -> &ChartState {
        &self.layers.main().get::<Charts>().state
    }

    /// The Forces view's state.
    pub fn forces(&self) -> &ForcesState {
        self.layers.main().get::<ForcesState>()
    }

    /// The Methods view's state.
    pub fn methods_state(&self) -> &MethodsState {
        &self.layers.main().get::<Methods>().state
    }

    /// The charts' time-stepping overlay and its job.
    pub fn overlay(&self) -> &OverlayRun {
        &self.layers.main().get::<Charts>().overlay
    }

    /// Overlays `choice` (a method and its step level) on the charts, or none.
    pub fn set_overlay(&mut self, choice: Option<(crate::methods::Method, u8)>) {
        self.layers.main_mut().get_mut::<Charts>().overlay.choice = choice;
        self.sync_jobs();
    }

    /// The Methods view's rows and their job.
    pub fn methods(&self) -> &MethodRows {
        &self.layers.main().get::<Methods>().rows
    }

    /// The Fit view's fits, their window and their jobs.
    pub fn fit(&self) -> &FitRuns {
        self.layers.main().get::<FitRuns>()
    }

    /// The `--data` video: its tracking, its pictures, whether the Scene panel shows it.
    pub fn video(&self) -> &VideoRun {
        self.layers.main().get::<VideoRun>()
    }

    /// The time span the charts' x axis covers unzoomed: the run's span, or while
    /// the outcome is hidden one that does not tell it ([`crate::tui::hide::neutral_span`]).
    pub fn chart_span(&self) -> (f64, f64) {
        let sol = &self.lab.solution;
        if self.hidden().derived() {
            crate::tui::hide::neutral_span(sol.t_start, self.t)
        } else {
            (sol.t_start, sol.t_end)
        }
    }

    /// The time range the charts show: the span, or the zoomed window of it.
    pub fn chart_range(&self) -> (f64, f64) {
        self.charts().zoom().range(self.chart_span())
    }

    /// Where `w`/`W` write a bare file name.
    pub fn export_dir(&self) -> &Path {
        &self.export_dir
    }

    /// Makes `w`/`W` write a bare file name into `dir`.
    pub fn set_export_dir(&mut self, dir: PathBuf) {
        self.export_dir = dir;
    }

    /// What b hidden hides (the rule; [`App::hidden`] adds a pending prediction).
    pub fn hide(&self) -> Hide {
        self.hide
    }

    /// The last prediction made.
    pub fn prediction(&self) -> Option<&Prediction> {
        self.prediction.as_ref()
    }

    /// True unless the app is `render`'s headless twin.
    pub fn writes_files(&self) -> bool {
        self.writes_files
    }

    /// Makes the app `render`'s headless twin: the export and save keys say what they
    /// would write and write nothing.
    pub fn write_no_files(&mut self) {
        self.writes_files = false;
    }
}
