//! The cells of a data file, read with the `csv` crate: the separator found in the
//! first lines (tabs, else semicolons — then commas are decimal commas —, else commas,
//! else runs of spaces), a byte-order mark, blank lines and `#` comments dropped
//! (Tracker's `#multi:` kept), every row with the file's own line number for errors;
//! and the helpers that read a cell: header names with their units, and numbers.

use crate::settings::units::{self, Dimension};

/// How the cells of a line are separated.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Sep {
    Tab,
    Semicolon,
    Comma,
    /// Runs of spaces (Tracker's space-separated export).
    Space,
}

impl Sep {
    /// The separator of a file whose first lines are `lines`: a title line (Tracker's
    /// track name) has none, so the first lines that have one decide.
    fn of<'a>(lines: impl Iterator<Item = &'a str>) -> Sep {
        let head: Vec<&str> = lines.take(5).collect();
        let any = |c: char| head.iter().any(|l| l.contains(c));
        if any('\t') {
            Sep::Tab
        } else if any(';') {
            Sep::Semicolon
        } else if any(',') {
            Sep::Comma
        } else {
            Sep::Space
        }
    }
}

/// One row of a file: its line number (from 1) and its cells, trimmed.
#[derive(Clone)]
pub(crate) struct TableRow {
    pub line: usize,
    pub cells: csv::StringRecord,
}

impl TableRow {
    /// Cell `i` without quotes and blanks; "" past the row's end.
    pub fn cell(&self, i: usize) -> &str {
        self.cells.get(i).map_or("", |c| c.trim().trim_matches('"'))
    }

    pub fn len(&self) -> usize {
        self.cells.len()
    }
}

/// A data file's rows, read lazily (a file may hold a million).
pub(crate) struct Table {
    pub sep: Sep,
    /// The lines kept, one per row, separated by the separator.
    text: String,
    /// The file's line number of each kept line.
    lines: Vec<usize>,
    /// The last line's number when it is cut short ([`cut_short_last`]): not a row.
    cut: Option<usize>,
}

/// The line number (from 1) of the file's last line when the file was cut off in the
/// middle of it: no line end after it, and fewer cells than the line before it (an
/// export stopped mid-row; its last number may be cut too, 0.0345 read as 0).
pub(crate) fn cut_short_last(text: &str) -> Option<usize> {
    if text.ends_with('\n') || text.ends_with('\r') {
        return None;
    }
    let total = text.lines().count();
    let mut kept = text
        .lines()
        .rev()
        .enumerate()
        .map(|(j, l)| (total - 1 - j, l))
        .filter(|(_, l)| !l.trim().is_empty() && !l.trim_start().starts_with('#'));
    let (n, last) = kept.next()?;
    let (_, before) = kept.next()?;
    // Both counted by the separator of the complete line.
    let sep = Sep::of(std::iter::once(before));
    let cells = |l: &str| match sep {
        Sep::Tab => l.split('\t').count(),
        Sep::Semicolon => l.split(';').count(),
        Sep::Comma => l.split(',').count(),
        Sep::Space => l.split_whitespace().count(),
    };
    (cells(last) < cells(before)).then_some(n + 1)
}

impl Table {
    pub fn new(text: &str) -> Table {
        // Spreadsheets often start a UTF-8 file with a byte-order mark.
        let text = text.strip_prefix('\u{feff}').unwrap_or(text);
        // Excel's `sep=;` first line names the separator (which the line itself
        // shows) and is no row.
        let kept = || {
            text.lines().enumerate().filter(|(n, l)| {
                let l = l.trim_start();
                let sep_line =
                    *n == 0 && l.to_lowercase().starts_with("sep=") && l.trim().len() <= 5;
                !l.trim().is_empty()
                    && (!l.starts_with('#') || l.to_lowercase().starts_with("#multi"))
                    && !sep_line
            })
        };
        let sep = Sep::of(kept().map(|(_, l)| l));
        let mut out = String::with_capacity(text.len());
        let mut lines = Vec::new();
        for (n, line) in kept() {
            if sep == Sep::Space {
                // Runs of spaces are one separator: the csv reader splits on one byte.
                out += &line.split_whitespace().collect::<Vec<_>>().join("\t");
            } else {
                out += line;
            }
            out.push('\n');
            lines.push(n + 1);
        }
        Table {
            sep,
            text: out,
            lines,
            cut: cut_short_last(text),
        }
    }

