//! The paper's line fits over the sliding phase (its table 1): straight lines through
//! the measured v_cm and v_t, the window they cover, and the paper's own numbers.

use serde::Serialize;

use super::problem::FitError;
use super::uncertainty::noise_vector;
use crate::physics::scene::Scene;
pub use crate::study::measured::line::{Line, line};
pub use crate::study::measured::noise::sliding_window;
use crate::study::measured::series::{Measured, NoLineVt};

/// [`line`] through velocities derived from a track, whose neighbours share frames:
/// point i is `e_i·x` over the tracked coordinates `x` (`shared[i]`,
/// [`noise_vector`]), so with each coordinate's noise σ the points' covariance is
/// `σ² E Eᵀ` — correlated, and far from equal: a point beside the impact is a
/// one-sided fit of a few frames, several times noisier than one inside the phase.
///
/// The line stays the ordinary least-squares one (what a student draws through the
/// plotted points, Logger Pro style, and the Fit view shows); only its ± changes. Its
/// slope is `Σ c_i y_i`, so its variance is exactly `σ² |Σ c_i e_i|²`; counting the
/// points as independent and alike gives `s² Σ c_i²`, too small twice over.
///
/// σ is `sigma`, the positions' scatter measured over the whole track (hundreds of
/// third differences). The line's own residuals would say little about it: they hold
/// only a few independent numbers, and they share noise with the slope itself (over
/// synthetic tracks the slope's error over such a ± piled up near ±1σ, and the 1σ held
/// the truth in 55–65 % of tracks instead of 68 %). They are used, with their expected
/// sum of squares `σ² tr((I − H) E Eᵀ)` (H the hat matrix), only when `sigma` is not
/// known. Why not generalised least squares with `E Eᵀ`: a different line from the
/// student's, and `E Eᵀ` is near-singular (velocities from positions know the mean
/// velocity far better than any one point — that is the position fit's business). Why
/// not an effective n from the residuals' lag correlation: it cannot see that the
/// points' variances differ. A point without a stencil counts as a coordinate of its
/// own with the typical point's weight.
fn line_shared(ts: &[f64], ys: &[f64], shared: &[Vec<(usize, f64)>], sigma: f64) -> Line {
    let l = line(ts, ys);
    let n = ts.len() as f64;
    let mt = ts.iter().sum::<f64>() / n;
    let sxx: f64 = ts.iter().map(|t| (t - mt).powi(2)).sum();
    let usable = |e: &[(usize, f64)]| {
        let norm2 = e.iter().map(|(_, x)| x * x).sum::<f64>();
        !e.is_empty() && norm2 > 0.0 && norm2.is_finite()
    };
    // The typical point's |e|² (RMS over those with a stencil), for those without.
    let with: Vec<f64> = shared
        .iter()
        .filter(|e| usable(e))
        .map(|e| e.iter().map(|(_, x)| x * x).sum::<f64>())
        .collect();
    let typical = if with.is_empty() {
        1.0
    } else {
        with.iter().sum::<f64>() / with.len() as f64
    };
    // Per coordinate: Σ e, Σ u e (u = t − mean t), then the slope's and the
    // intercept's weights times e; and tr(E Eᵀ) = Σ |e_i|². (In the coordinates'
    // order: a hash map's order changed the sums' last bits from run to run.)
    let mut sums: std::collections::BTreeMap<usize, [f64; 4]> = std::collections::BTreeMap::new();
    let mut own = [0.0; 4];
    let mut trace = 0.0;
    for (i, &t) in ts.iter().enumerate() {
        let u = t - mt;
        let (c, d) = (u / sxx, 1.0 / n - mt * u / sxx);
        let e = shared.get(i).map_or(&[][..], Vec::as_slice);
        if !usable(e) {
            // A point of its own: a coordinate of its own, of the typical weight.
            for (a, v) in own.iter_mut().zip([1.0, u, c, d]) {
                *a += v * v * typical;
            }
            trace += typical;
            continue;
        }
        for &(k, x) in e {
            trace += x * x;
            let acc = sums.entry(k).or_default();
            for (a, v) in acc.iter_mut().zip([1.0, u, c, d]) {
                *a += v * x;
            }
        }
    }
    let squares = sums.values().fold(own, |mut acc, s| {
        for (a, v) in acc.iter_mut().zip(s) {
            *a += v * v;
        }
        acc
    });
    // tr(H E Eᵀ) with H = 1 1ᵀ/n + u uᵀ/Sxx.
    let tr_he = squares[0] / n + squares[1] / sxx;
    let rss: f64 = ts
        .iter()
        .zip(ys)
        .map(|(t, y)| (y - l.intercept - l.slope * t).powi(2))
        .sum();
    let s2 = if sigma > 0.0 && sigma.is_finite() {
        sigma * sigma
    } else {
        rss / (trace - tr_he).max(f64::MIN_POSITIVE)
    };
    let [_, _, slope_sq, intercept_sq] = squares;
    Line {
        slope_se: (s2 * slope_sq).sqrt(),
        intercept_se: (s2 * intercept_sq).sqrt(),
        ..l
    }
}

