//! What a model fit is asked and how it stops: the values it may free ([`Free`]), why
//! it fails ([`FitError`]), and the count of model evaluations that reports progress
//! and stops the fit when asked ([`Evals`]).

use serde::Serialize;

use crate::physics::scene::Scene;
use crate::study::Progress;

/// Why a fit cannot be made.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum FitError {
    #[error("{0}")]
    Data(String),
    /// The caller's [`Progress`] asked to stop.
    #[error("cancelled")]
    Cancelled,
}

/// Counts model evaluations for [`Progress`] and stops when it asks.
pub(super) struct Evals<'a> {
    pub(super) progress: &'a dyn Progress,
    pub(super) done: std::cell::Cell<u64>,
}

impl Evals<'_> {
    /// Before each model evaluation.
    pub(super) fn next(&self) -> Result<(), FitError> {
        let done = self.done.get() + 1;
        self.done.set(done);
        self.progress.tick(done, 0);
        if self.progress.cancelled() {
            Err(FitError::Cancelled)
        } else {
            Ok(())
        }
    }
}

/// Which scene values a model fit may change.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Free {
    Mu,
    V0,
    Restitution,
    RollingResistance,
}

impl Free {
    /// Its value in `scene` (v0: the left ball's).
    pub fn value_in(self, scene: &Scene) -> f64 {
        match self {
            Free::Mu => scene.mu,
            Free::V0 => scene.left.v0,
            Free::Restitution => scene.restitution,
            Free::RollingResistance => scene.rolling_resistance,
        }
    }

    /// The name on the command line and in JSON.
    pub fn name(self) -> &'static str {
        match self {
            Free::Mu => "mu",
            Free::V0 => "v0",
            Free::Restitution => "restitution",
            Free::RollingResistance => "rolling_resistance",
        }
    }
}
