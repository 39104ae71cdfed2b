//! Presets: named scenes as TOML data (`presets/*.toml`, embedded in the binary, or a
//! user's file), optionally carrying a measured velocity series.

use std::path::{Path, PathBuf};

use crate::input::data::MAX_ROWS;
use crate::input::file::{MAX_FILE_BYTES, read_user_file};
use crate::input::params::{Key, SceneSpec};
use crate::input::units::parse_quantity;
use crate::study::measured::Measured;

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
pub enum Origin {
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
    pub origin: Origin,
}

#[derive(Debug, thiserror::Error)]
pub enum PresetError {
    #[error("unknown preset '{0}', allowed: a name from `groovelab presets` or a .toml file")]
    Unknown(String),
    #[error("cannot read preset file {path}: {reason}")]
    Io { path: String, reason: String },
    #[error("malformed preset {name}: {reason}")]
    Malformed { name: String, reason: String },
}

#[derive(serde::Deserialize)]
#[serde(deny_unknown_fields)]
struct PresetFile {
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
    pub fn parse(text: &str, label: &str, origin: Origin) -> Result<Preset, PresetError> {
        let malformed = |reason: String| PresetError::Malformed {
            name: label.to_string(),
            reason,
        };
        let file: PresetFile =
            toml::from_str(text).map_err(|e| malformed(e.message().to_string()))?;
        let mut spec = SceneSpec::default();
        for (key_name, value) in &file.scene {
            let key = Key::from_name(key_name).ok_or_else(|| {
                let allowed: Vec<&str> = Key::ALL.iter().map(|k| k.name()).collect();
                malformed(format!(
                    "unknown scene key '{key_name}', allowed: {}",
                    allowed.join(", ")
                ))
            })?;
            let si = match value {
                toml::Value::Float(f) => *f,
                toml::Value::Integer(i) => *i as f64,
                toml::Value::String(s) => parse_quantity(s, key.dimension())
                    .map_err(|e| malformed(format!("{key_name}: {e}")))?,
                other => {
                    return Err(malformed(format!(
                        "{key_name} = {other}: expected a number or a quantity such as \"2.75cm\""
                    )));
                }
            };
            if !si.is_finite() {
                return Err(malformed(format!("{key_name} is not finite")));
            }
            spec.set(key, si);
        }
        let measured = file
            .measured
            .map(|m| check_measured(m).map_err(malformed))
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

    /// A built-in preset by name, or a preset file by path.
    pub fn load(name_or_path: &str) -> Result<Preset, PresetError> {
        if let Some((_, text)) = BUILT_IN.iter().find(|(n, _)| *n == name_or_path) {
            return Preset::parse(text, name_or_path, Origin::BuiltIn);
        }
        let user = user_dir().map(|d| d.join(format!("{name_or_path}.toml")));
        let path = match user {
            Some(p) if p.exists() => p,
            _ => PathBuf::from(name_or_path),
        };
        if !path.exists() {
            return Err(PresetError::Unknown(name_or_path.to_string()));
        }
        // Something is there: it must be a regular file of sane size (not a FIFO
        // that would block, not /dev/zero).
        let text =
            read_user_file(&path, "preset file", MAX_FILE_BYTES).map_err(|e| PresetError::Io {
                path: path.display().to_string(),
                reason: e.why,
            })?;
        Preset::parse(&text, &path.display().to_string(), Origin::File(path))
    }

    pub fn built_in() -> Vec<Preset> {
        BUILT_IN
            .iter()
            .map(|(name, text)| {
                Preset::parse(text, name, Origin::BuiltIn).expect("built-in presets are tested")
            })
            .collect()
    }

    /// Built-in presets, then the user's (from [`user_dir`]); unreadable user files are
    /// returned as errors beside the good ones.
    pub fn all() -> (Vec<Preset>, Vec<PresetError>) {
        Preset::all_in(user_dir().as_deref())
    }

    /// Built-in presets, then those in `dir` (if any).
    pub fn all_in(dir: Option<&Path>) -> (Vec<Preset>, Vec<PresetError>) {
        let mut presets = Preset::built_in();
        let mut errors = Vec::new();
        if let Some(dir) = dir
            && let Ok(entries) = std::fs::read_dir(dir)
        {
            let mut paths: Vec<PathBuf> = entries
                .filter_map(|e| e.ok().map(|e| e.path()))
                .filter(|p| p.extension().is_some_and(|x| x == "toml"))
                .collect();
            paths.sort();
            for path in paths {
                match Preset::load(&path.display().to_string()) {
                    Ok(p) => presets.push(p),
                    Err(e) => errors.push(e),
                }
            }
        }
        (presets, errors)
    }
}

fn check_measured(m: MeasuredFile) -> Result<Measured, String> {
    if m.t.len() != m.v_cm.len() || m.t.len() != m.v_t.len() {
        return Err(format!(
            "measured series differ in length: t {}, v_cm {}, v_t {}",
            m.t.len(),
            m.v_cm.len(),
            m.v_t.len()
        ));
    }
    if m.t.len() > MAX_ROWS {
        return Err(format!(
            "measured series has {} points, allowed at most {MAX_ROWS}",
            m.t.len()
        ));
    }
    if m.t.len() < 2 {
        return Err("measured series needs at least 2 points".into());
    }
    // TOML writes inf and nan as plain floats. Times must be finite; a value may be
    // nan (a missing mark, as a saved position track has), never infinite.
    if let Some(i) = m.t.iter().position(|v| !v.is_finite()) {
        return Err(format!(
            "measured t[{i}] is not finite, allowed finite numbers"
        ));
    }
    for (name, series) in [("v_cm", &m.v_cm), ("v_t", &m.v_t)] {
        if let Some(i) = series.iter().position(|v| v.is_infinite()) {
            return Err(format!(
                "measured {name}[{i}] is not finite, allowed finite numbers or nan (missing)"
            ));
        }
    }
    if !m.t.windows(2).all(|w| w[0] < w[1]) {
        return Err("measured times must increase".into());
    }
    for (name, column) in [
        ("v_cm_sigma", &m.v_cm_sigma),
        ("v_t_sigma", &m.v_t_sigma),
        ("x", &m.x),
        ("angle", &m.angle),
    ] {
        if let Some(c) = column.as_ref().filter(|c| c.len() != m.t.len()) {
            return Err(format!(
                "measured {name} has {} values, t has {}: allowed the same length",
                c.len(),
                m.t.len()
            ));
        }
    }
    let measured = Measured {
        v_cm_sigma: m.v_cm_sigma,
        v_t_sigma: m.v_t_sigma,
        x: m.x,
        angle: m.angle,
        ..Measured::velocities(m.t, m.v_cm, m.v_t)
    };
    measured.check_magnitudes().map_err(|e| e.to_string())?;
    Ok(measured)
}

/// A preset file's text for `spec` (SI numbers), written by the toml serializer so
/// that any name or description comes out quoted right.
pub fn to_toml(
    name: &str,
    description: &str,
    spec: &SceneSpec,
    measured: Option<&Measured>,
) -> Result<String, String> {
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
    .map_err(|e| format!("cannot write the preset: {e}"))
}

/// Where user presets live: `$GROOVELAB_PRESETS`, else
/// `$XDG_CONFIG_HOME/groovelab/presets`, else `~/.config/groovelab/presets`.
pub fn user_dir() -> Option<PathBuf> {
    if let Some(dir) = std::env::var_os("GROOVELAB_PRESETS") {
        return Some(PathBuf::from(dir));
    }
    let config = std::env::var_os("XDG_CONFIG_HOME")
        .map(PathBuf::from)
        .or_else(|| std::env::var_os("HOME").map(|h| Path::new(&h).join(".config")))?;
    Some(config.join("groovelab").join("presets"))
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
        let err = Preset::parse(text, "x", Origin::BuiltIn).unwrap_err();
        assert!(err.to_string().contains("widht"), "{err}");
        let text = "name = \"x\"\ndescription = \"d\"\ncolour = 1\n[scene]\n";
        assert!(Preset::parse(text, "x", Origin::BuiltIn).is_err());
    }

