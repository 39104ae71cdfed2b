//! The one table of scene parameters — name, flag, symbol, unit, physical range, steps,
//! help and label — and the layers of settings (defaults, preset, command line) that
//! are read through it: settings in, a checked SI
//! [`Scene`](crate::physics::scene::Scene) out.
//!
//! The command line's scene options (`cli::args`), preset reading and saving
//! (`input::preset`), validation messages, the TUI's parameter rows and `--help` all
//! come from [`PARAMS`]. Adding a parameter is one row here, one line in
//! [`SceneSpec::resolve`], and its physics.

use crate::input::units::Dimension;
use crate::physics::solution::LATEST_END;

// The settings layers live in `spec`; their names stay here, beside the table they read.
pub use crate::input::spec::{STANDARD_GRAVITY, SceneError, SceneSpec};

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
        range: range(-1000.0, LATEST_END, true, "t_start < t_end ≤ 1e6 s"),
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
}
