//! The paper's closed forms (physics.md, misprints corrected) for the symmetric scene:
//! equal balls meeting with equal speeds `v0`. The engine never uses these for the
//! motion; they are the yardstick it is tested against and what the info panel quotes.

/// `k = r / R = sqrt(1 − (b / 2R)²)`.
pub fn contact_ratio(radius: f64, width: f64) -> f64 {
    let half = width / (2.0 * radius);
    // (1 − h)(1 + h) keeps its digits as b → 2R, where 1 − h² would cancel.
    ((1.0 - half) * (1.0 + half)).sqrt()
}

/// `D = |a_t| / |a_cm| = 5k²/2`: below 1 the rotation outlasts the translation.
pub fn determinant(k: f64) -> f64 {
    2.5 * k * k
}

/// The critical width `b* = 2R sqrt(1 − 2/(5e))`, `None` where `e < 2/5` (no width stops the balls).
pub fn critical_width(radius: f64, restitution: f64) -> Option<f64> {
    let inside = 1.0 - 2.0 / (5.0 * restitution);
    (inside >= 0.0).then(|| 2.0 * radius * inside.sqrt())
}

/// Time from the impact until the ball rolls again, `t' = 2k(1+e) v0 / ((2 + 5k²) μ_k g)`.
pub fn t_roll(k: f64, e: f64, v0: f64, mu: f64, g: f64) -> f64 {
    2.0 * k * (1.0 + e) * v0 / ((2.0 + 5.0 * k * k) * mu * g)
}

/// Rolling speed then, positive back toward the other ball: `v' = v0 (2 − 5ek²)/(2 + 5k²)`.
pub fn v_roll(k: f64, e: f64, v0: f64) -> f64 {
    v0 * (2.0 - 5.0 * e * k * k) / (2.0 + 5.0 * k * k)
}

/// Left ball's place then, from the impact place: `x' = −e v0 t' + μ_k g t'² / (2k)`.
pub fn x_roll(k: f64, e: f64, v0: f64, mu: f64, g: f64) -> f64 {
    let t = t_roll(k, e, v0, mu, g);
    -e * v0 * t + mu * g * t * t / (2.0 * k)
}

/// The paper's `x(t0')` for `e = 1` with the square on `(2 + 5k²)` restored.
pub fn x_roll_elastic(k: f64, v0: f64, mu: f64, g: f64) -> f64 {
    let q = 2.0 + 5.0 * k * k;
    -20.0 * k.powi(3) * v0 * v0 / (q * q * mu * g)
}

/// Pure gliding (ω = 0) at `t_r = 2 v0 / (5 k μ_k g)` (for `e = 1`, when `v' < 0`).
pub fn t_pure_gliding(k: f64, v0: f64, mu: f64, g: f64) -> f64 {
    2.0 * v0 / (5.0 * k * mu * g)
}

/// Pure slipping (v = 0) at `t_t = k e v0 / (μ_k g)` (when `v' > 0`).
pub fn t_pure_slipping(k: f64, e: f64, v0: f64, mu: f64, g: f64) -> f64 {
    k * e * v0 / (mu * g)
}

/// Cycle ratio of repeated impacts, `ρ = (2 − 5ek²)/(2 + 5k²)`.
pub fn cycle_ratio(k: f64, e: f64) -> f64 {
    v_roll(k, e, 1.0)
}

/// Time of the accumulation point `T∞ = T₁ / (1 − ρ)`, `T₁ = t' + |x'| / v'`, where
/// impacts repeat (`v' > 0`); `None` otherwise.
pub fn accumulation_time(k: f64, e: f64, v0: f64, mu: f64, g: f64) -> Option<f64> {
    let rho = cycle_ratio(k, e);
    let vp = v_roll(k, e, v0);
    (vp > 0.0 && rho < 1.0).then(|| {
        let t1 = t_roll(k, e, v0, mu, g) + x_roll(k, e, v0, mu, g).abs() / vp;
        // 1 − ρ = 5k²(1 + e)/(2 + 5k²), without the cancellation of 1 − ρ near 2R.
        let k2 = k * k;
        t1 * (2.0 + 5.0 * k2) / (5.0 * k2 * (1.0 + e))
    })
}

/// Speed at the foot of the run-up after rolling down height `h` in the same groove:
/// `v0 = sqrt(2 g h / (1 + 2/(5k²)))`.
pub fn release_speed(h: f64, k: f64, g: f64) -> f64 {
    (2.0 * g * h / (1.0 + 2.0 / (5.0 * k * k))).sqrt()
}

/// Inverse of [`release_speed`]: the height that gives `v0`.
pub fn release_height(v0: f64, k: f64, g: f64) -> f64 {
    v0 * v0 * (1.0 + 2.0 / (5.0 * k * k)) / (2.0 * g)
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    #[test]
    fn critical_width_of_the_paper() {
        // b*/R = sqrt(12/5) ≈ 1.549 for e = 1 (physics.md).
        let b = critical_width(1.0, 1.0).unwrap();
        assert_relative_eq!(b, (12.0f64 / 5.0).sqrt(), max_relative = 1e-15);
        assert!(critical_width(1.0, 0.39).is_none());
        // At b* the determinant is exactly 1 and v' vanishes.
        let k = contact_ratio(1.0, b);
        assert_relative_eq!(determinant(k), 1.0, max_relative = 1e-14);
        assert!(v_roll(k, 1.0, 1.0).abs() < 1e-15);
    }

    #[test]
    fn the_corrected_x_prime_is_the_general_one_at_e_1() {
        for k in [0.1, 0.45, 0.8, 1.0] {
            assert_relative_eq!(
                x_roll(k, 1.0, 0.7, 0.2, 9.81),
                x_roll_elastic(k, 0.7, 0.2, 9.81),
                max_relative = 1e-13
            );
        }
    }

    #[test]
    fn release_height_round_trips() {
        let k = 0.6;
        let v = release_speed(0.05, k, 9.81);
        assert_relative_eq!(release_height(v, k, 9.81), 0.05, max_relative = 1e-14);
        // A flat table (k = 1): v² = 10/7 g h, the textbook rolling ball.
        assert_relative_eq!(
            release_speed(0.1, 1.0, 9.81),
            (10.0 / 7.0 * 9.81 * 0.1f64).sqrt(),
            max_relative = 1e-15
        );
    }

    #[test]
    fn contact_ratio_keeps_digits_near_wedging() {
        // b = 2R(1 − δ): k² = δ(2 − δ) exactly.
        let delta = 1e-12;
        let k = contact_ratio(1.0, 2.0 * (1.0 - delta));
        assert_relative_eq!(k * k, delta * (2.0 - delta), max_relative = 1e-3);
    }
}