    /// The rows in file order.
    pub fn rows(&self) -> impl Iterator<Item = TableRow> + '_ {
        let delimiter = match self.sep {
            Sep::Tab | Sep::Space => b'\t',
            Sep::Semicolon => b';',
            Sep::Comma => b',',
        };
        let reader = csv::ReaderBuilder::new()
            .delimiter(delimiter)
            .has_headers(false)
            .flexible(true)
            .trim(csv::Trim::All)
            .from_reader(self.text.as_bytes());
        // Each kept line is one record (a quoted line break would shift the numbers,
        // so the record's own line is looked up, not counted).
        reader
            .into_records()
            .filter_map(Result::ok)
            .map(|cells| {
                let k = cells.position().map_or(0, |p| p.line() as usize - 1);
                TableRow {
                    line: self.lines.get(k).copied().unwrap_or(0),
                    cells,
                }
            })
            .filter(|row| Some(row.line) != self.cut)
    }
}

/// A header cell in lower case, without quotes, blanks and a run prefix (Logger Pro
/// and Graphical Analysis write `Latest: Time (s)`, `Run 1: X (m)`), a name in
/// another language read as its English one ([`ALIASES`]). Every header cell is read
/// through here.
pub(crate) fn clean(cell: &str) -> String {
    let c = cell.trim().trim_matches('"').trim().to_lowercase();
    let name = match c.split_once(':') {
        Some((_, name)) => name.trim().to_string(),
        None => c,
    };
    // `Zeit in s`, `Weg in cm`: the unit after "in", as German sheets write it.
    let name = match name.rsplit_once(" in ") {
        Some((quantity, unit)) if is_unit(unit) => format!("{} ({})", quantity.trim(), unit.trim()),
        _ => name,
    };
    english(name)
}

/// Column names that tools and spreadsheets in German, French, Spanish and Italian
/// write, and the name they are read as: time (`Zeit (s)`, `temps`, `tiempo`) and
/// position (`Position`, `Ort`, `posición`). A velocity (`Geschwindigkeit`,
/// `vitesse`, `velocidad`) names neither v_cm nor v_t and is read as a velocity `v`,
/// which a position track ignores; a file of velocities needs t, v_cm and v_t.
const ALIASES: [(&str, &str); 14] = [
    ("zeit", "time"),
    ("temps", "time"),
    ("tiempo", "time"),
    ("tempo", "time"),
    ("position", "x"),
    ("ort", "x"),
    ("weg", "x"),
    ("posición", "x"),
    ("posicion", "x"),
    ("posizione", "x"),
    ("geschwindigkeit", "v"),
    ("vitesse", "v"),
    ("velocidad", "v"),
    ("velocità", "v"),
];

/// `name` with a leading word of [`ALIASES`] (alone, or before its unit) in English;
/// a position word before the axis it names (`Position x (m)`, `Ort y`) is dropped,
/// as is the quantity's symbol after its word (`Zeit t`, `Weg s`).
fn english(name: String) -> String {
    for (from, to) in ALIASES {
        if let Some(rest) = name.strip_prefix(from)
            && (rest.is_empty() || rest.starts_with([' ', '(', '[', '/', '_']))
        {
            let axis = rest.trim_start_matches([' ', '_']);
            let names_axis = to == "x"
                && axis.starts_with(['x', 'y'])
                && axis[1..]
                    .trim_start_matches(|c: char| c.is_ascii_digit())
                    .chars()
                    .next()
                    .is_none_or(|c| " ([/_".contains(c));
            if names_axis {
                return axis.to_string();
            }
            // The quantity's own symbol after its word (`Zeit t in s`, `Weg s in cm`,
            // as German sheets write them) says it again.
            let symbol = match to {
                "time" => "t",
                "x" => "s",
                _ => "v",
            };
            if let Some(after) = axis.strip_prefix(symbol)
                && after.chars().next().is_none_or(|c| " ([/".contains(c))
                && rest.starts_with(' ')
            {
                return format!("{to} {}", after.trim_start())
                    .trim_end()
                    .to_string();
            }
            return format!("{to}{rest}");
        }
    }
    name
}

