//! Presets: named scenes as TOML text (`presets/*.toml`, embedded in the binary, or a
//! user's file, read at the edge by `input::preset`), optionally carrying a measured
//! velocity series; the text form read and written here.

use std::path::PathBuf;

use crate::settings::params::Key;
use crate::settings::spec::SceneSpec;
use crate::settings::units::{UnitError, parse_quantity};
use crate::study::measured::{MAX_ROWS, Measured, MeasuredParts, OutOfLabRange, Rule};

/// The preset used when none is named.
pub const DEFAULT: &str = "paper-b4.9";

/// Built-in presets, in the order `groovelab presets` lists them.
const BUILT_IN: &[(&str, &str)] = &[
    ("paper-b3.5", include_str!("../../presets/paper-b3.5.toml")),
    ("paper-b4.4", include_str!("../../presets/paper-b4.4.toml")),
    ("paper-b4.9", include_str!("../../presets/paper-b4.9.toml")),
    ("flat-table", include_str!("../../presets/flat-table.toml")),
    ("critical", include_str!("../../presets/critical.toml")),
    (
        "unequal-speeds",
        include_str!("../../presets/unequal-speeds.toml"),
    ),
    ("inelastic", include_str!("../../presets/inelastic.toml")),
    (
        "steel-and-glass",
        include_str!("../../presets/steel-and-glass.toml"),
    ),
];

/// Where a preset came from.
#[derive(Clone, Debug, PartialEq)]
pub enum PresetOrigin {
    BuiltIn,
    File(PathBuf),
}

#[derive(Clone, Debug, PartialEq)]
pub struct Preset {
    pub name: String,
    pub description: String,
    pub source: Option<String>,
    pub spec: SceneSpec,
    pub measured: Option<Measured>,
    pub origin: PresetOrigin,
}

#[derive(Debug, thiserror::Error)]
pub enum PresetError {
    #[error("malformed preset {name}: {reason}")]
    Malformed { name: String, reason: Malformed },
}

/// What is wrong in a preset's text.
#[derive(Debug, thiserror::Error)]
pub enum Malformed {
    /// Not TOML of a preset's shape (toml's own message, without its excerpt).
    #[error("{}", .0.message())]
    Toml(toml::de::Error),
    #[error("unknown scene key '{}', allowed: {}", crate::settings::quote::clip(key), Key::ALL.map(|k| k.name()).join(", "))]
    UnknownKey { key: String },
    #[error("{}: {source}", key.name())]
    Quantity { key: Key, source: UnitError },
    #[error("{} = {value}: expected a number or a quantity such as \"2.75cm\"", key.name())]
    NotAQuantity { key: Key, value: toml::Value },
    #[error("{} is not finite", key.name())]
    NotFinite { key: Key },
    #[error(transparent)]
    Measured(MeasuredError),
}

