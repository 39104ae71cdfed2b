//! Speed against accuracy: every method over a sweep of step sizes (or tolerances),
//! each run measured against the exact solution, classified (`ok`, `inaccurate`,
//! `chatter`, `unstable`, `stalled`) and timed. A comparison's work is bounded: it
//! covers at most [`WINDOW`] of simulated time (a longer span is cut there, and every
//! row says so), so no run takes more than [`STEP_BUDGET`] steps; the accuracy runs
//! share the cores, the timing runs go one at a time; it can be stopped
//! ([`Progress`]).

use std::sync::atomic::{AtomicU64, Ordering};
use std::time::Instant;

use rayon::prelude::*;
use serde::Serialize;

use crate::methods::{Method, Model, Observer, RunEnd, Settings, Y, gap, integrate, start_state};
use crate::physics::derived::{Outcome, Summary};
use crate::physics::engine::{self, NEGLIGIBLE_SPEED};
use crate::physics::model::Phase;
use crate::physics::scene::{Scene, Span};
use crate::physics::solution::{Event, EventKind, Segment, Solution, Who};
use crate::study::{Cancelled, Progress, Quiet};

/// The finest fixed step of the default sweep, s.
pub const FINEST_STEP: f64 = 1e-6;

/// Most steps one run of a comparison takes: the finest step over [`WINDOW`]. A
/// smaller `max_steps` in the settings skips (as `stalled`, saying so) the levels
/// that would need more.
pub const STEP_BUDGET: usize = 2_000_000;

/// The most simulated time a comparison covers, s: [`STEP_BUDGET`] steps of
/// [`FINEST_STEP`]. A longer span (`--mu 1e-6` reaches 147,000 s, a 10 kg right ball
/// 2.25 s, `paper-b4.4` 2.8 s) is compared over its first 2 s only, every row saying
/// so: a comparison's work then grows with the span up to 2 s and no further, at most
/// about 1.6 times the default scene's (`paper-b4.9`, 1.28 s), whatever the scene.
pub const WINDOW: f64 = STEP_BUDGET as f64 * FINEST_STEP;

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

/// A run is accurate (status `ok`) within this share of the scene's largest speed, in
/// its velocities, spins and end state.
pub const ACCURATE: f64 = 0.01;

/// What a comparison's runs are measured against: the exact solution over the stretch
/// compared (the span, or its first [`WINDOW`] seconds where the span is longer), and
/// the outcome and impacts a run should find there.
#[derive(Clone, Debug)]
pub struct Reference {
    pub exact: Solution,
    /// Where the step budget cut the span (s), if it did.
    pub cut: Option<f64>,
    pub outcome: Outcome,
    pub impacts: usize,
    /// Whether the exact impacts accumulate within the stretch (infinitely many: the
    /// outcome word alone decides whether a run gets it right).
    pub accumulating: bool,
}

impl Reference {
    /// The exact run of `scene` over `span`, cut at [`WINDOW`] after its start.
    pub fn new(scene: &Scene, span: &Span) -> Reference {
        let whole = engine::solve(scene, span);
        let end = whole.t_start + WINDOW;
        if whole.t_end <= end {
            let summary = Summary::of(&whole);
            return Reference {
                cut: None,
                outcome: summary.outcome,
                impacts: summary.impacts,
                accumulating: whole.accumulation.is_some(),
                exact: whole,
            };
        }
        let exact = engine::solve(
            scene,
            &Span {
                t_start: whole.t_start,
                t_end: Some(end),
            },
        );
        let (outcome, impacts) = outcome_until(&exact, end);
        Reference {
            cut: Some(end),
            outcome,
            impacts,
            accumulating: exact.accumulation.is_some_and(|t| t <= end),
            exact,
        }
    }
}

