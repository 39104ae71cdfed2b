//! What a model fit can say about its free values: their bounds, their standard errors
//! from the normal matrix, and why a value gets none ([`NotIdentified`]); with the
//! small dense solves the fit needs.

use serde::Serialize;

use super::problem::{Free, MAX_PLAUSIBLE_MU};
use crate::study::measured::series::Stencils;

/// Which measured value a residual compares with: the point's index and whether it is
/// its second channel (v_t, else v_cm; for positions the mark's angle, else x).
pub(super) type Label = (usize, bool);

/// A free value without an uncertainty, and why.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct NotIdentified {
    pub parameter: &'static str,
    pub reason: String,
    /// The value's physical range as people read it when the best fit lies on its
    /// edge (then the data push it there: they do not support it as a free value).
    #[serde(skip)]
    pub on_edge_of: Option<&'static str>,
}

/// A fitted value's bounds: its physical range in the parameter table (a fit is no
/// better than the scenes it may propose: μ_k = 1e10 is no friction coefficient).
pub(super) fn bounds(f: Free) -> (f64, f64) {
    let range = f.key().param().range;
    (range.lo, range.hi)
}

/// A fitted value's range as people read it.
fn range_text(f: Free) -> &'static str {
    f.key().param().range.text
}

/// The range a fitted value's ± must lie well inside of to say anything of it, and
/// that range as people read it: its physical range, but for μ_k what a ball rolling
/// in a groove may plausibly have ([`MAX_PLAUSIBLE_MU`]; the table
/// allows up to 10 for any scene one may set). A μ_k of 0.09 ± 1.4 (a track that
/// followed no ball) says nothing a student can use, yet its ± is a tenth of 0–10.
fn telling_range(f: Free) -> ((f64, f64), &'static str) {
    match f {
        Free::Mu => (
            (0.0, MAX_PLAUSIBLE_MU),
            "0 ≤ μ_k ≤ 1, the most a ball rolling in a groove may plausibly have",
        ),
        _ => (bounds(f), range_text(f)),
    }
}

/// True when the fitted value `v` of `f` lies on the edge of its physical range: at a
/// bound, or within a millionth of the range of it (a search that runs into a bound
/// stops a rounding short of it: μ_k = 9.999999999997 is μ_k = 10, and its ± from a
/// one-sided difference there means nothing).
pub(super) fn on_edge(f: Free, v: f64) -> bool {
    let (lo, hi) = bounds(f);
    let near = 1e-6 * (hi - lo);
    v <= lo + near || v >= hi - near
}

/// `p` moved into the bounds of each free value.
pub(super) fn clamped(free: &[Free], p: &[f64]) -> Vec<f64> {
    free.iter()
        .zip(p)
        .map(|(f, v)| {
            let (lo, hi) = bounds(*f);
            v.clamp(lo, hi)
        })
        .collect()
}

