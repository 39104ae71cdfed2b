//! Reading quantities: `2.75cm`, `167g`, `60cm/s` into SI, strictly (command line,
//! presets) or as typed into the app, and why a text is refused.

use std::fmt;

use super::dimension::Dimension;
use crate::settings::quote::clip;

/// Why a quantity could not be read.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum UnitError {
    #[error("'{}' is not a number, expected {allowed}", clip(text))]
    NotANumber { text: String, allowed: Expected },
    #[error(
        "unknown unit '{}' in '{}', expected {allowed}",
        clip(unit),
        clip(text)
    )]
    UnknownUnit {
        text: String,
        unit: String,
        allowed: Expected,
    },
    #[error("'{}' is not finite, expected a finite number", clip(text))]
    NotFinite { text: String },
    /// The text is a number, but its value (after the unit) overflows or rounds to 0.
    #[error(
        "'{}' is out of range ({why}), expected 0 or a magnitude from about 2.2e-308 to 1.8e308 in SI units",
        clip(text)
    )]
    OutOfRange { text: String, why: &'static str },
}

impl UnitError {
    /// The same error naming `text` as the text given.
    pub fn with_text(self, text: String) -> UnitError {
        match self {
            UnitError::NotANumber { allowed, .. } => UnitError::NotANumber { text, allowed },
            UnitError::UnknownUnit { unit, allowed, .. } => UnitError::UnknownUnit {
                text,
                unit,
                allowed,
            },
            UnitError::NotFinite { .. } => UnitError::NotFinite { text },
            UnitError::OutOfRange { why, .. } => UnitError::OutOfRange { text, why },
        }
    }
}

/// What a quantity's text may be, as an error says it after "expected".
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Expected {
    /// A number with a unit of the dimension, a bare number in SI (the command line,
    /// presets).
    Si(Dimension),
    /// What the app's typing field takes: a bare number is in the display unit.
    Typed(Dimension),
    /// One of the dimension's unit names, alone.
    UnitName(Dimension),
    /// A unit a data file names: the dimension's unit names (microseconds as `us`
    /// among them).
    FileUnit(Dimension),
}

impl fmt::Display for Expected {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let names = |dim: Dimension| {
            dim.units()
                .iter()
                .map(|u| u.0)
                .collect::<Vec<_>>()
                .join(", ")
        };
        match *self {
            Expected::Si(dim) if dim.units().is_empty() => write!(f, "a plain number"),
            Expected::Si(dim) => write!(f, "a number with unit {} (bare number = SI)", names(dim)),
            Expected::Typed(dim) => match dim.display_unit().0 {
                "" => write!(f, "a plain number"),
                unit => write!(
                    f,
                    "a number in {unit} (a bare number is in {unit}) or with a unit {}",
                    names(dim)
                ),
            },
            Expected::UnitName(dim) if dim.units().is_empty() => {
                write!(f, "no unit (a plain number)")
            }
            Expected::UnitName(dim) | Expected::FileUnit(dim) => {
                write!(f, "one of {}", names(dim))
            }
        }
    }
}

/// Smallest non-zero magnitude a quantity may have (SI): the smallest normal double,
/// so that no written non-zero value silently becomes 0 or loses its precision.
pub const MIN_MAGNITUDE: f64 = f64::MIN_POSITIVE;

