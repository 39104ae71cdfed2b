//! Showing SI values for people: in the unit a lab reads (cm, g, m/s, s), with every
//! digit for messages, with a ± by one rule, and numbers fitted to a column.

use std::fmt;

use super::dimension::Dimension;

impl Dimension {
    /// `value` (SI) as the parameter panel shows it: the display unit's fixed
    /// decimals (or four significant digits), without the unit.
    pub fn panel_number(self, value: f64) -> String {
        let v = self.to_display(value);
        match self.decimals() {
            Some(d) => format!("{v:.d$}"),
            None => significant(v, 4),
        }
    }
}

/// An SI value shown in the unit a lab user reads it in (cm for lengths, g for masses…).
#[derive(Clone, Copy, Debug)]
pub struct Shown {
    pub value: f64,
    pub dim: Dimension,
    /// In the unit for small values (mm, ms) rather than the display unit.
    pub small: bool,
}

/// Formats `value` (SI) for people: lengths in cm, masses in g, times in s, speeds in m/s.
pub fn show(value: f64, dim: Dimension) -> Shown {
    Shown {
        value,
        dim,
        small: false,
    }
}

/// Formats a small `value` (SI) for people: lengths in mm, times in ms (a position
/// scatter, a fit window); other kinds as [`show`].
pub fn show_small(value: f64, dim: Dimension) -> Shown {
    Shown {
        value,
        dim,
        small: true,
    }
}

impl fmt::Display for Shown {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let (unit, v) = if self.small {
            (self.dim.small_suffix(), self.dim.to_small(self.value))
        } else {
            (self.dim.suffix(), self.dim.to_display(self.value))
        };
        match f.precision() {
            Some(p) => write!(f, "{v:.p$}{unit}"),
            None => write!(f, "{}{unit}", significant(v, 4)),
        }
    }
}

/// `value` (SI) in the unit a lab reads it in, with every digit it has: for error
/// messages, where a rounded value (e = 1.0000001 shown as "1") would contradict the
/// range beside it. The decimal exponent is shifted, not multiplied, so 0.06 m reads
/// "6 cm", never "6.000000000000001 cm".
pub fn show_exact(value: f64, dim: Dimension) -> String {
    let shift = -dim.display_unit().1;
    let unit = dim.suffix();
    if !value.is_finite() {
        return format!("{value}{unit}");
    }
    let sci = format!("{value:e}");
    let shifted = match sci.split_once('e') {
        Some((m, e)) => e
            .parse::<i32>()
            .ok()
            .and_then(|e| format!("{m}e{}", e + shift).parse::<f64>().ok()),
        None => None,
    };
    let Some(v) = shifted.filter(|v| v.is_finite()) else {
        // Too large for the lab's unit: say it in SI.
        return format!("{value:e} {}", dim.si_unit())
            .trim_end()
            .to_string();
    };
    // Lab-sized values in plain decimals, the rest in scientific notation.
    let magnitude = if v == 0.0 {
        0
    } else {
        v.abs().log10().floor() as i32
    };
    if (-5..=9).contains(&magnitude) {
        format!("{v}{unit}")
    } else {
        format!("{v:e}{unit}")
    }
}

/// Below this a ± is said, not printed: what is left of an exact round trip (the
/// program's own noise-free export fitted back) is rounding and the fit's tolerance.
pub const SMALLEST_UNCERTAINTY: f64 = 1e-6;

