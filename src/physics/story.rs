//! What the exact run does, as values for every front end to tell: the left ball's
//! recovery after the first impact by the closed forms only where the run bears them
//! out (it rolls again, or rests, at t' before anything else happens), else by the
//! run's own events; the regime's verdict with its margin against a data set's rest
//! band; a spin left at the end; where the numbers are less exact than rounding. The
//! words are `study::story`'s (the CLI table, the app's Why panel and the fit's verdict
//! print them).

use crate::physics::derived::{Derived, Outcome, Recovery, Regime};
use crate::physics::model::Phase;
use crate::physics::solution::{EventKind, Solution, Who};

/// The left ball after the first impact.
#[derive(Clone, Debug, PartialEq)]
pub enum After {
    /// It rolls again (or rests) at t' before any other event of the pair: the
    /// closed forms (t', v', x', t_r, t_t) describe the run.
    Recovers(Recovery),
    /// Something comes first (the next impact, a push): the run's own events, with
    /// the closed form's t' it never reaches.
    Interrupted(Interruption),
}

/// What happens instead of the closed-form recovery.
#[derive(Clone, Debug, PartialEq)]
pub struct Interruption {
    /// The closed form's t', which the run does not reach sliding freely.
    pub t_roll_closed_form: f64,
    /// What ends the free slide, and when: the next impact or the start of a push.
    pub first: (EventKind, f64),
    /// Accumulation point of the impacts, and whether the pair then rests there.
    pub accumulation: Option<(f64, bool)>,
    /// Both balls at rest from this time on, and whether they were pressed together
    /// until then.
    pub rest_from: Option<(f64, bool)>,
    /// The left ball rolls on at this speed from this time (when it ends rolling).
    pub rolls_on: Option<(f64, f64)>,
}

/// How the run goes on after the first impact; `None` without an impact or friction.
pub fn after_first_impact(sol: &Solution, derived: &Derived) -> Option<After> {
    let rec = derived.left_after_impact?;
    let left = |who: Who| who != Who::Right;
    // The first thing after the impact that ends the left ball's free slide.
    let first = sol.events.iter().find(|e| {
        e.t > 0.0
            && match e.kind {
                EventKind::Rolling | EventKind::Rest => left(e.ball),
                EventKind::Collision | EventKind::ContactStart => true,
                EventKind::ZenoRest | EventKind::ZenoContact => true,
                _ => false,
            }
    })?;
    let matches_t_roll = (first.t - rec.t_roll).abs() <= 1e-9 * (1.0 + rec.t_roll);
    if matches!(first.kind, EventKind::Rolling | EventKind::Rest) && matches_t_roll {
        return Some(After::Recovers(rec));
    }
    let accumulation = sol.accumulation.map(|t| {
        let rests = sol
            .events
            .iter()
            .any(|e| e.kind == EventKind::ZenoRest && (e.t - t).abs() <= 1e-9 * (1.0 + t));
        (t, rests)
    });
    let last = sol.segments.last()?;
    let rest_from = (last.phase == [Phase::Resting, Phase::Resting]).then(|| {
        let pressed = sol
            .segments
            .iter()
            .rev()
            .nth(1)
            .is_some_and(|s| s.contact_force > 0.0);
        (last.t0, pressed)
    });
    let rolls_on = (last.phase[0] == Phase::Rolling && last.start[0].v != 0.0)
        .then_some((last.t0, last.start[0].v));
    Some(After::Interrupted(Interruption {
        t_roll_closed_form: rec.t_roll,
        first: (first.kind, first.t),
        accumulation,
        rest_from,
        rolls_on,
    }))
}

/// The regime of the first impact with its margin: the left ball's v' (when the closed
/// form gives one), and against a data set's rest band (speeds within ± `band` of zero
/// cannot be told from rest).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Verdict {
    pub regime: Regime,
    /// The left ball's rolling speed after the impact, positive back toward the other.
    pub v_roll: Option<f64>,
    pub band: Option<f64>,
    /// Whether the balls meet at all: without an impact the criterion has nothing to
    /// judge (its "rest" then means only "no closing speed").
    pub impact: bool,
}