/// SI value of one `unit` of `dim` (`ms` → 0.001): a unit name from the table, never
/// a number, so `e5`, `0` or `7` are refused rather than read as `1e5`, `10`, `17`.
pub fn unit_factor(unit: &str, dim: Dimension) -> Result<f64, UnitError> {
    let unit = unit.trim();
    dim.units()
        .iter()
        .find(|(name, _)| *name == unit)
        .map(|&(_, shift)| shift_exponent("1", shift))
        .ok_or_else(|| UnitError::UnknownUnit {
            text: unit.to_string(),
            unit: unit.to_string(),
            allowed: Expected::UnitName(dim),
        })
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
            allowed: Expected::Si(dim),
        });
    };
    let digits = trimmed[..split].trim();
    let number: f64 = digits.parse().expect("checked above");
    let unit = trimmed[split..].trim();
    // "inf", "NaN" and "1e999" (which parses to inf).
    if !number.is_finite() {
        return Err(UnitError::NotFinite {
            text: text.to_string(),
        });
    }
    let shift = if unit.is_empty() {
        0
    } else {
        dim.units()
            .iter()
            .find(|(name, _)| *name == unit)
            .map(|&(_, shift)| shift)
            .ok_or_else(|| UnitError::UnknownUnit {
                text: text.to_string(),
                unit: unit.to_string(),
                allowed: Expected::Si(dim),
            })?
    };
    let value = shift_exponent(digits, shift);
    let out_of_range = |why| UnitError::OutOfRange {
        text: text.to_string(),
        why,
    };
    if !value.is_finite() {
        return Err(out_of_range("too large"));
    }
    // A written non-zero number ("1e-400", "1e-2147483648cm") must not quietly
    // become 0 or a denormal that has lost its digits.
    let nonzero = mantissa(digits).bytes().any(|b| (b'1'..=b'9').contains(&b));
    if nonzero && value.abs() < MIN_MAGNITUDE {
        return Err(out_of_range("too small, it rounds to 0"));
    }
    Ok(value)
}

/// [`parse_quantity`] for a value given on the command line: one decimal comma and no
/// point counts as a decimal point (`--width 4,9cm`, as the app accepts it); an error
/// names the text as given.
pub fn parse_option(text: &str, dim: Dimension) -> Result<f64, UnitError> {
    let t = text.trim();
    if t.matches(',').count() != 1 || t.contains('.') {
        return parse_quantity(text, dim);
    }
    parse_quantity(&t.replace(',', "."), dim).map_err(|e| e.with_text(text.to_string()))
}

/// The part of a number's text before its exponent.
fn mantissa(text: &str) -> &str {
    text.find(['e', 'E']).map_or(text, |i| &text[..i])
}

/// `text` (a number that parses) times `10^shift`, rounded once from the decimal
/// text. The exponent is added in 128 bits, so no exponent the user writes can
/// overflow; one too long even for that is beyond every double (0 or inf).
fn shift_exponent(text: &str, shift: i32) -> f64 {
    let m = mantissa(text);
    let exponent: i128 = match text.get(m.len() + 1..) {
        None => 0,
        Some(e) => e.parse().unwrap_or_else(|_| {
            if e.starts_with('-') {
                -(1 << 100)
            } else {
                1 << 100
            }
        }),
    };
    format!("{m}e{}", exponent.saturating_add(i128::from(shift)))
        .parse()
        .unwrap_or(f64::NAN)
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
            // A bare number is in the display unit: read it as if that unit were
            // written, so the strict parser's range checks apply to it too.
            let (name, shift) = dim.display_unit();
            let number = normal.trim();
            return if shift == 0 {
                parse_quantity(number, dim)
            } else {
                parse_quantity(&format!("{number}{name}"), dim)
            }
            .map_err(|e| about_typed(e, text, dim));
        }
        normal = format!("{}{unit}", &normal[..i]);
    }
    parse_quantity(&normal, dim).map_err(|e| about_typed(e, text, dim))
}

