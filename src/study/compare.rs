//! Speed against accuracy: every method over a sweep of step sizes (or tolerances),
//! each run measured against the exact solution, classified (`ok`, `chatter`,
//! `unstable`, `stalled`) and timed. A sweep is bounded ([`STEP_BUDGET`] per run) and
//! can be stopped ([`Progress`]).

use std::time::Instant;

use serde::Serialize;

use crate::methods::{Method, Model, Observer, RunEnd, Settings, Y, integrate, start_state};
use crate::physics::model::Phase;
use crate::physics::scene::{Scene, Span};
use crate::physics::solution::{Event, EventKind, Solution, Who};
use crate::study::{Cancelled, Progress, Quiet};

/// Most steps one run of a [`sweep`] may take. A level that needs more (a fixed step
/// too fine for the span) is skipped as `stalled`, saying so. Every preset's default
/// span (under 4 s) runs its finest level (1 µs) within it, so the budget only bounds
/// long spans: without it `--t-end 19.7` spent 70 s on 20-million-step runs.
pub const STEP_BUDGET: usize = 4_000_000;

/// Steps between two looks at the stop flag: often enough to stop within
/// milliseconds, rare enough to cost nothing.
const CHECK_EVERY: u32 = 4096;

/// Counts steps and says when to stop because the caller cancelled.
struct Watch<'a> {
    progress: &'a dyn Progress,
    count: u32,
}

impl<'a> Watch<'a> {
    fn new(progress: &'a dyn Progress) -> Watch<'a> {
        Watch { progress, count: 0 }
    }

    fn stop(&mut self) -> bool {
        self.count = self.count.wrapping_add(1);
        self.count.is_multiple_of(CHECK_EVERY) && self.progress.cancelled()
    }
}

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
}

impl RunStatus {
    pub fn name(self) -> &'static str {
        match self {
            RunStatus::Ok => "ok",
            RunStatus::Chatter => "chatter",
            RunStatus::Unstable => "unstable",
            RunStatus::Stalled => "stalled",
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
    pub steps: usize,
    pub rhs_evals: usize,
    pub time_min_s: f64,
    pub time_median_s: f64,
    /// Why a run stalled.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub note: Option<String>,
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

/// Compares a run with the exact solution step by step.
struct Metrics<'a> {
    exact: &'a Solution,
    watch: Watch<'a>,
    model: Model,
    e0: f64,
    err_v: f64,
    err_u: f64,
    drift: f64,
    gain: f64,
    nonfinite: bool,
    first_roll: Option<f64>,
    /// Time to let a regularised slip settle after the exact ball starts rolling.
    settle: f64,
    last_slip: [Option<f64>; 2],
    flips: usize,
    slip_rolling: f64,
    /// Time windows around impacts left out of the error maxima (sorted), and where
    /// the scan through them stands.
    windows: Vec<(f64, f64)>,
    next_window: usize,
}

impl Observer for Metrics<'_> {
    fn step(&mut self, t: f64, y: &Y) -> bool {
        if self.watch.stop() {
            return false;
        }
        if !y.iter().all(|v| v.is_finite()) {
            self.nonfinite = true;
            return false;
        }
        // Near an impact a jump placed a little early or late makes any method's
        // error there the size of the jump: those windows are left out of the maxima,
        // and the timing is reported as err_t_impact instead.
        while self.next_window < self.windows.len() && self.windows[self.next_window].1 < t {
            self.next_window += 1;
        }
        let impact_step = self
            .windows
            .get(self.next_window)
            .is_some_and(|w| w.0 <= t && t <= w.1);
        let ex = self.exact.at(t);
        let ex_left = self.exact.at_left(t);
        let seg = self.exact.segment_at(t);
        for (i, (e, el)) in [(ex.left, ex_left.left), (ex.right, ex_left.right)]
            .into_iter()
            .enumerate()
        {
            if !impact_step {
                let dv = (y[3 * i + 1] - e.v).abs().min((y[3 * i + 1] - el.v).abs());
                let du = (y[3 * i + 2] - e.u).abs().min((y[3 * i + 2] - el.u).abs());
                self.err_v = self.err_v.max(dv);
                self.err_u = self.err_u.max(du);
            }
            let slip = y[3 * i + 1] - y[3 * i + 2];
            let rolling =
                !impact_step && seg.phase[i] == Phase::Rolling && t - seg.t0 > self.settle;
            if rolling {
                self.slip_rolling = self.slip_rolling.max(slip.abs());
                if let Some(prev) = self.last_slip[i]
                    && prev * slip < 0.0
                {
                    self.flips += 1;
                }
                self.last_slip[i] = Some(slip);
            } else {
                self.last_slip[i] = None;
            }
        }
        let e = self.model.energy(y);
        let e_exact = self.exact.energy_at(t).kinetic();
        if self.e0 > 0.0 {
            self.drift = self.drift.max((e - e_exact) / self.e0);
            self.gain = self.gain.max(e / self.e0 - 1.0);
        }
        true
    }

