//! What a video file is, from `ffprobe`'s JSON: its first video stream's size (turned
//! as the phone meant it), the container's frame rate, a slow-motion capture rate
//! where the metadata holds one (Android's `com.android.capture.fps`, any
//! `…capture.fps` key), its length; and the refusals: no video stream (audio), a
//! still image, a file ffprobe cannot read, a video too large to track.

// Tracker rewrites this file (src/input/video is being reworked beside issue 35);
// its indexing, unwrap and expect are converted to `get` and errors after that.
use std::path::Path;
use std::process::Command;

use serde_json::Value;

use super::info::{Info, Limits};
use super::problem::{VideoError, VideoProblem};

/// ffprobe's answer for a file.
#[derive(Clone, Debug, PartialEq)]
pub struct Probe {
    pub json: Value,
}

/// Files probed lately, by path, length and time modified: a file tracked again
/// (its band, then its whole frame; a retry; the app's second open) is probed
/// once, not once per opening (each ffprobe is a process start, some 70 ms).
type Probed = std::collections::HashMap<(std::path::PathBuf, u64, std::time::SystemTime), Probe>;

/// Most files whose probes are kept ([`cached`]); past it the memory starts over.
const PROBES_KEPT: usize = 64;

/// As [`probe`], a file probed before (the same path, length and time modified)
/// answered from memory. A file whose time modified is unknown is probed anew.
pub fn cached(path: &Path, meta: &std::fs::Metadata) -> Result<Probe, VideoError> {
    static PROBED: std::sync::OnceLock<std::sync::Mutex<Probed>> = std::sync::OnceLock::new();
    let Ok(modified) = meta.modified() else {
        return probe(path);
    };
    let key = (path.to_path_buf(), meta.len(), modified);
    let memory = PROBED.get_or_init(Default::default);
    if let Some(p) = memory.lock().ok().and_then(|m| m.get(&key).cloned()) {
        return Ok(p);
    }
    let p = probe(path)?;
    if let Ok(mut m) = memory.lock() {
        if m.len() >= PROBES_KEPT {
            m.clear();
        }
        m.insert(key, p.clone());
    }
    Ok(p)
}

/// Runs ffprobe on `path`.
pub fn probe(path: &Path) -> Result<Probe, VideoError> {
    let err = |what: VideoProblem| VideoError::new(path, what);
    let out = Command::new("ffprobe")
        .args([
            "-v",
            "error",
            "-print_format",
            "json",
            "-show_format",
            "-show_streams",
        ])
        .arg(url(path))
        .stdin(std::process::Stdio::null())
        .output()
        .map_err(|e| err(VideoProblem::cannot_run("ffprobe", e)))?;
    let json: Option<Value> = serde_json::from_slice(&out.stdout).ok();
    let has_format = json.as_ref().is_some_and(|j| j.get("format").is_some());
    if !out.status.success() || !has_format {
        if is_text(path) {
            return Err(err(VideoProblem::Text));
        }
        let why = String::from_utf8_lossy(&out.stderr);
        let why = why
            .lines()
            .rev()
            .find(|l| !l.trim().is_empty())
            .unwrap_or("")
            .trim();
        return Err(err(VideoProblem::Unreadable {
            ffprobe_says: (!why.is_empty()).then(|| {
                why.trim_start_matches(&format!("{}: ", path.display()))
                    .to_string()
            }),
        }));
    }
    Ok(Probe {
        json: json.unwrap_or(Value::Null),
    })
}

/// True when the file begins as text does (a data table, a tracks file): its first
/// 4 KiB are UTF-8 (a character cut at the end aside) with no control character but
/// tabs and line ends. Every video container has binary bytes in its first block.
fn is_text(path: &Path) -> bool {
    use std::io::Read;
    let mut head = Vec::with_capacity(4096);
    let read = std::fs::File::open(path).and_then(|f| f.take(4096).read_to_end(&mut head));
    if read.is_err() || head.is_empty() {
        return false;
    }
    let text = match std::str::from_utf8(&head) {
        Ok(t) => t,
        // A character cut by the 4 KiB: the part before it is the test.
        Err(e) if e.error_len().is_none() => {
            std::str::from_utf8(head.get(..e.valid_up_to()).unwrap_or_default()).unwrap_or("")
        }
        Err(_) => return false,
    };
    !text.is_empty()
        && text
            .chars()
            .all(|c| !c.is_control() || matches!(c, '\t' | '\n' | '\r'))
}

