//! Where each value of a fit's scene came from — the command line, the data file's
//! `# scene` lines, the data themselves (v0 from the approach), or the preset — the
//! values that nobody measured or gave yet enter a reported number (the mass, in F_net
//! and τ_net: assumed), and an option that contradicts the data: said on the scene
//! line and in JSON.

use std::collections::BTreeMap;

use serde::Serialize;

use crate::cli::args::{DataArgs, SceneArgs};
use crate::lab::Lab;
use crate::lab::approach;
use crate::settings::params::Key;
use crate::settings::units::{Dimension, show, show_exact, significant, with_uncertainty};
use crate::study::fit::Approach;

/// Where one scene value came from.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub(super) enum Source {
    /// An option on the command line.
    Flag,
    /// The data file's own `# scene` lines.
    File,
    /// Measured in the data (v0: the approach speed).
    Data,
    /// The preset under the rest.
    Preset,
}

/// The values of a scene, each with its source.
const SCENE: [Key; 10] = [
    Key::Radius,
    Key::Width,
    Key::MassLeft,
    Key::MassRight,
    Key::Mu,
    Key::V0Left,
    Key::V0Right,
    Key::Restitution,
    Key::RollingResistance,
    Key::G,
];

/// Where a fit's scene came from (JSON `sources`).
#[derive(Debug, Serialize)]
pub(super) struct Sources {
    /// The preset under the rest, by name.
    pub preset: String,
    /// Each scene value (by its parameter name) and where it came from.
    pub values: BTreeMap<&'static str, Source>,
    /// Values no option, file line or measurement gives that enter a reported number
    /// (the masses, in |F_net| and |τ_net|): the preset's, assumed for the user's data.
    pub assumed: Vec<&'static str>,
    /// The approach speed the data measure (the v0 they give), m/s.
    pub approach: Option<Approach>,
    /// Values given that contradict the data by more than the data's ± 2σ.
    pub contradictions: Vec<String>,
    /// The options as typed (`--mass`, not `--mass-left --mass-right`).
    #[serde(skip)]
    typed_rows: Vec<Key>,
    #[serde(skip)]
    preset_asked: bool,
    #[serde(skip)]
    file: Option<String>,
}

impl Sources {
    /// The sources of `lab`'s scene: the command line's `typed` values, the data
    /// file's own scene lines (the rest of `used`), the data's own values.
    pub fn of(lab: &Lab, typed: &SceneArgs, used: &SceneArgs, data: &DataArgs) -> Sources {
        let given = |spec: &crate::settings::spec::SceneSpec, k: Key| {
            let height = match k {
                Key::V0Left => Some(Key::HeightLeft),
                Key::V0Right => Some(Key::HeightRight),
                _ => None,
            };
            spec.given().any(|(j, _)| j == k || Some(j) == height)
        };
        let own = lab.own_data().is_some();
        let source = |k: Key| {
            if given(&typed.values, k) {
                Source::Flag
            } else if given(&used.values, k) {
                Source::File
            } else if own && given(&lab.settings().from_data, k) {
                Source::Data
            } else {
                Source::Preset
            }
        };
        let values: BTreeMap<&'static str, Source> =
            SCENE.iter().map(|&k| (k.name(), source(k))).collect();
        let assumed = [Key::MassLeft, Key::MassRight]
            .into_iter()
            .filter(|&k| own && typed.preset.is_none() && source(k) == Source::Preset)
            .map(Key::name)
            .collect();
        let approach = lab.own_data().and_then(|o| approach(&o.series));
        let file = data.data.first().map(|p| p.display().to_string());
        let mut out = Sources {
            preset: lab.preset().name.clone(),
            values,
            assumed,
            approach,
            contradictions: Vec::new(),
            typed_rows: typed.values.rows(),
            preset_asked: typed.preset.is_some(),
            file,
        };
        out.contradictions = out.contradicted(lab);
        out
    }

    fn source(&self, k: Key) -> Source {
        self.values.get(k.name()).copied().unwrap_or(Source::Preset)
    }

    fn keys(&self, s: Source) -> Vec<Key> {
        SCENE
            .iter()
            .copied()
            .filter(|&k| self.source(k) == s)
            .collect()
    }

