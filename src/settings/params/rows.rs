//! The rows of the scene parameter table ([`PARAMS`]): each parameter's name, flag,
//! symbol, unit, range, steps, default, help and how it is read from and written to
//! a scene, as data.

use super::row::{Fallback, Key, Param, Range, Steps};
use crate::physics::closed_form::{release_height, release_speed};
use crate::physics::scene::{Scene, Span};
use crate::physics::solution::LATEST_END;
use crate::settings::units::Dimension;

/// A physical range, SI, and its text for messages and `--help`.
const fn range(lo: f64, hi: f64, lo_open: bool, text: &'static str) -> Range {
    Range {
        lo,
        hi,
        lo_open,
        text,
    }
}

/// A row of the app's parameter panel, stepped by `fine` (←/→) and `coarse`
/// (Shift+←/→), SI.
const fn steps(fine: f64, coarse: f64) -> Option<Steps> {
    Some(Steps { fine, coarse })
}

const MASS: Range = range(1e-6, 1000.0, false, "1 mg ≤ m ≤ 1000 kg");
const SPEED: Range = range(-100.0, 100.0, false, "-100 m/s ≤ v0 ≤ 100 m/s");
const MASS_STEPS: Option<Steps> = steps(0.001, 0.01);
const HEIGHT: Range = range(0.0, 500.0, false, "0 ≤ h ≤ 500 m");
const HEIGHT_STEPS: Option<Steps> = steps(0.002, 0.02);
const SPEED_STEPS: Option<Steps> = steps(0.01, 0.1);

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
        steps: steps(0.0005, 0.005),
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
        steps: steps(0.0005, 0.005),
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
        symbol: "m left",
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
        symbol: "m right",
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
        steps: steps(0.01, 0.05),
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
        steps: steps(0.01, 0.1),
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
        steps: steps(0.001, 0.01),
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
