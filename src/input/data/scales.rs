//! Whether a file's numbers, read in the units given (SI where none was), are of the
//! size a ball in a groove has: a header without units whose numbers are plainly ms,
//! cm or mm is refused with what the numbers look like and the option that reads them.

use std::fmt;

use crate::settings::units::significant;
use crate::study::measured::Track;
#[cfg(test)]
use crate::study::measured::TrackParts;

/// Slowest frame rate a measurement of this experiment has (a frame a second), and
/// the largest speed a ball in a groove reaches (m/s): numbers beyond them, with no
/// unit said, are plainly in ms and cm/s (or cm, mm).
pub const LONGEST_FRAME: f64 = 1.0;
/// Frames closer than this (s: 50 000 frames/s) in a file that spans less than
/// [`SHORTEST_SPAN`] are no recording of balls in a groove: seconds read as ms.
pub const SHORTEST_FRAME: f64 = 2e-5;
/// The least time a recording of an approach and an impact spans, s: a ball at 10
/// m/s crosses its own radius in 3 ms, and its slide lasts longer.
pub const SHORTEST_SPAN: f64 = 0.01;
pub const FASTEST_BALL: f64 = 10.0;

/// The smallest speed (m/s) a tracked ball in this experiment shows between frames
/// (its approach, or the tracker's jitter alone, is far above it): a file below it is
/// in a length unit too small (metres read as mm).
pub const SLOWEST_BALL: f64 = 1e-3;

/// The fastest change of a ball's spin speed v_t (m/s²): in a groove it changes only by
/// kinetic friction, at (5/2) k μ_k g with k ≤ 1 (physics.md §3), so 10 g would need
/// μ_k ≥ 4, beyond any pair of solid surfaces (rubber on dry concrete is about 1); the
/// impact, a force through the centre, leaves v_t as it was. A file in cm/s read as m/s
/// shows a hundred times the real change (1 to 3 m/s² in the lab: 100 to 300 m/s²).
pub const FASTEST_SPIN_CHANGE: f64 = 10.0 * 9.806_65;

/// A change of v_t a ball in this experiment typically shows while it slides (m/s²):
/// of the speed units a file may be in, the one that brings the change nearest to it
/// is named.
pub const TYPICAL_SPIN_CHANGE: f64 = 2.0;

/// The shortest span (s) over which [`steepest_change`] fits a line: long enough that
/// a tracker's scatter (0.1 m/s between frames at 240 frames/s) shows as a few m/s²,
/// short enough to see a slow ball's slide (a few hundredths of a second).
const CHANGE_SPAN: f64 = 0.02;

/// The steepest change of `v` over time `t` (|dv/dt|, units of v per s): the largest
/// slope of a least-squares line through the points of any stretch of at least
/// [`CHANGE_SPAN`] and two frame intervals (at most 17 points of it, evenly spaced,
/// in a very dense file), each point the median of itself and its neighbours, so
/// that one glitch (a tracker's jump up and back) is no change while a ramp (a slow
/// ball's slide, two frames at 60 frames/s) keeps every value. `None` with fewer than
/// three points.
#[allow(clippy::indexing_slicing)] // every index is below n, the shorter column's length
pub fn steepest_change(t: &[f64], v: &[f64]) -> Option<f64> {
    let n = t.len().min(v.len());
    let v: Vec<f64> = (0..n)
        .map(|k| {
            let mut three = [v[k.saturating_sub(1)], v[k], v[(k + 1).min(n - 1)]];
            three.sort_by(f64::total_cmp);
            three[1]
        })
        .collect();
    let mut steepest: Option<f64> = None;
    let mut j = 0;
    for i in 0..n {
        j = j.max(i + 2);
        while j < n && t[j] - t[i] < CHANGE_SPAN {
            j += 1;
        }
        if j >= n {
            break;
        }
        let stride = (j - i).div_ceil(16);
        let points: Vec<(f64, f64)> = (i..=j)
            .step_by(stride)
            .map(|k| (t[k] - t[i], v[k]))
            .collect();
        let s = slope(&points).abs();
        if s.is_finite() && steepest.is_none_or(|x| s > x) {
            steepest = Some(s);
        }
    }
    steepest
}

/// The slope of the least-squares line through `points` (t, v).
fn slope(points: &[(f64, f64)]) -> f64 {
    let m = points.len() as f64;
    let (mt, mv) = points
        .iter()
        .fold((0.0, 0.0), |(a, b), &(x, y)| (a + x / m, b + y / m));
    let (sxy, sxx) = points.iter().fold((0.0, 0.0), |(a, b), &(x, y)| {
        (a + (x - mt) * (y - mv), b + (x - mt) * (x - mt))
    });
    sxy / sxx
}

