//! The lab's layers of settings — the table's defaults ← the preset ← the command
//! line's flags ← the edits made in the app, newest last — and the one rule that
//! settles them into a checked scene, its span and how the span ends. An edit is a
//! layer entry: undo pops it; a reset is an entry too (the edits before it stop
//! counting), and so is another preset picked (the scene starts over from it), so an
//! accidental reset or pick can be undone like any change. Under the flags, over the
//! preset, lie the values the data in use measure (v0 from the approach): the user's
//! own data while loaded and not dropped, else the preset's own series — whichever
//! preset is the template, it gives only what the data leave out. [`Origin`] says
//! where each settled value came from.

use crate::physics::scene::{Scene, Span};
use crate::settings::params::Key;
use crate::settings::spec::{SceneError, SceneSpec};
use crate::study::preset::Preset;

use super::span::SpanEnd;

/// One change made in the app: values set together (all or none), or how the span
/// ends (the span key).
#[derive(Clone, Debug, PartialEq)]
pub enum Edit {
    Values(Vec<(Key, f64)>),
    SpanEnd(SpanEnd),
    /// Every earlier edit set aside: the scene as the preset and the flags give it.
    Reset,
    /// Another preset picked: the scene starts over from it alone (the command line's
    /// values and every earlier edit set aside, as by a reset).
    Preset(Box<Preset>),
    /// The user's own data dropped (a scene value is not changed; undo brings them
    /// back).
    DropData,
}

/// The layers a lab's scene is settled from (the defaults are the table's own).
#[derive(Clone, Debug)]
pub struct Layers {
    /// The preset the lab started from (see [`Layers::preset`] for the one in use).
    start: Preset,
    /// The command line's values, SI (in force until another preset is picked).
    pub flags: SceneSpec,
    /// The data file whose `# scene` lines are among `flags`, as the user named it.
    pub scene_file: Option<String>,
    /// The values the user's own data measure (v0 from the approach), `Some` while
    /// the user's own data are loaded: over the preset (any preset, picked or not),
    /// under the flags and edits, until the data are dropped (then the preset's own
    /// series give theirs, [`Layers::data_values`]).
    pub from_data: Option<SceneSpec>,
    /// The keys (per ball) among `flags` that the data file's `# scene` lines gave.
    pub file_keys: Vec<Key>,
    /// The app's edits, oldest first.
    edits: Vec<Edit>,
}

impl Layers {
    pub fn new(preset: Preset, flags: SceneSpec) -> Layers {
        Layers {
            start: preset,
            flags,
            scene_file: None,
            from_data: None,
            file_keys: Vec::new(),
            edits: Vec::new(),
        }
    }

    /// Where the scene comes from, for the status line: `scene of FILE` while a data
    /// file's `# scene` lines give it (with the options over them), else `preset NAME`.
    pub fn source(&self) -> String {
        match (&self.scene_file, self.flags_in_force()) {
            (Some(file), Some(_)) => format!("scene of {}", file_name(file)),
            _ => format!("preset {}", self.preset().name),
        }
    }

    /// The preset the scene starts from: the one picked last, else the lab's first.
    pub fn preset(&self) -> &Preset {
        self.picked().unwrap_or(&self.start)
    }

    /// The preset picked last in the app, if any.
    fn picked(&self) -> Option<&Preset> {
        self.edits.iter().rev().find_map(|e| match e {
            Edit::Preset(p) => Some(&**p),
            _ => None,
        })
    }

    /// The command line's values while they are in force (until a preset is picked).
    pub fn flags_in_force(&self) -> Option<&SceneSpec> {
        self.picked().is_none().then_some(&self.flags)
    }

    /// The app's edits, oldest first.
    pub fn edits(&self) -> &[Edit] {
        &self.edits
    }

    /// Adds an edit on top (check it with [`Layers::settle`]; [`Layers::undo`]
    /// takes it back).
    pub fn push(&mut self, edit: Edit) {
        self.edits.push(edit);
    }

    /// Takes back the newest edit, if there is one.
    pub fn undo(&mut self) -> Option<Edit> {
        self.edits.pop()
    }

    /// The edits that count: those after the newest reset or preset picked.
    pub fn in_force(&self) -> &[Edit] {
        let from = self
            .edits
            .iter()
            .rposition(|e| matches!(e, Edit::Reset | Edit::Preset(_)))
            .map_or(0, |i| i + 1);
        &self.edits[from..]
    }

    /// Whether the user's own data were dropped (by an edit still on the list).
    pub fn data_dropped(&self) -> bool {
        self.edits.contains(&Edit::DropData)
    }