    fn event(&mut self, event: Event) {
        if event.kind == EventKind::Rolling && event.ball == Who::Left && event.t > 0.0 {
            self.first_roll.get_or_insert(event.t);
        }
    }
}

/// Collects the times of the impacts a method detects.
/// The first pass's observer: the impacts the method detects, and whoever else
/// watches that pass (`also`: the overlay records its points there).
struct Impacts<'a, 'o>(Vec<f64>, Watch<'a>, &'o mut dyn Observer);

impl Observer for Impacts<'_, '_> {
    fn step(&mut self, t: f64, y: &Y) -> bool {
        let also = self.2.step(t, y);
        also && !self.1.stop() && y.iter().all(|v| v.is_finite())
    }

    fn event(&mut self, event: Event) {
        if event.kind == EventKind::Collision {
            self.0.push(event.t);
        }
        self.2.event(event);
    }
}

/// Watches nothing.
struct Unwatched;

impl Observer for Unwatched {
    fn step(&mut self, _t: f64, _y: &Y) -> bool {
        true
    }
}

/// Windows around impacts that the error maxima leave out: from each exact impact to
/// the nearest impact the method detected, widened by `slack` on each side, where that
/// pairing is unambiguous (closer than half-way to the neighbouring exact impacts).
/// An impact a method misses gets no window: its jump counts as an error. Also the
/// largest distance from an exact impact to the nearest detected one.
fn impact_windows(exact: &[f64], method: &[f64], slack: f64) -> (Vec<(f64, f64)>, Option<f64>) {
    let mut windows = Vec::new();
    let mut worst: Option<f64> = None;
    for (k, &a) in exact.iter().enumerate() {
        let before = k.checked_sub(1).map_or(f64::INFINITY, |j| a - exact[j]);
        let after = exact.get(k + 1).map_or(f64::INFINITY, |&n| n - a);
        let reach = 0.5 * before.min(after);
        let i = method.partition_point(|&b| b < a);
        let nearest = [i.checked_sub(1), Some(i)]
            .into_iter()
            .flatten()
            .filter_map(|j| method.get(j))
            .min_by(|x, y| (*x - a).abs().total_cmp(&(*y - a).abs()));
        if let Some(&b) = nearest {
            worst = Some(worst.unwrap_or(0.0).max((a - b).abs()));
            if (a - b).abs() < reach {
                windows.push((a.min(b) - slack, a.max(b) + slack));
            }
        }
    }
    windows.sort_by(|a, b| a.0.total_cmp(&b.0));
    (windows, worst)
}

/// Only checks that the state stays finite: the observer of timed runs.
struct Finite<'a>(Watch<'a>);

impl Observer for Finite<'_> {
    fn step(&mut self, _t: f64, y: &Y) -> bool {
        !self.0.stop() && y.iter().all(|v| v.is_finite())
    }
}