/// A value and its ± for people, by the one rule every ± follows (the fit command,
/// the Fit view, the figures): both to `decimals` places while the ± shows a digit
/// there; a smaller ± keeps two significant digits and the value as many places
/// (`0.170012 ± 0.000040`, never `0.1700 ± 0.0000`); a ± below
/// [`SMALLEST_UNCERTAINTY`] is `< 1e-6`, the value to six places. A ± that is not a
/// number is written as it is (callers say in words why there is none).
pub fn with_uncertainty(value: f64, se: f64, decimals: usize) -> (String, String) {
    if se < SMALLEST_UNCERTAINTY {
        return (format!("{value:.6}"), "< 1e-6".to_string());
    }
    let half_unit = 0.5 * 10f64.powi(-(decimals.min(15) as i32));
    if !se.is_finite() || se >= half_unit {
        return (format!("{value:.decimals$}"), format!("{se:.decimals$}"));
    }
    // Two significant digits: the place of the first one, and one more.
    let places = (1 - se.log10().floor() as i32).max(decimals as i32) as usize;
    (format!("{value:.places$}"), format!("{se:.places$}"))
}

/// `v` to `decimals` places, without the sign of a value that rounds to zero (an
/// energy of −1e-18 J is `0.00000 J`, never `-0.00000 J`).
pub fn fixed(v: f64, decimals: usize) -> String {
    let s = format!("{v:.decimals$}");
    match s.strip_prefix('-') {
        Some(rest) if rest.chars().all(|c| c == '0' || c == '.') => rest.to_string(),
        _ => s,
    }
}

/// `value` (SI, below `limit`) with the fewest digits from four up that still read
/// below `limit`: a computed b = 4.260281680828159 cm reads 4.26 cm, while
/// b = 5.4999 cm beside 2R = 5.5 cm keeps its digits (5.5 cm would read as 2R).
pub fn show_below(value: f64, limit: f64, dim: Dimension) -> String {
    let limit_shown = dim.to_display(limit);
    (4..=17)
        .map(|digits| significant(dim.to_display(value), digits))
        .find(|text| text.parse::<f64>().is_ok_and(|v| v < limit_shown))
        .map(|text| format!("{text}{}", dim.suffix()))
        .unwrap_or_else(|| show_exact(value, dim).to_string())
}

/// `v` with `digits` significant digits, without trailing zeros or exponent for lab-sized values.
/// For a value someone set (μ_k = 0.17, not 0.1700); a computed quantity shown beside
/// others takes [`sig_figs`].
pub fn significant(v: f64, digits: usize) -> String {
    let s = sig_figs(v, digits);
    if s.contains('.') && !s.contains('e') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s
    }
}

/// `v` with exactly `digits` significant digits, trailing zeros kept (`-2.600`
/// beside `3.672`: the same precision), in exponent form outside 1e-4 … 1e6 (so a
/// tiny force reads `3.607e-9`, never `0.000`). Zero is `0`.
pub fn sig_figs(v: f64, digits: usize) -> String {
    if v == 0.0 || !v.is_finite() {
        return format!("{v}");
    }
    let magnitude = v.abs().log10().floor() as i32;
    if !(-4..=6).contains(&magnitude) {
        return format!("{v:.prec$e}", prec = digits.saturating_sub(1));
    }
    let decimals = (digits as i32 - 1 - magnitude).max(0) as usize;
    let s = format!("{v:.decimals$}");
    // Rounding may carry into a new digit (9.9996 → 10.000): one decimal fewer.
    let shown: f64 = s.parse().unwrap_or(v);
    if shown.abs() >= 10f64.powi(magnitude + 1) && decimals > 0 {
        return format!("{v:.prec$}", prec = decimals - 1);
    }
    s
}