/// `path` as ffmpeg's `file:` URL, so a name like `-x.mp4` or `a:b.mp4` is a file.
pub(super) fn url(path: &Path) -> std::ffi::OsString {
    let mut s = std::ffi::OsString::from("file:");
    s.push(path.as_os_str());
    s
}

/// A rate written as `30000/1001` or `29.97`; `None` for 0/0 and nonsense.
fn rate(text: &str) -> Option<f64> {
    let v = match text.split_once('/') {
        Some((n, d)) => n.trim().parse::<f64>().ok()? / d.trim().parse::<f64>().ok()?,
        None => text.trim().parse().ok()?,
    };
    (v.is_finite() && v > 0.0 && v < 1e5).then_some(v)
}

impl Probe {
    /// What the file holds, refused when it is no video or too large for `limits`.
    #[allow(clippy::indexing_slicing)] // serde_json's `Value[key]` gives Null for a missing key, never panics
    pub fn info(&self, file: &Path, limits: &Limits) -> Result<Info, VideoError> {
        let err = |what: VideoProblem| VideoError::new(file, what);
        let streams = self.json["streams"].as_array().cloned().unwrap_or_default();
        let format = &self.json["format"];
        let format_name = format["format_name"].as_str().unwrap_or("?");
        // A music file's cover picture is a "video" stream too, marked attached_pic.
        let Some(v) = streams
            .iter()
            .find(|s| s["codec_type"] == "video" && s["disposition"]["attached_pic"] != 1)
        else {
            let audio = streams.iter().find(|s| s["codec_type"] == "audio");
            return Err(err(match audio {
                Some(a) => VideoProblem::OnlyAudio {
                    codec: a["codec_name"].as_str().unwrap_or("?").to_string(),
                },
                None => VideoProblem::NoVideoStream,
            }));
        };
        let codec = v["codec_name"].as_str().unwrap_or("?");
        // ffmpeg reads a text file (a .txt of tracks, say) as a video of its
        // characters drawn as in a terminal (the `tty` demuxer, codec `ansi`).
        if format_name == "tty" || codec == "ansi" {
            return Err(err(VideoProblem::Text));
        }
        let frames_said = v["nb_frames"].as_str().and_then(|n| n.parse::<u64>().ok());
        let still = format_name.contains("image2")
            || format_name.ends_with("_pipe")
            || (frames_said == Some(1));
        if still {
            return Err(err(VideoProblem::StillVideo {
                codec: codec.to_string(),
            }));
        }
        let (mut w, mut h) = (
            v["width"].as_u64().unwrap_or(0) as usize,
            v["height"].as_u64().unwrap_or(0) as usize,
        );
        if rotation(v).is_some_and(|r| (r.abs() / 90.0).round() as i64 % 2 == 1) {
            std::mem::swap(&mut w, &mut h);
        }
        if w < 16 || h < 16 || w > limits.side || h > limits.side {
            return Err(err(VideoProblem::FrameSide {
                width: w,
                height: h,
                max_side: limits.side,
            }));
        }
        let container_fps = v["r_frame_rate"]
            .as_str()
            .and_then(rate)
            .or_else(|| v["avg_frame_rate"].as_str().and_then(rate));
        let duration = v["duration"]
            .as_str()
            .or(format["duration"].as_str())
            .and_then(|d| d.parse::<f64>().ok())
            .filter(|d| d.is_finite() && *d >= 0.0);
        let frames = frames_said
            .or_else(|| Some((duration? * container_fps?).round() as u64))
            .unwrap_or(0);
        let pixels = (w * h) as f64 * frames as f64;
        if pixels > limits.pixels {
            return Err(err(VideoProblem::TooMuchVideo {
                width: w,
                height: h,
                frames,
                duration,
                max_pixels: limits.pixels,
            }));
        }
        Ok(Info {
            kind: format!("video ({codec}, {format_name})"),
            width: w,
            height: h,
            frames,
            container_fps,
            capture_fps: capture_rate(&[&format["tags"], &v["tags"]]),
            gaps: Vec::new(),
            // The stream's own, not the file's (an audio track may run longer).
            duration: v["duration"]
                .as_str()
                .and_then(|d| d.parse::<f64>().ok())
                .filter(|d| d.is_finite() && *d > 0.0),
        })
    }
}

