//! The lab's layers of settings — the table's defaults ← the preset ← the command
//! line's flags ← the edits made in the app, newest last — and the one rule that
//! settles them into a checked scene, its span and how the span ends. An edit is a
//! layer entry: undo pops it; a reset is an entry too (the edits before it stop
//! counting), and so is another preset picked (the scene starts over from it), so an
//! accidental reset or pick can be undone like any change. Under the flags, over the
//! preset, lie the values the data in use measure (v0 from the approach): the user's
//! own data while loaded and not dropped, else the preset's own series — whichever
//! preset is the template, it gives only what the data leave out. Where each settled
//! value came from is `origin`'s.

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
    /// A fit's values applied (the Fit view's `a`): set as by [`Edit::Values`], but
    /// a value the data in use measure (v0) stays the data's (its origin `Data`):
    /// the fit's, not a value the user chose, so the next fit still frees it.
    Fitted(Vec<(Key, f64)>),
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
    /// What the edits up to each one add up to (`sums[i]` after `edits[i]`), so that
    /// settling the newest costs the same however long the history is.
    sums: Vec<Sum>,
}

/// What the edits up to one of them add up to: everything [`Layers::settle`] and the
/// questions about the edits need, made from the sum before it and that one edit.
#[derive(Clone, Debug, Default)]
struct Sum {
    /// Where the edits in force start: after the newest reset or preset picked.
    from: usize,
    /// Where the newest preset picked is, if any.
    picked: Option<usize>,
    /// Whether the user's data were dropped (by any edit up to this one).
    dropped: bool,
    /// Whether an edit in force changes the scene (any but a drop of the data).
    changes: bool,
    /// The values the edits in force set, newer over older.
    values: SceneSpec,
    /// Those of them a fit's values applied set last ([`Edit::Fitted`]).
    fitted: Vec<Key>,
    /// What the edits in force do to how the span ends.
    end: EndRule,
}

impl Sum {
    /// The sum after `edit`, the `at`-th edit, given the sum before it.
    fn then(&self, at: usize, edit: &Edit) -> Sum {
        let fresh = Sum {
            from: at + 1,
            dropped: self.dropped,
            ..Sum::default()
        };
        match edit {
            Edit::Reset => Sum {
                picked: self.picked,
                ..fresh
            },
            Edit::Preset(_) => Sum {
                picked: Some(at),
                ..fresh
            },
            Edit::DropData => Sum {
                dropped: true,
                values: self.values.clone(),
                fitted: self.fitted.clone(),
                ..*self
            },
            Edit::Values(changes) | Edit::Fitted(changes) => {
                let mut values = self.values.clone();
                let mut end = self.end;
                let mut fitted = self.fitted.clone();
                fitted.retain(|k| changes.iter().all(|(c, _)| c != k));
                for &(key, value) in changes {
                    values.set(key, value);
                    end = end.then(EndRule::of(key, value));
                    if matches!(edit, Edit::Fitted(_)) {
                        fitted.push(key);
                    }
                }
                Sum {
                    changes: true,
                    values,
                    fitted,
                    end,
                    ..*self
                }
            }
            Edit::SpanEnd(e) => Sum {
                changes: true,
                values: self.values.clone(),
                fitted: self.fitted.clone(),
                end: EndRule::Set(*e),
                ..*self
            },
        }
    }
}

/// What a run of values set does to how the span ends, whatever it was before.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
enum EndRule {
    /// Leaves it.
    #[default]
    Keep,
    /// Ends a preset's `t_end` (a value of the scene changed).
    EndPreset,
    /// Sets it (a `t_end` typed, or the span key).
    Set(SpanEnd),
}

impl EndRule {
    /// What setting `key` to `value` does: a `t_end` fixes the end, a value of the
    /// scene ends a preset's `t_end`.
    fn of(key: Key, value: f64) -> EndRule {
        match key {
            Key::TEnd => EndRule::Set(SpanEnd::Fixed {
                t_end: value,
                from_preset: false,
            }),
            _ if key.param().of_scene() => EndRule::EndPreset,
            _ => EndRule::Keep,
        }
    }

    /// This rule, then `next`.
    fn then(self, next: EndRule) -> EndRule {
        match (self, next) {
            (rule, EndRule::Keep) => rule,
            (_, EndRule::Set(end)) => EndRule::Set(end),
            (EndRule::Set(end), EndRule::EndPreset) => EndRule::Set(EndRule::EndPreset.on(end)),
            (_, EndRule::EndPreset) => EndRule::EndPreset,
        }
    }

