//! `fit`'s table: the summary first (the headline μ_k ± 2σ, its model and verdict,
//! then μ_k alone), the line fits, and the model fit's detail (of a track: fitted to
//! the velocities and to the positions side by side).

use std::fmt::Write as _;

use crate::physics::scene::Scene;
use crate::settings::units::{Dimension, show, show_small, significant, with_uncertainty};
use crate::study::fit::{self, Chosen, Fits, LineFit, MAX_PLAUSIBLE_MU, ModelFit};
use crate::study::measured::{Found, NoLineVt};

/// The short plain summary that opens the table: μ_k ± 2σ of the headline, its
/// model and why it is the one, and the verdict; then μ_k alone.
pub(super) fn summary(f: &Fits) -> String {
    let h = &f.model_fit;
    let model = model_name(&h.model);
    let supported = f.models.iter().find(|c| c.supported);
    let why = match (f.chosen, supported) {
        (Chosen::Supported, _) => "the model the data support".to_string(),
        (Chosen::Asked, Some(c)) if c.name == h.model => {
            "as --free asks; the data support it too".to_string()
        }
        (Chosen::Asked, Some(c)) => {
            format!("as --free asks; the data support {}", model_name(&c.name))
        }
        (Chosen::Asked, None) => "as --free asks; the data support no model".to_string(),
        (Chosen::Simplest, _) => "the simplest: the data support no model".to_string(),
    };
    let mu = match h.undetermined("mu") {
        Some(_) => "μ_k not determined".to_string(),
        None => format!("μ_k = {}", mu_text(h)),
    };
    let mut out = format!(
        "{mu}: {model} ({why}), fitted to the {}; {} ({})\n",
        h.fitted_to,
        h.agreement().word(),
        rms_text(h)
    );
    if h.mu_implausible {
        let _ = writeln!(out, "  {}", unit_hint(h.mu, h.fitted_to));
    } else if h.mu > 0.0 && h.mu + 2.0 * h.mu_se < SLIPPERIEST_MU {
        let _ = writeln!(
            out,
            "  μ_k under {SLIPPERIEST_MU} is less than the slipperiest solids slide at: if the {}",
            mix_up(h.mu, h.fitted_to)
                .replace(" are likely ", " are ")
                .replacen("): give", "), give", 1)
        );
    }
    if let Some(w) = f
        .line_fit
        .as_ref()
        .and_then(|l| l.width_from_lines.as_ref())
    {
        // The value and its ± to the same places (the ± rule: `with_uncertainty`).
        let length = Dimension::Length;
        let (b, pm) = crate::settings::units::with_uncertainty(
            length.to_display(w.width),
            length.to_display(2.0 * w.width_se),
            2,
        );
        let _ = writeln!(
            out,
            "  the measured a_t/a_cm gives b ≈ {b} ± {pm}{}, not {}: check --width",
            length.suffix(),
            show(w.given, length)
        );
    }
    // μ_k alone, with v0 free when the data measured it (not given).
    let alone = match f.mu_alone.model.as_str() {
        "mu" => "μ_k alone".to_string(),
        _ => "μ_k alone (with v0 fitted: the data measure it)".to_string(),
    };
    if h.model == f.mu_alone.model {
        let _ = writeln!(
            out,
            "  μ_k alone: the same fit{}",
            if f.mu_alone.model == "mu" {
                ""
            } else {
                " (v0 is fitted with μ_k wherever the data measure it)"
            }
        );
    } else {
        let a = &f.mu_alone;
        let _ = writeln!(
            out,
            "  {alone}: {}; {} ({})",
            match a.undetermined("mu") {
                Some(_) => "not determined".to_string(),
                None => mu_text(a),
            },
            a.agreement().word(),
            rms_text(a)
        );
    }
    out
}

/// What an implausible μ_k (beyond 1, or below 0.01) says of the data's unit: the
/// power of ten (10, 100, 1000) that brings it nearest a typical 0.17, and the unit
/// mix-up that makes it (mm read as cm: 10× too large; cm as m: 100×; mm as m:
/// 1000×; the other way round too small). The header's own unit is not known here,
/// so the mix-up is named, not assumed (a header saying cm over numbers in mm made
/// "give --length-unit cm" a loop).
fn unit_hint(mu: f64, fitted_to: &str) -> String {
    let words = if mu > MAX_PLAUSIBLE_MU {
        "a μ_k beyond 1 is no ball rolling in a groove"
    } else {
        "a μ_k below 0.01 is no ball sliding in a groove (the slipperiest solids slide at 0.04)"
    };
    format!("{words}: the {}", mix_up(mu, fitted_to))
}

