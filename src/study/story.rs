//! The story of a run in words, made from the values `physics::story` returns: the
//! left ball's recovery interrupted (clauses), the Why panel's heading and what an
//! outcome means, the paper's criterion where the run does otherwise, the regime's
//! verdict with its margin, and where the numbers are less exact than rounding. The
//! CLI table, the app's Why panel and the fit's verdict print these; the methods on
//! physics' types ([`Interruption::clauses`], [`Verdict::text`]) are defined here, with
//! the other words.

use crate::physics::derived::{Derived, Outcome, Regime};
use crate::physics::solution::{EventKind, Solution};
use crate::physics::story::{Imprecision, Interruption, Verdict, imprecisions, spin_kept};

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
    if outcome == Outcome::Rest
        && let Some(energy) = spin_kept(sol)
    {
        return format!(
            "the balls stop moving along the groove; they keep spinning ({})",
            joules(energy)
        );
    }
    // At rest from the start (v0 = 0 for both): nothing stops, nothing meets.
    if outcome == Outcome::Rest && sol.impacts == 0 {
        return "neither ball moves: no speed toward the other".to_string();
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
    use crate::settings::units::fixed;
    if e.abs() >= 0.01 {
        format!("{} J", fixed(e, 2))
    } else {
        format!("{} mJ", fixed(1e3 * e, 2))
    }
}

/// "the paper's criterion says recollide" where the run does otherwise, else `None`.
pub fn criterion_note(sol: &Solution, derived: &Derived) -> Option<String> {
    let outcome = Outcome::of(sol);
    (!outcome.agrees_with(derived.regime))
        .then(|| format!("the paper's criterion says {}", derived.regime.name()))
}

impl Verdict {
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
}

/// Where the run's numbers are less exact than rounding, in words (empty when they are
/// exact to rounding): see [`imprecisions`].
pub fn precision_notes(sol: &Solution) -> Vec<String> {
    imprecisions(sol).into_iter().map(imprecision).collect()
}

/// One [`Imprecision`] in words.
fn imprecision(note: Imprecision) -> String {
    match note {
        Imprecision::WidthRounding { gap, k, k_error } => format!(
            "b is within {gap:.1e}·2R of 2R: k = {k:.3e} carries the width's rounding (~{k_error:.0e} relative), and so do t', T∞ and the forces"
        ),
        Imprecision::SummedTail {
            from,
            cycles,
            ratio,
        } => {
            let amplified = 1.0 / (1.0 - ratio);
            format!(
                "impacts after t = {from:.4} s are summed, not resolved ({cycles} cycles of ratio ρ = {ratio:.6}): up to T∞ the run shows their cycle average, not each bounce; the summed limit carries rounding × 1/(1 − ρ) ≈ {amplified:.1e}"
            )
        }
        Imprecision::PartialTail {
            impacts,
            from,
            to,
            cycles,
            ratio,
        } => {
            let amplified = 1.0 / (1.0 - ratio);
            format!(
                "{impacts} impacts from t = {from:.4} s to {to:.4} s are summed, not resolved (after {cycles} cycles of ratio ρ = {ratio:.6}, up to shortly before rolling resistance stops a ball): there the run shows their cycle average, not each bounce; the summed state carries rounding × 1/(1 − ρ) ≈ {amplified:.1e}"
            )
        }
    }
}
