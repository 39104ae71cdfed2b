//! The Scene panel's video (`--data VIDEO`, `V`) as a view of its own (issue 36): the
//! tracking job it owns (started when the app opens, keyed by the generation it was
//! asked in and the seed: an edit of the scene does not track the video again), its
//! pictures once there, whether the panel shows the video or the drawn scene, and a
//! click on a ball in the picture (issue 34), which tracks the video again seeded
//! there. Its data join the lab when they arrive, the user's edits kept.

use std::sync::Arc;

use super::pane::{Pane, PaneCx, VideoData};
use crate::input::video::tracked::Options;
use crate::input::video::{VideoError, VideoProblem};
use crate::lab::jobs::{Job, State, Ticket};
use crate::lab::{Generation, Lab};
use crate::tui::interact::{Input, click};
use crate::tui::jobs::{Jobs, Notice, VideoResult};
use crate::tui::vocabulary::{Action, Handled, View};
use crate::vision::thumbs::VideoView;

/// One tracking's work, as the pool runs it.
pub type VideoWork = Box<dyn FnOnce(&Ticket) -> VideoResult + Send>;

/// What tracks the app's video for the options given (the edge makes it: it knows the
/// file, the scene's options and the cache), and the options it was opened with.
#[derive(Clone)]
pub struct VideoTracker {
    pub options: Options,
    pub work: Arc<dyn Fn(Options) -> VideoWork + Send + Sync>,
}

impl std::fmt::Debug for VideoTracker {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("VideoTracker")
            .field("options", &self.options)
            .finish_non_exhaustive()
    }
}

/// The `--data` video of the Scene panel and its tracking.
#[derive(Clone, Debug, Default)]
pub struct VideoRun {
    /// The video as the user named it.
    pub name: Option<String>,
    /// Keyed by the generation it was asked in and the how-many-th tracking it is.
    run: Job<(Generation, u64), VideoResult>,
    count: u64,
    /// The tracked video's pictures and points.
    pub view: Option<Arc<VideoView>>,
    /// The Scene panel shows the video (`V`).
    pub shown: bool,
    /// How to track it again (a click on a ball seeds it); none: it cannot be.
    pub tracker: Option<VideoTracker>,
    /// The seed of the tracking asked last, video pixels (a click on a ball).
    pub seed: Option<(f64, f64)>,
    /// The first frame shown alone in place of the tracked video's view, for a click
    /// on a ball there (a click on a later frame asked for it).
    pub first: Option<Arc<VideoView>>,
    /// The last tracking was refused (with its first frame to click on, or not).
    refused: Option<bool>,
}

impl VideoRun {
    /// Tracks the video `name` off the key path: `work` makes it, telling its ticket.
    pub fn start(
        &mut self,
        jobs: &Jobs,
        generation: Generation,
        name: String,
        work: impl FnOnce(&Ticket) -> VideoResult + Send + 'static,
    ) {
        self.name = Some(name);
        self.count += 1;
        self.run
            .request(jobs, (generation, self.count), Notice::Video, work);
    }

    /// The tracking's progress while it runs: frames done of the total (0: unknown).
    pub fn progress(&self) -> Option<(usize, usize)> {
        match self.run.state() {
            State::Computing { done, total } => Some((done, total)),
            _ => None,
        }
    }

    /// Why the video's data are not in the lab, where they are not: it is still being
    /// tracked, or its tracking was refused.
    pub fn data(&self) -> Option<VideoData> {
        let name = short(self.name.as_deref()?);
        if self.progress().is_some() {
            return Some(VideoData::Tracking(name));
        }
        self.refused
            .map(|first_frame| VideoData::Refused { name, first_frame })
    }

    /// The view the Scene panel draws: the first frame alone when a click asked for
    /// it, else the video's view.
    pub fn picture(&self) -> Option<&Arc<VideoView>> {
        self.first.as_ref().or(self.view.as_ref())
    }

    /// The finished tracking's result, once.
    pub fn take(&mut self) -> VideoResult {
        self.run.take().flatten()
    }

    /// A finished tracking: its data into the lab, its pictures kept, or why not;
    /// [`Handled::Ignored`] if none finished.
    fn arrived(&mut self, lab: &mut Lab) -> Handled {
        let Some(result) = self.take() else {
            return Handled::Ignored;
        };
        let name = short(self.name.as_deref().unwrap_or_default());
        self.first = None;
        self.refused = result.as_ref().err().map(|r| r.first_frame.is_some());
        match result {
            Ok(done) => {
                let Some(own) = done.own else {
                    self.view = done.view;
                    if let Some(unfit) = done.unfit {
                        lab.set_unfit(unfit);
                    }
                    return Handled::Refused(format!(
                        "tracked {name}: no fit (f says why; V: the video)"
                    ));
                };
                match lab.attach_data(own, done.from_data, done.file_keys, done.scene_file) {
                    Ok(()) => {
                        self.view = done.view;
                        Handled::Say(format!(
                            "tracked {name}: its data are in the scene (V: the video)"
                        ))
                    }
                    Err(e) => Handled::Refused(format!("{name}: not used: {e}")),
                }
            }
            Err(refused) => {
                let Some(first) = refused.first_frame else {
                    return Handled::Refused(format!("not tracked: {}", refused.error));
                };
                // The first frame in place of any earlier view: a click on a ball
                // there seeds the tracking again.
                self.view = Some(first);
                Handled::Refused(refusal_said(&name, refused.error.as_ref()))
            }
        }
    }

