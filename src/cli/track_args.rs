//! The options of `groovelab track` (clap), apart from the command so that
//! `args` can name them without a cycle.

use std::path::PathBuf;

use clap::{Args, ValueEnum};

#[derive(Args, Debug)]
pub struct TrackArgs {
    /// The video (mp4, mov, mkv, avi: decoded by the system's ffmpeg) or a folder of
    /// numbered PNG/JPEG frames.
    #[arg(value_name = "VIDEO")]
    pub video: PathBuf,
    /// Output: a Tracker-style text file (`--data` reads it) or JSON.
    #[arg(long, value_enum, default_value_t = TrackOutput::Tracker)]
    pub format: TrackOutput,
    /// Write the tracks to this file (atomically) instead of stdout; the notes then
    /// go to stdout.
    #[arg(long, value_name = "FILE")]
    pub output: Option<PathBuf>,
    /// Also write what was found drawn over the frames (each ball's outline, centre
    /// and mark), to check the tracking at a glance: a video (FILE ending in .mp4,
    /// .mov or .mkv; needs ffmpeg) or a contact sheet of 12 frames (.png). When the
    /// tracking is refused, what was found is still drawn, over a pixel grid to read
    /// --roi and --ball-at from.
    #[arg(long, value_name = "FILE")]
    pub overlay: Option<PathBuf>,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum TrackOutput {
    Tracker,
    Json,
}

/// Why an option's text is not a positive number in range (clap prints it after the
/// option's name).
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum PositiveError {
    #[error("'{}' is not a number of {what}", crate::settings::quote::clip(text))]
    NotANumber { text: String, what: &'static str },
    #[error(
        "{} is out of range, allowed {min} ≤ {what} ≤ {max:e}",
        crate::settings::quote::clip(text)
    )]
    OutOfRange {
        text: String,
        what: &'static str,
        min: f64,
        max: f64,
    },
}

/// A parser of a positive number from `min` to `max`.
pub(super) fn positive(
    what: &'static str,
    min: f64,
    max: f64,
) -> impl Fn(&str) -> Result<f64, PositiveError> + Clone {
    move |text: &str| {
        let v: f64 = text.trim().parse().map_err(|_| PositiveError::NotANumber {
            text: text.into(),
            what,
        })?;
        if v.is_finite() && v > 0.0 && v >= min && v <= max {
            Ok(v)
        } else {
            Err(PositiveError::OutOfRange {
                text: text.into(),
                what,
                min,
                max,
            })
        }
    }
}

#[cfg(test)]
mod tests {
    #[test]
    fn a_frame_rate_is_taken_from_1_to_100000() {
        let fps = super::positive("frames per second", 1.0, 1e5);
        assert_eq!(fps("30"), Ok(30.0));
        assert_eq!(fps("1"), Ok(1.0));
        assert_eq!(fps("1e5"), Ok(1e5));
        // `track --fps 1e-300` wrote times up to 2.6e301 s.
        for bad in ["1e-300", "0.5", "0", "-30", "1e6", "inf", "NaN"] {
            let e = fps(bad).unwrap_err().to_string();
            assert!(
                e.contains("allowed 1 ≤ frames per second ≤ 1e5"),
                "{bad}: {e}"
            );
        }
        assert!(
            fps("fast")
                .unwrap_err()
                .to_string()
                .contains("not a number")
        );
    }
}