/// A speed a ball in this experiment typically has (m/s): of the length units a file
/// may be in, the one that brings the numbers nearest to it is named.
const TYPICAL_SPEED: f64 = 0.5;

/// The median spacing of neighbouring times.
pub fn frame_spacing(t: &[f64]) -> f64 {
    let mut spacing: Vec<f64> = t.iter().zip(t.iter().skip(1)).map(|(a, b)| b - a).collect();
    spacing.sort_by(f64::total_cmp);
    spacing.get(spacing.len() / 2).copied().unwrap_or(f64::NAN)
}

/// The approach speed of the centre as the frames show it: the 90th percentile of
/// its speed between neighbouring frames with a position (the path's length per
/// time, so a tilted camera frame counts the same); `None` with fewer than two such
/// frames. Not the median: a recording may roll slowly for most of its frames after
/// the impact; not the largest: one glitch would be it.
pub fn approach_speed(track: &Track) -> Option<f64> {
    let mut speeds: Vec<f64> = (1..track.len())
        .filter_map(|i| {
            let (a, b) = (track.at(i - 1), track.at(i));
            let (dx, dy) = (b.x - a.x, b.y - a.y);
            let d = if dy.is_finite() {
                dx.hypot(dy)
            } else {
                dx.abs()
            };
            let v = d / (b.t - a.t);
            v.is_finite().then_some(v)
        })
        .collect();
    speeds.sort_by(f64::total_cmp);
    let at = (speeds.len() * 9 / 10).min(speeds.len().saturating_sub(1));
    speeds.get(at).copied()
}

