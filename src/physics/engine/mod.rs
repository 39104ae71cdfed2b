//! The exact event-driven engine. Inside a phase every acceleration is constant, so
//! each segment is a polynomial and every event time a closed-form root: no time step
//! anywhere. Repeated impacts are summed to their accumulation point, and touching
//! balls that friction presses together follow the sustained-contact model. The event
//! list reports changes, one event each: a ball is called at rest only if it stays at
//! rest until something acts on it, and a pressed contact starts and ends once.

use crate::physics::model::{self, BallState, Phase, Rails, slip};
use crate::physics::scene::{Scene, Span};
use crate::physics::solution::{
    Event, EventKind, Ledger, Segment, SeriesSum, Solution, Who, end_time, segment_losses,
};

mod candidates;
mod contact;
mod zeno;

/// Speeds below this fraction of the scene's largest speed count as zero. At `b = b*`
/// the rolling speed after the impact is zero up to rounding (~1e-16 relative).
pub const NEGLIGIBLE_SPEED: f64 = 1e-12;

/// Events that happen within this fraction of the earliest one are simultaneous.
const SIMULTANEOUS: f64 = 1e-12;

/// Upper bound on events: a solver must never hang.
pub const MAX_EVENTS: usize = 100_000;

/// Solves `scene` exactly over `span`.
pub fn solve(scene: &Scene, span: &Span) -> Solution {
    let mut engine = Engine::new(scene);
    engine.run(span.t_start);
    engine.into_solution(scene, span)
}

/// Impact cycles confirmed before the series is summed even when what remains of it is
/// not yet negligible (see `zeno`), bridging the rest (see
/// [`Segment::bridge`](crate::physics::solution::Segment::bridge)). Only cycle ratios
/// within ~1e-2 of 1 (b within ~1e-3 of 2R) need that many.
const CYCLES_BEFORE_SUMMING: usize = 5000;

/// At most `N` values on the stack, in the order pushed: a step runs for every segment
/// of every motion solved (a fit solves thousands), and small vectors allocated and
/// freed per step were a tenth of a solve.
#[derive(Clone, Copy, Debug)]
struct Few<T: Copy, const N: usize> {
    items: [T; N],
    len: usize,
}

impl<T: Copy, const N: usize> Few<T, N> {
    /// Empty; `filler` only fills the unused places.
    fn new(filler: T) -> Self {
        Few {
            items: [filler; N],
            len: 0,
        }
    }

    fn push(&mut self, item: T) {
        self.items[self.len] = item;
        self.len += 1;
    }

    fn as_slice(&self) -> &[T] {
        &self.items[..self.len]
    }
}

/// The possible next events of a segment: at most three per ball (rolling, pure
/// gliding, pure slipping) and the impact.
type Candidates = Few<(f64, EventCandidate), 7>;

impl Default for Candidates {
    fn default() -> Self {
        Few::new((0.0, EventCandidate::Impact))
    }
}

/// The events of one step: one per candidate that is due, and the impact.
type Kinds = Few<(EventKind, Who), 8>;

impl Default for Kinds {
    fn default() -> Self {
        Few::new((EventKind::Collision, Who::Both))
    }
}

/// A possible next event of the current segment.
#[derive(Clone, Copy, Debug, PartialEq)]
enum EventCandidate {
    Roll(usize),
    Glide(usize),
    Slip(usize),
    Stop(usize),
    Impact,
}

/// An impact as the series detector needs it.
#[derive(Clone, Copy, Debug)]
struct ImpactRecord {
    /// Time since the previous impact.
    cycle: f64,
    /// Closing speed just before.
    closing: f64,
    /// Each ball's velocity and phase as it arrived.
    arrival: [(f64, Phase); 2],
    /// Everything right after, for summing the series.
    state: [BallState; 2],
    angle: [f64; 2],
    ledger: Ledger,
}

