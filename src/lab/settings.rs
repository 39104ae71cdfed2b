//! The lab's layers of settings — the table's defaults ← the preset ← the command
//! line's flags ← the edits made in the app, newest last — and the one rule that
//! settles them into a checked scene, its span and how the span ends. An edit is a
//! layer entry: undo pops it; a reset is an entry too (the edits before it stop
//! counting), and so is another preset picked (the scene starts over from it), so an
//! accidental reset or pick can be undone like any change.

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
    /// The values the user's own data measure (v0 from the approach): over the
    /// preset, under the flags, while the flags are in force and the data not dropped.
    pub from_data: SceneSpec,
    /// The app's edits, oldest first.
    edits: Vec<Edit>,
}

impl Layers {
    pub fn new(preset: Preset, flags: SceneSpec) -> Layers {
        Layers {
            start: preset,
            flags,
            scene_file: None,
            from_data: SceneSpec::default(),
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

    /// True when the settled value of `key` (e.g. `v0`) is the data's own: the data
    /// layer gives it, and no flag in force or edit sets it or what replaces it (a
    /// release height).
    pub fn from_the_data(&self, key: Key) -> bool {
        let Some(flags) = self.flags_in_force() else {
            return false;
        };
        if self.data_dropped() || self.from_data.get(key).is_none() {
            return false;
        }
        let mut upper = flags.clone();
        for edit in self.in_force() {
            if let Edit::Values(changes) = edit {
                for &(k, v) in changes {
                    upper.set(k, v);
                }
            }
        }
        let touched = |k: Key| {
            crate::settings::params::PARAMS.iter().any(|p| {
                (p.key == k || p.replaces == Some(k)) && upper.given().any(|(j, _)| j == p.key)
            })
        };
        !key.param().sets.iter().any(|&k| touched(k))
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
        if let Some(flags) = self.flags_in_force() {
            if !self.data_dropped() {
                spec = spec.over(&self.from_data);
            }
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
