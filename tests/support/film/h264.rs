//! A film as a phone would hand it over: its frames encoded with ffmpeg's libx264 at
//! the look's constant rate factor (`Look::crf`), and such a clip's frames decoded
//! back into RGB pictures for tracking in memory.

use std::io::Read;
use std::path::Path;
use std::process::{Command, Stdio};

use groovelab::input::video::write::{self, Encoding};
use image::RgbImage;

use super::Film;

/// Writes the first `frames` frames of `film` as the H.264 clip `path` (mp4), at the
/// look's crf (18, visually lossless, when the look has none).
pub fn write(path: &Path, film: &Film, frames: usize) -> Result<(), String> {
    pictures(path, &film.look, (0..frames).map(|k| film.rgb(k)))
}

/// Writes `rgb` (pictures of `look`'s size, RGB rows) as the H.264 clip `path` (mp4)
/// at the look's frame rate and crf (18 when it has none): a film's frames changed
/// as a camera would change them (repeated, moved).
pub fn pictures(
    path: &Path,
    look: &super::Look,
    rgb: impl Iterator<Item = Vec<u8>>,
) -> Result<(), String> {
    let enc = Encoding {
        width: look.width,
        height: look.height,
        fps: look.fps,
        crf: look.crf.unwrap_or(18),
        metadata: Vec::new(),
    };
    write::video(path, &enc, rgb).map_err(|e| e.to_string())
}

/// The speed clip of issue 34's target (`benches/video.rs`, `examples/film.rs`): 3 s
/// of the scene `s` at 240 frames/s in 1080p (720 frames), the balls slowed to
/// 0.4 m/s so both stay in view, H.264 at crf 18, written to `path`.
pub fn speed_clip(path: &Path, s: &groovelab::physics::scene::Scene) -> Result<(), String> {
    use groovelab::physics::scene::{Ball, Scene};
    let slow = Scene {
        left: Ball { v0: 0.4, ..s.left },
        right: Ball { v0: 0.4, ..s.right },
        ..*s
    };
    let look = super::Look {
        width: 1920,
        height: 1080,
        px_per_m: 1400.0,
        origin: (960.0, 500.0),
        fps: 240.0,
        from: -1.0,
        ..super::Look::default()
    };
    let film = Film::new(&slow, look, 2.0);
    write(path, &film, SPEED_CLIP_FRAMES)
}

/// Frames in [`speed_clip`].
pub const SPEED_CLIP_FRAMES: usize = 720;

/// The frames of the clip `path` (`width × height`), decoded to RGB by ffmpeg.
pub fn read(path: &Path, width: usize, height: usize) -> Result<Vec<RgbImage>, String> {
    let mut child = Command::new("ffmpeg")
        .args(["-v", "error", "-i"])
        .arg(path)
        .args(["-f", "rawvideo", "-pix_fmt", "rgb24", "pipe:1"])
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .map_err(|e| format!("ffmpeg: {e}"))?;
    let mut raw = Vec::new();
    child
        .stdout
        .take()
        .expect("piped")
        .read_to_end(&mut raw)
        .map_err(|e| e.to_string())?;
    child.wait().map_err(|e| e.to_string())?;
    let size = width * height * 3;
    Ok(raw
        .chunks_exact(size)
        .filter_map(|c| RgbImage::from_raw(width as u32, height as u32, c.to_vec()))
        .collect())
}