/// How the residuals' noise is shared, for [`uncertainties`]: `Jᵀ C J` with `C` the
/// correlation of the residuals labelled `labels` (`j` has one row per free value).
/// A velocity derived from a track is a local fit's slope: linear in the tracked
/// coordinates (the centre's x, and for v_t the centre's and the mark's x and y through
/// the angle), so each residual's error is `e_i·n` over the coordinates' noise `n`, and
/// neighbours share frames. Taking every coordinate's noise alike, `C_ij = ê_i·ê_j`
/// (unit vectors), and `Jᵀ C J = Σ_k G_k G_kᵀ` with `G_k = Σ_i ê_ik J_i` over the
/// coordinates k — one pass over the stencils.
pub(super) fn shared_noise(j: &[Vec<f64>], labels: &[Label], st: &Stencils) -> Vec<Vec<f64>> {
    let n = j.len();
    let (centre, mark) = (st.centre_times.len(), st.mark_times.len());
    // The coordinates: the centre's x and y, the mark's x and y, frame by frame.
    let mut g = vec![vec![0.0; n]; 2 * centre + 2 * mark];
    let mut meat = vec![vec![0.0; n]; n];
    let mut e: Vec<(usize, f64)> = Vec::new();
    let mut column = vec![0.0; n];
    for (r, &(i, spin)) in labels.iter().enumerate() {
        // Residual r's column of `j`; a row too short to hold it is no Jacobian of
        // these residuals, and its entry is not a number (the ± then cannot be
        // computed), never a zero that would read as "does not depend on it".
        for (c, row) in column.iter_mut().zip(j) {
            *c = row.get(r).copied().unwrap_or(f64::NAN);
        }
        noise_vector(st, i, spin, &mut e);
        let norm = e.iter().map(|(_, x)| x * x).sum::<f64>().sqrt();
        if e.is_empty() || !(norm > 0.0 && norm.is_finite()) {
            // A point of its own: its noise shared with none.
            add_outer(&mut meat, &column);
            continue;
        }
        for &(k, x) in &e {
            // `noise_vector` numbers the coordinates below `g`'s length.
            let Some(gk) = g.get_mut(k) else { continue };
            for (ga, ja) in gk.iter_mut().zip(&column) {
                *ga += x / norm * ja;
            }
        }
    }
    for row in &g {
        add_outer(&mut meat, row);
    }
    meat
}

/// How the derived velocity `i` (its v_t if `spin`, else its v_cm) moves with the
/// tracked coordinates, into `e` (cleared first) as (coordinate, weight): the centre's
/// x and y, then the mark's x and y, frame by frame (the numbering [`shared_noise`]
/// uses). Empty for a point not made from the track.
pub(super) fn noise_vector(st: &Stencils, i: usize, spin: bool, e: &mut Vec<(usize, f64)>) {
    e.clear();
    let (centre, mark) = (st.centre_times.len(), st.mark_times.len());
    match (spin, if spin { st.v_t.get(i) } else { st.v_cm.get(i) }) {
        (false, Some(Some(s))) => {
            e.extend(
                s.weights(&st.centre_times)
                    .map(|(k, w)| (k, st.centre_sign * w)),
            );
        }
        (true, Some(Some(s))) => {
            for (k, w) in s.weights(&st.mark_times) {
                let Some(&(c, ax, ay)) = st.mark_frames.get(k) else {
                    continue;
                };
                e.extend([
                    (c, w * ax),
                    (centre + c, w * ay),
                    (2 * centre + k, -w * ax),
                    (2 * centre + mark + k, -w * ay),
                ]);
            }
        }
        _ => {}
    }
}

/// `m += v vᵀ` (`m` square, of `v`'s length).
fn add_outer(m: &mut [Vec<f64>], v: &[f64]) {
    for (row, va) in m.iter_mut().zip(v) {
        for (x, vb) in row.iter_mut().zip(v) {
            *x += va * vb;
        }
    }
}

/// Entry (a, b) of a matrix held as rows; not a number outside it, so that a
/// matrix of the wrong size gives "cannot be computed", never a panic.
fn entry(m: &[Vec<f64>], a: usize, b: usize) -> f64 {
    m.get(a)
        .and_then(|row| row.get(b))
        .copied()
        .unwrap_or(f64::NAN)
}

/// The square matrix of `m`'s rows and columns `idx` ([`entry`]).
fn sub_matrix(m: &[Vec<f64>], idx: &[usize]) -> Vec<Vec<f64>> {
    idx.iter()
        .map(|&a| idx.iter().map(|&b| entry(m, a, b)).collect())
        .collect()
}

