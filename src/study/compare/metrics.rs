//! What one run measures against the exact solution, step by step (its errors, energy
//! drift, slip while rolling, outcome), and the run's verdict from it.

use crate::methods::{Method, Model, Observer, RunEnd, Stepping, Y, gap};
use crate::physics::derived::Outcome;
use crate::physics::model::Phase;
use crate::physics::solution::{Event, EventKind, Segment, Solution, Who};
use crate::study::Progress;

use super::observers::Watch;
use super::row::{ACCURATE, RunStatus};

/// Compares a run with the exact solution step by step.
pub(super) struct Metrics<'a> {
    exact: &'a Solution,
    watch: Watch<'a>,
    model: Model,
    e0: f64,
    pub(super) err_v: f64,
    pub(super) err_u: f64,
    pub(super) drift: f64,
    gain: f64,
    nonfinite: bool,
    pub(super) first_roll: Option<f64>,
    /// Time to let a regularised slip settle after the exact ball starts rolling.
    settle: f64,
    last_slip: [Option<f64>; 2],
    flips: usize,
    pub(super) slip_rolling: f64,
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
        // Away from an impact (nearly every step) both are the same segment's.
        let ex_left = if before == at {
            ex
        } else {
            [state(seg_left, 0), state(seg_left, 1)]
        };
        for (i, (e, el)) in ex.into_iter().zip(ex_left).enumerate() {
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
    pub(super) fn new(
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

/// The largest velocity error (v and u of both balls) where the run ended.
pub(super) fn final_error(exact: &Solution, run_end: &RunEnd) -> f64 {
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
pub(super) fn run_status(
    metrics: &Metrics,
    run_end: &RunEnd,
    method: Method,
    settings: &Stepping,
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
/// end if they never settle), heading back a recollision unless rolling resistance
/// acts (`resisted`).
pub(super) fn run_outcome(
    metrics: &Metrics,
    end: &RunEnd,
    impacts: usize,
    (friction, resisted): (bool, bool),
) -> (Outcome, usize) {
    let (w, moving) = metrics
        .settled
        .unwrap_or_else(|| relative(&end.y, metrics.still));
    let pressed = impacts == 1 && !metrics.parted && friction;
    let facts = (impacts, false, pressed);
    let outcome = Outcome::classify(facts, w, moving, resisted, metrics.still);
    (outcome, impacts)
}
