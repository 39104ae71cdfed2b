//! The candidate models compared by AIC and BIC, the one the data support marked,
//! and the values some models leave undetermined.

use std::fmt::Write as _;

use super::table::{pm, symbol};
use crate::settings::units::Dimension;
use crate::study::fit::{self, BIC_MARGIN, Candidate};

/// The candidate models compared by AIC and BIC, and the one the data support.
pub(super) fn table(models: &[Candidate], positions: bool) -> String {
    let mut out = String::new();
    let _ = writeln!(
        out,
        "\nwhich model the data support (fitted to the {}; AIC and BIC, lower is better, listed by BIC, lowest first; the simplest model within 2 of the lowest BIC whose values are all determined is named, of those predicting the regime seen where one does):",
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

/// Below the models table: the model named (or why none is), and each model with a
/// lower BIC left unweighed for predicting a regime other than the one seen.
fn named(models: &[Candidate], names: &dyn Fn(&Candidate) -> String) -> String {
    let mut out = String::new();
    match models.iter().find(|c| c.supported) {
        Some(c) => {
            // Models left unweighed for predicting a regime other than the one seen.
            let unweighed: Vec<&Candidate> = models
                .iter()
                .filter(|o| o.bic < c.bic - BIC_MARGIN && !o.fit.agrees)
                .collect();
            let _ = writeln!(
                out,
                "  the data support: {} (marked *); a larger model{} does not lower the BIC by 2 or more",
                names(c),
                if unweighed.is_empty() {
                    ""
                } else {
                    " predicting the regime seen"
                }
            );
            for o in unweighed {
                let _ = writeln!(
                    out,
                    "  {} lowers the BIC by {:.1}, but the regime it predicts ({}) is not the one seen ({}): not weighed",
                    names(o),
                    c.bic - o.bic,
                    o.fit.regime_predicted.name(),
                    o.fit.regime_observed.name()
                );
            }
        }
        None if !models.is_empty() => {
            let best = models
                .iter()
                .min_by(|a, b| a.bic.total_cmp(&b.bic))
                .expect("not empty");
            let _ = writeln!(
                out,
                "  no model is named: the lowest BIC is {}'s, and no model within 2 of it has every value determined",
                names(best)
            );
        }
        None => {}
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
    /// `predicted` where the data show them at rest, supported or not.
    fn candidate(free: &[&'static str], bic: f64, predicted: Regime, supported: bool) -> Candidate {
        let mut fit = crate::study::fit::model::tests::blank();
        fit.regime_predicted = predicted;
        fit.regime_observed = Regime::Rest;
        fit.agrees = predicted == Regime::Rest;
        Candidate {
            name: free.join("+"),
            parameters: free
                .iter()
                .map(|&parameter| fit::Estimate {
                    parameter,
                    value: 0.5,
                    se: Some(0.01),
                    not_determined: None,
                })
                .collect(),
            rms: 0.001,
            points: 30,
            residuals: 30,
            effective_points: 24.0,
            aic: bic,
            bic,
            supported,
            free: Vec::new(),
            fit: Box::new(fit),
        }
    }

    fn names(c: &Candidate) -> String {
        c.name.clone()
    }

    #[test]
    fn a_model_left_out_for_its_regime_is_named_below_the_table() {
        // Small look 130's table: μ_k + v0 + e 9.8 lower in BIC, predicting a
        // recollision where the balls were seen to stop.
        let models = [
            candidate(&["mu", "v0", "restitution"], 98.0, Regime::Recollide, false),
            candidate(&["mu", "v0"], 107.8, Regime::Rest, true),
        ];
        let out = named(&models, &names);
        assert!(
            out.contains("the data support: mu+v0 (marked *); a larger model predicting the regime seen does not lower the BIC by 2 or more"),
            "{out}"
        );
        assert!(
            out.contains("mu+v0+restitution lowers the BIC by 9.8, but the regime it predicts (recollide) is not the one seen (rest): not weighed"),
            "{out}"
        );
        // Where the larger model agrees and is named, no model is left out.
        let models = [
            candidate(&["mu", "v0", "restitution"], 98.0, Regime::Rest, true),
            candidate(&["mu", "v0"], 107.8, Regime::Rest, false),
        ];
        let out = named(&models, &names);
        assert!(!out.contains("not weighed"), "{out}");
        assert!(out.contains("a larger model does not lower"), "{out}");
    }
}
