//! Fixed-step methods: explicit Euler and semi-implicit Euler with Coulomb friction,
//! classical RK4 with `tanh(s/ε)` friction. Impacts: see the module above.

use super::{
    EventTracker, Friction, Method, Model, Observer, Outcome, Settings, Y, resolve_overlap, rhs,
};

/// Butcher tableau of classical RK4, as data.
const RK4_C: [f64; 4] = [0.0, 0.5, 0.5, 1.0];
const RK4_B: [f64; 4] = [1.0 / 6.0, 1.0 / 3.0, 1.0 / 3.0, 1.0 / 6.0];

fn axpy(y: &Y, h: f64, d: &Y) -> Y {
    std::array::from_fn(|j| y[j] + h * d[j])
}

/// One step of `method`; returns the new state and the right-hand-side evaluations.
fn step(method: Method, m: &Model, law: Friction, y: &Y, h: f64) -> (Y, usize) {
    match method {
        Method::Euler => (axpy(y, h, &rhs(m, law, y)), 1),
        Method::SymplecticEuler => {
            // Velocities first, then positions with the new velocities.
            let d = rhs(m, law, y);
            let mut n = *y;
            for i in 0..2 {
                n[3 * i + 1] += h * d[3 * i + 1];
                n[3 * i + 2] += h * d[3 * i + 2];
                n[3 * i] += h * n[3 * i + 1];
            }
            (n, 1)
        }
        Method::Rk4 => {
            let mut k = [[0.0; 6]; 4];
            for i in 0..4 {
                let yi = if i == 0 {
                    *y
                } else {
                    axpy(y, RK4_C[i] * h, &k[i - 1])
                };
                k[i] = rhs(m, law, &yi);
            }
            let d: Y = std::array::from_fn(|j| (0..4).map(|i| RK4_B[i] * k[i][j]).sum());
            (axpy(y, h, &d), 4)
        }
        _ => unreachable!("not a fixed-step method"),
    }
}

pub(super) fn integrate(
    method: Method,
    m: &Model,
    y0: Y,
    t0: f64,
    t1: f64,
    s: &Settings,
    obs: &mut dyn Observer,
) -> Outcome {
    let law = if method.regularised() {
        Friction::Tanh(s.epsilon)
    } else {
        Friction::Coulomb
    };
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
    let mut tracker = EventTracker::new(match law {
        Friction::Tanh(eps) => eps,
        Friction::Coulomb => 0.0,
    });
    if !obs.step(t0, &y0) {
        out.aborted = true;
        return out;
    }
    tracker.step(t0, &y0, obs);
    let mut y = y0;
    for i in 1..=n {
        // Steps land on the grid t0 + i h (the last one on t1), without drift.
        let t = if i == n { t1 } else { t0 + i as f64 * h };
        let (next, evals) = step(method, m, law, &y, t - out.t);
        y = next;
        out.rhs_evals += evals;
        out.steps += 1;
        out.t = t;
        if resolve_overlap(m, &mut y) {
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
