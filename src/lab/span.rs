//! How the shown time span ends ([`SpanEnd`]) and the exact solution solved to that end.

use crate::physics::engine;
use crate::physics::scene::{Scene, Span};
use crate::physics::solution::Solution;
use crate::study::measured::Measured;

/// How the end of the shown time span is chosen. The rule, for the README: the span runs
/// to a little past the last event (rest, the accumulation point T∞, the start of the
/// final rolling) and past the last measured point, and is recomputed on every change.
/// An end set explicitly (`--t-end`, or typed in the app) is kept; a preset's `t_end`
/// holds until the first parameter change; the app's span key stretches or shrinks the
/// automatic span, which then still follows the physics.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum SpanEnd {
    /// A little past the last event and the last measured point.
    Auto,
    /// The automatic span times this factor (from `t_start`).
    Scaled(f64),
    /// A fixed end, s. `from_preset`: the preset's `t_end`, which gives way to
    /// [`SpanEnd::Auto`] at the first parameter change.
    Fixed { t_end: f64, from_preset: bool },
}

impl SpanEnd {
    /// The span key's cycle: auto, ×2, ×½, auto; a fixed end goes back to auto.
    pub fn next(self) -> SpanEnd {
        match self {
            SpanEnd::Auto => SpanEnd::Scaled(2.0),
            SpanEnd::Scaled(f) if f > 1.0 => SpanEnd::Scaled(0.5),
            SpanEnd::Scaled(_) | SpanEnd::Fixed { .. } => SpanEnd::Auto,
        }
    }

    /// How the status line names it.
    pub fn describe(self) -> String {
        match self {
            SpanEnd::Auto => "auto (a little past the last event)".into(),
            SpanEnd::Scaled(f) if f > 1.0 => format!("auto ×{f}"),
            SpanEnd::Scaled(f) => format!("auto ×1/{}", (1.0 / f).round()),
            SpanEnd::Fixed {
                from_preset: true, ..
            } => "the preset's t_end".into(),
            SpanEnd::Fixed { .. } => "fixed t_end".into(),
        }
    }
}

/// The exact solution with the shown end: the engine always runs to the end of the
/// motion, so only `t_end` depends on the choice. The automatic end also reaches the
/// last measured point and the end of a pinned run, so neither is cut.
pub(super) fn solve_shown(
    scene: &Scene,
    span: &Span,
    end: SpanEnd,
    measured: Option<&Measured>,
    pinned_end: Option<f64>,
) -> Solution {
    let auto_span = Span {
        t_start: span.t_start,
        t_end: None,
    };
    let mut sol = engine::solve(scene, &auto_span);
    let last_measured = measured.and_then(|m| m.t().last().copied());
    let auto = sol
        .t_end
        .max(last_measured.unwrap_or(f64::NEG_INFINITY))
        .max(pinned_end.unwrap_or(f64::NEG_INFINITY));
    sol.t_end = match end {
        SpanEnd::Auto => auto,
        SpanEnd::Scaled(f) => span.t_start + f * (auto - span.t_start),
        SpanEnd::Fixed { t_end, .. } => t_end,
    };
    sol
}
