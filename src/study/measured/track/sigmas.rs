//! Each fitted point's own uncertainty from the track's per-frame σ (where the file
//! states them, as `groovelab track` writes them): the centre's x as it is, the rim
//! mark's angle through the distance of the mark from the centre. The position fit
//! weights its residuals by them (`study::fit`).

use super::super::series::Track;
use super::derivative::{Local, median};

/// The σ of each point of the derived series (the frames `rows[i]` whose `dx[i]` is
/// a fit): of the centre's x, m, and with a mark (`spin`) of its angle, rad; `None`
/// where the track states no σ. A frame without a usable σ gets the median of the
/// others (a typical point), and none counts for more than a hundred typical ones
/// (σ at least a tenth of the median: a σ of zero would decide the fit alone).
pub(super) fn point_sigmas(
    track: &Track,
    rows: &[usize],
    dx: &[Option<Local>],
    spin: bool,
) -> (Option<Vec<f64>>, Option<Vec<f64>>) {
    let points: Vec<usize> = dx
        .iter()
        .zip(rows)
        .filter(|(l, _)| l.is_some())
        .map(|(_, &r)| r)
        .collect();
    let Some(centre) = track.sigma.as_deref().and_then(|s| usable(s, &points)) else {
        return (None, None);
    };
    let angle = match (&track.mark, track.mark_sigma.as_deref(), spin) {
        (Some((mx, my)), Some(ms), true) => {
            let mark = usable(ms, &points).unwrap_or_else(|| centre.clone());
            let a = points
                .iter()
                .enumerate()
                .map(|(k, &r)| {
                    let rho = (mx[r] - track.x[r]).hypot(my[r] - track.y[r]);
                    let s = centre[k].hypot(mark[k]) / rho;
                    if s.is_finite() { s } else { f64::NAN }
                })
                .collect();
            Some(a)
        }
        _ => None,
    };
    (Some(centre), angle)
}

/// `sigma` at the frames `points`, each missing one set to the median of the others
/// and each at least a tenth of it; `None` when none is usable.
fn usable(sigma: &[f64], points: &[usize]) -> Option<Vec<f64>> {
    let ok = |s: f64| s > 0.0 && s.is_finite();
    let at: Vec<f64> = points
        .iter()
        .map(|&r| sigma.get(r).copied().unwrap_or(f64::NAN))
        .collect();
    let good: Vec<f64> = at.iter().copied().filter(|&s| ok(s)).collect();
    if good.is_empty() {
        return None;
    }
    let mid = median(good);
    Some(
        at.into_iter()
            .map(|s| if ok(s) { s.max(0.1 * mid) } else { mid })
            .collect(),
    )
}
