//! The model fit's residuals: what it compares with the data ([`Target`]), the frames
//! it uses (away from the model's impacts), the derived velocities the model is put
//! through as the data were, and the positions with the impact's time, place and
//! mark angle profiled out.

use super::problem::Evals;
use super::uncertainty::{Label, solve};
use crate::physics::scene::Scene;
use crate::physics::solution::Solution;
use crate::study::measured::series::{Measured, Stencil, Stencils};

/// Points the model fit uses: all but the frames that straddle an impact of the
/// model `scene` (a frame holding a jump measures neither side of it).
pub(super) fn fit_points(
    m: &Measured,
    scene: &Scene,
    target: Target,
    evals: &mut Evals,
) -> Vec<usize> {
    // Positions do not jump at an impact: every frame counts.
    if target == Target::Position {
        return (0..m.t().len()).collect();
    }
    let sol = evals.solve(scene, start(m));
    let near = NearImpacts::of(m.t(), &sol);
    m.t()
        .iter()
        .enumerate()
        .filter(|&(_, &t)| !near.straddles(t))
        .map(|(i, _)| i)
        .collect()
}

/// Where the model's run starts for the series `m`: at its first point, and at the
/// latest a millisecond before the impact (t = 0); an empty series has no first point.
fn start(m: &Measured) -> f64 {
    m.t().first().map_or(-1e-3, |t0| t0.min(-1e-3))
}

/// The frames a velocity fit leaves out: those within one frame interval (the
/// shortest of the series) of an impact of the model, where the derived velocity
/// straddles the jump and measures neither side of it.
#[derive(Clone, Debug)]
pub struct NearImpacts {
    frame: f64,
    impacts: Vec<f64>,
}

impl NearImpacts {
    /// For the frame times `t` (sorted) against the impacts of `sol`.
    pub fn of(t: &[f64], sol: &Solution) -> NearImpacts {
        NearImpacts {
            frame: t
                .iter()
                .zip(t.iter().skip(1))
                .map(|(a, b)| b - a)
                .fold(f64::INFINITY, f64::min),
            impacts: sol
                .events
                .iter()
                .filter(|e| e.kind == crate::physics::solution::EventKind::Collision)
                .map(|e| e.t)
                .collect(),
        }
    }

    /// Whether the frame at time `t` is left out.
    pub fn straddles(&self, t: f64) -> bool {
        self.impacts.iter().any(|&a| (t - a).abs() < self.frame)
    }

    /// Whether any frame of `t` (sorted) is left out: the frames nearest each impact
    /// are looked at, not every frame (a series may hold a million).
    pub fn any_in(&self, t: &[f64]) -> bool {
        self.impacts.iter().any(|&a| {
            let i = t.partition_point(|&x| x < a);
            [i.checked_sub(1), Some(i)]
                .into_iter()
                .flatten()
                .filter_map(|k| t.get(k))
                .any(|&x| self.straddles(x))
        })
    }
}

/// What a model fit compares with the data.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Target {
    /// v_cm and v_t, each residual divided by its uncertainty when the data carry one.
    Velocity,
    /// The centre's x (m) and the mark's angle as an arc of the contact circle (r θ, m).
    Position,
}

/// Residuals of `scene` against `m` at `idx`, weighted (divided by the points'
/// uncertainties, where known) or not, with each velocity residual's [`Label`] (none
/// for positions); points not measured (NaN) are left out.
pub(super) fn labelled_residuals(
    scene: &Scene,
    m: &Measured,
    idx: &[usize],
    target: Target,
    weighted: bool,
    evals: &mut Evals,
) -> (Vec<f64>, Vec<Label>) {
    let sol = evals.solve(scene, start(m));
    match target {
        Target::Velocity => velocity_residuals(&sol, m, idx, weighted),
        Target::Position => position_residuals(scene, &sol, m, idx, weighted),
    }
}