/// [`line`] of `ys` on the times of the points `idx` of `m`: [`line_shared`] for
/// velocities derived from a track (the v_t if `spin`, else the v_cm). A v_t's
/// stencil makes the spin rate dθ/dt; times the contact radius `r` it makes v_t.
// `idx` holds points of `m` (from `0..m.len()`, as `line_fit` makes them), whose
// columns all have one value per time (the rules of `Measured`).
#[allow(clippy::indexing_slicing)]
fn line_of(m: &Measured, idx: &[usize], ys: &[f64], spin: bool, r: f64) -> Line {
    let ts: Vec<f64> = idx.iter().map(|&i| m.t()[i]).collect();
    match &m.stencils() {
        Some(st) => {
            let shared: Vec<Vec<(usize, f64)>> = idx
                .iter()
                .map(|&i| {
                    let mut e = Vec::new();
                    noise_vector(st, i, spin, &mut e);
                    if spin {
                        e.iter_mut().for_each(|(_, w)| *w *= r);
                    }
                    e
                })
                .collect();
            line_shared(&ts, ys, &shared, st.scatter)
        }
        None => line(&ts, ys),
    }
}

/// The paper's table-1 quantities from line fits over the sliding phase (magnitudes).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct LineFit {
    /// Window used, s.
    pub from: f64,
    pub to: f64,
    pub points: usize,
    pub a_cm: f64,
    pub a_cm_se: f64,
    pub a_t: f64,
    pub a_t_se: f64,
    /// μ_k,cm = k |a_cm| / g.
    pub mu_cm: f64,
    pub mu_cm_se: f64,
    /// μ_k,t = 2 |a_t| / (5 k g).
    pub mu_t: f64,
    pub mu_t_se: f64,
    /// |F_net| = μ_k,cm m g / k, N.
    pub f_net: f64,
    /// |τ_net| = μ_k,cm m g R, N m.
    pub tau_net: f64,
    /// The fitted lines themselves, v_cm then v_t (slopes and intercepts), for drawing.
    #[serde(skip)]
    pub lines: [Line; 2],
    /// Whether `from` and `to` were asked for (else the sliding phase's ends): what
    /// the window is called.
    #[serde(skip)]
    pub given: [bool; 2],
    /// The window asked for, s, before it was cut to the data's times.
    #[serde(skip)]
    pub asked: (f64, f64),
    /// The times the data run over, s (first impact at 0).
    #[serde(skip)]
    pub data_span: (f64, f64),
    /// Present only when the groove width that the measured |a_t|/|a_cm| gives
    /// ([`width_from_lines`]) disagrees with the scene's: a wrong `--width`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub width_from_lines: Option<WidthFromLines>,
    /// Why there is no v_t line, where the window holds fewer than 3 frames with a
    /// v_t (decided once here, said by `fit` and the Fit view).
    #[serde(skip)]
    pub no_v_t: Option<NoLineVt>,
}

/// The groove width b that the line fits' D = |a_t|/|a_cm| = 5/2 (1 − b²/4R²) gives
/// (docs/physics.md §3), b = 2R √(1 − 2D/5), beside the scene's, m.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct WidthFromLines {
    pub width: f64,
    pub width_se: f64,
    /// The scene's b, m.
    pub given: f64,
}

