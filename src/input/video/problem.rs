//! Why a video or a folder of frames cannot be read or written, as values: sizes,
//! counts, the frames' paths, the system's own error and the words ffmpeg said; the
//! sentence is made only by `Display`, where the error is printed.

use std::path::{Path, PathBuf};

use crate::vision::{Handles, TracksError};

/// Why the video or folder `file` cannot be read (or written): `{file}: {what}`.
#[derive(Debug, thiserror::Error)]
#[error("{}: {what}", file.display())]
pub struct VideoError {
    pub file: PathBuf,
    pub what: VideoProblem,
}

impl VideoError {
    /// `what` is wrong with the video or folder `file`.
    pub fn new(file: &Path, what: impl Into<VideoProblem>) -> VideoError {
        VideoError {
            file: file.to_path_buf(),
            what: what.into(),
        }
    }
}

/// The install hint when ffmpeg or ffprobe is missing.
pub const INSTALL_FFMPEG: &str = "reading a video needs ffmpeg and ffprobe, which are not installed (Debian/Ubuntu: apt-get install ffmpeg; macOS: brew install ffmpeg); a folder of numbered PNG/JPEG frames needs neither";

/// What is wrong with a video or folder (the file itself is named by `VideoError`).
#[derive(Debug, thiserror::Error)]
pub enum VideoProblem {
    #[error("{INSTALL_FFMPEG}")]
    NoFfmpeg,
    /// `program` (ffmpeg, ffprobe) is installed but could not be started.
    #[error("cannot run {program}: {error}")]
    CannotRun {
        program: &'static str,
        error: std::io::Error,
    },
    #[error("cannot open: {}", crate::input::file::io_words(.0))]
    Open(std::io::Error),
    #[error("is not a regular file, expected a video or a folder of frames")]
    NotRegular,
    #[error("is empty (0 bytes), expected a video")]
    Empty,
    #[error(
        "is a still image, not a video; give a video, or a folder of numbered frames (frame0001.png, …)"
    )]
    StillImage,
    /// ffprobe could not read the file; its last line, if it said one.
    #[error(
        "is not a video ffmpeg can read (corrupt, truncated or another kind of file){}",
        ffprobe_says.as_ref().map(|s| format!(": ffprobe says '{s}'")).unwrap_or_default()
    )]
    Unreadable { ffprobe_says: Option<String> },
    #[error("has no video, only audio ({codec}), expected a video")]
    OnlyAudio { codec: String },
    #[error("has no video stream, expected a video")]
    NoVideoStream,
    #[error(
        "is a text file, not a video: a data file (tracks, a table) is not tracked but read as data, by --data FILE named as data (.txt, .csv, …; e.g. groovelab fit --data tracks.txt)"
    )]
    Text,
    #[error(
        "is a still image ({codec}), not a video; give a video, or a folder of numbered frames"
    )]
    StillVideo { codec: String },
    /// Frames of `width × height` px, beyond 16 … `max_side` px a side.
    #[error("frames of {width}×{height} pixels, allowed 16 to {max_side} on each side")]
    FrameSide {
        width: usize,
        height: usize,
        max_side: usize,
    },
    /// A video of more than `max_pixels` pixels over all its frames (`duration`, s).
    #[error(
        "{width}×{height} pixels × {frames} frames{} is too much video to track, allowed at most {max_pixels:.0e} pixels (about 100 s of 1080p at 240 frames/s); cut the clip to the collision first, e.g. ffmpeg -ss START -t 5 -i VIDEO -c copy clip.mp4",
        duration.map(|d| format!(" ({d:.0} s)")).unwrap_or_default()
    )]
    TooMuchVideo {
        width: usize,
        height: usize,
        frames: u64,
        duration: Option<f64>,
        max_pixels: f64,
    },
    /// ffmpeg decoded `decoded` frames of the `expected`; its last line, if any.
    #[error(
        "only {decoded} of {expected} frames could be decoded: the file is truncated or damaged{}",
        ffmpeg_says.as_ref().map(|s| format!(": ffmpeg says '{s}'")).unwrap_or_default()
    )]
    Undecodable {
        decoded: u64,
        expected: u64,
        ffmpeg_says: Option<String>,
    },
    /// ffmpeg ended well and said nothing, yet handed over `decoded` frames of the
    /// `expected`: it drops frames whose timestamps collide (all zero, as a muxer
    /// that writes none leaves them, or closer together than the clip's rate).
    #[error(
        "only {decoded} of {expected} frames came from ffmpeg, which reported no error: the frames' timestamps collide (all zero, or closer than the clip's rate); time each frame by its number with `ffmpeg -i IN -vf setpts=N/FPS/TB OUT.mp4` (FPS the rate it was filmed at) and track OUT.mp4"
    )]
    TimestampsCollide { decoded: u64, expected: u64 },
    #[error("cannot read the folder: {0}")]
    Folder(std::io::Error),
    #[error(
        "{} has no frame number in its name, expected numbered frames (frame0001.png, …)",
        frame.display()
    )]
    NoFrameNumber { frame: PathBuf },
    #[error(
        "{} and {} have the same frame number {number}",
        first.display(),
        second.display()
    )]
    SameFrameNumber {
        first: PathBuf,
        second: PathBuf,
        number: u64,
    },
    #[error(
        "holds {frames} PNG/JPEG frame{}, expected a folder of numbered frames (at least two)",
        if *frames == 1 { "" } else { "s" }
    )]
    TooFewImages { frames: usize },
    /// A folder of `frames` frames of `width × height` px, beyond the limits.
    #[error(
        "{frames} frames of {width}×{height} pixels is too much to track, allowed at most {max_pixels:.0e} pixels and {max_side} px a side"
    )]
    FolderTooLarge {
        frames: usize,
        width: usize,
        height: usize,
        max_pixels: f64,
        max_side: usize,
    },
    /// A frame of `size` px in a folder whose first frame is `first` px.
    #[error("is {}×{}, the first frame {}×{}", size.0, size.1, first.0, first.1)]
    FrameSize {
        size: (usize, usize),
        first: (usize, usize),
    },
    #[error("cannot read the image: {0}")]
    ReadImage(image::ImageError),
    #[error("cannot write the image: {0}")]
    WriteImage(image::ImageError),
    #[error("a folder of frames says no frame rate; give it with --fps (e.g. --fps 240)")]
    NoRate,
    /// `--ball-at X,Y` off the frames of `size` px.
    #[error(
        "--ball-at {},{} lies outside the frame, expected a point on a ball within its {}×{} pixels (X 0 to {}, Y 0 to {} from the top-left corner)",
        at.0, at.1, size.0, size.1, size.0.saturating_sub(1), size.1.saturating_sub(1)
    )]
    BallAtOutside {
        at: (f64, f64),
        size: (usize, usize),
    },
    /// `--ball-at X,Y` outside `--roi X,Y,W,H`, where the tracker does not look.
    #[error(
        "--ball-at {},{} lies outside --roi {},{},{},{}, expected a point on a ball inside the rectangle the tracker looks in",
        tenth(at.0), tenth(at.1), roi.0, roi.1, roi.2, roi.3
    )]
    BallAtOutsideRoi {
        at: (f64, f64),
        roi: (f64, f64, f64, f64),
    },
    /// `--roi X,Y,W,H` wholly off the frames of `size` px.
    #[error(
        "--roi {},{},{},{} lies wholly outside the frame, expected a rectangle over its {}×{} pixels (X 0 to {}, Y 0 to {} from the top-left corner)",
        roi.0, roi.1, roi.2, roi.3, size.0, size.1, size.0.saturating_sub(1), size.1.saturating_sub(1)
    )]
    RoiOutside {
        roi: (f64, f64, f64, f64),
        size: (usize, usize),
    },
    #[error("holds {frames} frame(s), expected a video")]
    TooFewFrames { frames: usize },
    /// The container's rate contradicted by the stream's duration
    /// (`Info::rate_in_doubt`).
    #[error(
        "its {frames} frames at the container's {} frames/s would span {:.3} s, but the video lasts {duration:.3} s (its frames are unevenly spaced, or the container's rate is wrong), so no times are given; give --fps (the frames' average rate here is {:.2} frames/s)",
        crate::settings::units::significant(*fps, 6), *frames as f64 / fps, *frames as f64 / duration
    )]
    RateInDoubt {
        frames: u64,
        fps: f64,
        duration: f64,
    },
    /// The balls not found or the tracker unsure: why, then what to try next, by
    /// the handles that could help and were not given (`--roi`, `--scale`, the seed
    /// `at`); a tracking seeded with `--ball-at` (or a click) says so, as the seed's
    /// outline set the balls' first radius and the clip may track without it.
    #[error("{error}{}", next_try(error, *roi, *scale, *at))]
    Tracks {
        error: TracksError,
        roi: bool,
        scale: bool,
        at: Option<(f64, f64)>,
    },
    /// Waiting for ffmpeg failed.
    #[error("ffmpeg: {0}")]
    Ffmpeg(std::io::Error),
    /// ffmpeg ended with an error; what it wrote to its stderr.
    #[error("ffmpeg could not encode: {ffmpeg_says}")]
    Encode { ffmpeg_says: String },
    /// An overlay file's name ends in neither a picture's nor a video's ending.
    #[error(
        "is no overlay file: --overlay writes a contact sheet (.png) or a video (.mp4, .mov, .mkv), not {}",
        if ending.is_empty() { "a name without an ending".to_string() } else { format!("'.{ending}'") }
    )]
    OverlayKind { ending: String },
}

