//! Layers of scene settings ([`SceneSpec`]: defaults, preset, command line, app) and
//! their resolution through the parameter table into a checked SI scene and span.

use crate::physics::derived::Derived;
use crate::physics::scene::{Scene, Span};
use std::fmt;

use crate::settings::params::{Fallback, Key, PARAMS, Param, Range};
use crate::settings::units::{Dimension, show, show_exact};

/// Why a scene is not valid: which parameter, its value (SI) and what is allowed. The
/// sentence, naming the value and what is allowed, is made only where it is printed.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum SceneError {
    /// `key`'s value (SI) is outside what is allowed.
    #[error(
        "{} = {} is out of range, allowed {allowed}",
        key.param().symbol,
        show_exact(*value, key.dimension())
    )]
    OutOfRange {
        key: Key,
        value: f64,
        allowed: Allowed,
    },
    /// The release height `key` gives a run-up speed (m/s) beyond the speed range.
    #[error(
        "{} = {} is out of range, allowed {} (the run-up from this height is too fast)",
        Key::V0.param().symbol,
        show_exact(*speed, Dimension::Speed),
        Key::V0.param().range.text
    )]
    RunUpTooFast { key: Key, speed: f64 },
    /// A required parameter no layer gives.
    #[error(
        "{} is not set, give it with --{} or in the preset",
        key.param().symbol,
        key.param().flag
    )]
    NotSet { key: Key },
    /// The balls move apart at t = 0: v0_left + v0_right (m/s) is negative.
    #[error(
        "closing speed v0_left + v0_right = {} is out of range, allowed ≥ 0 m/s (the balls meet at t = 0)",
        show(*closing, Dimension::Speed)
    )]
    Receding { closing: f64 },
    /// R (m) below the least radius (m) that keeps a tracked rim mark, `mark` (m) from
    /// the centre, on the ball.
    #[error(
        "R = {} is out of range, allowed R ≥ {} (the rim mark tracked {} from the centre must be on the ball)",
        show_exact(*radius, Dimension::Length),
        show(*least, Dimension::Length),
        show(*mark, Dimension::Length)
    )]
    MarkOffTheBall { radius: f64, least: f64, mark: f64 },
    /// Every value is in range but a derived number (a time, a force) is not finite.
    #[error(
        "this combination of values gives numbers too large to compute (an infinite time or force); move a value toward the middle of its range"
    )]
    TooLarge,
}

impl SceneError {
    /// The parameter whose value was refused, if the error is about one.
    pub fn key(&self) -> Option<Key> {
        match self {
            SceneError::OutOfRange { key, .. }
            | SceneError::RunUpTooFast { key, .. }
            | SceneError::NotSet { key } => Some(*key),
            SceneError::MarkOffTheBall { .. } => Some(Key::Radius),
            SceneError::Receding { .. } | SceneError::TooLarge => None,
        }
    }
}

/// What a parameter's value must be.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Allowed {
    /// Its physical range in the table.
    Range(Range),
    /// A groove narrower than 2R for this R, m: `0 ≤ b < 2R`.
    BelowTwiceRadius { radius: f64 },
    /// An end after this start, s.
    After { t_start: f64 },
}

impl Allowed {
    /// Whether `v` (SI) is what is allowed.
    pub fn admits(&self, v: f64) -> bool {
        match self {
            Allowed::Range(r) => r.contains(v),
            Allowed::BelowTwiceRadius { radius } => (0.0..2.0 * radius).contains(&v),
            Allowed::After { t_start } => v > *t_start,
        }
    }
}

impl fmt::Display for Allowed {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Allowed::Range(r) => f.write_str(r.text),
            Allowed::BelowTwiceRadius { radius } => {
                write!(f, "0 ≤ b < 2R = {}", show(2.0 * radius, Dimension::Length))
            }
            Allowed::After { t_start } => {
                write!(f, "t_end > t_start = {}", show(*t_start, Dimension::Time))
            }
        }
    }
}

/// One layer of settings (built-in defaults, a preset, the command line, the app), SI
/// units, one optional value per key. Later layers override earlier ones with
/// [`SceneSpec::over`].
#[derive(Clone, Debug, PartialEq)]
pub struct SceneSpec {
    values: [Option<f64>; PARAMS.len()],
}

