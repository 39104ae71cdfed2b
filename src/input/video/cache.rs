//! Tracks of a video kept, so a video is tracked once: in this process (the scene's
//! and the series' reading of `--data` share one tracking), and in the user's cache
//! folder (`$XDG_CACHE_HOME/groovelab/tracks`, else `~/.cache/groovelab/tracks`) as
//! the Tracker-style text and the app's pictures, keyed by the video's content (a
//! folder's: its files' names and bytes), the options and the tracker's own version
//! (`vision::VERSION`, raised whenever the tracker finds other numbers: the
//! program's version would keep old tracks of a better tracker).
//! A cache that cannot be written or read is only slower. The folder is the
//! options' (`Options::cache`), so a test keeps its own.

// Tracker rewrites this file (src/input/video is being reworked beside issue 35);
// its indexing, unwrap and expect are converted to `get` and errors after that.
use std::collections::HashMap;
use std::hash::{Hash, Hasher};
use std::io::Read;
use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex, PoisonError};

use super::tracked::{self, Options};
use crate::study::Progress;
use crate::vision::thumbs::VideoView;

/// A video's tracks as `--data` reads them, and the app's view of it (`None` when
/// its cached pictures were lost or damaged).
#[derive(Clone, Debug)]
pub struct Kept {
    pub text: String,
    pub view: Option<Arc<VideoView>>,
}

type Memo = HashMap<(PathBuf, String), Kept>;

static DONE: Mutex<Option<Memo>> = Mutex::new(None);

/// The process's key of a tracking: the path and the options.
fn process_key(path: &Path, o: &Options) -> (PathBuf, String) {
    (path.to_path_buf(), options_key(o))
}

/// The options that change the tracks, as text (exact: floats by their bits).
fn options_key(o: &Options) -> String {
    let bits = |v: Option<f64>| v.map(f64::to_bits);
    format!(
        "v{} {:x} {:?} {:?} {:?} {:?}",
        crate::vision::VERSION,
        o.radius.to_bits(),
        bits(o.fps),
        bits(o.px_per_m),
        o.roi
            .map(|r| [r.x, r.y, r.width, r.height].map(f64::to_bits)),
        o.ball_at.map(|(x, y)| [x, y].map(f64::to_bits)),
    )
}

/// The tracks of `path` kept in this process or in the cache folder, if any.
pub fn kept(path: &Path, options: &Options) -> Option<Kept> {
    let pk = process_key(path, options);
    if let Some(k) = DONE
        .lock()
        .unwrap_or_else(PoisonError::into_inner)
        .as_ref()
        .and_then(|d| d.get(&pk).cloned())
    {
        return Some(k);
    }
    let base = cache_file(path, options)?;
    let text = std::fs::read_to_string(base.with_extension("txt")).ok()?;
    let view = std::fs::read(base.with_extension("view"))
        .ok()
        .and_then(|b| VideoView::from_bytes(&b).ok())
        .map(Arc::new);
    let k = Kept { text, view };
    remember(pk, &k);
    Some(k)
}

fn remember(pk: (PathBuf, String), k: &Kept) {
    DONE.lock()
        .unwrap_or_else(PoisonError::into_inner)
        .get_or_insert_with(HashMap::new)
        .insert(pk, k.clone());
}

/// The tracks of `path`: kept ones, or tracked now (telling `progress`) and kept;
/// `Ok(None)` when `progress` asked to stop. A refusal is not kept (a seed may
/// change it); it holds the first frame for the app to show.
pub fn tracks(
    path: &Path,
    options: &Options,
    progress: &dyn Progress,
) -> Result<Option<Kept>, Box<tracked::Refused>> {
    if let Some(k) = kept(path, options) {
        return Ok(Some(k));
    }
    let Some(done) = tracked::track_or_found(path, options, progress, tracked::Pictures::Made)?
    else {
        return Ok(None);
    };
    let k = Kept {
        text: done.text(),
        view: Some(Arc::new(done.view)),
    };
    if let Some(base) = cache_file(path, options) {
        store(&base, &k);
    }
    remember(process_key(path, options), &k);
    Ok(Some(k))
}