/// Each point's centre residual of the position fit of `scene` against `m`, m: the
/// model's x minus the data's, with the impact's time, place and mark angle profiled
/// out as the fit does (weighted as it is) over the points but those `out` (frames
/// left out of the fit, whose own residuals would pull the shifts); NaN where x is
/// not measured.
pub(super) fn centre_misses(
    scene: &Scene,
    m: &Measured,
    out: &[usize],
    evals: &mut Evals,
) -> Vec<f64> {
    let sol = evals.solve(scene, start(m));
    let kept: Vec<usize> = (0..m.t().len())
        .filter(|i| out.binary_search(i).is_err())
        .collect();
    let (_, shift, clock) = aligned(scene, &sol, m, &kept, true);
    let all: Vec<usize> = (0..m.t().len()).collect();
    let rows = position_rows(scene, &sol, m, &all, true, clock);
    let mut misses = vec![f64::NAN; m.t().len()];
    for (row, (i, spin)) in &rows {
        // A weighted row holds its weight w as ∂/∂δx = −w: over it, metres again.
        if let (Some(o), false) = (misses.get_mut(*i), *spin) {
            *o = shifted(row, &shift) / -row[2];
        }
    }
    misses
}

/// One over a residual's uncertainty (1 unweighted or without one); `None` for a
/// residual that is not a number or whose uncertainty is not usable (left out; a
/// column without point `i` has none usable).
fn weight(d: f64, sigma: Option<&[f64]>, i: usize, weighted: bool) -> Option<f64> {
    if !d.is_finite() {
        return None;
    }
    match sigma
        .filter(|_| weighted)
        .map(|s| s.get(i).copied().unwrap_or(f64::NAN))
    {
        None => Some(1.0),
        Some(s) if s > 0.0 && s.is_finite() => Some(1.0 / s),
        Some(_) => None,
    }
}

/// [`labelled_residuals`] of v_cm and v_t.
///
/// The impact time was estimated from the same noisy data (a track's positions, or a
/// velocity file's drop, which only says between which two frames it lies): the
/// model's time gets the best shift δt, profiled out of the fit as the position fit
/// does — else its error lands in μ_k and the ± leaves it out.
fn velocity_residuals(
    sol: &Solution,
    m: &Measured,
    idx: &[usize],
    weighted: bool,
) -> (Vec<f64>, Vec<Label>) {
    let rows = match &m.stencils() {
        // A track's impact is found to a fraction of a frame: the shift is small, and
        // linearised (v moves by a δt) it keeps the stencils on the tracked frames.
        Some(_) => {
            let rows = velocity_rows(sol, m, idx, weighted, 0.0);
            let shift = newton_step(&rows);
            rows.into_iter()
                .map(|(r, s, l)| (r + s * shift, s, l))
                .collect()
        }
        // A velocity file's shift can be most of a frame, and a linearised one is wrong
        // where a data point lies between the model's end of sliding and its shifted
        // time (the residuals then jump as the end of sliding passes the point): the
        // model is evaluated at the shifted times, by Newton steps (exact in one within
        // a phase of constant acceleration).
        None => {
            let half = 0.5 * frame_at_impact(m.t());
            let mut shift = 0.0;
            let mut rows = velocity_rows(sol, m, idx, weighted, shift);
            for _ in 0..6 {
                let next = eased(shift + newton_step(&rows), half);
                if (next - shift).abs() <= 1e-12 {
                    break;
                }
                shift = next;
                rows = velocity_rows(sol, m, idx, weighted, shift);
            }
            rows
        }
    };
    rows.into_iter().map(|(r, _, l)| (r, l)).unzip()
}

