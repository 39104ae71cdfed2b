//! `--data VIDEO`: a video given where a data file is read is
//! tracked as `groovelab track` would, and its Tracker-style text read as the data
//! file. The text is cached in the user's cache folder
//! (`$XDG_CACHE_HOME/groovelab/tracks`, else `~/.cache/groovelab/tracks`), keyed by
//! the video's content, R and the program's version, so a second run reads it at once; and kept for this process,
//! so the scene's and the series' reading track once.

use std::collections::HashMap;
use std::hash::{Hash, Hasher};
use std::io::Read;
use std::path::{Path, PathBuf};
use std::sync::Mutex;

use super::args::SceneArgs;
use super::error::CliError;
use super::track;

/// Names of video files (by their extension); a folder is frames.
const VIDEO_EXTENSIONS: [&str; 10] = [
    "mp4", "mov", "m4v", "mkv", "avi", "webm", "3gp", "mts", "m2ts", "mpg",
];

/// True when `path` is named as a video, not a data file. (A folder stays refused
/// as `--data`, which takes files; `track` reads a folder of frames.)
pub fn is_video(path: &Path) -> bool {
    path.extension()
        .and_then(|e| e.to_str())
        .is_some_and(|e| VIDEO_EXTENSIONS.contains(&e.to_ascii_lowercase().as_str()))
}

static DONE: Mutex<Option<HashMap<PathBuf, String>>> = Mutex::new(None);

/// The Tracker-style text of the video `path` for the scene `scene` (its R sets the
/// scale): from this process, the cache, or tracked now (and cached).
pub fn text(path: &Path, scene: &SceneArgs) -> Result<String, CliError> {
    if let Some(t) = DONE
        .lock()
        .ok()
        .and_then(|d| d.as_ref()?.get(path).cloned())
    {
        return Ok(t);
    }
    let (_, s, _) = scene.resolve()?;
    let key = key(path, s.radius)?;
    let cached = cache_dir().map(|d| d.join(format!("{key:016x}.txt")));
    let text = match cached
        .as_ref()
        .and_then(|c| std::fs::read_to_string(c).ok())
    {
        Some(t) => t,
        None => {
            let done = track::tracked(path, scene, None, None)?;
            let t = crate::study::vision::write::tracker_text(&done.tracks, &done.notes);
            if let Some(c) = &cached {
                // A cache that cannot be written is only slower next time.
                let _ =
                    std::fs::create_dir_all(c.parent().unwrap_or(Path::new("."))).and_then(|()| {
                        crate::output::write_atomically(c, t.as_bytes())
                            .map_err(std::io::Error::other)
                    });
            }
            t
        }
    };
    if let Ok(mut d) = DONE.lock() {
        d.get_or_insert_with(HashMap::new)
            .insert(path.to_path_buf(), text.clone());
    }
    Ok(text)
}

/// The user's cache folder for tracks, if there is one.
fn cache_dir() -> Option<PathBuf> {
    let base = std::env::var_os("XDG_CACHE_HOME")
        .filter(|v| !v.is_empty())
        .map(PathBuf::from)
        .or_else(|| std::env::var_os("HOME").map(|h| PathBuf::from(h).join(".cache")))?;
    Some(base.join("groovelab").join("tracks"))
}

/// The cache key: the content of the video, R, and the program's version.
fn key(path: &Path, radius: f64) -> Result<u64, CliError> {
    let mut h = std::collections::hash_map::DefaultHasher::new();
    env!("CARGO_PKG_VERSION").hash(&mut h);
    radius.to_bits().hash(&mut h);
    {
        let mut f = std::fs::File::open(path)?;
        let mut buf = vec![0u8; 1 << 20];
        loop {
            let n = f.read(&mut buf)?;
            if n == 0 {
                break;
            }
            buf[..n].hash(&mut h);
        }
    }
    Ok(h.finish())
}