/// [`WidthFromLines`] where it disagrees with the scene's b by more than twice its ±
/// and by over [`WIDTH_APART`] of b; `None` where it agrees or the line fits cannot
/// tell (no v_t, or a k outside the model's 0 … 1).
///
/// A measured v_t (a velocity file) gives k² = 2D/5 from D = |a_t|/|a_cm|. A v_t
/// derived from a rim mark's angle is r θ' with the scene's r = k_scene R, so its D
/// is (5/2) k_scene k, the scene's own k in it (the width it gave echoed the one
/// given: halfway to the truth). The angle itself is free of it: its α = (5/2) μ g/R
/// beside a_cm = μ g/k gives k = (2/5) R α/|a_cm| = (2/5) D/k_scene (`spin_from_angle`).
pub fn width_from_lines(
    (a_cm, a_cm_se): (f64, f64),
    (a_t, a_t_se): (f64, f64),
    scene: &Scene,
    spin_from_angle: bool,
) -> Option<WidthFromLines> {
    let d = a_t / a_cm;
    let d_rel = (a_t_se / a_t).hypot(a_cm_se / a_cm);
    let (k2, k2_rel) = if spin_from_angle {
        let k = 2.0 * d / (5.0 * scene.k());
        (k * k, 2.0 * d_rel)
    } else {
        (2.0 * d / 5.0, d_rel)
    };
    let rest = 1.0 - k2;
    if !(k2.is_finite() && k2 > 0.0 && rest > 0.0) {
        return None;
    }
    let width = 2.0 * scene.radius * rest.sqrt();
    // db/d(k²) = −R/√(1 − k²).
    let width_se = scene.radius * k2 * k2_rel / rest.sqrt();
    let apart = (width - scene.width).abs();
    (width_se.is_finite() && apart > 2.0 * width_se && apart > WIDTH_APART * scene.width).then_some(
        WidthFromLines {
            width,
            width_se,
            given: scene.width,
        },
    )
}

/// How far (a fraction of b) the width the line fits give must be from the scene's
/// to be said: b hardly moves D near b = 2R, where the paper's own series, whose
/// μ_k,cm and μ_k,t are up to 19 % apart, put it within 3 % of their b.
const WIDTH_APART: f64 = 0.05;

impl LineFit {
    /// True where |a_t| was measured but lies within two of its standard errors of 0:
    /// the v_t line's slope is not told from none (a rim mark followed in a few
    /// short runs of the window), so μ_k,t, which is that slope scaled, says nothing
    /// (a new user read μ_k,t = 4.08 beside |a_t| = 45 ± 40 m/s² as measured).
    pub fn a_t_undetermined(&self) -> bool {
        self.a_t.is_finite() && (self.a_t_se.is_nan() || self.a_t < 2.0 * self.a_t_se)
    }

    /// Why a_t and μ_k,t are not measured, where they are not: [`LineFit::no_v_t`],
    /// else (a v_t line that gave no number from 3 frames or more) too few frames
    /// of the window.
    pub fn why_no_v_t(&self) -> NoLineVt {
        self.no_v_t.unwrap_or(NoLineVt::FewInWindow)
    }

    /// The ends of the window asked for (`--from`, `--to`) that lay outside the data
    /// and were cut to them: (which, asked, the data's end there), s.
    pub fn cut_to_data(&self) -> Vec<(&'static str, f64, f64)> {
        let mut out = Vec::new();
        if self.given[0] && self.asked.0 < self.data_span.0 {
            out.push(("from", self.asked.0, self.data_span.0));
        }
        if self.given[1] && self.asked.1 > self.data_span.1 {
            out.push(("to", self.asked.1, self.data_span.1));
        }
        out
    }
}

/// How far apart μ_k,cm and μ_k,t may lie, relative to their mean, beyond their ±,
/// in data whose scene fits: the paper's own three series put them up to 19 % apart
/// (b = 4.9 cm: 0.149 and 0.180, each ± 0.004), the line fits' ± leaving out the
/// correlated errors of neighbouring frames. A wrong k = r/R (b or R) scales their
/// ratio by (k_wrong/k)²: 2.3 at b = 4 cm for 4.9 cm.
pub const LINES_APART: f64 = 0.25;

impl LineFit {
    /// μ_k,cm and μ_k,t when they disagree: by more than twice their combined ± and
    /// more than [`LINES_APART`] of their mean. `None` without a measured v_t.
    pub fn disagree(&self) -> Option<(f64, f64)> {
        let (a, b) = (self.mu_cm, self.mu_t);
        let apart = (a - b).abs();
        let se = self.mu_cm_se.hypot(self.mu_t_se);
        (apart.is_finite() && apart > 2.0 * se && apart > LINES_APART * 0.5 * (a + b).abs())
            .then_some((a, b))
    }
}