/// Writes `k` under `base` (.txt, .view); failures are ignored (slower next time).
fn store(base: &Path, k: &Kept) {
    let Some(dir) = base.parent() else { return };
    if std::fs::create_dir_all(dir).is_err() {
        return;
    }
    let _ = crate::output::write_atomically(&base.with_extension("txt"), k.text.as_bytes());
    if let Some(v) = &k.view {
        let _ = crate::output::write_atomically(&base.with_extension("view"), &v.to_bytes());
    }
}

/// The cache file's path without its extension, if there is a cache folder and the
/// video can be read.
fn cache_file(path: &Path, options: &Options) -> Option<PathBuf> {
    let dir = options.cache.as_ref()?;
    let key = key(path, options).ok()?;
    Some(dir.join(format!("{key:016x}")))
}

/// The user's cache folder for tracks, if there is one.
pub fn user_folder() -> Option<PathBuf> {
    let base = std::env::var_os("XDG_CACHE_HOME")
        .filter(|v| !v.is_empty())
        .map(PathBuf::from)
        .or_else(|| std::env::var_os("HOME").map(|h| PathBuf::from(h).join(".cache")))?;
    Some(base.join("groovelab").join("tracks"))
}

/// The cache key: the content of the video (a folder's frames, names and bytes, in
/// order: only its PNG/JPEG files, so a folder of other files is refused before a
/// byte of them is read), the options and the tracker's version.
fn key(path: &Path, o: &Options) -> std::io::Result<u64> {
    let mut h = std::collections::hash_map::DefaultHasher::new();
    options_key(o).hash(&mut h);
    if path.is_dir() {
        let mut files: Vec<PathBuf> = std::fs::read_dir(path)?
            .flatten()
            .map(|e| e.path())
            .filter(|p| p.is_file() && super::folder::is_image(p))
            .collect();
        files.sort();
        for f in files {
            f.file_name().hash(&mut h);
            hash_file(&f, &mut h)?;
        }
    } else {
        hash_file(path, &mut h)?;
    }
    Ok(h.finish())
}

/// Hashes a regular file's bytes; anything else is an error, never opened: a FIFO's
/// open waits for a writer for ever, a device's bytes never end.
fn hash_file(path: &Path, h: &mut impl Hasher) -> std::io::Result<()> {
    if !std::fs::metadata(path)?.is_file() {
        return Err(std::io::Error::other("not a regular file"));
    }
    let mut f = std::fs::File::open(path)?;
    let mut buf = vec![0u8; 1 << 20];
    loop {
        let n = f.read(&mut buf)?;
        if n == 0 {
            return Ok(());
        }
        buf.get(..n).unwrap_or_default().hash(h);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn options() -> Options {
        Options {
            radius: 0.0275,
            fps: Some(240.0),
            px_per_m: None,
            radius_from: "--radius".into(),
            cache: None,
            roi: None,
            ball_at: None,
        }
    }

    #[test]
    fn the_key_changes_with_every_option_that_changes_the_tracks() {
        let base = options_key(&options());
        assert_eq!(base, options_key(&options()));
        assert!(base.starts_with(&format!("v{} ", crate::vision::VERSION)));
        let roi = Options {
            roi: Some(crate::vision::Roi {
                x: 0.0,
                y: 10.0,
                width: 100.0,
                height: 50.0,
            }),
            ..options()
        };
        let seed = Options {
            ball_at: Some((12.0, 30.0)),
            ..options()
        };
        let fps = Options {
            fps: Some(120.0),
            ..options()
        };
        let keys = [
            base,
            options_key(&roi),
            options_key(&seed),
            options_key(&fps),
        ];
        for (i, a) in keys.iter().enumerate() {
            for b in &keys[i + 1..] {
                assert_ne!(a, b);
            }
        }
        // Where the tracks are kept (not what they are) is no part of the key.
        let elsewhere = Options {
            cache: Some(PathBuf::from("elsewhere")),
            ..options()
        };
        assert_eq!(options_key(&elsewhere), keys[0]);
    }
}
