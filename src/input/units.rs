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

    /// The unit the app shows and a bare typed number means, with its decimal exponent
    /// to SI (cm: −2); empty for a pure number.
    pub fn display_unit(self) -> (&'static str, i32) {
        match self {
            Dimension::Length => ("cm", -2),
            Dimension::Mass => ("g", -3),
            Dimension::Speed => ("m/s", 0),
            Dimension::Time => ("s", 0),
            Dimension::Acceleration => ("m/s²", 0),
            Dimension::Ratio => ("", 0),
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

/// Parses what a person typed into the app: like [`parse_quantity`], but a bare number
/// is in `dim`'s display unit (the unit the app shows it in: cm, g, m/s, s), a decimal
/// comma counts as a point (`4,4cm`) and the unit's case is ignored (`4.6CM`, `167G`).
/// The command line and preset files keep the strict [`parse_quantity`].
pub fn parse_typed(text: &str, dim: Dimension) -> Result<f64, UnitError> {
    let trimmed = text.trim();
    // One comma and no point: a decimal comma. Anything else keeps its commas (and fails
    // as a number), so "1,000.5" is not silently read as 1.0005.
    let mut normal = if trimmed.matches(',').count() == 1 && !trimmed.contains('.') {
        trimmed.replace(',', ".")
    } else {
        trimmed.to_string()
    };
    // The number is what parse_quantity finds; lower-case only the unit after it, so an
    // exponent's `E` stays as typed.
    let split = (1..=normal.len())
        .rev()
        .filter(|&i| normal.is_char_boundary(i))
        .find(|&i| normal[..i].trim().parse::<f64>().is_ok());
    if let Some(i) = split {
        let unit = normal[i..].trim().to_lowercase();
        if unit.is_empty() {
            let (_, shift) = dim.display_unit();
            let number = normal.trim().to_string();
            let value = parse_quantity(&number, dim)?;
            return Ok(shift_exponent(&number, shift).unwrap_or(value));
        }
        normal = format!("{}{unit}", &normal[..i]);
    }
    parse_quantity(&normal, dim).map_err(|e| match e {
        UnitError::NotANumber { text: _, allowed } => UnitError::NotANumber {
            text: text.to_string(),
            allowed,
        },
        UnitError::UnknownUnit {
            text: _,
            unit,
            allowed,
        } => UnitError::UnknownUnit {
            text: text.to_string(),
            unit,
            allowed,
        },
        other => other,
    })
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

#[cfg(test)]
mod tests {
    use super::*;

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
    fn typed_values_are_in_the_display_unit_and_lenient() {
        let cases = [
            ("4.4", Dimension::Length, 0.044),
            ("4,4cm", Dimension::Length, 0.044),
            ("4,4", Dimension::Length, 0.044),
            ("4.6CM", Dimension::Length, 0.046),
            ("44mm", Dimension::Length, 0.044),
            ("0.044 M", Dimension::Length, 0.044),
            ("167", Dimension::Mass, 0.167),
            ("167G", Dimension::Mass, 0.167),
            ("0.167Kg", Dimension::Mass, 0.167),
            ("0.6", Dimension::Speed, 0.6),
            ("60CM/S", Dimension::Speed, 0.6),
            ("0,17", Dimension::Ratio, 0.17),
            ("1E-2", Dimension::Ratio, 0.01),
            ("200MS", Dimension::Time, 0.2),
        ];
        for (text, dim, want) in cases {
            assert_eq!(parse_typed(text, dim), Ok(want), "{text}");
        }
        // Still refused: junk, thousands separators, a unit of another dimension.
        assert!(parse_typed("1,000.5", Dimension::Length).is_err());
        assert!(parse_typed("4,4,4", Dimension::Length).is_err());
        let e = parse_typed("3KG", Dimension::Length).unwrap_err();
        assert!(e.to_string().contains("'3KG'"), "{e}");
        assert!(parse_typed("", Dimension::Length).is_err());
        // The strict parser is unchanged: a bare number is SI, case matters.
        assert_eq!(parse_quantity("4.4", Dimension::Length), Ok(4.4));
        assert!(parse_quantity("4.6CM", Dimension::Length).is_err());
    }

    #[test]
    fn shows_lab_units() {
        assert_eq!(show(0.0275, Dimension::Length).to_string(), "2.75 cm");
        assert_eq!(show(0.167, Dimension::Mass).to_string(), "167 g");
        assert_eq!(format!("{:.3}", show(0.6, Dimension::Speed)), "0.600 m/s");
    }
}
