//! The one table of scene parameters — name, flag, symbol, label, unit, physical range,
//! steps, default, help, and how the value is read from and written to a scene — and
//! the layers of settings (defaults, preset, command line, app) read through it:
//! settings in, a checked SI [`Scene`] out.
//!
//! The command line's scene options and their conflicts (`cli::args`), preset reading
//! and saving (`study::preset`), validation and its messages, the app's parameter rows,
//! values and change labels, sweep axes and `--help` all come from [`PARAMS`]. Adding a
//! parameter is one row here and its physics.

use crate::physics::closed_form::{release_height, release_speed};
use crate::physics::scene::{Scene, Span};
use crate::physics::solution::LATEST_END;
use crate::settings::units::{Dimension, show};

/// A setting that a layer may give.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Key {
    Radius,
    Width,
    Mass,
    MassLeft,
    MassRight,
    Mu,
    V0,
    V0Left,
    V0Right,
    Height,
    HeightLeft,
    HeightRight,
    Restitution,
    RollingResistance,
    G,
    TStart,
    TEnd,
}

/// The physical range of a parameter, SI. Bounds are inclusive unless `open`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Range {
    pub lo: f64,
    pub hi: f64,
    pub lo_open: bool,
    /// Readable form for messages and `--help`, in the units a lab uses.
    pub text: &'static str,
}

impl Range {
    pub fn contains(&self, v: f64) -> bool {
        v.is_finite()
            && v <= self.hi
            && if self.lo_open {
                v > self.lo
            } else {
                v >= self.lo
            }
    }
}

/// Steps of ←/→ (fine) and Shift+←/→ (coarse) in the app, SI.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Steps {
    pub fine: f64,
    pub coarse: f64,
}

/// What a layer that does not give a value means.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Fallback {
    /// This value, SI (shown in `--help` as `[default: …]`).
    Value(f64),
    /// The scene needs it: a preset or a flag must give it.
    Required,
    /// Nothing: a release height is only a way to give a speed; without `t_end` the
    /// span follows the physics.
    Optional,
}

/// One scene parameter: everything every front end needs to know about it.
#[derive(Clone, Copy, Debug)]
pub struct Param {
    pub key: Key,
    /// Name in preset files; the flag is `--` and the name with `-` for `_`.
    pub name: &'static str,
    pub flag: &'static str,
    /// What messages call it.
    pub symbol: &'static str,
    /// The app's row label (ASCII; `mu` is drawn as μ where the screen can).
    pub label: &'static str,
    pub dim: Dimension,
    pub range: Range,
    /// The keys this one sets (`mass` sets both masses).
    pub sets: &'static [Key],
    /// Steps in the app; `None`: not a row of the app's parameter panel.
    pub steps: Option<Steps>,
    /// `--help`'s text, without the default (see [`Param::help_text`]).
    pub help: &'static str,
    pub default: Fallback,
    /// The key this one gives instead, for the same ball: a release height gives the
    /// speed, so the two contradict on the command line and one drops the other in a
    /// layer.
    pub replaces: Option<Key>,
    /// The value in a scene and span, SI (`None`: a span without a fixed end).
    pub get: fn(&Scene, &Span) -> Option<f64>,
    /// Writes the value (SI, checked) into a scene and span. A row that
    /// [`replaces`](Param::replaces) another computes it from the rest of the scene.
    pub set: fn(&mut Scene, &mut Span, f64),
}

const fn range(lo: f64, hi: f64, lo_open: bool, text: &'static str) -> Range {
    Range {
        lo,
        hi,
        lo_open,
        text,
    }
}

const MASS: Range = range(1e-6, 1000.0, false, "1 mg ≤ m ≤ 1000 kg");
const SPEED: Range = range(-100.0, 100.0, false, "-100 m/s ≤ v0 ≤ 100 m/s");
const MASS_STEPS: Option<Steps> = Some(Steps {
    fine: 0.001,
    coarse: 0.01,
});
const HEIGHT: Range = range(0.0, 500.0, false, "0 ≤ h ≤ 500 m");
const HEIGHT_STEPS: Option<Steps> = Some(Steps {
    fine: 0.002,
    coarse: 0.02,
});
const SPEED_STEPS: Option<Steps> = Some(Steps {
    fine: 0.01,
    coarse: 0.1,
});

/// Every scene parameter, in the order of `--help`, preset files and the app's panel
/// (an array, so `&PARAMS` iterates; its length is counted from [`ROWS`]).
pub const PARAMS: [Param; ROWS.len()] = {
    let mut rows = [ROWS[0]; ROWS.len()];
    let mut i = 0;
    while i < ROWS.len() {
        rows[i] = ROWS[i];
        i += 1;
    }
    rows
};

