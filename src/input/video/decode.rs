//! A video's frames streamed from the system's `ffmpeg`: its first video stream
//! decoded to yuv420p (h264's own format: no conversion, colour kept; turned as the
//! phone meant it) and piped raw, one frame read at a time, all of them or every
//! k-th (`open_every`'s sample; `track` decodes once, all of them); ffmpeg's own
//! messages gathered on a thread and said when it fails or stops short (a truncated
//! or damaged file).

// Tracker rewrites this file (src/input/video is being reworked beside issue 35);
// its indexing, unwrap and expect are converted to `get` and errors after that.
use std::io::Read;
use std::path::Path;
use std::process::{Child, ChildStdout, Command, Stdio};
use std::sync::Mutex;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::thread::JoinHandle;

use super::info::{Frames, Info};
use super::probe::url;
use super::problem::{VideoError, VideoProblem};
use crate::vision::Frame;
use crate::vision::band::Band;

/// The frames of the video at `path` (as `info` describes it): every `every`-th
/// (1: all), numbered as in the video.
pub(super) fn frames(path: &Path, info: &Info, every: usize) -> Result<Frames, VideoError> {
    Ok(stream(spawn(path, every)?, info))
}

/// ffmpeg started on `path`, decoding every `every`-th frame into its pipe, before
/// the frames' size is known (`open_if` starts it beside ffprobe: each takes a
/// tenth of a second to start, one after the other they kept a core idle).
/// Dropped unread, ffmpeg is ended.
pub(super) struct Started {
    file: std::path::PathBuf,
    child: Option<Child>,
    stdout: Option<ChildStdout>,
    messages: Option<JoinHandle<String>>,
    every: u64,
}

impl Drop for Started {
    fn drop(&mut self) {
        // Not streamed (the file refused, an error): end ffmpeg, never leave it running.
        if let Some(mut c) = self.child.take() {
            let _ = c.kill();
            let _ = c.wait();
        }
    }
}

/// The frames of the video at `path` (as `info` describes it), all of them, cut
/// by ffmpeg to the rows of `band` (after its decoding: only those rows are piped).
pub(super) fn band_frames(path: &Path, info: &Info, band: &Band) -> Result<Frames, VideoError> {
    let cut = Info {
        height: band.height,
        ..info.clone()
    };
    Ok(stream(spawn_cut(path, 1, Some(band))?, &cut))
}

/// Starts ffmpeg decoding `path` (every `every`-th frame) into a pipe.
pub(super) fn spawn(path: &Path, every: usize) -> Result<Started, VideoError> {
    spawn_cut(path, every, None)
}

/// As [`spawn`], the frames cut to `band`'s rows (exactly: its top is even).
fn spawn_cut(path: &Path, every: usize, band: Option<&Band>) -> Result<Started, VideoError> {
    let file = path.to_path_buf();
    let every = every.max(1);
    let mut cmd = Command::new("ffmpeg");
    cmd.args(["-v", "error", "-nostdin", "-i"])
        .arg(url(path))
        .args(["-map", "0:v:0"]);
    // One filter chain: ffmpeg keeps only the last `-vf` given.
    let mut filters = Vec::new();
    if let Some(b) = band {
        filters.push(format!("crop=w=iw:h={}:x=0:y={}:exact=1", b.height, b.y));
    }
    if every > 1 {
        filters.push(format!("select=not(mod(n\\,{every}))"));
        cmd.args(["-fps_mode", "passthrough"]);
    }
    if !filters.is_empty() {
        cmd.args(["-vf", &filters.join(",")]);
    }
    // The raw frames copied out in ffmpeg's own thread (`-threads 1` for the
    // output's rawvideo "encoder", a copy): spread over its frame threads the copy
    // took 11 % more of ffmpeg's time, not less, and the decoding keeps its threads.
    let mut child = cmd
        .args([
            "-threads", "1", "-f", "rawvideo", "-pix_fmt", "yuv420p", "pipe:1",
        ])
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .map_err(|e| VideoError::new(path, VideoProblem::cannot_run("ffmpeg", e)))?;
    let piped = |e: &str| {
        VideoError::new(
            path,
            VideoProblem::cannot_run("ffmpeg", std::io::Error::other(e.to_string())),
        )
    };
    let (Some(stdout), Some(mut stderr)) = (child.stdout.take(), child.stderr.take()) else {
        let _ = child.kill();
        let _ = child.wait();
        return Err(piped("no stdout or stderr"));
    };
    widen(&stdout);
    let messages = std::thread::spawn(move || {
        let mut s = String::new();
        let _ = (&mut stderr).take(64 * 1024).read_to_string(&mut s);
        // Drain the rest so ffmpeg never blocks on a full pipe.
        let _ = std::io::copy(&mut stderr, &mut std::io::sink());
        s
    });
    Ok(Started {
        file,
        child: Some(child),
        stdout: Some(stdout),
        messages: Some(messages),
        every: every as u64,
    })
}

/// The frames of a started ffmpeg (`spawn`), `info` describing its video.
pub(super) fn stream(mut started: Started, info: &Info) -> Frames {
    // Always there: `spawn` gives both.
    let (Some(child), Some(stdout)) = (started.child.take(), started.stdout.take()) else {
        return Box::new(std::iter::empty());
    };
    STREAMS.fetch_add(1, Ordering::Relaxed);
    let every = started.every;
    Box::new(Stream {
        file: std::mem::take(&mut started.file),
        child: Some(child),
        stdout,
        messages: started.messages.take(),
        width: info.width,
        height: info.height,
        expected: info.frames.div_ceil(every),
        every,
        next: 0,
    })
}