/// (residual, ∂/∂δt, label) of each v_cm and v_t at `idx`, each over its uncertainty
/// when `weighted`, with the model's clock moved by `shift` (s): the data's t is the
/// model's t + shift.
fn velocity_rows(
    sol: &Solution,
    m: &Measured,
    idx: &[usize],
    weighted: bool,
    shift: f64,
) -> Vec<(f64, f64, Label)> {
    let mut rows = Vec::with_capacity(2 * idx.len());
    let mut cursor = sol.cursor();
    for &i in idx {
        // A point the series does not hold has nothing to compare with.
        let (Some(&t), Some(&v_cm), Some(&v_t)) = (m.t().get(i), m.v_cm().get(i), m.v_t().get(i))
        else {
            continue;
        };
        let t = t + shift;
        let s = cursor.at(t);
        let (a, du) = cursor.segment_at(t).accel[0];
        let (v, u) = match &m.stencils() {
            Some(st) => as_derived(sol, st, i, (s.left.v, s.left.u)),
            None => (s.left.v, s.left.u),
        };
        let values = [
            (v - v_cm, a, m.v_cm_sigma(), false),
            (u - v_t, du, m.v_t_sigma(), true),
        ];
        for (d, slope, sigma, spin) in values {
            if let Some(w) = weight(d, sigma, i, weighted) {
                rows.push((d * w, slope * w, (i, spin)));
            }
        }
    }
    rows
}

/// The shift of the model's clock that minimises the residuals `rows` linearised
/// (each moves by its slope times the shift); 0 when none has a slope.
fn newton_step(rows: &[(f64, f64, Label)]) -> f64 {
    let (num, den) = rows
        .iter()
        .fold((0.0, 0.0), |(n, d), (r, s, _)| (n + r * s, d + s * s));
    if den > 0.0 { -num / den } else { 0.0 }
}

/// A velocity file's impact shift `shift`, kept near the frames of the drop: as is
/// within `half` (half a frame: the drop puts the impact there), beyond it eased
/// smoothly toward a whole frame and never past it. A larger shift would only hide a
/// misfit of the model (the paper's series would take 20–30 ms); a hard stop at half a
/// frame would push the estimate's own scatter into μ_k (measured: 2 of 40 synthetic
/// files then 5σ off), and its kink stalls the search.
fn eased(shift: f64, half: f64) -> f64 {
    if shift.abs() <= half {
        return shift;
    }
    let over = (shift.abs() - half) / half;
    (half + half * over.tanh()).copysign(shift)
}

/// The spacing of the two frames around t = 0 (the impact), s; 0 when the series
/// does not hold both.
fn frame_at_impact(t: &[f64]) -> f64 {
    let i = t.partition_point(|&x| x < 0.0);
    match (i.checked_sub(1).and_then(|j| t.get(j)), t.get(i)) {
        (Some(a), Some(b)) => b - a,
        _ => 0.0,
    }
}

/// The position residuals (x, and r θ of the mark), each over its point's σ when
/// `weighted` and the track states them ([`point_weights`]), with the impact's time,
/// place and mark angle profiled out ([`aligned`]).
fn position_residuals(
    scene: &Scene,
    sol: &Solution,
    m: &Measured,
    idx: &[usize],
    weighted: bool,
) -> (Vec<f64>, Vec<Label>) {
    let (rows, shift, _) = aligned(scene, sol, m, idx, weighted);
    rows.iter()
        .map(|(row, label)| (shifted(row, &shift), *label))
        .filter(|(d, _)| d.is_finite())
        .unzip()
}

/// A [`position_rows`] row's residual with the linear shifts `shift` (δt, δx and, with
/// a mark, δθ) applied: the residual plus each derivative times its shift.
fn shifted(row: &[f64; 4], shift: &[f64]) -> f64 {
    let [r, d @ ..] = row;
    r + d.iter().zip(shift).map(|(d, s)| d * s).sum::<f64>()
}

/// [`position_rows`]' rows: each residual with its derivatives by the shifts, and
/// its frame and whether the mark's.
type PositionRows = Vec<([f64; 4], Label)>;

/// Most Newton steps of the impact time's shift ([`aligned`]).
const SHIFT_STEPS: usize = 6;