/// `e` about `typed`, the text as the user typed it, not the text it was read as (a
/// bare number gets its display unit glued on: "nan" was read as "nancm"), with what
/// may be typed.
fn about_typed(e: UnitError, typed: &str, dim: Dimension) -> UnitError {
    let text = typed.trim().to_string();
    match e {
        UnitError::NotANumber { .. } => UnitError::NotANumber {
            text,
            allowed: Expected::Typed(dim),
        },
        UnitError::UnknownUnit { unit, .. } => UnitError::UnknownUnit {
            text,
            unit,
            allowed: Expected::Typed(dim),
        },
        UnitError::NotFinite { .. } => UnitError::NotFinite { text },
        UnitError::OutOfRange { why, .. } => UnitError::OutOfRange { text, why },
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_option_takes_a_decimal_comma() {
        assert_eq!(parse_option("4,9cm", Dimension::Length), Ok(0.049));
        assert_eq!(parse_option("4.9cm", Dimension::Length), Ok(0.049));
        // The error names the text as given; thousands stay refused.
        let e = parse_option("4,9kg", Dimension::Length)
            .unwrap_err()
            .to_string();
        assert!(e.contains("'4,9kg'"), "{e}");
        assert!(parse_option("1,000.5cm", Dimension::Length).is_err());
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
            // The unit range messages print (1 mg ≤ m) is accepted too.
            ("1mg", Dimension::Mass, 1e-6),
            ("250 mg", Dimension::Mass, 0.00025),
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
    fn typing_errors_quote_what_was_typed() {
        // A bare number is read with the display unit glued on; the error must not
        // show "nancm".
        for typed in ["nan", "1e999", " inf "] {
            let e = parse_typed(typed, Dimension::Length)
                .unwrap_err()
                .to_string();
            assert!(e.starts_with(&format!("'{}'", typed.trim())), "{e}");
            assert!(!e.contains("cm'"), "{e}");
        }
        let e = parse_typed("1e-400", Dimension::Length)
            .unwrap_err()
            .to_string();
        assert!(e.starts_with("'1e-400' is out of range"), "{e}");
        assert_eq!(parse_typed("12 MG", Dimension::Mass), Ok(12e-6));
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
    fn extreme_exponents_are_out_of_range_never_inf_or_zero() {
        for (text, dim) in [
            ("1e-2147483648cm", Dimension::Length),
            ("1e-2147483648ms", Dimension::Time),
            ("1e-2147483649", Dimension::Ratio),
            ("1e-400", Dimension::Ratio),
            (
                "1e-99999999999999999999999999999999999999999999cm",
                Dimension::Length,
            ),
            ("1e-308mm", Dimension::Length),
            ("1e308kg", Dimension::Length),
        ] {
            let got = parse_quantity(text, dim);
            assert!(
                matches!(
                    got,
                    Err(UnitError::OutOfRange { .. }) | Err(UnitError::UnknownUnit { .. })
                ),
                "{text}: {got:?}"
            );
        }
        let e = parse_quantity("1e-2147483648cm", Dimension::Length).unwrap_err();
        assert!(e.to_string().contains("out of range"), "{e}");
        // 1e2147483647 parses to inf already: not finite.
        assert!(matches!(
            parse_quantity("1e2147483647cm", Dimension::Length),
            Err(UnitError::NotFinite { .. })
        ));
        assert!(matches!(
            parse_quantity("1e308", Dimension::Speed),
            Ok(v) if v == 1e308
        ));
        // Within range the shift stays exact, and zero stays zero however written.
        assert_eq!(parse_quantity("1e-300cm", Dimension::Length), Ok(1e-302));
        assert_eq!(
            parse_quantity("0e-2147483648cm", Dimension::Length),
            Ok(0.0)
        );
        assert_eq!(parse_quantity("-0.0e-999999ms", Dimension::Time), Ok(-0.0));
    }

    #[test]
    fn unit_names_are_names_never_numbers() {
        assert_eq!(unit_factor("ms", Dimension::Time), Ok(1e-3));
        assert_eq!(unit_factor(" cm/s ", Dimension::Speed), Ok(0.01));
        assert_eq!(unit_factor("s", Dimension::Time), Ok(1.0));
        for (bad, dim) in [
            ("e5", Dimension::Time),
            ("0", Dimension::Time),
            ("7", Dimension::Speed),
            ("2", Dimension::Time),
            ("", Dimension::Time),
            ("1ms", Dimension::Time),
            ("kg", Dimension::Speed),
        ] {
            let e = unit_factor(bad, dim).unwrap_err();
            assert!(matches!(e, UnitError::UnknownUnit { .. }), "{bad}: {e}");
        }
        let e = unit_factor("e5", Dimension::Time).unwrap_err().to_string();
        assert!(e.contains("one of s, ms"), "{e}");
    }
}
