//! Helpers shared by the integration tests.
#![allow(dead_code)]

use groovelab::physics::scene::{Ball, Scene, Span};

/// The paper's symmetric scene with the given width, friction, speed and restitution.
pub fn symmetric(radius: f64, width: f64, mu: f64, v0: f64, e: f64) -> Scene {
    Scene {
        radius,
        width,
        mu,
        g: 9.81,
        restitution: e,
        rolling_resistance: 0.0,
        left: Ball { mass: 0.167, v0 },
        right: Ball { mass: 0.167, v0 },
    }
}

pub fn span() -> Span {
    Span {
        t_start: -0.2,
        t_end: None,
    }
}

/// `|a − b| ≤ rel · max(|a|, |b|, scale)`: relative, but not below `scale` for values
/// that are differences of larger numbers.
pub fn close(a: f64, b: f64, rel: f64, scale: f64) -> bool {
    (a - b).abs() <= rel * a.abs().max(b.abs()).max(scale)
}

#[macro_export]
macro_rules! assert_close {
    ($a:expr, $b:expr, $rel:expr, $scale:expr, $($msg:tt)*) => {{
        let (a, b) = ($a, $b);
        assert!(
            $crate::common::close(a, b, $rel, $scale),
            "{} vs {} (rel {:e}): {}",
            a,
            b,
            ((a - b) / b).abs(),
            format!($($msg)*)
        );
    }};
}