/// Line fits of v_cm and v_t over `[from, to]` (default: the sliding phase).
// Its points `idx` come from `0..m.len()`, and every column of `m` has one value per
// time (the rules of `Measured`).
#[allow(clippy::indexing_slicing)]
pub fn line_fit(
    m: &Measured,
    scene: &Scene,
    window: (Option<f64>, Option<f64>),
) -> Result<LineFit, FitError> {
    let auto = sliding_window(m);
    // Without v_t the window still starts at the first frame after the impact.
    let first_after = m.t().iter().copied().find(|&t| t > 0.0);
    let from = window
        .0
        .or(auto.map(|w| w.0))
        .or(first_after)
        .ok_or(FitError::NothingAfterImpact)?;
    let to = window.1.or(auto.map(|w| w.1)).unwrap_or(from);
    // A window reaching past the data's ends fits what the data hold: report that span
    // (a fitted model may roll again only after the track ends; `--to 5` on a 1 s track).
    let span = m
        .t()
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &t| {
            (lo.min(t), hi.max(t))
        });
    let asked = (from, to);
    let (from, to) = (from.max(span.0), to.min(span.1));
    let idx: Vec<usize> = (0..m.t().len())
        .filter(|&i| m.t()[i] >= from - 1e-12 && m.t()[i] <= to + 1e-12)
        .collect();
    if idx.len() < 3 {
        return Err(FitError::ShortWindow {
            asked,
            points: idx.len(),
            data: span,
        });
    }
    let cm = line_of(
        m,
        &idx,
        &idx.iter().map(|&i| m.v_cm()[i]).collect::<Vec<_>>(),
        false,
        scene.k() * scene.radius,
    );
    // v_t where it was measured (all of a velocity file; none of a track without mark).
    let with_t: Vec<usize> = idx
        .iter()
        .copied()
        .filter(|&i| m.v_t()[i].is_finite())
        .collect();
    let vt = if with_t.len() >= 3 {
        line_of(
            m,
            &with_t,
            &with_t.iter().map(|&i| m.v_t()[i]).collect::<Vec<_>>(),
            true,
            scene.k() * scene.radius,
        )
    } else {
        Line {
            intercept: f64::NAN,
            slope: f64::NAN,
            slope_se: f64::NAN,
            intercept_se: f64::NAN,
        }
    };
    let k = scene.k();
    let g = scene.g;
    let mass = scene.left.mass;
    let mu_cm = k * cm.slope.abs() / g;
    Ok(LineFit {
        from,
        to,
        points: idx.len(),
        a_cm: cm.slope.abs(),
        a_cm_se: cm.slope_se,
        a_t: vt.slope.abs(),
        a_t_se: vt.slope_se,
        mu_cm,
        mu_cm_se: k * cm.slope_se / g,
        mu_t: 2.0 * vt.slope.abs() / (5.0 * k * g),
        mu_t_se: 2.0 * vt.slope_se / (5.0 * k * g),
        f_net: mu_cm * mass * g / k,
        tau_net: mu_cm * mass * g * scene.radius,
        lines: [cm, vt],
        given: [window.0.is_some(), window.1.is_some()],
        asked,
        data_span: span,
        width_from_lines: width_from_lines(
            (cm.slope.abs(), cm.slope_se),
            (vt.slope.abs(), vt.slope_se),
            scene,
            m.angle().is_some(),
        ),
        no_v_t: (with_t.len() < 3).then(|| m.why_no_line_v_t()),
    })
}

/// The paper's table 1 (b in m; |a_cm|, μ_k,cm, |F_net|, |a_t|, μ_k,t, |τ_net|).
pub const PAPER_TABLE: [(f64, [f64; 6]); 3] = [
    (0.035, [2.15, 0.17, 0.36, 2.92, 0.15, 0.008]),
    (0.044, [2.86, 0.18, 0.48, 2.61, 0.17, 0.009]),
    (0.049, [3.26, 0.17, 0.54, 2.00, 0.16, 0.008]),
];

