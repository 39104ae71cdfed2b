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

/// How one dimension is written: the units accepted and the one people read.
struct Units {
    /// Accepted units and their decimal exponent to SI (cm: −2); the first entry is
    /// the SI unit.
    accepted: &'static [(&'static str, i32)],
    /// The unit the app shows, messages print and a bare typed number means.
    display: &'static str,
    /// Decimals of the app's parameter panel in that unit (columns line up); `None`:
    /// four significant digits.
    decimals: Option<usize>,
    /// The unit for the small values of this kind that people read in a finer one (a
    /// position scatter in mm, a fit window in ms); the display unit where none is.
    small: &'static str,
}

impl Dimension {
    /// The one table of units: everything else about units reads it.
    fn table(self) -> &'static Units {
        match self {
            Dimension::Length => &Units {
                accepted: &[("m", 0), ("cm", -2), ("mm", -3)],
                display: "cm",
                decimals: Some(2),
                small: "mm",
            },
            Dimension::Mass => &Units {
                accepted: &[("kg", 0), ("g", -3), ("mg", -6)],
                display: "g",
                decimals: Some(1),
                small: "g",
            },
            Dimension::Speed => &Units {
                accepted: &[("m/s", 0), ("cm/s", -2), ("mm/s", -3)],
                display: "m/s",
                decimals: Some(3),
                small: "m/s",
            },
            Dimension::Time => &Units {
                accepted: &[("s", 0), ("ms", -3)],
                display: "s",
                decimals: Some(3),
                small: "ms",
            },
            Dimension::Acceleration => &Units {
                accepted: &[("m/s^2", 0), ("m/s²", 0), ("m/s2", 0)],
                display: "m/s²",
                decimals: Some(2),
                small: "m/s²",
            },
            Dimension::Ratio => &Units {
                accepted: &[],
                display: "",
                decimals: None,
                small: "",
            },
        }
    }

    /// Accepted units and their decimal exponent to SI. Shifting the decimal exponent
    /// of the text, rather than multiplying, keeps `4.4cm` the very double that
    /// `0.044` is.
    fn units(self) -> &'static [(&'static str, i32)] {
        self.table().accepted
    }

    /// The unit the app shows and a bare typed number means, with its decimal exponent
    /// to SI (cm: −2); empty for a pure number.
    pub fn display_unit(self) -> (&'static str, i32) {
        self.named(self.table().display)
    }

    /// The unit for small values of this kind (mm, ms; else the display unit), with its
    /// decimal exponent to SI.
    pub fn small_unit(self) -> (&'static str, i32) {
        self.named(self.table().small)
    }

    /// An accepted unit with its decimal exponent to SI.
    fn named(self, name: &'static str) -> (&'static str, i32) {
        let shift = self
            .units()
            .iter()
            .find(|(n, _)| *n == name)
            .map_or(0, |u| u.1);
        (name, shift)
    }

    /// `value` (SI) in the display unit: 0.0275 m → 2.75 (cm). A power of ten exact
    /// in binary (100, 1000), so the result is the one multiplication by it.
    pub fn to_display(self, value: f64) -> f64 {
        in_unit(value, self.display_unit().1)
    }

    /// `value` (SI) in the unit for small values: 0.0012 m → 1.2 (mm).
    pub fn to_small(self, value: f64) -> f64 {
        in_unit(value, self.small_unit().1)
    }

    /// `value` (SI) as the parameter panel shows it: the display unit's fixed
    /// decimals (or four significant digits), without the unit.
    pub fn panel_number(self, value: f64) -> String {
        let v = self.to_display(value);
        match self.table().decimals {
            Some(d) => format!("{v:.d$}"),
            None => significant(v, 4),
        }
    }

    /// The display unit after a space (" cm"), empty for a pure number: what follows
    /// a number in text.
    pub fn suffix(self) -> String {
        match self.table().display {
            "" => String::new(),
            unit => format!(" {unit}"),
        }
    }

    /// The unit for small values after a space (" mm"), empty for a pure number.
    pub fn small_suffix(self) -> String {
        match self.small_unit().0 {
            "" => String::new(),
            unit => format!(" {unit}"),
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

    /// What the app's typing field takes: there a bare number is in the display unit,
    /// not SI (the command line's rule would set b to 0.049 cm for "0.049").
    fn allowed_typed(self) -> String {
        let names: Vec<&str> = self.units().iter().map(|u| u.0).collect();
        match self.table().display {
            "" => "a plain number".to_string(),
            unit => format!(
                "a number in {unit} (a bare number is in {unit}) or with a unit {}",
                names.join(", ")
            ),
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
    /// The text is a number, but its value (after the unit) overflows or rounds to 0.
    #[error(
        "'{text}' is out of range ({why}), expected 0 or a magnitude from about 2.2e-308 to 1.8e308 in SI units"
    )]
    OutOfRange { text: String, why: &'static str },
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
        .ok_or_else(|| {
            let names: Vec<&str> = dim.units().iter().map(|u| u.0).collect();
            UnitError::UnknownUnit {
                text: unit.to_string(),
                unit: unit.to_string(),
                allowed: if names.is_empty() {
                    "no unit (a plain number)".to_string()
                } else {
                    format!("one of {}", names.join(", "))
                },
            }
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
            allowed: dim.allowed(),
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
                allowed: dim.allowed(),
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
            allowed: dim.allowed_typed(),
        },
        UnitError::UnknownUnit { unit, .. } => UnitError::UnknownUnit {
            text,
            unit,
            allowed: dim.allowed_typed(),
        },
        UnitError::NotFinite { .. } => UnitError::NotFinite { text },
        UnitError::OutOfRange { why, .. } => UnitError::OutOfRange { text, why },
    }
}

/// `value` (SI) in the unit `shift` decimal places from SI (cm: −2): one
/// multiplication by a power of ten that is exact in binary.
fn in_unit(value: f64, shift: i32) -> f64 {
    match shift {
        0 => value,
        shift => value * 10f64.powi(-shift),
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

    use super::*;

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

    #[test]
    fn shows_lab_units() {
        assert_eq!(show(0.0275, Dimension::Length).to_string(), "2.75 cm");
        assert_eq!(show(0.167, Dimension::Mass).to_string(), "167 g");
        assert_eq!(format!("{:.3}", show(0.6, Dimension::Speed)), "0.600 m/s");
    }
}