/// The table as written: one row per parameter, in [`Key`]'s order.
const ROWS: &[Param] = &[
    Param {
        key: Key::Radius,
        name: "radius",
        flag: "radius",
        symbol: "radius R",
        label: "R",
        dim: Dimension::Length,
        range: range(1e-4, 10.0, false, "0.1 mm ≤ R ≤ 10 m"),
        sets: &[Key::Radius],
        steps: Some(Steps {
            fine: 0.0005,
            coarse: 0.005,
        }),
        help: "Ball radius R (e.g. 2.75cm)",
        default: Fallback::Required,
        replaces: None,
        get: |s, _| Some(s.radius),
        set: |s, _, v| s.radius = v,
    },
    Param {
        key: Key::Width,
        name: "width",
        flag: "width",
        symbol: "groove width b",
        label: "b",
        dim: Dimension::Length,
        // The upper end, 2R, depends on R: checked in `resolve`.
        range: range(0.0, 20.0, false, "0 ≤ b < 2R"),
        sets: &[Key::Width],
        steps: Some(Steps {
            fine: 0.0005,
            coarse: 0.005,
        }),
        help: "Groove width b, 0 ≤ b < 2R (e.g. 4.9cm)",
        default: Fallback::Required,
        replaces: None,
        get: |s, _| Some(s.width),
        set: |s, _, v| s.width = v,
    },
    Param {
        key: Key::Mass,
        name: "mass",
        flag: "mass",
        symbol: "mass",
        label: "m",
        dim: Dimension::Mass,
        range: MASS,
        sets: &[Key::MassLeft, Key::MassRight],
        steps: None,
        help: "Mass of both balls (e.g. 167g)",
        default: Fallback::Required,
        replaces: None,
        get: |s, _| Some(s.left.mass),
        set: |s, _, v| (s.left.mass, s.right.mass) = (v, v),
    },
    Param {
        key: Key::MassLeft,
        name: "mass_left",
        flag: "mass-left",
        symbol: "left mass",
        label: "m left",
        dim: Dimension::Mass,
        range: MASS,
        sets: &[Key::MassLeft],
        steps: MASS_STEPS,
        help: "Mass of the left ball",
        default: Fallback::Required,
        replaces: None,
        get: |s, _| Some(s.left.mass),
        set: |s, _, v| s.left.mass = v,
    },
    Param {
        key: Key::MassRight,
        name: "mass_right",
        flag: "mass-right",
        symbol: "right mass",
        label: "m right",
        dim: Dimension::Mass,
        range: MASS,
        sets: &[Key::MassRight],
        steps: MASS_STEPS,
        help: "Mass of the right ball",
        default: Fallback::Required,
        replaces: None,
        get: |s, _| Some(s.right.mass),
        set: |s, _, v| s.right.mass = v,
    },
    Param {
        key: Key::Mu,
        name: "mu",
        flag: "mu",
        symbol: "μ_k",
        label: "mu_k",
        dim: Dimension::Ratio,
        range: range(0.0, 10.0, false, "0 ≤ μ_k ≤ 10"),
        sets: &[Key::Mu],
        steps: Some(Steps {
            fine: 0.01,
            coarse: 0.05,
        }),
        help: "Kinetic friction coefficient μ_k, 0 ≤ μ_k ≤ 10",
        default: Fallback::Required,
        replaces: None,
        get: |s, _| Some(s.mu),
        set: |s, _, v| s.mu = v,
    },
    Param {
        key: Key::V0,
        name: "v0",
        flag: "v0",
        symbol: "v0",
        label: "v0 (both)",
        dim: Dimension::Speed,
        range: SPEED,
        sets: &[Key::V0Left, Key::V0Right],
        steps: SPEED_STEPS,
        help: "Speed of both balls toward the impact point just before it (e.g. 60cm/s)",
        default: Fallback::Required,
        replaces: None,
        get: |s, _| Some(s.left.v0),
        set: |s, _, v| (s.left.v0, s.right.v0) = (v, v),
    },
    Param {
        key: Key::V0Left,
        name: "v0_left",
        flag: "v0-left",
        symbol: "left v0",
        label: "v0 left",
        dim: Dimension::Speed,
        range: SPEED,
        sets: &[Key::V0Left],
        steps: SPEED_STEPS,
        help: "Speed of the left ball toward the impact point",
        default: Fallback::Required,
        replaces: None,
        get: |s, _| Some(s.left.v0),
        set: |s, _, v| s.left.v0 = v,
    },
    Param {
        key: Key::V0Right,
        name: "v0_right",
        flag: "v0-right",
        symbol: "right v0",
        label: "v0 right",
        dim: Dimension::Speed,
        range: SPEED,
        sets: &[Key::V0Right],
        steps: SPEED_STEPS,
        help: "Speed of the right ball toward the impact point",
        default: Fallback::Required,
        replaces: None,
        get: |s, _| Some(s.right.v0),
        set: |s, _, v| s.right.v0 = v,
    },
    Param {
        key: Key::Height,
        name: "height",
        flag: "height",
        symbol: "release height h",
        label: "h",
        dim: Dimension::Length,
        range: HEIGHT,
        sets: &[Key::HeightLeft, Key::HeightRight],
        steps: None,
        help: "Release height on the run-up instead of v0 (both balls)",
        default: Fallback::Optional,
        replaces: Some(Key::V0),
        get: |s, _| Some(release_height(s.left.v0, s.k(), s.g)),
        set: |s, _, h| {
            let v = release_speed(h, s.k(), s.g);
            (s.left.v0, s.right.v0) = (v, v);
        },
    },
    // One row per ball in the app: each ball's own run-up, so the panel never shows
    // one ball's height for both when their speeds differ.
    Param {
        key: Key::HeightLeft,
        name: "height_left",
        flag: "height-left",
        symbol: "left release height",
        label: "h left",
        dim: Dimension::Length,
        range: HEIGHT,
        sets: &[Key::HeightLeft],
        steps: HEIGHT_STEPS,
        help: "Release height of the left ball on its run-up instead of its v0",
        default: Fallback::Optional,
        replaces: Some(Key::V0Left),
        get: |s, _| Some(release_height(s.left.v0, s.k(), s.g)),
        set: |s, _, h| s.left.v0 = release_speed(h, s.k(), s.g),
    },
    Param {
        key: Key::HeightRight,
        name: "height_right",
        flag: "height-right",
        symbol: "right release height",
        label: "h right",
        dim: Dimension::Length,
        range: HEIGHT,
        sets: &[Key::HeightRight],
        steps: HEIGHT_STEPS,
        help: "Release height of the right ball on its run-up instead of its v0",
        default: Fallback::Optional,
        replaces: Some(Key::V0Right),
        get: |s, _| Some(release_height(s.right.v0, s.k(), s.g)),
        set: |s, _, h| s.right.v0 = release_speed(h, s.k(), s.g),
    },
    Param {
        key: Key::Restitution,
        name: "restitution",
        flag: "restitution",
        symbol: "restitution e",
        label: "e",
        dim: Dimension::Ratio,
        range: range(0.0, 1.0, false, "0 ≤ e ≤ 1"),
        sets: &[Key::Restitution],
        steps: Some(Steps {
            fine: 0.01,
            coarse: 0.1,
        }),
        help: "Coefficient of restitution e, 0 ≤ e ≤ 1",
        default: Fallback::Value(Scene::DEFAULT.restitution),
        replaces: None,
        get: |s, _| Some(s.restitution),
        set: |s, _, v| s.restitution = v,
    },
    Param {
        key: Key::RollingResistance,
        name: "rolling_resistance",
        flag: "rolling-resistance",
        symbol: "rolling resistance c_rr",
        label: "c_rr",
        dim: Dimension::Ratio,
        range: range(0.0, 1.0, false, "0 ≤ c_rr ≤ 1"),
        sets: &[Key::RollingResistance],
        steps: Some(Steps {
            fine: 0.001,
            coarse: 0.01,
        }),
        help: "Rolling-resistance coefficient c_rr, 0 ≤ c_rr ≤ 1",
        default: Fallback::Value(Scene::DEFAULT.rolling_resistance),
        replaces: None,
        get: |s, _| Some(s.rolling_resistance),
        set: |s, _, v| s.rolling_resistance = v,
    },
    Param {
        key: Key::G,
        name: "g",
        flag: "g",
        symbol: "g",
        label: "g",
        dim: Dimension::Acceleration,
        range: range(0.01, 1000.0, false, "0.01 m/s² ≤ g ≤ 1000 m/s²"),
        sets: &[Key::G],
        steps: None,
        help: "Gravity",
        default: Fallback::Value(Scene::DEFAULT.g),
        replaces: None,
        get: |s, _| Some(s.g),
        set: |s, _, v| s.g = v,
    },
    Param {
        key: Key::TStart,
        name: "t_start",
        flag: "t-start",
        symbol: "t_start",
        label: "t start",
        dim: Dimension::Time,
        range: range(
            -1000.0,
            0.0,
            false,
            "-1000 s ≤ t_start ≤ 0 s (the first impact is at t = 0)",
        ),
        sets: &[Key::TStart],
        steps: None,
        help: "Start of the simulated span, -1000 s ≤ t_start ≤ 0",
        default: Fallback::Value(Span::DEFAULT.t_start),
        replaces: None,
        get: |_, span| Some(span.t_start),
        set: |_, span, v| span.t_start = v,
    },
    Param {
        key: Key::TEnd,
        name: "t_end",
        flag: "t-end",
        symbol: "t_end",
        label: "t end",
        dim: Dimension::Time,
        // The lower end, t_start, depends on the span: checked in `resolve`.
        range: range(-1000.0, LATEST_END, true, "t_start < t_end ≤ 1e6 s"),
        sets: &[Key::TEnd],
        steps: None,
        help: "End of the simulated span, ≤ 1e6 s [default: the preset's, or a little past the last event]",
        default: Fallback::Optional,
        replaces: None,
        get: |_, span| span.t_end,
        set: |_, span, v| span.t_end = Some(v),
    },
];

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
