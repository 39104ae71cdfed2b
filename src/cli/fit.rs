//! `groovelab fit`: the paper's line fits and the whole-model fit of measured data.

use std::fmt::Write as _;

use serde::Serialize;

use super::args::{DataArgs, FitArgs, FitFormat, SceneArgs};
use super::error::{BadValue, CliError};
use super::open::lab_of_stated_scene;
use crate::lab::Lab;
use crate::output::write_atomically;
use crate::physics::scene::Scene;
use crate::settings::params::Key;
use crate::settings::units::{
    Dimension, show, show_exact, show_small, significant, with_uncertainty,
};
use crate::study::fit::{self, Candidate, Fits, Free, LineFit, ModelFit};
use crate::study::measured::Found;

/// The `--data` file read, its velocities derived as far as no scene enters; `None`
/// without `--data`.
#[derive(Serialize)]
struct FitJson<'a> {
    scene: &'a Scene,
    /// True when the data file was read mirrored: recorded with x pointing away
    /// from the other ball, turned x → −x.
    mirrored: bool,
    #[serde(flatten)]
    fits: &'a Fits,
    /// For a position track: the model fitted to the positions themselves.
    #[serde(skip_serializing_if = "Option::is_none")]
    position_fit: Option<&'a ModelFit>,
    /// For a position track: what was found in it (impact, direction, window).
    #[serde(skip_serializing_if = "Option::is_none")]
    track: Option<&'a Found>,
    /// The groove the data were measured in, where it is not the model's (R and b, m).
    #[serde(skip_serializing_if = "Option::is_none")]
    data_groove: Option<crate::lab::Groove>,
    /// The values that are null because the data cannot give them, and why.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    not_measured: Vec<NotMeasured>,
}

/// `fit --format json`: values the data do not determine null, times rounded.
fn json_text(fit: FitJson) -> String {
    let mut json = serde_json::to_value(fit).expect("plain data serializes");
    for fit in ["model_fit", "position_fit"] {
        if let Some(fit) = json.get_mut(fit) {
            null_undetermined(fit);
        }
    }
    round_times(&mut json);
    let mut s = serde_json::to_string_pretty(&json).expect("plain data serializes");
    s.push('\n');
    s
}

/// A model fit's values that the data do not determine (listed in its
/// `not_identified`, with why) are `null`, not a number that reads as fitted.
fn null_undetermined(fit: &mut serde_json::Value) {
    let names: Vec<String> = fit["not_identified"]
        .as_array()
        .into_iter()
        .flatten()
        .filter_map(|n| n["parameter"].as_str().map(str::to_string))
        .collect();
    for name in names {
        if let Some(v) = fit.get_mut(&name) {
            *v = serde_json::Value::Null;
        }
    }
}

/// The times `fit` reports, s, rounded to the microsecond: they are frame times (and
/// differences of them), whose meaning ends far above the last bits of a float
/// (`0.17084999999999997` is the frame at 0.17085 s).
fn round_times(json: &mut serde_json::Value) {
    let round = |v: &mut serde_json::Value| {
        if let Some(x) = v.as_f64() {
            *v = serde_json::json!((x * 1e6).round() / 1e6);
        }
    };
    for (part, key) in [
        ("line_fit", "from"),
        ("line_fit", "to"),
        ("track", "impact_t"),
        ("track", "half_window"),
        ("track", "half_window_widened_from"),
    ] {
        if let Some(v) = json.get_mut(part).and_then(|p| p.get_mut(key)) {
            round(v);
        }
    }
    for key in ["later_impacts", "centre_gaps", "mark_gaps"] {
        if let Some(list) = json
            .get_mut("track")
            .and_then(|t| t.get_mut(key))
            .and_then(|l| l.as_array_mut())
        {
            for v in list {
                match v.as_array_mut() {
                    Some(run) => run.iter_mut().for_each(round),
                    None => round(v),
                }
            }
        }
    }
}

/// A value the data cannot give (JSON null), and why.
#[derive(Serialize)]
struct NotMeasured {
    quantity: &'static str,
    reason: &'static str,
}

/// The line fit's values that are null for `fits`: a_t and μ_k,t without a rim mark.
fn not_measured(fits: &Fits) -> Vec<NotMeasured> {
    let l = &fits.line_fit;
    let reason = "no rim mark was tracked: v_t is not measured";
    [
        ("line_fit.a_t", l.a_t),
        ("line_fit.a_t_se", l.a_t_se),
        ("line_fit.mu_t", l.mu_t),
        ("line_fit.mu_t_se", l.mu_t_se),
    ]
    .into_iter()
    .filter(|(_, v)| !v.is_finite())
    .map(|(quantity, _)| NotMeasured { quantity, reason })
    .collect()
}

