//! Time-stepping methods for the same 1-D model, to weigh against the exact engine:
//! one signature ([`integrate`]), one result type ([`RunEnd`]), the right-hand side
//! kept apart from the methods, each method in its own file.
//!
//! Impacts, for the fixed-step methods (`euler`, `symplectic-euler`, `rk4`), are
//! found the way game engines find them: after a step, if the balls overlap while
//! closing, Newton's law is applied as an impulse at the end of that step and the
//! overlap is removed by moving both centres apart in inverse proportion to their
//! masses. `rk45` locates impacts and slip reversals on its dense output; `moreau`
//! treats impacts and friction as set-valued laws at the velocity level.

mod fixed;
mod moreau;
mod rk45;

use serde::Serialize;

use crate::physics::model::{self, BallState, Groove};
use crate::physics::scene::Scene;
use crate::physics::solution::{Event, EventKind, Who};

/// The state vector `[x_L, v_L, u_L, x_R, v_R, u_R]` (SI).
pub type Y = [f64; 6];

/// A solution method.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Method {
    /// The event-driven engine (reference).
    Exact,
    /// Explicit Euler, Coulomb friction `sgn(s)`.
    Euler,
    /// Semi-implicit (symplectic) Euler, Coulomb friction.
    SymplecticEuler,
    /// Classical Runge–Kutta 4, friction regularised as `tanh(s/ε)`.
    Rk4,
    /// Adaptive Dormand–Prince 5(4) with dense output and event location.
    Rk45,
    /// Moreau–Jean time-stepping (θ = 1/2), impacts and friction set-valued.
    Moreau,
}

impl Method {
    pub const TIME_STEPPING: [Method; 5] = [
        Method::Euler,
        Method::SymplecticEuler,
        Method::Rk4,
        Method::Rk45,
        Method::Moreau,
    ];

    pub fn name(self) -> &'static str {
        match self {
            Method::Exact => "exact",
            Method::Euler => "euler",
            Method::SymplecticEuler => "symplectic-euler",
            Method::Rk4 => "rk4",
            Method::Rk45 => "rk45",
            Method::Moreau => "moreau",
        }
    }

    /// One line on what the method is (`--help`).
    pub fn description(self) -> &'static str {
        match self {
            Method::Exact => "The event-driven engine (reference)",
            Method::Euler => "Explicit Euler, Coulomb friction sgn(s)",
            Method::SymplecticEuler => "Semi-implicit (symplectic) Euler, Coulomb friction",
            Method::Rk4 => "Classical Runge-Kutta 4, friction regularised as tanh(s/ε)",
            Method::Rk45 => "Adaptive Dormand-Prince 5(4) with dense output and event location",
            Method::Moreau => {
                "Moreau-Jean time-stepping (θ = 1/2), impacts and friction set-valued"
            }
        }
    }

    /// Adaptive methods are driven by a tolerance, the others by a step.
    pub fn adaptive(self) -> bool {
        self == Method::Rk45
    }

    /// Methods whose friction is smoothed (`tanh(s/ε)`).
    pub fn regularised(self) -> bool {
        self == Method::Rk4
    }
}

/// Knobs of a run.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Settings {
    /// Step size h, s (fixed-step methods and moreau); first step of rk45.
    pub step: f64,
    /// Relative and absolute tolerance of rk45 (absolute scaled by the speed scale).
    pub tolerance: f64,
    /// Regularisation speed ε of `tanh(s/ε)`, m/s.
    pub epsilon: f64,
    /// Step budget: no run goes beyond it.
    pub max_steps: usize,
}

impl Default for Settings {
    fn default() -> Self {
        Settings {
            step: 1e-4,
            tolerance: 1e-6,
            epsilon: 1e-3,
            max_steps: 20_000_000,
        }
    }
}

/// How friction depends on slip in the smooth right-hand side.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Friction {
    Coulomb,
    Tanh(f64),
}

impl Friction {
    fn sign(self, s: f64) -> f64 {
        match self {
            Friction::Coulomb => {
                if s > 0.0 {
                    1.0
                } else if s < 0.0 {
                    -1.0
                } else {
                    0.0
                }
            }
            Friction::Tanh(eps) => (s / eps).tanh(),
        }
    }
}

/// The scene's constants as the methods need them: the per-ball formulas come from
/// the physics' [`Groove`], so every method integrates the very model the engine solves.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Model {
    /// The scene itself: the exact method solves it directly.
    pub scene: Scene,
    pub groove: Groove,
    pub mass: [f64; 2],
    pub radius: f64,
    pub restitution: f64,
}

impl Model {
    pub fn of(scene: &Scene) -> Model {
        Model {
            scene: *scene,
            groove: scene.groove(),
            mass: [scene.left.mass, scene.right.mass],
            radius: scene.radius,
            restitution: scene.restitution,
        }
    }

    /// `A = μ_k g (1/k + 5k/2)`: how fast friction closes the slip.
    pub fn slip_rate(&self) -> f64 {
        self.groove.slip_rate()
    }

