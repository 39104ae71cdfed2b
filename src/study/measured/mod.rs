//! Measured data for a scene. A reader (`input::data`) gives a [`RawSeries`];
//! [`prepare`] derives what does not depend on the scene once (a position track's
//! velocities and spin rate, by `track`); [`for_scene`] is the pure, cheap step that
//! the lab runs on every scene change: a track's v_t from the scene's contact radius
//! r = kR, the rest band, and the ghost ball's track (`ghost`).

#![deny(
    clippy::indexing_slicing,
    clippy::unwrap_used,
    clippy::expect_used,
    clippy::panic
)]

mod ghost;
pub mod line;
pub mod noise;
pub mod series;
pub mod track;

use std::sync::Arc;

pub use series::{
    Measured, MeasuredParts, NoCommonFrame, NoLineVt, OutOfLabRange, RawSeries, Rule, Track,
    TrackParts,
};
pub use track::{Derive, Found, TrackError, in_file_time, more_runs, ordinal, runs_text};

use crate::physics::scene::Scene;

/// Most data rows a series may have: far more than a video gives (a minute at 1000
/// frames/s is 60,000), and a bound on the memory and time a fit can take.
pub const MAX_ROWS: usize = 1_000_000;

/// A measured series ready for any scene.
#[derive(Clone, Debug, PartialEq)]
pub enum Series {
    /// Velocities measured as such (a velocity file, a preset's data): v_t is given.
    Velocities(Arc<Measured>),
    /// Velocities derived from a position track: `v_t` and `v_t_sigma` hold the spin
    /// rate dθ/dt and its uncertainty (rad/s) until a scene gives r.
    Track(Arc<Measured>, Box<Found>),
}

impl Series {
    /// The left ball's velocities as derived without a scene.
    pub fn measured(&self) -> &Measured {
        match self {
            Series::Velocities(m) | Series::Track(m, _) => m,
        }
    }

    /// True when the file was read mirrored (its x ran away from the other ball).
    pub fn mirrored(&self) -> bool {
        self.measured().mirrored()
    }

    /// True when a velocity file's v_t was read turned (it ran opposite to v_cm).
    pub fn spin_turned(&self) -> bool {
        self.measured().spin_turned()
    }

    /// What the derivation found in a position track; `None` for velocities.
    pub fn found(&self) -> Option<&Found> {
        match self {
            Series::Velocities(_) => None,
            Series::Track(_, found) => Some(found.as_ref()),
        }
    }
}

/// Derives a raw series' velocities as far as the scene does not enter: a position
/// track's impact, direction, v_cm and spin rate (`track::derive` with r = 1).
pub fn prepare(raw: RawSeries, opts: &Derive) -> Result<Series, TrackError> {
    Ok(match raw {
        RawSeries::Velocities(m) => Series::Velocities(Arc::new(m)),
        RawSeries::Positions(t) => {
            let (m, found) = track::derive(&t, 1.0, opts)?;
            Series::Track(Arc::new(m), Box::new(found))
        }
    })
}

/// A measured series as seen in one scene.
#[derive(Clone, Debug, PartialEq)]
pub struct InScene {
    /// The left ball's velocities: a track's v_t with this scene's r.
    pub measured: Arc<Measured>,
    /// Speeds within ± this of zero cannot be told from rest ([`noise::rest_band`]).
    pub rest_band: f64,
    /// The measured ball's centre at each measured time, model's x (`ghost`).
    ghost: Vec<f64>,
    /// Where a track's rim mark turns more than half a turn between frames in this
    /// scene (rad per frame, [`mark_turn_per_frame`]): its angle cannot be unwrapped
    /// (each frame's turn read as its nearest branch runs backward), so the mark is
    /// left out of `measured` (no v_t, no angle) and the fit uses the centre alone.
    pub mark_aliased: Option<f64>,
}

/// The series `series` in `scene`: pure, and cheap beside a solve (one pass over the
/// points), so the lab calls it on every scene change.
pub fn for_scene(series: &Series, scene: &Scene) -> InScene {
    let mut mark_aliased = None;
    let measured = match series {
        Series::Velocities(m) => m.clone(),
        Series::Track(m, _) => {
            let r = scene.k() * scene.radius;
            let turn = m.angle().and(mark_turn_per_frame(m, r));
            mark_aliased = turn.filter(|w| *w > std::f64::consts::PI);
            Arc::new(match mark_aliased {
                Some(_) => m.without_mark(),
                None => m.v_t_scaled(r),
            })
        }
    };
    InScene {
        mark_aliased,
        rest_band: noise::rest_band(&measured),
        ghost: ghost::track(&measured, scene.radius),
        measured,
    }
}

/// How far a ball rolling in at the track's approach speed turns between two frames
/// on the contact radius `r` (m), rad: the fastest |v_cm| before the impact times the
/// median frame interval over r. `None` without both.
fn mark_turn_per_frame(m: &Measured, r: f64) -> Option<f64> {
    let mut steps: Vec<f64> = m
        .t()
        .iter()
        .zip(m.t().iter().skip(1))
        .map(|(a, b)| b - a)
        .collect();
    steps.sort_by(f64::total_cmp);
    let dt = *steps.get(steps.len() / 2)?;
    let fastest = m
        .t()
        .iter()
        .zip(m.v_cm())
        .filter(|(t, v)| **t < 0.0 && v.is_finite())
        .map(|(_, v)| v.abs())
        .fold(None, |a: Option<f64>, v| Some(a.map_or(v, |a| a.max(v))))?;
    (r > 0.0).then(|| fastest * dt / r)
}

impl InScene {
    /// Where the measured left ball's centre is at `t`, model's x; `None` outside the
    /// series.
    pub fn ghost_x(&self, t: f64) -> Option<f64> {
        ghost::x_at(&self.measured, &self.ghost, t)
    }

    /// How far the tracked rim mark has turned since the first impact at `t`, rad;
    /// `None` without a mark or outside the series.
    pub fn ghost_turn(&self, t: f64) -> Option<f64> {
        ghost::turn_at(&self.measured, t)
    }
}
