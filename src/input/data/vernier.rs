//! Logger Pro's and Graphical Analysis's "Export As Text" (Vernier Format 2): a title
//! line `Vernier Format 2`, a line with the file's name and date, the data set's
//! name, the columns' long names, their short names, their units, a blank line, then
//! tab-separated data. The header lines are folded into one header of `Name (unit)`
//! cells and the rest is read as any table (a position track or velocities); the
//! other header lines become comments, so every error still names the file's line.

use super::table::file_unit;
use crate::settings::units::Dimension;

/// The format's name, as `groovelab data` and the fit say it.
pub const FORMAT: &str = "Logger Pro text (Vernier Format 2)";

/// True when the first line that is not blank says `Vernier Format 2`.
pub(super) fn is_vernier(text: &str) -> bool {
    text.trim_start_matches('\u{feff}')
        .lines()
        .find(|l| !l.trim().is_empty())
        .is_some_and(|l| l.trim().eq_ignore_ascii_case("vernier format 2"))
}

/// True when a line starts with a number (a data row).
fn is_data(line: &str) -> bool {
    line.split('\t')
        .next()
        .is_some_and(|c| super::table::number(c).is_some())
}

/// True when every cell of `cells` is empty or a unit of time, length or speed (a
/// units line, not a line of short names).
fn is_units(cells: &[&str]) -> bool {
    cells.iter().any(|c| !c.trim().is_empty())
        && cells.iter().all(|c| {
            let c = c.trim();
            c.is_empty()
                || [Dimension::Time, Dimension::Length, Dimension::Speed]
                    .into_iter()
                    .any(|d| file_unit(c, d).is_ok())
        })
}

/// `text` with its header lines folded into one table header (see the module doc):
/// the long names with the units line's units, the other header lines as `#`
/// comments, each line where it was.
pub(super) fn as_table(text: &str) -> String {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let lines: Vec<&str> = text.lines().collect();
    let first_data = lines.iter().position(|l| is_data(l)).unwrap_or(lines.len());
    let title = lines.iter().position(|l| !l.trim().is_empty()).unwrap_or(0);
    // The lines of names below the title, file and data-set lines: the long names
    // first, the units (if any) last.
    let named: Vec<usize> = (title + 1..first_data)
        .filter(|&i| lines.get(i).is_some_and(|l| l.contains('\t')))
        .collect();
    let long = named.first().copied();
    let units = named
        .iter()
        .rev()
        .copied()
        .filter_map(|i| Some((i, *lines.get(i)?)))
        .find(|&(i, l)| Some(i) != long && is_units(&l.split('\t').collect::<Vec<_>>()))
        .map(|(_, l)| l);
    let mut out = String::with_capacity(text.len() + 64);
    for (i, line) in lines.iter().enumerate() {
        if i >= first_data {
            out += line;
        } else if Some(i) == long {
            out += &header(line, units);
        } else if !line.trim().is_empty() {
            out += "# ";
            out += line;
        }
        out.push('\n');
    }
    out
}

/// The long names with their units: `Time (s)`, `X (m)`; a name without a unit as it is.
fn header(names: &str, units: Option<&str>) -> String {
    let units: Vec<&str> = units.map_or_else(Vec::new, |u| u.split('\t').collect());
    names
        .split('\t')
        .enumerate()
        .map(|(j, name)| match units.get(j).map(|u| u.trim()) {
            Some(u) if !u.is_empty() => format!("{} ({u})", name.trim()),
            _ => name.trim().to_string(),
        })
        .collect::<Vec<_>>()
        .join("\t")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_header_lines_fold_into_one() {
        let text = "Vernier Format 2\r\nrun.cmbl 11/26/2026 9:00:00 .\r\nLatest\r\nTime\tX\tY\r\nt\tX\tY\r\ns\tcm\tcm\r\n\r\n0\t1,5\t2\r\n";
        assert!(is_vernier(text));
        let t = as_table(text);
        let lines: Vec<&str> = t.lines().collect();
        assert_eq!(lines[3], "Time (s)\tX (cm)\tY (cm)");
        assert!(lines[0].starts_with("# ") && lines[4].starts_with("# "));
        assert_eq!(lines[7], "0\t1,5\t2");
        // Without a units line the names stay bare.
        let t = as_table("Vernier Format 2\nf\nRun 1\nTime\tPosition\nt\tx\n\n0\t1\n");
        assert_eq!(t.lines().nth(3), Some("Time\tPosition"));
        assert!(!is_vernier("t\tx\n0\t1\n"));
    }
}