    /// Kinetic energy of the pair, J.
    pub fn energy(&self, y: &Y) -> f64 {
        (0..2)
            .map(|i| {
                let (tr, rot) = self.groove.energy(self.mass[i], ball(y, i));
                tr + rot
            })
            .sum()
    }

    /// Deceleration of rolling resistance, `c_rr g` (0 without it).
    pub fn rolling_deceleration(&self) -> f64 {
        self.groove.rolling_resistance * self.groove.g
    }
}

/// The smooth right-hand side `dy/dt` with friction law `law`. Rolling resistance is
/// smoothed with the same law on v (time-stepping has no rolling phase to switch to).
pub fn rhs(m: &Model, law: Friction, y: &Y) -> Y {
    let mut d = [0.0; 6];
    for i in 0..2 {
        let (v, u) = (y[3 * i + 1], y[3 * i + 2]);
        // The sliding accelerations are linear in the slip's sign, so a smoothed sign
        // gives the smoothed law.
        let (a, du) = m.groove.sliding_accelerations(law.sign(v - u));
        let rr = -m.rolling_deceleration() * law.sign(v);
        d[3 * i] = v;
        d[3 * i + 1] = a + rr;
        d[3 * i + 2] = du + rr;
    }
    d
}

/// Surface gap between the balls, m.
pub fn gap(m: &Model, y: &Y) -> f64 {
    y[3] - y[0] - 2.0 * m.radius
}

/// Newton's impact law on the centre velocities of `y` (spins unchanged).
pub fn collide(m: &Model, y: &mut Y) {
    let (vl, vr) = model::impact(m.mass[0], m.mass[1], y[1], y[4], m.restitution);
    y[1] = vl;
    y[4] = vr;
}

/// The game-engine treatment: after a step, an overlap while closing is an impact;
/// any overlap is removed by moving the centres apart (mass-weighted).
pub fn resolve_overlap(m: &Model, y: &mut Y) -> bool {
    let g = gap(m, y);
    if g >= 0.0 {
        return false;
    }
    let closing = y[1] > y[4];
    if closing {
        collide(m, y);
    }
    let total = m.mass[0] + m.mass[1];
    y[0] += g * m.mass[1] / total;
    y[3] -= g * m.mass[0] / total;
    closing
}

pub fn ball(y: &Y, i: usize) -> BallState {
    BallState {
        x: y[3 * i],
        v: y[3 * i + 1],
        u: y[3 * i + 2],
    }
}

/// What a method reports while it runs.
pub trait Observer {
    /// Called after every accepted step (and at the start). Return false to stop.
    fn step(&mut self, t: f64, y: &Y) -> bool;
    /// Called for each event the method detects.
    fn event(&mut self, _event: Event) {}
}

/// How a run ended: where, after how much work, and why if early.
#[derive(Clone, Debug, PartialEq)]
pub struct RunEnd {
    pub steps: usize,
    pub rhs_evals: usize,
    /// Why the run ended early, if it did (step budget, step-size collapse).
    pub stalled: Option<String>,
    /// Stopped by the observer (non-finite state, …).
    pub aborted: bool,
    pub t: f64,
    pub y: Y,
}

/// Runs `method` from the state `y0` at `t0` (the rolling run-up is integrated too)
/// to `t1`, reporting to `obs`.
pub fn integrate(
    method: Method,
    m: &Model,
    y0: Y,
    t0: f64,
    t1: f64,
    s: &Settings,
    obs: &mut dyn Observer,
) -> RunEnd {
    match method {
        Method::Exact => exact(m, t0, t1, obs),
        Method::Euler | Method::SymplecticEuler | Method::Rk4 => {
            fixed::integrate(method, m, y0, t0, t1, s, obs)
        }
        Method::Rk45 => rk45::integrate(m, y0, t0, t1, s, obs),
        Method::Moreau => moreau::integrate(m, y0, t0, t1, s, obs),
    }
}

/// The exact engine behind the same signature: its "steps" are its segments (one
/// polynomial piece from event to event), reported at each segment start, and its
/// events are the engine's. It solves the scene itself, from the same run-up state
/// that [`start_state`] gives every method.
fn exact(m: &Model, t0: f64, t1: f64, obs: &mut dyn Observer) -> RunEnd {
    let span = crate::physics::scene::Span {
        t_start: t0,
        t_end: Some(t1),
    };
    let sol = crate::physics::engine::solve(&m.scene, &span);
    let state = |s: crate::physics::solution::Snapshot| -> Y {
        [
            s.left.x, s.left.v, s.left.u, s.right.x, s.right.v, s.right.u,
        ]
    };
    let mut out = RunEnd {
        steps: 0,
        rhs_evals: 0,
        stalled: sol
            .truncated
            .then(|| "the event budget ended the run early".to_string()),
        aborted: false,
        t: t0,
        y: state(sol.at(t0)),
    };
    let starts = sol.segments.iter().map(|seg| seg.t0.max(t0));
    for t in std::iter::once(t0).chain(starts.filter(|&t| t > t0 && t < t1)) {
        out.steps += 1;
        if !obs.step(t, &state(sol.at(t))) {
            out.aborted = true;
            return out;
        }
    }
    for e in sol.visible_events() {
        obs.event(*e);
    }
    out.t = t1;
    out.y = state(sol.at(t1));
    obs.step(t1, &out.y);
    out
}