/// Unit names that tools write and the unit table does not hold: microseconds as
/// `us`, `µs` (micro sign) or `μs` (Greek mu), and units spelt out (`seconds`,
/// `meters`), as Logger Pro and Arduino sketches write them; each as its table name.
const UNIT_SPELLINGS: [(&str, &str); 14] = [
    ("sec", "s"),
    ("secs", "s"),
    ("second", "s"),
    ("seconds", "s"),
    ("milliseconds", "ms"),
    ("meter", "m"),
    ("meters", "m"),
    ("metre", "m"),
    ("metres", "m"),
    ("centimeters", "cm"),
    ("centimetres", "cm"),
    ("millimeters", "mm"),
    ("millimetres", "mm"),
    ("m/sec", "m/s"),
];

/// The SI factor of a unit a data file or a data option names: the unit table's
/// names, microseconds (`us`, `µs`, `μs`) and the spellings of [`UNIT_SPELLINGS`].
pub fn file_unit(unit: &str, dim: Dimension) -> Result<f64, units::UnitError> {
    let u = unit.trim();
    if dim == Dimension::Time && ["us", "µs", "μs", "microseconds"].contains(&u) {
        return Ok(1e-6);
    }
    let lower = u.to_lowercase();
    // A speed written with a negative power (`m s^-1`, `m·s⁻¹`, `cm s-1`) as a quotient.
    let quotient = (dim == Dimension::Speed)
        .then(|| {
            let compact = lower.replace(['·', ' ', '*'], "").replace("⁻¹", "^-1");
            ["s^-1", "s-1"]
                .iter()
                .find_map(|p| compact.strip_suffix(p).map(|l| format!("{l}/s")))
        })
        .flatten();
    let name = match &quotient {
        Some(q) => q.as_str(),
        None => UNIT_SPELLINGS
            .iter()
            .find(|(from, _)| *from == lower)
            .map_or(u, |(_, to)| to),
    };
    units::unit_factor(name, dim).map_err(|e| match e {
        units::UnitError::UnknownUnit { .. } => units::UnitError::UnknownUnit {
            text: u.to_string(),
            unit: u.to_string(),
            allowed: units::Expected::FileUnit(dim),
        },
        other => other,
    })
}

/// The SI factor of a unit written after a column name: `(ms)`, `[cm/s]`, `/ms`,
/// `_m_per_s`; `Some(None)` when there is none, `None` when it is not a unit of `dim`.
pub(crate) fn unit_factor(rest: &str, dim: Dimension) -> Option<Option<f64>> {
    header_unit(rest, dim).ok()
}

/// Position columns in pixels (`x (px)`), which need a scale.
pub(crate) const PIXELS: [&str; 3] = ["px", "pixel", "pixels"];

/// True when `cell` is written as a unit a column can have: a time, length or speed
/// unit, or pixels (`ms`, `(mm)`, `[m/s]`, `px`).
fn is_unit(cell: &str) -> bool {
    let unit = written_unit(cell);
    !unit.is_empty()
        && (PIXELS.contains(&unit.to_lowercase().as_str())
            || [Dimension::Time, Dimension::Length, Dimension::Speed]
                .into_iter()
                .any(|dim| file_unit(&unit, dim).is_ok()))
}

