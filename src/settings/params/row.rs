//! What a row of the scene parameter table is: the keys of the settings, a
//! parameter's physical range, its steps in the app and its default ([`Param`]); the
//! rows themselves are in `rows`.

use crate::physics::scene::{Scene, Span};
use crate::settings::units::Dimension;

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