    /// The given v0 that the data's approach speed contradicts by more than its ± 2σ.
    fn contradicted(&self, lab: &Lab) -> Vec<String> {
        let Some(a) = self.approach else {
            return Vec::new();
        };
        let v0 = lab.scene.left.v0;
        let by = match self.source(Key::V0Left) {
            Source::Flag => "--v0".to_string(),
            Source::File => format!("{}'s header", self.file.as_deref().unwrap_or("the file")),
            _ => return Vec::new(),
        };
        if (v0 - a.speed).abs() <= 2.0 * a.se {
            return Vec::new();
        }
        let (speed, pm) = with_uncertainty(a.speed, 2.0 * a.se, 3);
        vec![format!(
            "the left ball's v0 = {} ({by}) contradicts the data: they approach at {speed} ± {pm} m/s (± 2σ, {} frames before the impact); the value given is used",
            show(v0, Dimension::Speed),
            a.frames
        )]
    }

    /// "m = 167 g (assumed: preset paper-b4.9's)", for the note under |F_net| and
    /// |τ_net|; `None` when the masses were given.
    pub fn assumed_mass(&self, lab: &Lab) -> Option<String> {
        (!self.assumed.is_empty()).then(|| {
            format!(
                "|F_net| and |τ_net| take m = {}: assumed (preset {}'s value), as the data do not measure it; give yours with --mass",
                show(lab.scene.left.mass, Dimension::Mass),
                self.preset
            )
        })
    }

    /// The scene a fit used, and where it came from: the scene line of the table, and
    /// under it where the data were measured if that is another groove, and a value
    /// given that contradicts the data.
    pub fn scene_line(&self, lab: &Lab) -> String {
        let scene = &lab.scene;
        let len = |v: f64| show(v, Dimension::Length);
        let (flags, file, data) = (
            self.keys(Source::Flag),
            self.keys(Source::File),
            self.keys(Source::Data),
        );
        let mut parts = Vec::new();
        if self.preset_asked || !self.keys(Source::Preset).is_empty() {
            // Named as it came: the user's `--preset`, or the default under the rest.
            let default = if self.preset_asked { "" } else { "default " };
            parts.push(format!("{default}preset {}", self.preset));
        }
        if let Some(name) = self.file.as_ref().filter(|_| !file.is_empty()) {
            parts.push(if parts.is_empty() {
                format!("from {name}'s header")
            } else {
                let names: Vec<&str> = file.iter().map(|k| k.name()).collect();
                format!("{name}'s header ({})", names.join(", "))
            });
        }
        if !data.is_empty() {
            parts.push("v0 from the data's approach".to_string());
        }
        if !flags.is_empty() {
            let typed: Vec<String> = self
                .typed_rows
                .iter()
                .map(|k| format!("--{}", k.param().flag))
                .collect();
            parts.push(typed.join(" "));
        }
        let source = match parts.as_slice() {
            [] => unreachable!("a preset, the file's header, data or flags give the scene"),
            [one] => one.clone(),
            [first, rest @ ..] => format!("{first} with {}", rest.join(" and ")),
        };
        let mut tail = String::new();
        // Data of another groove are never fitted without saying so.
        if let Some(o) = &lab.other_groove {
            tail += &format!("data: {}\n", o.describe());
        }
        for c in &self.contradictions {
            tail += &format!("note: {c}\n");
        }
        let assumed = if self.assumed.is_empty() {
            ""
        } else {
            " (assumed)"
        };
        format!(
            "scene ({source}): R = {}, b = {}, m = {} / {}{assumed}, v0 = {} / {}, μ_k = {} (start), e = {}\n{tail}",
            len(scene.radius),
            // Every digit given: b = 5.4999 cm at four digits reads 5.5 cm = 2R.
            show_exact(scene.width, Dimension::Length),
            show(scene.left.mass, Dimension::Mass),
            show(scene.right.mass, Dimension::Mass),
            show(scene.left.v0, Dimension::Speed),
            show(scene.right.v0, Dimension::Speed),
            significant(scene.mu, 4),
            significant(scene.restitution, 4),
        )
    }
}
