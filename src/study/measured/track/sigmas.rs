//! Each fitted point's own uncertainty from the track's per-frame σ (where the file
//! states them, as `groovelab track` writes them): the centre's x as it is, the rim
//! mark's angle through the distance of the mark from the centre. The position fit
//! weights its residuals by them (`study::fit`).

use super::super::series::Track;
use super::derivative::{Local, median};

/// The σ of each point of the derived series (the frames `rows[i]` whose `dx[i]` is
/// a fit): of the centre's x, m, and with a mark (`spin`) of its angle, rad (the
/// centre's σ standing in for a mark without its own); `None` where the track states
/// no σ for the centre. A frame without a usable σ gets the median of the
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
    let Some(centre) = track.sigma().and_then(|s| usable(s, &points)) else {
        return (None, None);
    };
    let angle = match (&track.mark(), track.mark_sigma(), spin) {
        (Some(_), ms, true) => {
            // Without the mark's own σ, the centre's stands in (both are points of
            // the same picture).
            let mark = ms
                .and_then(|s| usable(s, &points))
                .unwrap_or_else(|| centre.clone());
            let a = points
                .iter()
                .zip(centre.iter().zip(&mark))
                .map(|(&r, (c, m))| {
                    let (dx, dy) = track.at(r).mark_offset();
                    let s = c.hypot(*m) / dx.hypot(dy);
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::study::measured::series::{Stencil, TrackParts};

    #[test]
    fn each_point_gets_its_frames_sigma_filled_and_floored() {
        let local = Some(Local {
            value: 0.0,
            slope: 0.0,
            slope_se: 0.0,
            stencil: Stencil {
                lo: 0,
                hi: 0,
                t0: 0.0,
                h: 1.0,
                c: [0.0; 3],
            },
        });
        // Five frames, the fourth without a centre fit (no point); the mark 3 cm from
        // the centre, straight above it.
        let parts = TrackParts {
            t: vec![0.0, 0.01, 0.02, 0.03, 0.04],
            x: vec![0.0; 5],
            y: vec![0.0; 5],
            mark: Some((vec![0.0; 5], vec![0.03; 5])),
            sigma: Some(vec![1e-4, f64::NAN, 1e-9, 5.0, 3e-4]),
            mark_sigma: Some(vec![1e-4; 5]),
            ..TrackParts::default()
        };
        let track = Track::new(parts.clone()).unwrap();
        let dx = [local, local, local, None, local];
        let (x, angle) = point_sigmas(&track, &[0, 1, 2, 3, 4], &dx, true);
        let (x, angle) = (x.unwrap(), angle.unwrap());
        // Points at frames 0, 1, 2, 4: the usable σ 1e-4, 1e-9, 3e-4 have the median
        // 1e-4; the missing one gets it, the tiny one a tenth of it.
        assert_eq!(x, vec![1e-4, 1e-4, 1e-5, 3e-4]);
        // σ_θ = √(σ_c² + σ_m²)/ρ.
        let want = 1e-4f64.hypot(1e-4) / 0.03;
        assert!((angle[0] - want).abs() <= 1e-12 * want, "{angle:?}");
        // Without a mark's σ the centre's stands in; without the centre's, none.
        let no_mark = Track::new(TrackParts {
            mark_sigma: None,
            ..parts.clone()
        })
        .unwrap();
        let angle = point_sigmas(&no_mark, &[0, 1, 2, 3, 4], &dx, true)
            .1
            .unwrap();
        let want = 1e-5f64.hypot(1e-5) / 0.03;
        assert!((angle[2] - want).abs() <= 1e-12 * want, "{angle:?}");
        let none = Track::new(TrackParts {
            sigma: None,
            ..parts
        })
        .unwrap();
        assert_eq!(
            point_sigmas(&none, &[0, 1, 2, 3, 4], &dx, true),
            (None, None)
        );
    }
}
