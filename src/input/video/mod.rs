//! Videos and folders of frames at the edge: what a video is (`probe`: the system's
//! `ffprobe`, its size, frame rate and a phone's slow-motion capture rate), its
//! frames streamed as luma (`decode`: the system's `ffmpeg` through a pipe, one frame
//! in memory at a time), a folder of numbered PNG/JPEG frames (`folder`, no ffmpeg
//! needed), and writing frames and videos (`write`: for tests and benchmarks). Never
//! a binary fetched at run time: without ffmpeg a video is refused with how to
//! install it.

mod decode;
mod folder;
mod info;
mod probe;
pub mod write;

use std::path::Path;

pub use info::{Frames, INSTALL_FFMPEG, Info, Limits, RateSource, VideoError};
pub use probe::Probe;

/// Opens `path`: a folder of numbered frames, or a video through ffprobe and ffmpeg.
/// Refuses what is no video (empty, an image, audio, unreadable) and what is too
/// large for `limits`, each with one line.
pub fn open(path: &Path, limits: &Limits) -> Result<(Info, Frames), VideoError> {
    let file = path.display().to_string();
    let err = |what: String| VideoError {
        file: file.clone(),
        what,
    };
    let meta = std::fs::metadata(path).map_err(|e| err(format!("cannot open: {e}")))?;
    if meta.is_dir() {
        return folder::open(path, limits);
    }
    if !meta.is_file() {
        return Err(err(
            "is not a regular file, expected a video or a folder of frames".into(),
        ));
    }
    if meta.len() == 0 {
        return Err(err("is empty (0 bytes), expected a video".into()));
    }
    if folder::is_image(path) {
        return Err(err(
            "is a still image, not a video; give a video, or a folder of numbered frames (frame0001.png, …)"
                .into(),
        ));
    }
    let probe = probe::probe(path)?;
    let info = probe.info(&file, limits)?;
    let frames = decode::frames(path, &info)?;
    Ok((info, frames))
}
