//! Adaptive Dormand–Prince 5(4) as a hybrid-ODE solver, the approach of scipy's
//! `solve_ivp` events or DifferentialEquations.jl callbacks: integrate the smooth
//! dynamics of the current mode (each ball sliding with a fixed slip sign, or
//! rolling), locate the zeros of the switching functions (slip, gap, rolling speed) on
//! the dense output by bisection, apply the jump, restart. Its weak point is the
//! accumulation of impacts: every one of infinitely many events costs steps.

use super::grid::EventTracker;
use super::run::{Integrator, Observer, Run, RunEnd, Stall};
use super::system::{Model, Stepping, Y, collide, gap};

/// The Dormand–Prince 5(4) method with event location.
pub(super) struct Rk45;

// The Dormand–Prince 5(4) tableau with Shampine's dense output (as scipy's RK45).
// The system is autonomous, so the stage times only serve the tableau check.
// Statics, not consts: an unoptimised build copies a const table whole at every use.
#[cfg_attr(not(test), allow(dead_code))]
static C: [f64; 7] = [0.0, 1.0 / 5.0, 3.0 / 10.0, 4.0 / 5.0, 8.0 / 9.0, 1.0, 1.0];
static A: [[f64; 6]; 7] = [
    [0.0; 6],
    [1.0 / 5.0, 0.0, 0.0, 0.0, 0.0, 0.0],
    [3.0 / 40.0, 9.0 / 40.0, 0.0, 0.0, 0.0, 0.0],
    [44.0 / 45.0, -56.0 / 15.0, 32.0 / 9.0, 0.0, 0.0, 0.0],
    [
        19372.0 / 6561.0,
        -25360.0 / 2187.0,
        64448.0 / 6561.0,
        -212.0 / 729.0,
        0.0,
        0.0,
    ],
    [
        9017.0 / 3168.0,
        -355.0 / 33.0,
        46732.0 / 5247.0,
        49.0 / 176.0,
        -5103.0 / 18656.0,
        0.0,
    ],
    FIFTH,
];
/// The 5th-order weights, which are also the last stage's row (first same as last).
const FIFTH: [f64; 6] = [
    35.0 / 384.0,
    0.0,
    500.0 / 1113.0,
    125.0 / 192.0,
    -2187.0 / 6784.0,
    11.0 / 84.0,
];
static B: [f64; 7] = [
    FIFTH[0], FIFTH[1], FIFTH[2], FIFTH[3], FIFTH[4], FIFTH[5], 0.0,
];
static E: [f64; 7] = [
    -71.0 / 57600.0,
    0.0,
    71.0 / 16695.0,
    -71.0 / 1920.0,
    17253.0 / 339200.0,
    -22.0 / 525.0,
    1.0 / 40.0,
];
static P: [[f64; 4]; 7] = [
    [
        1.0,
        -8048581381.0 / 2820520608.0,
        8663915743.0 / 2820520608.0,
        -12715105075.0 / 11282082432.0,
    ],
    [0.0, 0.0, 0.0, 0.0],
    [
        0.0,
        131558114200.0 / 32700410799.0,
        -68118460800.0 / 10900136933.0,
        87487479700.0 / 32700410799.0,
    ],
    [
        0.0,
        -1754552775.0 / 470086768.0,
        14199869525.0 / 1410260304.0,
        -10690763975.0 / 1880347072.0,
    ],
    [
        0.0,
        127303824393.0 / 49829197408.0,
        -318862633887.0 / 49829197408.0,
        701980252875.0 / 199316789632.0,
    ],
    [
        0.0,
        -282668133.0 / 205662961.0,
        2019193451.0 / 616988883.0,
        -1453857185.0 / 822651844.0,
    ],
    [
        0.0,
        40617522.0 / 29380423.0,
        -110615467.0 / 29380423.0,
        69997945.0 / 29380423.0,
    ],
];

/// Event budget: past it an accumulation of impacts is reported as `stalled`.
const MAX_IMPACTS: usize = 2_000;

/// Each ball's mode: sliding with slip sign ±1, or rolling (0).
type Modes = [i8; 2];

