//! The one table of scene parameters — name, flag, symbol, unit, physical range, steps,
//! help and label — and the layers of settings (defaults, preset, command line) that
//! are read through it: settings in, a checked SI [`Scene`] out.
//!
//! The command line's scene options (`cli::args`), preset reading and saving
//! (`input::preset`), validation messages, the TUI's parameter rows and `--help` all
//! come from [`PARAMS`]. Adding a parameter is one row here, one line in
//! [`SceneSpec::resolve`], and its physics.

use crate::input::units::{Dimension, show, show_exact};
use crate::physics::closed_form;
use crate::physics::derived::Derived;
use crate::physics::scene::{Ball, Scene, Span};

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

/// One scene parameter: everything every front end needs to know about it.
#[derive(Clone, Copy, Debug, PartialEq)]
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
    pub help: &'static str,
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

/// Every scene parameter, in the order of `--help`, preset files and the app's panel.
pub const PARAMS: [Param; 17] = [
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
        help: "Coefficient of restitution e, 0 ≤ e ≤ 1 [default: 1]",
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
        help: "Rolling-resistance coefficient c_rr, 0 ≤ c_rr ≤ 1 [default: 0]",
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
        help: "Gravity [default: 9.81 m/s²]",
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
        help: "Start of the simulated span, -1000 s ≤ t_start ≤ 0 [default: -0.2 s]",
    },
    Param {
        key: Key::TEnd,
        name: "t_end",
        flag: "t-end",
        symbol: "t_end",
        label: "t end",
        dim: Dimension::Time,
        // The lower end, t_start, depends on the span: checked in `resolve`.
        range: range(-1000.0, 1e6, true, "t_start < t_end ≤ 1e6 s"),
        sets: &[Key::TEnd],
        steps: None,
        help: "End of the simulated span, ≤ 1e6 s [default: the preset's, or a little past the last event]",
    },
];

impl Key {
    /// Every key, in the table's order.
    pub const ALL: [Key; 17] = {
        let mut keys = [Key::Radius; 17];
        let mut i = 0;
        while i < 17 {
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
}

/// Why a scene is not valid. Each message names the value and what is allowed.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum SceneError {
    #[error("{name} = {value} is out of range, allowed {allowed}")]
    OutOfRange {
        name: &'static str,
        value: String,
        allowed: String,
    },
    #[error("{0}")]
    Other(String),
}

/// One layer of settings (built-in defaults, a preset, the command line, the app), SI
/// units, one optional value per key. Later layers override earlier ones with
/// [`SceneSpec::over`].
#[derive(Clone, Debug, Default, PartialEq)]
pub struct SceneSpec {
    values: [Option<f64>; 17],
}

/// Standard gravity used when nothing else is said, m/s².
pub const STANDARD_GRAVITY: f64 = 9.81;

impl SceneSpec {
    /// The value this layer gives for `key`, SI; a key that sets others (`mass`,
    /// `v0`, `height`) gives their value when they agree.
    pub fn get(&self, key: Key) -> Option<f64> {
        match key.param().sets {
            [only] if *only == key => self.values[key as usize],
            sets => {
                let first = self.values[sets[0] as usize]?;
                sets.iter()
                    .all(|k| self.values[*k as usize] == Some(first))
                    .then_some(first)
            }
        }
    }

    /// Sets one key (already in SI units); `mass`, `v0` and `height` set both balls'.
    /// A ball's speed drops its release height of the same layer and a height drops
    /// the speed: the run-up replaces v0.
    pub fn set(&mut self, key: Key, value: f64) {
        // −0 is 0: a sign on zero must not reach the physics (e = −0 gave b* = ∞).
        let value = value + 0.0;
        for &k in key.param().sets {
            let replaced = match k {
                Key::V0Left => Some(Key::HeightLeft),
                Key::V0Right => Some(Key::HeightRight),
                Key::HeightLeft => Some(Key::V0Left),
                Key::HeightRight => Some(Key::V0Right),
                _ => None,
            };
            if let Some(r) = replaced {
                self.values[r as usize] = None;
            }
            self.values[k as usize] = Some(value);
        }
    }

    /// Builder form of [`SceneSpec::set`].
    pub fn with(mut self, key: Key, value: f64) -> SceneSpec {
        self.set(key, value);
        self
    }

    /// Every value this layer stores, in table order (per ball: `mass_left`, not `mass`).
    pub fn given(&self) -> impl Iterator<Item = (Key, f64)> + '_ {
        Key::ALL
            .into_iter()
            .filter_map(|k| self.values[k as usize].map(|v| (k, v)))
    }

    /// `upper` over `self`: every value `upper` gives wins (through [`SceneSpec::set`],
    /// so a speed on the upper layer drops a release height from below and the other
    /// way round).
    pub fn over(&self, upper: &SceneSpec) -> SceneSpec {
        let mut merged = self.clone();
        for (k, v) in upper.given() {
            merged.set(k, v);
        }
        merged
    }

    /// The complete layer of a scene and span: what an app or a saved preset holds.
    pub fn of(scene: &Scene, span: &Span) -> SceneSpec {
        let mut spec = SceneSpec::default();
        for (k, v) in [
            (Key::Radius, scene.radius),
            (Key::Width, scene.width),
            (Key::MassLeft, scene.left.mass),
            (Key::MassRight, scene.right.mass),
            (Key::Mu, scene.mu),
            (Key::V0Left, scene.left.v0),
            (Key::V0Right, scene.right.v0),
            (Key::Restitution, scene.restitution),
            (Key::RollingResistance, scene.rolling_resistance),
            (Key::G, scene.g),
            (Key::TStart, span.t_start),
        ] {
            spec.set(k, v);
        }
        if let Some(t_end) = span.t_end {
            spec.set(Key::TEnd, t_end);
        }
        spec
    }

