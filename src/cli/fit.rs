//! `groovelab fit`: the paper's line fits and the whole-model fit of measured data.

use std::fmt::Write as _;

use serde::Serialize;

use super::{CliError, DataArgs, FitArgs, FitFormat, SceneArgs, methods::write_atomically};
use crate::input::data::Measured;
use crate::input::data::{self, Reading};
use crate::input::preset::Preset;
use crate::input::units::{Dimension, parse_quantity};
use crate::physics::scene::Scene;
use crate::study::fit::{self, Fits, Free};

/// The measured series: `--data FILE`, else the preset's.
pub fn measured(preset: &Preset, args: &DataArgs) -> Result<Measured, CliError> {
    let Some(path) = &args.data else {
        return preset.measured.clone().ok_or_else(|| {
            CliError::Invalid(format!(
                "preset {} has no measured data, allowed: a paper-b* preset or --data FILE",
                preset.name
            ))
        });
    };
    let text = std::fs::read_to_string(path)
        .map_err(|e| CliError::Invalid(format!("cannot read --data {}: {e}", path.display())))?;
    let unit = |text: &Option<String>, dim: Dimension, flag: &str| {
        text.as_ref()
            .map(|u| {
                parse_quantity(&format!("1{u}"), dim)
                    .map_err(|e| CliError::Invalid(format!("{flag} {u}: {e}")))
            })
            .transpose()
    };
    let reading = Reading {
        time_unit: unit(&args.time_unit, Dimension::Time, "--time-unit")?,
        speed_unit: unit(&args.speed_unit, Dimension::Speed, "--speed-unit")?,
        impact_at: args.impact_at,
    };
    data::parse(&text, &path.display().to_string(), &reading)
        .map_err(|e| CliError::Invalid(e.to_string()))
}

#[derive(Serialize)]
struct FitJson<'a> {
    scene: &'a Scene,
    #[serde(flatten)]
    fits: &'a Fits,
}

pub fn run(scene_args: &SceneArgs, data: &DataArgs, args: &FitArgs) -> Result<String, CliError> {
    let (preset, scene, _) = scene_args.resolve()?;
    let m = measured(&preset, data)?;
    // Each value once: a repeated one (`--free mu,mu`) made the normal matrix
    // singular and the uncertainty NaN.
    let mut free: Vec<Free> = Vec::new();
    for f in args.free.clone().unwrap_or_else(|| vec![Free::Mu]) {
        if !free.contains(&f) {
            free.push(f);
        }
    }
    if let (Some(a), Some(b)) = (args.from, args.to)
        && a >= b
    {
        return Err(CliError::Invalid(format!(
            "--from {a} s must be before --to {b} s"
        )));
    }
    // A series long enough to take a noticeable time shows a counter.
    let bar = super::progress::Bar::counter("model evaluations", m.t.len() > 5_000);
    let fits = fit::fit_all(&scene, &m, (args.from, args.to), &free, &bar);
    bar.finish();
    let fits = fits.map_err(|e| match e {
        fit::FitError::Cancelled => CliError::Interrupted,
        e => CliError::Invalid(e.to_string()),
    })?;
    let text = match args.format {
        FitFormat::Json => {
            let mut s = serde_json::to_string_pretty(&FitJson {
                scene: &scene,
                fits: &fits,
            })
            .expect("plain data serializes");
            s.push('\n');
            s
        }
        FitFormat::Table => table(&scene, &fits),
        FitFormat::Svg => crate::study::figures::fit_figure(&scene, &m, &fits)
            .map_err(|e| CliError::Invalid(format!("cannot draw the figure: {e}")))?,
    };
    match &args.output {
        None => Ok(text),
        Some(path) => {
            write_atomically(path, &text)?;
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