/// The state at `t_start` that rolls into the first impact at t = 0: the exact
/// run-up, shared by every method so that they all start alike.
pub fn start_state(scene: &Scene, t_start: f64) -> Y {
    let sol = crate::physics::engine::solve(
        scene,
        &crate::physics::scene::Span {
            t_start,
            t_end: None,
        },
    );
    let s = sol.at(t_start);
    [
        s.left.x, s.left.v, s.left.u, s.right.x, s.right.v, s.right.u,
    ]
}

/// One step of a fixed-grid method: the new state, right-hand-side evaluations, and
/// whether an impact happened in it.
pub(crate) struct GridStep {
    pub y: Y,
    pub rhs_evals: usize,
    pub impact: bool,
}

/// Runs a fixed-step method on the grid `t0 + i h` (the last step lands on `t1`, with
/// no drift), reporting steps and events; refuses up front a run beyond the budget.
pub(crate) fn run_grid(
    y0: Y,
    t0: f64,
    t1: f64,
    s: &Settings,
    roll_threshold: f64,
    obs: &mut dyn Observer,
    mut step: impl FnMut(&Y, f64) -> GridStep,
) -> RunEnd {
    let h = s.step;
    let n = ((t1 - t0) / h).ceil() as usize;
    let mut out = RunEnd {
        steps: 0,
        rhs_evals: 0,
        stalled: None,
        aborted: false,
        t: t0,
        y: y0,
    };
    if n > s.max_steps {
        out.stalled = Some(format!("{n} steps needed, budget {}", s.max_steps));
        return out;
    }
    let mut tracker = EventTracker::new(roll_threshold);
    if !obs.step(t0, &y0) {
        out.aborted = true;
        return out;
    }
    tracker.step(t0, &y0, obs);
    for i in 1..=n {
        let t = if i == n { t1 } else { t0 + i as f64 * h };
        let next = step(&out.y, t - out.t);
        out.y = next.y;
        out.rhs_evals += next.rhs_evals;
        out.steps += 1;
        out.t = t;
        if next.impact {
            tracker.impact(t, &out.y, obs);
        }
        tracker.step(t, &out.y, obs);
        if !obs.step(t, &out.y) {
            out.aborted = true;
            break;
        }
    }
    out
}

/// Reports "rolling" once per ball after each impact, as a time-stepping method can
/// see it: the slip changes sign (Coulomb friction), or falls below `threshold` (the
/// regularised law, whose slip decays without crossing zero).
#[derive(Clone, Debug, Default)]
pub(crate) struct EventTracker {
    rolled: [bool; 2],
    last: Option<(f64, Y)>,
    threshold: f64,
}

impl EventTracker {
    pub(crate) fn new(threshold: f64) -> EventTracker {
        EventTracker {
            threshold,
            ..EventTracker::default()
        }
    }

    pub(crate) fn impact(&mut self, t: f64, y: &Y, obs: &mut dyn Observer) {
        self.rolled = [false; 2];
        obs.event(event(t, y, EventKind::Collision, Who::Both));
    }

    pub(crate) fn step(&mut self, t: f64, y: &Y, obs: &mut dyn Observer) {
        if let Some((t0, y0)) = self.last {
            for i in 0..2 {
                let s0 = y0[3 * i + 1] - y0[3 * i + 2];
                let s1 = y[3 * i + 1] - y[3 * i + 2];
                let crossed = s0 * s1 < 0.0 || (s1 == 0.0 && s0 != 0.0);
                let settled = s0.abs() > self.threshold && s1.abs() <= self.threshold;
                if !self.rolled[i] && t0 >= 0.0 && (crossed || settled) {
                    // Linear interpolation of the crossing inside the step.
                    let target = if crossed {
                        0.0
                    } else {
                        self.threshold * s0.signum()
                    };
                    let f = (s0 - target) / (s0 - s1);
                    let tc = t0 + f * (t - t0);
                    let yc: Y = std::array::from_fn(|j| y0[j] + f * (y[j] - y0[j]));
                    self.rolled[i] = true;
                    obs.event(event(tc, &yc, EventKind::Rolling, Who::ball(i)));
                }
            }
        }
        self.last = Some((t, *y));
    }
}

pub(crate) fn event(t: f64, y: &Y, kind: EventKind, who: Who) -> Event {
    Event {
        t,
        kind,
        ball: who,
        left: ball(y, 0),
        right: ball(y, 1),
    }
}
