//! Which columns of a position file are whose: the column header and the lines above
//! it (Tracker's `#multi:` and track names, a single track's title, or a spreadsheet's
//! names above tracks side by side, each with its own time column), the track each
//! column belongs to, and which track is the centre and which the rim mark.

use super::options::Reading;
use super::positions::{Axis, Col, position_column};
use super::table::{Row, Sep};

/// Names that say "the centre" or "the mark" when no option does.
const CENTRE_NAMES: [&str; 6] = ["centre", "center", "ball", "cm", "c", "mass a"];
const MARK_NAMES: [&str; 6] = ["mark", "rim", "spot", "m", "mass b", "point 2"];

fn same(a: &str, b: &str) -> bool {
    let norm = |s: &str| s.to_lowercase().replace([' ', '_'], "");
    norm(a) == norm(b)
}

/// The column header and the lines before it (Tracker's `#multi:` and track names, or
/// a single track's name): the first row with a time column, within four rows.
pub(super) fn find_header(rows: &mut impl Iterator<Item = Row>) -> Result<(Vec<Row>, Row), String> {
    let mut before = Vec::new();
    loop {
        let Some(row) = rows.next() else {
            return Err(
                "no header with a time column t found, expected columns t and x (and y), or t, v_cm and v_t"
                    .into(),
            );
        };
        let has_t =
            (0..row.len()).any(|i| position_column(row.cell(i)).is_some_and(|c| c.axis == Axis::T));
        if has_t {
            return Ok((before, row));
        }
        if before.len() == 3 {
            return Err(format!(
                "line {}: no header with a time column t in the first lines, expected columns t and x (and y) for a position track, or t, v_cm and v_t for velocities",
                row.line
            ));
        }
        before.push(row);
    }
}

/// Why the lines above a position file's column names do not say its tracks.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum LayoutError {
    #[error("a '#multi:' file needs a line of track names before the column names")]
    NoTrackNames,
    #[error(
        "line {line}: a multi-track file must be tab, comma or semicolon separated (Tracker writes tabs)"
    )]
    SpaceSeparated { line: usize },
}

/// Gives the columns without a track name the one the lines above them say: a
/// multi-track file's names line, or a single-track file's title; returns the format.
pub(super) fn name_tracks(
    cols: &mut [Option<Col>],
    before: &[Row],
    sep: Sep,
) -> Result<&'static str, LayoutError> {
    let multi = before
        .first()
        .is_some_and(|r| r.cell(0).to_lowercase().starts_with("#multi"));
    if multi {
        // The names line puts each track's name above its first column.
        let Some(names) = before.get(1) else {
            return Err(LayoutError::NoTrackNames);
        };
        if sep == Sep::Space {
            return Err(LayoutError::SpaceSeparated { line: names.line });
        }
        let mut current = String::new();
        for (j, col) in cols.iter_mut().enumerate() {
            let name = names.cell(j);
            if !name.is_empty() {
                current = name.to_string();
            }
            if let Some(c) = col
                && c.axis != Axis::T
                && c.track.is_empty()
            {
                c.track = current.clone();
            }
        }
        Ok("Tracker multi-track")
    } else if let Some(names) = before.last().filter(|r| named_cells(r) > 1) {
        // Tracks side by side (a spreadsheet of several tracks, `A;;;B;;` above
        // `t;x;y;t;x;y`): each name above its track's first column, its own time
        // column included.
        let mut current = String::new();
        for (j, col) in cols.iter_mut().enumerate() {
            let name = names.cell(j);
            if !name.is_empty() {
                current = name.to_string();
            }
            if let Some(c) = col
                && c.track.is_empty()
            {
                c.track = current.clone();
            }
        }
        Ok("tracks side by side")
    } else if let Some(title) = before.last() {
        // Tracker's single-track export: the track's name above the header.
        let name = title.cell(0).to_string();
        for c in cols.iter_mut().flatten() {
            if c.axis != Axis::T && c.track.is_empty() {
                c.track = name.clone();
            }
        }
        Ok("Tracker single-track")
    } else {
        Ok("CSV")
    }
}

/// How many cells of `row` are not empty.
fn named_cells(row: &Row) -> usize {
    (0..row.len()).filter(|&i| !row.cell(i).is_empty()).count()
}

/// The centre's and the mark's track names among `names` (tracks with an x column, in
/// file order): as the options say, else by their names, else the first two.
pub fn pick_roles(names: &[String], reading: &Reading) -> Result<(String, Option<String>), String> {
    let pick = |want: &Option<String>, defaults: &[&str], role: &str| match want {
        Some(w) => names
            .iter()
            .find(|n| same(n, w))
            .cloned()
            .map(Some)
            .ok_or_else(|| {
                let found: Vec<&str> = names
                    .iter()
                    .map(|n| {
                        if n.is_empty() {
                            "(unnamed)"
                        } else {
                            n.as_str()
                        }
                    })
                    .collect();
                format!(
                    "no track '{w}' for the {role} in the file, tracks found: {}",
                    found.join(", ")
                )
            }),
        None => Ok(names
            .iter()
            .find(|n| defaults.iter().any(|d| same(n, d)))
            .cloned()),
    };
    let centre = match pick(&reading.centre, &CENTRE_NAMES, "centre")? {
        Some(c) => c,
        None => names
            .iter()
            .find(|n| n.is_empty())
            .unwrap_or(&names[0])
            .clone(),
    };
    let mark = match pick(&reading.mark, &MARK_NAMES, "mark")? {
        Some(m) if m != centre => Some(m),
        Some(_) => None,
        None => names.iter().find(|n| **n != centre).cloned(),
    };
    if reading.mark.is_some() && mark.is_none() {
        return Err("the mark and the centre name the same track".into());
    }
    Ok((centre, mark))
}