    /// Checks every value and builds the scene and time span.
    pub fn resolve(&self) -> Result<(Scene, Span), SceneError> {
        let value = |key: Key| -> Result<f64, SceneError> {
            let p = key.param();
            let v = self.get(key).ok_or_else(|| {
                SceneError::Other(format!(
                    "{} is not set, give it with --{} or in the preset",
                    p.symbol, p.flag
                ))
            })?;
            in_range(p, v)
        };
        let default = |key: Key, v: f64| self.get(key).map_or(Ok(v), |_| value(key));
        let radius = value(Key::Radius)?;
        let width = value(Key::Width)?;
        check(Key::Width.param(), width, width < 2.0 * radius, || {
            format!("0 ≤ b < 2R = {}", show(2.0 * radius, Dimension::Length))
        })?;
        let mu = value(Key::Mu)?;
        let g = default(Key::G, STANDARD_GRAVITY)?;
        let restitution = default(Key::Restitution, 1.0)?;
        let rolling_resistance = default(Key::RollingResistance, 0.0)?;
        let mass_left = value(Key::MassLeft)?;
        let mass_right = value(Key::MassRight)?;
        let k = closed_form::contact_ratio(radius, width);
        // Each ball's speed: its run-up's if a height is given, else its v0.
        let speed = |height: Key, v0: Key| -> Result<f64, SceneError> {
            if self.values[height as usize].is_none() {
                return value(v0);
            }
            let v = closed_form::release_speed(value(height)?, k, g);
            let p = Key::V0.param();
            check(p, v, p.range.contains(v), || {
                format!("{} (the run-up from this height is too fast)", p.range.text)
            })?;
            Ok(v)
        };
        let v0_left = speed(Key::HeightLeft, Key::V0Left)?;
        let v0_right = speed(Key::HeightRight, Key::V0Right)?;
        if v0_left + v0_right < 0.0 {
            return Err(SceneError::OutOfRange {
                name: "closing speed v0_left + v0_right",
                value: show(v0_left + v0_right, Dimension::Speed).to_string(),
                allowed: "≥ 0 m/s (the balls meet at t = 0)".into(),
            });
        }
        let t_start = default(Key::TStart, Span::default().t_start)?;
        if self.get(Key::TEnd).is_some() {
            let t_end = value(Key::TEnd)?;
            check(Key::TEnd.param(), t_end, t_end > t_start, || {
                format!("t_end > t_start = {}", show(t_start, Dimension::Time))
            })?;
        }
        let scene = Scene {
            radius,
            width,
            mu,
            g,
            restitution,
            rolling_resistance,
            left: Ball {
                mass: mass_left,
                v0: v0_left,
            },
            right: Ball {
                mass: mass_right,
                v0: v0_right,
            },
        };
        finite_derived(&scene)?;
        Ok((
            scene,
            Span {
                t_start,
                t_end: self.get(Key::TEnd),
            },
        ))
    }
}

/// `v` if it lies in the parameter's physical range.
fn in_range(p: &Param, v: f64) -> Result<f64, SceneError> {
    check(p, v, p.range.contains(v), || p.range.text.to_string()).map(|()| v)
}

/// `Ok` if `ok` and `value` is finite; the message is only built for an error (this
/// runs for every point of a sweep).
fn check(
    p: &Param,
    value: f64,
    ok: bool,
    allowed: impl FnOnce() -> String,
) -> Result<(), SceneError> {
    if ok && value.is_finite() {
        Ok(())
    } else {
        Err(SceneError::OutOfRange {
            name: p.symbol,
            value: show_exact(value, p.dim),
            allowed: allowed(),
        })
    }
}

/// Every number the front ends derive from an accepted scene must be finite; the
/// ranges above are chosen so that it is, and this says so if a corner slips through.
fn finite_derived(scene: &Scene) -> Result<(), SceneError> {
    let d = Derived::of(scene);
    let f = d.forces;
    let mut numbers = vec![d.k, d.r, d.d, d.separation_speed, d.release_height];
    numbers.extend(d.b_star);
    for v in [
        f.weight,
        f.normal_a,
        f.normal_b,
        f.friction_a,
        f.net,
        f.torque,
    ] {
        numbers.extend(v.iter().copied());
    }
    if let Some(r) = d.left_after_impact {
        numbers.extend([r.t_roll, r.v_roll, r.x_roll, r.a_cm, r.a_t]);
    }
    if numbers.iter().all(|v| v.is_finite()) {
        Ok(())
    } else {
        Err(SceneError::Other(
            "this combination of values gives numbers too large to compute (an infinite time or force); move a value toward the middle of its range".into(),
        ))
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
    fn mass_sets_both_and_a_height_replaces_speeds() {
        let s = SceneSpec::default().with(Key::Mass, 0.2);
        assert_eq!(s.get(Key::MassLeft), Some(0.2));
        assert_eq!(s.get(Key::MassRight), Some(0.2));
        let lower = SceneSpec::default().with(Key::V0, 1.0);
        let upper = SceneSpec::default().with(Key::Height, 0.1);
        let merged = lower.over(&upper);
        assert_eq!(merged.get(Key::V0Left), None);
        assert_eq!(merged.get(Key::Height), Some(0.1));
        let back = merged.over(&SceneSpec::default().with(Key::V0Left, 0.5));
        assert_eq!(back.get(Key::Height), None);
    }

    #[test]
    fn negative_zero_is_zero() {
        let s = SceneSpec::default().with(Key::Restitution, -0.0);
        assert!(s.get(Key::Restitution).unwrap().is_sign_positive());
    }
}