/// Standard errors from the normal matrix `jtj` (residual variance `s2`) of the free
/// values `p`: a value on its bound, one the data do not depend on, and values along a
/// direction the data cannot see (an eigenvector of the scaled matrix with a
/// negligible eigenvalue) get no ± but a reason; the rest from the inverse of the
/// matrix without them (the others held at their fitted values). With correlated
/// residuals, `shared` is [`shared_noise`]'s `Jᵀ C J` and the covariance is the
/// sandwich `(JᵀJ)⁻¹ JᵀCJ (JᵀJ)⁻¹` (without it, `C` is the identity).
pub(super) fn uncertainties(
    jtj: &[Vec<f64>],
    shared: Option<&[Vec<f64>]>,
    s2: f64,
    free: &[Free],
    p: &[f64],
) -> (Vec<Option<f64>>, Vec<NotIdentified>) {
    let mut out = vec![None; free.len()];
    let (active, mut why) = determinable(jtj, free, p);
    let unseen = unseen_directions(jtj, &active, &mut why);
    // The values kept: (index into `free`, the value).
    let kept: Vec<(usize, Free)> = active
        .iter()
        .zip(&unseen)
        .filter(|(_, unseen)| !**unseen)
        .map(|(&kept, _)| kept)
        .collect();
    let rows: Vec<usize> = kept.iter().map(|&(i, _)| i).collect();
    let sub = sub_matrix(jtj, &rows);
    let cov = inverse(&sub).map(|inv| match shared {
        None => inv,
        Some(c) => product(&product(&inv, &sub_matrix(c, &rows)), &inv),
    });
    // Every value without a ± has its reason: none reads as fitted without one.
    for (x, &(i, f)) in kept.iter().enumerate() {
        let ((lo, hi), range) = telling_range(f);
        match cov.as_ref().map(|cov| (s2 * entry(cov, x, x)).sqrt()) {
            // A ± wider than the whole range the value may have says nothing of it.
            Some(se) if se.is_finite() && 2.0 * se >= hi - lo => why.push(NotIdentified {
                parameter: f.name(),
                reason: format!(
                    "its ± 2σ ({}) spans more than its whole range ({range}), so the data do not determine it",
                    crate::settings::units::significant(2.0 * se, 3),
                ),
                on_edge_of: None,
            }),
            Some(se) if se.is_finite() => {
                if let Some(o) = out.get_mut(i) {
                    *o = Some(se);
                }
            }
            _ => why.push(NotIdentified {
                parameter: f.name(),
                reason: "its uncertainty cannot be computed from these data".into(),
                on_edge_of: None,
            }),
        }
    }
    (out, why)
}

/// The free values the fit can give a ± (each with its index into `free`), and why
/// each other one cannot: on the edge of its physical range, or the fitted points not
/// depending on it.
fn determinable(
    jtj: &[Vec<f64>],
    free: &[Free],
    p: &[f64],
) -> (Vec<(usize, Free)>, Vec<NotIdentified>) {
    let mut why = Vec::new();
    let mut active = Vec::new();
    for (i, (&f, &v)) in free.iter().zip(p).enumerate() {
        let diagonal = entry(jtj, i, i);
        if on_edge(f, v) {
            why.push(NotIdentified {
                parameter: f.name(),
                reason: format!(
                    "the best fit lies on the edge of its physical range ({}), so the data do not determine it (fix it and fit the others)",
                    range_text(f)
                ),
                on_edge_of: Some(range_text(f)),
            });
        } else if !(diagonal > 0.0 && diagonal.is_finite()) {
            why.push(NotIdentified {
                parameter: f.name(),
                reason: "the fitted points do not depend on it".into(),
                on_edge_of: None,
            });
        } else {
            active.push((i, f));
        }
    }
    (active, why)
}

