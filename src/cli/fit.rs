//! `groovelab fit`: the paper's line fits and the whole-model fit of measured data.

use std::fmt::Write as _;

use serde::Serialize;

use super::{CliError, DataArgs, FitArgs, FitFormat, SceneArgs, output::write_atomically};
use crate::input::data::Measured;
use crate::input::data::Reading;
use crate::input::preset::Preset;
use crate::input::units::{Dimension, unit_factor};
use crate::physics::scene::Scene;
use crate::study::fit::{self, Fits, Free, ModelFit};
use crate::study::track::{self, Derive, Found};

/// The measured series: `--data FILE`, else the preset's. A position track's
/// velocities are derived with the preset's own scene (its contact radius r = kR).
pub fn measured(preset: &Preset, args: &DataArgs) -> Result<Measured, CliError> {
    let scene = preset
        .spec
        .resolve()
        .map_err(|e| CliError::Invalid(e.to_string()))?
        .0;
    load(preset, &scene, args).map(|l| l.0)
}

/// The measured series for `scene`, and what was found in a position track.
pub fn load(
    preset: &Preset,
    scene: &Scene,
    args: &DataArgs,
) -> Result<(Measured, Option<Found>), CliError> {
    let Some(path) = &args.data else {
        return preset.measured.clone().map(|m| (m, None)).ok_or_else(|| {
            CliError::Invalid(format!(
                "preset {} has no measured data, allowed: a paper-b* preset or --data FILE",
                preset.name
            ))
        });
    };
    let text = crate::input::read_user_file(path, "--data", crate::input::MAX_FILE_BYTES)
        .map_err(|e| CliError::Invalid(e.to_string()))?;
    let unit = |text: &Option<String>, dim: Dimension, flag: &str| {
        text.as_ref()
            .map(|u| unit_factor(u, dim).map_err(|e| CliError::Invalid(format!("{flag} {u}: {e}"))))
            .transpose()
    };
    let reading = Reading {
        time_unit: unit(&args.time_unit, Dimension::Time, "--time-unit")?,
        speed_unit: unit(&args.speed_unit, Dimension::Speed, "--speed-unit")?,
        impact_at: args.impact_at,
        ..Reading::default()
    };
    let loaded = track::load(
        &text,
        &path.display().to_string(),
        &reading,
        scene,
        &Derive::default(),
    )
    .map_err(|e| CliError::Invalid(e.to_string()))?;
    Ok((loaded.measured, loaded.found))
}

#[derive(Serialize)]
struct FitJson<'a> {
    scene: &'a Scene,
    #[serde(flatten)]
    fits: &'a Fits,
    /// For a position track: the model fitted to the positions themselves.
    #[serde(skip_serializing_if = "Option::is_none")]
    position_fit: Option<&'a ModelFit>,
    /// For a position track: what was found in it (impact, direction, window).
    #[serde(skip_serializing_if = "Option::is_none")]
    track: Option<&'a Found>,
}

pub fn run(scene_args: &SceneArgs, data: &DataArgs, args: &FitArgs) -> Result<String, CliError> {
    let (preset, scene, _) = scene_args.resolve()?;
    if let Some(path) = &args.output {
        super::output::check_output(path)?;
    }
    let (m, found) = load(&preset, &scene, data)?;
    let free: Vec<Free> = args.free.clone().unwrap_or_else(|| vec![Free::Mu]);
    if let (Some(a), Some(b)) = (args.from, args.to)
        && a >= b
    {
        return Err(CliError::Invalid(format!(
            "--from {a} s must be before --to {b} s"
        )));
    }
    let fits = fit::fit_all(&scene, &m, (args.from, args.to), &free)
        .map_err(|e| CliError::Invalid(e.to_string()))?;
    let position = match &found {
        Some(_) => Some(
            fit::position_fit(&scene, &m, &free).map_err(|e| CliError::Invalid(e.to_string()))?,
        ),
        None => None,
    };
    let text = match args.format {
        FitFormat::Json => {
            let mut s = serde_json::to_string_pretty(&FitJson {
                scene: &scene,
                fits: &fits,
                position_fit: position.as_ref(),
                track: found.as_ref(),
            })
            .expect("plain data serializes");
            s.push('\n');
            s
        }
        FitFormat::Table => match (&found, &position) {
            (Some(found), Some(position)) => track_table(&scene, &fits, found, position),
            _ => table(&scene, &fits),
        },
        FitFormat::Svg => crate::study::figures::fit_figure(&scene, &m, &fits)
            .map_err(|e| CliError::Invalid(format!("cannot draw the figure: {e}")))?,
    };
    match &args.output {
        None => Ok(text),
        Some(path) => {
            // From here a stop signal removes the temporary file and writes nothing.
            super::output::watch_signals();
            write_atomically(path, text.as_bytes())?;
            Ok(format!("wrote {}\n", path.display()))
        }
    }
}

