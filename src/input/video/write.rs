//! Writing frames and videos: PNG frames (the `image` crate) and an H.264 mp4
//! encoded by the system's `ffmpeg` from raw RGB frames piped to it. For the tests'
//! and benchmarks' synthetic videos, and for anyone who wants to see them.

// Tracker rewrites this file (src/input/video is being reworked beside issue 35);
// its indexing, unwrap and expect are converted to `get` and errors after that.
use std::io::Write;
use std::path::Path;
use std::process::{Command, Stdio};

use super::problem::{VideoError, VideoProblem};

/// Writes one RGB frame (`width × height × 3` bytes) as a PNG file.
pub fn png(path: &Path, rgb: &[u8], width: usize, height: usize) -> Result<(), VideoError> {
    image::save_buffer(
        path,
        rgb,
        width as u32,
        height as u32,
        image::ExtendedColorType::Rgb8,
    )
    .map_err(|e| VideoError::new(path, VideoProblem::WriteImage(e)))
}

/// How a video is encoded.
#[derive(Clone, Debug, PartialEq)]
pub struct Encoding {
    pub width: usize,
    pub height: usize,
    /// The container's frame rate.
    pub fps: f64,
    /// x264's constant rate factor (0 lossless … 51; 18 looks lossless).
    pub crf: u32,
    /// Metadata `key=value` written into the container (e.g. a capture rate).
    pub metadata: Vec<(String, String)>,
}

/// Encodes the RGB frames `frames` into the video `path` (mp4, mov or mkv, by its
/// name) with ffmpeg's libx264.
pub fn video(
    path: &Path,
    enc: &Encoding,
    frames: impl Iterator<Item = Vec<u8>>,
) -> Result<(), VideoError> {
    let err = |what: VideoProblem| VideoError::new(path, what);
    let mut cmd = Command::new("ffmpeg");
    cmd.args([
        "-v", "error", "-y", "-f", "rawvideo", "-pix_fmt", "rgb24", "-s",
    ])
    .arg(format!("{}x{}", enc.width, enc.height))
    .args(["-r", &format!("{}", enc.fps), "-i", "pipe:0"])
    .args([
        "-c:v", "libx264", "-preset", "veryfast", "-pix_fmt", "yuv420p", "-crf",
    ])
    .arg(enc.crf.to_string())
    // x264's output depends on its thread count, by default one and a half per
    // core: three, as on the 2-core machines the video tests were set on, gives the
    // same clip on any machine.
    .args(["-threads", "3"]);
    if !enc.metadata.is_empty() {
        cmd.args(["-movflags", "use_metadata_tags"]);
    }
    for (k, v) in &enc.metadata {
        cmd.arg("-metadata").arg(format!("{k}={v}"));
    }
    let mut child = cmd
        .arg(path)
        .stdin(Stdio::piped())
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .map_err(|e| err(VideoProblem::cannot_run("ffmpeg", e)))?;
    let mut stdin = child.stdin.take().ok_or_else(|| {
        err(VideoProblem::cannot_run(
            "ffmpeg",
            std::io::Error::other("its input could not be opened"),
        ))
    })?;
    let mut broken = None;
    for f in frames {
        if let Err(e) = stdin.write_all(&f) {
            broken = Some(e);
            break;
        }
    }
    drop(stdin);
    let out = child
        .wait_with_output()
        .map_err(|e| err(VideoProblem::Ffmpeg(e)))?;
    if !out.status.success() || broken.is_some() {
        return Err(err(VideoProblem::Encode {
            ffmpeg_says: String::from_utf8_lossy(&out.stderr).trim().to_string(),
        }));
    }
    Ok(())
}
