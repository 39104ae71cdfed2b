//! The candidate models compared by AIC and BIC, the one the data support marked,
//! and the values some models leave undetermined.

use std::fmt::Write as _;

use super::table::{pm, symbol};
use crate::settings::units::Dimension;
use crate::study::fit::{self, Candidate};

/// The candidate models compared by AIC and BIC, and the one the data support.
pub(super) fn table(models: &[Candidate], positions: bool) -> String {
    let mut out = String::new();
    let _ = writeln!(
        out,
        "\nwhich model the data support (fitted to the {}; AIC and BIC, lower is better, listed by BIC, lowest first; the simplest model within 2 of the lowest BIC whose values are all determined is named, not weighing a model whose added values predict a regime other than the one seen, or give a rolling resistance over its μ_k):",
        if positions { "positions" } else { "velocities" }
    );
    // What AIC and BIC count as n: the points the residuals are worth.
    if let Some(c) = models.first() {
        let _ = if c.effective_points < c.residuals as f64 {
            writeln!(
                out,
                "  (the {} residuals count as {:.0} independent points: neighbouring frames' errors are correlated)",
                c.residuals, c.effective_points
            )
        } else {
            writeln!(
                out,
                "  (the {} residuals count as independent points: neighbouring frames' errors are not correlated)",
                c.residuals
            )
        };
    }
    let unit = if positions {
        Dimension::Length.small_unit().0
    } else {
        Dimension::Speed.display_unit().0
    };
    let _ = writeln!(
        out,
        "  {:<34} {:>10} {:>10} {:>10}   values (± 2σ)",
        "model",
        format!("RMS {unit}"),
        "AIC",
        "BIC"
    );
    let names = |c: &Candidate| {
        c.parameters
            .iter()
            .map(|e| symbol(e.parameter).0)
            .collect::<Vec<_>>()
            .join(" + ")
    };
    for c in models {
        let values: Vec<String> = c
            .parameters
            .iter()
            .map(|e| {
                let (name, unit) = symbol(e.parameter);
                match (&e.not_determined, e.se) {
                    (Some(_), _) => format!("{name} not determined"),
                    (None, Some(se)) => {
                        format!("{name} {}{unit}", pm(e.value, 2.0 * se))
                    }
                    (None, None) => format!("{name} {:.4}{unit}", e.value),
                }
            })
            .collect();
        let rms = if positions {
            Dimension::Length.to_small(c.rms)
        } else {
            c.rms
        };
        let _ = writeln!(
            out,
            "{} {:<34} {:>10.4} {:>10.1} {:>10.1}   {}",
            if c.supported { "*" } else { " " },
            names(c),
            rms,
            c.aic,
            c.bic,
            values.join(", ")
        );
    }
    out += &undetermined_notes(models, &names);
    out += &named(models, &names);
    out
}

/// Below the models table: the model named (or why none is), and each model left
/// unweighed for its verdict (`Candidate::weighed`).
fn named(models: &[Candidate], names: &dyn Fn(&Candidate) -> String) -> String {
    let mut out = String::new();
    let unweighed: Vec<&Candidate> = models.iter().filter(|c| !c.weighed).collect();
    let of_weighed = if unweighed.is_empty() { "" } else { " weighed" };
    match models.iter().find(|c| c.supported) {
        Some(c) => {
            let _ = writeln!(
                out,
                "  the data support: {} (marked *); a larger model{of_weighed} does not lower the BIC by 2 or more",
                names(c),
            );
        }
        None if !models.is_empty() => {
            let best = models
                .iter()
                .filter(|c| c.weighed)
                .min_by(|a, b| a.bic.total_cmp(&b.bic))
                .unwrap_or(&models[0]);
            let _ = writeln!(
                out,
                "  no model is named: the lowest BIC of those{of_weighed} is {}'s, and no{of_weighed} model within 2 of it has every value determined",
                names(best)
            );
        }
        None => {}
    }
    for o in unweighed {
        let _ = match fit::rolls_harder_than_it_slides(o) {
            Some((c_rr, mu)) => writeln!(
                out,
                "  {} is not weighed: its rolling resistance c_rr = {c_rr:.4} exceeds its μ_k = {mu:.4}, and a ball resisted more than friction can hold it rolling slides instead: the data's slowing is not rolling resistance (check the tracks), and a smaller model inside it is determined (its BIC {:.1})",
                names(o),
                o.bic
            ),
            None => writeln!(
                out,
                "  {} is not weighed: it predicts {} where the data show {} after its sliding phase, and a smaller model inside it agrees with the data (its BIC {:.1})",
                names(o),
                o.fit.regime_predicted.name(),
                o.fit.observed_name(),
                o.bic
            ),
        };
    }
    out
}

