//! `--data VIDEO` and `--data FOLDER` (numbered PNG/JPEG frames): a video given where
//! a data file is read is tracked as `groovelab track` would, and its Tracker-style
//! text read as the data file; kept in this process and in the user's cache folder
//! (`input::video::cache`), so a second run reads it at once. The app tracks on a
//! worker instead ([`pending`]): a key never waits for it.

use std::path::Path;

use super::args::{DataArgs, SceneArgs};
use super::error::CliError;
use super::progress::Bar;
use super::track;
use crate::input::video::cache::{self, Kept};
use crate::input::video::tracked::Options;
use crate::settings::params::Key;
use crate::settings::spec::SceneSpec;

/// Names of video files (by their extension).
const VIDEO_EXTENSIONS: [&str; 11] = [
    "mp4", "mov", "m4v", "mkv", "avi", "webm", "3gp", "mts", "m2ts", "mpg", "gif",
];

/// True when `path` is a video (named as one) or a folder, not a data file: a folder
/// given as data can only be one of frames, and one without them is refused as such
/// ("holds 0 PNG/JPEG frames"), `--fps` taken, not as a directory where a file was
/// allowed.
pub fn is_video(path: &Path) -> bool {
    let named = path
        .extension()
        .and_then(|e| e.to_str())
        .is_some_and(|e| VIDEO_EXTENSIONS.contains(&e.to_ascii_lowercase().as_str()));
    named || path.is_dir()
}

/// What the tracking of a `--data` video is asked: R of the scene options, `--fps`,
/// `--scale`, `--roi` and `--ball-at`.
pub fn options(scene: &SceneArgs, data: &DataArgs) -> Result<Options, CliError> {
    track::options(scene, data)
}

/// The scene a video's tracks state: the R its scale came from (the text's
/// `# scene radius` line), known before tracking.
pub fn own_scene(scene: &SceneArgs, data: &DataArgs) -> Result<SceneSpec, CliError> {
    Ok(SceneSpec::default().with(Key::Radius, options(scene, data)?.radius))
}

/// The tracks of the video `path` for the scene `scene`: kept, or tracked now with a
/// progress bar on a terminal (Ctrl-C stops it).
pub fn tracks(path: &Path, scene: &SceneArgs, data: &DataArgs) -> Result<Kept, CliError> {
    let options = options(scene, data)?;
    let bar = Bar::new("frames", true);
    let done = cache::tracks(path, &options, &bar).map_err(|r| CliError::from(r.error));
    bar.finish();
    done?.ok_or(CliError::Interrupted)
}

/// The Tracker-style text of the video `path` ([`tracks`]).
pub fn text(path: &Path, scene: &SceneArgs, data: &DataArgs) -> Result<String, CliError> {
    tracks(path, scene, data).map(|k| k.text)
}

/// A `--data` video the app will track on a worker: not kept yet, and readable (a
/// video ffprobe reads, or a folder of frames: checked now, so bad input is refused
/// before the app starts). `None` when there is none to track (none given, or kept).
pub fn pending(scene: &SceneArgs, data: &DataArgs) -> Result<Option<Options>, CliError> {
    let [path] = data.data.as_slice() else {
        return Ok(None);
    };
    if !is_video(path) {
        return Ok(None);
    }
    let options = options(scene, data)?;
    if cache::kept(path, &options).is_some() {
        return Ok(None);
    }
    let info = crate::input::video::check(path, &Default::default()).map_err(CliError::from)?;
    if info.rate(options.fps).is_none() {
        return Err(CliError::from(crate::input::video::VideoError::new(
            path,
            crate::input::video::VideoProblem::NoRate,
        )));
    }
    Ok(Some(options))
}
