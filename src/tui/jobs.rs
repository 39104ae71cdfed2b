//! The app's slow analyses, each owned by the view that shows it (gitui's asyncgit
//! shape): the Methods view's rows, the charts' overlay run, the Fit view's fits, the
//! export the prompt started, and the tracking of a `--data` video (the Scene
//! panel's, which draws the video). Each asks the lab for its work on the app's
//! [`Jobs`], keyed by the snapshot's generation (a result made for an earlier scene is
//! dropped unseen), and a finished one arrives as its [`Notice`] on the event loop's
//! one channel. [`sync`](Analyses::sync) requests what the views shown want after every
//! change; a key never waits for a result.

use crate::lab::analyses;
use crate::lab::jobs::{Job, State};
use std::sync::Arc;

use crate::lab::{ExportResult, FitWindow, FitWindowError, Generation, Lab, Overlay, OwnData};
use crate::methods::Method;
use crate::settings::spec::SceneSpec;
use crate::study::compare::Row;
use crate::study::fit::{FitError, Fits};
use crate::vision::thumbs::VideoView;

/// Which job finished (or moved on a percent): what the event loop is told.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Notice {
    MethodRows,
    Overlay,
    Fits,
    Export,
    Video,
}

/// The app's jobs on its worker pool.
pub type Jobs = crate::lab::jobs::JobSet<Notice>;

/// The Methods view's rows, timed or not.
#[derive(Clone, Debug, Default)]
pub struct MethodRows {
    rows: Job<(Generation, bool), Vec<Row>>,
}

impl MethodRows {
    /// Asks for this scene's rows while the view is `shown` (timed if `timed`: the
    /// timing runs cost more, and only the time axis shows them); leaving the view
    /// stops a running job and keeps finished rows until the scene changes.
    pub fn sync(&mut self, shown: bool, timed: bool, lab: &Lab, jobs: &Jobs) {
        let generation = lab.generation();
        if !shown {
            match self.rows.key() {
                Some((g, _)) if *g != generation => self.rows.cancel(),
                _ => self.rows.stop_running(),
            }
            return;
        }
        // Timed rows serve every axis: going back to steps keeps the scene's timed rows.
        let timed = timed || self.rows.key() == Some(&(generation, true));
        let work = analyses::method_rows(lab, timed);
        self.rows
            .request(jobs, (generation, timed), Notice::MethodRows, work);
    }

    pub fn state(&self) -> State<'_, Vec<Row>> {
        self.rows.state()
    }
}

/// A time-stepping run drawn over the exact curves: which (method, level), if any.
#[derive(Clone, Debug)]
pub struct OverlayRun {
    pub choice: Option<(Method, u8)>,
    /// The overlay's level when one is switched on.
    pub level: u8,
    /// `None` only for a run that was cancelled before it finished.
    run: Job<(Generation, Method, u8), Option<Overlay>>,
}

impl Default for OverlayRun {
    fn default() -> Self {
        OverlayRun {
            choice: None,
            level: 2,
            run: Job::default(),
        }
    }
}

impl OverlayRun {
    /// Asks for the chosen run of this scene (or forgets it).
    pub fn sync(&mut self, lab: &Lab, jobs: &Jobs) {
        let Some((method, level)) = self.choice else {
            self.run.cancel();
            return;
        };
        let key = (lab.generation(), method, level);
        let work = analyses::overlay(lab, method, level);
        self.run.request(jobs, key, Notice::Overlay, work);
    }

    pub fn state(&self) -> State<'_, Overlay> {
        match self.run.state() {
            State::Ready(Some(o)) => State::Ready(o),
            State::Ready(None) | State::Idle => State::Idle,
            State::Computing { done, total } => State::Computing { done, total },
        }
    }
}

/// The Fit view's fits of the measured series, and the line fit's window.
#[derive(Clone, Debug, Default)]
pub struct FitRuns {
    /// Line-fit window (None: the sliding phase).
    pub window: FitWindow,
    fits: Job<(Generation, FitWindow), Result<Fits, FitError>>,
}