/// The stream's rotation in degrees (a phone held upright), if any.
#[allow(clippy::indexing_slicing)] // serde_json's `Value[key]` gives Null for a missing key, never panics
fn rotation(v: &Value) -> Option<f64> {
    let side = v["side_data_list"].as_array().and_then(|l| {
        l.iter().find_map(|d| {
            d["rotation"]
                .as_f64()
                .or_else(|| d["rotation"].as_i64().map(|r| r as f64))
        })
    });
    side.or_else(|| v["tags"]["rotate"].as_str().and_then(|r| r.parse().ok()))
        .filter(|r: &f64| *r != 0.0)
}

/// A slow-motion capture rate in the metadata `tags`: a key ending in `capture.fps`
/// or `capture_fps` (Android writes `com.android.capture.fps`).
fn capture_rate(tags: &[&Value]) -> Option<(f64, String)> {
    tags.iter()
        .filter_map(|t| t.as_object())
        .flatten()
        .find_map(|(k, v)| {
            let key = k.to_ascii_lowercase();
            if !(key.ends_with("capture.fps") || key.ends_with("capture_fps")) {
                return None;
            }
            let f = v.as_str().and_then(rate).or_else(|| v.as_f64())?;
            Some((f, k.clone()))
        })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn info(json: &str) -> Result<Info, VideoError> {
        Probe {
            json: serde_json::from_str(json).unwrap(),
        }
        .info(Path::new("v.mp4"), &Limits::default())
    }

    #[test]
    fn a_phone_slow_motion_file_gives_its_capture_rate() {
        let i = info(r#"{"format":{"format_name":"mov,mp4","duration":"4.0","tags":{"com.android.capture.fps":"240.000000"}},
            "streams":[{"codec_type":"video","codec_name":"h264","width":1920,"height":1080,"r_frame_rate":"30/1","nb_frames":"120"}]}"#).unwrap();
        assert_eq!(i.container_fps, Some(30.0));
        assert_eq!(
            i.capture_fps,
            Some((240.0, "com.android.capture.fps".into()))
        );
        assert_eq!(i.rate(None).unwrap().0, 240.0);
        assert_eq!(i.rate(Some(120.0)).unwrap().0, 120.0);
    }

    #[test]
    fn an_upright_phone_video_is_turned_and_an_hour_of_4k_refused() {
        let i = info(r#"{"format":{"format_name":"mov,mp4"},"streams":[{"codec_type":"video","codec_name":"h264","width":1920,"height":1080,"r_frame_rate":"30/1","nb_frames":"10","side_data_list":[{"rotation":-90}]}]}"#).unwrap();
        assert_eq!((i.width, i.height), (1080, 1920));
        let e = info(r#"{"format":{"format_name":"mov,mp4","duration":"3600"},"streams":[{"codec_type":"video","codec_name":"hevc","width":3840,"height":2160,"r_frame_rate":"30/1"}]}"#).unwrap_err();
        assert!(matches!(e.what, VideoProblem::TooMuchVideo { .. }), "{e}");
        assert!(e.to_string().contains("too much video"), "{e}");
        let e = info(r#"{"format":{"format_name":"mp3"},"streams":[{"codec_type":"audio","codec_name":"mp3"}]}"#).unwrap_err();
        assert!(e.to_string().contains("only audio (mp3)"), "{e}");
    }
}
