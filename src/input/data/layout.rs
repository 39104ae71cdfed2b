//! Which columns of a position file are whose: the column header and the lines above
//! it (Tracker's `#multi:` and track names, a single track's title, or a spreadsheet's
//! names above tracks side by side, each with its own time column), the track each
//! column belongs to (a header cell's track, axis and unit), and which track is the
//! centre and which the rim mark.

use super::options::Reading;
use crate::settings::units::Dimension;

use super::table::{
    PIXELS, Sep, TableRow, UnreadUnit, clean, header_unit, unit_factor, written_unit,
};

/// One header cell of a position file: which track, which axis, its SI factor, and
/// whether its unit is pixels (a length only `--scale` or `--length-unit` gives).
#[derive(Clone, Debug, PartialEq)]
pub(super) struct Col {
    pub track: String,
    pub axis: Axis,
    pub factor: Option<f64>,
    pub pixels: bool,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Axis {
    T,
    X,
    Y,
}

/// Symbols and names of other quantities that share a column name with an axis:
/// Tracker's `v_x`, `a_y`, `p_x`, Logger Pro's `X Velocity` are a velocity, an
/// acceleration and a momentum, not positions.
const OTHER_QUANTITIES: [&str; 10] = [
    "v",
    "a",
    "p",
    "f",
    "θ",
    "ω",
    "velocity",
    "acceleration",
    "speed",
    "momentum",
];

/// Reads a header cell such as `t`, `t/ms`, `x (cm)`, `mass A x`, `xA`, `x_mark [mm]`,
/// `y_cm` (unit as suffix), `Latest: X2 (m)` (a second point). `None` for other
/// columns (`v_x`, `v_{x}`, `frame`, …) and for a unit that does not fit the axis.
pub(super) fn position_column(cell: &str) -> Option<Col> {
    column(cell).ok().flatten()
}

/// The axis a header's token names, and the track it names with it: `x2`, `y2`
/// (Logger Pro's second point), `t1`, `t2` (each point's own time), `xA`, `yB` (a
/// sheet's ball A and B); `None` for a token that names no axis.
fn axis_of(t: &str) -> Option<(Axis, Option<String>)> {
    if let [axis @ ('x' | 'y'), ball] = t.chars().collect::<Vec<char>>()[..]
        && ball.is_ascii_alphabetic()
    {
        let axis = if axis == 'x' { Axis::X } else { Axis::Y };
        return Some((axis, Some(ball.to_string())));
    }
    let (letter, digits) = t.split_at(t.find(|c: char| c.is_ascii_digit()).unwrap_or(t.len()));
    let point = (!digits.is_empty() && digits.chars().all(|c| c.is_ascii_digit()))
        .then(|| format!("point {digits}"));
    if !digits.is_empty() && point.is_none() {
        return None;
    }
    match (letter, &point) {
        // `t1`, `t2`: point 1's and point 2's own time columns (`t1,x1,t2,x2`).
        ("t" | "time", _) => Some((Axis::T, point)),
        ("x", _) => Some((Axis::X, point)),
        ("y", _) => Some((Axis::Y, point)),
        _ => None,
    }
}

/// [`position_column`], or the unit where a t, x or y column's unit does not fit its
/// axis (`x (in)`, `t (min)`).
fn column(cell: &str) -> Result<Option<Col>, UnreadUnit> {
    let h = clean(cell);
    // A unit in brackets or after a slash.
    let (name, unit) = match h.find(['(', '[', '/']) {
        Some(i) => (&h[..i], &h[i..]),
        None => (h.as_str(), ""),
    };
    let tokens: Vec<&str> = name
        .split([' ', '_', '.', '-'])
        .filter(|t| !t.is_empty())
        .collect();
    let mut axes = tokens
        .iter()
        .enumerate()
        .filter_map(|(i, t)| axis_of(t).map(|a| (i, a)));
    let Some((at, (axis, point))) = axes.next() else {
        return Ok(None);
    };
    if axes.next().is_some() {
        return Ok(None);
    }
    let dim = if axis == Axis::T {
        Dimension::Time
    } else {
        Dimension::Length
    };
    let mut rest: Vec<&str> = tokens
        .iter()
        .enumerate()
        .filter(|&(i, _)| i != at)
        .map(|(_, t)| *t)
        .collect();
    // A quantity's letter comes before the axis (`v_x`, `ball v x`); after it
    // (`x_A`), or after Tracker's "mass" (`mass A x`), a letter is a track's name.
    let letter_of_track = |i: usize, t: &str| {
        t.chars().count() == 1
            && !"θω".contains(t)
            && (i > at || (i > 0 && tokens.get(i - 1) == Some(&"mass")))
    };
    let quantity = tokens
        .iter()
        .enumerate()
        .any(|(i, t)| i != at && OTHER_QUANTITIES.contains(t) && !letter_of_track(i, t));
    if quantity {
        return Ok(None);
    }
    let pixels = dim == Dimension::Length && PIXELS.contains(&written_unit(unit).as_str());
    let mut factor = match header_unit(unit, dim) {
        Ok(f) => f,
        Err(_) if pixels => None,
        Err(unread) => return Err(unread),
    };
    // `x_cm`, `t_s`: a trailing unit token rather than a track name; after a track's
    // name too (`x_mark_cm`: the track 'mark' in cm).
    if factor.is_none()
        && let [only] = rest.as_slice()
        && let Some(Some(f)) = unit_factor(only, dim)
    {
        factor = Some(f);
        rest.clear();
    }
    if factor.is_none()
        && rest.len() >= 2
        && at < tokens.len() - 1
        && let Some(Some(f)) = rest.last().and_then(|last| unit_factor(last, dim))
    {
        factor = Some(f);
        rest.pop();
    }
    let track = match point {
        Some(p) if rest.is_empty() => p,
        Some(p) => format!("{} {p}", rest.join(" ")),
        None => rest.join(" "),
    };
    Ok(Some(Col {
        track,
        axis,
        factor,
        pixels,
    }))
}

/// The first t, x or y cell of the header `row` whose unit does not fit its axis
/// (only a time's when `times_only`), as the error that names it.
pub(super) fn unknown_unit(row: &TableRow, times_only: bool) -> Option<LayoutError> {
    (0..row.len()).find_map(|i| match column(row.cell(i)) {
        Err(UnreadUnit { unit, dim }) if !times_only || dim == Dimension::Time => {
            Some(LayoutError::UnknownUnit {
                line: row.line,
                cell: row.cell(i).to_string(),
                unit,
                dim,
            })
        }
        _ => None,
    })
}

/// Names that say "the centre" or "the mark" when no option does.
const CENTRE_NAMES: [&str; 6] = ["centre", "center", "ball", "cm", "c", "mass a"];
const MARK_NAMES: [&str; 6] = ["mark", "rim", "spot", "m", "mass b", "point 2"];

fn same(a: &str, b: &str) -> bool {
    let norm = |s: &str| s.to_lowercase().replace([' ', '_'], "");
    norm(a) == norm(b)
}

/// The column header and the lines before it (Tracker's `#multi:` and track names, or
/// a single track's name): the first row with a time column, within four rows.
pub(super) fn find_header(
    rows: &mut impl Iterator<Item = TableRow>,
) -> Result<(Vec<TableRow>, TableRow), LayoutError> {
    let mut before = Vec::new();
    loop {
        let Some(row) = rows.next() else {
            return Err(LayoutError::NoHeader);
        };
        let has_t =
            (0..row.len()).any(|i| position_column(row.cell(i)).is_some_and(|c| c.axis == Axis::T));
        if has_t {
            return Ok((before, row));
        }
        // A time column in a unit not read is this header's, not a missing one.
        if let Some(e) = unknown_unit(&row, true) {
            return Err(e);
        }
        if before.len() == 3 {
            let first = before.first().unwrap_or(&row);
            return Err(LayoutError::NoHeaderNearTop {
                line: row.line,
                first: (
                    first.line,
                    (0..first.len())
                        .map(|i| first.cell(i))
                        .collect::<Vec<_>>()
                        .join(" "),
                ),
            });
        }
        before.push(row);
    }
}

/// Why a position file's header and the lines above it do not say its columns and
/// tracks, or the tracks the options name; or why a header's unit is not read (a
/// velocity file's too).
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum LayoutError {
    #[error(
        "no header with a time column t found, expected columns t and x (and y), or t, v_cm and v_t"
    )]
    NoHeader,
    /// No header in the lines up to `line`, the first of them `first` (its line and
    /// its cells).
    #[error(
        "no header with a time column t in lines {} to {line} (line {}: '{}'), expected columns t and x (and y) for a position track, or t, v_cm and v_t for velocities",
        first.0,
        first.0,
        crate::settings::quote::clip(&first.1)
    )]
    NoHeaderNearTop { line: usize, first: (usize, String) },
    /// The header at `line` (its cells) has no x column.
    #[error(
        "line {line}: no position column x in '{}', expected t and x (and y) for a position track, or t, v_cm and v_t for velocities",
        crate::settings::quote::clip(&cells.join(" "))
    )]
    NoPositionColumn { line: usize, cells: Vec<String> },
    /// The header at `line` has no x column but one speed, `cell` (`v (m/s)`,
    /// `Geschwindigkeit`): not the two speeds a file of velocities gives.
    #[error(
        "line {line}: '{}' is one speed, and no position column x is there: a file of speeds needs two, the centre's and the contact point's, as columns t, v_cm and v_t; a position track needs t and x (and y)",
        crate::settings::quote::clip(cell)
    )]
    OneSpeed { line: usize, cell: String },
    /// No track named `want` (as the option gave it) for the `role` ("centre",
    /// "mark") among the file's tracks (`found`; an empty name is an unnamed track).
    #[error(
        "no track '{}' for the {role} in the file, tracks found: {}",
        crate::settings::quote::clip(want),
        crate::settings::quote::clip(&found.iter().map(|n| if n.is_empty() { "(unnamed)" } else { n }).collect::<Vec<_>>().join(", "))
    )]
    NoTrack {
        want: String,
        role: &'static str,
        found: Vec<String>,
    },
    /// The header cell `cell` at `line` names a column whose `unit` (as written) is
    /// none of its quantity's.
    #[error(
        "line {line}: unknown {} unit '{}' in '{}', expected {}",
        quantity(*dim),
        crate::settings::quote::clip(unit),
        crate::settings::quote::clip(cell),
        crate::settings::units::Expected::FileUnit(*dim)
    )]
    UnknownUnit {
        line: usize,
        cell: String,
        unit: String,
        dim: Dimension,
    },
    /// The header cell `cell` at `line` gives positions in pixels, and no option
    /// gives the length one shows.
    #[error(
        "line {line}: '{}' is in pixels, which need a scale: give the length one pixel shows with --scale (e.g. --scale 1.105mm for a 1 m ruler 905 pixels long)",
        crate::settings::quote::clip(cell)
    )]
    Pixels { line: usize, cell: String },
    #[error("the mark and the centre name the same track")]
    SameTrack,
    #[error("a '#multi:' file needs a line of track names before the column names")]
    NoTrackNames,
    #[error(
        "line {line}: a multi-track file must be tab, comma or semicolon separated (Tracker writes tabs)"
    )]
    SpaceSeparated { line: usize },
}