/// Which of the `active` values lie along a direction the data cannot see, each with
/// its reason added to `why`: scaled to unit diagonal, the normal matrix's small
/// eigenvalues are such directions, and a value with a large share in one is not
/// identifiable.
fn unseen_directions(
    jtj: &[Vec<f64>],
    active: &[(usize, Free)],
    why: &mut Vec<NotIdentified>,
) -> Vec<bool> {
    let m = active.len();
    let rows: Vec<usize> = active.iter().map(|&(i, _)| i).collect();
    let sub = sub_matrix(jtj, &rows);
    let d: Vec<f64> = (0..m).map(|a| entry(&sub, a, a).sqrt()).collect();
    let scale = |a: usize| d.get(a).copied().unwrap_or(f64::NAN);
    let scaled = nalgebra::DMatrix::from_fn(m, m, |a, b| entry(&sub, a, b) / (scale(a) * scale(b)));
    let mut unseen = vec![false; m];
    if m > 0 {
        let eig = scaled.symmetric_eigen();
        for (&lambda, v) in eig.eigenvalues.iter().zip(eig.eigenvectors.column_iter()) {
            if lambda > 1e-9 {
                continue;
            }
            // (position in `active`, the value) of each value with a large share.
            let involved: Vec<(usize, Free)> = v
                .iter()
                .zip(active)
                .enumerate()
                .filter(|(_, (x, _))| x.abs() > 0.2)
                .map(|(a, (_, &(_, f)))| (a, f))
                .collect();
            for &(a, f) in &involved {
                match unseen.get_mut(a) {
                    Some(seen) if !*seen => *seen = true,
                    _ => continue,
                }
                let others: Vec<&str> = involved
                    .iter()
                    .filter(|&&(b, _)| b != a)
                    .map(|&(_, g)| g.name())
                    .collect();
                why.push(NotIdentified {
                    parameter: f.name(),
                    reason: if others.is_empty() {
                        "not identifiable from these data".into()
                    } else {
                        format!(
                            "not identifiable from these data: correlated with {}",
                            others.join(", ")
                        )
                    },
                    on_edge_of: None,
                });
            }
        }
    }
    unseen
}

/// How many independent points the residuals `r` (labelled by frame and channel, in
/// frame order) are worth: `n (1 − ρ) / (1 + ρ)` with ρ the correlation of each
/// channel's residuals between neighbouring frames (as for errors that drift from
/// frame to frame, a first-order autoregression: a tracker's error, a velocity file
/// some tool smoothed), taken as 0 when negative. White noise gives about n; the same
/// motion filmed at twice the frame rate with the same drift (in seconds) is worth
/// about as many points as before, not twice as many.
pub(super) fn effective_points(r: &[f64], labels: &[Label]) -> f64 {
    let n = r.len() as f64;
    let var: f64 = r.iter().map(|x| x * x).sum();
    if !(var > 0.0 && var.is_finite()) || labels.len() != r.len() {
        return n;
    }
    // Pairs of the same channel on neighbouring frames (a missing frame breaks one).
    let mut next = 0.0;
    let mut points = labels.iter().zip(r);
    while let Some(((i, c), x)) = points.next() {
        let partner = points
            .clone()
            .take(2)
            .find(|((j, d), _)| *j == i + 1 && d == c);
        if let Some((_, y)) = partner {
            next += x * y;
        }
    }
    let rho = (next / var).clamp(0.0, 0.99);
    n * (1.0 - rho) / (1.0 + rho)
}

/// Solves the small system `a x = b` (LU with partial pivoting, nalgebra).
pub(super) fn solve(a: Vec<Vec<f64>>, b: Vec<f64>) -> Option<Vec<f64>> {
    let n = b.len();
    let m = nalgebra::DMatrix::from_fn(n, n, |i, j| entry(&a, i, j));
    let x = m.lu().solve(&nalgebra::DVector::from_vec(b))?;
    x.iter()
        .all(|v| v.is_finite())
        .then(|| x.iter().copied().collect())
}

fn product(a: &[Vec<f64>], b: &[Vec<f64>]) -> Vec<Vec<f64>> {
    a.iter()
        .map(|row| {
            (0..b.first().map_or(0, Vec::len))
                .map(|j| {
                    row.iter()
                        .zip(b)
                        .map(|(x, r)| x * r.get(j).copied().unwrap_or(f64::NAN))
                        .sum()
                })
                .collect()
        })
        .collect()
}

fn inverse(a: &[Vec<f64>]) -> Option<Vec<Vec<f64>>> {
    let n = a.len();
    let inv = nalgebra::DMatrix::from_fn(n, n, |i, j| entry(a, i, j)).try_inverse()?;
    Some(
        inv.row_iter()
            .map(|row| row.iter().copied().collect())
            .collect(),
    )
}