impl VideoProblem {
    /// The tracker's refusal, where that is the problem.
    pub fn tracks_error(&self) -> Option<&TracksError> {
        match self {
            VideoProblem::Tracks { error, .. } => Some(error),
            _ => None,
        }
    }

    /// `program` could not be started: not installed, or `error`.
    pub fn cannot_run(program: &'static str, error: std::io::Error) -> VideoProblem {
        match error.kind() {
            std::io::ErrorKind::NotFound => VideoProblem::NoFfmpeg,
            _ => VideoProblem::CannotRun { program, error },
        }
    }
}

/// What to try after the refusal `error` (`VideoProblem::Tracks`): the handles that
/// could help and were not given (`roi`, `scale`, a seed `at`); after a seed, to try
/// without it, and where nothing else is left, to film the clip again. (Every refusal
/// but a clip too short is helped by a seed or a scale, and a refusal with a scale
/// given is never for the radius: no advice is left empty but the too-short clip's.)
fn next_try(error: &TracksError, roi: bool, scale: bool, at: Option<(f64, f64)>) -> String {
    let help = error.helped_by();
    let given = Handles {
        roi,
        ball_at: at.is_some(),
        scale,
    };
    let untried: Vec<&str> = [
        (
            help.roi && !given.roi,
            "--roi X,Y,W,H (pixels) around the groove",
        ),
        (
            help.ball_at && !given.ball_at,
            "--ball-at X,Y on a ball in the first frame",
        ),
        (
            help.scale && !given.scale,
            "--scale LENGTH (a pixel's length)",
        ),
    ]
    .into_iter()
    .filter_map(|(open, what)| open.then_some(what))
    .collect();
    let seed =
        at.map(|(x, y)| format!(" (tracked with the seed --ball-at {x},{y}: try without it too)"));
    let again = "film the clip again with the balls standing out from the wall (a plain wall of another brightness or colour, more light, less compression)";
    match (untried.is_empty(), seed) {
        (false, seed) => format!("; try {}{}", untried.join(" or "), seed.unwrap_or_default()),
        (true, Some(seed)) => format!("{seed}; else {again}"),
        (true, None) => String::new(),
    }
}

