//! Speed against accuracy: every method over a sweep of step sizes (or tolerances),
//! each run measured against the exact solution, classified (`ok`, `inaccurate`,
//! `chatter`, `unstable`, `stalled`) and timed. A comparison's work is bounded: it
//! covers at most [`WINDOW`] of simulated time (a longer span is cut there, and every
//! row says so), so no run takes more than [`STEP_BUDGET`] steps; the accuracy runs
//! share the cores, the timing runs go one at a time; it can be stopped
//! ([`Progress`]). The exact scene is solved once, as the [`Reference`]: every run
//! starts from its state and is measured against it.
//!
//! Here the sweep and its orchestration; beside it the reference (`reference`), the
//! rows and what is read from them (`row`), one run's measurement (`measure`, with
//! its observers in `metrics` and `observers`) and the timing (`timing`).

mod measure;
mod metrics;
mod observers;
mod reference;
mod row;
#[cfg(test)]
mod tests;
mod timing;

use std::sync::atomic::{AtomicU64, Ordering};

use rayon::prelude::*;

use crate::methods::{Method, Settings};
use crate::physics::scene::{Scene, Span};
use crate::study::{Cancelled, Progress};

pub use measure::{measure, measure_observed, run};
pub use reference::{FINEST_STEP, Reference, STEP_BUDGET, WINDOW, outcome_until};
pub use row::{ACCURATE, Note, Row, RunStatus, fitted_order, headline};
pub use timing::{time, timing};

/// The default sweep: two steps per decade from 10 ms to 1 µs, tolerances 1e-2…1e-10.
pub fn default_sweep(method: Method) -> Vec<f64> {
    match method {
        Method::Exact => vec![0.0],
        Method::Rk45 => (2..=10).map(|e| 10f64.powi(-e)).collect(),
        _ => (4..=12).map(|i| 10f64.powf(-(i as f64) / 2.0)).collect(),
    }
}

/// Runs every method in `methods` over its sweep against the exact run of `scene`
/// over `span` (cut at [`WINDOW`]), each run within [`STEP_BUDGET`] steps (or the
/// settings' smaller `max_steps`); see [`measure_all`] for progress and stopping.
pub fn sweep(
    scene: &Scene,
    span: &Span,
    methods: &[Method],
    base: &Settings,
    progress: &dyn Progress,
) -> Result<Vec<Row>, Cancelled> {
    let reference = Reference::new(scene, span);
    let budget = STEP_BUDGET.min(base.max_steps);
    let runs: Vec<(Method, Settings)> = methods
        .iter()
        .flat_map(|&m| default_sweep(m).into_iter().map(move |v| (m, v)))
        .map(|(method, value)| {
            let settings = if method.adaptive() {
                Settings {
                    tolerance: value,
                    step: 1e-3,
                    max_steps: budget,
                    ..*base
                }
            } else {
                Settings {
                    step: value,
                    max_steps: budget,
                    ..*base
                }
            };
            (method, settings)
        })
        .collect();
    let mut rows = measure_all(scene, &reference, &runs, true, progress)?;
    for (row, (method, settings)) in rows.iter_mut().zip(&runs) {
        // A fixed step that needs more than the budget was refused before its first
        // step: say why in words a reader of the table can act on.
        let needed = ((reference.exact.t_end - reference.exact.t_start) / settings.step).ceil();
        if *method != Method::Exact && !method.adaptive() && needed > budget as f64 {
            row.note = Some(Note::Skipped { needed, budget });
        }
    }
    Ok(rows)
}

/// Measures every run of `runs` against `reference`, and times it if `timed`. The
/// accuracy runs (deterministic) share all cores; the timing runs then go one at a
/// time, so that each is timed without the others competing for a core. Ticks
/// `progress` once per run of each kind and stops soon after it says so.
pub fn measure_all(
    scene: &Scene,
    reference: &Reference,
    runs: &[(Method, Settings)],
    timed: bool,
    progress: &dyn Progress,
) -> Result<Vec<Row>, Cancelled> {
    let total = if timed { 2 } else { 1 } * runs.len() as u64;
    let done = AtomicU64::new(0);
    let tick = || progress.tick(done.fetch_add(1, Ordering::Relaxed) + 1, total);
    progress.tick(0, total);
    let mut rows = runs
        .par_iter()
        .map(|(method, settings)| {
            let row = measure(*method, scene, settings, reference, false, progress)?;
            tick();
            Ok(row)
        })
        .collect::<Result<Vec<Row>, Cancelled>>()?;
    for (row, (method, settings)) in rows.iter_mut().zip(runs).filter(|_| timed) {
        (row.time_min_s, row.time_median_s) =
            timing(*method, scene, settings, reference, row, progress)?;
        tick();
    }
    Ok(rows)
}
