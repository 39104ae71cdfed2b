//! Physical quantities at the edges: parsing `2.75cm`, `167g`, `60cm/s` into SI and
//! formatting SI values back for people. Nothing inside the physics uses this module.

use std::fmt;

/// What a value measures; decides which units are accepted and how it is printed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Dimension {
    Length,
    Mass,
    Speed,
    Time,
    Acceleration,
    /// A pure number (μ_k, e, c_rr).
    Ratio,
}

impl Dimension {
    /// Accepted units and their decimal exponent to SI (cm: −2); the first entry is
    /// the SI unit. Shifting the decimal exponent of the text, rather than multiplying,
    /// keeps `4.4cm` the very double that `0.044` is.
    fn units(self) -> &'static [(&'static str, i32)] {
        match self {
            Dimension::Length => &[("m", 0), ("cm", -2), ("mm", -3)],
            Dimension::Mass => &[("kg", 0), ("g", -3)],
            Dimension::Speed => &[("m/s", 0), ("cm/s", -2), ("mm/s", -3)],
            Dimension::Time => &[("s", 0), ("ms", -3)],
            Dimension::Acceleration => &[("m/s^2", 0), ("m/s²", 0), ("m/s2", 0)],
            Dimension::Ratio => &[],
        }
    }

    /// The SI unit symbol, empty for a pure number.
    pub fn si_unit(self) -> &'static str {
        self.units().first().map_or("", |u| u.0)
    }

    fn allowed(self) -> String {
        let names: Vec<&str> = self.units().iter().map(|u| u.0).collect();
        if names.is_empty() {
            "a plain number".to_string()
        } else {
            format!("a number with unit {} (bare number = SI)", names.join(", "))
        }
    }
}

/// Why a quantity could not be read.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum UnitError {
    #[error("'{text}' is not a number, expected {allowed}")]
    NotANumber { text: String, allowed: String },
    #[error("unknown unit '{unit}' in '{text}', expected {allowed}")]
    UnknownUnit {
        text: String,
        unit: String,
        allowed: String,
    },
    #[error("'{text}' is not finite, expected a finite number")]
    NotFinite { text: String },
}

/// Parses `text` as a quantity of `dim` and returns it in SI units.
pub fn parse_quantity(text: &str, dim: Dimension) -> Result<f64, UnitError> {
    let trimmed = text.trim();
    // The number is the longest prefix that parses; a unit may follow, with or without a space.
    let split = trimmed
        .char_indices()
        .map(|(i, _)| i)
        .chain(std::iter::once(trimmed.len()))
        .rev()
        .find(|&i| i > 0 && trimmed[..i].trim().parse::<f64>().is_ok());
    let Some(split) = split else {
        return Err(UnitError::NotANumber {
            text: text.to_string(),
            allowed: dim.allowed(),
        });
    };
    let number: f64 = trimmed[..split].trim().parse().expect("checked above");
    let unit = trimmed[split..].trim();
    if !number.is_finite() {
        return Err(UnitError::NotFinite {
            text: text.to_string(),
        });
    }
    if unit.is_empty() {
        return Ok(number);
    }
    dim.units()
        .iter()
        .find(|(name, _)| *name == unit)
        .map(|&(_, shift)| shift_exponent(trimmed[..split].trim(), shift).unwrap_or(number))
        .ok_or_else(|| UnitError::UnknownUnit {
            text: text.to_string(),
            unit: unit.to_string(),
            allowed: dim.allowed(),
        })
}

/// `text` (a parsed number) times `10^shift`, rounded once from the decimal text.
fn shift_exponent(text: &str, shift: i32) -> Option<f64> {
    let (mantissa, exponent) = match text.find(['e', 'E']) {
        Some(i) => (&text[..i], text[i + 1..].parse::<i32>().ok()?),
        None => (text, 0),
    };
    format!("{mantissa}e{}", exponent + shift).parse().ok()
}

