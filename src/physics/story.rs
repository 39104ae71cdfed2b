//! What the exact run does, in words, for every front end: the left ball's recovery
//! after the first impact told by the closed forms only where the run bears them out
//! (it rolls again, or rests, at t' before anything else happens), else told by the
//! run's own events; and the regime's verdict with its margin against a data set's
//! rest band. The CLI table and the app's Why panel both print these.

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

impl Interruption {
    /// The story in short clauses, for a line each or joined with "; ". `infinity` is
    /// the glyph for ∞ (the app's ASCII mode has its own).
    pub fn clauses(&self, infinity: &str) -> Vec<String> {
        let mut out = Vec::new();
        let (kind, t) = self.first;
        // The closed form assumes a free slide to t'; say where the run leaves it.
        let t_closed = self.t_roll_closed_form;
        let before = if t < t_closed {
            format!("before the closed form's t' = {t_closed:.4} s")
        } else {
            format!("not at the closed form's t' = {t_closed:.4} s")
        };
        out.push(match kind {
            EventKind::ContactStart => {
                format!("pressed against the other ball from t = {t:.4} s, {before}")
            }
            EventKind::ZenoRest | EventKind::ZenoContact => {
                format!("impacts accumulate at T{infinity} = {t:.4} s, {before}")
            }
            EventKind::Collision => {
                format!("slides into the next impact at t = {t:.4} s, {before}")
            }
            EventKind::Rest => format!("comes to rest at t = {t:.4} s, {before}"),
            _ => format!("rolls again at t = {t:.4} s, {before}"),
        });
        if let Some((t, rests)) = self.accumulation
            && !matches!(kind, EventKind::ZenoRest | EventKind::ZenoContact)
        {
            out.push(format!(
                "impacts accumulate at T{infinity} = {t:.4} s{}",
                if rests { ": at rest in contact" } else { "" }
            ));
        }
        match (self.rest_from, self.rolls_on) {
            (Some((t, true)), _) => out.push(format!("pressed together, at rest from {t:.4} s")),
            (Some((t, false)), _) => out.push(format!("both at rest from {t:.4} s")),
            (None, Some((t, v))) => out.push(format!("rolls on at {v:+.4} m/s from {t:.4} s")),
            (None, None) => {}
        }
        out
    }
}

/// The Why panel's heading: what the run does ([`Outcome`], its word first, the same
/// as `summary.outcome`). The paper's criterion ([`Derived::regime`]) says what the
/// balls do once each rolls on its own; where the run does otherwise (rolling
/// resistance stops them before they meet again, friction presses them together),
/// [`criterion_note`] says so beside it.
pub fn headline(sol: &Solution, derived: &Derived) -> String {
    let outcome = Outcome::of(sol);
    format!(
        "{}: {}",
        outcome.name().to_uppercase(),
        outcome_says(outcome, sol, derived)
    )
}

/// What an outcome means, in a few words: "the balls roll apart".
pub fn outcome_says(outcome: Outcome, sol: &Solution, derived: &Derived) -> String {
    // Without friction (μ_k = 0) nothing couples spin to translation: the centres
    // stop, the balls do not, and their spin keeps its energy.
    if outcome == Outcome::Rest && spins_at_the_end(sol) {
        return format!(
            "the balls stop moving along the groove; they keep spinning ({})",
            joules(sol.energy_at(sol.t_end).rotational)
        );
    }
    match outcome {
        // Without friction nothing rolls: they slide apart.
        Outcome::Depart if derived.left_after_impact.is_none() => "the balls move apart",
        Outcome::Depart => "the balls roll apart",
        Outcome::Together => "the pair moves on as one",
        Outcome::Pressed => "friction holds them together",
        Outcome::Stopped => "they stop before they meet again",
        Outcome::Recollide => "they come back",
        Outcome::Rest => "the balls stop",
    }
    .to_string()
}

/// An energy in J with two decimals, in mJ below 0.01 J (a small scene's spin).
fn joules(e: f64) -> String {
    if e.abs() >= 0.01 {
        format!("{e:.2} J")
    } else {
        format!("{:.2} mJ", 1e3 * e)
    }
}