/// The two parts of μ_k's and v0's standard errors where the lengths' scale has a
/// ± of its own (a video's px per metre from the balls' fitted radius): a scale off
/// by a factor multiplies every length, speed and deceleration by it, and so μ_k
/// (`k|a_cm|/g`) and v0. The fit's `mu_se` and `v0_se` are both parts in quadrature.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
pub struct ScalePart {
    /// The scale's relative standard error.
    pub rel_se: f64,
    /// μ_k's standard error from the fit alone, and from the scale (μ_k · rel_se).
    pub mu_se_fit: f64,
    pub mu_se_scale: f64,
    /// v0's, where v0 was fitted and determined.
    pub v0_se_fit: Option<f64>,
    pub v0_se_scale: Option<f64>,
}

/// Adds the scale's relative standard error `rel` to the standard errors `ses` of
/// μ_k and v0 among `free` (fitted to `p`), in quadrature; the parts, or `None`
/// when the scale has no ± or μ_k is not determined.
pub(super) fn with_scale(
    rel: f64,
    free: &[Free],
    p: &[f64],
    ses: &mut [Option<f64>],
) -> Option<ScalePart> {
    let at = |f: Free| free.iter().position(|x| *x == f);
    let mu = at(Free::Mu)?;
    let mu_se_fit = ses
        .get(mu)
        .copied()
        .flatten()
        .filter(|_| rel > 0.0 && rel.is_finite())?;
    let mu_se_scale = p.get(mu)?.abs() * rel;
    let mu_se = ses.get_mut(mu)?;
    *mu_se = Some(mu_se_fit.hypot(mu_se_scale));
    // v0's index, its fit's standard error and its scale's.
    let v0 = at(Free::V0).and_then(|i| Some((i, (*ses.get(i)?)?, p.get(i)?.abs() * rel)));
    if let Some((i, fit, scale)) = v0
        && let Some(se) = ses.get_mut(i)
    {
        *se = Some(fit.hypot(scale));
    }
    Some(ScalePart {
        rel_se: rel,
        mu_se_fit,
        mu_se_scale,
        v0_se_fit: v0.map(|(_, fit, _)| fit),
        v0_se_scale: v0.map(|(_, _, scale)| scale),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn residuals_that_drift_are_worth_fewer_points() {
        // Two channels interleaved frame by frame (x and the mark's angle), as the
        // position residuals come: white, and drifting with φ = 0.8 from frame to frame.
        let mut noise = crate::study::video::Noise::new(7);
        let frames = 4000;
        let labels: Vec<Label> = (0..frames).flat_map(|i| [(i, false), (i, true)]).collect();
        let white: Vec<f64> = labels.iter().map(|_| noise.gauss()).collect();
        let n = labels.len() as f64;
        // ρ = 0 ± 1/√4000 each channel: within 0.05 of n relative.
        assert!((effective_points(&white, &labels) / n - 1.0).abs() < 0.05);
        let phi = 0.8;
        let mut e = [noise.gauss(), noise.gauss()];
        let drift: Vec<f64> = labels
            .iter()
            .map(|&(_, c)| {
                let c = usize::from(c);
                e[c] = phi * e[c] + (1.0f64 - phi * phi).sqrt() * noise.gauss();
                e[c]
            })
            .collect();
        // n (1 − φ)/(1 + φ) = n / 9, to the sampling error of ρ (±0.01: ±5 %).
        let worth = effective_points(&drift, &labels);
        assert!((worth / (n / 9.0) - 1.0).abs() < 0.1, "{worth} of {n}");
        // A missing frame breaks the pair across it, never pairs frames apart.
        let gap: Vec<Label> = vec![(0, false), (2, false), (3, false)];
        // ρ = 1/3 from frames 2 and 3 alone (with 0 and 2 paired it would be 2/3).
        let worth = effective_points(&[1.0, 1.0, 1.0], &gap);
        assert!((worth - 1.5).abs() < 1e-12, "{worth}");
    }

    #[test]
    fn residuals_made_from_the_same_frames_count_as_one() {
        use crate::study::measured::series::Stencil;
        // The slope over frames lo..=hi at t0 = 1 of three frames: (y2 − y0)/2.
        let slope = |lo, hi| Stencil {
            lo,
            hi,
            t0: lo as f64 + 1.0,
            h: 1.0,
            c: [0.0, 0.5, 0.0],
        };
        let st = |second| Stencils {
            centre_times: (0..6).map(f64::from).collect(),
            centre_sign: -1.0,
            v_cm: vec![Some(slope(0, 2)), Some(second), None],
            ..Stencils::default()
        };
        let labels = [(0, false), (1, false), (2, false)];
        let j = vec![vec![1.0, 1.0, 1.0]];
        // The same frames: the first two errors are one, (1 + 1)² + 1.
        let meat = shared_noise(&j, &labels, &st(slope(0, 2)));
        assert!((meat[0][0] - 5.0).abs() < 1e-12, "{meat:?}");
        // Frames of their own: independent, 1 + 1 + 1.
        let meat = shared_noise(&j, &labels, &st(slope(3, 5)));
        assert!((meat[0][0] - 3.0).abs() < 1e-12, "{meat:?}");
        // The sandwich: (JᵀJ)⁻¹ · 5 · (JᵀJ)⁻¹ = 5/9, not the 1/3 of independent points
        // (times the residuals' variance, 1/16 here: a μ_k ± of 2σ under 1).
        let (se, _) = uncertainties(
            &[vec![3.0]],
            Some(&[vec![5.0]]),
            1.0 / 16.0,
            &[Free::Mu],
            &[0.2],
        );
        assert!((se[0].unwrap() - (5.0f64 / 9.0).sqrt() / 4.0).abs() < 1e-12);
    }

    /// Trial item 9: μ_k = 9.999999999996795 (a search run into the bound 10) printed
    /// as "μ_k 10.0000 ± 0.0000"; within a millionth of its range of a bound a value
    /// is on the edge, whichever value it is (μ_k too), and gets no ±.
    #[test]
    fn a_value_a_rounding_short_of_its_bound_is_on_the_edge() {
        let jtj = vec![vec![16.0, 0.0], vec![0.0, 9.0]];
        let free = [Free::Mu, Free::RollingResistance];
        for p in [
            [9.999999999996795, 0.02],
            [10.0, 0.02],
            [0.0, 0.02],
            [0.22, 1e-9],
        ] {
            let (se, why) = uncertainties(&jtj, None, 1.0, &free, &p);
            let edge = if p[1] < 1e-6 { 1 } else { 0 };
            assert_eq!(se[edge], None, "{p:?}");
            assert!(se[1 - edge].is_some(), "{p:?}");
            assert_eq!(why.len(), 1, "{why:?}");
            assert_eq!(why[0].parameter, free[edge].name());
            assert!(why[0].on_edge_of.is_some(), "{why:?}");
        }
        // Away from the bounds both are fitted values.
        let (se, why) = uncertainties(&jtj, None, 1.0, &free, &[9.99, 0.001]);
        assert!(se.iter().all(Option::is_some) && why.is_empty(), "{why:?}");
    }

    /// μ_k's ± says something only well inside what a ball in a groove may have (0–1),
    /// not the table's 0–10: at ± 2σ of 0.9 it is fitted, at 1.1 not determined,
    /// with that range in its reason; e (range 0–1 too) and c_rr keep theirs.
    #[test]
    fn a_mu_whose_pm_spans_every_plausible_mu_is_not_determined() {
        let free = [Free::Mu, Free::Restitution];
        for (two_sigma, determined) in [(0.9, true), (1.1, false)] {
            // se = 1/sqrt(jtj) for a diagonal matrix, s2 = 1.
            let d = (2.0f64 / two_sigma).powi(2);
            let jtj = vec![vec![d, 0.0], vec![0.0, 100.0]];
            let (se, why) = uncertainties(&jtj, None, 1.0, &free, &[0.09, 0.5]);
            assert_eq!(se[0].is_some(), determined, "{two_sigma}: {why:?}");
            assert!(se[1].is_some(), "{why:?}");
            if !determined {
                assert_eq!(why.len(), 1, "{why:?}");
                assert_eq!(why[0].parameter, "mu");
                assert!(why[0].reason.contains("0 ≤ μ_k ≤ 1"), "{}", why[0].reason);
            }
        }
        // Only the ± is judged, not the value: a μ_k of 5 with a ± 2σ of 0.9 is
        // fitted (the fit calls it implausible apart, `mu_implausible`).
        let jtj = vec![vec![(2.0f64 / 0.9).powi(2), 0.0], vec![0.0, 100.0]];
        let (se, _) = uncertainties(&jtj, None, 1.0, &free, &[5.0, 0.5]);
        assert!(se[0].is_some());
    }

    /// No matrix the fit makes is smaller than its values, but the data path never
    /// panics (issue 35): an entry outside the matrix is not a number, so a value
    /// without one gets a reason, and the others their ± as before.
    #[test]
    fn a_matrix_too_small_for_its_values_gives_reasons_not_a_panic() {
        let free = [Free::Mu, Free::V0];
        let (se, why) = uncertainties(&[vec![16.0]], None, 1.0, &free, &[0.2, 0.5]);
        // μ alone: 1/sqrt(16).
        assert!((se[0].unwrap() - 0.25).abs() < 1e-12, "{se:?}");
        assert_eq!(se[1], None);
        assert_eq!(why.len(), 1, "{why:?}");
        assert_eq!(why[0].parameter, "v0");
        // A Jacobian row shorter than the residuals: the shared noise is not a
        // number, and the ± "cannot be computed", never a zero read as none.
        let st = Stencils {
            centre_times: vec![0.0, 1.0],
            centre_sign: 1.0,
            ..Stencils::default()
        };
        let labels = [(0, false), (1, false)];
        let meat = shared_noise(&[vec![1.0]], &labels, &st);
        assert!(meat[0][0].is_nan(), "{meat:?}");
        let (se, why) = uncertainties(&[vec![4.0]], Some(&meat), 1.0, &[Free::Mu], &[0.2]);
        assert_eq!(se[0], None);
        assert!(why[0].reason.contains("cannot be computed"), "{why:?}");
    }

    #[test]
    fn a_value_on_its_bound_or_along_an_unseen_direction_gets_a_reason_not_a_nan() {
        let free = [Free::Mu, Free::V0, Free::Restitution];
        // μ and v0 enter the data only as μ + v0 (equal columns), e is fine.
        let jtj = vec![
            vec![4.0, 4.0, 1.0],
            vec![4.0, 4.0, 1.0],
            vec![1.0, 1.0, 9.0],
        ];
        let (se, why) = uncertainties(&jtj, None, 1.0, &free, &[0.2, 0.5, 0.8]);
        assert_eq!(se[0], None);
        assert_eq!(se[1], None);
        // e alone: 1/sqrt(9).
        assert!((se[2].unwrap() - 1.0 / 3.0).abs() < 1e-12, "{se:?}");
        assert_eq!(why.len(), 2, "{why:?}");
        assert!(why[0].reason.contains("correlated with v0"), "{why:?}");
        assert!(why[1].reason.contains("correlated with mu"), "{why:?}");
        // e at its upper bound: μ and v0 from the matrix without it.
        let jtj = vec![
            vec![4.0, 0.0, 1.0],
            vec![0.0, 16.0, 1.0],
            vec![1.0, 1.0, 9.0],
        ];
        // (The residuals' variance 1/16: a μ_k ± of 2σ under 1.)
        let (se, why) = uncertainties(&jtj, None, 1.0 / 16.0, &free, &[0.2, 0.5, 1.0]);
        assert!((se[0].unwrap() - 0.125).abs() < 1e-12);
        assert!((se[1].unwrap() - 0.0625).abs() < 1e-12);
        assert_eq!(se[2], None);
        assert_eq!(why[0].parameter, "restitution");
        assert!(
            why[0]
                .reason
                .contains("edge of its physical range (0 ≤ e ≤ 1)"),
            "{why:?}"
        );
    }
}
