//! What a solver returns: the event list, the piecewise-polynomial segments between
//! events, and exact sampling of state, spin angle and energy at any time.

use serde::Serialize;

use crate::physics::model::{BallState, Phase, Rails};
use crate::physics::scene::{Scene, Span};

/// Which ball an event belongs to.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Who {
    Left,
    Right,
    Both,
}

impl Who {
    pub fn ball(index: usize) -> Who {
        if index == 0 { Who::Left } else { Who::Right }
    }

    pub fn name(self) -> &'static str {
        match self {
            Who::Left => "left",
            Who::Right => "right",
            Who::Both => "both",
        }
    }
}

/// What happened (interface.md's event kinds).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum EventKind {
    Collision,
    /// Slip ends: the ball rolls again.
    Rolling,
    /// `u` crosses 0 while sliding: no rotation.
    PureGliding,
    /// `v` crosses 0 while sliding: no translation.
    PureSlipping,
    /// `v = u = 0`, and the ball stays so until a collision or contact event. A ball
    /// rolling through `v = 0` because the other one pushes it is no event.
    Rest,
    /// The touching balls start to press on each other (push `P > 0`) and move as one.
    ContactStart,
    /// The push between them is gone (`P = 0`): they may part from here on.
    ContactEnd,
    /// Impacts accumulated and the pair rests in contact.
    ZenoRest,
    /// Impacts accumulated and the pair moves on together.
    ZenoContact,
}

impl EventKind {
    pub fn name(self) -> &'static str {
        match self {
            EventKind::Collision => "collision",
            EventKind::Rolling => "rolling",
            EventKind::PureGliding => "pure_gliding",
            EventKind::PureSlipping => "pure_slipping",
            EventKind::Rest => "rest",
            EventKind::ContactStart => "contact_start",
            EventKind::ContactEnd => "contact_end",
            EventKind::ZenoRest => "zeno_rest",
            EventKind::ZenoContact => "zeno_contact",
        }
    }

    /// Short label for a chart's event line; `None` for contact changes, which
    /// charts do not mark.
    pub fn label(self) -> Option<&'static str> {
        match self {
            EventKind::Collision => Some("impact"),
            EventKind::Rolling => Some("rolling"),
            EventKind::PureGliding => Some("gliding"),
            EventKind::PureSlipping => Some("slipping"),
            EventKind::Rest => Some("rest"),
            EventKind::ZenoRest | EventKind::ZenoContact => Some("T∞"),
            EventKind::ContactStart | EventKind::ContactEnd => None,
        }
    }
}

/// One event, with both balls' states right after it.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Event {
    pub t: f64,
    pub kind: EventKind,
    pub ball: Who,
    pub left: BallState,
    pub right: BallState,
}

/// Energy dissipated so far, J.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct Ledger {
    pub friction: f64,
    pub impacts: f64,
    pub rolling_resistance: f64,
}

impl Ledger {
    pub fn total(&self) -> f64 {
        self.friction + self.impacts + self.rolling_resistance
    }

    fn lerp(&self, other: &Ledger, f: f64) -> Ledger {
        Ledger {
            friction: self.friction + (other.friction - self.friction) * f,
            impacts: self.impacts + (other.impacts - self.impacts) * f,
            rolling_resistance: self.rolling_resistance
                + (other.rolling_resistance - self.rolling_resistance) * f,
        }
    }
}

/// The motion between two events: constant accelerations for each ball.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Segment {
    pub t0: f64,
    /// End time; `f64::INFINITY` for the last segment.
    pub t1: f64,
    pub start: [BallState; 2],
    /// `(dv/dt, du/dt)` of each ball.
    pub accel: [(f64, f64); 2],
    pub phase: [Phase; 2],
    /// Compressive force between touching balls, N (0 when apart).
    pub contact_force: f64,
    /// Share of each ball's rolling resistance that acts, 0..=1: 1, except for a pushed
    /// rolling ball at the friction limit (physics.md, "Rolling resistance").
    pub rolling_share: [f64; 2],
    /// Spin angle of each ball at `t0`, rad (0 at `t_start`).
    pub angle0: [f64; 2],
    pub ledger0: Ledger,
    /// `Some(ledger at t1)` for the short bridge over the last, unresolved impacts
    /// before an accumulation point; its states are interpolated, not solved.
    pub bridge: Option<Ledger>,
}

/// A solver's answer for one scene.
#[derive(Clone, Debug)]
pub struct Solution {
    pub scene: Scene,
    pub t_start: f64,
    pub t_end: f64,
    pub method: &'static str,
    pub events: Vec<Event>,
    pub segments: Vec<Segment>,
    /// Number of impacts actually resolved (an accumulation point stands for infinitely many).
    pub impacts: usize,
    /// Time of the accumulation point of repeated impacts, if any.
    pub accumulation: Option<f64>,
    /// True if the solver hit its event budget before the motion ended.
    pub truncated: bool,
    /// The stretches of impact series summed in closed form, in time order.
    pub series: Vec<SeriesSum>,
}

