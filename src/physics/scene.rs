//! The scene in SI units: the two balls, the groove and the simulated time span.
//! How a scene is built from settings and checked lives in `settings::params`.

use serde::Serialize;

use crate::physics::closed_form;
use crate::physics::model::Rails;

/// Standard gravity, used when nothing else is said, m/s².
pub const STANDARD_GRAVITY: f64 = 9.81;

/// One ball's own numbers. Default: the paper's ball, 167 g at 60 cm/s.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Ball {
    /// Mass in kg. Default 0.167 kg.
    pub mass: f64,
    /// Speed toward the impact point just before the first impact, m/s. Default 0.6 m/s.
    pub v0: f64,
}

impl Ball {
    /// The paper's ball: 167 g at 60 cm/s.
    pub const DEFAULT: Ball = Ball {
        mass: 0.167,
        v0: 0.6,
    };
}

impl Default for Ball {
    fn default() -> Self {
        Ball::DEFAULT
    }
}

/// The physical scene, SI units throughout. Always valid once built by
/// `settings::spec::SceneSpec::resolve`. Default: the paper's wide groove (b = 4.9 cm)
/// with two 167 g balls of radius 2.75 cm meeting at 60 cm/s each, e = 1, no rolling
/// resistance, standard gravity; change what a test needs with
/// `Scene { width: 0.03, ..Scene::default() }`.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Scene {
    /// Ball radius R, m (both balls). Default 0.0275 m.
    pub radius: f64,
    /// Groove width b, m, `0 ≤ b < 2R`. Default 0.049 m.
    pub width: f64,
    /// Kinetic friction coefficient μ_k between ball and groove edges, no unit.
    /// Default 0.17.
    pub mu: f64,
    /// Gravitational acceleration g, m/s². Default [`STANDARD_GRAVITY`], 9.81 m/s².
    pub g: f64,
    /// Newton's coefficient of restitution e between the balls, `0..=1`, no unit.
    /// Default 1 (elastic).
    pub restitution: f64,
    /// Rolling-resistance coefficient c_rr ≥ 0, no unit (rolling deceleration c_rr g).
    /// Default 0.
    pub rolling_resistance: f64,
    /// The left ball, coming from x < 0. Default [`Ball::DEFAULT`].
    pub left: Ball,
    /// The right ball, coming from x > 0. Default [`Ball::DEFAULT`].
    pub right: Ball,
}

impl Scene {
    /// The paper's wide-groove scene (see [`Scene`]); the defaults of `g`, `e` and
    /// `c_rr` are also the parameter table's.
    pub const DEFAULT: Scene = Scene {
        radius: 0.0275,
        width: 0.049,
        mu: 0.17,
        g: STANDARD_GRAVITY,
        restitution: 1.0,
        rolling_resistance: 0.0,
        left: Ball::DEFAULT,
        right: Ball::DEFAULT,
    };
}

impl Default for Scene {
    fn default() -> Self {
        Scene::DEFAULT
    }
}

/// The simulated time span, s. The first impact is at t = 0.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Span {
    pub t_start: f64,
    /// `None`: long enough to show the last event.
    pub t_end: Option<f64>,
}

impl Span {
    /// The span when none is given: from 0.2 s before the first impact to a little
    /// past the last event (the `t_start` default of the parameter table).
    pub const DEFAULT: Span = Span {
        t_start: -0.2,
        t_end: None,
    };
}

impl Default for Span {
    fn default() -> Self {
        Span::DEFAULT
    }
}

impl Scene {
    /// `k = r / R`, the contact circle's radius over the ball's.
    pub fn k(&self) -> f64 {
        closed_form::contact_ratio(self.radius, self.width)
    }

    /// One ball's groove: what the per-ball formulas of `model` need.
    pub fn groove(&self) -> Rails {
        Rails {
            k: self.k(),
            mu: self.mu,
            g: self.g,
            rolling_resistance: self.rolling_resistance,
        }
    }

    /// True for the paper's symmetric scene: equal masses and equal speeds.
    pub fn is_symmetric(&self) -> bool {
        self.left == self.right
    }

    /// The largest speed in the scene, the scale for "negligibly small" speeds.
    pub fn speed_scale(&self) -> f64 {
        self.left.v0.abs().max(self.right.v0.abs())
    }
}