fn modes_of(y: &Y, eps: f64) -> Modes {
    std::array::from_fn(|i| {
        let s = y[3 * i + 1] - y[3 * i + 2];
        if s > eps {
            1
        } else if s < -eps {
            -1
        } else {
            0
        }
    })
}

/// Right-hand side in fixed modes (constant accelerations; rolling resistance while
/// rolling, in the direction of motion at the mode's start).
fn rhs(m: &Model, modes: &Modes, roll_dir: &[f64; 2], y: &Y) -> Y {
    let mut d = [0.0; 6];
    for i in 0..2 {
        d[3 * i] = y[3 * i + 1];
        let (a, du) = if modes[i] == 0 {
            let a = -roll_dir[i] * m.rolling_deceleration();
            (a, a)
        } else {
            m.groove.sliding_accelerations(f64::from(modes[i]))
        };
        d[3 * i + 1] = a;
        d[3 * i + 2] = du;
    }
    d
}

/// The switching functions of the current modes: slip of sliding balls, speed of
/// rolling balls with rolling resistance, and the gap.
fn switches(m: &Model, modes: &Modes, y: &Y) -> [f64; 3] {
    let f = |i: usize| {
        if modes[i] != 0 {
            y[3 * i + 1] - y[3 * i + 2]
        } else if m.groove.rolling_resistance > 0.0 {
            y[3 * i + 1]
        } else {
            f64::NAN
        }
    };
    [f(0), f(1), gap(m, y)]
}

/// Sign of a speed, 0 for 0 (`f64::signum(0.0)` is 1).
fn direction(v: f64) -> f64 {
    if v == 0.0 { 0.0 } else { v.signum() }
}

fn crossed(which: usize, g0: f64, g1: f64) -> bool {
    if g0.is_nan() || g1.is_nan() {
        return false;
    }
    if which == 2 {
        g0 > 0.0 && g1 <= 0.0
    } else {
        g0 != 0.0 && (g0 * g1 < 0.0 || g1 == 0.0)
    }
}

/// The seven stages of one Dormand–Prince step (`k[0]` given, at `y`).
type Stages = [[f64; 6]; 7];

/// Fills stages 1 … 6 of a step of size `h` from `y` (stage 0 is the derivative at `y`).
fn fill_stages(m: &Model, modes: &Modes, roll_dir: &[f64; 2], y: &Y, h: f64, k: &mut Stages) {
    for i in 1..7 {
        let yi: Y =
            std::array::from_fn(|j| y[j] + h * (0..i).map(|l| A[i][l] * k[l][j]).sum::<f64>());
        k[i] = rhs(m, modes, roll_dir, &yi);
    }
}

/// The RMS of the embedded error estimate, each component over its tolerance
/// `atol + rtol |y|` (> 1: the step is rejected).
fn step_error(k: &Stages, h: f64, y: &Y, y_new: &Y, (rtol, atol): (f64, f64)) -> f64 {
    let err = (0..6)
        .map(|j| {
            let e = h * (0..7).map(|i| E[i] * k[i][j]).sum::<f64>();
            let sc = atol + rtol * y[j].abs().max(y_new[j].abs());
            (e / sc).powi(2)
        })
        .sum::<f64>()
        / 6.0;
    err.sqrt()
}

/// The dense output of an accepted step at the fraction `theta` of it.
fn dense(y: &Y, k: &Stages, h: f64, theta: f64) -> Y {
    let q = [theta, theta * theta, theta.powi(3), theta.powi(4)];
    // Each stage's weight at θ, the same for every component. The sums are written
    // out (same terms, same order as an iterator's sum): the event search calls this
    // in its bisection, and iterator chains are slow in the debug build the tests use.
    let b: [f64; 7] = P.map(|p| p[0] * q[0] + p[1] * q[1] + p[2] * q[2] + p[3] * q[3]);
    std::array::from_fn(|j| {
        let s = k[0][j] * b[0]
            + k[1][j] * b[1]
            + k[2][j] * b[2]
            + k[3][j] * b[3]
            + k[4][j] * b[4]
            + k[5][j] * b[5]
            + k[6][j] * b[6];
        y[j] + h * s
    })
}