/// The tail of an impact series summed in closed form (physics.md, "Repeated impacts").
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct SeriesSum {
    /// The last impact resolved one by one, s; a bridge segment runs from here to `to`.
    pub from: f64,
    /// Where the sum ends, s: the accumulation point T∞ for a whole tail, the impact
    /// that ends the summed cycles for a partial one.
    pub to: f64,
    /// Geometric cycles resolved before the tail was summed.
    pub cycles: usize,
    /// The cycle ratio ρ: each cycle is the last one scaled by ρ.
    pub ratio: f64,
    /// True when the tail was summed because the cycle budget ran out, not because
    /// it had become negligible: the bridge then spans a visible time.
    pub by_budget: bool,
    /// Impacts the sum stands for: `None` for a whole tail (infinitely many, up to the
    /// accumulation point), `Some(n)` for a partial one, summed up to shortly before
    /// rolling resistance stops a ball inside the series. Summed impacts are not
    /// counted in [`Solution::impacts`].
    pub impacts: Option<usize>,
}

/// Both balls at one time.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Snapshot {
    pub t: f64,
    pub left: BallState,
    pub right: BallState,
}

/// Energy at one time, J. `translational + rotational + lost()` is the initial energy.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct EnergySplit {
    pub translational: f64,
    pub rotational: f64,
    pub lost: Ledger,
}

impl EnergySplit {
    pub fn kinetic(&self) -> f64 {
        self.translational + self.rotational
    }

    pub fn total(&self) -> f64 {
        self.kinetic() + self.lost.total()
    }
}

impl Solution {
    pub fn groove(&self) -> Rails {
        self.scene.groove()
    }

    fn masses(&self) -> [f64; 2] {
        [self.scene.left.mass, self.scene.right.mass]
    }

    /// The segment that holds `t` (the first before `t_start`, the last after the end).
    pub fn segment_at(&self, t: f64) -> &Segment {
        self.cursor().segment_at(t)
    }

    /// A [`Cursor`] for sampling this run at many times in order.
    pub fn cursor(&self) -> Cursor<'_> {
        Cursor {
            sol: self,
            hint: None,
            contact_radius: self.scene.k() * self.scene.radius,
        }
    }

    fn ball_at(seg: &Segment, i: usize, t: f64) -> BallState {
        let (a, du) = seg.accel[i];
        seg.start[i].advanced(a, du, t - seg.t0)
    }

    /// The state just before `t`: differs from [`Solution::at`] only at an impact.
    pub fn at_left(&self, t: f64) -> Snapshot {
        let i = self.segments.partition_point(|s| s.t1 < t);
        let seg = &self.segments[i.min(self.segments.len() - 1)];
        Snapshot {
            t,
            left: Self::ball_at(seg, 0, t),
            right: Self::ball_at(seg, 1, t),
        }
    }

    /// Exact state of both balls at time `t`.
    pub fn at(&self, t: f64) -> Snapshot {
        self.cursor().at(t)
    }

    /// States on the uniform grid `t_start, t_start + dt, …` up to `t_end`.
    pub fn sample(&self, dt: f64) -> Vec<Snapshot> {
        let n = ((self.t_end - self.t_start) / dt + 1e-9).floor() as usize;
        let mut cursor = self.cursor();
        (0..=n)
            .map(|i| cursor.at(grid_time(self.t_start, dt, i)))
            .collect()
    }

    /// Spin angle of each ball at `t`, rad, `∫ ω dt` from `t_start` with `ω = u / (kR)`.
    pub fn angle_at(&self, t: f64) -> [f64; 2] {
        self.cursor().angle_at(t)
    }

    /// Ball `i`'s state and spin angle at `t` from one segment lookup: what
    /// [`Solution::at`] and [`Solution::angle_at`] give, for the fit's inner loop.
    pub fn ball_and_angle(&self, i: usize, t: f64) -> (BallState, f64) {
        self.cursor().ball_and_angle(i, t)
    }

    /// The energy at the start of the span, before anything that happens at that
    /// instant: with `t_start = 0` the energy just before the first impact (both balls
    /// rolling in at v0, nothing lost yet), not after it.
    pub fn energy_start(&self) -> EnergySplit {
        // A negative start has the rolling run-up, which ends at the impact.
        if self.t_start < 0.0 {
            return self.energy_at(self.t_start);
        }
        let groove = self.groove();
        let masses = self.masses();
        let balls = [self.scene.left.v0, -self.scene.right.v0];
        let (mut translational, mut rotational) = (0.0, 0.0);
        for (m, v) in masses.into_iter().zip(balls) {
            let (tr, rot) = groove.energy(m, BallState { x: 0.0, v, u: v });
            translational += tr;
            rotational += rot;
        }
        EnergySplit {
            translational,
            rotational,
            lost: Ledger::default(),
        }
    }

    /// Kinetic energy and what has been dissipated by `t`.
    pub fn energy_at(&self, t: f64) -> EnergySplit {
        let seg = self.segment_at(t);
        let groove = self.groove();
        let masses = self.masses();
        let snap = self.at(t);
        let (mut translational, mut rotational) = (0.0, 0.0);
        for (m, st) in masses.iter().zip([snap.left, snap.right]) {
            let (tr, rot) = groove.energy(*m, st);
            translational += tr;
            rotational += rot;
        }
        let lost = match seg.bridge {
            Some(end) => {
                // What the bridge has lost by `t`: the books at its end less the kinetic
                // energy still to go, split like the bridge's losses. Its states are
                // cycle averages, whose kinetic energy starts below the last impact's:
                // the difference (the swinging the average leaves out) counts as lost
                // from the bridge's start, so the books balance throughout.
                let kinetic = |t: f64| -> f64 {
                    (0..2)
                        .map(|i| {
                            let (tr, rot) = groove.energy(masses[i], Self::ball_at(seg, i, t));
                            tr + rot
                        })
                        .sum()
                };
                let to_go = kinetic(t.min(seg.t1)) - kinetic(seg.t1);
                let bridged = end.total() - seg.ledger0.total();
                let f = if bridged > 0.0 {
                    (to_go / bridged).clamp(0.0, 1.0)
                } else {
                    0.0
                };
                end.lerp(&seg.ledger0, f)
            }
            None => segment_losses(&groove, masses, seg, t - seg.t0),
        };
        EnergySplit {
            translational,
            rotational,
            lost,
        }
    }

    /// Events inside the simulated span.
    pub fn visible_events(&self) -> impl Iterator<Item = &Event> {
        self.events
            .iter()
            .filter(move |e| e.t >= self.t_start && e.t <= self.t_end)
    }

    /// Time of the last event (0 if there is none).
    pub fn last_event_time(&self) -> f64 {
        self.events.last().map_or(0.0, |e| e.t)
    }
}

