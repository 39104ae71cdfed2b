//! What the edges read of the app (the screen, the runner, `render`, the tests), and
//! the few settings they make before the first key: the app's fields stay private.

use std::path::{Path, PathBuf};

use super::{App, Library, Prediction, View};
use crate::tui::hide::Hide;
use crate::tui::jobs::{FitRuns, MethodRows, OverlayRun, VideoRun};

impl App {
    /// The playback speed's index in [`super::SPEEDS`].
    pub fn speed(&self) -> usize {
        self.speed
    }

    /// The parameter row selected (an index in [`super::ROWS`]).
    pub fn selected(&self) -> usize {
        self.selected
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
        self.view
    }

    /// The charts' time-stepping overlay and its job.
    pub fn overlay(&self) -> &OverlayRun {
        &self.overlay
    }

    /// Overlays `choice` (a method and its step level) on the charts, or none.
    pub fn set_overlay(&mut self, choice: Option<(crate::methods::Method, u8)>) {
        self.overlay.choice = choice;
        self.sync_jobs();
    }

    /// The Methods view's rows and their job.
    pub fn methods(&self) -> &MethodRows {
        &self.methods
    }

    /// The Fit view's fits, their window and their jobs.
    pub fn fit(&self) -> &FitRuns {
        &self.fit
    }

    /// The `--data` video: its tracking, its pictures, whether the Scene panel shows it.
    pub fn video(&self) -> &VideoRun {
        &self.video
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