/// What the slipperiest solids slide at (PTFE on steel): a μ_k under it, though
/// within what a fit gives a verdict on, is said beside the unit mix-up that would
/// make it (cm read as mm gave μ_k 0.017 that "agrees").
const SLIPPERIEST_MU: f64 = 0.04;

/// "lengths are likely 10× too small (cm read as mm? then μ_k ≈ 0.17): give
/// --length-unit cm, or fix the header": the mix-up that brings `mu` nearest 0.17.
fn mix_up(mu: f64, fitted_to: &str) -> String {
    let large = mu > MAX_PLAUSIBLE_MU;
    let off = |p: f64| (if large { mu / p } else { mu * p } / 0.17).ln().abs();
    let (power, meant, read) = crate::settings::units::MIX_UPS
        .into_iter()
        .min_by(|a, b| off(a.0).total_cmp(&off(b.0)))
        .unwrap_or((100.0, "cm", "m"));
    let (meant, read) = if large { (meant, read) } else { (read, meant) };
    let (what, per, flag) = match fitted_to {
        "positions" => ("lengths", "", "--length-unit"),
        _ => ("speeds", "/s", "--speed-unit"),
    };
    format!(
        "{what} are likely {}× too {} ({meant}{per} read as {read}{per}? then μ_k ≈ {}): give {flag} {meant}{per}, or fix the header",
        power as u32,
        if large { "large" } else { "small" },
        significant(if large { mu / power } else { mu * power }, 3)
    )
}

/// A fit's μ_k ± 2σ, or why it has none.
fn mu_text(m: &ModelFit) -> String {
    match m.undetermined("mu") {
        Some(n) => format!("not determined ({})", n.reason),
        None if m.mu_se.is_finite() => match &m.scale {
            // Both parts in the precision of the whole.
            Some(s) => {
                let part = |e: f64| pm(m.mu, 2.0 * e).split(" ± ").nth(1).map(str::to_string);
                format!(
                    "{} (± 2σ, 95 %: the fit's ± {} and the scale's ± {} ({:.2} %), in quadrature)",
                    pm(m.mu, 2.0 * m.mu_se),
                    part(s.mu_se_fit).unwrap_or_default(),
                    part(s.mu_se_scale).unwrap_or_default(),
                    100.0 * s.rel_se
                )
            }
            None => format!("{} (± 2σ, 95 %)", pm(m.mu, 2.0 * m.mu_se)),
        },
        None => format!("{:.4}", m.mu),
    }
}

/// "RMS 0.0172 m/s" or "RMS 0.241 mm", as the fit was made.
fn rms_text(m: &ModelFit) -> String {
    match m.fitted_to {
        "positions" => format!("RMS {:.3}", show_small(m.rms, Dimension::Length)),
        _ => format!("RMS {:.4} m/s", m.rms),
    }
}

/// A model's name for people: `mu+v0` → `μ_k + v0`.
pub(super) fn model_name(model: &str) -> String {
    model
        .split('+')
        .map(|p| symbol(p).0)
        .collect::<Vec<_>>()
        .join(" + ")
}

/// The line fits and the model fit; the paper's table-1 row beside them only for the
/// preset's own (the paper's) data, `paper_data`.
pub(super) fn table(scene: &Scene, f: &Fits, mass: Option<&str>, paper_data: bool) -> String {
    let mut out = String::new();
    line_fit_or_why(&mut out, scene, f, mass, paper_data);
    let _ = writeln!(out);
    model_fit_lines(&mut out, &f.model_fit);
    out
}

/// The line fits over their window (the sliding phase unless --from/--to set it), and
/// the paper's table-1 row with where it contradicts itself when `paper_data`; the
/// `mass` assumed, if it was, under them. Where the line fits cannot be made, why, on
/// their line: the model fits below need none.
fn line_fit_or_why(
    out: &mut String,
    scene: &Scene,
    f: &Fits,
    mass: Option<&str>,
    paper_data: bool,
) {
    match (&f.line_fit, &f.no_line_fit) {
        (Some(l), _) => line_fit_lines(out, scene, l, mass, paper_data),
        (None, why) => {
            let _ = writeln!(
                out,
                "line fit: not possible ({}); the model fits need none",
                why.as_ref().map_or_else(String::new, ToString::to_string)
            );
        }
    }
}