/// The first switching-function zero inside an accepted step (its fraction of the
/// step and which function), located to a time error below `tolerance`. Each
/// function is sampled at quarters of the step too, so a gap that dips below zero and
/// back is seen.
fn first_switch(
    m: &Model,
    modes: &Modes,
    (y, y_new): (&Y, &Y),
    k: &Stages,
    h: f64,
    tolerance: f64,
) -> Option<(f64, usize)> {
    const SAMPLES: [f64; 4] = [0.25, 0.5, 0.75, 1.0];
    let g0 = switches(m, modes, y);
    // Every function at each sample from one dense output there.
    let sampled = SAMPLES.map(|theta| {
        if theta == 1.0 {
            switches(m, modes, y_new)
        } else {
            switches(m, modes, &dense(y, k, h, theta))
        }
    });
    let mut first: Option<(f64, usize)> = None;
    for (which, &g_start) in g0.iter().enumerate() {
        let mut prev = (0.0, g_start);
        for (&theta, g) in SAMPLES.iter().zip(&sampled) {
            let g = g[which];
            if crossed(which, prev.1, g) {
                let (mut lo, mut hi) = (prev.0, theta);
                // Bisect to a time error below the tolerance.
                while (hi - lo) * h > tolerance * 1e-3 && hi - lo > 1e-15 {
                    let mid = 0.5 * (lo + hi);
                    let gm = switches(m, modes, &dense(y, k, h, mid))[which];
                    if crossed(which, prev.1, gm) {
                        hi = mid;
                    } else {
                        lo = mid;
                    }
                }
                if first.is_none_or(|(f, _)| hi < f) {
                    first = Some((hi, which));
                }
                break;
            }
            prev = (theta, g);
        }
    }
    first
}

/// Why the run cannot go on at `t` with step `h`, if it cannot: the step budget
/// spent, impacts accumulating faster than steps, or the step size collapsed.
fn stall(out: &RunEnd, impacts: usize, t: f64, h: f64, s: &Stepping) -> Option<Stall> {
    if out.steps >= s.max_steps {
        Some(Stall::StepBudget {
            budget: s.max_steps,
            t,
        })
    } else if impacts >= MAX_IMPACTS {
        Some(Stall::Accumulating { impacts, t })
    } else if h < 1e-14 * t.abs().max(1.0) {
        Some(Stall::Collapsed { h, t })
    } else {
        None
    }
}

/// A ball's sliding ends (`which` 0 or 1): it rolls again, or it rolled to rest.
fn end_sliding(y: &mut Y, modes: &Modes, i: usize) {
    if modes[i] != 0 {
        y[3 * i + 2] = y[3 * i + 1]; // rolls again
    } else {
        y[3 * i + 1] = 0.0; // rolled to rest
        y[3 * i + 2] = 0.0;
    }
}

/// How much the next step grows after an accepted one of error `err` (×0.2 … ×5).
fn growth(err: f64) -> f64 {
    if err == 0.0 {
        5.0
    } else {
        (0.9 * err.powf(-0.2)).clamp(0.2, 5.0)
    }
}

/// A rolling ball's spin follows its speed exactly (after an event).
fn roll_on(y: &mut Y, modes: &Modes) {
    for i in 0..2 {
        if modes[i] == 0 {
            y[3 * i + 2] = y[3 * i + 1];
        }
    }
}

/// At a located zero of switching function `which`: the impact (the balls then put
/// exactly in touch, the gap being closed) or the end of a ball's sliding. True for an
/// impact.
fn at_switch(m: &Model, y: &mut Y, modes: &Modes, which: usize) -> bool {
    if which == 2 {
        collide(m, y);
        let overlap = gap(m, y);
        y[3] -= overlap;
        true
    } else {
        end_sliding(y, modes, which);
        false
    }
}

impl Integrator for Rk45 {
    fn integrate(&self, run: &Run, obs: &mut dyn Observer) -> RunEnd {
        integrate(run, obs)
    }
}