impl Default for SceneSpec {
    /// The empty layer: it gives nothing.
    fn default() -> Self {
        SceneSpec {
            values: [None; PARAMS.len()],
        }
    }
}

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
            // What `k` replaces, and what replaces `k`.
            let replaced = k.param().replaces.into_iter().chain(
                PARAMS
                    .iter()
                    .filter(|p| p.replaces == Some(k))
                    .map(|p| p.key),
            );
            for r in replaced {
                self.values[r as usize] = None;
            }
            self.values[k as usize] = Some(value);
        }
    }

    /// The row `p`'s value was given through: the one setting both balls (`mass`)
    /// when this layer holds the same value for both, else `p`.
    pub fn given_as(&self, p: &'static Param) -> &'static Param {
        PARAMS
            .iter()
            .find(|q| q.sets.len() > 1 && q.sets.contains(&p.key) && self.get(q.key).is_some())
            .unwrap_or(p)
    }

    /// Builder form of [`SceneSpec::set`].
    pub fn with(mut self, key: Key, value: f64) -> SceneSpec {
        self.set(key, value);
        self
    }

    /// This layer without `key`'s own value (a key that sets others drops theirs).
    pub fn without(mut self, key: Key) -> SceneSpec {
        for &k in key.param().sets {
            self.values[k as usize] = None;
        }
        self
    }

    /// The rows this layer's values were given through, in table order: one that sets
    /// several keys (`mass`) where this layer holds one value for them all, else each
    /// key's own row (`mass_left`) — the options as they were typed.
    pub fn rows(&self) -> Vec<Key> {
        PARAMS
            .iter()
            .filter(|p| {
                let own = p.sets.len() == 1 && self.values[p.key as usize].is_some();
                let joint = |q: &&Param| q.sets.len() > 1 && q.sets.contains(&p.key);
                match p.sets.len() {
                    1 => {
                        own && !PARAMS
                            .iter()
                            .filter(joint)
                            .any(|q| self.get(q.key).is_some())
                    }
                    _ => self.get(p.key).is_some(),
                }
            })
            .map(|p| p.key)
            .collect()
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

    /// The complete layer of a scene and span: what an app or a saved preset holds
    /// (every row with a value of its own, except those computed from others).
    pub fn of(scene: &Scene, span: &Span) -> SceneSpec {
        let mut spec = SceneSpec::default();
        for p in PARAMS.iter().filter(|p| p.is_own() && p.replaces.is_none()) {
            if let Some(v) = (p.get)(scene, span) {
                spec.set(p.key, v);
            }
        }
        spec
    }

    /// Checks every value and builds the scene and time span: each row writes its
    /// value (or its default) in table order, then the rows that replace others (a
    /// release height's speed needs k and g), each checked against its range and the
    /// relations between values checked where both are known. Every number of the
    /// default scene it starts from is overwritten (`params`' tests check that each
    /// field is some row's).
    pub fn resolve(&self) -> Result<(Scene, Span), SceneError> {
        let (mut scene, mut span) = (Scene::DEFAULT, Span::DEFAULT);
        let own = PARAMS.iter().filter(|p| p.is_own());
        let (first, then): (Vec<&Param>, Vec<&Param>) = own.partition(|p| p.replaces.is_none());
        for p in first.into_iter().chain(then) {
            let given = self.values[p.key as usize];
            let replaced = PARAMS
                .iter()
                .any(|q| q.replaces == Some(p.key) && self.values[q.key as usize].is_some());
            let v = match (given, p.default) {
                // Out of range under the name the user gave: `mass` for both balls'.
                (Some(v), _) => in_range(self.given_as(p), v, &scene)?,
                (None, Fallback::Value(v)) => v,
                (None, Fallback::Optional) => continue,
                (None, Fallback::Required) if replaced => continue,
                (None, Fallback::Required) => return Err(SceneError::NotSet { key: p.key }),
            };
            (p.set)(&mut scene, &mut span, v);
            relations(p, &scene, &span)?;
        }
        let closing = scene.left.v0 + scene.right.v0;
        if closing < 0.0 {
            return Err(SceneError::Receding { closing });
        }
        finite_derived(&scene)?;
        Ok((scene, span))
    }
}

/// The checks between values, once `p` is written: b < 2R, t_end after t_start, and a
/// release height's speed within the speed range.
fn relations(p: &Param, scene: &Scene, span: &Span) -> Result<(), SceneError> {
    match (p.key, p.replaces) {
        (Key::Width, _) => check(
            p,
            scene.width,
            scene.width < 2.0 * scene.radius,
            Allowed::BelowTwiceRadius {
                radius: scene.radius,
            },
        ),
        (Key::TEnd, _) => {
            let t_end = span.t_end.unwrap_or(f64::NAN);
            let allowed = Allowed::After {
                t_start: span.t_start,
            };
            check(p, t_end, t_end > span.t_start, allowed)
        }
        (_, Some(speed)) => {
            let v = (speed.param().get)(scene, span).unwrap_or(f64::NAN);
            if Key::V0.param().range.contains(v) {
                Ok(())
            } else {
                Err(SceneError::RunUpTooFast {
                    key: p.key,
                    speed: v,
                })
            }
        }
        _ => Ok(()),
    }
}

/// `v` if it lies in the parameter's physical range; a width's refusal names 2R's
/// value (the radius is written before the width).
fn in_range(p: &Param, v: f64, scene: &Scene) -> Result<f64, SceneError> {
    let allowed = match p.key {
        Key::Width => Allowed::BelowTwiceRadius {
            radius: scene.radius,
        },
        _ => Allowed::Range(p.range),
    };
    check(p, v, p.range.contains(v), allowed).map(|()| v)
}

/// `Ok` if `ok` and `value` is finite (this runs for every point of a sweep: no text
/// is made here).
fn check(p: &Param, value: f64, ok: bool, allowed: Allowed) -> Result<(), SceneError> {
    if ok && value.is_finite() {
        Ok(())
    } else {
        Err(SceneError::OutOfRange {
            key: p.key,
            value,
            allowed,
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
        Err(SceneError::TooLarge)
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

    /// The typed errors say what the strings said before, and name the parameter.
    #[test]
    fn scene_errors_name_the_key_and_print_as_before() {
        let base = SceneSpec::default()
            .with(Key::Radius, 0.0275)
            .with(Key::Width, 0.049)
            .with(Key::Mass, 0.167)
            .with(Key::Mu, 0.17)
            .with(Key::V0, 0.6);
        assert!(base.resolve().is_ok());
        let cases = [
            (
                base.clone().with(Key::Mass, 2000.0),
                Some(Key::Mass),
                "mass = 2000000 g is out of range, allowed 1 mg ≤ m ≤ 1000 kg",
            ),
            (
                base.clone().with(Key::Width, 0.06),
                Some(Key::Width),
                "groove width b = 6 cm is out of range, allowed 0 ≤ b < 2R = 5.5 cm",
            ),
            (
                base.clone().with(Key::TEnd, -0.5),
                Some(Key::TEnd),
                "t_end = -0.5 s is out of range, allowed t_end > t_start = -0.2 s",
            ),
            (
                base.clone()
                    .with(Key::HeightLeft, 499.0)
                    .with(Key::G, 1000.0),
                Some(Key::HeightLeft),
                "v0 = ",
            ),
            (
                base.clone().without(Key::Mu),
                Some(Key::Mu),
                "μ_k is not set, give it with --mu or in the preset",
            ),
            (
                base.clone().with(Key::V0Right, -1.0),
                None,
                "closing speed v0_left + v0_right = -0.4 m/s is out of range, allowed ≥ 0 m/s (the balls meet at t = 0)",
            ),
        ];
        for (spec, key, text) in cases {
            let e = spec.resolve().unwrap_err();
            assert_eq!(e.key(), key, "{e}");
            assert!(e.to_string().starts_with(text), "{e}");
        }
        let fast = base.with(Key::HeightLeft, 499.0).with(Key::G, 1000.0);
        assert!(fast.resolve().unwrap_err().to_string().ends_with(
            "allowed -100 m/s ≤ v0 ≤ 100 m/s (the run-up from this height is too fast)"
        ));
    }
}
