//! What a video or a folder of frames is, before its frames are read: the types the
//! readers share (why one cannot be read is `problem`'s).

use crate::vision::Frame;

use super::problem::VideoError;

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
}

impl Info {
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