/// [`line_fit_or_why`] of line fits that were made.
fn line_fit_lines(
    out: &mut String,
    scene: &Scene,
    l: &LineFit,
    mass: Option<&str>,
    paper_data: bool,
) {
    // The window said as it was chosen: the sliding phase, or what --from/--to set;
    // its times from the impact (as --from and --to are), not the file's clock.
    let (over, hint) = match l.given {
        [false, false] => ("over the sliding phase", "; change with --from/--to"),
        [true, true] => ("over the window --from/--to set", ""),
        [true, false] => ("from --from to the end of the sliding phase", ""),
        [false, true] => ("from the start of the sliding phase to --to", ""),
    };
    let _ = writeln!(
        out,
        "line fits {over}, t = {:.3} … {:.3} s after the impact ({} frames{hint})",
        l.from, l.to, l.points
    );
    // A window reaching past the data is cut to them: said, not done quietly.
    for (flag, asked, end) in l.cut_to_data() {
        let (lies, data, window) = if flag == "from" {
            ("before", "start", "starts")
        } else {
            ("past", "end", "ends")
        };
        let _ = writeln!(
            out,
            "  (--{flag} {} s lies {lies} the data, which {data} at t = {end:.3} s: the window {window} there)",
            significant(asked, 4),
        );
    }
    let _ = writeln!(
        out,
        "{:<12} {:>14} {:>9} {:>11} {:>14} {:>9} {:>11}",
        "", "|a_cm| m/s²", "μ_k,cm", "|F_net| N", "|a_t| m/s²", "μ_k,t", "|τ_net| N m"
    );
    // Without a rim mark a_t and μ_k,t are not measured: said in words, never NaN.
    let (a_t, mu_t) = if l.a_t.is_finite() && l.mu_t.is_finite() {
        let mu_t = if l.a_t_undetermined() {
            "–".to_string()
        } else {
            format!("{:.3}", l.mu_t)
        };
        (pm_column(l.a_t, l.a_t_se), mu_t)
    } else {
        ("not measured".to_string(), "–".to_string())
    };
    let _ = writeln!(
        out,
        "{:<12} {:>14} {:>9.3} {:>11.3} {:>14} {:>9} {:>11.4}",
        "this fit",
        pm_column(l.a_cm, l.a_cm_se),
        l.mu_cm,
        l.f_net,
        a_t,
        mu_t,
        l.tau_net
    );
    // A rim mark tracked but followed in too few frames: why, as the Fit view says
    // it (with no mark at all, the track's table says so once, below).
    let why = l.why_no_v_t();
    if !(l.a_t.is_finite() && l.mu_t.is_finite()) && why != NoLineVt::NoMark {
        let _ = writeln!(out, "  (|a_t| and μ_k,t not measured: {})", why.reason());
    }
    if l.a_t_undetermined() {
        let _ = writeln!(out, "  ({UNDETERMINED_A_T})");
    }
    if let Some(mass) = mass {
        let _ = writeln!(out, "  ({mass})");
    }
    if let Some(p) = fit::paper_row(scene.width).filter(|_| paper_data) {
        let _ = writeln!(
            out,
            "{:<12} {:>14.2} {:>9.2} {:>11.2} {:>14.2} {:>9.2} {:>11.3}",
            "paper (tab.1)", p[0], p[1], p[2], p[3], p[4], p[5]
        );
        // Where the paper's row contradicts itself, say so (physics.md).
        for d in fit::paper_disagreements(scene.width, scene.radius, scene.g) {
            let _ = writeln!(
                out,
                "  the paper's own |a_{}| gives μ_k,{} = {:.3}, not its printed {:.2}: the table disagrees with itself",
                d.which, d.which, d.own, d.printed
            );
        }
    }
}

/// A fitted value and its ± (4 places, as the fits print; [`with_uncertainty`]).
pub(super) fn pm(v: f64, e: f64) -> String {
    let (v, e) = with_uncertainty(v, e, 4);
    format!("{v} ± {e}")
}

/// An acceleration and its ± in the line fits' 14-character column (2 places).
fn pm_column(v: f64, e: f64) -> String {
    let (v, e) = with_uncertainty(v, e, 2);
    format!("{v:>6} ± {e:<5}")
}

/// What the text says where |a_t| is not told from 0
/// ([`LineFit::a_t_undetermined`]).
const UNDETERMINED_A_T: &str = "μ_k,t not determined: |a_t| lies within two of its standard errors of 0, the rim mark's v_t in the window too few to fix its slope";