/// The [`position_rows`] with the model's clock moved by the profiled impact time
/// shift (returned last), and the remaining linear shifts (δt left, δx, δθ:
/// [`profiled_shift`]) that make them the residuals. The time shift is not linear (x moves by v δt only
/// within one phase: an impact or the end of sliding between a frame and its shifted
/// time breaks it), so it is found by Newton steps on the model's own run, as long as
/// each lowers the residuals: a linear shift alone left 0.02 mm residuals on an
/// exact 30 frames/s track, which larger models then fitted with e and c_rr.
fn aligned(
    scene: &Scene,
    sol: &Solution,
    m: &Measured,
    idx: &[usize],
    weighted: bool,
) -> (PositionRows, Vec<f64>, f64) {
    let square = |rows: &[([f64; 4], Label)], shift: &[f64]| -> f64 {
        rows.iter()
            .map(|(row, _)| {
                let d = shifted(row, shift);
                d * d
            })
            .sum()
    };
    let mut clock = 0.0;
    let mut rows = position_rows(scene, sol, m, idx, weighted, clock);
    let mut shift = profiled_shift(&rows);
    let mut cost = None;
    for _ in 0..SHIFT_STEPS {
        let step = shift.first().copied().unwrap_or(0.0);
        if !step.is_finite() || step.abs() <= 1e-12 {
            break;
        }
        let next_rows = position_rows(scene, sol, m, idx, weighted, clock + step);
        if next_rows.len() != rows.len() {
            break;
        }
        let next = profiled_shift(&next_rows);
        let next_cost = square(&next_rows, &next);
        if next_cost >= *cost.get_or_insert_with(|| square(&rows, &shift)) {
            break;
        }
        (clock, rows, shift, cost) = (clock + step, next_rows, next, Some(next_cost));
    }
    (rows, shift, clock)
}

/// Each position residual of `scene`'s run `sol` against the track `m` at `idx`, the
/// model's clock moved by `clock` (s: the data's t is the model's t + `clock`), with
/// its derivatives by the impact's time, place and mark angle shifts (δt, δx, δθ:
/// linearised, x moves by v δt, r θ by u δt), and which frame and whether the mark's;
/// each row over its point's σ when `weighted` ([`point_weights`]). Rows not all
/// finite are left out.
fn position_rows(
    scene: &Scene,
    sol: &Solution,
    m: &Measured,
    idx: &[usize],
    weighted: bool,
    clock: f64,
) -> Vec<([f64; 4], Label)> {
    let (Some(x), radius) = (m.x(), scene.k() * scene.radius) else {
        return Vec::new();
    };
    let theta0 = sol.angle_at(0.0)[0];
    // One segment lookup per frame: the state and the angle come from the same one.
    // (frame, the left ball's state, its angle); a frame the series does not hold
    // has no time and is left out. Every column has the times' length ([`Measured`]),
    // so a frame with a time has its x and angle (NaN where not measured: such a row
    // is left out below).
    let mut cursor = sol.cursor();
    let mut at = Vec::with_capacity(idx.len());
    at.extend(idx.iter().filter_map(|&i| {
        let t = m.t().get(i)? + clock;
        let (s, angle) = cursor.ball_and_angle(0, t);
        Some((i, s, angle))
    }));
    let value = |column: &[f64], i: usize| column.get(i).copied().unwrap_or(f64::NAN);
    let turn = m
        .angle()
        .map(|a| branch_offset(at.iter().map(|&(i, _, angle)| angle - theta0 - value(a, i))));
    let w = point_weights(m, weighted, radius);
    let times = |row: [f64; 4], w: f64| row.map(|v| v * w);
    let mut rows: Vec<([f64; 4], Label)> = Vec::with_capacity(2 * at.len());
    // Rows not all finite are left out as they are made.
    let mut push = |row: [f64; 4], label: Label| {
        if row.iter().all(|v| v.is_finite()) {
            rows.push((row, label));
        }
    };
    for &(i, s, angle) in &at {
        push(
            times([s.x + scene.radius - value(x, i), s.v, -1.0, 0.0], w.0(i)),
            (i, false),
        );
        if let (Some(a), Some(c)) = (&m.angle(), turn) {
            let d = same_turn(angle - theta0 - value(a, i), c);
            push(times([radius * d, s.u, 0.0, -radius], w.1(i)), (i, true));
        }
    }
    rows
}

