//! Where each settled scene value came from ([`Origin`]): an edit in the app, a flag
//! (or the data file's `# scene` line among them), the data in use, the preset — and
//! the masses, which no data measure, named assumed under the user's data. The one
//! rule the app's marks, `fit`'s sources and the notes read.

use crate::settings::params::Key;
use crate::settings::spec::SceneSpec;

use super::settings::Layers;

/// Where a settled scene value came from: the mark beside it on every screen.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Origin {
    /// Changed in the app.
    Edited,
    /// An option on the command line.
    Flag,
    /// The data file's own `# scene` lines.
    File,
    /// Measured in the data in use (v0: their approach speed).
    Data,
    /// The preset's (or the table's default), the data being silent.
    Preset,
    /// The preset's value for one no data measure (the masses), while the user's own
    /// data are in use: an assumption that enters F_net, τ_net and the energies.
    Assumed,
}

impl Origin {
    /// Every origin, in the order the legend lists them.
    pub const ALL: [Origin; 6] = [
        Origin::Data,
        Origin::Flag,
        Origin::File,
        Origin::Preset,
        Origin::Edited,
        Origin::Assumed,
    ];

    /// The one-letter mark beside a value in the app's parameters panel.
    pub fn mark(self) -> char {
        match self {
            Origin::Edited => 'e',
            Origin::Flag => 'f',
            Origin::File => 'h',
            Origin::Data => 'd',
            Origin::Preset => 'p',
            Origin::Assumed => 'a',
        }
    }

    /// The legend's word for the mark: "data", "flag", "header" (the data file's
    /// `# scene` lines), "preset", "edited", "assumed".
    pub fn legend(self) -> &'static str {
        match self {
            Origin::File => "header",
            o => o.word(),
        }
    }

    /// The word for it: "data", "flag", "file", "preset", "edited", "assumed".
    pub fn word(self) -> &'static str {
        match self {
            Origin::Edited => "edited",
            Origin::Flag => "flag",
            Origin::File => "file",
            Origin::Data => "data",
            Origin::Preset => "preset",
            Origin::Assumed => "assumed",
        }
    }
}

/// True when the layer `spec` sets the per-ball key `k` or what replaces it (a
/// release height replaces v0).
fn touches(spec: &SceneSpec, k: Key) -> bool {
    crate::settings::params::PARAMS
        .iter()
        .any(|p| (p.key == k || p.replaces == Some(k)) && spec.given().any(|(j, _)| j == p.key))
}

impl Layers {
    /// True when the settled value of `key` (e.g. `v0`) is the data's own: the data
    /// give it, and no flag in force or edit sets it or what replaces it (a release
    /// height).
    pub fn from_the_data(&self, key: Key) -> bool {
        self.origin(key) == Origin::Data
    }

    /// Where the settled value of `key` came from: an edit in force, a flag in force
    /// (or the data file's `# scene` line among them), the data in use, else the
    /// preset (named assumed for a value no data measure — the masses — while the
    /// user's own data are in use). A key setting both balls' (`v0`) is named by its
    /// left ball's.
    pub fn origin(&self, key: Key) -> Origin {
        // A release height shows the v0 it stands for: its origin is that v0's.
        let k = key.param().replaces.unwrap_or(key).param().sets[0];
        if touches(&self.edited(), k) {
            // A fit's value applied for one the data measure is still the data's.
            let fitted = self
                .fitted()
                .iter()
                .any(|f| *f == k || f.param().sets.contains(&k));
            return if fitted && self.data_values().get(k).is_some() {
                Origin::Data
            } else {
                Origin::Edited
            };
        }
        if let Some(flags) = self.flags_in_force()
            && touches(flags, k)
        {
            return if self.file_keys.contains(&k) {
                Origin::File
            } else {
                Origin::Flag
            };
        }
        if self.data_values().get(k).is_some() {
            return Origin::Data;
        }
        if matches!(k, Key::MassLeft | Key::MassRight) && self.own_data_in_use() {
            return Origin::Assumed;
        }
        Origin::Preset
    }

    /// True when a ball's mass is assumed ([`Origin::Assumed`]): what F_net, τ_net
    /// and the energies say beside them.
    pub fn mass_assumed(&self) -> bool {
        [Key::MassLeft, Key::MassRight]
            .into_iter()
            .any(|k| self.origin(k) == Origin::Assumed)
    }
}