/// True when a ball still spins at the end of the run: its rim speed beyond a
/// millionth of the approach speed (rounding, not motion, below that).
fn spins_at_the_end(sol: &Solution) -> bool {
    let end = sol.at(sol.t_end);
    let scale = sol.scene.left.v0.abs() + sol.scene.right.v0.abs();
    end.left.u.abs().max(end.right.u.abs()) > 1e-6 * scale
}

/// "the paper's criterion says recollide" where the run does otherwise, else `None`.
pub fn criterion_note(sol: &Solution, derived: &Derived) -> Option<String> {
    let outcome = Outcome::of(sol);
    (!outcome.agrees_with(derived.regime))
        .then(|| format!("the paper's criterion says {}", derived.regime.name()))
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

    /// The margin in words: "v' = +0.028 m/s, within the data's ±0.042 m/s rest band:
    /// indistinguishable from rest" (empty without a v'). `pm` is the glyph for ±.
    pub fn margin(&self, pm: &str) -> String {
        let Some(v) = self.v_roll else {
            return String::new();
        };
        let mut s = format!("v' = {v:+.3} m/s");
        if let Some(b) = self.band {
            if self.indistinguishable_from_rest() {
                s += &format!(
                    ", within the data's {pm}{b:.3} m/s rest band: indistinguishable from rest"
                );
            } else if self.regime != Regime::Rest {
                s += &format!(", outside the data's {pm}{b:.3} m/s rest band");
            }
        }
        s
    }

    /// "recollide (v' = +0.028 m/s, within …: indistinguishable from rest)".
    pub fn text(&self, pm: &str) -> String {
        if !self.impact {
            return "no impact: the balls never meet".to_string();
        }
        let margin = self.margin(pm);
        if margin.is_empty() {
            self.regime.name().to_string()
        } else {
            format!("{} ({margin})", self.regime.name())
        }
    }

    /// Whether an observed regime agrees with this prediction: the same, or rest seen
    /// where the prediction cannot be told from rest.
    pub fn agrees_with(&self, observed: Regime) -> bool {
        observed == self.regime || (observed == Regime::Rest && self.indistinguishable_from_rest())
    }
}

/// Where the run's numbers are less exact than rounding, in words (empty when they are
/// exact to rounding): a width so close to 2R that k itself carries the width's
/// rounding, and an impact series whose tail was summed after the cycle budget.
pub fn precision_notes(sol: &Solution) -> Vec<String> {
    let mut out = Vec::new();
    let sc = &sol.scene;
    // k² = (1 − h)(1 + h) with h = b/2R: h carries half an ulp of rounding, so
    // 1 − h, and with it k², is known to ~1.1e-16 / (1 − h) relative.
    let gap = 1.0 - sc.width / (2.0 * sc.radius);
    let k_error = 0.5 * f64::EPSILON / gap;
    if k_error >= 1e-10 {
        out.push(format!(
            "b is within {gap:.1e}·2R of 2R: k = {:.3e} carries the width's rounding (~{k_error:.0e} relative), and so do t', T∞ and the forces",
            sc.k()
        ));
    }
    for series in sol.series.iter().filter(|s| s.by_budget) {
        let amplified = 1.0 / (1.0 - series.ratio);
        out.push(match series.impacts {
            None => format!(
                "impacts after t = {:.4} s are summed, not resolved ({} cycles of ratio ρ = {:.6}): up to T∞ the run shows their cycle average, not each bounce; the summed limit carries rounding × 1/(1 − ρ) ≈ {amplified:.1e}",
                series.from, series.cycles, series.ratio
            ),
            Some(n) => format!(
                "{n} impacts from t = {:.4} s to {:.4} s are summed, not resolved (after {} cycles of ratio ρ = {:.6}, up to shortly before rolling resistance stops a ball): there the run shows their cycle average, not each bounce; the summed state carries rounding × 1/(1 − ρ) ≈ {amplified:.1e}",
                series.from, series.to, series.cycles, series.ratio
            ),
        });
    }
    out
}