/// What is wrong in a preset's measured series (`name`: a column's key).
#[derive(Debug, thiserror::Error)]
pub enum MeasuredError {
    #[error("measured series differ in length: t {t}, v_cm {v_cm}, v_t {v_t}")]
    Lengths { t: usize, v_cm: usize, v_t: usize },
    #[error("measured series has {0} points, allowed at most {MAX_ROWS}")]
    TooMany(usize),
    #[error("measured series needs at least 2 points")]
    TooFew,
    #[error("measured t[{0}] is not finite, allowed finite numbers")]
    TimeNotFinite(usize),
    #[error("measured {name}[{i}] is not finite, allowed finite numbers or nan (missing)")]
    Infinite { name: &'static str, i: usize },
    #[error("measured times must increase")]
    NotIncreasing,
    #[error("measured {name} has {len} values, t has {t}: allowed the same length")]
    ColumnLength {
        name: &'static str,
        len: usize,
        t: usize,
    },
    #[error(transparent)]
    Magnitude(#[from] OutOfLabRange),
    #[error("measured series: {0}")]
    Rule(#[from] Rule),
}

#[derive(serde::Deserialize)]
#[serde(deny_unknown_fields)]
struct PresetToml {
    name: String,
    description: String,
    source: Option<String>,
    scene: toml::Table,
    measured: Option<MeasuredFile>,
}

#[derive(serde::Deserialize)]
#[serde(deny_unknown_fields)]
struct MeasuredFile {
    t: Vec<f64>,
    v_cm: Vec<f64>,
    v_t: Vec<f64>,
    /// The optional columns of a series derived from a track ([`Measured`]'s fields).
    v_cm_sigma: Option<Vec<f64>>,
    v_t_sigma: Option<Vec<f64>>,
    x: Option<Vec<f64>>,
    angle: Option<Vec<f64>>,
}

impl Preset {
    /// Parses a preset's TOML text; `label` names it in errors.
    pub fn parse(text: &str, label: &str, origin: PresetOrigin) -> Result<Preset, PresetError> {
        let malformed = |reason: Malformed| PresetError::Malformed {
            name: label.to_string(),
            reason,
        };
        let file: PresetToml = toml::from_str(text).map_err(|e| malformed(Malformed::Toml(e)))?;
        let mut spec = SceneSpec::default();
        for (key_name, value) in &file.scene {
            let key = Key::from_name(key_name).ok_or_else(|| {
                malformed(Malformed::UnknownKey {
                    key: key_name.clone(),
                })
            })?;
            let si = match value {
                toml::Value::Float(f) => *f,
                toml::Value::Integer(i) => *i as f64,
                toml::Value::String(s) => parse_quantity(s, key.dimension())
                    .map_err(|source| malformed(Malformed::Quantity { key, source }))?,
                other => {
                    let value = other.clone();
                    return Err(malformed(Malformed::NotAQuantity { key, value }));
                }
            };
            if !si.is_finite() {
                return Err(malformed(Malformed::NotFinite { key }));
            }
            spec.set(key, si);
        }
        let measured = file
            .measured
            .map(|m| check_measured(m).map_err(|e| malformed(Malformed::Measured(e))))
            .transpose()?;
        Ok(Preset {
            name: file.name,
            description: file.description,
            source: file.source,
            spec,
            measured,
            origin,
        })
    }

    /// The built-in preset of this name, if there is one.
    pub fn built_in_named(name: &str) -> Option<Result<Preset, PresetError>> {
        BUILT_IN
            .iter()
            .find(|(n, _)| *n == name)
            .map(|(n, text)| Preset::parse(text, n, PresetOrigin::BuiltIn))
    }

    pub fn built_in() -> Vec<Preset> {
        BUILT_IN
            .iter()
            .map(|(name, text)| {
                Preset::parse(text, name, PresetOrigin::BuiltIn)
                    .expect("built-in presets are tested")
            })
            .collect()
    }
}

fn check_measured(m: MeasuredFile) -> Result<Measured, MeasuredError> {
    if m.t.len() != m.v_cm.len() || m.t.len() != m.v_t.len() {
        return Err(MeasuredError::Lengths {
            t: m.t.len(),
            v_cm: m.v_cm.len(),
            v_t: m.v_t.len(),
        });
    }
    if m.t.len() > MAX_ROWS {
        return Err(MeasuredError::TooMany(m.t.len()));
    }
    if m.t.len() < 2 {
        return Err(MeasuredError::TooFew);
    }
    // TOML writes inf and nan as plain floats. Times must be finite; a value may be
    // nan (a missing mark, as a saved position track has), never infinite.
    if let Some(i) = m.t.iter().position(|v| !v.is_finite()) {
        return Err(MeasuredError::TimeNotFinite(i));
    }
    for (name, series) in [("v_cm", &m.v_cm), ("v_t", &m.v_t)] {
        if let Some(i) = series.iter().position(|v| v.is_infinite()) {
            return Err(MeasuredError::Infinite { name, i });
        }
    }
    if !m.t.windows(2).all(|w| w[0] < w[1]) {
        return Err(MeasuredError::NotIncreasing);
    }
    for (name, column) in [
        ("v_cm_sigma", &m.v_cm_sigma),
        ("v_t_sigma", &m.v_t_sigma),
        ("x", &m.x),
        ("angle", &m.angle),
    ] {
        if let Some(c) = column.as_ref().filter(|c| c.len() != m.t.len()) {
            return Err(MeasuredError::ColumnLength {
                name,
                len: c.len(),
                t: m.t.len(),
            });
        }
    }
    let measured = Measured::new(MeasuredParts {
        t: m.t,
        v_cm: m.v_cm,
        v_t: m.v_t,
        v_cm_sigma: m.v_cm_sigma,
        v_t_sigma: m.v_t_sigma,
        x: m.x,
        angle: m.angle,
        ..MeasuredParts::default()
    })?;
    measured.check_magnitudes()?;
    Ok(measured)
}

/// A preset file's text for `spec` (SI numbers), written by the toml serializer so
/// that any name or description comes out quoted right.
pub fn to_toml(
    name: &str,
    description: &str,
    spec: &SceneSpec,
    measured: Option<&Measured>,
) -> Result<String, toml::ser::Error> {
    #[derive(serde::Serialize)]
    struct Out<'a> {
        name: &'a str,
        description: &'a str,
        scene: toml::Table,
        #[serde(skip_serializing_if = "Option::is_none")]
        measured: Option<&'a Measured>,
    }
    let scene = spec
        .given()
        .map(|(k, v)| (k.name().to_string(), toml::Value::Float(v)))
        .collect();
    toml::to_string(&Out {
        name,
        description,
        scene,
        measured,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_built_in_preset_parses_and_resolves() {
        for p in Preset::built_in() {
            let (scene, _) = p
                .spec
                .resolve()
                .unwrap_or_else(|e| panic!("{}: {e}", p.name));
            assert!(scene.radius > 0.0, "{}", p.name);
            assert!(!p.description.is_empty());
        }
    }

    #[test]
    fn unknown_keys_are_errors() {
        let text = "name = \"x\"\ndescription = \"d\"\n[scene]\nradius = 0.02\nwidht = 0.01\n";
        let err = Preset::parse(text, "x", PresetOrigin::BuiltIn).unwrap_err();
        assert!(err.to_string().contains("widht"), "{err}");
        let text = "name = \"x\"\ndescription = \"d\"\ncolour = 1\n[scene]\n";
        assert!(Preset::parse(text, "x", PresetOrigin::BuiltIn).is_err());
    }

    #[test]
    fn measured_series_round_trip_with_their_optional_columns() {
        let m = Measured::new(MeasuredParts {
            t: vec![-0.1, 0.0, 0.1],
            v_cm: vec![0.8, 0.7, -0.2],
            v_t: vec![0.8, f64::NAN, 0.3],
            x: Some(vec![-0.08, 0.0, 0.01]),
            v_cm_sigma: Some(vec![0.01; 3]),
            ..MeasuredParts::default()
        })
        .unwrap();
        let spec = SceneSpec::default().with(Key::Radius, 0.0275);
        let text = to_toml("x", "d", &spec, Some(&m)).unwrap();
        let back = Preset::parse(&text, "x", PresetOrigin::BuiltIn).unwrap();
        let got = back.measured.unwrap();
        assert_eq!((got.t(), got.v_cm(), got.x()), (m.t(), m.v_cm(), m.x()));
        assert!(got.v_t()[1].is_nan() && got.v_t()[2] == 0.3);
        assert_eq!(got.v_cm_sigma(), m.v_cm_sigma());
        assert_eq!(got.angle(), None);
        let short = text.replace("x = [-0.08, 0.0, 0.01]", "x = [-0.08]");
        assert!(short != text, "{text}");
        let err = Preset::parse(&short, "x", PresetOrigin::BuiltIn).unwrap_err();
        assert!(err.to_string().contains("measured x has 1 values"), "{err}");
    }

    #[test]
    fn measured_series_must_be_finite() {
        let text = "name = \"x\"\ndescription = \"d\"\n[scene]\n[measured]\nt = [0.0, 0.01, 0.02]\nv_cm = [1.0, inf, -1.0]\nv_t = [1.0, 1.0, 1.0]\n";
        let e = Preset::parse(text, "x", PresetOrigin::BuiltIn).unwrap_err();
        assert!(e.to_string().contains("v_cm[1] is not finite"), "{e}");
    }

    #[test]
    fn quantities_with_units_are_read() {
        let text =
            "name = \"x\"\ndescription = \"d\"\n[scene]\nradius = \"2.75cm\"\nmass = \"167g\"\n";
        let p = Preset::parse(text, "x", PresetOrigin::BuiltIn).unwrap();
        assert_eq!(p.spec.get(Key::Radius), Some(0.0275));
        assert_eq!(p.spec.get(Key::MassRight), Some(0.167));
        let bad = "name = \"x\"\ndescription = \"d\"\n[scene]\nradius = \"2.75kg\"\n";
        assert!(Preset::parse(bad, "x", PresetOrigin::BuiltIn).is_err());
    }
}
