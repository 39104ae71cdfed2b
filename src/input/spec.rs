//! Layers of scene settings ([`SceneSpec`]: defaults, preset, command line, app) and
//! their resolution through the parameter table into a checked SI scene and span.
//! Re-exported from `input::params`, which is the path to use.

use crate::input::params::{Key, Param};
use crate::input::units::{Dimension, show, show_exact};
use crate::physics::closed_form;
use crate::physics::derived::Derived;
use crate::physics::scene::{Ball, Scene, Span};

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
