//! Videos and folders of frames at the edge: what a video is (`probe`: the system's
//! `ffprobe`, its size, frame rate and a phone's slow-motion capture rate), its
//! frames streamed in colour (`decode`: the system's `ffmpeg` through a pipe, one frame
//! in memory at a time), a folder of numbered PNG/JPEG frames (`folder`, no ffmpeg
//! needed), a video tracked (`tracked`) and kept (`cache`), what was tracked drawn over
//! its frames (`overlay`), and writing frames and videos (`write`). Never
//! a binary fetched at run time: without ffmpeg a video is refused with how to
//! install it.

pub mod cache;
mod decode;
mod folder;
mod info;
pub mod overlay;
mod probe;
mod problem;
pub mod tracked;
pub mod write;

use std::path::Path;

pub use folder::is_image;
pub use info::{Frames, Info, Limits, RateSource};
pub use probe::Probe;
pub use problem::{INSTALL_FFMPEG, VideoError, VideoProblem};

/// Opens `path`: a folder of numbered frames, or a video through ffprobe and ffmpeg.
/// Refuses what is no video (empty, an image, audio, unreadable) and what is too
/// large for `limits`, each with one line.
pub fn open(path: &Path, limits: &Limits) -> Result<(Info, Frames), VideoError> {
    open_every(path, limits, 1)
}

/// As [`open`], but only every `every`-th frame (a video still decodes all of them,
/// but only those are piped and read).
pub fn open_every(
    path: &Path,
    limits: &Limits,
    every: usize,
) -> Result<(Info, Frames), VideoError> {
    let every = every.max(1);
    match checked(path, limits)? {
        Opened::Folder(info, frames) => Ok((
            info,
            Box::new(
                frames
                    .enumerate()
                    .filter(move |(i, _)| i % every == 0)
                    .map(|(_, f)| f),
            ),
        )),
        Opened::Video(info) => {
            let frames = decode::frames(path, &info, every)?;
            Ok((info, frames))
        }
    }
}

/// As [`open`], with `accept` asked of the video's description before a frame is
/// read: one probe (one run of ffprobe), not one to check and one to open; ffmpeg
/// starts beside it (ended unread when the video is refused).
pub fn open_if(
    path: &Path,
    limits: &Limits,
    accept: impl FnOnce(&Info) -> Result<(), VideoError>,
) -> Result<(Info, Frames), VideoError> {
    // A file that may be a video: ffmpeg started at once, beside ffprobe (ended
    // unread when the file is refused); not started (no ffmpeg), it is started
    // after the probe as before, which says why it cannot be.
    let started = (path.is_file() && !folder::is_image(path))
        .then(|| decode::spawn(path, 1).ok())
        .flatten();
    match checked(path, limits)? {
        Opened::Folder(info, frames) => {
            accept(&info)?;
            Ok((info, frames))
        }
        Opened::Video(info) => {
            accept(&info)?;
            let frames = match started {
                Some(s) => decode::stream(s, &info),
                None => decode::frames(path, &info, 1)?,
            };
            Ok((info, frames))
        }
    }
}

/// The frames of the video at `path` (`info`: what [`open_if`] said of it), cut to
/// the rows of `band` by ffmpeg: only those rows are piped (a video file; a
/// folder's frames are cut by `band.cut` as they are read).
pub fn open_band(
    path: &Path,
    info: &Info,
    band: &crate::vision::band::Band,
) -> Result<Frames, VideoError> {
    decode::band_frames(path, info, band)
}

/// What `path` is, as [`open`] would refuse it, without decoding a frame (a
/// folder's first frame is read).
pub fn check(path: &Path, limits: &Limits) -> Result<Info, VideoError> {
    match checked(path, limits)? {
        Opened::Folder(info, _) | Opened::Video(info) => Ok(info),
    }
}

enum Opened {
    Folder(Info, Frames),
    Video(Info),
}

fn checked(path: &Path, limits: &Limits) -> Result<Opened, VideoError> {
    let err = |what: VideoProblem| VideoError::new(path, what);
    let meta = std::fs::metadata(path).map_err(|e| err(VideoProblem::Open(e)))?;
    if meta.is_dir() {
        let (info, frames) = folder::open(path, limits)?;
        return Ok(Opened::Folder(info, frames));
    }
    if !meta.is_file() {
        return Err(err(VideoProblem::NotRegular));
    }
    if meta.len() == 0 {
        return Err(err(VideoProblem::Empty));
    }
    if folder::is_image(path) {
        return Err(err(VideoProblem::StillImage));
    }
    let probe = probe::cached(path, &meta)?;
    Ok(Opened::Video(probe.info(path, limits)?))
}