    /// How the span ends after this rule, if it ended as `end` before.
    fn on(self, end: SpanEnd) -> SpanEnd {
        match (self, end) {
            (EndRule::Keep, end) => end,
            (
                EndRule::EndPreset,
                SpanEnd::Fixed {
                    from_preset: true, ..
                },
            ) => SpanEnd::Auto,
            (EndRule::EndPreset, end) => end,
            (EndRule::Set(end), _) => end,
        }
    }
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
            sums: Vec::new(),
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
        match self.top().picked.map(|at| &self.edits[at]) {
            Some(Edit::Preset(p)) => Some(p),
            _ => None,
        }
    }

    /// What the edits add up to (the empty sum before the first).
    fn top(&self) -> std::borrow::Cow<'_, Sum> {
        self.sums.last().map_or_else(
            || std::borrow::Cow::Owned(Sum::default()),
            std::borrow::Cow::Borrowed,
        )
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
        let sum = self.top().then(self.edits.len(), &edit);
        self.sums.push(sum);
        self.edits.push(edit);
    }

    /// Takes back the newest edit, if there is one.
    pub fn undo(&mut self) -> Option<Edit> {
        self.sums.pop();
        self.edits.pop()
    }

    /// The edits that count: those after the newest reset or preset picked.
    pub fn in_force(&self) -> &[Edit] {
        &self.edits[self.top().from..]
    }

    /// Whether the user's own data were dropped (by an edit still on the list).
    pub fn data_dropped(&self) -> bool {
        self.top().dropped
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

    /// The values the edits in force set, newer over older.
    pub(super) fn edited(&self) -> SceneSpec {
        self.top().values.clone()
    }

    /// The keys whose value in force a fit's values applied set last
    /// ([`Edit::Fitted`]).
    pub(super) fn fitted(&self) -> Vec<Key> {
        self.top().fitted.clone()
    }

    /// Sets every edit aside (the scene as the preset and the flags give it); false,
    /// and nothing added, when none that changes the scene is in force. Undo brings
    /// them back.
    pub fn reset(&mut self) -> bool {
        if !self.top().changes {
            return false;
        }
        self.push(Edit::Reset);
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
        // The edits in force, summed as they were made (a value set on an upper
        // layer replaces the same value below, so the sum goes on top at once).
        let top = self.top();
        let spec = spec.over(&top.values);
        let end = top.end.on(end);
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
        .and_then(|m| crate::study::fit::of_velocities(m.t(), m.v_cm()))
    else {
        return SceneSpec::default();
    };
    let stated = preset
        .spec
        .get(Key::V0)
        .filter(|v| (v - a.speed).abs() <= 2.0 * a.se);
    SceneSpec::default().with(Key::V0, stated.unwrap_or(a.speed))
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
        *end = EndRule::of(key, value).on(*end);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The layers settled by replaying every edit, as before the sums: the
    /// reference the sums must agree with.
    fn replayed(layers: &Layers) -> (Result<(Scene, Span, SpanEnd), SceneError>, bool, bool) {
        let edits = &layers.edits;
        let picked = edits.iter().rev().find_map(|e| match e {
            Edit::Preset(p) => Some(&**p),
            _ => None,
        });
        let preset = picked.unwrap_or(&layers.start);
        let flags = picked.is_none().then_some(&layers.flags);
        let from = edits
            .iter()
            .rposition(|e| matches!(e, Edit::Reset | Edit::Preset(_)))
            .map_or(0, |i| i + 1);
        let dropped = edits.contains(&Edit::DropData);
        let mut spec = preset.spec.clone();
        let mut end = match spec.get(Key::TEnd) {
            Some(t_end) => SpanEnd::Fixed {
                t_end,
                from_preset: true,
            },
            None => SpanEnd::Auto,
        };
        let mut upper = flags.cloned().unwrap_or_default();
        let data = match (&layers.from_data, dropped) {
            (Some(own), false) => own.clone(),
            _ => values_of_preset(preset),
        };
        spec = spec.over(&data);
        if let Some(flags) = flags {
            let flags: Vec<(Key, f64)> = flags.given().collect();
            replay_values(&mut spec, &mut end, &flags);
        }
        for edit in &edits[from..] {
            match edit {
                Edit::Values(changes) | Edit::Fitted(changes) => {
                    replay_values(&mut spec, &mut end, changes);
                    for &(k, v) in changes {
                        upper.set(k, v);
                    }
                }
                Edit::SpanEnd(e) => end = *e,
                Edit::Reset | Edit::Preset(_) | Edit::DropData => {}
            }
        }
        let mut spec = spec.without(Key::TEnd);
        if let SpanEnd::Fixed { t_end, .. } = end {
            spec.set(Key::TEnd, t_end);
        }
        let settled = spec.resolve().map(|(scene, span)| (scene, span, end));
        let touched = |k: Key| {
            crate::settings::params::PARAMS.iter().any(|p| {
                (p.key == k || p.replaces == Some(k)) && upper.given().any(|(j, _)| j == p.key)
            })
        };
        let own_v0 =
            data.get(Key::V0).is_some() && !Key::V0.param().sets.iter().any(|&k| touched(k));
        (settled, dropped, own_v0)
    }

    /// `set_values` as it was before the sums, written out on its own.
    fn replay_values(spec: &mut SceneSpec, end: &mut SpanEnd, changes: &[(Key, f64)]) {
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

    /// A small deterministic generator (the same edits on every run).
    struct Seeded(u64);

    impl Seeded {
        fn below(&mut self, n: usize) -> usize {
            self.0 = self
                .0
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            ((self.0 >> 33) % n as u64) as usize
        }
    }

    /// A random edit: values (in range or not, several at once), a span end, a reset,
    /// another preset, the data dropped.
    fn edit(draw: &mut Seeded, presets: &[Preset]) -> Edit {
        const KEYS: [(Key, [f64; 3]); 9] = [
            (Key::Width, [0.049, 0.050, 0.5]),
            (Key::TEnd, [0.8, 2.0, -1.0]),
            (Key::V0, [0.3, 0.5, 0.0]),
            (Key::V0Left, [0.4, 0.2, 1e9]),
            (Key::Height, [0.01, 0.02, 0.03]),
            (Key::HeightLeft, [0.015, 0.005, 0.02]),
            (Key::Mass, [0.05, 0.07, 0.06]),
            (Key::Mu, [0.17, 0.1, 0.3]),
            (Key::Restitution, [0.9, 0.5, 1.0]),
        ];
        match draw.below(10) {
            0..=4 => Edit::Values(
                (0..1 + draw.below(3))
                    .map(|_| {
                        let (key, values) = KEYS[draw.below(KEYS.len())];
                        (key, values[draw.below(3)])
                    })
                    .collect(),
            ),
            5 => Edit::SpanEnd(
                [
                    SpanEnd::Auto,
                    SpanEnd::Scaled(2.0),
                    SpanEnd::Fixed {
                        t_end: 1.5,
                        from_preset: false,
                    },
                ][draw.below(3)],
            ),
            6 => Edit::Reset,
            7 => Edit::Preset(Box::new(presets[draw.below(presets.len())].clone())),
            _ => Edit::DropData,
        }
    }

    #[test]
    fn the_sums_settle_as_replaying_every_edit_does() {
        // The built-in presets, and one with a `t_end` of its own (none has one).
        let mut presets = Preset::built_in();
        let mut timed = presets[0].clone();
        timed.name = "timed".into();
        timed.spec.set(Key::TEnd, 0.9);
        presets.push(timed);
        for seed in 0..40 {
            let mut draw = Seeded(seed);
            // Every fourth lab starts from the preset with a `t_end`.
            let start = presets[if seed % 4 == 0 {
                presets.len() - 1
            } else {
                draw.below(presets.len())
            }]
            .clone();
            let mut flags = SceneSpec::default();
            if seed % 2 == 0 {
                flags.set(Key::Mu, 0.2);
            }
            if seed % 3 == 0 {
                flags.set(Key::Height, 0.01);
            }
            let mut layers = Layers::new(start, flags);
            if seed % 4 != 1 {
                layers.from_data = Some(SceneSpec::default().with(Key::V0, 0.45));
            }
            for _ in 0..60 {
                match draw.below(6) {
                    0 => {
                        layers.undo();
                    }
                    1 => {
                        layers.reset();
                    }
                    _ => layers.push(edit(&mut draw, &presets)),
                }
                let (settled, dropped, own_v0) = replayed(&layers);
                assert_eq!(layers.settle(), settled, "seed {seed}: {:?}", layers.edits);
                assert_eq!(layers.data_dropped(), dropped, "seed {seed}");
                assert_eq!(layers.from_the_data(Key::V0), own_v0, "seed {seed}");
            }
        }
    }

    /// Settling reads the sum of the edits, not the edits: with the history below
    /// the newest edit overwritten by values no scene allows, the newest settles as
    /// before (replaying every edit, an edit cost O(edits so far): 990 µs a re-solve
    /// after a few hundred thousand edits instead of 9 µs).
    #[test]
    fn an_edit_costs_the_same_however_long_the_history() {
        let preset = Preset::built_in().swap_remove(0);
        let mut layers = Layers::new(preset, SceneSpec::default().with(Key::Mu, 0.2));
        layers.from_data = Some(SceneSpec::default().with(Key::V0, 0.45));
        for i in 0..1000 {
            let width = if i % 2 == 0 { 0.049 } else { 0.050 };
            layers.push(Edit::Values(vec![(Key::Width, width)]));
        }
        layers.push(Edit::DropData);
        layers.push(Edit::Values(vec![(Key::Mu, 0.15)]));
        let before = (
            layers.settle(),
            layers.data_dropped(),
            layers.from_the_data(Key::V0),
        );
        assert!(before.0.is_ok());
        let newest = layers.edits.len() - 1;
        for edit in &mut layers.edits[..newest] {
            *edit = Edit::Values(vec![(Key::Width, f64::NAN)]);
        }
        let after = (
            layers.settle(),
            layers.data_dropped(),
            layers.from_the_data(Key::V0),
        );
        assert_eq!(after, before, "the old edits were read again");
        assert!(
            replayed(&layers).0.is_err(),
            "replaying the overwritten history fails"
        );
    }
}