/// `v` in at most `width` characters with as many significant digits as fit, up to
/// `max_digits`: plain decimals for lab-sized values (as [`significant`]), else an
/// exponent form whose exponent is always whole (`2.89e-10`, then `2.9e-10`, `3e-10`).
/// A number is never cut: when not even one digit fits, the answer is `width` `#`s
/// (as a spreadsheet does), never a wrong value. Trailing zeros are dropped.
pub fn fit_digits(v: f64, width: usize, max_digits: usize) -> String {
    if !v.is_finite() || v == 0.0 {
        let s = if v == 0.0 {
            "0".to_string()
        } else {
            format!("{v}")
        };
        return if s.chars().count() <= width {
            s
        } else {
            "#".repeat(width)
        };
    }
    let magnitude = v.abs().log10().floor() as i32;
    let plain = (-4..=6).contains(&magnitude);
    for digits in (1..=max_digits.max(1)).rev() {
        let candidate = if plain {
            let decimals = (digits as i32 - 1 - magnitude).max(0) as usize;
            trim_zeros(format!("{v:.decimals$}"))
        } else {
            exponent_form(v, digits)
        };
        if candidate.chars().count() <= width {
            return candidate;
        }
        // A plain value too wide for its integer digits may still fit as an exponent.
        if plain && (digits as i32) <= magnitude + 1 {
            let e = exponent_form(v, digits);
            if e.chars().count() <= width {
                return e;
            }
        }
    }
    "#".repeat(width)
}

/// [`fit_digits`] with the lab's usual four significant digits at most.
pub fn fit_number(v: f64, width: usize) -> String {
    fit_digits(v, width, 4)
}

/// `v` as `m.mmme-x` with `digits` significant digits, trailing mantissa zeros dropped.
fn exponent_form(v: f64, digits: usize) -> String {
    let s = format!("{v:.prec$e}", prec = digits.saturating_sub(1));
    match s.split_once('e') {
        Some((mantissa, exp)) => format!("{}e{exp}", trim_zeros(mantissa.to_string())),
        None => s,
    }
}

fn trim_zeros(s: String) -> String {
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s
    }
}

#[cfg(test)]
mod tests {
    #[test]
    fn fixed_drops_the_sign_of_a_rounded_zero_only() {
        use super::fixed;
        assert_eq!(fixed(-1e-18, 5), "0.00000");
        assert_eq!(fixed(-0.0, 2), "0.00");
        assert_eq!(fixed(-0.000004, 5), "0.00000");
        assert_eq!(fixed(-0.000006, 5), "-0.00001");
        assert_eq!(fixed(-1.5, 1), "-1.5");
        assert_eq!(fixed(2.0, 0), "2");
        assert_eq!(fixed(f64::NAN, 3), "NaN");
    }

    use super::*;

    #[test]
    fn sig_figs_keeps_the_same_precision_for_every_value() {
        use super::sig_figs;
        assert_eq!(sig_figs(-2.6, 4), "-2.600");
        assert_eq!(sig_figs(3.672, 4), "3.672");
        assert_eq!(sig_figs(0.613, 4), "0.6130");
        assert_eq!(sig_figs(2.16e-8, 4), "2.160e-8");
        assert_eq!(sig_figs(0.00766, 3), "0.00766");
        assert_eq!(sig_figs(9.9996, 4), "10.00");
        assert_eq!(sig_figs(152.0, 3), "152");
        assert_eq!(sig_figs(0.0, 4), "0");
        assert_eq!(super::significant(-2.6, 4), "-2.6");
        assert_eq!(super::significant(2.16e-8, 4), "2.160e-8");
    }

    #[test]
    fn an_uncertainty_is_never_printed_as_zero() {
        let pm = |v, e, d| {
            let (v, e) = with_uncertainty(v, e, d);
            format!("{v} ± {e}")
        };
        // A ± that shows at the column's places keeps them.
        assert_eq!(pm(0.16983, 0.00041, 4), "0.1698 ± 0.0004");
        assert_eq!(pm(3.6512, 0.061, 2), "3.65 ± 0.06");
        assert_eq!(pm(3.6512, 0.005, 2), "3.65 ± 0.01");
        // Smaller: two significant digits, the value as many places.
        assert_eq!(pm(0.1700123, 0.0000403, 4), "0.170012 ± 0.000040");
        assert_eq!(pm(3.6512, 0.00499, 2), "3.6512 ± 0.0050");
        assert_eq!(pm(0.5, 1.2e-6, 4), "0.5000000 ± 0.0000012");
        // Below 1e-6 it is said.
        assert_eq!(pm(0.17, 3e-9, 4), "0.170000 ± < 1e-6");
        assert_eq!(pm(0.17, 0.0, 4), "0.170000 ± < 1e-6");
        assert_eq!(pm(0.17, 3e-9, 9), "0.170000 ± < 1e-6");
        // Wider than the places: as before.
        assert_eq!(pm(12.0, 3.0, 1), "12.0 ± 3.0");
    }

