//! `fit --format json`: the scene and where its values came from, the fits (values
//! the data do not determine null), what was found in a track; times rounded.

use serde::Serialize;

use super::sources::Sources;
use crate::physics::scene::Scene;
use crate::study::fit::Fits;
use crate::study::measured::Found;

/// `fit --format json`.
#[derive(Serialize)]
pub(super) struct FitJson<'a> {
    pub scene: &'a Scene,
    /// Where each scene value came from, and which are assumed.
    pub sources: &'a Sources,
    /// True when the data file was read mirrored: recorded with x pointing away
    /// from the other ball, turned x → −x.
    pub mirrored: bool,
    #[serde(flatten)]
    pub fits: &'a Fits,
    /// For a position track: what was found in it (impact, direction, window).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub track: Option<&'a Found>,
    /// The groove the data were measured in, where it is not the model's (R and b, m;
    /// null where the data do not state it).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub data_groove: Option<DataGroove>,
    /// The values that are null because the data cannot give them, and why.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub not_measured: Vec<NotMeasured>,
}

/// The groove the data state they were measured in (`data_groove`), m: a value their
/// file leaves out is null, never the preset's (the data were not "measured at" it).
#[derive(Serialize)]
pub(super) struct DataGroove {
    radius: Option<f64>,
    width: Option<f64>,
}

impl DataGroove {
    pub(super) fn of(g: &crate::lab::Groove) -> DataGroove {
        let [r, b] = g.stated;
        DataGroove {
            radius: r.then_some(g.radius),
            width: b.then_some(g.width),
        }
    }
}

/// `fit --format json`: values the data do not determine null, times rounded.
pub(super) fn text(fit: FitJson) -> String {
    let mut json = serde_json::to_value(fit).expect("plain data serializes");
    for fit in ["model_fit", "mu_alone", "velocity_fit"] {
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
pub(super) struct NotMeasured {
    quantity: &'static str,
    reason: String,
}

/// The line fit's values that are null for `fits`: a_t and μ_k,t without a rim mark's
/// v_t in the window, the line fit's `why_no_v_t` or `no_v_t` (a mark whose turn a
/// frame cannot be followed) saying why; the whole `line_fit` where it could not be
/// made, with why.
pub(super) fn not_measured(fits: &Fits, no_v_t: Option<&str>) -> Vec<NotMeasured> {
    let Some(l) = &fits.line_fit else {
        return vec![NotMeasured {
            quantity: "line_fit",
            reason: fits
                .no_line_fit
                .as_ref()
                .map_or_else(|| "not possible".into(), |e| format!("not possible: {e}")),
        }];
    };
    let reason = no_v_t.unwrap_or(l.why_no_v_t().reason());
    [
        ("line_fit.a_t", l.a_t),
        ("line_fit.a_t_se", l.a_t_se),
        ("line_fit.mu_t", l.mu_t),
        ("line_fit.mu_t_se", l.mu_t_se),
    ]
    .into_iter()
    .filter(|(_, v)| !v.is_finite())
    .map(|(quantity, _)| NotMeasured {
        quantity,
        reason: reason.into(),
    })
    .collect()
}