fn integrate(run: &Run, obs: &mut dyn Observer) -> RunEnd {
    let (m, y0, t0, t1, s) = (run.model, run.y0, run.t0, run.t1, run.stepping);
    // The larger centre speed (at least 1 mm/s) scales the absolute tolerances.
    let scale = [y0[1], y0[4]].iter().map(|v| v.abs()).fold(1e-3, f64::max);
    let tolerances = (s.tolerance, s.tolerance * scale);
    let eps_v = 1e-12 * scale;
    let mut out = RunEnd::at_start(t0, y0);
    let mut tracker = EventTracker::new(0.0);
    if !obs.step(t0, &y0) {
        out.aborted = true;
        return out;
    }
    tracker.step(t0, &y0, obs);
    let (mut t, mut y) = (t0, y0);
    let mut modes = modes_of(&y, eps_v);
    let mut roll_dir = [direction(y[1]), direction(y[4])];
    let mut h = s.step.min(t1 - t0);
    let mut k: Stages = [[0.0; 6]; 7];
    let mut fresh = true;
    let mut impacts = 0;
    while t < t1 {
        if let Some(why) = stall(&out, impacts, t, h, s) {
            out.stalled = Some(why);
            break;
        }
        h = h.min(t1 - t);
        if gap(m, &y) <= 0.0 && y[1] > y[4] {
            // Touching and closing: an impact now (the last one of a series left the
            // balls in touch with a sliver of closing speed).
            collide(m, &mut y);
            tracker.impact(t, &y, obs);
            impacts += 1;
            modes = modes_of(&y, eps_v);
            roll_dir = [direction(y[1]), direction(y[4])];
            fresh = true;
            continue;
        }
        if fresh {
            k[0] = rhs(m, &modes, &roll_dir, &y);
            out.rhs_evals += 1;
            fresh = false;
        }
        fill_stages(m, &modes, &roll_dir, &y, h, &mut k);
        out.rhs_evals += 6;
        let y_new: Y =
            std::array::from_fn(|j| y[j] + h * (0..7).map(|i| B[i] * k[i][j]).sum::<f64>());
        let err = step_error(&k, h, &y, &y_new, tolerances);
        if err > 1.0 {
            h *= (0.9 * err.powf(-0.2)).max(0.2);
            out.steps += 1;
            continue;
        }
        // Accepted: look for switching-function zeros inside the step.
        let first = first_switch(m, &modes, (&y, &y_new), &k, h, s.tolerance);
        out.steps += 1;
        if first.is_none() && switches(m, &modes, &y_new)[2] < 0.0 {
            // The balls overlap at the end of a step with no closing located: a whole
            // cycle fitted inside the step (or they press together). Retry smaller.
            h *= 0.5;
            continue;
        }
        match first {
            None => {
                t += h;
                y = y_new;
                k[0] = k[6];
                h *= growth(err);
            }
            Some((theta, which)) => {
                t += theta * h;
                y = dense(&y, &k, h, theta);
                if at_switch(m, &mut y, &modes, which) {
                    tracker.impact(t, &y, obs);
                    impacts += 1;
                }
                modes = modes_of(&y, eps_v);
                roll_on(&mut y, &modes);
                roll_dir = [direction(y[1]), direction(y[4])];
                fresh = true;
            }
        }
        tracker.step(t, &y, obs);
        if !obs.step(t, &y) {
            out.aborted = true;
            break;
        }
    }
    out.t = t;
    out.y = y;
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tableau_is_consistent() {
        for i in 0..7 {
            let row: f64 = A[i].iter().sum();
            assert!((row - C[i]).abs() < 1e-14, "row {i}");
        }
        assert!((B.iter().sum::<f64>() - 1.0).abs() < 1e-14);
        assert!(E.iter().sum::<f64>().abs() < 1e-14);
        // The dense output at θ = 1 is the 5th-order step.
        for i in 0..7 {
            let at_one: f64 = P[i].iter().sum();
            assert!((at_one - B[i]).abs() < 1e-12, "P row {i}");
        }
    }
}