/// The weights of a point's x residual and of its mark's r θ residual (1/σ of each,
/// from `x_sigma`, and `angle_sigma` times the contact radius `radius`), when
/// `weighted` and the track states the σ of x and (with a mark) of the angle; else 1
/// for all, as without σ. A weight that is not a number leaves its row out.
fn point_weights(
    m: &Measured,
    weighted: bool,
    radius: f64,
) -> (impl Fn(usize) -> f64 + '_, impl Fn(usize) -> f64 + '_) {
    let x = m.x_sigma().filter(|_| weighted);
    let angle = m.angle_sigma();
    // Both or neither: x in metres beside unweighted angles would mix units.
    let on = x.is_some() && (m.angle().is_none() || angle.is_some());
    let inverse = |s: Option<&f64>, scale: f64| s.map_or(f64::NAN, |s| 1.0 / (s * scale));
    (
        move |i: usize| {
            if on {
                inverse(x.and_then(|s| s.get(i)), 1.0)
            } else {
                1.0
            }
        },
        move |i: usize| {
            if on {
                inverse(angle.and_then(|s| s.get(i)), radius)
            } else {
                1.0
            }
        },
    )
}

/// The common offset (rad) of model-minus-measured mark angles, as their circular mean:
/// a mark hidden by the rail for a few frames turns by more than π meanwhile, so the
/// measured angles' unwrapping can be off by whole turns after a gap. It only picks
/// each residual's turn ([`same_turn`]), so [`OFFSET_SAMPLE`] angles spread over the
/// track give it as well as all of them (a sine and a cosine per frame were a tenth
/// of a fit's time).
fn branch_offset(diffs: impl Iterator<Item = f64> + Clone) -> f64 {
    let finite = diffs.clone().filter(|d| d.is_finite()).count();
    let every = finite.div_ceil(OFFSET_SAMPLE).max(1);
    let (s, c) = diffs
        .filter(|d| d.is_finite())
        .step_by(every)
        .fold((0.0, 0.0), |(s, c), d| (s + d.sin(), c + d.cos()));
    s.atan2(c)
}

/// At most how many mark angles [`branch_offset`] averages.
const OFFSET_SAMPLE: usize = 16;

/// `d` moved by whole turns to within π of `centre`: the residual of a mark angle does
/// not depend on which turn the measured angle was unwrapped to (nor on `centre`, as
/// long as the turn is the same).
fn same_turn(d: f64, centre: f64) -> f64 {
    let tau = std::f64::consts::TAU;
    d - tau * nearest_whole((d - centre) / tau)
}

/// `x` rounded to the nearest whole number, halves away from zero: exactly
/// [`f64::round`], without its call into the maths library (which does not inline on
/// the baseline x86-64 and was 8 % of a marked-track fit: it runs for every mark row
/// of every model evaluation).
fn nearest_whole(x: f64) -> f64 {
    // 2^52: from here on every f64 is whole; NaN is not below it either.
    if x.is_nan() || x.abs() >= 4_503_599_627_370_496.0 {
        return x.round();
    }
    // Truncation toward zero; `x - whole` is exact for |x| < 2^52.
    let whole = x as i64 as f64;
    let rest = x - whole;
    let r = if rest >= 0.5 {
        whole + 1.0
    } else if rest <= -0.5 {
        whole - 1.0
    } else {
        whole
    };
    // f64::round keeps the sign of a zero result (−0.3 → −0).
    r.copysign(x)
}