/// The exact engine's first rolling (or rest) time of the left ball after the impact.
fn exact_roll(sol: &Solution) -> Option<f64> {
    sol.events
        .iter()
        .find(|e| {
            e.t > 0.0
                && e.ball == Who::Left
                && matches!(e.kind, EventKind::Rolling | EventKind::Rest)
        })
        .map(|e| e.t)
}

/// Minimum and median of repeated timings of `f` (after one untimed warm-up), with
/// more repeats for quick runs.
pub fn time<T>(mut f: impl FnMut() -> T) -> (f64, f64) {
    std::hint::black_box(f());
    let mut times = Vec::new();
    let budget = Instant::now();
    while times.len() < 3 || (times.len() < 15 && budget.elapsed().as_secs_f64() < 0.05) {
        let start = Instant::now();
        std::hint::black_box(f());
        times.push(start.elapsed().as_secs_f64());
    }
    times.sort_by(f64::total_cmp);
    (times[0], times[times.len() / 2])
}

/// One run of `method` on `scene` over `span`, measured against `exact`.
pub fn run(
    method: Method,
    scene: &Scene,
    span: &Span,
    settings: &Settings,
    exact: &Solution,
) -> Row {
    measure(method, scene, span, settings, exact, true, &Quiet).expect("Quiet never cancels")
}

/// [`run`], with the timing runs only if `timed` (the untimed row is deterministic),
/// stopping early (with `Cancelled`) when `progress` says so.
pub fn measure(
    method: Method,
    scene: &Scene,
    span: &Span,
    settings: &Settings,
    exact: &Solution,
    timed: bool,
    progress: &dyn Progress,
) -> Result<Row, Cancelled> {
    measure_observed(
        method,
        scene,
        span,
        settings,
        exact,
        timed,
        progress,
        &mut Unwatched,
    )
}

/// [`measure`], with `also` watching the steps and events of the run's first pass (so
/// a caller that wants the run's points, as the overlay, need not integrate it again).
#[allow(clippy::too_many_arguments)]
pub fn measure_observed(
    method: Method,
    scene: &Scene,
    span: &Span,
    settings: &Settings,
    exact: &Solution,
    timed: bool,
    progress: &dyn Progress,
    also: &mut dyn Observer,
) -> Result<Row, Cancelled> {
    let model = Model::of(scene);
    let (t0, t1) = (exact.t_start, exact.t_end);
    if method == Method::Exact {
        let (time_min_s, time_median_s) = if timed {
            time(|| crate::physics::engine::solve(scene, span))
        } else {
            (0.0, 0.0)
        };
        return Ok(Row {
            method,
            step: None,
            tolerance: None,
            status: RunStatus::Ok,
            err_v: 0.0,
            err_u: 0.0,
            err_t_roll: exact_roll(exact).map(|_| 0.0),
            err_t_impact: Some(0.0),
            err_final: 0.0,
            energy_drift: 0.0,
            slip_rolling: 0.0,
            steps: exact.segments.len(),
            rhs_evals: 0,
            time_min_s,
            time_median_s,
            note: None,
        });
    }
    let y0 = start_state(scene, t0);
    let settle = if method.regularised() {
        20.0 * settings.epsilon / model.slip_rate()
    } else {
        2.0 * settings.step
    };
    // First pass: where the method puts its impacts, to pair them with the exact ones.
    let mut found = Impacts(Vec::new(), Watch::new(progress), also);
    integrate(method, &model, y0, t0, t1, settings, &mut found);
    if progress.cancelled() {
        return Err(Cancelled);
    }
    let exact_impacts: Vec<f64> = exact
        .events
        .iter()
        .filter(|e| {
            matches!(
                e.kind,
                EventKind::Collision | EventKind::ZenoRest | EventKind::ZenoContact
            )
        })
        .map(|e| e.t)
        .collect();
    // rk45 places its steps itself: its windows are one tolerance wide.
    let slack = if method.adaptive() {
        settings.tolerance
    } else {
        settings.step
    };
    let (windows, err_t_impact) = impact_windows(&exact_impacts, &found.0, slack);
    let mut metrics = Metrics {
        exact,
        watch: Watch::new(progress),
        model,
        e0: model.energy(&y0),
        err_v: 0.0,
        err_u: 0.0,
        drift: 0.0,
        gain: 0.0,
        nonfinite: false,
        first_roll: None,
        settle,
        last_slip: [None; 2],
        flips: 0,
        slip_rolling: 0.0,
        windows: windows.clone(),
        next_window: 0,
    };
    let outcome: RunEnd = integrate(method, &model, y0, t0, t1, settings, &mut metrics);
    if progress.cancelled() {
        return Err(Cancelled);
    }
    let end = exact.at(outcome.t);
    let err_final = [
        outcome.y[1] - end.left.v,
        outcome.y[2] - end.left.u,
        outcome.y[4] - end.right.v,
        outcome.y[5] - end.right.u,
    ]
    .iter()
    .fold(0.0_f64, |a, d| a.max(d.abs()));
    let status = if metrics.nonfinite || metrics.gain > 1e-6 {
        RunStatus::Unstable
    } else if outcome.stalled.is_some() {
        RunStatus::Stalled
    } else if method.regularised() && metrics.slip_rolling > 0.01 * settings.epsilon {
        // The exact regularised slip would have decayed by e^-20 by now.
        RunStatus::Unstable
    } else if metrics.flips > 3 {
        RunStatus::Chatter
    } else {
        RunStatus::Ok
    };
    let (time_min_s, time_median_s) = if !timed || (outcome.stalled.is_some() && outcome.steps == 0)
    {
        (0.0, 0.0)
    } else {
        time(|| {
            integrate(
                method,
                &model,
                y0,
                t0,
                t1,
                settings,
                &mut Finite(Watch::new(progress)),
            )
        })
    };
    if progress.cancelled() {
        return Err(Cancelled);
    }
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
        steps: outcome.steps,
        rhs_evals: outcome.rhs_evals,
        time_min_s,
        time_median_s,
        note: outcome.stalled,
    })
}

