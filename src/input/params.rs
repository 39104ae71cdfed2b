//! The one table of scene parameters (name, symbol, unit, range, steps, flag, label)
//! and the layers of settings (defaults, preset, command line) it reads: text and
//! settings in, a checked SI [`Scene`] out.

use crate::input::units::{Dimension, show};
use crate::physics::closed_form;
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

/// A setting that a layer may give: one entry of the table shared by the command line
/// (`--mass-left`) and preset files (`mass_left`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
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
    Restitution,
    RollingResistance,
    G,
    TStart,
    TEnd,
}

impl Key {
    pub const ALL: [Key; 15] = [
        Key::Radius,
        Key::Width,
        Key::Mass,
        Key::MassLeft,
        Key::MassRight,
        Key::Mu,
        Key::V0,
        Key::V0Left,
        Key::V0Right,
        Key::Height,
        Key::Restitution,
        Key::RollingResistance,
        Key::G,
        Key::TStart,
        Key::TEnd,
    ];

    /// The name in preset files; the command-line flag is the same with `-` for `_`.
    pub fn name(self) -> &'static str {
        match self {
            Key::Radius => "radius",
            Key::Width => "width",
            Key::Mass => "mass",
            Key::MassLeft => "mass_left",
            Key::MassRight => "mass_right",
            Key::Mu => "mu",
            Key::V0 => "v0",
            Key::V0Left => "v0_left",
            Key::V0Right => "v0_right",
            Key::Height => "height",
            Key::Restitution => "restitution",
            Key::RollingResistance => "rolling_resistance",
            Key::G => "g",
            Key::TStart => "t_start",
            Key::TEnd => "t_end",
        }
    }

    pub fn dimension(self) -> Dimension {
        match self {
            Key::Radius | Key::Width | Key::Height => Dimension::Length,
            Key::Mass | Key::MassLeft | Key::MassRight => Dimension::Mass,
            Key::V0 | Key::V0Left | Key::V0Right => Dimension::Speed,
            Key::Mu | Key::Restitution | Key::RollingResistance => Dimension::Ratio,
            Key::G => Dimension::Acceleration,
            Key::TStart | Key::TEnd => Dimension::Time,
        }
    }

    pub fn from_name(name: &str) -> Option<Key> {
        Key::ALL.into_iter().find(|k| k.name() == name)
    }
}

/// One layer of settings (built-in defaults, a preset, the command line), SI units.
/// Later layers override earlier ones with [`SceneSpec::over`].
#[derive(Clone, Debug, Default, PartialEq)]
pub struct SceneSpec {
    pub radius: Option<f64>,
    pub width: Option<f64>,
    pub mass_left: Option<f64>,
    pub mass_right: Option<f64>,
    pub mu: Option<f64>,
    pub v0_left: Option<f64>,
    pub v0_right: Option<f64>,
    /// Release height on the run-up; replaces both v0 when set on a higher layer.
    pub height: Option<f64>,
    pub restitution: Option<f64>,
    pub rolling_resistance: Option<f64>,
    pub g: Option<f64>,
    pub t_start: Option<f64>,
    pub t_end: Option<f64>,
}

/// Standard gravity used when nothing else is said, m/s².
pub const STANDARD_GRAVITY: f64 = 9.81;

impl SceneSpec {
    /// Sets one key (already in SI units).
    pub fn set(&mut self, key: Key, value: f64) {
        match key {
            Key::Radius => self.radius = Some(value),
            Key::Width => self.width = Some(value),
            Key::Mass => {
                self.mass_left = Some(value);
                self.mass_right = Some(value);
            }
            Key::MassLeft => self.mass_left = Some(value),
            Key::MassRight => self.mass_right = Some(value),
            Key::Mu => self.mu = Some(value),
            Key::V0 => {
                self.v0_left = Some(value);
                self.v0_right = Some(value);
            }
            Key::V0Left => self.v0_left = Some(value),
            Key::V0Right => self.v0_right = Some(value),
            Key::Height => self.height = Some(value),
            Key::Restitution => self.restitution = Some(value),
            Key::RollingResistance => self.rolling_resistance = Some(value),
            Key::G => self.g = Some(value),
            Key::TStart => self.t_start = Some(value),
            Key::TEnd => self.t_end = Some(value),
        }
    }

