//! What the derivation found in a track, for the user to check: the centre's and
//! mark's frames, the impact, the window, the scatter, and the gaps, in a few lines.

use serde::Serialize;

use super::derivative::MIN_HALF_WINDOW;
use crate::settings::units::{Dimension, show, show_small};

/// What the derivation found in the track, for the user to check.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Found {
    /// "Tracker multi-track", "Tracker single-track" or "CSV".
    pub format: &'static str,
    pub centre: String,
    /// The rim mark's track, `None` when there is none (then v_t is not measured).
    pub mark: Option<String>,
    /// Frames with a centre position.
    pub frames: usize,
    /// Rows with a time but no centre position (an empty or NaN cell), left out.
    #[serde(skip_serializing_if = "is_zero")]
    pub frames_dropped: usize,
    /// Those rows' times in the file, s, as runs of neighbouring rows `[first, last]`.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub centre_gaps: Vec<[f64; 2]>,
    /// Frames with a centre but without the rim mark (an empty or NaN cell): no v_t
    /// there, nothing filled in.
    #[serde(skip_serializing_if = "is_zero")]
    pub mark_missing: usize,
    /// k where the mark was followed in every k-th frame only and its angle is
    /// unwrapped in those steps (it turns slowly enough in them): v_t in those frames.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub mark_every: Option<usize>,
    /// Those frames' times in the file, s, as runs `[first, last]`.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub mark_gaps: Vec<[f64; 2]>,
    /// Frames absent from the file (its time jumps).
    #[serde(flatten)]
    pub skipped: Skipped,
    /// Frames per second (from the median spacing).
    pub frame_rate: f64,
    /// Estimated scatter of a tracked position, m.
    pub scatter: f64,
    /// Half-width of the local fits, s, and in frames.
    pub half_window: f64,
    pub half_window_frames: usize,
    /// The half-width asked for (`--window`), s, when it was under two frames and so
    /// widened to two (a local quadratic needs them).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub half_window_widened_from: Option<f64>,
    /// The first impact in the file's time, s (becomes t = 0).
    pub impact_t: f64,
    /// True when found in the motion, false when given.
    pub impact_detected: bool,
    /// The file's x of the centre at the first impact, m (becomes x = 0).
    pub impact_x: f64,
    /// +1 when the other ball lies toward the file's +x, −1 when toward −x.
    pub direction: f64,
    /// Speed of the centre toward the other ball before the first impact, m/s: the
    /// slope of a straight line through every frame of the approach (the ball rolls
    /// toward the impact at a steady speed; one local slope at the impact scattered
    /// by several of its own ±).
    pub approach_speed: f64,
    /// Its standard error, m/s (the line's, from its residuals: the frames' errors are
    /// independent).
    pub approach_speed_se: f64,
    pub frames_before: usize,
    pub frames_after: usize,
    /// Later impacts found in the motion, s from the first; the derivative does not
    /// reach across them either.
    pub later_impacts: Vec<f64>,
    /// Median distance of the mark from the centre, m.
    pub mark_radius: Option<f64>,
    /// A rim mark tracked but left out: it lies off the centre, but within
    /// `scatters` position scatters of it (its angle would be noise).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub mark_left_out: Option<MarkLeftOut>,
}

/// A rim mark left out because it lies too near the centre for the centre's scatter.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct MarkLeftOut {
    /// The mark's track name ("" for a CSV's columns).
    pub name: String,
    /// Its median distance from the centre, m.
    pub radius: f64,
    /// How many position scatters it needed to lie from the centre.
    pub scatters: f64,
    /// Where it was left out because its distance from the centre changes (10th and
    /// 90th percentiles, m): no mark on the ball.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub range: Option<[f64; 2]>,
}

impl MarkLeftOut {
    /// Why it was left out, after "rim mark NAME left out…: " (`scatter`: the
    /// position scatter, m).
    pub fn why(&self, scatter: f64) -> String {
        match self.range {
            Some([lo, hi]) => format!(
                "its distance from the centre changes from {:.1} to {:.1} (10th to 90th percentile), where a mark on the ball keeps one: another ball or run?",
                show_small(lo, Dimension::Length),
                show_small(hi, Dimension::Length)
            ),
            None => format!(
                "it lies {:.1} from the centre, within {}× the position scatter ({:.2}), so its angle would be noise",
                show_small(self.radius, Dimension::Length),
                self.scatters,
                show_small(scatter, Dimension::Length)
            ),
        }
    }
}

/// Frames absent from a file: where its time jumps by more than one and a half frames.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct Skipped {
    /// How many frames are missing.
    #[serde(skip_serializing_if = "is_zero")]
    pub frames_skipped: usize,
    /// The times either side of each jump, s.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub skipped_gaps: Vec<[f64; 2]>,
}

