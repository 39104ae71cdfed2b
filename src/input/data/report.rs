//! What groovelab makes of a data file before any fit (`groovelab data`): the format,
//! the tracks and their roles, frames, rate and span, the units and who decided
//! them, missing frames, scatter, approach speed and the impacts found. A track with
//! no impact is described too ("a single ball's track, no impact found").

use serde::Serialize;

use super::notes::Notes;
use super::options::Reading;
use super::problem::{DataError, DataProblem};
use super::scales::{approach_speed, frame_spacing};
use crate::study::measured::track::derivative::scatter;
use crate::study::measured::{self, Derive, RawSeries, Series, Track};

/// What a file holds, as groovelab reads it.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Report {
    pub file: String,
    #[serde(flatten)]
    pub notes: Notes,
    /// "position track" or "velocities".
    pub kind: &'static str,
    /// The tracks taken for the ball's centre and its rim mark (position tracks).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub centre: Option<String>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub mark: Option<String>,
    /// The mark's median distance from the centre, m, over the frames that have both:
    /// a rim mark lies within R of it (`groovelab data` says when it cannot be one).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub mark_distance: Option<f64>,
    /// A rim mark tracked but left out by the fits: it lies within a few position
    /// scatters of the centre, so its angle would be noise (`fit` says the same).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub mark_left_out: Option<crate::study::measured::track::MarkLeftOut>,
    /// Frames with a time (and, for a track, rows kept).
    pub frames: usize,
    /// The frames of the file's time span at its rate, found or not (a video's
    /// frames: 11 found of 58 at 60 frames/s is `frames` 11 of `frames_spanned` 58).
    pub frames_spanned: usize,
    /// Frames per second, from the median spacing of every row's time (the clip's
    /// rate, not the found frames'); `None` (JSON `null`) where fewer than two
    /// distinct times give none.
    pub frame_rate: Option<f64>,
    /// First and last time of the file, s (a velocity file's with the impact at 0).
    pub t_first: f64,
    pub t_last: f64,
    /// Frames missing: runs of rows without a centre position, and jumps in time.
    pub missing: Vec<Gap>,
    /// Scatter of a tracked position, m (third differences).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub scatter: Option<f64>,
    /// Speed toward the other ball before the first impact, m/s, and its ±.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub approach_speed: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub approach_speed_se: Option<f64>,
    /// A track without an impact: its speed between frames (90th percentile), m/s.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub speed: Option<f64>,
    /// Impacts in the file's time, s; the first is where the fit puts t = 0.
    pub impacts: Vec<f64>,
    /// What was found about impacts, in words.
    pub impact_note: String,
    /// The lengths are in the file's own unit, not known to be metres (none stated and
    /// the numbers not metres, or a video never scaled): why, and what to give. Every
    /// length and speed of the report is then in that unit (per s).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub length_unit_doubt: Option<String>,
}

impl Report {
    /// True when the file holds velocities (else a position track).
    pub fn holds_velocities(&self) -> bool {
        self.kind == "velocities"
    }
}

/// A run of missing frames.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Gap {
    /// The times around the gap, s (of the rows without a position, or the frames on
    /// either side of a jump in time).
    pub from: f64,
    pub to: f64,
    /// Frames missing there.
    pub frames: usize,
    /// "no position" (an empty or NaN cell) or "no row" (a jump in time).
    pub why: &'static str,
}

