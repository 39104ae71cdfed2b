//! The command line of the solution methods: `simulate --method` and `compare`.

use std::fmt::Write as _;

use serde::Serialize;

use super::args::{
    CompareArgs, CompareFormat, DataArgs, MAX_SAMPLES, SceneArgs, SimulateArgs, SimulateFormat,
};
use super::deliver::deliver;
use super::error::{BadValue, CliError, Flag};
use super::open::lab_of_stated_scene;
use super::states::{csv_output, samples, state_header, state_row};
use crate::methods::{self, Method, RunEnd, Stepping, Y};
use crate::physics::derived::Derived;
use crate::physics::scene::{Scene, Span};
use crate::physics::solution::{Event, Snapshot, Solution};
use crate::settings::units::{Dimension, show};
use crate::study::compare::{self as cmp, Row};

/// Stepping of a time-stepping run from the options, checked.
pub(super) fn settings(
    dt: Option<f64>,
    tol: Option<f64>,
    epsilon: Option<f64>,
) -> Result<Stepping, CliError> {
    let mut s = Stepping::default();
    if let Some(dt) = dt {
        if !(dt > 0.0 && dt <= 1.0) {
            return Err(BadValue::OutOfRange {
                flag: Flag("dt"),
                value: dt,
                dim: Dimension::Time,
                allowed: "0 < dt ≤ 1 s",
            }
            .into());
        }
        s.step = dt;
    }
    if let Some(tol) = tol {
        if !(1e-14..=0.1).contains(&tol) {
            return Err(BadValue::OutOfRange {
                flag: Flag("tol"),
                value: tol,
                dim: Dimension::Ratio,
                allowed: "1e-14 ≤ tol ≤ 0.1",
            }
            .into());
        }
        s.tolerance = tol;
    }
    if let Some(eps) = epsilon {
        if eps <= 0.0 {
            return Err(BadValue::OutOfRange {
                flag: Flag("epsilon"),
                value: eps,
                dim: Dimension::Speed,
                allowed: "ε > 0",
            }
            .into());
        }
        s.epsilon = eps;
    }
    Ok(s)
}

/// Collects what a time-stepping run detects: its events, and its states on a grid
/// (linearly interpolated between steps).
struct Recorder {
    events: Vec<Event>,
    grid: Vec<f64>,
    samples: Vec<Snapshot>,
    last: Option<(f64, Y)>,
    finite: bool,
}

impl methods::Observer for Recorder {
    fn step(&mut self, t: f64, y: &Y) -> bool {
        if !y.iter().all(|v| v.is_finite()) {
            self.finite = false;
            return false;
        }
        let (t0, y0) = self.last.unwrap_or((t, *y));
        while let Some(&tg) = self.grid.get(self.samples.len()) {
            if tg > t {
                break;
            }
            let f = if t > t0 {
                ((tg - t0) / (t - t0)).clamp(0.0, 1.0)
            } else {
                1.0
            };
            let yi: Y = std::array::from_fn(|j| y0[j] + f * (y[j] - y0[j]));
            self.samples.push(Snapshot {
                t: tg,
                left: methods::ball(&yi, 0),
                right: methods::ball(&yi, 1),
            });
        }
        self.last = Some((t, *y));
        true
    }

    fn event(&mut self, event: Event) {
        if self.events.len() < MAX_SAMPLES {
            self.events.push(event);
        }
    }
}

#[derive(Serialize)]
struct MethodRunJson<'a> {
    scene: &'a Scene,
    span: Span,
    derived: Derived,
    method: Method,
    settings: Stepping,
    steps: usize,
    rhs_evals: usize,
    /// Why the run ended early, if it did.
    stalled: Option<String>,
    events: &'a [Event],
    #[serde(skip_serializing_if = "Option::is_none")]
    samples: Option<&'a [Snapshot]>,
    #[serde(rename = "final")]
    final_state: Snapshot,
}