/// `fit` on the scene of `scene_args` (the command line's `typed` over the data
/// file's own scene lines, [`with_file_scene`]).
pub fn run(
    scene_args: &SceneArgs,
    typed: &SceneArgs,
    data: &DataArgs,
    args: &FitArgs,
) -> Result<String, CliError> {
    // The app's snapshot: the scene by the same layers, the data derived for it.
    let lab = lab_of_stated_scene(scene_args, data)?;
    let (preset, scene) = (lab.preset(), lab.scene);
    if let Some(path) = &args.output {
        crate::output::check_output(path)?;
    }
    let m = lab.measured().ok_or_else(|| BadValue::NoMeasuredData {
        preset: preset.name.clone(),
    })?;
    let found = lab.series().and_then(|s| s.found().cloned());
    let free = free_values(args)?;
    // A series long enough to take a noticeable time shows a counter.
    let bar = super::progress::Bar::counter("model evaluations", m.t.len() > 5_000);
    let fits = fit::fit_all(&scene, m, (args.from, args.to), &free, &bar);
    let position = match (&fits, &found) {
        (Ok(_), Some(_)) => Some(fit::position_fit(&scene, m, &free, &bar)),
        _ => None,
    };
    bar.finish();
    let cancelled = |e: fit::FitError| match e {
        fit::FitError::Cancelled => CliError::Interrupted,
        e => CliError::Fit(e),
    };
    let fits = fits.map_err(cancelled)?;
    let position = position.transpose().map_err(cancelled)?;
    let text = match args.format {
        FitFormat::Json => json_text(FitJson {
            scene: &scene,
            mirrored: lab.series().is_some_and(|s| s.mirrored()),
            fits: &fits,
            position_fit: position.as_ref(),
            track: found.as_ref(),
            data_groove: lab.other_groove.as_ref().map(|o| o.data),
            not_measured: not_measured(&fits),
        }),
        FitFormat::Table => {
            let own = data.data.is_empty();
            let mut out = scene_line(&lab, typed, scene_args, data);
            if let Some(note) = lab.own_data().and_then(|o| o.mirrored_note()) {
                out += &note;
                out.push('\n');
            }
            out += &match (&found, &position) {
                (Some(found), Some(position)) => track_table(&scene, &fits, found, position, own),
                _ => table(&scene, &fits, own),
            };
            out += &models_table(&fits.models, found.is_some());
            out
        }
        FitFormat::Svg => {
            crate::study::figures::fit_figure(&scene, m, &fits).map_err(|source| {
                CliError::Draw {
                    what: "figure",
                    source,
                }
            })?
        }
    };
    match &args.output {
        None => Ok(text),
        Some(path) => {
            // From here a stop signal removes the temporary file and writes nothing.
            crate::signals::watch();
            write_atomically(path, text.as_bytes())?;
            Ok(format!("wrote {}\n", path.display()))
        }
    }
}

/// The values `--free` sets free, each once (a repeated one, `--free mu,mu`, is
/// refused, not quietly dropped: it once made the normal matrix singular and the
/// uncertainty NaN), after checking that the window `--from`/`--to` lies after the
/// impact and runs forward.
fn free_values(args: &FitArgs) -> Result<Vec<Free>, CliError> {
    // A window reaching back over the impact fits a line across the jump.
    for (flag, value) in [("from", args.from), ("to", args.to)] {
        if let Some(value) = value.filter(|v| *v <= 0.0) {
            return Err(BadValue::FitWindowBeforeImpact { flag, value }.into());
        }
    }
    if let (Some(a), Some(b)) = (args.from, args.to)
        && a >= b
    {
        return Err(BadValue::FitWindowBackwards { from: a, to: b }.into());
    }
    let mut free: Vec<Free> = Vec::new();
    for f in args.free.clone().unwrap_or_else(|| vec![Free::Mu]) {
        if free.contains(&f) {
            return Err(BadValue::FreeTwice { name: f.name() }.into());
        }
        free.push(f);
    }
    Ok(free)
}

