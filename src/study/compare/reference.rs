//! What a comparison's runs are measured against: the exact solution over the
//! stretch compared, solved once, with the outcome and impacts a run should find and
//! the state every run starts from.

use crate::methods::{self, Model, Run, Stepping, Y};
use crate::physics::derived::{Outcome, Summary};
use crate::physics::engine::NEGLIGIBLE_SPEED;
use crate::physics::model::Phase;
use crate::physics::scene::{Scene, Span};
use crate::physics::solution::{Event, EventKind, Solution, Who};

/// The finest fixed step of the default sweep, s.
pub const FINEST_STEP: f64 = 1e-6;

/// Most steps one run of a comparison takes: the finest step over [`WINDOW`]. A
/// smaller `max_steps` in the settings skips (as `stalled`, saying so) the levels
/// that would need more.
pub const STEP_BUDGET: usize = 2_000_000;

/// The most simulated time a comparison covers, s: [`STEP_BUDGET`] steps of
/// [`FINEST_STEP`]. A longer span (`--mu 1e-6` reaches 147,000 s, a 10 kg right ball
/// 2.25 s, `paper-b4.4` 2.8 s) is compared over its first 2 s only, every row saying
/// so: a comparison's work then grows with the span up to 2 s and no further, at most
/// about 1.6 times the default scene's (`paper-b4.9`, 1.28 s), whatever the scene.
pub const WINDOW: f64 = STEP_BUDGET as f64 * FINEST_STEP;

/// What a comparison's runs are measured against: the exact solution over the stretch
/// compared (the span, or its first [`WINDOW`] seconds where the span is longer), and
/// the outcome and impacts a run should find there.
#[derive(Clone, Debug)]
pub struct Reference {
    pub exact: Solution,
    /// Where the step budget cut the span (s), if it did.
    pub cut: Option<f64>,
    pub outcome: Outcome,
    pub impacts: usize,
    /// Whether the exact impacts accumulate within the stretch (infinitely many: the
    /// outcome word alone decides whether a run gets it right).
    pub accumulating: bool,
}

impl Reference {
    /// The state every run starts from: the exact run-up's at the stretch's start,
    /// as [`methods::start_state`] would solve it again.
    pub fn start(&self) -> Y {
        methods::state(self.exact.at(self.exact.t_start))
    }

    /// A run of `model` over the stretch compared, from [`Reference::start`], stepped
    /// as `settings` say.
    pub fn run<'a>(&self, model: &'a Model, settings: &'a Stepping) -> Run<'a> {
        Run {
            model,
            y0: self.start(),
            t0: self.exact.t_start,
            t1: self.exact.t_end,
            stepping: settings,
        }
    }

    /// The exact run of `scene` over `span`, cut at [`WINDOW`] after its start.
    pub fn new(scene: &Scene, span: &Span) -> Reference {
        let whole = methods::exact_solution(scene, span);
        let end = whole.t_start + WINDOW;
        if whole.t_end <= end {
            let summary = Summary::of(&whole);
            return Reference {
                cut: None,
                outcome: summary.outcome,
                impacts: summary.impacts,
                accumulating: whole.accumulation.is_some(),
                exact: whole,
            };
        }
        let exact = methods::exact_solution(
            scene,
            &Span {
                t_start: whole.t_start,
                t_end: Some(end),
            },
        );
        let (outcome, impacts) = outcome_until(&exact, end);
        Reference {
            cut: Some(end),
            outcome,
            impacts,
            accumulating: exact.accumulation.is_some_and(|t| t <= end),
            exact,
        }
    }
}

/// What the exact run does up to `end` (a cut comparison's runs see no further), and
/// its impacts there: the rule of [`Outcome::of`] applied to the events up to `end`,
/// with the relative velocity in the first stretch after the impact where neither
/// ball slides, else at `end`.
pub fn outcome_until(sol: &Solution, end: f64) -> (Outcome, usize) {
    let eps = NEGLIGIBLE_SPEED * sol.scene.speed_scale();
    let shown = |e: &&Event| e.t >= sol.t_start && e.t <= end;
    let impacts = sol
        .events
        .iter()
        .filter(shown)
        .filter(|e| e.kind == EventKind::Collision)
        .count();
    let pressed = sol
        .events
        .iter()
        .filter(shown)
        .any(|e| e.kind == EventKind::ContactStart);
    let settled = sol
        .segments
        .iter()
        .find(|s| {
            s.t0 >= 0.0
                && s.t0 <= end
                && s.phase
                    .iter()
                    .all(|p| matches!(p, Phase::Rolling | Phase::Resting))
        })
        .map_or_else(
            || {
                let s = sol.at(end);
                [s.left, s.right]
            },
            |s| s.start,
        );
    let [l, r] = settled;
    let accumulating = sol.accumulation.is_some_and(|t| t <= end);
    let moving = l.v.abs() > eps || r.v.abs() > eps;
    let resisted = sol.scene.rolling_resistance > 0.0;
    let facts = (impacts, accumulating, pressed);
    let outcome = Outcome::classify(facts, r.v - l.v, moving, resisted, eps);
    (outcome, impacts)
}

/// The exact engine's first rolling (or rest) time of the left ball after the impact.
pub(super) fn exact_roll(sol: &Solution) -> Option<f64> {
    sol.events
        .iter()
        .find(|e| {
            e.t > 0.0
                && e.ball == Who::Left
                && matches!(e.kind, EventKind::Rolling | EventKind::Rest)
        })
        .map(|e| e.t)
}

/// The times of the exact run's impacts (collisions and accumulation points).
pub(super) fn impact_times(exact: &Solution) -> Vec<f64> {
    exact
        .events
        .iter()
        .filter(|e| {
            matches!(
                e.kind,
                EventKind::Collision | EventKind::ZenoRest | EventKind::ZenoContact
            )
        })
        .map(|e| e.t)
        .collect()
}