    /// `upper` over `self`: every value `upper` gives wins. A speed given on the upper
    /// layer drops a release height from below, and a height drops speeds from below.
    pub fn over(&self, upper: &SceneSpec) -> SceneSpec {
        let mut merged = self.clone();
        if upper.height.is_some() {
            merged.v0_left = None;
            merged.v0_right = None;
        }
        if upper.v0_left.is_some() || upper.v0_right.is_some() {
            merged.height = None;
        }
        macro_rules! take {
            ($($f:ident),*) => { $( if upper.$f.is_some() { merged.$f = upper.$f; } )* };
        }
        take!(
            radius,
            width,
            mass_left,
            mass_right,
            mu,
            v0_left,
            v0_right,
            height,
            restitution,
            rolling_resistance,
            g,
            t_start,
            t_end
        );
        merged
    }

    /// Checks every value and builds the scene and time span.
    pub fn resolve(&self) -> Result<(Scene, Span), SceneError> {
        let need = |v: Option<f64>, name: &'static str| {
            v.ok_or_else(|| SceneError::Other(format!("{name} is not set, give it as an option")))
        };
        let radius = need(self.radius, "radius")?;
        check("radius R", radius, Dimension::Length, radius > 0.0, || {
            "R > 0".into()
        })?;
        let width = need(self.width, "groove width")?;
        check(
            "groove width b",
            width,
            Dimension::Length,
            width >= 0.0 && width < 2.0 * radius,
            || format!("0 ≤ b < 2R = {}", show(2.0 * radius, Dimension::Length)),
        )?;
        let mu = need(self.mu, "friction coefficient mu")?;
        check("μ_k", mu, Dimension::Ratio, mu >= 0.0, || "μ_k ≥ 0".into())?;
        let g = self.g.unwrap_or(STANDARD_GRAVITY);
        check("g", g, Dimension::Acceleration, g > 0.0, || "g > 0".into())?;
        let restitution = self.restitution.unwrap_or(1.0);
        check(
            "restitution e",
            restitution,
            Dimension::Ratio,
            (0.0..=1.0).contains(&restitution),
            || "0 ≤ e ≤ 1".into(),
        )?;
        let rolling_resistance = self.rolling_resistance.unwrap_or(0.0);
        check(
            "rolling resistance c_rr",
            rolling_resistance,
            Dimension::Ratio,
            rolling_resistance >= 0.0,
            || "c_rr ≥ 0".into(),
        )?;
        let mass_left = need(self.mass_left, "mass")?;
        let mass_right = need(self.mass_right, "mass")?;
        for (name, m) in [("left mass", mass_left), ("right mass", mass_right)] {
            check(name, m, Dimension::Mass, m > 0.0, || "m > 0".into())?;
        }
        let k = closed_form::contact_ratio(radius, width);
        let (v0_left, v0_right) = match self.height {
            Some(h) => {
                check("release height h", h, Dimension::Length, h >= 0.0, || {
                    "h ≥ 0".into()
                })?;
                let v = closed_form::release_speed(h, k, g);
                (v, v)
            }
            None => (need(self.v0_left, "v0")?, need(self.v0_right, "v0")?),
        };
        for (name, v) in [("left v0", v0_left), ("right v0", v0_right)] {
            check(name, v, Dimension::Speed, v.is_finite(), || {
                "a finite speed".into()
            })?;
        }
        if v0_left + v0_right < 0.0 {
            return Err(SceneError::OutOfRange {
                name: "closing speed v0_left + v0_right",
                value: show(v0_left + v0_right, Dimension::Speed).to_string(),
                allowed: "≥ 0 m/s (the balls meet at t = 0)".into(),
            });
        }
        let t_start = self.t_start.unwrap_or(Span::default().t_start);
        check("t_start", t_start, Dimension::Time, t_start <= 0.0, || {
            "t_start ≤ 0 s (the first impact is at t = 0)".into()
        })?;
        if let Some(t_end) = self.t_end {
            check("t_end", t_end, Dimension::Time, t_end > t_start, || {
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
        Ok((
            scene,
            Span {
                t_start,
                t_end: self.t_end,
            },
        ))
    }
}

/// `Ok` if `ok` and `value` is finite; the message is only built for an error (this
/// runs for every point of a sweep).
fn check(
    name: &'static str,
    value: f64,
    dim: Dimension,
    ok: bool,
    allowed: impl FnOnce() -> String,
) -> Result<(), SceneError> {
    if ok && value.is_finite() {
        Ok(())
    } else {
        Err(SceneError::OutOfRange {
            name,
            value: show(value, dim).to_string(),
            allowed: allowed(),
        })
    }
}
