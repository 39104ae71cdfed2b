//! A run's states as `simulate` prints them (the exact run and a method's alike):
//! samples at a step, the CSV, and the table of both balls' states.

use std::fmt::Write as _;

use super::args::MAX_SAMPLES;
use super::error::{BadValue, CliError};
use crate::physics::model::BallState;
use crate::physics::solution::{Snapshot, Solution};
use crate::settings::units::Dimension;

/// The exact states every `dt` over the run, at most [`MAX_SAMPLES`] of them.
pub(super) fn samples(solution: &Solution, dt: f64) -> Result<Vec<Snapshot>, CliError> {
    // As many as `Solution::sample` gives: the grid points from t_start to t_end.
    let count = ((solution.t_end - solution.t_start) / dt + 1e-9).floor() + 1.0;
    if dt <= 0.0 || count > MAX_SAMPLES as f64 {
        return Err(BadValue::TooManySamples {
            dt,
            count,
            start: solution.t_start,
            end: solution.t_end,
        }
        .into());
    }
    Ok(solution.sample(dt))
}

/// CSV: the samples if `--sample` is given, else the events. SI units.
pub(super) fn csv_output(
    solution: &Solution,
    samples: Option<&[Snapshot]>,
) -> Result<String, CliError> {
    crate::study::export::run_csv(solution, samples).map_err(|e| CliError::Io(e.into()))
}

/// The state at each event, then at each sample if any.
pub(super) fn state_rows(out: &mut String, solution: &Solution, samples: Option<&[Snapshot]>) {
    let header = state_header();
    let row = state_row;
    let _ = writeln!(out, "{header}");
    for e in solution.visible_events() {
        let _ = writeln!(
            out,
            "{}",
            row(e.t, e.kind.name(), e.ball.name(), e.left, e.right)
        );
    }
    if let Some(samples) = samples {
        let _ = writeln!(out, "\nsamples\n{header}");
        for s in samples {
            let _ = writeln!(out, "{}", row(s.t, "", "", s.left, s.right));
        }
    }
}

/// Header of the tables of both balls' states (events and samples).
pub(super) fn state_header() -> String {
    format!(
        "{:>10}  {:<14} {:<6} {:>9} {:>9} {:>9}  {:>9} {:>9} {:>9}",
        "t (s)",
        "event",
        "ball",
        format!("x_L ({})", Dimension::Length.display_unit().0),
        "v_L (m/s)",
        "u_L (m/s)",
        format!("x_R ({})", Dimension::Length.display_unit().0),
        "v_R (m/s)",
        "u_R (m/s)"
    )
}

/// One row of those tables.
pub(super) fn state_row(t: f64, kind: &str, ball: &str, l: BallState, r: BallState) -> String {
    format!(
        "{t:>10.6}  {kind:<14} {ball:<6} {:>9.4} {:>9.5} {:>9.5}  {:>9.4} {:>9.5} {:>9.5}",
        Dimension::Length.to_display(l.x),
        l.v,
        l.u,
        Dimension::Length.to_display(r.x),
        r.v,
        r.u
    )
}