/// The impact's time and place, and the mark's angle then, were estimated from the
/// same noisy track: the least-squares shifts (δt, δx and, with a mark's rows, δθ)
/// of the [`position_rows`], profiled out of the fit (zero when they cannot be
/// solved). δθ only where a mark's row is among them: a track that names a mark
/// whose angles give no row (its frames too few or apart for a local fit) left δθ's
/// column empty, the three unsolvable, and no shift at all, so the impact's time
/// and place stayed where one noisy frame put them and e took up the miss (μ_k 0.146
/// with e 0.91 from a film of 0.17 and 1; 0.168 without the mark's columns).
fn profiled_shift(rows: &[([f64; 4], Label)]) -> Vec<f64> {
    let mark = rows.iter().any(|(_, (_, spin))| *spin);
    let k = if mark { 3 } else { 2 };
    // Fixed-size sums: this runs on every row of every model evaluation.
    let mut ata = [[0.0; 3]; 3];
    let mut atb = [0.0; 3];
    for (row, _) in rows {
        let [r, d @ ..] = *row;
        for ((atb_a, ata_a), da) in atb.iter_mut().zip(&mut ata).zip(d) {
            *atb_a -= da * r;
            for (x, db) in ata_a.iter_mut().zip(d) {
                *x += da * db;
            }
        }
    }
    let ata = ata
        .iter()
        .take(k)
        .map(|row| row.iter().take(k).copied().collect())
        .collect();
    solve(ata, atb.iter().take(k).copied().collect()).unwrap_or_else(|| vec![0.0; k])
}

/// A position track's centre where the model's left ball would be (x − R, m) at each
/// frame, moved by the impact time and place shifts the position fit profiles out
/// ([`profiled_shift`]; the detected impact is one noisy frame's estimate, and without
/// them every residual leans one way): model minus this is the position fit's
/// residual. NaN outside the run `sol` of `scene` and where x is not measured; `None`
/// without positions.
pub fn aligned_track(scene: &Scene, sol: &Solution, m: &Measured) -> Option<Vec<f64>> {
    m.x()?;
    let idx: Vec<usize> = m
        .t()
        .iter()
        .enumerate()
        .filter(|(_, t)| (sol.t_start..=sol.t_end).contains(*t))
        .map(|(i, _)| i)
        .collect();
    let (rows, shift, _) = aligned(scene, sol, m, &idx, true);
    // The time and place shifts, zero where they could not be solved (as there).
    let (dt, dx) = match shift.as_slice() {
        [dt, dx, ..] => (*dt, *dx),
        _ => (0.0, 0.0),
    };
    let mut out = vec![f64::NAN; m.t().len()];
    let mut cursor = sol.cursor();
    // The model's x at each frame minus the frame's residual (each row holds its
    // weight w as ∂/∂δx = −w): model minus the aligned track is the residual.
    for (row, (i, spin)) in &rows {
        let (Some(o), Some(&t), false) = (out.get_mut(*i), m.t().get(*i), *spin) else {
            continue;
        };
        let d = row[0] + row[1] * dt + row[2] * dx;
        *o = cursor.at(t).left.x + d / row[2];
    }
    Some(out)
}

/// The model's v_cm and v_t at point `i` (`exact` there) as the data were made: a
/// velocity derived from a track is a local fit's slope over frames, which rounds the
/// corners of v(t) (the end of sliding, an impact), so the model's positions go
/// through the same stencil and get the same rounding — else the fit bends μ_k to
/// match the rounded corner. Within one segment the positions are quadratic in t and
/// the stencil gives the exact slope back: only windows over a boundary are summed.
fn as_derived(sol: &Solution, st: &Stencils, i: usize, exact: (f64, f64)) -> (f64, f64) {
    // A stencil whose ends lie past the frames has no times there: the model's exact
    // value stands (`weights` gives frames without a time no weight either).
    let one_segment = |times: &[f64], s: &Stencil| match (times.get(s.lo), times.get(s.hi)) {
        (Some(&lo), Some(&hi)) => std::ptr::eq(sol.segment_at(lo), sol.segment_at(hi)),
        _ => true,
    };
    // `weights` yields only frames with a time.
    let at = |times: &[f64], k: usize| times.get(k).copied().unwrap_or(f64::NAN);
    let v = match st.v_cm.get(i) {
        Some(Some(s)) if !one_segment(&st.centre_times, s) => s
            .weights(&st.centre_times)
            .map(|(k, w)| w * sol.at(at(&st.centre_times, k)).left.x)
            .sum(),
        _ => exact.0,
    };
    let r = sol.scene.k() * sol.scene.radius;
    let u = match st.v_t.get(i) {
        Some(Some(s)) if !one_segment(&st.mark_times, s) => {
            r * s
                .weights(&st.mark_times)
                .map(|(k, w)| w * sol.angle_at(at(&st.mark_times, k))[0])
                .sum::<f64>()
        }
        _ => exact.1,
    };
    (v, u)
}