/// The default sweep: two steps per decade from 10 ms to 1 µs, tolerances 1e-2…1e-10.
pub fn default_sweep(method: Method) -> Vec<f64> {
    match method {
        Method::Exact => vec![0.0],
        Method::Rk45 => (2..=10).map(|e| 10f64.powi(-e)).collect(),
        _ => (4..=12).map(|i| 10f64.powf(-(i as f64) / 2.0)).collect(),
    }
}

/// Runs every method in `methods` over its sweep, each run within [`STEP_BUDGET`]
/// steps; ticks `progress` once per row and stops when it says so.
pub fn sweep(
    scene: &Scene,
    span: &Span,
    methods: &[Method],
    base: &Settings,
    progress: &dyn Progress,
) -> Result<Vec<Row>, Cancelled> {
    let exact = crate::physics::engine::solve(scene, span);
    let budget = STEP_BUDGET.min(base.max_steps);
    let levels: Vec<(Method, f64)> = methods
        .iter()
        .flat_map(|&m| default_sweep(m).into_iter().map(move |v| (m, v)))
        .collect();
    let total = levels.len() as u64;
    let mut rows = Vec::with_capacity(levels.len());
    progress.tick(0, total);
    for (method, value) in levels {
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
        let mut row = measure(method, scene, span, &settings, &exact, true, progress)?;
        // A fixed step that needs more than the budget was refused before its first
        // step: say why in words a reader of the table can act on.
        let needed = ((exact.t_end - exact.t_start) / value).ceil();
        if method != Method::Exact && !method.adaptive() && needed > budget as f64 {
            row.note = Some(format!(
                "skipped: {needed} steps needed, over the budget of {budget} steps per run (a shorter span runs it)"
            ));
        }
        rows.push(row);
        progress.tick(rows.len() as u64, total);
    }
    Ok(rows)
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