/// A μ value of the paper's table 1 that the accelerations in its own row do not give,
/// even allowing for rounding (physics.md, "Where the paper disagrees with itself").
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PaperDisagreement {
    /// `"cm"` for μ_k,cm, `"t"` for μ_k,t.
    pub which: &'static str,
    pub printed: f64,
    /// From the row's own acceleration: `k |a_cm| / g` or `2 |a_t| / (5 k g)`.
    pub own: f64,
}

/// The μ values of the paper's row for groove width `b` that contradict the row's own
/// accelerations (ball radius `radius`, gravity `g`): each printed number stands for
/// ± half a unit of its last digit (0.005 for both), and a contradiction is where the
/// two ranges do not meet. Empty where they agree or `b` is not one of the paper's.
pub fn paper_disagreements(b: f64, radius: f64, g: f64) -> Vec<PaperDisagreement> {
    let Some(row) = paper_row(b) else {
        return Vec::new();
    };
    let k = (1.0 - (b / (2.0 * radius)).powi(2)).sqrt();
    let half = 0.005;
    [
        ("cm", row[1], row[0], k / g),
        ("t", row[4], row[3], 2.0 / (5.0 * k * g)),
    ]
    .into_iter()
    .filter(|&(_, mu, a, factor)| {
        let (lo, hi) = ((a - half) * factor, (a + half) * factor);
        hi < mu - half || lo > mu + half
    })
    .map(|(which, printed, a, factor)| PaperDisagreement {
        which,
        printed,
        own: a * factor,
    })
    .collect()
}

/// The paper's row for groove width `b`, if it is one of its three.
pub fn paper_row(b: f64) -> Option<[f64; 6]> {
    PAPER_TABLE
        .iter()
        .find(|(w, _)| (w - b).abs() < 1e-9)
        .map(|(_, row)| *row)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_line_through_shared_frames_has_the_larger_uncertainty() {
        let ts = [0.0, 1.0, 2.0, 3.0, 4.0, 5.0];
        let ys = [0.1, 0.9, 2.2, 2.8, 4.1, 5.0];
        let plain = line(&ts, &ys);
        // Each point its own coordinate: the ordinary standard errors.
        let own: Vec<Vec<(usize, f64)>> = (0..6).map(|i| vec![(i, 1.0)]).collect();
        let l = line_shared(&ts, &ys, &own, 0.0);
        assert!((l.slope_se - plain.slope_se).abs() < 1e-12 * plain.slope_se);
        assert!((l.intercept_se - plain.intercept_se).abs() < 1e-12 * plain.intercept_se);
        // Neighbours made from the same two frames: their errors are shared, the
        // residuals understate them, and the slope is less sure.
        let shared: Vec<Vec<(usize, f64)>> = (0..6).map(|i| vec![(i, 1.0), (i + 1, 1.0)]).collect();
        let l = line_shared(&ts, &ys, &shared, 0.0);
        assert!(
            l.slope_se > 1.2 * plain.slope_se,
            "{} vs {}",
            l.slope_se,
            plain.slope_se
        );
        assert_eq!(l.slope, plain.slope);
    }

    #[test]
    fn a_known_position_scatter_gives_the_slopes_error_exactly() {
        // Points of their own with weight w and coordinate noise σ: each point's error
        // is w σ, so the slope's standard error is w σ / √Sxx (Sxx = 17.5 here) — the
        // residuals do not enter.
        let ts = [0.0, 1.0, 2.0, 3.0, 4.0, 5.0];
        let ys = [0.1, 0.9, 2.2, 2.8, 4.1, 5.0];
        let own: Vec<Vec<(usize, f64)>> = (0..6).map(|i| vec![(i, 3.0)]).collect();
        let l = line_shared(&ts, &ys, &own, 0.01);
        let want = 3.0 * 0.01 / 17.5f64.sqrt();
        assert!((l.slope_se - want).abs() < 1e-12 * want, "{}", l.slope_se);
        // Two points from the same frames: one coordinate, its noise counted once.
        let pair = vec![vec![(0, 1.0)], vec![(0, 1.0)], vec![(1, 1.0)]];
        let l = line_shared(&[0.0, 1.0, 2.0], &[0.0, 1.0, 2.0], &pair, 1.0);
        // Slope weights c = (−1, 0, 1)/2: (c₀ + c₁) on frame 0, c₂ on frame 1.
        let want = (0.25f64 + 0.25).sqrt();
        assert!((l.slope_se - want).abs() < 1e-12, "{}", l.slope_se);
    }
}
