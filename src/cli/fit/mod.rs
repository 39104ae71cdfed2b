//! `groovelab fit`: the paper's line fits and the whole-model fit of measured data.
//! Here the command and where each scene value came from (`sources`); the JSON in
//! `json`, the table in `table`, the candidate models' table in `models`.

mod json;
mod models;
mod sources;
mod table;

use super::args::{DataArgs, FitArgs, FitFormat, SceneArgs};
use super::error::{BadValue, CliError};
use super::open::lab_of_stated_scene;
use crate::study::fit::{self, Free};

/// `fit` on the scene of `scene_args` (the command line's `typed` over the data
/// file's own scene lines, [`super::open::with_file_scene`]).
pub fn run(
    scene_args: &SceneArgs,
    typed: &SceneArgs,
    data: &DataArgs,
    args: &FitArgs,
) -> Result<String, CliError> {
    // The app's snapshot: the scene by the same layers, the data derived for it.
    let lab = lab_of_stated_scene(scene_args, data)?;
    let (preset, scene) = (lab.preset(), lab.scene);
    let m = lab.measured().ok_or_else(|| BadValue::NoMeasuredData {
        preset: preset.name.clone(),
    })?;
    let found = lab.series().and_then(|s| s.found().cloned());
    let free = free_values(args)?;
    // A series long enough to take a noticeable time shows a counter.
    let bar = super::progress::Bar::counter("model evaluations", m.t().len() > 5_000);
    let ask = fit::Ask {
        window: (args.from, args.to),
        free,
        v0_measured: lab
            .settings()
            .from_the_data(crate::settings::params::Key::V0),
    };
    let fits = fit::fit_all(&scene, m, &ask, &bar);
    bar.finish();
    let fits = fits.map_err(|e| match e {
        fit::FitError::Cancelled => CliError::Interrupted,
        e => CliError::Fit(e),
    })?;
    let sources = sources::Sources::of(&lab, typed, data);
    // A rim mark that turns over half a turn a frame in this scene: left out, said.
    let aliased = lab.data.as_ref().and_then(|d| d.mark_aliased).map(|w| {
        format!(
            "the rim mark turns {w:.1} rad (over half a turn) between frames in this scene, so its angle cannot be followed at this frame rate: v_t is not measured and the fits use the centre alone (film faster to measure the spin)"
        )
    });
    Ok(match args.format {
        FitFormat::Json => json::text(json::FitJson {
            scene: &scene,
            sources: &sources,
            mirrored: lab.series().is_some_and(|s| s.mirrored()),
            fits: &fits,
            track: found.as_ref(),
            data_groove: lab
                .other_groove
                .as_ref()
                .map(|o| json::DataGroove::of(&o.data)),
            not_measured: json::not_measured(&fits, aliased.as_deref()),
        }),
        FitFormat::Table => {
            // The scene and where it came from, then the short summary, the detail after.
            let mut out = sources.scene_line(&lab);
            if let Some(note) = lab.own_data().and_then(|o| o.reading_notes()) {
                out += &note;
                out.push('\n');
            }
            out += &table::summary(&fits);
            if let Some(note) = &aliased {
                out += note;
                out.push('\n');
            }
            let own = data.data.is_empty();
            let mass = sources.assumed_mass(&lab);
            out += &match &found {
                Some(found) => table::track_table(&scene, &fits, found, mass.as_deref(), own),
                None => table::table(&scene, &fits, mass.as_deref(), own),
            };
            out += &models::table(&fits.models, found.is_some());
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
    })
}

/// The values `--free` sets free, each once (`None` without `--free`: the model the
/// data support is the headline) (a repeated one, `--free mu,mu`, is
/// refused, not quietly dropped: it once made the normal matrix singular and the
/// uncertainty NaN), after checking that the window `--from`/`--to` lies after the
/// impact and runs forward.
fn free_values(args: &FitArgs) -> Result<Option<Vec<Free>>, CliError> {
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
    let Some(asked) = &args.free else {
        return Ok(None);
    };
    let mut free: Vec<Free> = Vec::new();
    for &f in asked {
        if free.contains(&f) {
            return Err(BadValue::FreeTwice { name: f.name() }.into());
        }
        free.push(f);
    }
    if !free.contains(&Free::Mu) {
        let names: Vec<&str> = free.iter().map(|f| f.name()).collect();
        return Err(BadValue::FreeWithoutMu {
            list: names.join(","),
        }
        .into());
    }
    Ok(Some(free))
}