/// `x` to a tenth of a pixel: a click's point (56.18421052631579) said as 56.2, a
/// typed one as typed (300).
fn tenth(x: f64) -> f64 {
    (x * 10.0).round() / 10.0
}

#[cfg(test)]
mod tests {
    use super::*;

    const SPARSE: TracksError = TracksError::Sparse {
        seen: 8,
        frames: 27,
    };
    const SCATTER: TracksError = TracksError::RadiiDisagree {
        median_px: 11.8,
        scatter: 0.09,
    };

    const DOUBTED: TracksError = TracksError::RadiusDoubted {
        radius_px: 17.45,
        fits: 34,
        outlines: 43,
        outlines_px: 12.77,
    };

    /// The doubt says both radii and both counts, the way out being a scale.
    #[test]
    fn a_doubted_radius_is_refused_with_both_radii() {
        assert_eq!(
            DOUBTED.to_string(),
            "tracking unsure: 43 clear outlines left out for their radius put it at 12.8 px, where the 34 fits kept give 17.4 px, so no scale is given"
        );
    }

    #[test]
    fn the_advice_names_only_the_options_not_yet_given_that_could_help() {
        let scale = "; try --scale LENGTH (a pixel's length)";
        let cases = [
            (
                &SPARSE,
                (false, false),
                "; try --roi X,Y,W,H (pixels) around the groove or --ball-at X,Y on a ball in the first frame",
            ),
            (
                &SPARSE,
                (true, true),
                "; try --ball-at X,Y on a ball in the first frame",
            ),
            (&SCATTER, (false, false), scale),
            (&SCATTER, (true, false), scale),
            (&DOUBTED, (false, false), scale),
            (
                &TracksError::TooFewFrames { frames: 2, need: 3 },
                (false, false),
                "",
            ),
        ];
        for (error, (roi, given_scale), want) in cases {
            assert_eq!(
                next_try(error, roi, given_scale, None),
                want,
                "{error:?} {roi} {given_scale}"
            );
        }
        let seeded = next_try(&SCATTER, false, false, Some((40.0, 120.0)));
        assert_eq!(
            seeded,
            format!("{scale} (tracked with the seed --ball-at 40,120: try without it too)")
        );
        // Every option that could help given: without the seed, else film again.
        let all = next_try(&SPARSE, true, false, Some((33.0, 151.0)));
        assert!(
            all.starts_with(" (tracked with the seed --ball-at 33,151: try without it too); else film the clip again"),
            "{all}"
        );
    }
}
