//! The `--data` video in the app: tracked on a worker when the app opens (its data
//! join the lab when they arrive, the user's edits kept), and `V`, which switches
//! the Scene panel between the drawn scene and the video.

use std::sync::Arc;

use super::{App, Status};
use crate::lab::jobs::Ticket;
use crate::tui::jobs::VideoResult;
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
        self.video
            .start(&self.jobs, self.lab.generation(), name, work);
    }

    /// The video's pictures, when its tracks were kept (no tracking needed).
    pub fn set_video(&mut self, name: String, view: Option<Arc<VideoView>>) {
        self.video.name = Some(name);
        self.video.view = view;
    }

    /// A finished tracking: its data into the lab, its pictures to the Scene panel,
    /// or why not in the status line; true if one finished.
    pub(super) fn take_video(&mut self) -> bool {
        let Some(result) = self.video.take() else {
            return false;
        };
        let name = short(self.video.name.as_deref().unwrap_or_default());
        match result {
            Ok(done) => match self.lab.attach_data(
                done.own,
                done.from_data,
                done.file_keys,
                done.scene_file,
            ) {
                Ok(()) => {
                    self.video.view = done.view;
                    let sol = &self.lab.solution;
                    self.t = self.t.clamp(sol.t_start, sol.t_end);
                    self.status = Status::Info(format!(
                        "tracked {name}: its data are in the scene (V: the video)"
                    ));
                }
                Err(e) => self.status = Status::Error(format!("{name}: not used: {e}")),
            },
            Err(e) => self.status = Status::Error(format!("not tracked: {e}")),
        }
        true
    }

    /// `V`: the Scene panel shows the video or the drawn scene.
    pub(super) fn toggle_video(&mut self) {
        let Some(name) = self.video.name.clone() else {
            self.status =
                Status::Error("no video: give one with --data (groovelab --data clip.mp4)".into());
            return;
        };
        self.video.shown = !self.video.shown;
        self.status = Status::Info(if self.video.shown {
            format!(
                "Scene panel: the video {} (V: the drawn scene)",
                short(&name)
            )
        } else {
            "Scene panel: the drawn scene (V: the video)".into()
        });
    }
}

/// A video's name as the status line says it: its file's name, without the folders.
fn short(name: &str) -> String {
    std::path::Path::new(name)
        .file_name()
        .map_or(name.into(), |f| f.to_string_lossy().into_owned())
}