/// The model fit of a series: what it was fitted to, the fitted values with their
/// 95 % ranges (or why a value has none), and the regime predicted against the one
/// observed.
fn model_fit_lines(out: &mut String, mf: &ModelFit) {
    let model = model_name(&mf.model);
    match mf.every {
        None => {
            let _ = writeln!(
                out,
                "model fit ({model}) to all {} frames (v_cm and v_t; frames that straddle an impact left out):",
                mf.points
            );
        }
        Some(k) => {
            let _ = writeln!(
                out,
                "model fit ({model}) to {} frames, one in {k} of the series (at most {} are used; v_cm and v_t; frames that straddle an impact left out):",
                mf.points,
                fit::MAX_MODEL_POINTS
            );
        }
    }
    // A value the data do not determine gets its reason, not a number.
    let value = |name: &str, v: f64, se: Option<f64>, unit: &str| match (mf.undetermined(name), se)
    {
        (Some(n), _) => format!("not determined ({})", n.reason),
        (None, Some(se)) => format!("{}{unit}", pm(v, 2.0 * se)),
        (None, None) => format!("{v:.4}{unit}"),
    };
    let mu_se = Some(mf.mu_se).filter(|s| s.is_finite());
    let _ = writeln!(
        out,
        "  μ_k = {}{}   RMS residual {:.4} m/s",
        value("mu", mf.mu, mu_se, ""),
        if mu_se.is_some() {
            " (± 2σ, 95 %)"
        } else {
            ""
        },
        mf.rms
    );
    if mf.v0_se.is_some() || mf.undetermined("v0").is_some() {
        let _ = writeln!(out, "  v0 = {}", value("v0", mf.v0, mf.v0_se, " m/s"));
    }
    if mf.restitution_se.is_some() || mf.undetermined("restitution").is_some() {
        let _ = writeln!(
            out,
            "  e = {}",
            value("restitution", mf.restitution, mf.restitution_se, "")
        );
    }
    if mf.rolling_resistance_se.is_some() || mf.undetermined("rolling_resistance").is_some() {
        let _ = writeln!(
            out,
            "  c_rr = {}",
            value(
                "rolling_resistance",
                mf.rolling_resistance,
                mf.rolling_resistance_se,
                ""
            )
        );
    }
    let _ = writeln!(
        out,
        "  regime predicted {}; observed {} (speeds within ±{:.3} m/s count as rest: 3× the data's scatter)",
        mf.verdict,
        mf.observed_name(),
        mf.rest_band
    );
    let _ = writeln!(out, "  {}", mf.agreement().sentence());
}

/// The table for a position track: what was found, the line fits, and the headline's
/// model fitted to the velocities and to the positions side by side.
pub(super) fn track_table(
    scene: &Scene,
    f: &Fits,
    found: &Found,
    mass: Option<&str>,
    paper_data: bool,
) -> String {
    let mut out = found.describe();
    out.push('\n');
    // The line fits as for a velocity file; the model fits in two columns below.
    line_fit_or_why(&mut out, scene, f, mass, paper_data);
    if found.mark.is_none() {
        let _ = writeln!(
            out,
            "(no rim mark: v_t, a_t and μ_k,t are not measured; the sliding phase ends where the fitted model rolls again)"
        );
    }
    let p = &f.model_fit;
    let v = f.velocity_fit.as_ref().unwrap_or(p);
    let _ = writeln!(out);
    let title = format!(
        "model fits ({}; {})",
        model_name(&p.model),
        if found.mark.is_some() {
            "centre and rim mark"
        } else {
            "centre only"
        }
    );
    let _ = writeln!(
        out,
        "{title:<35} {:>24} {:>24}",
        "velocities (derived)", "positions (direct)"
    );
    let row = |out: &mut String, name: &str, a: String, b: String| {
        let _ = writeln!(out, "  {name:<33} {a:>24} {b:>24}");
    };
    row(&mut out, "μ_k (± 2σ, 95 %)", mu_cell(v), mu_cell(p));
    free_rows(&mut out, v, p);
    row(
        &mut out,
        "RMS residual",
        format!("{:.4} m/s", v.rms),
        format!("{:.3}", show_small(p.rms, Dimension::Length)),
    );
    row(
        &mut out,
        "frames used",
        v.points.to_string(),
        p.points.to_string(),
    );
    row(
        &mut out,
        "regime predicted / observed",
        regime(v),
        regime(p),
    );
    row(&mut out, "verdict", verdict(v), verdict(p));
    let _ = writeln!(out, "  velocity fit: regime {}", v.verdict);
    let _ = writeln!(out, "  position fit: regime {}", p.verdict);
    if let Some((mu_p, mu_v)) = p.fits_disagree {
        let _ = writeln!(
            out,
            "  {} (μ_k {mu_p:.4} from the positions, {mu_v:.4} from the velocities)",
            p.agreement().sentence()
        );
    }
    if let Some(slips) = &f.slips {
        let _ = writeln!(out, "  {}", slips_sentence(slips, found.impact_t));
    }
    for (what, m) in [("velocity", v), ("position", p)] {
        for n in &m.not_identified {
            let _ = writeln!(
                out,
                "  {what} fit: {} not determined: {}",
                symbol(n.parameter).0,
                n.reason
            );
        }
    }
    let _ = writeln!(
        out,
        "  (the velocity fit takes the model through the same local fits as the data, profiles out the impact time and counts the frames neighbouring points share; the position fit needs no derivatives and is the more precise: quote it)"
    );
    out
}

