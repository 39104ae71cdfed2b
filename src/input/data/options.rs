//! How a data file is to be read beyond what it says itself.

pub use crate::study::measured::MAX_ROWS;

/// How to read a file beyond what its header says.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Reading {
    /// Seconds per time unit of the file (1 = s); wins over the header's.
    pub time_unit: Option<f64>,
    /// m/s per speed unit of the file; wins over the header's.
    pub speed_unit: Option<f64>,
    /// Metres per length unit of a position file (wins over the header's).
    pub length_unit: Option<f64>,
    /// Metres per pixel of a video track in pixels (a Tracker or Logger Pro file whose
    /// video was not calibrated), from `--scale`.
    pub scale: Option<f64>,
    /// Time of the first impact in the file's time (after units); detected if absent.
    pub impact_at: Option<f64>,
    /// Which track (Tracker) or column prefix holds the ball's centre, e.g. "mass A"
    /// [default: a track named centre/center/ball, else the first].
    pub centre: Option<String>,
    /// Keep a position file's lengths in its own unit, unchecked: `groovelab data` and
    /// the app show a file whose length unit is in doubt (none stated and the numbers
    /// not metres, or a video never scaled) in its own units rather than not at all;
    /// nothing fits such a reading.
    pub own_lengths: bool,
    /// Which track holds the mark on its rim, e.g. "mass B" [default: a track named
    /// mark/rim/spot, else the second; none: v_t is not measured].
    pub mark: Option<String>,
}