    #[test]
    fn small_values_read_in_mm_and_ms_from_the_one_table() {
        assert_eq!(
            format!("{:.2}", show_small(0.00123, Dimension::Length)),
            "1.23 mm"
        );
        assert_eq!(
            format!("{:.1}", show_small(0.0125, Dimension::Time)),
            "12.5 ms"
        );
        // The same multiplication as by hand: 1e3 · x to the bit.
        for x in [0.00123, 3.7e-4, 0.0281, 1.0 / 3.0] {
            assert_eq!(Dimension::Length.to_small(x), 1e3 * x);
            assert_eq!(Dimension::Time.to_small(x), 1e3 * x);
        }
        // Kinds without a finer unit read as in their display unit.
        assert_eq!(
            Dimension::Speed.small_unit(),
            Dimension::Speed.display_unit()
        );
        assert_eq!(format!("{}", show_small(0.5, Dimension::Speed)), "0.5 m/s");
        assert_eq!(format!("{}", show_small(0.4, Dimension::Ratio)), "0.4");
    }

    #[test]
    fn fitted_numbers_keep_their_exponent_and_lose_digits_first() {
        assert_eq!(fit_number(2.894e-10, 8), "2.89e-10");
        assert_eq!(fit_number(2.894e-10, 9), "2.894e-10");
        assert_eq!(fit_number(2.894e-10, 7), "2.9e-10");
        assert_eq!(fit_number(2.894e-10, 5), "3e-10");
        assert_eq!(fit_number(2.894e-10, 4), "####");
        assert_eq!(fit_number(46.48, 5), "46.48");
        assert_eq!(fit_number(46.48, 4), "46.5");
        assert_eq!(fit_number(46.48, 2), "46");
        assert_eq!(fit_number(-0.1718, 6), "-0.172");
        assert_eq!(fit_number(123456.0, 4), "1e5");
        assert_eq!(fit_number(123456.0, 6), "123456");
        assert_eq!(fit_number(0.0, 3), "0");
        assert_eq!(fit_number(f64::NAN, 3), "NaN");
        assert_eq!(fit_number(f64::NAN, 2), "##");
        // Whatever the width, the printed text is the value to its printed precision.
        for v in [
            3.14159e-7, -0.04648, 1.0, 99.96, 46.48, 0.1407, 7.27e3, -2.5e12,
        ] {
            for width in 1..12 {
                let s = fit_number(v, width);
                assert!(s.chars().count() <= width, "{v} in {width}: {s}");
                if s.starts_with('#') {
                    continue;
                }
                let printed: f64 = s.parse().unwrap();
                let (mantissa, exp) = match s.split_once('e') {
                    Some((m, e)) => (m, e.parse::<i32>().unwrap()),
                    None => (s.as_str(), 0),
                };
                let decimals = mantissa.split_once('.').map_or(0, |(_, d)| d.len()) as i32;
                let half_unit = 0.5 * 10f64.powi(exp - decimals);
                assert!(
                    (printed - v).abs() <= half_unit * (1.0 + 1e-9),
                    "{v} in {width}: {s}"
                );
            }
        }
    }

    #[test]
    fn shows_lab_units() {
        assert_eq!(show(0.0275, Dimension::Length).to_string(), "2.75 cm");
        assert_eq!(show(0.167, Dimension::Mass).to_string(), "167 g");
        assert_eq!(format!("{:.3}", show(0.6, Dimension::Speed)), "0.600 m/s");
    }
}
