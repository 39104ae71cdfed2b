//! Moreau–Jean time-stepping, the standard of non-smooth dynamics: velocities by a
//! θ-method (θ = 1/2 for positions), impacts by Newton's law at the velocity level,
//! Coulomb friction as a set-valued law solved exactly in each step. No event is
//! located and no step is ever refused: accumulations of impacts cost nothing.

use super::grid::{GridStep, run_grid};
use super::run::{Integrator, Observer, Run, RunEnd};
use super::system::{Model, Y, gap};

/// The Moreau–Jean method.
pub(super) struct Moreau;

const THETA: f64 = 0.5;

/// One ball over one step before the contact impulse is known: its velocities after
/// rolling resistance, and the friction law's constants.
struct Braked {
    v: f64,
    u: f64,
    mass: f64,
    /// `(1 + 5k²/2)/m`: how much a friction impulse changes the slip.
    stiffness: f64,
    /// The largest friction impulse over the step, `μ m g h / k`.
    limit: f64,
    k2: f64,
}

impl Braked {
    fn new(m: &Model, i: usize, v: f64, u: f64, h: f64) -> Braked {
        let mass = m.mass[i];
        // Rolling resistance, explicit: it only brakes (never flips the sign of v).
        let rr = m.rolling_deceleration() * h;
        let brake = |x: f64| x - x.signum() * rr.min(x.abs());
        let k2 = m.groove.k * m.groove.k;
        Braked {
            v: brake(v),
            u: brake(u),
            mass,
            stiffness: (1.0 + 2.5 * k2) / mass,
            limit: m.groove.friction_limit(mass) * h,
            k2,
        }
    }

    /// End-of-step velocities `(v⁺, u⁺)` under contact impulse `c` (along x): the
    /// friction impulse F ∈ −μ m g h / k · Sgn(s⁺) is solved exactly (stick if it can).
    fn update(&self, c: f64) -> (f64, f64) {
        // m Δv = F + c,  (2m/(5k²)) Δu = −F  ⇒  s⁺ = s + c/m + F (1 + 5k²/2)/m.
        let free_slip = self.v - self.u + c / self.mass;
        let f = if free_slip.abs() <= self.limit * self.stiffness {
            -free_slip / self.stiffness
        } else {
            -free_slip.signum() * self.limit
        };
        (
            self.v + (f + c) / self.mass,
            self.u - 2.5 * self.k2 * f / self.mass,
        )
    }

    /// The contact impulses at which friction switches between sticking and sliding:
    /// v⁺ is linear in `c` between them.
    fn kinks(&self) -> [f64; 2] {
        let edge = self.limit * self.stiffness;
        let slip = self.v - self.u;
        [self.mass * (-edge - slip), self.mass * (edge - slip)]
    }
}

/// Separation speed `v_R⁺ − v_L⁺` for a contact impulse `lambda` ≥ 0 pushing them apart.
fn separation(balls: &[Braked; 2], lambda: f64) -> (f64, [(f64, f64); 2]) {
    let l = balls[0].update(-lambda);
    let r = balls[1].update(lambda);
    (r.0 - l.0, [l, r])
}

/// The contact impulse λ > 0 that makes the separation speed `target` (which it
/// exceeds at λ = 0). The separation grows with λ, linearly between the balls' kinks
/// (friction switching between sticking and sliding), so the root is found exactly on
/// the piece that holds it: a few evaluations, where a bisection took 120.
fn contact_impulse(balls: &[Braked; 2], target: f64) -> f64 {
    let [l, r] = balls.each_ref().map(Braked::kinks);
    let mut knots = [-l[0], -l[1], r[0], r[1]];
    knots.sort_by(f64::total_cmp);
    let mut prev = (0.0, separation(balls, 0.0).0);
    for &x in knots.iter().filter(|&&x| x > 0.0 && x.is_finite()) {
        let s = separation(balls, x).0;
        if s >= target {
            return on_line(balls, target, prev, (x, s));
        }
        prev = (x, s);
    }
    // Past the last kink the separation is linear: its slope from one more point.
    let x = prev.0 + prev.0.max(1e-6);
    on_line(balls, target, prev, (x, separation(balls, x).0))
}

