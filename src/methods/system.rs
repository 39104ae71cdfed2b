//! The one 1-D model every method steps: the state vector, the methods' names and
//! settings, the friction laws, the right-hand side, the impact map and the overlap
//! rule.

use serde::Serialize;

use crate::physics::model::{self, BallState, Rails};
use crate::physics::scene::Scene;

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
/// the physics' [`Rails`], so every method integrates the very model the engine solves.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Model {
    /// The scene itself: the exact method solves it directly.
    pub scene: Scene,
    pub groove: Rails,
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
