//! What a model fit is asked and how it stops: the values it may free ([`Free`]), why
//! it fails ([`FitError`]), and the count of model evaluations that reports progress
//! and stops the fit when asked ([`Evals`]).

use serde::Serialize;

use crate::physics::engine;
use crate::physics::scene::{Scene, Span};
use crate::physics::solution::Solution;
use crate::settings::params::Key;
use crate::settings::units::significant;
use crate::study::Progress;

/// Why a fit cannot be made.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum FitError {
    /// Fewer usable points than the fit's values need (two more than the free values).
    #[error("{usable} usable points, allowed at least {needed}")]
    TooFewPoints { usable: usize, needed: usize },
    /// A position fit of data without positions.
    #[error("the data hold no positions (a velocity file): no position fit")]
    NoPositions,
    /// No measured point after the impact for the line fits.
    #[error("no measured points after the impact (t > 0) to fit")]
    NothingAfterImpact,
    /// The line fits' window holds too few points.
    #[error(
        "the window {} … {} s holds {points} points (the data run from t = {} to {} s after the impact), allowed at least 3",
        significant(asked.0, 4), significant(asked.1, 4), significant(data.0, 4), significant(data.1, 4)
    )]
    ShortWindow {
        /// The window asked for, s.
        asked: (f64, f64),
        points: usize,
        /// The data's first and last time, s.
        data: (f64, f64),
    },
    /// A fitted number is not finite: the data's numbers are in other units than read,
    /// most likely.
    #[error("the fit gives no finite {} for this scene and data: {looks}", bad.join(", "))]
    NotFinite {
        bad: Vec<&'static str>,
        looks: DataLooks,
    },
    /// The fit used up its work budget ([`WORK_BUDGET`]) before it settled.
    #[error(
        "the fit stopped at its work budget ({evaluations} model evaluations, {segments} motion segments computed) before it settled: each run of this scene's model has up to {longest} segments (near b = 2R the balls meet again and again), so μ_k is not determined here; a scene farther from its limits fits in a moment"
    )]
    Budget {
        evaluations: u64,
        segments: u64,
        longest: usize,
    },
    /// The caller's [`Progress`] asked to stop.
    #[error("cancelled")]
    Cancelled,
}

/// What a series' numbers look like, said when a fit of them gives no finite number
/// (numbers in ms, cm/s or cm read as s, m/s or m are the usual cause).
#[derive(Clone, Debug, PartialEq)]
pub struct DataLooks {
    /// The first and last time, s; the median frame interval, s.
    pub t: (f64, f64),
    pub frame: f64,
    /// The fastest speed, m/s; the positions' span, m (a track's).
    pub fastest: f64,
    pub positions: Option<(f64, f64)>,
    /// The scene's larger v0, m/s.
    pub v0: f64,
}

impl std::fmt::Display for DataLooks {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let sig = |v: f64| significant(v, 3);
        write!(
            f,
            "the data run over t = {} … {} s with frames {} s apart and speeds up to {} m/s",
            sig(self.t.0),
            sig(self.t.1),
            sig(self.frame),
            sig(self.fastest)
        )?;
        if let Some((x0, x1)) = self.positions {
            write!(f, ", positions {} … {} m", sig(x0), sig(x1))?;
        }
        write!(
            f,
            ", and the scene's v0 is {} m/s (a lab's frames are ms apart and its balls roll at about 0.1 to 2 m/s); if the file's numbers are in other units, say so with --time-unit (e.g. ms), --speed-unit (e.g. cm/s) or --length-unit (e.g. cm), or with units in its header",
            sig(self.v0)
        )
    }
}

/// The most work one fit (`fit_all`: the model fit and every candidate model) may
/// take, in motion segments computed over all its model evaluations: a model
/// evaluation solves the motion and walks the data through its segments, so its
/// cost grows with them. A lab scene's motion has tens of segments and a whole fit
/// takes a few thousand evaluations (under a million segments); near b = 2R a run
/// has up to the engine's 15 000 segments and the same fit took minutes. The budget
/// is about ten times the most a paper series' fit takes (`paper-b4.9`: 0.54 million
/// in 10 800 evaluations; a 120 frames/s track about 0.06 million in 2 000).
pub const WORK_BUDGET: u64 = 5_000_000;

/// Counts model evaluations and the work they took, for [`Progress`] and the work
/// budget; stops the fit when asked or when the budget is spent. The fit hands it on
/// as `&mut`: each motion solved is counted where it is solved.
pub(super) struct Evals<'a> {
    progress: &'a dyn Progress,
    /// Model evaluations (motions solved) so far.
    done: u64,
    /// Their motion segments so far, and the most of one.
    segments: u64,
    longest: usize,
    budget: u64,
}

impl<'a> Evals<'a> {
    pub(super) fn new(progress: &'a dyn Progress) -> Evals<'a> {
        Evals::with_budget(progress, WORK_BUDGET)
    }

    /// With a work budget of `budget` motion segments.
    pub(super) fn with_budget(progress: &'a dyn Progress, budget: u64) -> Evals<'a> {
        Evals {
            progress,
            done: 0,
            segments: 0,
            longest: 0,
            budget,
        }
    }

    /// The motion of `scene` from `t_start` on, counted as one model evaluation.
    pub(super) fn solve(&mut self, scene: &Scene, t_start: f64) -> Solution {
        let sol = engine::solve(
            scene,
            &Span {
                t_start,
                t_end: None,
            },
        );
        let n = sol.segments.len();
        self.done += 1;
        self.segments += n as u64;
        self.longest = self.longest.max(n);
        sol
    }

    /// Before each step of a search: stops when asked or when the budget is spent.
    pub(super) fn next(&self) -> Result<(), FitError> {
        self.progress.tick(self.done, 0);
        if self.progress.cancelled() {
            Err(FitError::Cancelled)
        } else if self.segments > self.budget {
            Err(FitError::Budget {
                evaluations: self.done,
                segments: self.segments,
                longest: self.longest,
            })
        } else {
            Ok(())
        }
    }
}

/// The largest μ_k a ball rolling in a groove may plausibly have: beyond it the fit
/// says the data's units are likely wrong (`Agreement::ImplausibleMu`), and a μ_k
/// whose ± 2σ spans 0 to it is not determined (`uncertainty::uncertainties`).
pub const MAX_PLAUSIBLE_MU: f64 = 1.0;

/// The least μ_k a ball sliding in a groove may plausibly have: the slipperiest
/// solids slide at 0.04 (PTFE on steel), so a μ_k whose ± 2σ lies wholly below this
/// says the data's units are likely wrong (speeds in m/s under a cm/s header make
/// every deceleration, and μ_k, 100× too small: 0.0017 for 0.17).
pub const MIN_PLAUSIBLE_MU: f64 = 0.01;

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
        (self.key().param().get)(scene, &Span::default()).unwrap_or(f64::NAN)
    }

    /// The name on the command line and in JSON.
    pub fn name(self) -> &'static str {
        self.key().param().name
    }

    /// Its row of the scene parameter table, which gives its name, symbol, label,
    /// unit and physical range (a fitted value is a scene parameter set free).
    pub fn key(self) -> Key {
        match self {
            Free::Mu => Key::Mu,
            Free::V0 => Key::V0,
            Free::Restitution => Key::Restitution,
            Free::RollingResistance => Key::RollingResistance,
        }
    }
}