/// The frames left out of a track's fits as slips, in a sentence: at the file's
/// times (the series' t plus `file_t0`, the first impact's time in the file) and how
/// far off each was.
fn slips_sentence(s: &fit::slips::Slips, file_t0: f64) -> String {
    let mm = |v: f64| format!("{:.2}", show_small(v.abs(), Dimension::Length));
    let times: Vec<String> = s.t.iter().map(|t| format!("{:.3}", t + file_t0)).collect();
    let off: Vec<String> = s.residual.iter().map(|&r| mm(r)).collect();
    format!(
        "{} of {} frames left out of both fits, as tracking slips: their centres lie over {} ({:.0}× the residuals' spread) off the model fitted without them (t = {} s of the file; {} off){}; check them with track --overlay",
        s.t.len(),
        s.frames,
        mm(s.beyond),
        fit::slips::SLIP_SPREADS,
        times.join(", "),
        off.join(", "),
        match s.velocities_left_out {
            0 => String::new(),
            k => format!(
                ", and {k} derived velocities of other frames that they move beyond their ±"
            ),
        }
    )
}

/// The rows of v0, e and c_rr where either fit freed them: the velocities' `v` and
/// the positions' `p` side by side.
fn free_rows(out: &mut String, v: &ModelFit, p: &ModelFit) {
    let free =
        |m: &ModelFit, name: &str, se: Option<f64>| se.is_some() || m.undetermined(name).is_some();
    let rows = [
        ("v0 m/s (± 2σ)", "v0", (v.v0, v.v0_se), (p.v0, p.v0_se)),
        (
            "e (± 2σ)",
            "restitution",
            (v.restitution, v.restitution_se),
            (p.restitution, p.restitution_se),
        ),
        (
            "c_rr (± 2σ)",
            "rolling_resistance",
            (v.rolling_resistance, v.rolling_resistance_se),
            (p.rolling_resistance, p.rolling_resistance_se),
        ),
    ];
    for (label, name, a, b) in rows {
        if free(v, name, a.1) || free(p, name, b.1) {
            let _ = writeln!(
                out,
                "  {label:<33} {:>24} {:>24}",
                cell(v, name, a.0, a.1),
                cell(p, name, b.0, b.1)
            );
        }
    }
}

/// The fitted μ_k in a column: with its 95 % range, or "not determined" when the data
/// do not pin it down (a value the data do not determine gets no number that reads as
/// fitted).
fn mu_cell(m: &ModelFit) -> String {
    if m.undetermined("mu").is_some() {
        "not determined".to_string()
    } else {
        pm(m.mu, 2.0 * m.mu_se)
    }
}

/// A fitted value `v` of the parameter `name` in a column: with its 95 % range when
/// its standard error `se` is known, "not determined" when the data do not pin it
/// down.
fn cell(m: &ModelFit, name: &str, v: f64, se: Option<f64>) -> String {
    match se {
        _ if m.undetermined(name).is_some() => "not determined".to_string(),
        Some(se) => pm(v, 2.0 * se),
        None => format!("{v:.4}"),
    }
}

/// "recollide / rest": the regime a fit predicts and the one observed.
fn regime(m: &ModelFit) -> String {
    format!("{} / {}", m.regime_predicted.name(), m.observed_name())
}

/// Whether a fit's prediction agrees with what was observed, in a column.
fn verdict(m: &ModelFit) -> String {
    m.agreement().word().to_string()
}

/// A fitted parameter's symbol and unit for people.
pub(super) fn symbol(parameter: &str) -> (&'static str, &'static str) {
    match parameter {
        "mu" => ("μ_k", ""),
        "v0" => ("v0", " m/s"),
        "restitution" => ("e", ""),
        _ => ("c_rr", ""),
    }
}