struct Engine {
    groove: Rails,
    mass: [f64; 2],
    radius: f64,
    restitution: f64,
    /// Speeds below this are zero, m/s.
    eps_v: f64,
    /// The scene's largest speed, m/s.
    speed_scale: f64,
    t: f64,
    state: [BallState; 2],
    phase: [Phase; 2],
    /// Gap between the balls' surfaces, m; set to exactly 0 at an impact.
    gap: f64,
    /// Compressive force while the balls press on each other, N.
    push: f64,
    /// Whether the touching balls move as one (pressed, or alike without a push).
    together: bool,
    /// Share of each ball's rolling resistance that acts (1 but at the friction limit).
    rolling_share: [f64; 2],
    /// Whether the event list says the balls press on each other: the last contact
    /// event recorded was `contact_start`. Contact events report changes of this.
    told_pressed: bool,
    /// `(dv/dt, du/dt)` of each ball in the current segment.
    accel: [(f64, f64); 2],
    angle: [f64; 2],
    ledger: Ledger,
    events: Vec<Event>,
    segments: Vec<Segment>,
    history: Vec<ImpactRecord>,
    since_impact: f64,
    geometric_cycles: usize,
    /// Cycles a geometric series is resolved one by one before its tail is summed.
    cycle_budget: usize,
    /// Events after which the run stops, `truncated`.
    event_budget: usize,
    impacts: usize,
    accumulation: Option<f64>,
    truncated: bool,
    series: Vec<SeriesSum>,
}

impl Engine {
    fn new(scene: &Scene) -> Engine {
        let groove = scene.groove();
        let r = scene.radius;
        // Just before the first impact both balls roll toward x = 0.
        let left = BallState {
            x: -r,
            v: scene.left.v0,
            u: scene.left.v0,
        };
        let right = BallState {
            x: r,
            v: -scene.right.v0,
            u: -scene.right.v0,
        };
        let eps_v = NEGLIGIBLE_SPEED * scene.speed_scale();
        let free_phase = |v: f64| {
            if v.abs() <= eps_v {
                Phase::Resting
            } else {
                Phase::Rolling
            }
        };
        Engine {
            groove,
            mass: [scene.left.mass, scene.right.mass],
            radius: r,
            restitution: scene.restitution,
            eps_v,
            speed_scale: scene.speed_scale(),
            t: 0.0,
            state: [left, right],
            phase: [free_phase(left.v), free_phase(right.v)],
            gap: 0.0,
            push: 0.0,
            together: false,
            rolling_share: [1.0; 2],
            told_pressed: false,
            accel: [(0.0, 0.0); 2],
            angle: [0.0; 2],
            ledger: Ledger::default(),
            events: Vec::with_capacity(16),
            segments: Vec::with_capacity(16),
            history: Vec::with_capacity(8),
            since_impact: 0.0,
            geometric_cycles: 0,
            cycle_budget: CYCLES_BEFORE_SUMMING,
            event_budget: MAX_EVENTS,
            impacts: 0,
            accumulation: None,
            truncated: false,
            series: Vec::new(),
        }
    }

    fn t_last_event(&self) -> f64 {
        self.events.last().map_or(0.0, |e| e.t)
    }

    fn run(&mut self, t_start: f64) {
        self.run_up(t_start);
        if self.state[0].v > self.state[1].v {
            self.collide();
            self.settle();
            self.record(&[(EventKind::Collision, Who::Both)]);
            self.check_series();
        } else {
            self.settle();
        }
        self.record_contact();
        loop {
            if self.events.len() >= self.event_budget {
                self.truncated = true;
                self.push_segment(f64::INFINITY);
                return;
            }
            if !self.step() {
                return;
            }
        }
    }

    /// The rolling run-up from `t_start` to the first impact at t = 0, solved backwards.
    fn run_up(&mut self, t_start: f64) {
        let accel = self.state.map(|s| {
            let a = self.groove.rolling_acceleration(s.v);
            (a, a)
        });
        let start: [BallState; 2] =
            std::array::from_fn(|i| self.state[i].advanced(accel[i].0, accel[i].1, t_start));
        let seg = Segment {
            t0: t_start,
            t1: 0.0,
            start,
            accel,
            phase: self.phase,
            contact_force: 0.0,
            rolling_share: [1.0; 2],
            angle0: [0.0; 2],
            ledger0: Ledger::default(),
            bridge: None,
        };
        let r = self.groove.k * self.radius;
        let tau = -t_start;
        self.angle = std::array::from_fn(|i| (start[i].u * tau + 0.5 * accel[i].1 * tau * tau) / r);
        self.ledger = segment_losses(&self.groove, self.mass, &seg, tau);
        if t_start < 0.0 {
            self.segments.push(seg);
        }
    }