/// Samples a [`Solution`] at times mostly in ascending order (a track's frames, a
/// chart's grid): each lookup steps on from the segment of the last one instead of
/// searching them all, and gives exactly what [`Solution::segment_at`] gives. A fit
/// samples every frame of a track in each of its thousands of model evaluations, and a
/// search per frame was a fifth of its time.
#[derive(Clone, Copy, Debug)]
pub struct Cursor<'a> {
    sol: &'a Solution,
    /// The segment of the last lookup; `None` before the first.
    hint: Option<usize>,
    /// kR, m: the spin angle's radius, worked out once rather than per sample.
    contact_radius: f64,
}

impl<'a> Cursor<'a> {
    /// Steps tried forward from the last segment before a search of the rest.
    const WALK: usize = 8;

    /// The segment that holds `t`: [`Solution::segment_at`].
    pub fn segment_at(&mut self, t: f64) -> &'a Segment {
        let segments = &self.sol.segments;
        let last = segments.len() - 1;
        // The answer is the first segment ending after `t` (the last one at most):
        // from the hint on when every segment before it ends at or before `t`.
        let from = self
            .hint
            .filter(|&i| i == 0 || segments.get(i - 1).is_some_and(|s| s.t1 <= t));
        let i = match from {
            Some(mut i) => {
                let stop = (i + Self::WALK).min(last);
                while i < stop && segments[i].t1 <= t {
                    i += 1;
                }
                if i < last && segments[i].t1 <= t {
                    i + 1 + segments[i + 1..].partition_point(|s| s.t1 <= t)
                } else {
                    i
                }
            }
            None => segments.partition_point(|s| s.t1 <= t),
        }
        .min(last);
        self.hint = Some(i);
        &segments[i]
    }

    /// Both balls' state at `t`: [`Solution::at`].
    pub fn at(&mut self, t: f64) -> Snapshot {
        let seg = self.segment_at(t);
        Snapshot {
            t,
            left: Solution::ball_at(seg, 0, t),
            right: Solution::ball_at(seg, 1, t),
        }
    }

    /// Ball `i`'s state and spin angle at `t`: [`Solution::ball_and_angle`].
    pub fn ball_and_angle(&mut self, i: usize, t: f64) -> (BallState, f64) {
        let seg = self.segment_at(t);
        let r = self.contact_radius;
        let tau = t - seg.t0;
        let (_, du) = seg.accel[i];
        let angle = seg.angle0[i] + (seg.start[i].u * tau + 0.5 * du * tau * tau) / r;
        (Solution::ball_at(seg, i, t), angle)
    }

    /// Each ball's spin angle at `t`: [`Solution::angle_at`].
    pub fn angle_at(&mut self, t: f64) -> [f64; 2] {
        let seg = self.segment_at(t);
        let r = self.contact_radius;
        let tau = t - seg.t0;
        std::array::from_fn(|i| {
            let (_, du) = seg.accel[i];
            seg.angle0[i] + (seg.start[i].u * tau + 0.5 * du * tau * tau) / r
        })
    }
}