/// How a position file's units were decided: each unit's SI factor and who said it
/// (`Some("the header")`, `Some("--time-unit")`; `None`: nobody, SI was assumed).
#[derive(Clone, Debug)]
pub struct Given {
    pub time: (f64, Option<&'static str>),
    pub length: (f64, Option<&'static str>),
}

/// Candidate units of a dimension that a plausibility error may name.
pub const TIMES: [(&str, f64); 3] = [("s", 1.0), ("ms", 1e-3), ("us", 1e-6)];
pub const LENGTHS: [(&str, f64); 3] = [("m", 1.0), ("cm", 1e-2), ("mm", 1e-3)];
pub const SPEEDS: [(&str, f64); 3] = [("m/s", 1.0), ("cm/s", 1e-2), ("mm/s", 1e-3)];

/// The name of the candidate unit of SI factor `factor`, if it is one.
pub fn unit_name(units: &[(&'static str, f64)], factor: f64) -> Option<&'static str> {
    units
        .iter()
        .find(|(_, f)| (f / factor - 1.0).abs() < 1e-9)
        .map(|(n, _)| *n)
}

/// Of `units`, the one other than `current` (SI factor) under which a value read as
/// `value` (SI, in the current unit) comes nearest to `typical` while `fits`.
pub fn fitting(
    units: &[(&'static str, f64)],
    current: f64,
    value: f64,
    typical: f64,
    fits: impl Fn(f64) -> bool,
) -> Option<&'static str> {
    units
        .iter()
        .filter(|(_, f)| (f / current - 1.0).abs() > 1e-9)
        .map(|&(n, f)| (n, value / current * f))
        .filter(|&(_, v)| fits(v))
        .min_by(|a, b| {
            let off = |v: f64| (v / typical).log10().abs();
            off(a.1).total_cmp(&off(b.1))
        })
        .map(|(n, _)| n)
}

/// What to do about a unit that does not fit: the option, and the header's fix when
/// the header said it.
fn advice(flag: &str, unit: &str, header: &str, said_by: Option<&str>) -> String {
    match said_by {
        Some("the header") => format!("fix the header ({header} ({unit})) or give --{flag} {unit}"),
        _ => format!("give --{flag} {unit}"),
    }
}

/// Why a position track's numbers are not of a ball in a groove, in the units they
/// were read in (frame spacing in s, speeds in m/s); each says what the numbers look
/// like and the unit that fits. `by`: who gave the unit (the header, an option).
#[derive(Clone, Debug, PartialEq)]
pub enum ScaleError {
    /// No time unit given, and the frames are a second or more apart.
    TimesNotSeconds { frame: f64 },
    /// The time unit given puts the frames a second or more apart; `unit` fits.
    FramesTooSlow {
        frame: f64,
        by: &'static str,
        unit: &'static str,
    },
    /// The ball approaches slower than any ball in a groove; `unit`, if any, fits.
    TooSlow {
        speed: f64,
        by: Option<&'static str>,
        unit: Option<&'static str>,
    },
    /// No unit given, and as metres the ball is too fast; `unit`, if any, fits (the
    /// numbers may be pixels of a video never calibrated too: `--scale` is named).
    LengthsNotMetres {
        speed: f64,
        unit: Option<&'static str>,
    },
    /// In the units given the ball is too fast; `unit`, if any, fits.
    TooFast {
        frame: f64,
        speed: f64,
        by: Option<&'static str>,
        unit: Option<&'static str>,
    },
}

impl std::error::Error for ScaleError {}

impl ScaleError {
    /// The lengths' unit is in doubt (the times are fine): the file can still be
    /// shown in its own length unit ([`super::Reading::own_lengths`]).
    pub fn about_lengths(&self) -> bool {
        matches!(
            self,
            ScaleError::TooSlow { .. }
                | ScaleError::LengthsNotMetres { .. }
                | ScaleError::TooFast { .. }
        )
    }
}

/// [`check_track`], leaving out the lengths' checks where the file is read in its own
/// length unit ([`super::Reading::own_lengths`]).
pub fn check_track_as_read(
    track: &Track,
    given: &Given,
    own_lengths: bool,
) -> Result<(), ScaleError> {
    match check_track(track, given) {
        Err(e) if own_lengths && e.about_lengths() => Ok(()),
        checked => checked,
    }
}

impl fmt::Display for ScaleError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            ScaleError::TimesNotSeconds { frame } => write!(
                f,
                "the header gives no time unit and the times do not look like s: frames {} apart (as s: {} frames/s; as ms: {:.0} frames/s); if they are ms, give --time-unit ms (or a unit in the header: t (ms))",
                significant(frame, 3),
                significant(1.0 / frame, 2),
                1e3 / frame
            ),
            ScaleError::FramesTooSlow { frame, by, unit } => write!(
                f,
                "in the time unit {by} gives the frames are {} s apart ({} frames/s), slower than any video: if the times are {unit}, {}",
                significant(frame, 3),
                significant(1.0 / frame, 2),
                advice("time-unit", unit, "t", Some(by))
            ),
            ScaleError::TooSlow { speed, by, unit } => {
                let read_in = match by {
                    Some(by) => format!("the length unit {by} gives"),
                    None => "metres".into(),
                };
                let named = match unit {
                    Some(u) => format!(
                        ": if the positions are {u}, {}",
                        advice("length-unit", u, "x", by)
                    ),
                    None => ": check the length unit (--length-unit, or the header's)".into(),
                };
                write!(
                    f,
                    "read in {read_in} the ball moves at up to {} m/s between frames, slower than any ball in a groove (at least {SLOWEST_BALL} m/s){named}",
                    significant(speed, 3),
                )
            }
            ScaleError::LengthsNotMetres { speed, unit } => {
                let named = match unit {
                    Some(u) => format!(
                        "if they are {u}, give --length-unit {u} (or units in the header: x ({u}), y ({u})); if they are pixels"
                    ),
                    None => "they are not m, cm or mm: if they are pixels".into(),
                };
                write!(
                    f,
                    "the header gives no length unit and the positions do not look like metres: as m the ball moves at up to {} m/s between frames (as cm {} m/s, as mm {} m/s); {named} of a video never calibrated, give the length one pixel shows with --scale (e.g. --scale 0.5mm){}",
                    significant(speed, 3),
                    significant(speed * 1e-2, 3),
                    significant(speed * 1e-3, 3),
                    if unit.is_none() {
                        ", or their unit with --length-unit"
                    } else {
                        ""
                    }
                )
            }
            ScaleError::TooFast {
                frame,
                speed,
                by,
                unit,
            } => {
                let named = match unit {
                    Some(u) => format!(
                        "; if the positions are {u}, {}",
                        advice("length-unit", u, "x", by)
                    ),
                    None => String::new(),
                };
                write!(
                    f,
                    "in the units given the frames are {} s apart and the ball moves at up to {} m/s between frames, beyond any ball in a groove (below {FASTEST_BALL} m/s): check the time and length units (--time-unit, --length-unit, or the header's){named}",
                    significant(frame, 3),
                    significant(speed, 3),
                )
            }
        }
    }
}

/// A position track checked in the units it was read in: refused when its frames are
/// a second or more apart (ms, not s), or its ball moves at 10 m/s or more (cm or mm,
/// not m), or below 1 mm/s (metres read as mm), whether the units were stated or
/// assumed.
pub fn check_track(track: &Track, given: &Given) -> Result<(), ScaleError> {
    let frame = frame_spacing(track.t());
    let (tf, t_by) = given.time;
    let (lf, l_by) = given.length;
    if frame >= LONGEST_FRAME {
        let unit = fitting(&TIMES, tf, frame, 0.01, |f| f < LONGEST_FRAME).unwrap_or("ms");
        return Err(match t_by {
            None => ScaleError::TimesNotSeconds { frame },
            Some(by) => ScaleError::FramesTooSlow { frame, by, unit },
        });
    }
    let Some(speed) = approach_speed(track) else {
        return Ok(());
    };
    let plausible = |v: f64| (SLOWEST_BALL..FASTEST_BALL).contains(&v);
    let unit = fitting(&LENGTHS, lf, speed, TYPICAL_SPEED, plausible);
    if speed < SLOWEST_BALL {
        return Err(ScaleError::TooSlow {
            speed,
            by: l_by,
            unit,
        });
    }
    if speed < FASTEST_BALL {
        return Ok(());
    }
    if l_by.is_none() && t_by.is_none() {
        return Err(ScaleError::LengthsNotMetres { speed, unit });
    }
    Err(ScaleError::TooFast {
        frame,
        speed,
        by: l_by,
        unit: unit.filter(|_| unit_name(&LENGTHS, lf).is_some()),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A ball approaching at `v` (file units per s) for 40 frames at 100 frames/s,
    /// then rolling back at v/10 for 60.
    fn track(v: f64) -> Track {
        let t: Vec<f64> = (0..100).map(|i| f64::from(i) * 0.01).collect();
        let x = t
            .iter()
            .map(|&t| {
                if t < 0.4 {
                    v * t
                } else {
                    0.4 * v - 0.1 * v * (t - 0.4)
                }
            })
            .collect();
        Track::new(TrackParts {
            y: vec![0.0; t.len()],
            x,
            t,
            ..TrackParts::default()
        })
        .unwrap()
    }

    #[test]
    fn the_steepest_change_is_a_lines_slope_and_a_glitch_is_none() {
        let t: Vec<f64> = (0..50).map(|i| f64::from(i) / 120.0).collect();
        // Steady for 0.2 s, then falling at 3 units per s.
        let v: Vec<f64> = t.iter().map(|&t| 1.0 - 3.0 * (t - 0.2).max(0.0)).collect();
        let s = steepest_change(&t, &v).unwrap();
        assert!((s - 3.0).abs() < 1e-9, "{s}");
        // One value up by 5 and back: no change, whatever its size.
        let mut flat = vec![0.4; 50];
        flat[25] += 5.0;
        assert_eq!(steepest_change(&t, &flat), Some(0.0));
        assert_eq!(steepest_change(&t[..2], &v[..2]), None);
    }

    #[test]
    fn the_unit_named_is_the_one_that_gives_a_lab_speed() {
        let none = Given {
            time: (1.0, None),
            length: (1.0, None),
        };
        assert!(check_track(&track(0.6), &none).is_ok());
        // Metres read as mm: 0.6 mm/s; the header said mm.
        let mm = Given {
            time: (1.0, None),
            length: (1e-3, Some("the header")),
        };
        let e = check_track(&track(0.6e-3), &mm).unwrap_err().to_string();
        assert!(
            e.contains("slower than any ball")
                && e.contains(
                    "if the positions are m, fix the header (x (m)) or give --length-unit m"
                ),
            "{e}"
        );
        // Mostly the slow roll after the impact: the approach still decides.
        let e = check_track(&track(60.0), &none).unwrap_err().to_string();
        assert!(
            e.contains("moves at up to 60 m/s between frames") && e.contains("--length-unit cm"),
            "{e}"
        );
        let e = check_track(&track(600.0), &none).unwrap_err().to_string();
        assert!(e.contains("--length-unit mm"), "{e}");
        let given = Given {
            time: (1.0, Some("--time-unit")),
            length: (1.0, None),
        };
        let e = check_track(&track(600.0), &given).unwrap_err().to_string();
        assert!(
            e.contains("in the units given") && e.contains("give --length-unit mm"),
            "{e}"
        );
        // Times stated in s that are ms: the unit that fits is named.
        let stated = Given {
            time: (1.0, Some("the header")),
            length: (1.0, Some("the header")),
        };
        let mut slow = track(0.6).into_parts();
        slow.t.iter_mut().for_each(|t| *t *= 1e3);
        let slow = Track::new(slow).unwrap();
        let e = check_track(&slow, &stated).unwrap_err().to_string();
        assert!(
            e.contains("fix the header (t (ms)) or give --time-unit ms"),
            "{e}"
        );
    }
}