struct Stream {
    file: std::path::PathBuf,
    child: Option<Child>,
    /// Unbuffered: whole planes are read at once, straight into their buffers.
    stdout: ChildStdout,
    messages: Option<JoinHandle<String>>,
    width: usize,
    height: usize,
    expected: u64,
    every: u64,
    next: u64,
}

impl Stream {
    /// After the last frame: ffmpeg's verdict. An error when it failed, or when far
    /// fewer frames came than the file said it holds.
    fn finish(&mut self) -> Option<VideoError> {
        let status = self.child.take()?.wait().ok();
        let messages = self
            .messages
            .take()
            .and_then(|m| m.join().ok())
            .unwrap_or_default();
        let said = messages
            .lines()
            .rev()
            .find(|l| !l.trim().is_empty())
            .map(|l| l.trim().to_string());
        let failed = status.is_none_or(|s| !s.success());
        let short = self.expected > 0 && self.next * 10 < self.expected * 9;
        if short && !failed && said.is_none() {
            return Some(VideoError::new(
                &self.file,
                VideoProblem::TimestampsCollide {
                    decoded: self.next,
                    expected: self.expected,
                },
            ));
        }
        if (failed && self.next == 0) || short {
            return Some(VideoError::new(
                &self.file,
                VideoProblem::Undecodable {
                    decoded: self.next,
                    expected: self.expected,
                    ffmpeg_says: said,
                },
            ));
        }
        None
    }
}

impl Iterator for Stream {
    type Item = Result<(u64, Frame), VideoError>;

    fn next(&mut self) -> Option<Self::Item> {
        self.child.as_ref()?;
        // The three planes read straight into buffers of their own: no zeroing
        // first, no copying apart (3 MB a 1080p frame).
        let (w, h) = (self.width, self.height);
        let (cw, ch) = crate::vision::frame::chroma_size(w, h);
        let planes = [w * h, cw * ch, cw * ch].map(|n| plane(&mut self.stdout, n));
        match planes {
            [Some(luma), Some(u), Some(v)] => {
                let k = self.next * self.every;
                self.next += 1;
                let frame = Frame {
                    luma: crate::vision::Gray {
                        width: w,
                        height: h,
                        data: luma,
                    },
                    chroma_width: cw,
                    chroma_height: ch,
                    u,
                    v,
                };
                Some(Ok((k, frame)))
            }
            _ => self.finish().map(Err),
        }
    }
}

/// The pipe's room, bytes: 1 MiB (Linux's most for a user without privileges).
const PIPE_BYTES: usize = 1 << 20;

/// The pipe from ffmpeg widened from 64 KiB to [`PIPE_BYTES`]: ffmpeg and the
/// reader then wait on each other, and wake each other, every megabyte instead of
/// every 64 KiB (48 times a 1080p frame). Refused (an older kernel, a lower limit):
/// the pipe stays as it was, only slower.
#[cfg(target_os = "linux")]
fn widen(pipe: &ChildStdout) {
    let _ = rustix::pipe::fcntl_setpipe_size(pipe, PIPE_BYTES);
}

#[cfg(not(target_os = "linux"))]
fn widen(_pipe: &ChildStdout) {}

/// Plane buffers of frames the tracker is done with ([`recycle`]), read into again
/// while a video streams: a new 3 MB buffer per 1080p frame is the system's work of
/// mapping and zeroing its pages, then of unmapping them.
static SPARE: Mutex<Vec<Vec<u8>>> = Mutex::new(Vec::new());
/// Most buffers kept spare (the planes of the frames the reader may run ahead,
/// `tracked::READ_BYTES`, and a few more: a 1080p frame is three buffers). Never
/// more than were in use at once.
const SPARE_MAX: usize = 3 * 24;
/// Streams open: with none, a buffer given back is freed, nothing is kept.
static STREAMS: AtomicUsize = AtomicUsize::new(0);

/// Gives a frame's buffers back for the next frames a stream reads (freed when no
/// stream is open, or enough are kept).
pub(super) fn recycle(frame: Frame) {
    if STREAMS.load(Ordering::Relaxed) == 0 {
        return;
    }
    let Ok(mut spare) = SPARE.lock() else { return };
    for b in [frame.luma.data, frame.u, frame.v] {
        if spare.len() < SPARE_MAX {
            spare.push(b);
        }
    }
}

/// A spare buffer of at least `n` bytes' capacity (the smallest), else a new one.
fn spare(n: usize) -> Vec<u8> {
    let reused = SPARE.lock().ok().and_then(|mut s| {
        let (i, _) = s
            .iter()
            .enumerate()
            .filter(|(_, b)| b.capacity() >= n)
            .min_by_key(|(_, b)| b.capacity())?;
        Some(s.swap_remove(i))
    });
    let mut buf = reused.unwrap_or_else(|| Vec::with_capacity(n));
    buf.clear();
    buf
}

/// The next `n` bytes of `r`, `None` when fewer come (the stream's end, an error).
fn plane(r: &mut impl Read, n: usize) -> Option<Vec<u8>> {
    let mut buf = spare(n);
    r.take(n as u64).read_to_end(&mut buf).ok()?;
    (buf.len() == n).then_some(buf)
}

impl Drop for Stream {
    fn drop(&mut self) {
        // The last stream closed: its spare buffers freed.
        if STREAMS.fetch_sub(1, Ordering::Relaxed) == 1
            && let Ok(mut s) = SPARE.lock()
        {
            s.clear();
        }
        // Stopped early (an error, Ctrl-C): end ffmpeg, never leave it running.
        if let Some(mut c) = self.child.take() {
            let _ = c.kill();
            let _ = c.wait();
        }
    }
}