    /// Advances to the next event and applies it. Returns false once nothing more happens.
    fn step(&mut self) -> bool {
        let candidates = self.candidates();
        let Some(tau) = candidates.as_slice().iter().map(|c| c.0).reduce(f64::min) else {
            self.push_segment(f64::INFINITY);
            return false;
        };
        let mut due = Candidates::default();
        for &c in candidates.as_slice() {
            if c.0 <= tau * (1.0 + SIMULTANEOUS) {
                due.push(c);
            }
        }
        let due = due.as_slice().iter().map(|c| c.1);
        let before = self.state;
        let phase_before = self.phase;
        self.advance(tau);
        let mut kinds = Kinds::default();
        for c in due.clone().filter(|c| *c != EventCandidate::Impact) {
            kinds.push(self.apply(c, &before));
        }
        if self.together {
            // Touching balls share one velocity; keep it exactly shared after snapping.
            let v = if self.state[0].v == 0.0 || self.state[1].v == 0.0 {
                0.0
            } else {
                self.state[0].v
            };
            self.state[0].v = v;
            self.state[1].v = v;
        }
        let impact = due.clone().any(|c| c == EventCandidate::Impact);
        if impact {
            self.collide();
            kinds.push((EventKind::Collision, Who::Both));
        }
        self.settle();
        let mut confirmed = Kinds::default();
        for &(kind, who) in kinds.as_slice() {
            if let Some(k) = self.confirmed(kind, who, &phase_before) {
                confirmed.push(k);
            }
        }
        self.record(confirmed.as_slice());
        if impact {
            self.check_series();
        }
        // After the series check: summing a series can change whether the balls
        // press, and the event list must say so once, after the accumulation point.
        self.record_contact();
        true
    }

    /// What a ball's event `kind` really was, once [`Engine::settle`] has decided the
    /// motion that follows (`phase_before`: the phases of the segment that just ended).
    /// `rest` means v = u = 0 until something acts, so a ball whose speed reached zero
    /// is at rest only if it stays there. One that the other ball pushes on through
    /// v = 0 is no event while it rolls (its speed changes sign, nothing else), and
    /// `rolling` if its slip ended just then; the dynamics are the same either way.
    fn confirmed(
        &self,
        kind: EventKind,
        who: Who,
        phase_before: &[Phase; 2],
    ) -> Option<(EventKind, Who)> {
        let i = match (kind, who) {
            (EventKind::Rest, Who::Left) => 0,
            (EventKind::Rest, Who::Right) => 1,
            _ => return Some((kind, who)),
        };
        match (phase_before[i], self.phase[i]) {
            (_, Phase::Resting) => Some((EventKind::Rest, who)),
            (Phase::Sliding { .. }, Phase::Rolling) => Some((EventKind::Rolling, who)),
            _ => None,
        }
    }

    /// Pushes the segment from the current time to `t1` with the current accelerations.
    fn push_segment(&mut self, t1: f64) {
        self.segments.push(Segment {
            t0: self.t,
            t1,
            start: self.state,
            accel: self.accel,
            phase: self.phase,
            contact_force: self.push,
            rolling_share: self.rolling_share,
            angle0: self.angle,
            ledger0: self.ledger,
            bridge: None,
        });
    }

    fn advance(&mut self, tau: f64) {
        if !self.together {
            let w = self.state[1].v - self.state[0].v;
            let c = self.accel[1].0 - self.accel[0].0;
            self.gap = (self.gap + tau * (w + 0.5 * c * tau)).max(0.0);
        }
        self.push_segment(self.t + tau);
        let seg = *self.segments.last().expect("just pushed");
        if seg.t1 == seg.t0 {
            // Shorter than the clock's resolution at this time: the states still move
            // on, but no empty segment stands in the solution.
            self.segments.pop();
        }
        self.ledger = segment_losses(&self.groove, self.mass, &seg, tau);
        let r = self.groove.k * self.radius;
        for i in 0..2 {
            let (a, du) = self.accel[i];
            self.angle[i] += (self.state[i].u * tau + 0.5 * du * tau * tau) / r;
            self.state[i] = self.state[i].advanced(a, du, tau);
        }
        self.t += tau;
        self.since_impact += tau;
    }