impl Verdict {
    /// The verdict on the run `sol` of a scene with `derived` values; v' only where
    /// the run really rolls again at t' ([`after_first_impact`]).
    pub fn of(sol: &Solution, derived: &Derived, band: Option<f64>) -> Verdict {
        let v_roll = match after_first_impact(sol, derived) {
            Some(After::Recovers(r)) => Some(r.v_roll),
            _ => None,
        };
        Verdict {
            regime: derived.regime,
            v_roll,
            band,
            impact: sol.events.iter().any(|e| e.kind == EventKind::Collision),
        }
    }

    /// True when v' lies inside the rest band: the data cannot tell it from rest.
    pub fn indistinguishable_from_rest(&self) -> bool {
        match (self.v_roll, self.band) {
            (Some(v), Some(b)) => self.regime != Regime::Rest && v.abs() <= b,
            _ => false,
        }
    }

    /// Whether an observed regime agrees with this prediction: the same, or rest seen
    /// where the prediction cannot be told from rest.
    pub fn agrees_with(&self, observed: Regime) -> bool {
        observed == self.regime || (observed == Regime::Rest && self.indistinguishable_from_rest())
    }
}

/// The rotational energy (J) the balls keep when their centres stop but a ball still
/// spins (without friction nothing couples spin to translation), else `None`.
pub fn spin_kept(sol: &Solution) -> Option<f64> {
    (Outcome::of(sol) == Outcome::Rest && spins_at_the_end(sol))
        .then(|| sol.energy_at(sol.t_end).rotational)
}

/// True when a ball still spins at the end of the run: its rim speed beyond a
/// millionth of the approach speed (rounding, not motion, below that).
fn spins_at_the_end(sol: &Solution) -> bool {
    let end = sol.at(sol.t_end);
    let scale = sol.scene.left.v0.abs() + sol.scene.right.v0.abs();
    end.left.u.abs().max(end.right.u.abs()) > 1e-6 * scale
}

/// Where the run's numbers are less exact than rounding.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Imprecision {
    /// b within `gap`·2R of 2R: k carries the width's rounding, `k_error` relative.
    WidthRounding { gap: f64, k: f64, k_error: f64 },
    /// The impacts after `from` (s) summed to their limit after `cycles` cycles of
    /// ratio `ratio`.
    SummedTail {
        from: f64,
        cycles: usize,
        ratio: f64,
    },
    /// `impacts` impacts from `from` to `to` (s) summed after `cycles` cycles of ratio
    /// `ratio`, up to shortly before rolling resistance stops a ball.
    PartialTail {
        impacts: usize,
        from: f64,
        to: f64,
        cycles: usize,
        ratio: f64,
    },
}

/// Where the run's numbers are less exact than rounding (empty when they are exact to
/// rounding): a width so close to 2R that k itself carries the width's rounding, and an
/// impact series whose tail was summed after the cycle budget.
pub fn imprecisions(sol: &Solution) -> Vec<Imprecision> {
    let mut out = Vec::new();
    let sc = &sol.scene;
    // k² = (1 − h)(1 + h) with h = b/2R: h carries half an ulp of rounding, so
    // 1 − h, and with it k², is known to ~1.1e-16 / (1 − h) relative.
    let gap = 1.0 - sc.width / (2.0 * sc.radius);
    let k_error = 0.5 * f64::EPSILON / gap;
    if k_error >= 1e-10 {
        out.push(Imprecision::WidthRounding {
            gap,
            k: sc.k(),
            k_error,
        });
    }
    for series in sol.series.iter().filter(|s| s.by_budget) {
        let (from, cycles, ratio) = (series.from, series.cycles, series.ratio);
        out.push(match series.impacts {
            None => Imprecision::SummedTail {
                from,
                cycles,
                ratio,
            },
            Some(impacts) => Imprecision::PartialTail {
                impacts,
                from,
                to: series.to,
                cycles,
                ratio,
            },
        });
    }
    out
}