/// Reads `text` (the file named `file`) and says what it holds; an error only when
/// it cannot be read at all.
pub fn inspect(
    text: &str,
    file: &str,
    reading: &Reading,
    derive: &Derive,
) -> Result<Report, DataError> {
    // The ball `fit` fits: the right one where the left one's frames give no series.
    if let Ok((_, Some(right))) = super::ball_choice::chosen(text, file, reading, derive) {
        return inspect(text, file, &right, derive);
    }
    let (raw, notes) = match super::detect::read_with_notes(text, file, reading) {
        // A length unit in doubt: the file in its own unit, with the doubt and the fix.
        Err(e) if !reading.own_lengths && lengths_in_doubt(&e.what) => {
            let own = Reading {
                own_lengths: true,
                ..reading.clone()
            };
            let mut report = inspect(text, file, &own, derive)?;
            for u in &mut report.notes.units {
                if u.quantity == "length" {
                    u.unit = "the file's own unit".into();
                    u.how = "not known to be metres (see below)".into();
                }
            }
            // Its speeds, too, are in the file's unit per second.
            report.impact_note = report.impact_note.replace(" m/s", " units/s");
            report.length_unit_doubt = Some(e.what.to_string());
            return Ok(report);
        }
        Err(e) if e.what == DataProblem::NoImpact => {
            // A velocity file without an impact: what it holds all the same.
            let table = super::table::Table::new(text);
            let (m, notes) = super::velocities::without_impact(&table, file, reading)?;
            return Ok(single_ball(m, file, notes));
        }
        read => read?,
    };
    Ok(match raw {
        RawSeries::Velocities(m) => {
            let t = m.t();
            let before: Vec<f64> = t
                .iter()
                .zip(m.v_cm())
                .filter(|(t, _)| **t < 0.0)
                .map(|(_, v)| *v)
                .collect();
            Report {
                approach_speed: (!before.is_empty())
                    .then(|| before.iter().sum::<f64>() / before.len() as f64),
                impacts: vec![0.0],
                impact_note: format!(
                    "first impact {}{}; the times above are from it (t = 0){}",
                    if reading.impact_at.is_some() {
                        "given"
                    } else {
                        "found"
                    },
                    notes
                        .impact_in_file
                        .map(|at| format!(" at t = {at:.4} s of the file"))
                        .unwrap_or_default(),
                    [
                        (
                            m.mirrored(),
                            "; the file's x runs away from the other ball: read mirrored"
                        ),
                        (m.spin_turned(), SPIN_TURNED),
                    ]
                    .iter()
                    .filter(|(on, _)| *on)
                    .map(|(_, said)| *said)
                    .collect::<String>()
                ),
                ..velocities(t, file, notes)
            }
        }
        RawSeries::Positions(track) => of_track(track, file, notes, reading, derive),
    })
}

/// Said where a velocity file's v_t was read turned.
pub const SPIN_TURNED: &str = "; v_t runs opposite to v_cm while the ball rolls before the impact (where v_t = v_cm): read turned, v_t → −v_t";

/// A problem that is only the lengths' unit: none stated and the numbers not metres,
/// or a Logger Pro video never scaled.
fn lengths_in_doubt(what: &DataProblem) -> bool {
    match what {
        // Only where nobody stated the unit: a unit stated and implausible is an error.
        DataProblem::Scale(e) => matches!(
            e,
            super::scales::ScaleError::LengthsNotMetres { .. }
                | super::scales::ScaleError::TooSlow { by: None, .. }
        ),
        DataProblem::Unscaled { .. } => true,
        DataProblem::Layout(super::layout::LayoutError::Pixels { .. }) => true,
        DataProblem::InDataSet { problem, .. } => lengths_in_doubt(problem),
        _ => false,
    }
}

/// The report of a velocity file with no impact in it: a single ball's velocities.
fn single_ball(m: crate::study::measured::Measured, file: &str, notes: Notes) -> Report {
    let t = &m.t();
    let fastest = m.v_cm().iter().fold(0.0_f64, |a, v| a.max(v.abs()));
    Report {
        speed: Some(fastest),
        impact_note: "a single ball's velocities, no impact found (v_cm never drops sharply): a fit needs one; give its time with --impact-at".into(),
        ..velocities(t, file, notes)
    }
}

/// What every velocity file's report says of its times (no impact, approach or
/// speed yet: the callers say those).
fn velocities(t: &[f64], file: &str, notes: Notes) -> Report {
    Report {
        file: file.to_string(),
        notes,
        kind: "velocities",
        centre: None,
        mark: None,
        mark_distance: None,
        mark_left_out: None,
        frames: t.len(),
        frames_spanned: spanned(t),
        frame_rate: rate_of(t),
        t_first: t.first().copied().unwrap_or(f64::NAN),
        t_last: t.last().copied().unwrap_or(f64::NAN),
        missing: jumps(t),
        scatter: None,
        approach_speed: None,
        approach_speed_se: None,
        speed: None,
        impacts: Vec::new(),
        impact_note: String::new(),
        length_unit_doubt: None,
    }
}