/// `simulate --method NAME`: one time-stepping run over the span of the exact run
/// `exact` (the lab's snapshot's); its events are those it detects.
pub(super) fn simulate_method(
    exact: &Solution,
    args: &SimulateArgs,
    settings: &Stepping,
) -> Result<String, CliError> {
    let scene = &exact.scene;
    let (t0, t1) = (exact.t_start, exact.t_end);
    let grid = match args.sample {
        Some(dt) => samples(exact, dt)?.iter().map(|s| s.t).collect(),
        None => Vec::new(),
    };
    let model = methods::Model::of(scene);
    let mut rec = Recorder {
        events: Vec::new(),
        grid,
        samples: Vec::new(),
        last: None,
        finite: true,
    };
    // Every method starts from the exact run-up's state at the span's start.
    let run = methods::Run {
        model: &model,
        y0: methods::state(exact.at(t0)),
        t0,
        t1,
        stepping: settings,
    };
    let outcome = args.method.integrate(&run, &mut rec);
    if let (Some(why), 0) = (&outcome.stalled, outcome.steps) {
        // Refused before the first step: there is no run to report.
        return Err(BadValue::MethodCannotRun {
            method: args.method,
            why: *why,
        }
        .into());
    }
    let stalled = match (&outcome.stalled, rec.finite) {
        (Some(why), _) => Some(why.to_string()),
        (None, false) => Some(format!(
            "the state became non-finite at t = {:.6} s",
            outcome.t
        )),
        _ => None,
    };
    let final_state = Snapshot {
        t: outcome.t,
        left: methods::ball(&outcome.y, 0),
        right: methods::ball(&outcome.y, 1),
    };
    let samples = args.sample.map(|_| rec.samples.as_slice());
    Ok(match args.format {
        SimulateFormat::Json => {
            let doc = MethodRunJson {
                scene,
                span: Span {
                    t_start: t0,
                    t_end: Some(t1),
                },
                derived: Derived::of(scene),
                method: args.method,
                settings: *settings,
                steps: outcome.steps,
                rhs_evals: outcome.rhs_evals,
                stalled,
                events: &rec.events,
                samples,
                final_state,
            };
            let mut s = serde_json::to_string_pretty(&doc).expect("plain data serializes");
            s.push('\n');
            s
        }
        SimulateFormat::Csv => {
            let detected = Solution {
                events: rec.events.clone(),
                ..exact.clone()
            };
            csv_output(&detected, samples)?
        }
        SimulateFormat::Table => method_table(args, settings, &outcome, stalled, &rec, final_state),
    })
}

/// `simulate --method`'s table: the run's method, settings and work, then its
/// detected events, the samples and the final state in time order.
fn method_table(
    args: &SimulateArgs,
    settings: &Stepping,
    outcome: &RunEnd,
    stalled: Option<String>,
    rec: &Recorder,
    final_state: Snapshot,
) -> String {
    let mut out = String::new();
    let _ = writeln!(
        out,
        "method   {} (step {}, tolerance {}, ε {}): {} steps, {} right-hand-side evaluations{}",
        args.method.name(),
        show(settings.step, Dimension::Time),
        settings.tolerance,
        show(settings.epsilon, Dimension::Speed),
        outcome.steps,
        outcome.rhs_evals,
        stalled.map_or(String::new(), |s| format!(", stalled: {s}"))
    );
    let _ = writeln!(out, "{}", state_header());
    let mut rows: Vec<_> = rec
        .events
        .iter()
        .map(|e| (e.t, e.kind.name(), e.ball.name(), e.left, e.right))
        .chain(
            rec.samples
                .iter()
                .map(|s| (s.t, "sample", "", s.left, s.right)),
        )
        .chain(std::iter::once((
            final_state.t,
            "final",
            "",
            final_state.left,
            final_state.right,
        )))
        .collect();
    rows.sort_by(|a, b| a.0.total_cmp(&b.0));
    for (t, kind, ball, l, r) in rows {
        let _ = writeln!(out, "{}", state_row(t, kind, ball, l, r));
    }
    out
}

#[derive(Serialize)]
struct CompareJson<'a> {
    scene: &'a Scene,
    /// The span compared (the snapshot's; a run may be cut earlier, see `cut`).
    span: Span,
    rows: &'a [Row],
}

/// `compare`: every method over its sweep, against the exact solution, on the lab's
/// snapshot of the scene the options give and over its span (the app's Methods view
/// compares over the same one: a measured series, the preset's or `--data`, stretches
/// it to the last measured point).
pub(super) fn compare(
    scene_args: &SceneArgs,
    data: &DataArgs,
    args: &CompareArgs,
) -> Result<String, CliError> {
    let lab = lab_of_stated_scene(scene_args, data)?;
    let (scene, span) = (lab.scene, lab.span);
    let base = settings(None, None, args.epsilon)?;
    deliver(args.output.as_deref(), || {
        compare_text(&scene, &span, &base, args)
    })
}

/// What `compare` prints: the methods' rows in the format asked for.
fn compare_text(
    scene: &Scene,
    span: &Span,
    base: &Stepping,
    args: &CompareArgs,
) -> Result<String, CliError> {
    let methods: Vec<Method> = match &args.methods {
        Some(m) if !m.is_empty() => {
            // Exact first, then each method once (a repeated name adds no rows, and
            // no work: the sweep's bound is per method).
            let mut unique = vec![Method::Exact];
            for x in m {
                if !unique.contains(x) {
                    unique.push(*x);
                }
            }
            unique
        }
        _ => std::iter::once(Method::Exact)
            .chain(Method::TIME_STEPPING)
            .collect(),
    };
    let bar = super::progress::Bar::new("runs", true);
    let rows = cmp::sweep(scene, span, &methods, base, &bar);
    bar.finish();
    let rows = rows.map_err(|_| CliError::Interrupted)?;
    Ok(match args.format {
        CompareFormat::Json => {
            let doc = CompareJson {
                scene,
                span: *span,
                rows: &rows,
            };
            let mut s = serde_json::to_string_pretty(&doc).expect("plain data serializes");
            s.push('\n');
            s
        }
        CompareFormat::Table => table(&rows),
        CompareFormat::Svg => {
            crate::study::figures::work_precision(&rows, scene).map_err(|source| {
                CliError::Draw {
                    what: "diagram",
                    source,
                }
            })?
        }
    })
}

