//! Where each value of a fit's scene came from ([`crate::lab::Origin`], the lab's one
//! rule) — the command line, the data file's `# scene` lines, the data themselves (v0
//! from the approach: the user's, else the preset's own series), or the preset — the
//! values that nobody measured or gave yet enter a reported number (the mass, in F_net
//! and τ_net: assumed), and an option that contradicts the data: said on the scene
//! line and in JSON.

use std::collections::BTreeMap;

use serde::Serialize;

use crate::cli::args::{DataArgs, SceneArgs};
use crate::lab::Lab;
use crate::lab::{Contradiction, Whose, approach};
use crate::settings::params::Key;
use crate::settings::units::{Dimension, show, show_below, significant};
use crate::study::fit::Approach;

use crate::lab::Origin as Source;

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
    /// (the masses, in |F_net|, |τ_net| and the energies): the preset's, assumed for
    /// the user's data.
    pub assumed: Vec<&'static str>,
    /// Whose data the `data` values were measured in: the file(s) named, or `preset
    /// NAME's series`; `null` without data.
    pub data: Option<String>,
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
    /// The sources of `lab`'s scene ([`crate::lab::Layers::origin`]): the command
    /// line's `typed` values, the data file's own scene lines, the data's own values.
    pub fn of(lab: &Lab, typed: &SceneArgs, data: &DataArgs) -> Sources {
        let settings = lab.settings();
        let values: BTreeMap<&'static str, Source> = SCENE
            .iter()
            .map(|&k| (k.name(), settings.origin(k)))
            .collect();
        let assumed = SCENE
            .iter()
            .filter(|k| values.get(k.name()) == Some(&Source::Assumed))
            .map(|k| k.name())
            .collect();
        let file = data.data.first().map(|p| p.display().to_string());
        let whose = match lab.data_in_use().map(|d| &d.whose) {
            Some(Whose::Own(name)) => Some(name.clone()),
            Some(Whose::Preset(name)) => Some(format!("preset {name}'s series")),
            None => None,
        };
        let by = |c: &Contradiction| match c.origin {
            Source::Flag => "--v0".to_string(),
            Source::File => format!("{}'s header", file.as_deref().unwrap_or("the file")),
            _ => "edited".to_string(),
        };
        Sources {
            preset: lab.preset().name.clone(),
            values,
            assumed,
            data: whose,
            approach: lab.series().and_then(approach),
            contradictions: lab
                .contradiction
                .iter()
                .map(|c| c.describe(&by(c)))
                .collect(),
            typed_rows: typed.values.rows(),
            preset_asked: typed.preset.is_some(),
            file,
        }
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
        let from_preset = !self.keys(Source::Preset).is_empty() || !self.assumed.is_empty();
        if self.preset_asked || from_preset {
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
            parts.push(
                match self.data.as_deref().filter(|w| w.starts_with("preset ")) {
                    Some(_) => "v0 from the approach in its series".to_string(),
                    None => "v0 from the data's approach".to_string(),
                },
            );
        }
        if !self.typed_rows.is_empty() {
            let typed: Vec<String> = self
                .typed_rows
                .iter()
                .map(|k| format!("--{}", k.param().flag))
                .collect();
            parts.push(typed.join(" "));
        }
        // The one value among the options that nobody typed: the R a `--data` video
        // was tracked with (its tracks state it, as a track file's header does).
        let untyped_radius = flags.contains(&Key::Radius)
            && !self
                .typed_rows
                .iter()
                .any(|t| t.param().sets.contains(&Key::Radius));
        if let Some(name) = self.file.as_ref().filter(|n| {
            untyped_radius && super::super::video_data::is_video(std::path::Path::new(n))
        }) {
            parts.push(format!("{name}'s tracks (radius)"));
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
            show_below(scene.width, 2.0 * scene.radius, Dimension::Length),
            show(scene.left.mass, Dimension::Mass),
            show(scene.right.mass, Dimension::Mass),
            show(scene.left.v0, Dimension::Speed),
            show(scene.right.v0, Dimension::Speed),
            significant(scene.mu, 4),
            significant(scene.restitution, 4),
        )
    }
}