/// The header `header` with the units of the row under it, where that row gives
/// them (`t`, `x` over `s`, `mm`, as spreadsheets and some loggers write them): each
/// name that has no unit of its own written with its cell's (`t (s)`, `x (mm)`), as
/// if the header said them. `None` when `row` is no units row: a cell of it is a
/// number, or none is a unit.
pub(crate) fn with_units_row(header: &TableRow, row: &TableRow) -> Option<TableRow> {
    let cells = (0..row.len()).map(|i| row.cell(i));
    if cells.clone().any(|c| number(c).is_some()) || !cells.clone().any(is_unit) {
        return None;
    }
    let merged = (0..header.len().max(row.len())).map(|i| {
        let (name, unit) = (header.cell(i), row.cell(i));
        if unit.is_empty() || name.contains(['(', '[', '/']) {
            name.to_string()
        } else {
            format!("{name} ({})", written_unit(unit))
        }
    });
    Some(TableRow {
        line: header.line,
        cells: merged.collect::<Vec<_>>().into(),
    })
}

/// The header `header`, with the units of the next row of `rows` where it is a
/// units row ([`with_units_row`]), which is then taken from `rows`.
pub(crate) fn units_under(
    header: TableRow,
    rows: &mut std::iter::Peekable<impl Iterator<Item = TableRow>>,
) -> TableRow {
    match rows.peek().and_then(|row| with_units_row(&header, row)) {
        Some(merged) => {
            rows.next();
            merged
        }
        None => header,
    }
}

/// A unit written after a column name that is none of its quantity's: the unit as
/// written (`in`, `min`) and the quantity.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) struct UnreadUnit {
    pub unit: String,
    pub dim: Dimension,
}

/// [`unit_factor`], or the unit as written when it is none of `dim`'s.
pub(crate) fn header_unit(rest: &str, dim: Dimension) -> Result<Option<f64>, UnreadUnit> {
    let unit = written_unit(rest);
    if unit.is_empty() {
        return Ok(None);
    }
    // Only a unit name counts: `t2`, `t_1` or `time0` are other columns, not times in
    // units of 12, 11 or 10 s.
    file_unit(&unit, dim)
        .map(Some)
        .map_err(|_| UnreadUnit { unit, dim })
}

/// The unit written after a column name, without its brackets (`cm/s` of `[cm/s]`,
/// `m/s` of `_m_per_s`); empty when there is none.
pub(crate) fn written_unit(rest: &str) -> String {
    rest.trim()
        .trim_start_matches(['_', '(', '[', '/', ' '])
        .trim_end_matches([')', ']', ' '])
        .replace("_per_", "/")
}

/// A number as video tools write it: `0.12`, `0,12` (decimal comma), `1.2e-3`,
/// `3.200000000E-2`.
pub(crate) fn number(cell: &str) -> Option<f64> {
    let c = cell.trim().trim_matches('"');
    c.parse::<f64>()
        .ok()
        .or_else(|| c.replace(',', ".").parse::<f64>().ok())
        .filter(|v| v.is_finite())
}