    #[test]
    fn measured_series_round_trip_with_their_optional_columns() {
        let mut m = Measured::velocities(
            vec![-0.1, 0.0, 0.1],
            vec![0.8, 0.7, -0.2],
            vec![0.8, f64::NAN, 0.3],
        );
        m.x = Some(vec![-0.08, 0.0, 0.01]);
        m.v_cm_sigma = Some(vec![0.01; 3]);
        let spec = SceneSpec::default().with(Key::Radius, 0.0275);
        let text = to_toml("x", "d", &spec, Some(&m)).unwrap();
        let back = Preset::parse(&text, "x", Origin::BuiltIn).unwrap();
        let got = back.measured.unwrap();
        assert_eq!((got.t, got.v_cm, got.x), (m.t, m.v_cm, m.x));
        assert!(got.v_t[1].is_nan() && got.v_t[2] == 0.3);
        assert_eq!(got.v_cm_sigma, m.v_cm_sigma);
        assert_eq!(got.angle, None);
        let short = text.replace("x = [-0.08, 0.0, 0.01]", "x = [-0.08]");
        assert!(short != text, "{text}");
        let err = Preset::parse(&short, "x", Origin::BuiltIn).unwrap_err();
        assert!(err.to_string().contains("measured x has 1 values"), "{err}");
    }

    #[test]
    fn measured_series_must_be_finite() {
        let text = "name = \"x\"\ndescription = \"d\"\n[scene]\n[measured]\nt = [0.0, 0.01, 0.02]\nv_cm = [1.0, inf, -1.0]\nv_t = [1.0, 1.0, 1.0]\n";
        let e = Preset::parse(text, "x", Origin::BuiltIn).unwrap_err();
        assert!(e.to_string().contains("v_cm[1] is not finite"), "{e}");
    }

    #[test]
    fn preset_files_must_be_regular_files() {
        let dir = std::env::temp_dir();
        let e = Preset::load(&dir.display().to_string()).unwrap_err();
        assert!(e.to_string().contains("a directory"), "{e}");
        #[cfg(unix)]
        {
            let e = Preset::load("/dev/zero").unwrap_err();
            assert!(e.to_string().contains("a device"), "{e}");
        }
    }

    #[test]
    fn quantities_with_units_are_read() {
        let text =
            "name = \"x\"\ndescription = \"d\"\n[scene]\nradius = \"2.75cm\"\nmass = \"167g\"\n";
        let p = Preset::parse(text, "x", Origin::BuiltIn).unwrap();
        assert_eq!(p.spec.get(Key::Radius), Some(0.0275));
        assert_eq!(p.spec.get(Key::MassRight), Some(0.167));
        let bad = "name = \"x\"\ndescription = \"d\"\n[scene]\nradius = \"2.75kg\"\n";
        assert!(Preset::parse(bad, "x", Origin::BuiltIn).is_err());
    }
}
