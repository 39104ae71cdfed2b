//! The app's jobs on its worker pool: which one finished ([`Notice`], what the event
//! loop is told on its one channel), the export the prompt started (the app's), and
//! what a video's tracking reports. The views' own jobs live with their views
//! (`layer/main`, gitui's shape: the Methods view's rows, the charts' overlay run, the
//! Fit view's fits, the Scene panel's video): each asks the lab for its work on the
//! app's [`Jobs`], keyed by the snapshot's generation (a result made for an earlier
//! scene is dropped unseen); the app asks every view to sync after every change, and a
//! key never waits for a result.

use crate::lab::jobs::Job;
use std::sync::Arc;

use crate::lab::{ExportResult, OwnData};
use crate::settings::spec::SceneSpec;
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
    /// The tracks as the lab's data; `None` where no fit can use them (`unfit`).
    pub own: Option<OwnData>,
    /// Tracks `data` reads but no fit can use (no impact in the clip).
    pub unfit: Option<crate::lab::Unfit>,
    pub from_data: Option<SceneSpec>,
    pub file_keys: Vec<crate::settings::params::Key>,
    pub scene_file: Option<String>,
    pub view: Option<Arc<VideoView>>,
}

/// What a tracking job reports: the video tracked, or why not; `None` when it was
/// stopped.
pub type VideoResult = Option<Result<TrackedVideo, VideoRefused>>;

/// Why a video gave the lab no data (the edge's own error, kept whole), and, where
/// the tracker refused it, its first frame with what was found there (a click on a
/// ball seeds the tracking again).
#[derive(Clone, Debug)]
pub struct VideoRefused {
    pub error: Arc<dyn std::error::Error + Send + Sync>,
    pub first_frame: Option<Arc<VideoView>>,
}

impl VideoRefused {
    /// A refusal with no picture to show.
    pub fn of(error: impl std::error::Error + Send + Sync + 'static) -> VideoRefused {
        VideoRefused {
            error: Arc::new(error),
            first_frame: None,
        }
    }
}