/// Ledger `tau` seconds into segment `seg`: sliding friction `μ m g/k ∫|s|dt` and
/// rolling resistance `F_rr ∫|v|dt`, each exact because `s` and `v` keep their sign
/// inside a segment (their zeros are events).
pub fn segment_losses(groove: &Rails, masses: [f64; 2], seg: &Segment, tau: f64) -> Ledger {
    let mut ledger = seg.ledger0;
    for (i, mass) in masses.into_iter().enumerate() {
        let st = seg.start[i];
        let (a, du) = seg.accel[i];
        match seg.phase[i] {
            Phase::Sliding { .. } => {
                let s0 = st.v - st.u;
                let ds = a - du;
                let path = (s0 * tau + 0.5 * ds * tau * tau).abs();
                ledger.friction += groove.friction_limit(mass) * path;
            }
            Phase::Rolling => {
                // Only rolling resistance takes work (a push between touching balls is
                // internal to the pair), over the path the ball really rolls.
                if groove.rolling_resistance > 0.0 {
                    let path = (st.v * tau + 0.5 * a * tau * tau).abs();
                    ledger.rolling_resistance +=
                        seg.rolling_share[i] * groove.rolling_resistance_force(mass) * path;
                }
            }
            Phase::Resting => {}
        }
    }
    ledger
}

/// The latest end a span may have, s (the `t_end` a user may give). A default end
/// never goes past it, so every span the program picks could also be typed in.
pub const LATEST_END: f64 = 1e6;

/// The simulated span's end: the given `t_end`, or far enough past the last event
/// to see what follows it, but never past [`LATEST_END`] (a motion that slow, e.g.
/// μ_k = 1e-9, goes on beyond the span; its events are still in the solution).
pub fn end_time(span: &Span, last_event: f64) -> f64 {
    span.t_end.unwrap_or_else(|| {
        let shown = last_event - span.t_start;
        (last_event + (0.2 * shown).max(0.1)).min(LATEST_END)
    })
}

/// The `k`-th time of the grid `t0, t0 + dt, …`. Where dt is a whole fraction of a
/// second (1/n s) and `t0` lies on its grid, the whole number of steps over n: the
/// times are then the decimals typed (−0.08 s, where −0.2 + 12 × 0.01 is
/// −0.08000000000000002 and a CSV wrote it so); else `t0 + k dt`.
pub fn grid_time(t0: f64, dt: f64, k: usize) -> f64 {
    let per_second = (1.0 / dt).round();
    let steps = (t0 * per_second).round();
    let whole = |x: f64, of: f64| (x - of).abs() <= 1e-9 * of.abs().max(1.0);
    if per_second >= 1.0 && whole(1.0 / dt, per_second) && whole(t0 * per_second, steps) {
        (steps + k as f64) / per_second
    } else {
        t0 + k as f64 * dt
    }
}

#[cfg(test)]
mod tests {
    use super::grid_time;

    #[test]
    fn grid_times_are_the_decimals_typed_and_the_grid_else() {
        // −0.2 + 12 × 0.01 is −0.08000000000000002: the grid gives −0.08.
        assert_eq!(grid_time(-0.2, 0.01, 12), -0.08);
        assert_eq!(grid_time(0.0, 0.1, 3), 0.3);
        assert_eq!(grid_time(-0.2, 0.001, 1234), 1.034);
        assert_eq!(grid_time(0.35, 0.05, 0), 0.35);
        // Every time within rounding of t0 + k dt, on the grid or off it (1/0.003 s
        // is no whole number; 0.0123 s no step of 0.01).
        for (t0, dt) in [
            (-0.2, 0.01),
            (0.0, 1.0 / 120.0),
            (0.0, 0.003),
            (0.0123, 0.01),
        ] {
            for k in 0..2000 {
                let t = grid_time(t0, dt, k);
                let plain = t0 + k as f64 * dt;
                assert!(
                    (t - plain).abs() <= 1e-12 * plain.abs().max(1.0),
                    "{t} {plain}"
                );
            }
        }
        assert_eq!(grid_time(0.0, 0.003, 7), 7.0 * 0.003);
    }
}
