//! Axis ticks for the plot: round positions covering a range and labels with the
//! decimals (or scientific notation) their step needs, finite for any input.

/// Round tick positions covering `lo..hi` with at most about `max` ticks, and the
/// bounds widened to the outer ticks.
///
/// Any input gives a finite result: non-finite bounds become 0 … 1, a span too thin
/// for its magnitude is padded, and a range whose round ticks would overflow (near
/// ±1.8e308) or be too many keeps its own bounds as the only ticks.
pub fn nice_ticks(lo: f64, hi: f64, max: usize) -> ((f64, f64), Vec<f64>) {
    let (lo, hi) = if !(lo.is_finite() && hi.is_finite()) {
        (0.0, 1.0)
    } else {
        (lo.min(hi), hi.max(lo))
    };
    // Halves never overflow where the span itself might.
    let half_span = hi / 2.0 - lo / 2.0;
    let mag = lo.abs().max(hi.abs());
    let (lo, hi) = if half_span <= 1e-9 * mag || half_span < 1e-300 {
        // Zero or too thin a span for its magnitude: pad so there is something to draw.
        let pad = if mag < 1e-300 { 1.0 } else { 0.1 * mag };
        (lo - pad, hi + pad)
    } else {
        (lo, hi)
    };
    let fallback = ((lo, hi), vec![lo, hi]);
    let raw = (hi / 2.0 - lo / 2.0) * 2.0 / max.max(1) as f64;
    let mag = 10f64.powf(raw.log10().floor());
    let step = [1.0, 2.0, 2.5, 5.0, 10.0]
        .iter()
        .map(|m| m * mag)
        .find(|s| *s >= raw)
        .unwrap_or(10.0 * mag);
    let first = (lo / step).floor();
    let last = (hi / step).ceil();
    let count = last - first;
    let (a, b) = (first * step, last * step);
    let usable = step > 0.0 && a.is_finite() && b.is_finite() && (0.0..=1000.0).contains(&count);
    if !usable {
        return if lo.is_finite() && hi.is_finite() {
            fallback
        } else {
            ((0.0, 1.0), vec![0.0, 1.0])
        };
    }
    let ticks: Vec<f64> = (0..=(count as usize))
        .map(|i| (first + i as f64) * step)
        .collect();
    ((a, b), ticks)
}

/// A tick label with as many decimals as the step needs.
pub fn tick_label(v: f64, step: f64) -> String {
    label_on_axis(v, step, v.abs())
}

/// A tick label on an axis whose largest tick magnitude is `scale`: huge or tiny
/// values in scientific notation (1e38 s in decimals would be 39 digits), with the
/// mantissa digits the step needs, the same for every tick of the axis.
fn label_on_axis(v: f64, step: f64, scale: f64) -> String {
    if !v.is_finite() {
        return format!("{v}");
    }
    let step = step.abs();
    // A fine step on an axis of ordinary values (a deep time zoom: 0.21590, 0.21595 s)
    // keeps decimals; only a step finer than they write goes scientific.
    let scientific = scale >= 1e6 || (scale != 0.0 && scale < 1e-4) || (step > 0.0 && step < 1e-7);
    if scientific && v == 0.0 {
        return "0".into();
    }
    if scientific {
        let digits = if step > 0.0 && step.is_finite() && scale > 0.0 {
            ((scale / step).log10().ceil().max(0.0) as usize).min(6)
        } else {
            0
        };
        return format!("{v:.digits$e}");
    }
    // Enough decimals to write the step exactly (0.25 needs two).
    let decimals = (0..7)
        .find(|&d| {
            let scaled = step.abs() * 10f64.powi(d);
            (scaled - scaled.round()).abs() < 1e-9 * scaled.max(1.0)
        })
        .unwrap_or(7) as usize;
    let s = format!("{v:.decimals$}");
    if s.starts_with('-') && s[1..].chars().all(|c| c == '0' || c == '.') {
        s[1..].to_string()
    } else {
        s
    }
}

pub(super) fn ticks_with_labels(ticks: &[f64]) -> Vec<(f64, String)> {
    let step = if ticks.len() > 1 {
        ticks[1] - ticks[0]
    } else {
        1.0
    };
    let scale = ticks.iter().fold(0.0, |m: f64, t| m.max(t.abs()));
    ticks
        .iter()
        .map(|&t| (t, label_on_axis(t, step, scale)))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_deep_time_zoom_labels_its_ticks_in_decimals() {
        // Issue 37: ×4096 of a 1 s run labelled its ticks `2.1590e-1`.
        let (lo, hi) = (0.2159, 0.2159 + 1.0 / 4096.0);
        let (_, ticks) = nice_ticks(lo, hi, 5);
        let labels = ticks_with_labels(&ticks);
        for (t, l) in &labels {
            assert!(!l.contains('e'), "{l}");
            let v: f64 = l.parse().unwrap();
            assert!((v - t).abs() < 1e-9, "{l} for {t}");
        }
        let distinct: std::collections::BTreeSet<_> = labels.iter().map(|l| &l.1).collect();
        assert_eq!(distinct.len(), labels.len(), "{labels:?}");
    }

    #[test]
    fn ticks_are_round_and_cover_the_range() {
        let ((lo, hi), ticks) = nice_ticks(-0.2, 0.86, 6);
        assert!(lo <= -0.2 && hi >= 0.86);
        assert_eq!(ticks.first().copied(), Some(lo));
        assert!(ticks.len() <= 8);
        let step = ticks[1] - ticks[0];
        assert!((step - 0.2).abs() < 1e-12, "{step}");
        assert_eq!(tick_label(-0.0, 0.2), "0.0");
        assert_eq!(tick_label(0.4, 0.2), "0.4");
        assert_eq!(tick_label(2.25, 0.25), "2.25");
        assert_eq!(tick_label(10.0, 5.0), "10");
    }

    #[test]
    fn ticks_of_extreme_ranges_are_finite_few_and_short() {
        let cases = [
            (-1e308, 1e308),
            (-f64::MAX, f64::MAX),
            (0.0, 1e38),
            (-0.2, 1e300),
            (1e300, 1e300),
            (1.0, 1.0 + 1e-15),
            (1e-300, 2e-300),
            (0.0, 5e-324),
            (f64::NAN, 1.0),
            (f64::NEG_INFINITY, f64::INFINITY),
            (3.0, -3.0),
        ];
        for (lo, hi) in cases {
            let ((a, b), ticks) = nice_ticks(lo, hi, 6);
            assert!(
                a.is_finite() && b.is_finite() && a < b,
                "{lo} {hi}: {a} {b}"
            );
            assert!(
                !ticks.is_empty() && ticks.len() <= 1001,
                "{lo} {hi}: {}",
                ticks.len()
            );
            for (t, label) in ticks_with_labels(&ticks) {
                assert!(t.is_finite(), "{lo} {hi}");
                assert!(label.len() <= 12, "{lo} {hi}: {label}");
            }
        }
        let ((_, _), t) = nice_ticks(0.0, 1e38, 2);
        let labels: Vec<String> = ticks_with_labels(&t).into_iter().map(|l| l.1).collect();
        assert_eq!(labels, ["0", "5.0e37", "1.0e38"]);
    }

    #[test]
    fn zero_span_is_padded() {
        let ((lo, hi), _) = nice_ticks(0.0, 0.0, 4);
        assert!(lo < 0.0 && hi > 0.0);
    }
}
