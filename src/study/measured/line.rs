//! A straight line through measured points by ordinary least squares, with standard
//! errors: the track's approach and the paper's line fits (`study::fit`) both draw it.

use serde::Serialize;

/// A straight line `y = a + b t` by least squares, with standard errors.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Line {
    pub intercept: f64,
    pub slope: f64,
    pub slope_se: f64,
    pub intercept_se: f64,
}

/// Ordinary least squares of `ys` on `ts` (pairs beyond the shorter are left out).
/// Its standard errors need at least 3 points (NaN with fewer); the line itself 2.
pub fn line(ts: &[f64], ys: &[f64]) -> Line {
    let pairs = || ts.iter().zip(ys);
    let n = pairs().count() as f64;
    let mt = pairs().map(|(t, _)| t).sum::<f64>() / n;
    let my = pairs().map(|(_, y)| y).sum::<f64>() / n;
    let sxx: f64 = pairs().map(|(t, _)| (t - mt).powi(2)).sum();
    let sxy: f64 = pairs().map(|(t, y)| (t - mt) * (y - my)).sum();
    let slope = sxy / sxx;
    let intercept = my - slope * mt;
    let rss: f64 = pairs()
        .map(|(t, y)| (y - intercept - slope * t).powi(2))
        .sum();
    let s2 = if n > 2.0 { rss / (n - 2.0) } else { f64::NAN };
    Line {
        intercept,
        slope,
        slope_se: (s2 / sxx).sqrt(),
        intercept_se: (s2 * (1.0 / n + mt * mt / sxx)).sqrt(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_line_through_exact_points_is_found_with_zero_error_and_two_points_have_no_error() {
        let ts = [0.0, 1.0, 2.0, 3.0];
        let ys: Vec<f64> = ts.iter().map(|t| 0.5 - 2.0 * t).collect();
        let l = line(&ts, &ys);
        assert!((l.slope + 2.0).abs() < 1e-12 && (l.intercept - 0.5).abs() < 1e-12);
        assert!(l.slope_se.abs() < 1e-12, "{l:?}");
        // A longer ys is cut to the times: the same line.
        assert_eq!(line(&ts, &[ys.as_slice(), &[99.0]].concat()), l);
        assert!(line(&ts[..2], &ys[..2]).slope_se.is_nan());
    }
}