impl LayoutError {
    /// No header with a time column at `line` (a header that lost it).
    pub(super) fn no_header_at(line: usize) -> LayoutError {
        LayoutError::NoHeaderNearTop {
            line,
            first: (line, String::new()),
        }
    }
}

/// What a header's unit measures, as an error names it.
fn quantity(dim: Dimension) -> &'static str {
    match dim {
        Dimension::Time => "time",
        Dimension::Speed => "speed",
        _ => "length",
    }
}

/// Gives the columns without a track name the one the lines above them say: a
/// multi-track file's names line, or a single-track file's title; returns the format.
pub(super) fn name_tracks(
    cols: &mut [Option<Col>],
    before: &[TableRow],
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
        name_below(cols, names, false);
        Ok("Tracker multi-track")
    } else if let Some(names) = before.last().filter(|r| named_cells(r) > 1) {
        // Tracks side by side (a spreadsheet of several tracks, `A;;;B;;` above
        // `t;x;y;t;x;y`): each name above its track's first column, its own time
        // column included.
        name_below(cols, names, true);
        Ok("tracks side by side")
    } else if let [title] = before {
        // Tracker's single-track export: the track's name alone above the header
        // (lines of notes above it are no track's name).
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

/// Gives each column without a track name the last name at or left of it in `names`
/// (a name stands above its track's first column); time columns too when `times`
/// (tracks side by side each have their own), else they stay shared.
fn name_below(cols: &mut [Option<Col>], names: &TableRow, times: bool) {
    let mut current = String::new();
    for (j, col) in cols.iter_mut().enumerate() {
        let name = names.cell(j);
        if !name.is_empty() {
            current = name.to_string();
        }
        if let Some(c) = col
            && (times || c.axis != Axis::T)
            && c.track.is_empty()
        {
            c.track = current.clone();
        }
    }
}

/// How many cells of `row` are not empty.
fn named_cells(row: &TableRow) -> usize {
    (0..row.len()).filter(|&i| !row.cell(i).is_empty()).count()
}

/// The centre's and the mark's track names among `names` (tracks with an x column, in
/// file order): as the options say, else by their names, else the first two.
pub fn pick_roles(
    names: &[String],
    reading: &Reading,
) -> Result<(String, Option<String>), LayoutError> {
    let pick = |want: &Option<String>, defaults: &[&str], role: &'static str| match want {
        Some(w) => names
            .iter()
            .find(|n| same(n, w))
            .cloned()
            .map(Some)
            .ok_or_else(|| LayoutError::NoTrack {
                want: w.clone(),
                role,
                found: names.to_vec(),
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
            .or(names.first())
            .cloned()
            .unwrap_or_default(),
    };
    let mark = match pick(&reading.mark, &MARK_NAMES, "mark")? {
        Some(m) if m != centre => Some(m),
        Some(_) => None,
        None => names.iter().find(|n| **n != centre).cloned(),
    };
    if reading.mark.is_some() && mark.is_none() {
        return Err(LayoutError::SameTrack);
    }
    Ok((centre, mark))
}