/// The scene a fit used, and where it came from: the first line of the table, and
/// under it where the data were measured if that is another groove. The values come
/// from the command line (`typed`), the data file's own scene lines (the rest of
/// `used`) and the preset under them (named unless those give every value).
fn scene_line(lab: &Lab, typed: &SceneArgs, used: &SceneArgs, data: &DataArgs) -> String {
    let (preset, scene) = (lab.preset(), &lab.scene);
    let len = |v: f64| show(v, Dimension::Length);
    let flags: Vec<Key> = typed.values.given().map(|(k, _)| k).collect();
    let from_file: Vec<Key> = used
        .values
        .given()
        .map(|(k, _)| k)
        .filter(|k| !flags.contains(k))
        .collect();
    let all: Vec<Key> = flags.iter().chain(&from_file).copied().collect();
    let file = data.data.first().map(|p| p.display().to_string());
    let mut sources = Vec::new();
    if typed.preset.is_some() || !every_scene_value(&all) {
        // Named as it came: the user's `--preset`, or the default under the options.
        let default = if typed.preset.is_none() {
            "default "
        } else {
            ""
        };
        sources.push(format!("{default}preset {}", preset.name));
    }
    match (&file, from_file.is_empty(), sources.is_empty()) {
        (Some(file), false, true) => sources.push(format!("from {file}'s header")),
        (Some(file), false, false) => {
            let names: Vec<&str> = from_file.iter().map(|k| k.name()).collect();
            sources.push(format!("{file}'s header ({})", names.join(", ")));
        }
        _ => {}
    }
    if !flags.is_empty() {
        // As typed: `--mass`, not the `--mass-left --mass-right` it sets.
        let flags: Vec<String> = typed
            .values
            .rows()
            .iter()
            .map(|k| format!("--{}", k.param().flag))
            .collect();
        sources.push(flags.join(" "));
    }
    let source = match sources.as_slice() {
        [] => unreachable!("a preset, the file's header or flags give the scene"),
        [one] => one.clone(),
        [first, rest @ ..] => format!("{first} with {}", rest.join(" and ")),
    };
    // Data of another groove are never fitted without saying so.
    let other = lab
        .other_groove
        .as_ref()
        .map_or(String::new(), |o| format!("data: {}\n", o.describe()));
    format!(
        "scene ({source}): R = {}, b = {}, m = {} / {}, v0 = {} / {}, μ_k = {} (start), e = {}\n{other}",
        len(scene.radius),
        // Every digit given: b = 5.4999 cm at four digits reads 5.5 cm = 2R, out of range.
        show_exact(scene.width, Dimension::Length),
        show(scene.left.mass, Dimension::Mass),
        show(scene.right.mass, Dimension::Mass),
        show(scene.left.v0, Dimension::Speed),
        show(scene.right.v0, Dimension::Speed),
        significant(scene.mu, 4),
        significant(scene.restitution, 4),
    )
}

/// The line fits and the model fit; the paper's table-1 row beside them only for the
/// preset's own (the paper's) data, `paper_data`.
fn table(scene: &Scene, f: &Fits, paper_data: bool) -> String {
    let mut out = String::new();
    line_fit_lines(&mut out, scene, &f.line_fit, paper_data);
    let _ = writeln!(out);
    model_fit_lines(&mut out, &f.model_fit);
    out
}

