//! A comparison's rows: how each run ended, what it measured, and what is read
//! from the rows (the headline, a method's fitted order).

use serde::Serialize;

use crate::methods::{Method, Stall};
use crate::physics::derived::Outcome;

use super::reference::{Reference, exact_roll};

/// A run is accurate (status `ok`) within this share of the scene's largest speed, in
/// its velocities, spins and end state.
pub const ACCURATE: f64 = 0.01;

/// How a run ended (interface.md).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum RunStatus {
    /// Converges as it should.
    Ok,
    /// The slip never settles: it flips sign while the ball should roll.
    Chatter,
    /// Blow-up, energy growth, or a rolling state that does not hold.
    Unstable,
    /// Step-size collapse or step budget hit (e.g. at an accumulation point).
    Stalled,
    /// Stable, but off by more than [`ACCURATE`] of the scene's largest speed.
    Inaccurate,
}

impl RunStatus {
    pub fn name(self) -> &'static str {
        match self {
            RunStatus::Ok => "ok",
            RunStatus::Chatter => "chatter",
            RunStatus::Unstable => "unstable",
            RunStatus::Stalled => "stalled",
            RunStatus::Inaccurate => "inaccurate",
        }
    }
}

/// One run of the sweep (interface.md's row, plus the rolling-phase slip).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Row {
    pub method: Method,
    pub step: Option<f64>,
    pub tolerance: Option<f64>,
    pub status: RunStatus,
    /// max |Δv_cm| over the run, m/s, away from impacts (see `err_t_impact`).
    pub err_v: f64,
    /// max |Δv_t| over the run, m/s, away from impacts.
    pub err_u: f64,
    /// Error of the left ball's first rolling time after the impact, s.
    pub err_t_roll: Option<f64>,
    /// Largest timing error of an impact (the k-th detected against the k-th exact), s.
    pub err_t_impact: Option<f64>,
    /// Largest velocity error at the end of the run, m/s.
    pub err_final: f64,
    /// Largest energy excess over the exact solution, relative to the initial energy.
    pub energy_drift: f64,
    /// Largest |slip| while the exact ball rolls (after a short settling time), m/s.
    pub slip_rolling: f64,
    /// What the run does ([`Outcome`]) as it detects it, and its impacts.
    pub outcome: Outcome,
    pub impacts: usize,
    /// The same outcome word as the exact run, and the same impact count (where the
    /// exact impacts accumulate, infinitely many: the word decides).
    pub outcome_right: bool,
    pub steps: usize,
    pub rhs_evals: usize,
    pub time_min_s: f64,
    pub time_median_s: f64,
    /// Where the step budget ended the comparison (s) when the span went on beyond
    /// [`WINDOW`]; `None` when the run covered the whole span.
    pub cut: Option<f64>,
    /// Why a run stalled.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub note: Option<Note>,
}

impl Row {
    /// The run's setting in a few characters: `h 1e-3` (a step, s) or `tol 1e-6`.
    pub fn setting(&self) -> String {
        match (self.step, self.tolerance) {
            (Some(h), _) => format!("h {h:.0e}"),
            (_, Some(t)) => format!("tol {t:.0e}"),
            _ => String::new(),
        }
    }
}

/// Why a row's run stalled, shown as a sentence (and so in JSON).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Note {
    /// The method stalled on its own.
    Stalled(Stall),
    /// A fixed step that would need `needed` steps, over the `budget` of a run:
    /// refused before its first step.
    Skipped { needed: f64, budget: usize },
}

impl std::fmt::Display for Note {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Note::Stalled(why) => why.fmt(f),
            Note::Skipped { needed, budget } => write!(
                f,
                "skipped: {needed} steps needed, over the budget of {budget} steps per run (a shorter span runs it)"
            ),
        }
    }
}

impl Serialize for Note {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.collect_str(self)
    }
}

/// The exact engine's row: no error, its segments as steps.
pub(super) fn exact_row(reference: &Reference) -> Row {
    let exact = &reference.exact;
    Row {
        method: Method::Exact,
        step: None,
        tolerance: None,
        status: RunStatus::Ok,
        outcome: reference.outcome,
        impacts: reference.impacts,
        outcome_right: true,
        err_v: 0.0,
        err_u: 0.0,
        err_t_roll: exact_roll(exact).map(|_| 0.0),
        err_t_impact: Some(0.0),
        err_final: 0.0,
        energy_drift: 0.0,
        slip_rolling: 0.0,
        steps: exact.segments.len(),
        rhs_evals: 0,
        time_min_s: 0.0,
        time_median_s: 0.0,
        cut: reference.cut,
        note: None,
    }
}

/// The headline: how many times faster `exact` is than the fastest time-stepping run
/// that reached `accuracy` (m/s) in err_v with status ok.
pub fn headline(rows: &[Row], accuracy: f64) -> Option<(f64, &Row, &Row)> {
    let exact = rows.iter().find(|r| r.method == Method::Exact)?;
    let best = rows
        .iter()
        .filter(|r| r.method != Method::Exact && r.status == RunStatus::Ok && r.err_v <= accuracy)
        .min_by(|a, b| a.time_median_s.total_cmp(&b.time_median_s))?;
    Some((best.time_median_s / exact.time_median_s, best, exact))
}

/// The order p of a fixed-step method (err_v ∝ h^p): the least-squares slope of
/// log err_v against log h over its runs that neither blew up nor stalled, with an
/// error above rounding; `None` for an adaptive method or with fewer than three runs.
pub fn fitted_order(rows: &[Row], method: Method) -> Option<f64> {
    let points: Vec<(f64, f64)> = rows
        .iter()
        .filter(|r| r.method == method && r.err_v > 1e-13 && r.err_v.is_finite())
        .filter(|r| !matches!(r.status, RunStatus::Unstable | RunStatus::Stalled))
        .filter_map(|r| Some((r.step?.log10(), r.err_v.log10())))
        .collect();
    if method.adaptive() || points.len() < 3 {
        return None;
    }
    let n = points.len() as f64;
    let (mx, my) = points
        .iter()
        .fold((0.0, 0.0), |a, p| (a.0 + p.0 / n, a.1 + p.1 / n));
    let sxx: f64 = points.iter().map(|p| (p.0 - mx).powi(2)).sum();
    let sxy: f64 = points.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum();
    (sxx > 0.0).then(|| sxy / sxx)
}
