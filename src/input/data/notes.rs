//! What a reader found beside the numbers, for `groovelab data` to show: the format,
//! the tracks in the file, and how each unit was decided (the header, an option, a
//! video's calibration, or nobody: SI assumed and checked for plausibility).

use serde::Serialize;

/// What a file said about itself.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct Notes {
    /// The format detected, e.g. "Tracker project (.trk)".
    pub format: String,
    /// The tracks found (position files), in file order; "" is a plain x, y file.
    pub tracks: Vec<String>,
    /// How each quantity's unit was decided.
    pub units: Vec<UnitNote>,
    /// The line number of the file's last line when it is cut short (no line end,
    /// fewer cells than the line before: an export stopped mid-row), dropped.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub cut_row: Option<usize>,
    /// A velocity file's first impact in the file's own time, s (its times are then
    /// shifted to put the impact at t = 0).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub impact_in_file: Option<f64>,
}

/// One quantity's unit and who decided it.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct UnitNote {
    /// "time", "length", "v_cm", "v_t".
    pub quantity: &'static str,
    /// The unit, e.g. "ms", or "1.105 mm" for a scale.
    pub unit: String,
    /// "the header", "--time-unit", "the video's calibration (904.8 px/m)",
    /// "none stated: read as s".
    pub how: String,
}

impl UnitNote {
    /// The note of a unit of SI factor `factor` named in `units`, said by `by` (the
    /// header or an option), or assumed SI when nobody said it.
    pub fn of(
        quantity: &'static str,
        units: &[(&'static str, f64)],
        factor: f64,
        by: Option<&'static str>,
    ) -> UnitNote {
        let si = units.first().map_or("", |u| u.0);
        let unit = super::scales::unit_name(units, factor).map_or_else(
            || format!("{} {si}", crate::settings::units::significant(factor, 4)),
            str::to_string,
        );
        UnitNote {
            quantity,
            unit,
            how: match by {
                Some(by) => by.to_string(),
                None => format!("none stated: read as {si}, and the numbers fit it"),
            },
        }
    }
}