/// The impulse where the separation, linear through the points `a` and `b`, reaches
/// `target`; corrected once from the separation there (a point far from the root
/// would otherwise leave its rounding magnified in the result).
fn on_line(balls: &[Braked; 2], target: f64, a: (f64, f64), b: (f64, f64)) -> f64 {
    let slope = (b.1 - a.1) / (b.0 - a.0);
    let x = a.0 + (target - a.1) / slope;
    x + (target - separation(balls, x).0) / slope
}

/// One Moreau–Jean step of length `dt` from `y`.
fn step(m: &Model, y: &Y, dt: f64) -> GridStep {
    let w = y[4] - y[1]; // v_R − v_L before the step; negative while closing
    // Contact is active when the predicted gap closes within the step.
    let active = gap(m, y) + dt * w.min(0.0) <= 1e-12 * m.radius;
    let balls = [
        Braked::new(m, 0, y[1], y[2], dt),
        Braked::new(m, 1, y[4], y[5], dt),
    ];
    let (sep, mut next) = separation(&balls, 0.0);
    // Newton at velocity level: v_R⁺ − v_L⁺ ≥ −e w, with a push λ ≥ 0 only if needed.
    let target = (-m.restitution * w).max(0.0);
    let mut impact = false;
    if active && sep < target {
        next = separation(&balls, contact_impulse(&balls, target)).1;
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

impl Integrator for Moreau {
    fn integrate(&self, run: &Run, obs: &mut dyn Observer) -> RunEnd {
        run_grid(run, 0.0, obs, |y, dt| step(run.model, y, dt))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::physics::scene::{Ball, Scene};

    /// The exact piecewise-linear solve agrees with a bisection to rounding, on
    /// approaches and pressed pairs, sticking and sliding, with rolling resistance.
    #[test]
    fn the_contact_impulse_matches_a_bisection() {
        // The paper's balls in a 4.9 cm groove, the right one three times heavier.
        let ball = |mass| Ball { mass, v0: 0.0 };
        let scene = Scene {
            restitution: 0.6,
            rolling_resistance: 0.01,
            left: ball(0.05),
            right: ball(0.15),
            ..Scene::default()
        };
        let m = Model::of(&scene);
        let cases = [
            [0.0, 0.8, 0.8, 0.0, 0.0, 0.0],
            [0.0, 0.8, 0.5, 0.0, -0.1, 0.2],
            [0.0, 0.3, 0.3, 0.0, 0.29, 0.29],
            [0.0, 1e-4, 0.0, 0.0, 0.0, 1e-4],
            [0.0, 2.0, -1.0, 0.0, -2.0, 1.0],
        ];
        for (n, y) in cases.iter().enumerate() {
            for h in [1e-2, 1e-4, 1e-6] {
                let balls = [
                    Braked::new(&m, 0, y[1], y[2], h),
                    Braked::new(&m, 1, y[4], y[5], h),
                ];
                let w = y[4] - y[1];
                for target in [0.0, -0.5 * w, -w] {
                    if separation(&balls, 0.0).0 >= target {
                        continue;
                    }
                    let (mut lo, mut hi) = (0.0, 1e-9_f64);
                    while separation(&balls, hi).0 < target {
                        lo = hi;
                        hi *= 2.0;
                    }
                    for _ in 0..200 {
                        let mid = 0.5 * (lo + hi);
                        if separation(&balls, mid).0 < target {
                            lo = mid;
                        } else {
                            hi = mid;
                        }
                    }
                    let exact = contact_impulse(&balls, target);
                    assert!(
                        (exact - hi).abs() <= 1e-12 * hi,
                        "case {n}, h {h}, target {target}: {exact} against {hi}"
                    );
                    let s = separation(&balls, exact).0;
                    assert!(
                        (s - target).abs() <= 1e-12 * w.abs().max(1e-3),
                        "{s} {target}"
                    );
                }
            }
        }
    }
}