/// Parameters a fit to `target` estimates besides the free scene values.
pub(super) fn nuisance(m: &Measured, target: Target) -> usize {
    match (target, m.angle().is_some()) {
        // The impact time ([`velocity_residuals`]).
        (Target::Velocity, _) => 1,
        (Target::Position, false) => 2,
        (Target::Position, true) => 3,
    }
}

/// The weighted residuals of [`labelled_residuals`], without their labels: what a
/// fit minimises.
pub(super) fn residuals(
    scene: &Scene,
    m: &Measured,
    idx: &[usize],
    target: Target,
    evals: &mut Evals,
) -> Vec<f64> {
    labelled_residuals(scene, m, idx, target, true, evals).0
}

#[cfg(test)]
mod tests {
    use super::{NearImpacts, branch_offset, nearest_whole, same_turn};
    use proptest::prelude::*;

    proptest! {
        /// The fit's rounding gives exactly what `f64::round` gives, sign of zero
        /// included: any f64 (the whole bit space: NaN, infinities, subnormals, huge)
        /// and every value near a half, where the two ways of rounding could part.
        #[test]
        fn nearest_whole_is_exactly_round(bits in any::<u64>(), k in -1_000_000i64..1_000_000, ulps in -3i64..=3) {
            let x = f64::from_bits(bits);
            prop_assert_eq!(nearest_whole(x).to_bits(), x.round().to_bits(), "{}", x);
            let half = k as f64 + 0.5;
            let near = f64::from_bits((half.to_bits() as i64 + ulps) as u64);
            prop_assert_eq!(nearest_whole(near).to_bits(), near.round().to_bits(), "{}", near);
        }
    }

    #[test]
    fn nearest_whole_at_its_edges() {
        for x in [
            0.0,
            -0.0,
            0.5,
            -0.5,
            0.49999999999999994,
            -0.49999999999999994,
            1.5,
            -2.5,
            4_503_599_627_370_495.5,
            4_503_599_627_370_496.0,
            -4_503_599_627_370_495.5,
            f64::MAX,
            f64::MIN_POSITIVE,
            f64::NAN,
            f64::INFINITY,
            f64::NEG_INFINITY,
        ] {
            assert_eq!(nearest_whole(x).to_bits(), x.round().to_bits(), "{x}");
        }
    }

    #[test]
    fn a_mark_angle_unwrapped_a_turn_off_leaves_its_residual_unchanged() {
        use std::f64::consts::TAU;
        // Model-minus-measured angles 0.3 rad apart, two of them a whole turn off
        // (the mark hidden across a gap longer than half a turn).
        let diffs = [0.30, 0.31, 0.29 + TAU, 0.30, 0.32 - 2.0 * TAU];
        let c = branch_offset(diffs.iter().copied());
        assert!((c - 0.304).abs() < 0.01, "{c}");
        for d in diffs {
            let r = same_turn(d, c);
            assert!((r - 0.30).abs() < 0.03, "{d} -> {r}");
        }
        // Near ±π the branch follows the common offset, not the principal value.
        assert!((same_turn(-3.1, 3.1) - (TAU - 3.1)).abs() < 1e-12);
    }

    #[test]
    fn any_in_agrees_with_every_frame_looked_at() {
        let t: Vec<f64> = (0..50).map(|i| -0.2 + 0.02 * f64::from(i)).collect();
        for impacts in [
            vec![],
            vec![0.0],
            vec![0.3, 0.61],
            vec![-1.0, 5.0],
            vec![-0.21],
            vec![0.79],
        ] {
            let near = NearImpacts {
                frame: 0.02 - 1e-12,
                impacts: impacts.clone(),
            };
            let every = t.iter().any(|&x| near.straddles(x));
            assert_eq!(near.any_in(&t), every, "{impacts:?}");
        }
    }
}