    /// `V`: the Scene panel shows the video or the drawn scene.
    fn toggle(&mut self) -> Handled {
        let Some(name) = self.name.clone() else {
            return Handled::Refused(
                "no video: give one with --data (groovelab --data clip.mp4)".into(),
            );
        };
        self.shown = !self.shown;
        self.first = None;
        Handled::Say(if self.shown {
            format!(
                "Scene panel: the video {} (V: the drawn scene)",
                short(&name)
            )
        } else {
            "Scene panel: the drawn scene (V: the video)".into()
        })
    }

    /// A click on the picture at the video's pixel `at` of its `frame`: the tracking
    /// again, seeded there (`Options::ball_at`) if the frame is the first; else the
    /// first frame shown alone, to click a ball in (a seed is a point in the first
    /// frame: a ball clicked later in the clip is elsewhere then).
    fn seed_at(&mut self, at: (f64, f64), frame: Option<usize>, cx: &PaneCx<'_>) -> Handled {
        let Some(tracker) = &self.tracker else {
            return Handled::Refused("this video cannot be tracked again here".into());
        };
        let alone = self.picture().is_some_and(|v| v.first_only.is_some());
        if !alone && frame != Some(0) {
            let Some(view) = &self.view else {
                return Handled::Ignored;
            };
            let note = "A seed is a point on a ball in the first frame: this is it.";
            self.first = Some(Arc::new(view.first_only(note.into())));
            return Handled::Say(
                "the video's first frame: click a ball there to track from it (V: the drawn scene)"
                    .into(),
            );
        }
        let options = Options {
            ball_at: Some(at),
            ..tracker.options.clone()
        };
        let work = (tracker.work)(options);
        let name = self.name.clone().unwrap_or_default();
        self.start(cx.jobs, cx.lab.generation(), name.clone(), work);
        self.seed = Some(at);
        Handled::Say(format!(
            "tracking {} again from the ball at ({:.0}, {:.0}) px",
            short(&name),
            at.0,
            at.1
        ))
    }
}

impl Pane for VideoRun {
    fn view(&self) -> Option<View> {
        None
    }

    fn handle(&mut self, input: &Input, cx: &mut PaneCx<'_>) -> Handled {
        match (input, cx.pointer.pixel) {
            (Input::Key(Action::ToggleVideo), _) => self.toggle(),
            (Input::Mouse(..), Some(at)) if self.shown && click(input).is_some() => {
                self.seed_at(at, cx.pointer.frame, cx)
            }
            _ => Handled::Ignored,
        }
    }

    fn notice(&mut self, notice: Notice, cx: &mut PaneCx<'_>) -> Handled {
        match notice {
            Notice::Video => self.arrived(cx.lab),
            _ => Handled::Ignored,
        }
    }
}

/// A video's name as the status line says it: its file's name, without the folders.
pub fn short(name: &str) -> String {
    std::path::Path::new(name)
        .file_name()
        .map_or(name.into(), |f| f.to_string_lossy().into_owned())
}

/// The status line's words for the tracker's refusal of the video `name`, whose
/// first frame is shown: the refusal alone, without the file's path (the clip is
/// named) and without the command line's `--roi`/`--ball-at` (a click on a ball is
/// the app's seed), so that the reason comes first and is read whole; a tracking
/// seeded by a click says where. Any other error whole, as before.
fn refusal_said(name: &str, error: &(dyn std::error::Error + Send + Sync + 'static)) -> String {
    let tracks = error
        .downcast_ref::<VideoError>()
        .and_then(|e| match &e.what {
            VideoProblem::Tracks { error, at, .. } => Some((error, *at)),
            _ => None,
        });
    match tracks {
        Some((why, None)) => {
            format!("{name} not tracked: {why} (V: its first frame; click a ball there to seed it)")
        }
        Some((why, Some((x, y)))) => format!(
            "{name} not tracked from the ball clicked at ({x:.0}, {y:.0}) px: {why} (V: its first frame; click another ball there)"
        ),
        None => format!("not tracked (V: its first frame; click a ball there to seed it): {error}"),
    }
}
