//! The `--data` video in the app, as the edges start it: tracked on a worker when the
//! app opens (the Scene panel's video view owns the job, [`VideoRun`], and takes its
//! data into the lab when they arrive), its pictures when its tracks were kept, and
//! how to track it again (a click on a ball seeds it).

use std::sync::Arc;

use super::{App, Status};
use crate::lab::jobs::Ticket;
use crate::tui::jobs::VideoResult;
use crate::tui::layer::main::video::{VideoRun, VideoTracker, short};
use crate::vision::thumbs::VideoView;

impl App {
    /// Tracks the video `name` on a worker (`work` does it); the app runs on meanwhile
    /// and the Scene panel counts the frames.
    pub fn track_video(
        &mut self,
        name: String,
        work: impl FnOnce(&Ticket) -> VideoResult + Send + 'static,
    ) {
        self.status = Status::Info(format!(
            "tracking {} on a worker: its data join the scene when done (V: the video)",
            short(&name)
        ));
        let generation = self.lab.generation();
        let video: &mut VideoRun = self.layers.main_mut().get_mut::<VideoRun>();
        video.start(&self.jobs, generation, name, work);
    }

    /// The video's pictures, when its tracks were kept (no tracking needed).
    pub fn set_video(&mut self, name: String, view: Option<Arc<VideoView>>) {
        let video = self.layers.main_mut().get_mut::<VideoRun>();
        video.name = Some(name);
        video.view = view;
    }

    /// How the video is tracked again when a click on its picture seeds a ball
    /// (`tracker.options`, its `ball_at` set to the click).
    pub fn set_video_tracker(&mut self, tracker: VideoTracker) {
        self.layers.main_mut().get_mut::<VideoRun>().tracker = Some(tracker);
    }
}
