//! Fixed-step methods: explicit Euler and semi-implicit Euler with Coulomb friction,
//! classical RK4 with `tanh(s/ε)` friction. Impacts: see the module above.

use super::grid::{GridStep, run_grid};
use super::run::{Integrator, Observer, Run, RunEnd};
use super::system::{Friction, Model, Y, resolve_overlap, rhs};

/// The fixed-step methods.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Fixed {
    Euler,
    SymplecticEuler,
    Rk4,
}

/// Butcher tableau of classical RK4, as data (statics: an unoptimised build copies a
/// const table whole at every use).
static RK4_C: [f64; 4] = [0.0, 0.5, 0.5, 1.0];
static RK4_B: [f64; 4] = [1.0 / 6.0, 1.0 / 3.0, 1.0 / 3.0, 1.0 / 6.0];

fn axpy(y: &Y, h: f64, d: &Y) -> Y {
    std::array::from_fn(|j| y[j] + h * d[j])
}

/// One step of `method`; returns the new state and the right-hand-side evaluations.
fn step(method: Fixed, m: &Model, law: Friction, y: &Y, h: f64) -> (Y, usize) {
    match method {
        Fixed::Euler => (axpy(y, h, &rhs(m, law, y)), 1),
        Fixed::SymplecticEuler => {
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
        Fixed::Rk4 => {
            let mut k = [[0.0; 6]; 4];
            for i in 0..4 {
                let yi = if i == 0 {
                    *y
                } else {
                    axpy(y, RK4_C[i] * h, &k[i - 1])
                };
                k[i] = rhs(m, law, &yi);
            }
            // Written out (same terms and order as an iterator's sum, so the same
            // bits): iterator chains are slow in the debug build the tests use.
            let d: Y = std::array::from_fn(|j| {
                RK4_B[0] * k[0][j] + RK4_B[1] * k[1][j] + RK4_B[2] * k[2][j] + RK4_B[3] * k[3][j]
            });
            (axpy(y, h, &d), 4)
        }
    }
}

impl Integrator for Fixed {
    fn integrate(&self, run: &Run, obs: &mut dyn Observer) -> RunEnd {
        let (m, s) = (run.model, run.stepping);
        // RK4's friction is regularised (`Method::regularised`).
        let (law, roll_threshold) = if *self == Fixed::Rk4 {
            (Friction::Tanh(s.epsilon), s.epsilon)
        } else {
            (Friction::Coulomb, 0.0)
        };
        run_grid(run, roll_threshold, obs, |y, h| {
            let (mut next, rhs_evals) = step(*self, m, law, y, h);
            let impact = resolve_overlap(m, &mut next);
            GridStep {
                y: next,
                rhs_evals,
                impact,
            }
        })
    }
}
