//! Whether the tracks taken for a ball's centre and for the mark on its rim are the
//! other way round: the centre moves along the groove, a straight line in any camera
//! frame, while a rim mark turns around it and strays from that line by up to its
//! distance from the centre. Swapped, the "centre" is a wheel's rim and every velocity
//! derived from it nonsense.

use crate::settings::units::{Dimension, show_small};
use crate::study::measured::Track;

/// How many times as far from a straight line as the mark's the centre's path must
/// stray to be taken for a rim mark's (a true centre's strays by its scatter and a
/// camera's lens distortion; a mark turning a full turn, by its distance from the
/// centre over √2).
const STRAYS_MORE: f64 = 3.0;

/// A track whose centre and mark look swapped: each path's RMS distance from its best
/// straight line (m) and the tracks' names.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error(
    "the track taken for the ball's centre{} strays {} from a straight line and the rim mark's{} only {}: a centre moves along the groove and a mark turns around it, so the two look swapped; {}",
    named(centre),
    straightness(*centre_off),
    named(mark),
    straightness(*mark_off),
    advice(centre, mark)
)]
pub struct Swapped {
    pub centre: String,
    pub mark: String,
    pub centre_off: f64,
    pub mark_off: f64,
}

fn named(name: &str) -> String {
    if name.is_empty() {
        String::new()
    } else {
        format!(" ('{}')", crate::settings::quote::clip(name))
    }
}

/// A path's RMS distance from its straight line (m) as a sentence says it: below a
/// micrometre (far under any video's resolution: rounding noise) as "under 0.001 mm".
fn straightness(off: f64) -> String {
    if off < 1e-6 {
        "under 0.001 mm".to_string()
    } else {
        show_small(off, Dimension::Length).to_string()
    }
}

fn advice(centre: &str, mark: &str) -> String {
    if centre.is_empty() || mark.is_empty() || centre == mark {
        "give the centre's positions as the centre (swap the columns, or the two --data files)"
            .into()
    } else {
        format!("give --track \"centre={mark}\" --track \"mark={centre}\"")
    }
}

/// The RMS distance (m) of the points from their best straight line (total least
/// squares: the root of the smaller eigenvalue of their covariance).
fn off_line(points: &[(f64, f64)]) -> f64 {
    let n = points.len() as f64;
    let (mx, my) = points
        .iter()
        .fold((0.0, 0.0), |(a, b), &(x, y)| (a + x / n, b + y / n));
    let (mut sxx, mut syy, mut sxy) = (0.0, 0.0, 0.0);
    for &(x, y) in points {
        sxx += (x - mx) * (x - mx) / n;
        syy += (y - my) * (y - my) / n;
        sxy += (x - mx) * (y - my) / n;
    }
    // The smaller eigenvalue as the determinant over the larger (no cancellation).
    let larger = 0.5 * (sxx + syy) + (0.25 * (sxx - syy) * (sxx - syy) + sxy * sxy).sqrt();
    if larger <= 0.0 {
        return 0.0;
    }
    ((sxx * syy - sxy * sxy) / larger).max(0.0).sqrt()
}

/// The track's centre and mark when they look swapped: over the frames where both
/// have a position, the centre's path strays from a straight line [`STRAYS_MORE`]
/// times as far as the mark's, and by more than a fifth of their distance apart.
pub fn swapped(track: &Track) -> Result<(), Swapped> {
    if track.mark().is_none() {
        return Ok(());
    }
    // The frames where both have a position (a column shorter than the times has
    // none past its end: `Track::at`).
    let (centre, mark): (Vec<_>, Vec<_>) = (0..track.t().len())
        .map(|i| track.at(i))
        .filter(|f| [f.x, f.y, f.mark_x, f.mark_y].iter().all(|v| v.is_finite()))
        .map(|f| ((f.x, f.y), (f.mark_x, f.mark_y)))
        .unzip();
    if centre.len() < 10 {
        return Ok(());
    }
    let mut apart: Vec<f64> = centre
        .iter()
        .zip(&mark)
        .map(|(c, m)| (c.0 - m.0).hypot(c.1 - m.1))
        .collect();
    apart.sort_by(f64::total_cmp);
    let apart = apart.get(apart.len() / 2).copied().unwrap_or(f64::NAN);
    let (centre_off, mark_off) = (off_line(&centre), off_line(&mark));
    if centre_off > STRAYS_MORE * mark_off && centre_off > 0.2 * apart {
        return Err(Swapped {
            centre: track.centre_name().to_string(),
            mark: track.mark_name().unwrap_or_default().to_string(),
            centre_off,
            mark_off,
        });
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_circle_strays_its_radius_over_root_two_and_a_line_not_at_all() {
        let circle: Vec<(f64, f64)> = (0..400)
            .map(|k| (f64::from(k) * std::f64::consts::TAU / 400.0).sin_cos())
            .map(|(s, c)| (0.5 + 0.02 * c, 0.1 + 0.02 * s))
            .collect();
        assert!((off_line(&circle) - 0.02 / 2f64.sqrt()).abs() < 1e-12);
        let tilted: Vec<(f64, f64)> = (0..50)
            .map(|k| (f64::from(k), 0.3 * f64::from(k)))
            .collect();
        // Points 15 apart along the line: within rounding of it.
        assert!(off_line(&tilted) < 1e-6, "{}", off_line(&tilted));
    }

    #[test]
    fn named_tracks_are_swapped_by_their_names() {
        let e = Swapped {
            centre: "mass B".into(),
            mark: "mass A".into(),
            centre_off: 0.017,
            mark_off: 2e-4,
        };
        assert!(
            e.to_string()
                .ends_with("give --track \"centre=mass A\" --track \"mark=mass B\""),
            "{e}"
        );
    }
}