/// The report of a position track: its derivation's findings when it shows an impact.
fn of_track(track: Track, file: &str, notes: Notes, reading: &Reading, derive: &Derive) -> Report {
    let (t, x): (Vec<f64>, Vec<f64>) = track
        .t()
        .iter()
        .zip(track.x())
        .filter(|(_, x)| x.is_finite())
        .unzip();
    let mut missing = no_position(&track);
    missing.extend(jumps(track.t()));
    missing.sort_by(|a, b| a.from.total_cmp(&b.from));
    let mut report = Report {
        file: file.to_string(),
        notes,
        kind: "position track",
        centre: Some(track.centre_name().to_string()),
        mark: track.mark_name().map(str::to_string),
        mark_distance: mark_distance(&track),
        mark_left_out: None,
        frames: t.len(),
        // The rate and span of every row: a video's frames left out (no position)
        // are frames of the clip all the same.
        frames_spanned: spanned(track.t()),
        frame_rate: rate_of(track.t()),
        t_first: t.first().copied().unwrap_or(f64::NAN),
        t_last: t.last().copied().unwrap_or(f64::NAN),
        missing,
        scatter: Some(scatter(&t, &x)),
        approach_speed: None,
        approach_speed_se: None,
        speed: None,
        impacts: Vec::new(),
        impact_note: String::new(),
        length_unit_doubt: None,
    };
    let opts = Derive {
        impact_at: reading.impact_at.or(derive.impact_at),
        ..*derive
    };
    match measured::prepare(RawSeries::Positions(track.clone()), &opts) {
        Ok(Series::Track(_, found)) => {
            report.scatter = Some(found.scatter);
            report.mark_left_out = found.mark_left_out.clone();
            report.approach_speed = Some(found.approach_speed);
            report.approach_speed_se = Some(found.approach_speed_se).filter(|s| s.is_finite());
            report.impacts = std::iter::once(found.impact_t)
                .chain(found.later_impacts.iter().map(|dt| found.impact_t + dt))
                .collect();
            report.impact_note = format!(
                "first impact {} at t = {:.4} s ({} frames before, {} after); the other ball lies toward {}x{}",
                if found.impact_detected {
                    "found"
                } else {
                    "given"
                },
                found.impact_t,
                found.frames_before,
                found.frames_after,
                if found.direction > 0.0 { "+" } else { "−" },
                if found.later_impacts.is_empty() {
                    String::new()
                } else {
                    format!(
                        "; {} later impact{}",
                        found.later_impacts.len(),
                        if found.later_impacts.len() == 1 {
                            ""
                        } else {
                            "s"
                        }
                    )
                }
            );
        }
        Ok(Series::Velocities(_)) => {}
        Err(e) => {
            report.speed = approach_speed(&track);
            let what = if track.mark().is_some() {
                "a ball's track with a rim mark"
            } else {
                "a single ball's track"
            };
            let e = e.to_string();
            report.impact_note = match e.strip_prefix("no impact found") {
                Some(why) => format!("{what}, no impact found{why}"),
                None => format!("{what}, no impact found ({e})"),
            };
        }
    }
    report
}

/// The median distance of the track's mark from its centre, m, over the frames that
/// have both; `None` without a mark or such a frame.
fn mark_distance(track: &Track) -> Option<f64> {
    track.mark().as_ref()?;
    let mut d: Vec<f64> = (0..track.t().len())
        .map(|i| {
            let (dx, dy) = track.at(i).mark_offset();
            dx.hypot(dy)
        })
        .filter(|d| d.is_finite())
        .collect();
    d.sort_by(f64::total_cmp);
    d.get(d.len() / 2).copied()
}

/// Runs of rows with a time but no centre position.
fn no_position(track: &Track) -> Vec<Gap> {
    let mut out: Vec<Gap> = Vec::new();
    let mut open = false;
    for (&t, x) in track.t().iter().zip(track.x()) {
        match out.last_mut() {
            Some(gap) if open && !x.is_finite() => {
                gap.to = t;
                gap.frames += 1;
            }
            _ if !x.is_finite() => out.push(Gap {
                from: t,
                to: t,
                frames: 1,
                why: "no position",
            }),
            _ => {}
        }
        open = !x.is_finite();
    }
    out
}

/// Jumps in time of more than one and a half frames: the frames between are missing.
fn jumps(t: &[f64]) -> Vec<Gap> {
    let frame = frame_spacing(t);
    if frame.is_nan() || frame <= 0.0 {
        return Vec::new();
    }
    t.iter()
        .zip(t.iter().skip(1))
        .filter(|(a, b)| *b - *a > 1.5 * frame)
        .map(|(&a, &b)| Gap {
            from: a,
            to: b,
            frames: ((b - a) / frame).round() as usize - 1,
            why: "no row",
        })
        .collect()
}

/// Frames per second from the median spacing of `t`, where it gives a finite one.
/// The frames from the first time of `t` to its last at its rate (at least its
/// rows; all of them when it has no rate).
fn spanned(t: &[f64]) -> usize {
    let (Some(first), Some(last), Some(rate)) = (t.first(), t.last(), rate_of(t)) else {
        return t.len();
    };
    let n = ((last - first) * rate).round() + 1.0;
    if n.is_finite() && n < 1e9 {
        (n as usize).max(t.len())
    } else {
        t.len()
    }
}

fn rate_of(t: &[f64]) -> Option<f64> {
    let rate = 1.0 / frame_spacing(t);
    (rate.is_finite() && rate > 0.0).then_some(rate)
}
