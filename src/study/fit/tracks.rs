//! Both model fits of a series derived from a position track, side by side: to its
//! derived velocities and directly to its positions.

use serde::Serialize;

use super::model::{ModelFit, model_fit, position_fit};
use super::problem::{FitError, Free};
use crate::physics::scene::Scene;
use crate::study::measured::Measured;

/// Both model fits of a tracked series, side by side.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct TrackFits {
    /// The model's v_cm and v_t against the derived velocities, weighted by their
    /// uncertainties.
    pub velocity: ModelFit,
    /// The model's x(t) (and the mark's angle) against the track itself.
    pub position: ModelFit,
    /// False when no rim mark was tracked: both fits use the centre only.
    pub uses_spin: bool,
}

/// Fits the model to the derived velocities and directly to the positions of `m`
/// (which must carry `x`), freeing `free`.
pub fn fit_tracks(
    scene: &Scene,
    m: &Measured,
    free: &[Free],
    progress: &dyn crate::study::Progress,
) -> Result<TrackFits, FitError> {
    Ok(TrackFits {
        velocity: model_fit(scene, m, free, progress)?,
        position: position_fit(scene, m, free, progress)?,
        uses_spin: m.has_v_t(),
    })
}