/// What the exact run does up to `end` (a cut comparison's runs see no further), and
/// its impacts there: the rule of [`Outcome::of`] applied to the events up to `end`,
/// with the relative velocity in the first stretch after the impact where neither
/// ball slides, else at `end`.
pub fn outcome_until(sol: &Solution, end: f64) -> (Outcome, usize) {
    let eps = NEGLIGIBLE_SPEED * sol.scene.speed_scale();
    let shown = |e: &&Event| e.t >= sol.t_start && e.t <= end;
    let impacts = sol
        .events
        .iter()
        .filter(shown)
        .filter(|e| e.kind == EventKind::Collision)
        .count();
    let pressed = sol
        .events
        .iter()
        .filter(shown)
        .any(|e| e.kind == EventKind::ContactStart);
    let settled = sol
        .segments
        .iter()
        .find(|s| {
            s.t0 >= 0.0
                && s.t0 <= end
                && s.phase
                    .iter()
                    .all(|p| matches!(p, Phase::Rolling | Phase::Resting))
        })
        .map_or_else(
            || {
                let s = sol.at(end);
                [s.left, s.right]
            },
            |s| s.start,
        );
    let [l, r] = settled;
    let accumulating = sol.accumulation.is_some_and(|t| t <= end);
    let moving = l.v.abs() > eps || r.v.abs() > eps;
    let outcome = Outcome::classify(impacts, accumulating, pressed, r.v - l.v, moving, eps);
    (outcome, impacts)
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
    /// The segment of the last step (see [`Metrics::seek`]).
    cursor: usize,
    /// Where the method put its first and last impacts (from the first pass).
    impacts: (Option<f64>, Option<f64>),
    /// Speeds below this are zero for the run's outcome, m/s.
    still: f64,
    /// Whether the balls parted after the first impact.
    parted: bool,
    /// Right minus left velocity, and whether the pair moves, at the first step after
    /// the last impact where neither ball slides (within `still`).
    settled: Option<(f64, bool)>,
    /// Each ball's slip at the first step after the last impact, and whether it has
    /// rolled since.
    slip_after: [Option<f64>; 2],
    rolled: [bool; 2],
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
        let (at, before) = self.seek(t);
        let segments = &self.exact.segments;
        let (seg, seg_left) = (&segments[at], &segments[before]);
        // The exact states at t and just before it (they differ only at an impact):
        // `Solution::at` and `at_left`, without their searches.
        let state = |seg: &Segment, i: usize| {
            let (a, du) = seg.accel[i];
            seg.start[i].advanced(a, du, t - seg.t0)
        };
        let ex = [state(seg, 0), state(seg, 1)];
        for (i, (e, el)) in ex
            .into_iter()
            .zip([state(seg_left, 0), state(seg_left, 1)])
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
        self.follow_outcome(t, y);
        let e = self.model.energy(y);
        // The exact kinetic energy, summed as `Solution::energy_at` sums it.
        let (mut translational, mut rotational) = (0.0, 0.0);
        for (m, st) in self.model.mass.into_iter().zip(ex) {
            let (tr, rot) = self.model.groove.energy(m, st);
            translational += tr;
            rotational += rot;
        }
        let e_exact = translational + rotational;
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

impl<'a> Metrics<'a> {
    /// Nothing measured yet of a run of `model` from `y0` against `exact`, leaving
    /// out the time `windows` around impacts; `impacts`: where the method's first
    /// pass put them.
    fn new(
        exact: &'a Solution,
        progress: &'a dyn Progress,
        model: Model,
        y0: &Y,
        settle: f64,
        windows: Vec<(f64, f64)>,
        impacts: &[f64],
    ) -> Metrics<'a> {
        Metrics {
            exact,
            watch: Watch::new(progress),
            model,
            e0: model.energy(y0),
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
            windows,
            next_window: 0,
            cursor: 0,
            impacts: (impacts.first().copied(), impacts.last().copied()),
            still: ACCURATE * model.scene.speed_scale(),
            parted: false,
            settled: None,
            slip_after: [None; 2],
            rolled: [false; 2],
        }
    }
    /// The segments holding `t` and just before `t`, as `Solution::segment_at` and
    /// `Solution::at_left` find them, searched from the last step's (steps come in
    /// order, so this walks a segment or two where a search took dozens of looks).
    fn seek(&mut self, t: f64) -> (usize, usize) {
        let segments = &self.exact.segments;
        let mut i = self.cursor.min(segments.len() - 1);
        while i > 0 && segments[i - 1].t1 > t {
            i -= 1;
        }
        while i + 1 < segments.len() && segments[i].t1 <= t {
            i += 1;
        }
        self.cursor = i;
        let mut before = i;
        while before > 0 && segments[before - 1].t1 >= t {
            before -= 1;
        }
        (i, before)
    }

    /// What the run does after its impacts, for its outcome word: whether the balls
    /// part after the first, and their relative velocity once both roll after the last.
    fn follow_outcome(&mut self, t: f64, y: &Y) {
        let (first, last) = self.impacts;
        if first.is_some_and(|t0| t > t0) && gap(&self.model, y) > 1e-9 * self.model.radius {
            self.parted = true;
        }
        if self.settled.is_some() || last.is_some_and(|t1| t <= t1) {
            return;
        }
        // A ball has rolled once its slip is within `still` or has changed sign (a
        // chattering method's slip never settles, but it crosses zero when it rolls).
        for i in 0..2 {
            let s = y[3 * i + 1] - y[3 * i + 2];
            let s0 = *self.slip_after[i].get_or_insert(s);
            self.rolled[i] |= s.abs() <= self.still || s * s0 < 0.0;
        }
        if self.rolled == [true; 2] {
            self.settled = Some(relative(y, self.still));
        }
    }
}

