//! One run of a method measured against the reference: its first pass finds the
//! impacts, the second measures the errors; then the row.

use crate::methods::{Method, Model, Observer, RunEnd, Stepping};
use crate::physics::scene::Scene;
use crate::study::{Cancelled, Progress, Quiet};

use super::metrics::{Metrics, final_error, run_outcome, run_status};
use super::observers::{Impacts, Unwatched, Watch, impact_windows};
use super::reference::{Reference, exact_roll, impact_times};
use super::row::{ACCURATE, Note, Row, exact_row};
use super::timing::timing;

/// One run of `method` on `scene`, measured against `reference` and timed.
pub fn run(method: Method, scene: &Scene, settings: &Stepping, reference: &Reference) -> Row {
    measure(method, scene, settings, reference, true, &Quiet).expect("Quiet never cancels")
}

/// [`run`], with the timing runs only if `timed` (the untimed row is deterministic),
/// stopping early (with `Cancelled`) when `progress` says so.
pub fn measure(
    method: Method,
    scene: &Scene,
    settings: &Stepping,
    reference: &Reference,
    timed: bool,
    progress: &dyn Progress,
) -> Result<Row, Cancelled> {
    let mut row = measure_observed(method, scene, settings, reference, progress, &mut Unwatched)?;
    if timed {
        (row.time_min_s, row.time_median_s) =
            timing(method, scene, settings, reference, &row, progress)?;
    }
    Ok(row)
}

/// The untimed row of one run, with `also` watching the steps and events of its first
/// pass (so a caller that wants the run's points, as the overlay, need not integrate
/// it again).
pub fn measure_observed(
    method: Method,
    scene: &Scene,
    settings: &Stepping,
    reference: &Reference,
    progress: &dyn Progress,
    also: &mut dyn Observer,
) -> Result<Row, Cancelled> {
    if method == Method::Exact {
        return Ok(exact_row(reference));
    }
    let exact = &reference.exact;
    let model = Model::of(scene);
    let run = reference.run(&model, settings);
    let settle = if method.regularised() {
        20.0 * settings.epsilon / model.slip_rate()
    } else {
        2.0 * settings.step
    };
    // First pass: where the method puts its impacts, to pair them with the exact ones.
    let mut found = Impacts(Vec::new(), Watch::new(progress), also);
    method.integrate(&run, &mut found);
    if progress.cancelled() {
        return Err(Cancelled);
    }
    let exact_impacts = impact_times(exact);
    // rk45 places its steps itself: its windows are one tolerance wide.
    let slack = if method.adaptive() {
        settings.tolerance
    } else {
        settings.step
    };
    let (windows, err_t_impact) = impact_windows(&exact_impacts, &found.0, slack);
    let mut metrics = Metrics::new(exact, progress, model, &run.y0, settle, windows, &found.0);
    let run_end: RunEnd = method.integrate(&run, &mut metrics);
    if progress.cancelled() {
        return Err(Cancelled);
    }
    let err_final = final_error(exact, &run_end);
    let forces = (scene.mu > 0.0, scene.rolling_resistance > 0.0);
    let (outcome, impacts) = run_outcome(&metrics, &run_end, found.0.len(), forces);
    let outcome_right =
        outcome == reference.outcome && (reference.accumulating || impacts == reference.impacts);
    let accurate = [metrics.err_v, metrics.err_u, err_final]
        .iter()
        .all(|&e| e <= ACCURATE * scene.speed_scale());
    let status = run_status(&metrics, &run_end, method, settings, accurate);
    let exact_roll = exact_roll(exact);
    Ok(Row {
        method,
        step: (!method.adaptive()).then_some(settings.step),
        tolerance: method.adaptive().then_some(settings.tolerance),
        status,
        err_v: metrics.err_v,
        err_u: metrics.err_u,
        err_t_roll: match (metrics.first_roll, exact_roll) {
            (Some(a), Some(b)) => Some((a - b).abs()),
            _ => None,
        },
        err_t_impact,
        err_final: if err_final.is_finite() {
            err_final
        } else {
            f64::INFINITY
        },
        energy_drift: metrics.drift,
        slip_rolling: metrics.slip_rolling,
        outcome,
        impacts,
        outcome_right,
        steps: run_end.steps,
        rhs_evals: run_end.rhs_evals,
        time_min_s: 0.0,
        time_median_s: 0.0,
        cut: reference.cut,
        note: run_end.stalled.map(Note::Stalled),
    })
}