    /// The phase a ball is in from its state (after an impact or a jump).
    fn phase_of(&self, s: BallState) -> Phase {
        let sl = slip(s);
        if sl.abs() > self.eps_v {
            Phase::Sliding {
                sign: sl.signum() as i8,
            }
        } else if s.v != 0.0 {
            // No snapping of v here: after an impact a heavy ball may really move at a
            // tiny speed, and zeroing it would break momentum conservation.
            Phase::Rolling
        } else {
            Phase::Resting
        }
    }

    fn set_phases_from_state(&mut self) {
        let before = self.kinetic(&self.state);
        for i in 0..2 {
            self.phase[i] = self.phase_of(self.state[i]);
            match self.phase[i] {
                Phase::Rolling => self.state[i].u = self.state[i].v,
                Phase::Resting => self.state[i].u = 0.0,
                Phase::Sliding { .. } => {}
            }
        }
        // Snapping a negligible slip (≤ 1e-12 of the speeds) moves the spin energy
        // m u²/(5k²) by ~1e-12/k² of it: near b = 2R, thousands of snaps would show
        // in the books. What it moved is booked as friction (it ends a slip).
        self.ledger.friction += before - self.kinetic(&self.state);
    }

    /// The impact: Newton's law on the centre velocities, spins unchanged.
    fn collide(&mut self) {
        let [l, r] = self.state;
        let closing = l.v - r.v;
        let arrival = [(l.v, self.phase[0]), (r.v, self.phase[1])];
        let e = self.restitution;
        let (vl, vr) = model::impact(self.mass[0], self.mass[1], l.v, r.v, e);
        self.ledger.impacts += model::impact_loss(self.mass[0], self.mass[1], l.v, r.v, e);
        self.state[0].v = vl;
        self.state[1].v = vr;
        if vr - vl <= self.eps_v {
            // No rebound (e = 0, or a vanishing impact): the balls move on as one.
            let p = (self.mass[0] * vl + self.mass[1] * vr) / (self.mass[0] + self.mass[1]);
            self.state[0].v = p;
            self.state[1].v = p;
        }
        self.gap = 0.0;
        self.impacts += 1;
        self.set_phases_from_state();
        self.history.push(ImpactRecord {
            cycle: self.since_impact,
            closing,
            arrival,
            state: self.state,
            angle: self.angle,
            ledger: self.ledger,
        });
        self.since_impact = 0.0;
    }

    fn record(&mut self, kinds: &[(EventKind, Who)]) {
        for &(kind, ball) in kinds {
            self.events.push(Event {
                t: self.t,
                kind,
                ball,
                left: self.state[0],
                right: self.state[1],
            });
        }
    }

    /// Records `contact_start` or `contact_end` if the balls' pressing differs from
    /// what the event list last said: one event per change, however many times the
    /// motion was settled in between.
    fn record_contact(&mut self) {
        let pressed = self.push > 0.0;
        if pressed != self.told_pressed {
            self.told_pressed = pressed;
            let kind = if pressed {
                EventKind::ContactStart
            } else {
                EventKind::ContactEnd
            };
            self.record(&[(kind, Who::Both)]);
        }
    }
}

impl Engine {
    /// The run as a solution over `span` (its end from the span rule and the last event).
    fn into_solution(self, scene: &Scene, span: &Span) -> Solution {
        let t_end = end_time(span, self.t_last_event());
        Solution {
            scene: *scene,
            t_start: span.t_start,
            t_end,
            method: "exact",
            events: self.events,
            segments: self.segments,
            impacts: self.impacts,
            accumulation: self.accumulation,
            truncated: self.truncated,
            series: self.series,
        }
    }
}

#[cfg(test)]
mod tests;