/// The line fits over their window (the sliding phase unless --from/--to set it), and
/// the paper's table-1 row with where it contradicts itself when `paper_data`.
fn line_fit_lines(out: &mut String, scene: &Scene, l: &LineFit, paper_data: bool) {
    // The window said as it was chosen: the sliding phase, or what --from/--to set.
    let (over, hint) = match l.given {
        [false, false] => ("over the sliding phase", "; change with --from/--to"),
        [true, true] => ("over the window --from/--to set", ""),
        [true, false] => ("from --from to the end of the sliding phase", ""),
        [false, true] => ("from the start of the sliding phase to --to", ""),
    };
    let _ = writeln!(
        out,
        "line fits {over}, t = {:.3} … {:.3} s ({} frames{hint})",
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
        (pm_column(l.a_t, l.a_t_se), format!("{:.3}", l.mu_t))
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
fn pm(v: f64, e: f64) -> String {
    let (v, e) = with_uncertainty(v, e, 4);
    format!("{v} ± {e}")
}

/// An acceleration and its ± in the line fits' 14-character column (2 places).
fn pm_column(v: f64, e: f64) -> String {
    let (v, e) = with_uncertainty(v, e, 2);
    format!("{v:>6} ± {e:<5}")
}

/// The model fit of a series: what it was fitted to, the fitted values with their
/// 95 % ranges (or why a value has none), and the regime predicted against the one
/// observed.
fn model_fit_lines(out: &mut String, mf: &ModelFit) {
    match mf.every {
        None => {
            let _ = writeln!(
                out,
                "model fit to all {} frames (v_cm and v_t; frames that straddle an impact left out):",
                mf.points
            );
        }
        Some(k) => {
            let _ = writeln!(
                out,
                "model fit to {} frames, one in {k} of the series (at most {} are used; v_cm and v_t; frames that straddle an impact left out):",
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
        mf.regime_observed.name(),
        mf.rest_band
    );
    let _ = writeln!(out, "  {}", mf.agreement().sentence());
}

/// The table for a position track: what was found, the line fits, and the velocity and
/// position fits side by side.
fn track_table(scene: &Scene, f: &Fits, found: &Found, p: &ModelFit, paper_data: bool) -> String {
    let mut out = found.describe();
    out.push('\n');
    // The line fits as for a velocity file; the model fits in two columns below.
    line_fit_lines(&mut out, scene, &f.line_fit, paper_data);
    if found.mark.is_none() {
        let _ = writeln!(
            out,
            "(no rim mark: v_t, a_t and μ_k,t are not measured; the sliding phase ends where the fitted model rolls again)"
        );
    }
    let v = &f.model_fit;
    let _ = writeln!(out);
    let title = format!(
        "model fits ({})",
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
    let free =
        |m: &ModelFit, name: &str, se: Option<f64>| se.is_some() || m.undetermined(name).is_some();
    if free(v, "v0", v.v0_se) || free(p, "v0", p.v0_se) {
        row(
            &mut out,
            "v0 m/s (± 2σ)",
            cell(v, "v0", v.v0, v.v0_se),
            cell(p, "v0", p.v0, p.v0_se),
        );
    }
    if free(v, "restitution", v.restitution_se) || free(p, "restitution", p.restitution_se) {
        row(
            &mut out,
            "e (± 2σ)",
            cell(v, "restitution", v.restitution, v.restitution_se),
            cell(p, "restitution", p.restitution, p.restitution_se),
        );
    }
    let c_rr = "rolling_resistance";
    if free(v, c_rr, v.rolling_resistance_se) || free(p, c_rr, p.rolling_resistance_se) {
        row(
            &mut out,
            "c_rr (± 2σ)",
            cell(v, c_rr, v.rolling_resistance, v.rolling_resistance_se),
            cell(p, c_rr, p.rolling_resistance, p.rolling_resistance_se),
        );
    }
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
    format!(
        "{} / {}",
        m.regime_predicted.name(),
        m.regime_observed.name()
    )
}

/// Whether a fit's prediction agrees with what was observed, in a column.
fn verdict(m: &ModelFit) -> String {
    m.agreement().word().to_string()
}

/// True when `keys` set every value of a scene: no preset's value is left in it.
fn every_scene_value(keys: &[Key]) -> bool {
    let has = |k: &Key| keys.contains(k);
    let ball = |v0: Key, h: Key| has(&v0) || has(&h);
    [
        Key::Radius,
        Key::Width,
        Key::MassLeft,
        Key::MassRight,
        Key::Mu,
        Key::Restitution,
        Key::RollingResistance,
        Key::G,
    ]
    .iter()
    .all(has)
        && ball(Key::V0Left, Key::HeightLeft)
        && ball(Key::V0Right, Key::HeightRight)
}

/// A fitted parameter's symbol and unit for people.
fn symbol(parameter: &str) -> (&'static str, &'static str) {
    match parameter {
        "mu" => ("μ_k", ""),
        "v0" => ("v0", " m/s"),
        "restitution" => ("e", ""),
        _ => ("c_rr", ""),
    }
}

/// The candidate models compared by AIC and BIC, and the one the data support.
fn models_table(models: &[Candidate], positions: bool) -> String {
    let mut out = String::new();
    let _ = writeln!(
        out,
        "\nwhich model the data support (fitted to the {}; AIC and BIC, lower is better, listed by BIC, lowest first; the simplest model within 2 of the lowest BIC whose values are all determined is named):",
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
                    (None, Some(se)) => format!("{name} {}{unit}", pm(e.value, 2.0 * se)),
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
    match models.iter().find(|c| c.supported) {
        Some(c) => {
            let _ = writeln!(
                out,
                "  the data support: {} (marked *); a larger model does not lower the BIC by 2 or more",
                names(c)
            );
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
