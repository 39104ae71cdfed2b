//! Moreau–Jean time-stepping, the standard of non-smooth dynamics: velocities by a
//! θ-method (θ = 1/2 for positions), impacts by Newton's law at the velocity level,
//! Coulomb friction as a set-valued law solved exactly in each step. No event is
//! located and no step is ever refused: accumulations of impacts cost nothing.

use super::{EventTracker, Model, Observer, Outcome, Settings, Y, gap};

const THETA: f64 = 0.5;

/// End-of-step velocities `(v⁺, u⁺)` of ball `i` under contact impulse `c` (along x):
/// the friction impulse F ∈ −μ m g h / k · Sgn(s⁺) is solved exactly (stick if it can).
fn ball_update(m: &Model, i: usize, v: f64, u: f64, c: f64, h: f64) -> (f64, f64) {
    let mass = m.mass[i];
    let k2 = m.k * m.k;
    // Rolling resistance, explicit: it only brakes (never flips the sign of v).
    let rr = m.rolling_resistance * m.g * h;
    let brake = |x: f64| x - x.signum() * rr.min(x.abs());
    let (v, u) = (brake(v), brake(u));
    // m Δv = F + c,  (2m/(5k²)) Δu = −F  ⇒  s⁺ = s + c/m + F (1 + 5k²/2)/m.
    let free_slip = v - u + c / mass;
    let stiffness = (1.0 + 2.5 * k2) / mass;
    let limit = m.mu * mass * m.g * h / m.k;
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

pub(super) fn integrate(
    m: &Model,
    y0: Y,
    t0: f64,
    t1: f64,
    s: &Settings,
    obs: &mut dyn Observer,
) -> Outcome {
    let h = s.step;
    let n = ((t1 - t0) / h).ceil() as usize;
    let mut out = Outcome {
        steps: 0,
        rhs_evals: 0,
        stalled: None,
        aborted: false,
        t: t0,
        y: y0,
    };
    if n > s.max_steps {
        out.stalled = Some(format!("{n} steps needed, budget {}", s.max_steps));
        return out;
    }
    let mut tracker = EventTracker::new(0.0);
    if !obs.step(t0, &y0) {
        out.aborted = true;
        return out;
    }
    tracker.step(t0, &y0, obs);
    let mut y = y0;
    for i in 1..=n {
        let t = if i == n { t1 } else { t0 + i as f64 * h };
        let dt = t - out.t;
        let w = y[4] - y[1]; // v_R − v_L before the step; negative while closing
        // Contact is active when the predicted gap closes within the step.
        let active = gap(m, &y) + dt * w.min(0.0) <= 1e-12 * m.radius;
        let (mut sep, mut next) = separation(m, &y, 0.0, dt);
        // Newton at velocity level: v_R⁺ − v_L⁺ ≥ −e w, with a push λ ≥ 0 only if needed.
        let target = (-m.restitution * w).max(0.0);
        let mut impact = false;
        if active && sep < target {
            // The separation speed grows monotonically with λ: bracket, then bisect.
            let (mut lo, mut hi) = (0.0, 1e-6_f64);
            while separation(m, &y, hi, dt).0 < target {
                lo = hi;
                hi *= 2.0;
            }
            for _ in 0..60 {
                let mid = 0.5 * (lo + hi);
                if separation(m, &y, mid, dt).0 < target {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            (sep, next) = separation(m, &y, hi, dt);
            // Report impacts, not the steady pressing of balls in contact.
            impact = w < -1e-9;
        }
        debug_assert!(sep.is_finite());
        let old = y;
        for (b, &(v, u)) in next.iter().enumerate() {
            y[3 * b] += dt * ((1.0 - THETA) * old[3 * b + 1] + THETA * v);
            y[3 * b + 1] = v;
            y[3 * b + 2] = u;
        }
        out.steps += 1;
        out.t = t;
        if impact {
            tracker.impact(t, &y, obs);
        }
        tracker.step(t, &y, obs);
        if !obs.step(t, &y) {
            out.aborted = true;
            break;
        }
    }
    out.y = y;
    out
}
