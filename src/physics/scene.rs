//! The scene in SI units: the two balls, the groove and the simulated time span.
//! How a scene is built from settings and checked lives in `settings::params`.

use serde::Serialize;

use crate::physics::closed_form;
use crate::physics::model::Groove;

/// One ball's own numbers.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Ball {
    /// Mass in kg.
    pub mass: f64,
    /// Speed toward the impact point just before the first impact, m/s.
    pub v0: f64,
}

/// The physical scene, SI units throughout. Always valid once built by `settings::spec::SceneSpec::resolve`.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Scene {
    /// Ball radius R, m (both balls).
    pub radius: f64,
    /// Groove width b, m, `0 ≤ b < 2R`.
    pub width: f64,
    /// Kinetic friction coefficient μ_k between ball and groove edges.
    pub mu: f64,
    /// Gravitational acceleration g, m/s².
    pub g: f64,
    /// Newton's coefficient of restitution e between the balls, `0..=1`.
    pub restitution: f64,
    /// Rolling-resistance coefficient c_rr ≥ 0 (rolling deceleration c_rr g).
    pub rolling_resistance: f64,
    pub left: Ball,
    pub right: Ball,
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
    pub fn groove(&self) -> Groove {
        Groove {
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