impl Skipped {
    /// The jumps of the times `t` (frames `dt` apart).
    pub fn of(t: &[f64], dt: f64) -> Skipped {
        let gaps: Vec<[f64; 2]> = t
            .windows(2)
            .filter_map(|w| match *w {
                [a, b] if b - a > 1.5 * dt => Some([a, b]),
                _ => None,
            })
            .collect();
        Skipped {
            frames_skipped: gaps
                .iter()
                .map(|g| ((g[1] - g[0]) / dt).round() as usize - 1)
                .sum(),
            skipped_gaps: gaps,
        }
    }
}

fn is_zero(n: &usize) -> bool {
    *n == 0
}

impl Found {
    /// The least ball radius R the tracked rim mark allows, m: its distance from the
    /// centre less three times the position scatter (within the noise it may lie on
    /// the rim); `None` without a mark. A smaller R puts the mark off the ball: a
    /// wrong R, or the wrong track taken for the mark, and a spin wrong by that ratio.
    pub fn least_radius(&self) -> Option<f64> {
        self.mark_radius.map(|m| m - 3.0 * self.scatter)
    }

    /// The rim mark as [`Found::describe`] names it, `name` quoting a track's name.
    fn mark_text(&self, name: impl Fn(&str) -> String) -> String {
        match (&self.mark, self.mark_radius) {
            (Some(m), Some(r)) => format!(
                "rim mark {} (at {:.1} from the centre)",
                name(m),
                show_small(r, Dimension::Length)
            ),
            // Never in a frame with the centre: nothing shows it is a mark.
            (Some(m), None) => format!(
                "second track {} (never in a frame with the centre: not known to be a rim mark, no spin measured)",
                name(m)
            ),
            (None, _) => match &self.mark_left_out {
                Some(l) => format!(
                    "rim mark {} left out: {}; v_t is not measured, the fits use v_cm (x) only",
                    name(&l.name),
                    l.why(self.scatter)
                ),
                None => "no rim mark: v_t is not measured, the fits use v_cm (x) only".to_string(),
            },
        }
    }

    /// What was found, in a few lines for people.
    pub fn describe(&self) -> String {
        let name = |n: &str| {
            if n.is_empty() {
                "x, y".to_string()
            } else {
                format!("'{n}'")
            }
        };
        let mut s = format!(
            "position track ({}): centre {}, {}; {} frames at {:.1} frames/s, scatter ≈ {:.2}\n",
            self.format,
            name(&self.centre),
            self.mark_text(name),
            self.frames,
            self.frame_rate,
            show_small(self.scatter, Dimension::Length)
        );
        if self.frames_dropped > 0 {
            s += &format!(
                "{} of {} rows left out: their centre position is empty or NaN ({} of the file)\n",
                self.frames_dropped,
                self.frames + self.frames_dropped,
                runs_text(&self.centre_gaps)
            );
        }
        if self.skipped.frames_skipped > 0 {
            s += &format!(
                "{} frame{} missing from the file (its time jumps between {}): nothing filled in, the local fits reach across\n",
                self.skipped.frames_skipped,
                if self.skipped.frames_skipped == 1 {
                    ""
                } else {
                    "s"
                },
                runs_text(&self.skipped.skipped_gaps)
            );
        }
        if let Some(k) = self.mark_every {
            s += &format!(
                "rim mark followed in every {} frame only ({} of {} frames): v_t in those, nothing filled in\n",
                ordinal(k),
                self.frames - self.mark_missing,
                self.frames,
            );
        } else if self.mark_missing > 0 {
            s += &format!(
                "rim mark missing in {} of {} frames ({} of the file): no v_t there, nothing filled in (the local fits beside a gap reach across it)\n",
                self.mark_missing,
                self.frames,
                runs_text(&self.mark_gaps)
            );
        }
        // Two frames before the impact give a speed but no ± (`--impact-at` early).
        let approach = if self.approach_speed_se.is_finite() {
            let (v, e) = crate::settings::units::with_uncertainty(
                self.approach_speed,
                self.approach_speed_se,
                3,
            );
            format!("{v} ± {e}")
        } else {
            format!("{:.3}", self.approach_speed)
        };
        s += &format!(
            "first impact {} at t = {:.4} s, x = {:.2} of the file ({} frames before, {} after); the other ball lies toward {}x; approach speed {approach} m/s (a line through the frames before it)
",
            if self.impact_detected {
                "found"
            } else {
                "given"
            },
            self.impact_t,
            show_small(self.impact_x, Dimension::Length),
            self.frames_before,
            self.frames_after,
            if self.direction > 0.0 { "+" } else { "−" },
        );

        s += &format!(
            "velocities by local quadratic fits over ±{:.1} ({} frames), never across an impact",
            show_small(self.half_window, Dimension::Time),
            self.half_window_frames
        );
        if let Some(asked) = self.half_window_widened_from {
            s += &format!(
                " (the ±{} asked for widened: a local quadratic needs at least {MIN_HALF_WINDOW} frames each side)",
                show(asked, Dimension::Time)
            );
        }
        if !self.later_impacts.is_empty() {
            let later: Vec<String> = self
                .later_impacts
                .iter()
                .map(|t| format!("{t:.3}"))
                .collect();
            s += &format!(" (later impacts at t = {} s)", later.join(", "));
        }
        s.push('\n');
        s
    }
}

