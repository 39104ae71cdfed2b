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
    let l = &film.look;
    let enc = Encoding {
        width: l.width,
        height: l.height,
        fps: l.fps,
        crf: l.crf.unwrap_or(18),
        metadata: Vec::new(),
    };
    write::video(path, &enc, (0..frames).map(|k| film.rgb(k))).map_err(|e| e.to_string())
}

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
