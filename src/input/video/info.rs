//! What a video or a folder of frames is, before its frames are read: the types the
//! readers share (why one cannot be read is `problem`'s).

use crate::vision::Frame;

use super::problem::{VideoError, VideoProblem};

/// Where the frame rate comes from.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum RateSource {
    /// The container's frame rate.
    Container,
    /// A slow-motion capture rate in the file's metadata (the key named).
    Capture(String),
    /// Given on the command line (`--fps`).
    Given,
}

/// What was opened, before any frame is read.
#[derive(Clone, Debug, PartialEq)]
pub struct Info {
    /// "video (h264, mov,mp4,m4a,3gp,3g2,mj2)" or "folder of PNG/JPEG frames".
    pub kind: String,
    pub width: usize,
    pub height: usize,
    /// Frames expected (a video's estimate, a folder's count).
    pub frames: u64,
    /// The container's rate (frames/s) and a capture rate found in the metadata.
    pub container_fps: Option<f64>,
    pub capture_fps: Option<(f64, String)>,
    /// A folder's frame numbers where frames are missing, as runs `[first, last]`.
    pub gaps: Vec<[u64; 2]>,
    /// The video stream's own duration, s, where the container gives one.
    pub duration: Option<f64>,
}

impl Info {
    /// Why the container's frame rate `fps` cannot be the clip's, seen after its
    /// `frames` were decoded: at `fps` they would span a time other than the
    /// stream's own duration (by a tenth of it and two frames' time), as in a clip
    /// whose frames are unevenly spaced, where the container's rate is a guess
    /// (ffprobe's `r_frame_rate` of a clip with frames 15 and 18 ms apart said 60
    /// frames/s for a clip of 30: every speed twice the truth).
    pub fn rate_in_doubt(&self, frames: u64, fps: f64) -> Option<VideoProblem> {
        let duration = self.duration.filter(|d| d.is_finite() && *d > 0.0)?;
        let span = frames as f64 / fps;
        let off = (span - duration).abs() > (0.1 * duration).max(2.0 / fps);
        (frames >= 3 && fps.is_finite() && fps > 0.0 && off).then_some(VideoProblem::RateInDoubt {
            frames,
            fps,
            duration,
        })
    }

    /// The rate to use: `given`, else a capture rate in the metadata, else the
    /// container's; `None` when none is known (a folder without `--fps`).
    pub fn rate(&self, given: Option<f64>) -> Option<(f64, RateSource)> {
        if let Some(f) = given {
            return Some((f, RateSource::Given));
        }
        if let Some((f, key)) = &self.capture_fps {
            return Some((*f, RateSource::Capture(key.clone())));
        }
        self.container_fps.map(|f| (f, RateSource::Container))
    }
}

/// A frame source: each item one frame (in colour) and its number (a folder's numbers
/// may skip; a video's count up from 0).
pub type Frames = Box<dyn Iterator<Item = Result<(u64, Frame), VideoError>> + Send>;

/// How much video `track` takes on: larger is refused before any frame is decoded.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Limits {
    /// Most pixels over all frames (width × height × frames). Default 5e10: about
    /// 100 s of 1080p at 240 frames/s, or 100 s of 4K at 60.
    pub pixels: f64,
    /// Largest frame side, px. Default 8192.
    pub side: usize,
}

impl Default for Limits {
    fn default() -> Self {
        Limits {
            pixels: 5e10,
            side: 8192,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn video(duration: Option<f64>) -> Info {
        Info {
            kind: "video".into(),
            width: 854,
            height: 480,
            frames: 27,
            container_fps: Some(60.0),
            capture_fps: None,
            gaps: Vec::new(),
            duration,
        }
    }

    #[test]
    fn a_rate_the_streams_duration_contradicts_is_in_doubt() {
        // A new user's clip: 27 frames lasting 0.9 s, its frames 15 and 18 ms apart,
        // ffprobe's rate 60: every speed twice the truth, μ_k 0.67 "agrees".
        let jittered = video(Some(0.9));
        let what = jittered.rate_in_doubt(27, 60.0).map(|w| w.to_string());
        let what = what.expect("in doubt");
        assert!(
            what.contains("would span 0.450 s") && what.contains("30.00 frames/s"),
            "{what}"
        );
        // The rate that fits, frames lost at the end (within a tenth), or no duration.
        assert!(jittered.rate_in_doubt(27, 30.0).is_none());
        assert!(jittered.rate_in_doubt(26, 30.0).is_none());
        assert!(jittered.rate_in_doubt(25, 30.0).is_none());
        assert!(video(None).rate_in_doubt(27, 60.0).is_none());
        // Half the frames, or twice the rate: in doubt either way.
        assert!(jittered.rate_in_doubt(13, 30.0).is_some());
        assert!(jittered.rate_in_doubt(27, 15.0).is_some());
        // Two frames' time at least: a 3-frame clip off by one frame is not doubted.
        assert!(video(Some(0.1)).rate_in_doubt(4, 30.0).is_none());
    }
}