fn table(scene: &Scene, f: &Fits) -> String {
    let l = &f.line_fit;
    let mut out = String::new();
    let _ = writeln!(
        out,
        "line fits over the sliding phase, t = {:.3} … {:.3} s ({} frames; change with --from/--to)",
        l.from, l.to, l.points
    );
    let _ = writeln!(
        out,
        "{:<12} {:>14} {:>9} {:>11} {:>14} {:>9} {:>11}",
        "", "|a_cm| m/s²", "μ_k,cm", "|F_net| N", "|a_t| m/s²", "μ_k,t", "|τ_net| N m"
    );
    let _ = writeln!(
        out,
        "{:<12} {:>6.2} ± {:<5.2} {:>9.3} {:>11.3} {:>6.2} ± {:<5.2} {:>9.3} {:>11.4}",
        "this fit", l.a_cm, l.a_cm_se, l.mu_cm, l.f_net, l.a_t, l.a_t_se, l.mu_t, l.tau_net
    );
    if let Some(p) = fit::paper_row(scene.width) {
        let _ = writeln!(
            out,
            "{:<12} {:>14.2} {:>9.2} {:>11.2} {:>14.2} {:>9.2} {:>11.3}",
            "paper (tab.1)", p[0], p[1], p[2], p[3], p[4], p[5]
        );
    }
    let mf = &f.model_fit;
    let _ = writeln!(out);
    let _ = writeln!(
        out,
        "model fit to all {} frames (v_cm and v_t; frames that straddle an impact left out):",
        mf.points
    );
    let _ = writeln!(
        out,
        "  μ_k = {:.4} ± {:.4} (± 2σ, 95 %)   RMS residual {:.4} m/s",
        mf.mu,
        2.0 * mf.mu_se,
        mf.rms
    );
    if let Some(se) = mf.v0_se {
        let _ = writeln!(out, "  v0 = {:.4} ± {:.4} m/s", mf.v0, 2.0 * se);
    }
    if let Some(se) = mf.restitution_se {
        let _ = writeln!(out, "  e = {:.4} ± {:.4}", mf.restitution, 2.0 * se);
    }
    let _ = writeln!(
        out,
        "  regime predicted {} (v' = {:+.3} m/s), observed {}; speeds within ±{:.3} m/s count as rest (3× the data's scatter)",
        mf.regime_predicted.name(),
        mf.v_roll,
        mf.regime_observed.name(),
        mf.rest_band
    );
    let _ = writeln!(
        out,
        "  {}",
        if mf.regime_predicted == mf.regime_observed {
            "the model predicts what was observed"
        } else {
            "the model does NOT predict what was observed"
        }
    );
    out
}

/// The table for a position track: what was found, the line fits, and the velocity and
/// position fits side by side.
fn track_table(scene: &Scene, f: &Fits, found: &Found, p: &ModelFit) -> String {
    let mut out = found.describe();
    out.push('\n');
    let full = table(scene, f);
    // The line fits as for a velocity file; the model fits in two columns below.
    let lines: Vec<&str> = full.lines().take_while(|l| !l.is_empty()).collect();
    for l in lines {
        let _ = writeln!(out, "{l}");
    }
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
    let pm = |m: &ModelFit| format!("{:.4} ± {:.4}", m.mu, 2.0 * m.mu_se);
    let row = |out: &mut String, name: &str, a: String, b: String| {
        let _ = writeln!(out, "  {name:<33} {a:>24} {b:>24}");
    };
    row(&mut out, "μ_k (± 2σ, 95 %)", pm(v), pm(p));
    if let (Some(a), Some(b)) = (v.v0_se, p.v0_se) {
        row(
            &mut out,
            "v0 m/s (± 2σ)",
            format!("{:.4} ± {:.4}", v.v0, 2.0 * a),
            format!("{:.4} ± {:.4}", p.v0, 2.0 * b),
        );
    }
    if let (Some(a), Some(b)) = (v.restitution_se, p.restitution_se) {
        row(
            &mut out,
            "e (± 2σ)",
            format!("{:.4} ± {:.4}", v.restitution, 2.0 * a),
            format!("{:.4} ± {:.4}", p.restitution, 2.0 * b),
        );
    }
    row(
        &mut out,
        "RMS residual",
        format!("{:.4} m/s", v.rms),
        format!("{:.3} mm", 1e3 * p.rms),
    );
    row(
        &mut out,
        "frames used",
        v.points.to_string(),
        p.points.to_string(),
    );
    let regime = |m: &ModelFit| {
        format!(
            "{} / {}",
            m.regime_predicted.name(),
            m.regime_observed.name()
        )
    };
    row(
        &mut out,
        "regime predicted / observed",
        regime(v),
        regime(p),
    );
    let verdict = |m: &ModelFit| {
        if m.regime_predicted == m.regime_observed {
            "agree".to_string()
        } else {
            "DISAGREE".to_string()
        }
    };
    row(&mut out, "verdict", verdict(v), verdict(p));
    let _ = writeln!(
        out,
        "  (the velocity fit weights each derived point by its uncertainty but counts the points as independent and the impact time as exact: its ± is too small; the position fit profiles out the impact's time and place, and its ± is the one to quote)"
    );
    out
}