fn table(rows: &[Row]) -> String {
    let mut out = String::new();
    let _ = writeln!(
        out,
        "{:<17} {:>8} {:>8} {:<10} {:<20} {:>9} {:>9} {:>9} {:>9} {:>9} {:>9} {:>10} {:>10}",
        "method",
        "step s",
        "tol",
        "status",
        "outcome",
        "err_v",
        "err_u",
        "err_t'",
        "err_end",
        "E drift",
        "steps",
        "min s",
        "median s"
    );
    let opt = |v: Option<f64>| v.map_or("-".to_string(), |v| format!("{v:.1e}"));
    for r in rows {
        let _ = writeln!(
            out,
            "{:<17} {:>8} {:>8} {:<10} {:<20} {:>9.2e} {:>9.2e} {:>9} {:>9.2e} {:>9.2e} {:>9} {:>10.3e} {:>10.3e}",
            r.method.name(),
            opt(r.step),
            opt(r.tolerance),
            r.status.name(),
            outcome_cell(r),
            r.err_v,
            r.err_u,
            opt(r.err_t_roll),
            r.err_final,
            r.energy_drift,
            r.steps,
            r.time_min_s,
            r.time_median_s
        );
    }
    for r in rows.iter().filter(|r| r.status == cmp::RunStatus::Stalled) {
        if let Some(note) = &r.note {
            let _ = writeln!(
                out,
                "stalled: {} at {}: {note}",
                r.method.name(),
                run_setting(r)
            );
        }
    }
    if let Some(end) = rows.iter().find_map(|r| r.cut) {
        let _ = writeln!(
            out,
            "cut: every run compared up to t = {} only (the span goes on): the step budget, {} steps of {:.0e} s per run",
            show(end, Dimension::Time),
            cmp::STEP_BUDGET,
            cmp::FINEST_STEP
        );
    }
    let orders: Vec<String> = Method::TIME_STEPPING
        .iter()
        .filter_map(|&m| cmp::fitted_order(rows, m).map(|p| format!("{} {p:.2}", m.name())))
        .collect();
    if !orders.is_empty() {
        let _ = writeln!(
            out,
            "fitted order (slope of log err_v against log h): {}",
            orders.join(", ")
        );
    }
    let _ = writeln!(
        out,
        "\nerrors in m/s (err_t' in s) against the exact solution at each method's own steps;\n\
         status ok: stable, and errors within 1 % of the scene's largest speed (else inaccurate);\n\
         outcome: the run's outcome word and impacts, \"wrong\" where either differs from exact's;\n\
         E drift: largest energy excess over the exact run, relative to the start;\n\
         times: minimum and median of at least three runs (after an untimed warm-up for runs under 10 ms)."
    );
    let _ = writeln!(out, "{}", headline(rows));
    out
}

/// A run's setting in a few characters: its step ("h = 1.0e-3 s") or tolerance.
fn run_setting(r: &Row) -> String {
    match (r.step, r.tolerance) {
        (Some(h), _) => format!("h = {h:.1e} s"),
        (None, Some(t)) => format!("tol = {t:.0e}"),
        _ => String::new(),
    }
}

/// The comparison's headline: how much faster exact is than the fastest run that is
/// ok and reaches err_v ≤ 1e-6 m/s, or that none did.
fn headline(rows: &[Row]) -> String {
    match cmp::headline(rows, 1e-6) {
        Some((factor, best, exact)) => format!(
            "headline: exact takes {:.2e} s; the fastest run reaching err_v ≤ 1e-6 m/s with status ok is {} ({}) at {:.2e} s: exact is {}× faster.",
            exact.time_median_s,
            best.method.name(),
            run_setting(best),
            best.time_median_s,
            crate::settings::units::significant(factor, 2)
        ),
        None => {
            "headline: no time-stepping run reached err_v ≤ 1e-6 m/s with status ok in this sweep."
                .to_string()
        }
    }
}

/// "recollide 20", "pressed 1 wrong": the run's outcome word and impact count, marked
/// where either differs from the exact run's.
fn outcome_cell(r: &Row) -> String {
    let mark = if r.outcome_right { "" } else { " wrong" };
    format!("{} {}{mark}", r.outcome.name(), r.impacts)
}