    /// The values the data in use measure: the user's own while loaded and not
    /// dropped, else the preset's own series' (a preset's series are its data; its
    /// file's values give only what they leave out).
    pub fn data_values(&self) -> SceneSpec {
        match (&self.from_data, self.data_dropped()) {
            (Some(own), false) => own.clone(),
            _ => values_of_preset(self.preset()),
        }
    }

    /// True when the user's own data are loaded and not dropped.
    pub fn own_data_in_use(&self) -> bool {
        self.from_data.is_some() && !self.data_dropped()
    }

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
        let mut edited = SceneSpec::default();
        for edit in self.in_force() {
            if let Edit::Values(changes) = edit {
                for &(k, v) in changes {
                    edited.set(k, v);
                }
            }
        }
        if touches(&edited, k) {
            return Origin::Edited;
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

    /// Sets every edit aside (the scene as the preset and the flags give it); false,
    /// and nothing added, when none that changes the scene is in force. Undo brings
    /// them back.
    pub fn reset(&mut self) -> bool {
        if self.in_force().iter().all(|e| *e == Edit::DropData) {
            return false;
        }
        self.edits.push(Edit::Reset);
        true
    }

    /// The scene, its span and how the span ends, by the span rule (see [`SpanEnd`]):
    /// a preset's `t_end` holds until a layer above changes a value of the scene;
    /// `--t-end` or a typed `t_end` is kept through later changes; the span key
    /// chooses the automatic span or a multiple of it. The span's `t_end` is the fixed
    /// end, if any (the solve gives the shown one).
    pub fn settle(&self) -> Result<(Scene, Span, SpanEnd), SceneError> {
        let mut spec = self.preset().spec.clone();
        let mut end = match spec.get(Key::TEnd) {
            Some(t_end) => SpanEnd::Fixed {
                t_end,
                from_preset: true,
            },
            None => SpanEnd::Auto,
        };
        spec = spec.over(&self.data_values());
        if let Some(flags) = self.flags_in_force() {
            let flags: Vec<(Key, f64)> = flags.given().collect();
            set_values(&mut spec, &mut end, &flags);
        }
        for edit in self.in_force() {
            match edit {
                Edit::Values(changes) => set_values(&mut spec, &mut end, changes),
                Edit::SpanEnd(e) => end = *e,
                // `in_force` starts after the newest reset or preset picked; a drop
                // of the data changes no value.
                Edit::Reset | Edit::Preset(_) | Edit::DropData => {}
            }
        }
        // The end is `end`'s alone: a fixed one is checked with the scene.
        let mut spec = spec.without(Key::TEnd);
        if let SpanEnd::Fixed { t_end, .. } = end {
            spec.set(Key::TEnd, t_end);
        }
        let (scene, span) = spec.resolve()?;
        Ok((scene, span, end))
    }
}

/// The scene values a preset's own series measure (its v0: the approach), as its
/// file states them where they agree within the series' ± 2σ (the preset's value is
/// that measurement, rounded as the preset wrote it), else as the series give them.
pub fn values_of_preset(preset: &Preset) -> SceneSpec {
    let Some(a) = preset
        .measured
        .as_ref()
        .and_then(|m| crate::study::fit::of_velocities(&m.t, &m.v_cm))
    else {
        return SceneSpec::default();
    };
    let stated = preset
        .spec
        .get(Key::V0)
        .filter(|v| (v - a.speed).abs() <= 2.0 * a.se);
    SceneSpec::default().with(Key::V0, stated.unwrap_or(a.speed))
}

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

/// The last part of a path (`ball.csv` of `runs/ball.csv`).
pub fn file_name(path: &str) -> String {
    std::path::Path::new(path)
        .file_name()
        .map_or(path.into(), |f| f.to_string_lossy().into_owned())
}

/// Writes `changes` into a layer's sum and moves the span's end by the rule: a
/// `t_end` fixes it, a value of the scene ends a preset's `t_end`.
fn set_values(spec: &mut SceneSpec, end: &mut SpanEnd, changes: &[(Key, f64)]) {
    for &(key, value) in changes {
        spec.set(key, value);
        *end = match (key, *end) {
            (Key::TEnd, _) => SpanEnd::Fixed {
                t_end: value,
                from_preset: false,
            },
            (
                _,
                SpanEnd::Fixed {
                    from_preset: true, ..
                },
            ) if key.param().of_scene() => SpanEnd::Auto,
            (_, end) => end,
        };
    }
}