/// Right minus left velocity of `y`, and whether the pair moves (beyond `still`).
fn relative(y: &Y, still: f64) -> (f64, bool) {
    (y[4] - y[1], y[1].abs() > still || y[4].abs() > still)
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

/// A run at least this long (s) is its own warm-up: its first timing counts.
const NO_WARM_UP: f64 = 0.01;

/// Minimum and median of at least three timings of `f`, more for quick runs (up to
/// 15 within 50 ms). A quick run's first call is an untimed warm-up (caches, the
/// allocator); a run of [`NO_WARM_UP`] or more is timed from its first call, where
/// such start-up costs are lost in the run.
pub fn time<T>(mut f: impl FnMut() -> T) -> (f64, f64) {
    let mut times = Vec::new();
    let first = Instant::now();
    std::hint::black_box(f());
    let first = first.elapsed().as_secs_f64();
    if first >= NO_WARM_UP {
        times.push(first);
    }
    let budget = Instant::now();
    while times.len() < 3 || (times.len() < 15 && budget.elapsed().as_secs_f64() < 0.05) {
        let start = Instant::now();
        std::hint::black_box(f());
        times.push(start.elapsed().as_secs_f64());
    }
    times.sort_by(f64::total_cmp);
    (times[0], times[times.len() / 2])
}

/// One run of `method` on `scene`, measured against `reference` and timed.
pub fn run(method: Method, scene: &Scene, settings: &Settings, reference: &Reference) -> Row {
    measure(method, scene, settings, reference, true, &Quiet).expect("Quiet never cancels")
}

/// [`run`], with the timing runs only if `timed` (the untimed row is deterministic),
/// stopping early (with `Cancelled`) when `progress` says so.
pub fn measure(
    method: Method,
    scene: &Scene,
    settings: &Settings,
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

/// The minimum and median time of the run `row` measured (see [`time`]); zero for a
/// run refused before its first step.
pub fn timing(
    method: Method,
    scene: &Scene,
    settings: &Settings,
    reference: &Reference,
    row: &Row,
    progress: &dyn Progress,
) -> Result<(f64, f64), Cancelled> {
    let exact = &reference.exact;
    let times = if method == Method::Exact {
        let span = Span {
            t_start: exact.t_start,
            t_end: Some(exact.t_end),
        };
        time(|| engine::solve(scene, &span))
    } else if row.status == RunStatus::Stalled && row.steps == 0 {
        (0.0, 0.0)
    } else {
        let model = Model::of(scene);
        let (t0, t1) = (exact.t_start, exact.t_end);
        let y0 = start_state(scene, t0);
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
    Ok(times)
}

/// The exact engine's row: no error, its segments as steps.
fn exact_row(reference: &Reference) -> Row {
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

/// The untimed row of one run, with `also` watching the steps and events of its first
/// pass (so a caller that wants the run's points, as the overlay, need not integrate
/// it again).
pub fn measure_observed(
    method: Method,
    scene: &Scene,
    settings: &Settings,
    reference: &Reference,
    progress: &dyn Progress,
    also: &mut dyn Observer,
) -> Result<Row, Cancelled> {
    if method == Method::Exact {
        return Ok(exact_row(reference));
    }
    let exact = &reference.exact;
    let model = Model::of(scene);
    let (t0, t1) = (exact.t_start, exact.t_end);
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
    let exact_impacts = impact_times(exact);
    // rk45 places its steps itself: its windows are one tolerance wide.
    let slack = if method.adaptive() {
        settings.tolerance
    } else {
        settings.step
    };
    let (windows, err_t_impact) = impact_windows(&exact_impacts, &found.0, slack);
    let mut metrics = Metrics::new(exact, progress, model, &y0, settle, windows, &found.0);
    let run_end: RunEnd = integrate(method, &model, y0, t0, t1, settings, &mut metrics);
    if progress.cancelled() {
        return Err(Cancelled);
    }
    let err_final = final_error(exact, &run_end);
    let (outcome, impacts) = run_outcome(&metrics, &run_end, found.0.len(), scene.mu > 0.0);
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
        note: run_end.stalled,
    })
}

/// The times of the exact run's impacts (collisions and accumulation points).
fn impact_times(exact: &Solution) -> Vec<f64> {
    exact
        .events
        .iter()
        .filter(|e| {
            matches!(
                e.kind,
                EventKind::Collision | EventKind::ZenoRest | EventKind::ZenoContact
            )
        })
        .map(|e| e.t)
        .collect()
}

/// The largest velocity error (v and u of both balls) where the run ended.
fn final_error(exact: &Solution, run_end: &RunEnd) -> f64 {
    let end = exact.at(run_end.t);
    [
        run_end.y[1] - end.left.v,
        run_end.y[2] - end.left.u,
        run_end.y[4] - end.right.v,
        run_end.y[5] - end.right.u,
    ]
    .iter()
    .fold(0.0_f64, |a, d| a.max(d.abs()))
}

/// The run's verdict: unstable (non-finite, energy gained, or a regularised slip that
/// never decays), stalled, chattering, inaccurate, or ok, in that order.
fn run_status(
    metrics: &Metrics,
    run_end: &RunEnd,
    method: Method,
    settings: &Settings,
    accurate: bool,
) -> RunStatus {
    if metrics.nonfinite || metrics.gain > 1e-6 {
        RunStatus::Unstable
    } else if run_end.stalled.is_some() {
        RunStatus::Stalled
    } else if method.regularised() && metrics.slip_rolling > 0.01 * settings.epsilon {
        // The exact regularised slip would have decayed by e^-20 by now.
        RunStatus::Unstable
    } else if metrics.flips > 3 {
        RunStatus::Chatter
    } else if !accurate {
        RunStatus::Inaccurate
    } else {
        RunStatus::Ok
    }
}

/// The outcome word of a time-stepping run and its impacts: `impacts` detected, the
/// balls pressed if they never parted after a single impact (with friction to press
/// them), and their relative velocity once both roll after the last impact (at the
/// end if they never settle).
fn run_outcome(
    metrics: &Metrics,
    end: &RunEnd,
    impacts: usize,
    friction: bool,
) -> (Outcome, usize) {
    let (w, moving) = metrics
        .settled
        .unwrap_or_else(|| relative(&end.y, metrics.still));
    let pressed = impacts == 1 && !metrics.parted && friction;
    let outcome = Outcome::classify(impacts, false, pressed, w, moving, metrics.still);
    (outcome, impacts)
}

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
            row.note = Some(format!(
                "skipped: {needed} steps needed, over the budget of {budget} steps per run (a shorter span runs it)"
            ));
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
            let row = measure_observed(
                *method,
                scene,
                settings,
                reference,
                progress,
                &mut Unwatched,
            )?;
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