/// Below the models table: each value some model leaves undetermined, in which models
/// and why; such a model is never the one named.
fn undetermined_notes(models: &[Candidate], names: &dyn Fn(&Candidate) -> String) -> String {
    let mut out = String::new();
    // (parameter, reason) → the models where it is so, in table order.
    let mut seen: Vec<(&fit::NotIdentified, Vec<String>)> = Vec::new();
    for c in models {
        for n in c
            .parameters
            .iter()
            .filter_map(|e| e.not_determined.as_ref())
        {
            match seen
                .iter_mut()
                .find(|(m, _)| m.parameter == n.parameter && m.reason == n.reason)
            {
                Some((_, list)) => list.push(names(c)),
                None => seen.push((n, vec![names(c)])),
            }
        }
    }
    for (n, list) in &seen {
        let name = symbol(n.parameter).0;
        let models = list.join("; ");
        let _ = match n.on_edge_of {
            // μ_k is in every model: on its edge, those models do not fit the data.
            Some(range) if n.parameter == "mu" => writeln!(
                out,
                "  {name} lies on the edge of its physical range ({range}) in {models}: not determined, those models do not fit these data"
            ),
            Some(range) => writeln!(
                out,
                "  {name} lies on the edge of its physical range ({range}) in {models}: the data do not support {name} as a free value"
            ),
            None => writeln!(out, "  {name} not determined in {models}: {}", n.reason),
        };
    }
    if !seen.is_empty() {
        let _ = writeln!(
            out,
            "  (a model with a value the data do not determine is never the one named)"
        );
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::physics::derived::Regime;

    /// A determined candidate of `free` values at `bic`, its predicted regime
    /// `predicted` where the data show them at rest.
    fn candidate(free: &[&'static str], bic: f64, predicted: Regime) -> Candidate {
        let values: Vec<(&'static str, bool)> = free.iter().map(|&p| (p, true)).collect();
        let mut c = fit::blank_candidate(&values, bic);
        c.fit.regime_predicted = predicted;
        c.fit.regime_observed = Regime::Rest;
        c.fit.agrees = predicted == Regime::Rest;
        c
    }

    /// `models` weighed and the one supported marked, as `fit` marks them.
    fn chosen(mut models: Vec<Candidate>) -> Vec<Candidate> {
        fit::mark(&mut models, &|_| true);
        models
    }

    fn names(c: &Candidate) -> String {
        c.name.clone()
    }

    #[test]
    fn a_model_left_out_for_its_regime_is_named_below_the_table() {
        // Small look 130's table: μ_k + v0 + e 9.8 lower in BIC, predicting a
        // recollision where the balls were seen to stop, μ_k + v0 inside it agreeing.
        let models = chosen(vec![
            candidate(&["mu", "v0", "restitution"], 98.0, Regime::Recollide),
            candidate(&["mu", "v0"], 107.8, Regime::Rest),
        ]);
        let out = named(&models, &names);
        assert!(
            out.contains("the data support: mu+v0 (marked *); a larger model weighed does not lower the BIC by 2 or more"),
            "{out}"
        );
        assert!(
            out.contains("mu+v0+restitution is not weighed: it predicts recollide where the data show rest after its sliding phase, and a smaller model inside it agrees with the data (its BIC 98.0)"),
            "{out}"
        );
        // Where the smaller one disagrees, nothing is left out and the BIC decides:
        // the larger, agreeing, is named; or, within 2, the smaller, disagreeing.
        for (bic, named_one) in [(98.0, "mu+v0+restitution"), (106.0, "mu+v0")] {
            let models = chosen(vec![
                candidate(&["mu", "v0", "restitution"], bic, Regime::Rest),
                candidate(&["mu", "v0"], 107.8, Regime::Recollide),
            ]);
            let out = named(&models, &names);
            assert!(!out.contains("not weighed"), "{out}");
            assert!(
                out.contains(&format!(
                    "the data support: {named_one} (marked *); a larger model does not lower"
                )),
                "{out}"
            );
        }
    }

    #[test]
    fn a_model_left_out_for_rolling_harder_than_it_slides_says_so() {
        // Small look 11's first 30 frames: c_rr 0.116 beside μ_k 0.062.
        let mut resisted = candidate(&["mu", "v0", "rolling_resistance"], 90.8, Regime::Rest);
        for (e, v) in resisted.parameters.iter_mut().zip([0.062, 0.56, 0.116]) {
            e.value = v;
        }
        let models = chosen(vec![
            resisted,
            candidate(&["mu", "v0"], 120.0, Regime::Recollide),
        ]);
        let out = named(&models, &names);
        assert!(out.contains("the data support: mu+v0 (marked *)"), "{out}");
        assert!(
            out.contains("mu+v0+rolling_resistance is not weighed: its rolling resistance c_rr = 0.1160 exceeds its μ_k = 0.0620, and a ball resisted more than friction can hold it rolling slides instead"),
            "{out}"
        );
        assert!(out.contains("(its BIC 90.8)"), "{out}");
    }
}