/// Runs of missing frames said as times: "t = 0.325 … 0.392, 0.983 s" (the first
/// five runs, then how many more: "t = 0.021, …, 0.096 s, and 31 more runs", the
/// unit with the times it is of).
pub fn runs_text(runs: &[[f64; 2]]) -> String {
    const SHOWN: usize = 5;
    let parts: Vec<String> = runs
        .iter()
        .take(SHOWN)
        .map(|[a, b]| {
            if a == b {
                format!("{a:.3}")
            } else {
                format!("{a:.3} … {b:.3}")
            }
        })
        .collect();
    let more = more_runs(runs.len().saturating_sub(SHOWN));
    format!("t = {} s{more}", parts.join(", "))
}

/// ", and 31 more runs" after a list of runs that leaves `more` out; "" for none.
pub fn more_runs(more: usize) -> String {
    match more {
        0 => String::new(),
        1 => ", and 1 more run".into(),
        n => format!(", and {n} more runs"),
    }
}

/// The runs of neighbouring entries flagged `missing`, as their first and last
/// `times`.
pub(super) fn runs(times: &[f64], missing: &[bool]) -> Vec<[f64; 2]> {
    let mut out = Vec::new();
    let mut start = None;
    for (i, &m) in missing.iter().enumerate() {
        match (m, start) {
            (true, None) => start = Some(i),
            (false, Some(s)) => {
                if let (Some(&a), Some(&b)) = (times.get(s), times.get(i - 1)) {
                    out.push([a, b]);
                }
                start = None;
            }
            _ => {}
        }
    }
    if let Some(s) = start
        && let (Some(&a), Some(&b)) = (times.get(s), times.get(missing.len() - 1))
    {
        out.push([a, b]);
    }
    out
}

/// k where a rim mark missing in the runs `gaps` (times in the file, s, frames `dt`
/// apart) was followed in every k-th frame only (clicked every other frame in
/// Tracker): every gap is k − 1 frames long (but the first and last, which the
/// file's ends may cut) and the gaps lie k frames apart, over at least four gaps;
/// `None` otherwise.
pub(super) fn steady_every(gaps: &[[f64; 2]], dt: f64) -> Option<usize> {
    let frames = |a: f64, b: f64| ((b - a) / dt).round();
    let inner = gaps.get(1..gaps.len().saturating_sub(1))?;
    let length = inner.first().map(|&[a, b]| frames(a, b) + 1.0)?;
    // Ends but the last's, starts but the first's: the file's ends may cut those.
    let ends: Vec<f64> = gaps.iter().rev().skip(1).map(|&[_, b]| b).collect();
    let starts: Vec<f64> = gaps.iter().skip(1).map(|&[a, _]| a).collect();
    let apart = |v: &[f64]| {
        v.windows(2).all(|w| match *w {
            [a, b] => frames(b, a).abs() == length + 1.0,
            _ => false,
        })
    };
    let steady = gaps.len() >= 4
        && inner.iter().all(|&[a, b]| frames(a, b) + 1.0 == length)
        && apart(&ends)
        && apart(&starts);
    (steady && (1.0..10.0).contains(&length)).then_some(length as usize + 1)
}

/// "2nd", "3rd", "4th", … for k ≥ 2.
pub fn ordinal(k: usize) -> String {
    match k {
        2 => "2nd".into(),
        3 => "3rd".into(),
        k => format!("{k}th"),
    }
}

#[cfg(test)]
mod tests {
    use super::runs_text;

    #[test]
    fn runs_are_said_with_their_unit_after_the_times_and_the_rest_counted() {
        let runs: Vec<[f64; 2]> = (0..8)
            .map(|k| [0.1 * f64::from(k), 0.1 * f64::from(k)])
            .collect();
        assert_eq!(
            runs_text(&runs[..2]),
            "t = 0.000, 0.100 s",
            "a run of one frame is its time"
        );
        assert_eq!(runs_text(&[[0.325, 0.392]]), "t = 0.325 … 0.392 s");
        assert_eq!(
            runs_text(&runs),
            "t = 0.000, 0.100, 0.200, 0.300, 0.400 s, and 3 more runs"
        );
        assert_eq!(
            runs_text(&runs[..6]),
            "t = 0.000, 0.100, 0.200, 0.300, 0.400 s, and 1 more run"
        );
    }
}