/// True for a cell that marks a missing value: empty, `NaN` as Tracker writes where
/// it cannot differentiate (the first and last frames), or a spreadsheet's "not
/// available" (`#N/A` in English Excel and Google Sheets, `#NV` in German Excel).
pub(crate) fn missing(cell: &str) -> bool {
    let c = cell.trim().trim_matches('"');
    c.is_empty()
        || ["nan", "#n/a", "#nv", "#nd", "#n/d"]
            .iter()
            .any(|m| c.eq_ignore_ascii_case(m))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rows_keep_their_line_numbers_and_quotes_go() {
        let text = "\u{feff}# a comment\n\"Latest: Time (s)\",\"Latest: X (m)\"\r\n\r\n0,\"1.5\"\n# c\n0.1,2\n";
        let t = Table::new(text);
        assert_eq!(t.sep, Sep::Comma);
        let rows: Vec<TableRow> = t.rows().collect();
        assert_eq!(rows.len(), 3);
        assert_eq!(
            rows.iter().map(|r| r.line).collect::<Vec<_>>(),
            vec![2, 4, 6]
        );
        assert_eq!(clean(rows[0].cell(0)), "time (s)");
        assert_eq!(rows[1].cell(1), "1.5");
    }

    #[test]
    fn names_in_other_languages_read_as_english() {
        assert_eq!(clean("Zeit (s)"), "time (s)");
        assert_eq!(clean("\"Latest: Temps (ms)\""), "time (ms)");
        assert_eq!(clean("tiempo"), "time");
        assert_eq!(clean("Posición [cm]"), "x [cm]");
        assert_eq!(clean("Geschwindigkeit (m/s)"), "v (m/s)");
        // Only a whole word: other names that begin alike stay as they are.
        assert_eq!(clean("Zeitpunkt"), "zeitpunkt");
        assert_eq!(clean("orthogonal"), "orthogonal");
        assert_eq!(clean("t"), "t");
        // A position word before its axis names that axis.
        assert_eq!(clean("Position x (m)"), "x (m)");
        assert_eq!(clean("Run 1: Position y [cm]"), "y [cm]");
        assert_eq!(clean("Position X2 (m)"), "x2 (m)");
        assert_eq!(clean("Position (m)"), "x (m)");
        assert_eq!(clean("Position xyz"), "x xyz");
        // A unit after "in", as German sheets write it; "in" alone is no unit.
        assert_eq!(clean("Zeit in s"), "time (s)");
        assert_eq!(clean("v_cm in m/s"), "v_cm (m/s)");
        assert_eq!(clean("Weg in cm"), "x (cm)");
        assert_eq!(clean("x in"), "x in");
        assert_eq!(clean("Ort in Metern"), "x in metern");
        // The quantity's symbol after its word is the same column, once.
        assert_eq!(clean("Zeit t in s"), "time (s)");
        assert_eq!(clean("Weg s in cm"), "x (cm)");
        assert_eq!(clean("Zeit t"), "time");
        assert_eq!(clean("Geschwindigkeit v in m/s"), "v (m/s)");
        // Not a word that only begins with the symbol.
        assert_eq!(clean("Weg stop"), "x stop");
    }

    #[test]
    fn microseconds_and_spelt_out_units_are_units() {
        for us in ["us", "µs", "μs"] {
            assert_eq!(
                unit_factor(&format!("({us})"), Dimension::Time),
                Some(Some(1e-6))
            );
        }
        assert_eq!(unit_factor("(seconds)", Dimension::Time), Some(Some(1.0)));
        assert_eq!(unit_factor("(Meters)", Dimension::Length), Some(Some(1.0)));
        assert_eq!(unit_factor("(us)", Dimension::Length), None);
        // A speed with a negative power of s, spaced or not, is its quotient.
        for (unit, factor) in [
            ("m s^-1", 1.0),
            ("ms^-1", 1.0),
            ("m·s⁻¹", 1.0),
            ("cm s-1", 0.01),
        ] {
            assert_eq!(
                file_unit(unit, Dimension::Speed).ok(),
                Some(factor),
                "{unit}"
            );
        }
        assert!(file_unit("m s^-1", Dimension::Length).is_err());
        let e = file_unit("fortnights", Dimension::Time)
            .unwrap_err()
            .to_string();
        assert!(e.contains("us"), "{e}");
    }

    #[test]
    fn the_separator_comes_from_the_lines_that_have_one() {
        let t = Table::new("mass_A\nt\tx\ty\n0\t1,5\t2\n");
        assert_eq!(t.sep, Sep::Tab);
        let rows: Vec<TableRow> = t.rows().collect();
        assert_eq!(rows[0].len(), 1);
        assert_eq!(number(rows[2].cell(1)), Some(1.5));
        let t = Table::new("t   x\n0  1\n");
        assert_eq!(t.sep, Sep::Space);
        assert_eq!(t.rows().nth(1).unwrap().cell(1), "1");
        let t = Table::new("#multi:\nt;x\n0;1,5\n");
        assert_eq!(t.sep, Sep::Semicolon);
        assert_eq!(t.rows().next().unwrap().cell(0), "#multi:");
    }
}
