//! Moreau–Jean time-stepping, the standard of non-smooth dynamics: velocities by a
//! θ-method (θ = 1/2 for positions), impacts by Newton's law at the velocity level,
//! Coulomb friction as a set-valued law solved exactly in each step. No event is
//! located and no step is ever refused: accumulations of impacts cost nothing.

use super::{GridStep, Model, Observer, RunEnd, Settings, Y, gap, run_grid};

const THETA: f64 = 0.5;

/// End-of-step velocities `(v⁺, u⁺)` of ball `i` under contact impulse `c` (along x):
/// the friction impulse F ∈ −μ m g h / k · Sgn(s⁺) is solved exactly (stick if it can).
fn ball_update(m: &Model, i: usize, v: f64, u: f64, c: f64, h: f64) -> (f64, f64) {
    let mass = m.mass[i];
    let k2 = m.groove.k * m.groove.k;
    // Rolling resistance, explicit: it only brakes (never flips the sign of v).
    let rr = m.rolling_deceleration() * h;
    let brake = |x: f64| x - x.signum() * rr.min(x.abs());
    let (v, u) = (brake(v), brake(u));
    // m Δv = F + c,  (2m/(5k²)) Δu = −F  ⇒  s⁺ = s + c/m + F (1 + 5k²/2)/m.
    let free_slip = v - u + c / mass;
    let stiffness = (1.0 + 2.5 * k2) / mass;
    let limit = m.groove.friction_limit(mass) * h;
    let f = if free_slip.abs() <= limit * stiffness {
        -free_slip / stiffness
    } else {
        -free_slip.signum() * limit
    };
    (v + (f + c) / mass, u - 2.5 * k2 * f / mass)
}

/// Separation speed `v_R⁺ − v_L⁺` for a contact impulse `lambda` ≥ 0 pushing them apart.
fn separation(m: &Model, y: &Y, lambda: f64, h: f64) -> (f64, [(f64, f64); 2]) {
    let l = ball_update(m, 0, y[1], y[2], -lambda, h);
    let r = ball_update(m, 1, y[4], y[5], lambda, h);
    (r.0 - l.0, [l, r])
}

/// One Moreau–Jean step of length `dt` from `y`.
fn step(m: &Model, y: &Y, dt: f64) -> GridStep {
    let w = y[4] - y[1]; // v_R − v_L before the step; negative while closing
    // Contact is active when the predicted gap closes within the step.
    let active = gap(m, y) + dt * w.min(0.0) <= 1e-12 * m.radius;
    let (sep, mut next) = separation(m, y, 0.0, dt);
    // Newton at velocity level: v_R⁺ − v_L⁺ ≥ −e w, with a push λ ≥ 0 only if needed.
    let target = (-m.restitution * w).max(0.0);
    let mut impact = false;
    if active && sep < target {
        // The separation speed grows monotonically with λ: bracket, then bisect.
        let (mut lo, mut hi) = (0.0, 1e-6_f64);
        while separation(m, y, hi, dt).0 < target {
            lo = hi;
            hi *= 2.0;
        }
        for _ in 0..60 {
            let mid = 0.5 * (lo + hi);
            if separation(m, y, mid, dt).0 < target {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        next = separation(m, y, hi, dt).1;
        // Report impacts, not the steady pressing of balls in contact.
        impact = w < -1e-9;
    }
    let mut out = *y;
    for (b, &(v, u)) in next.iter().enumerate() {
        out[3 * b] += dt * ((1.0 - THETA) * y[3 * b + 1] + THETA * v);
        out[3 * b + 1] = v;
        out[3 * b + 2] = u;
    }
    GridStep {
        y: out,
        rhs_evals: 0,
        impact,
    }
}

pub(super) fn integrate(
    m: &Model,
    y0: Y,
    t0: f64,
    t1: f64,
    s: &Settings,
    obs: &mut dyn Observer,
) -> RunEnd {
    run_grid(y0, t0, t1, s, 0.0, obs, |y, dt| step(m, y, dt))
}