/// An SI value shown in the unit a lab user reads it in (cm for lengths, g for masses…).
#[derive(Clone, Copy, Debug)]
pub struct Shown {
    pub value: f64,
    pub dim: Dimension,
}

/// Formats `value` (SI) for people: lengths in cm, masses in g, times in s, speeds in m/s.
pub fn show(value: f64, dim: Dimension) -> Shown {
    Shown { value, dim }
}

impl fmt::Display for Shown {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let (factor, unit) = match self.dim {
            Dimension::Length => (1e2, " cm"),
            Dimension::Mass => (1e3, " g"),
            Dimension::Speed => (1.0, " m/s"),
            Dimension::Time => (1.0, " s"),
            Dimension::Acceleration => (1.0, " m/s²"),
            Dimension::Ratio => (1.0, ""),
        };
        let v = self.value * factor;
        match f.precision() {
            Some(p) => write!(f, "{v:.p$}{unit}"),
            None => write!(f, "{}{unit}", significant(v, 4)),
        }
    }
}

/// `v` with `digits` significant digits, without trailing zeros or exponent for lab-sized values.
pub fn significant(v: f64, digits: usize) -> String {
    if v == 0.0 || !v.is_finite() {
        return format!("{v}");
    }
    let magnitude = v.abs().log10().floor() as i32;
    if !(-4..=6).contains(&magnitude) {
        return format!("{v:.prec$e}", prec = digits.saturating_sub(1));
    }
    let decimals = (digits as i32 - 1 - magnitude).max(0) as usize;
    let s = format!("{v:.decimals$}");
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s
    }
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
    use super::*;

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
    fn parses_units_of_the_interface() {
        let cases = [
            ("2.75cm", Dimension::Length, 0.0275),
            ("27.5mm", Dimension::Length, 0.0275),
            ("0.0275", Dimension::Length, 0.0275),
            ("167g", Dimension::Mass, 0.167),
            ("0.167kg", Dimension::Mass, 0.167),
            ("60cm/s", Dimension::Speed, 0.6),
            ("0.6m/s", Dimension::Speed, 0.6),
            ("200ms", Dimension::Time, 0.2),
            ("-0.2 s", Dimension::Time, -0.2),
            ("9.81m/s^2", Dimension::Acceleration, 9.81),
            ("1e-2m", Dimension::Length, 0.01),
            ("4.4cm", Dimension::Length, 0.044),
            ("1.5e1mm", Dimension::Length, 0.015),
            ("+3E2g", Dimension::Mass, 0.3),
        ];
        for (text, dim, want) in cases {
            let got = parse_quantity(text, dim).unwrap();
            assert_eq!(got, want, "{text}");
        }
    }

    #[test]
    fn rejects_wrong_units_and_junk() {
        assert!(matches!(
            parse_quantity("5kg", Dimension::Length),
            Err(UnitError::UnknownUnit { .. })
        ));
        assert!(matches!(
            parse_quantity("abc", Dimension::Length),
            Err(UnitError::NotANumber { .. })
        ));
        assert!(matches!(
            parse_quantity("inf", Dimension::Speed),
            Err(UnitError::NotFinite { .. })
        ));
        assert!(matches!(
            parse_quantity("NaN", Dimension::Speed),
            Err(UnitError::NotFinite { .. })
        ));
        assert!(matches!(
            parse_quantity("", Dimension::Speed),
            Err(UnitError::NotANumber { .. })
        ));
        assert!(parse_quantity("0.5cm", Dimension::Ratio).is_err());
    }

    #[test]
    fn shows_lab_units() {
        assert_eq!(show(0.0275, Dimension::Length).to_string(), "2.75 cm");
        assert_eq!(show(0.167, Dimension::Mass).to_string(), "167 g");
        assert_eq!(format!("{:.3}", show(0.6, Dimension::Speed)), "0.600 m/s");
    }
}