impl FitRuns {
    /// Asks for this scene's fits while the Fit view is `shown`; leaving it stops a
    /// running fit (a finished one is kept); without data it is forgotten, so a fit of
    /// data no longer shown is neither drawn nor applied.
    pub fn sync(&mut self, shown: bool, lab: &Lab, jobs: &Jobs) {
        let Some(fits) = analyses::fits(lab, self.window) else {
            self.fits.cancel();
            return;
        };
        if !shown {
            self.fits.stop_running();
            return;
        }
        let generation = lab.generation();
        self.fits
            .request(jobs, (generation, self.window), Notice::Fits, fits);
    }

    pub fn fits(&self) -> State<'_, Result<Fits, FitError>> {
        self.fits.state()
    }

    /// Moves one end of the line-fit window by one measured frame (the fits follow at
    /// the next [`FitRuns::sync`]).
    pub fn move_window(&mut self, lab: &Lab, end: bool, later: bool) -> Result<(), FitWindowError> {
        let fitted = match self.fits.ready() {
            Some(Ok(f)) => Some((f.line_fit.from, f.line_fit.to)),
            _ => None,
        };
        self.window = analyses::moved_fit_window(lab, self.window, fitted, end, later)?;
        Ok(())
    }
}

/// A file the app is writing (run CSV, chart SVG): each export its own request, a
/// newer one superseding a running one.
#[derive(Clone, Debug, Default)]
pub struct ExportRun {
    run: Job<u64, ExportResult>,
    count: u64,
}

impl ExportRun {
    /// Writes a file off the key press: `work` returns the file written, or why not.
    pub fn start<E: std::error::Error + Send + Sync + 'static>(
        &mut self,
        jobs: &Jobs,
        work: impl FnOnce() -> Result<crate::lab::Exported, E> + Send + 'static,
    ) {
        self.count += 1;
        self.run
            .request(jobs, self.count, Notice::Export, move |_| {
                work().map_err(|e| std::sync::Arc::new(e) as _)
            });
    }

    /// The finished export's result, once; `None` while it runs or when there is none.
    pub fn take(&mut self) -> Option<ExportResult> {
        self.run.take()
    }
}

/// A video tracked for the lab: its series as the user's own data (with what they
/// measure and the file whose `# scene` lines the scene took), and the pictures the
/// Scene panel draws.
#[derive(Clone, Debug)]
pub struct TrackedVideo {
    pub own: OwnData,
    pub from_data: Option<SceneSpec>,
    pub file_keys: Vec<crate::settings::params::Key>,
    pub scene_file: Option<String>,
    pub view: Option<Arc<VideoView>>,
}

/// What a tracking job reports: the video tracked, or why not (the edge's own error,
/// kept whole); `None` when it was stopped.
pub type VideoResult = Option<Result<TrackedVideo, Arc<dyn std::error::Error + Send + Sync>>>;

/// The `--data` video of the Scene panel: tracked on a worker while the app runs
/// (started once, keyed by the generation it was asked in: an edit of the scene does
/// not track the video again), its pictures once there, and whether the panel shows
/// the video or the drawn scene.
#[derive(Clone, Debug, Default)]
pub struct VideoRun {
    /// The video as the user named it.
    pub name: Option<String>,
    run: Job<Generation, VideoResult>,
    /// The tracked video's pictures and points.
    pub view: Option<Arc<VideoView>>,
    /// The Scene panel shows the video (`V`).
    pub shown: bool,
}

impl VideoRun {
    /// Tracks the video `name` off the key path: `work` makes it, telling its ticket.
    pub fn start(
        &mut self,
        jobs: &Jobs,
        generation: Generation,
        name: String,
        work: impl FnOnce(&crate::lab::jobs::Ticket) -> VideoResult + Send + 'static,
    ) {
        self.name = Some(name);
        self.run.request(jobs, generation, Notice::Video, work);
    }

    /// The tracking's progress while it runs: frames done of the total (0: unknown).
    pub fn progress(&self) -> Option<(usize, usize)> {
        match self.run.state() {
            State::Computing { done, total } => Some((done, total)),
            _ => None,
        }
    }

    /// The finished tracking's result, once.
    pub fn take(&mut self) -> VideoResult {
        self.run.take().flatten()
    }
}
