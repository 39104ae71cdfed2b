//! The one table of units: for each kind of quantity the units accepted, the one people
//! read, and the finer one for small values.

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
struct UnitRow {
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
    fn table(self) -> &'static UnitRow {
        match self {
            Dimension::Length => &UnitRow {
                accepted: &[("m", 0), ("cm", -2), ("mm", -3)],
                display: "cm",
                decimals: Some(2),
                small: "mm",
            },
            Dimension::Mass => &UnitRow {
                accepted: &[("kg", 0), ("g", -3), ("mg", -6)],
                display: "g",
                decimals: Some(1),
                small: "g",
            },
            Dimension::Speed => &UnitRow {
                accepted: &[("m/s", 0), ("cm/s", -2), ("mm/s", -3)],
                display: "m/s",
                decimals: Some(3),
                small: "m/s",
            },
            Dimension::Time => &UnitRow {
                accepted: &[("s", 0), ("ms", -3), ("us", -6), ("µs", -6), ("μs", -6)],
                display: "s",
                decimals: Some(3),
                small: "ms",
            },
            Dimension::Acceleration => &UnitRow {
                accepted: &[("m/s^2", 0), ("m/s²", 0), ("m/s2", 0)],
                display: "m/s²",
                decimals: Some(2),
                small: "m/s²",
            },
            Dimension::Ratio => &UnitRow {
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
    pub(super) fn units(self) -> &'static [(&'static str, i32)] {
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

    /// Decimals of the parameter panel in the display unit; `None`: four significant
    /// digits.
    pub(super) fn decimals(self) -> Option<usize> {
        self.table().decimals
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
}

/// `value` (SI) in the unit `shift` decimal places from SI (cm: −2): one
/// multiplication by a power of ten that is exact in binary.
fn in_unit(value: f64, shift: i32) -> f64 {
    match shift {
        0 => value,
        shift => value * 10f64.powi(-shift),
    }
}
