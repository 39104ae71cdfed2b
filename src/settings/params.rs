//! The one table of scene parameters — name, flag, symbol, label, unit, physical range,
//! steps, default, help, and how the value is read from and written to a scene — and
//! the layers of settings (defaults, preset, command line, app) read through it:
//! settings in, a checked SI [`Scene`] out.
//!
//! The command line's scene options and their conflicts (`cli::args`), preset reading
//! and saving (`study::preset`), validation and its messages, the app's parameter rows,
//! values and change labels, sweep axes and `--help` all come from [`PARAMS`]. Adding a
//! parameter is one row here and its physics.

use crate::physics::scene::{Scene, Span};
use crate::settings::units::{Dimension, show};

mod row;
mod rows;

pub use row::{Fallback, Key, Param, Range, Steps};
pub use rows::PARAMS;

impl Param {
    /// `--help`'s text: the help and, for a value with a default, `[default: …]` in
    /// the unit people read.
    pub fn help_text(&self) -> String {
        match self.default {
            Fallback::Value(v) => format!("{} [default: {}]", self.help, show(v, self.dim)),
            _ => self.help.to_string(),
        }
    }

    /// The row's label as the app's screen writes it, in messages too: `mu` as μ (an
    /// ASCII screen spells it back as `mu`).
    pub fn screen_label(&self) -> String {
        self.label.replace("mu", "μ")
    }

    /// True for a row that holds a value of its own in a layer; false for one that
    /// sets others (`mass` sets both masses).
    pub fn is_own(&self) -> bool {
        self.sets == [self.key]
    }

    /// The rows that contradict this one on one command line: those that set a key
    /// that one of this row's keys replaces (`--height-left` and `--v0-left`, `--v0`).
    pub fn conflicts(&self) -> impl Iterator<Item = &'static Param> + '_ {
        let replaced: Vec<Key> = self
            .sets
            .iter()
            .filter_map(|k| k.param().replaces)
            .collect();
        PARAMS
            .iter()
            .filter(move |q| q.sets.iter().any(|k| replaced.contains(k)))
    }

    /// Whether it is a value of the balls (a mass, a speed, a release height), not of
    /// the groove, the scene as a whole or the span.
    pub fn of_ball(&self) -> bool {
        let (mut scene, mut span) = (Scene::DEFAULT, Span::DEFAULT);
        (self.set)(&mut scene, &mut span, 0.5);
        scene.left != Scene::DEFAULT.left || scene.right != Scene::DEFAULT.right
    }

    /// Whether it is a value of the scene (what sweeps vary), not of the simulated
    /// span: writing it leaves a span as it was.
    pub fn of_scene(&self) -> bool {
        let span = Span {
            t_start: -1.0,
            t_end: Some(1.0),
        };
        let (mut scene, mut written) = (Scene::DEFAULT, span);
        (self.set)(&mut scene, &mut written, 0.5);
        written == span
    }
}

impl Key {
    /// Every key, in the table's order.
    pub const ALL: [Key; PARAMS.len()] = {
        let mut keys = [Key::Radius; PARAMS.len()];
        let mut i = 0;
        while i < PARAMS.len() {
            keys[i] = PARAMS[i].key;
            i += 1;
        }
        keys
    };

    /// This key's row of the table.
    pub fn param(self) -> &'static Param {
        &PARAMS[self as usize]
    }

    /// The name in preset files.
    pub fn name(self) -> &'static str {
        self.param().name
    }

    pub fn dimension(self) -> Dimension {
        self.param().dim
    }

    pub fn from_name(name: &str) -> Option<Key> {
        PARAMS.iter().find(|p| p.name == name).map(|p| p.key)
    }

    /// This parameter's value in a scene and span, SI (`None`: a span without a
    /// fixed end).
    pub fn get(self, scene: &Scene, span: &Span) -> Option<f64> {
        (self.param().get)(scene, span)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_table_is_in_key_order_and_flags_follow_names() {
        for (i, p) in PARAMS.iter().enumerate() {
            assert_eq!(p.key as usize, i, "{}", p.name);
            assert_eq!(p.flag, p.name.replace('_', "-"));
            assert!(p.range.lo < p.range.hi, "{}", p.name);
        }
    }

    #[test]
    fn ball_rows_are_told_from_the_grooves_and_the_spans() {
        let balls: Vec<&str> = PARAMS
            .iter()
            .filter(|p| p.of_ball())
            .map(|p| p.name)
            .collect();
        assert_eq!(
            balls,
            [
                "mass",
                "mass_left",
                "mass_right",
                "v0",
                "v0_left",
                "v0_right",
                "height",
                "height_left",
                "height_right"
            ]
        );
        assert!(
            PARAMS
                .iter()
                .filter(|p| !p.of_scene())
                .all(|p| !p.of_ball())
        );
    }

    /// Every number of a scene is some row's: `resolve` starts from
    /// [`Scene::DEFAULT`] and must overwrite all of it, so a field no row writes
    /// would silently keep its default. Each own row writes a value no default has.
    #[test]
    fn every_field_of_a_scene_is_some_rows() {
        let (mut scene, mut span) = (Scene::DEFAULT, Span::DEFAULT);
        for p in PARAMS.iter().filter(|p| p.is_own() && p.replaces.is_none()) {
            (p.set)(&mut scene, &mut span, 0.123456789);
        }
        let json = serde_json::to_value(scene).unwrap();
        let mut leaves = Vec::new();
        fn walk(path: String, v: &serde_json::Value, out: &mut Vec<(String, f64)>) {
            match v {
                serde_json::Value::Object(m) => {
                    for (k, v) in m {
                        walk(format!("{path}.{k}"), v, out);
                    }
                }
                other => out.push((path, other.as_f64().unwrap_or(f64::NAN))),
            }
        }
        walk("scene".into(), &json, &mut leaves);
        assert!(leaves.len() >= 8, "{leaves:?}");
        for (path, v) in leaves {
            assert_eq!(v, 0.123456789, "no row of the table writes {path}");
        }
    }
}
