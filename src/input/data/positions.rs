//! Reading position tracks exported by video-analysis tools: Tracker's single-track
//! (the track's name, then `t x y v_x …`) and multi-track (`#multi:`, track names,
//! column names) data files, Logger Pro / Graphical Analysis exports (`Latest: X (m)`,
//! a second point as `X2`, `Y2`), and plain CSV/TSV with named columns. Finds the
//! time, the ball's centre and an optional rim mark by name and uses their position
//! columns only (velocities and the like are ignored), converts to SI, keeps empty and
//! `NaN` cells as missing. The velocities are derived in `study::measured`.

use super::layout::{
    Axis, Col, LayoutError, find_header, name_tracks, pick_roles, position_column, unknown_unit,
};
use super::notes::{Notes, UnitNote};
use super::options::{MAX_ROWS, Reading};
use super::problem::{DataError, DataProblem, RowError};
use super::scales::{Given, LENGTHS, TIMES, check_track_as_read};
use super::table::{Sep, Table, TableRow, clean, missing, number, units_under};
use crate::study::measured::{Track, TrackParts};

/// Parses a position file (see the module doc) into a [`Track`] in SI units.
pub fn parse(text: &str, file: &str, reading: &Reading) -> Result<Track, DataError> {
    from_table(&Table::new(text), file, reading)
}

/// [`parse`] of a file already split into rows.
pub(super) fn from_table(table: &Table, file: &str, reading: &Reading) -> Result<Track, DataError> {
    read_table(table, file, reading).map(|(track, _)| track)
}

/// [`from_table`] with what the file said about itself ([`Notes`]).
pub(super) fn read_table(
    table: &Table,
    file: &str,
    reading: &Reading,
) -> Result<(Track, Notes), DataError> {
    let err = |what: DataProblem| DataError::new(file, what);
    let mut rows = table.rows().peekable();
    let (before, header) = find_header(&mut rows).map_err(|e| err(e.into()))?;
    let header = units_under(header, &mut rows);
    let mut cols: Vec<Option<Col>> = (0..header.len())
        .map(|i| position_column(header.cell(i)))
        .collect();
    units_read(&header, &cols, reading).map_err(|e| err(e.into()))?;
    let format = name_tracks(&mut cols, &before, table.sep).map_err(|e| err(e.into()))?;
    let format = match format {
        "CSV" if (0..header.len()).any(|i| header.cell(i).contains(':')) => {
            "Logger Pro / Graphical Analysis"
        }
        f => f,
    };
    let names = tracks_with_x(&cols, &header).map_err(|e| err(e.into()))?;
    let (centre, mark) = pick_roles(&names, reading).map_err(|e| err(e.into()))?;
    let index = |track: &str, axis: Axis| {
        cols.iter().position(|c| {
            c.as_ref()
                .is_some_and(|c| c.axis == axis && c.track == track)
        })
    };
    // A track's own time column where it has one (tracks side by side), else the
    // first (one time for every track).
    // `find_header` found a t column; were it gone, the header would be no header.
    let first_t = cols
        .iter()
        .position(|c| c.as_ref().is_some_and(|c| c.axis == Axis::T))
        .ok_or_else(|| err(LayoutError::no_header_at(header.line).into()))?;
    let it = index(&centre, Axis::T).unwrap_or(first_t);
    let mark_t = mark
        .as_ref()
        .map(|m| index(m, Axis::T).unwrap_or(first_t))
        .filter(|&t| t != it);
    let ix = index(&centre, Axis::X).ok_or_else(|| {
        err(DataProblem::NoPosition {
            centre: centre.clone(),
        })
    })?;
    let iy = index(&centre, Axis::Y);
    let im = match &mark {
        Some(m) => match (index(m, Axis::X), index(m, Axis::Y), iy) {
            (Some(a), Some(b), Some(_)) => Some((a, b)),
            _ if reading.mark.is_some() => {
                return Err(err(DataProblem::MarkWithoutXy { mark: m.clone() }));
            }
            _ => None,
        },
        None => None,
    };
    let units = Decided::new(&cols, reading);
    let mut parts = TrackParts {
        centre_name: centre.clone(),
        mark_name: im.and(mark.clone()),
        format,
        mark: im.map(|_| (Vec::new(), Vec::new())),
        ..TrackParts::default()
    };
    let columns = Columns {
        header: (header.clone(), table.sep),
        t: (it, units.factor(it, Axis::T)),
        x: (ix, units.factor(ix, Axis::X)),
        y: iy.map(|i| (i, units.factor(i, Axis::Y))),
        mark: im
            .filter(|_| mark_t.is_none())
            .map(|(a, b)| ((a, units.factor(a, Axis::X)), (b, units.factor(b, Axis::Y)))),
    };
    if mark_t.is_some() {
        parts.mark = None;
    }
    read_rows(rows, &columns, &mut parts).map_err(|e| err(e.into()))?;
    let mut track = Track::new(parts).map_err(|e| err(e.into()))?;
    // A mark with its own time column: read as a track of its own, matched to the
    // centre's frames by time (as two one-track exports are).
    if let (Some(t), Some((a, b))) = (mark_t, im) {
        let own = Columns {
            header: (header.clone(), table.sep),
            t: (t, units.factor(t, Axis::T)),
            x: (a, units.factor(a, Axis::X)),
            y: Some((b, units.factor(b, Axis::Y))),
            mark: None,
        };
        let name = mark.clone().unwrap_or_default();
        track = with_own_time_mark(track, table, &own, name).map_err(err)?;
    }
    if track.x().iter().filter(|x| x.is_finite()).count() == 0 {
        return Err(err(DataProblem::NoPosition { centre }));
    }
    let given = units.given(it, ix);
    check_track_as_read(&track, &given, reading.own_lengths).map_err(|e| err(e.into()))?;
    Ok((track, notes(format, names, &given)))
}

/// Whether the header's units can be read: every t, x and y column's a unit of its
/// axis, and pixels only with the length one shows (`--scale`, `--length-unit`; or
/// read in the file's own unit).
fn units_read(
    header: &TableRow,
    cols: &[Option<Col>],
    reading: &Reading,
) -> Result<(), LayoutError> {
    if let Some(e) = unknown_unit(header, false) {
        return Err(e);
    }
    let unscaled = reading.scale.or(reading.length_unit).is_none() && !reading.own_lengths;
    let pixels = cols
        .iter()
        .position(|c| c.as_ref().is_some_and(|c| c.pixels));
    match pixels.filter(|_| unscaled) {
        Some(i) => Err(LayoutError::Pixels {
            line: header.line,
            cell: header.cell(i).to_string(),
        }),
        None => Ok(()),
    }
}

/// What a position file said about itself: its format, tracks and units.
fn notes(format: &str, tracks: Vec<String>, given: &Given) -> Notes {
    Notes {
        cut_row: None,
        impact_in_file: None,
        format: format.to_string(),
        tracks,
        units: vec![
            UnitNote::of("time", &TIMES, given.time.0, given.time.1),
            UnitNote::of("length", &LENGTHS, given.length.0, given.length.1),
        ],
    }
}

/// Each column's unit: an option given wins over the header (a header that states a
/// wrong unit is set right by the option its error names), else SI.
struct Decided<'a> {
    cols: &'a [Option<Col>],
    time: Option<f64>,
    length: Option<f64>,
    length_flag: &'static str,
}

impl Decided<'_> {
    fn new<'a>(cols: &'a [Option<Col>], reading: &Reading) -> Decided<'a> {
        Decided {
            cols,
            time: reading.time_unit,
            length: reading.length_unit.or(reading.scale),
            length_flag: if reading.length_unit.is_some() {
                "--length-unit"
            } else {
                "--scale"
            },
        }
    }

    fn header(&self, i: usize) -> Option<f64> {
        self.cols.get(i)?.as_ref().and_then(|c| c.factor)
    }

    fn factor(&self, i: usize, axis: Axis) -> f64 {
        let option = if axis == Axis::T {
            self.time
        } else {
            self.length
        };
        option.or(self.header(i)).unwrap_or(1.0)
    }

    /// Who decided the time column `t`'s and the x column `x`'s units.
    fn given(&self, t: usize, x: usize) -> Given {
        let by = |option: Option<f64>, flag: &'static str, i: usize| match (option, self.header(i))
        {
            (Some(f), _) => (f, Some(flag)),
            (None, Some(f)) => (f, Some("the header")),
            (None, None) => (1.0, None),
        };
        Given {
            time: by(self.time, "--time-unit", t),
            length: by(self.length, self.length_flag, x),
        }
    }
}

/// The tracks with an x column, in file order, or why the header has none.
fn tracks_with_x(cols: &[Option<Col>], header: &TableRow) -> Result<Vec<String>, LayoutError> {
    let mut names: Vec<String> = Vec::new();
    for c in cols.iter().flatten() {
        if c.axis == Axis::X && !names.contains(&c.track) {
            names.push(c.track.clone());
        }
    }
    if let Some(cell) = names
        .is_empty()
        .then(|| {
            (0..header.len())
                .map(|i| header.cell(i))
                .find(|c| one_speed(c))
        })
        .flatten()
    {
        return Err(LayoutError::OneSpeed {
            line: header.line,
            cell: cell.to_string(),
        });
    }
    if names.is_empty() {
        return Err(LayoutError::NoPositionColumn {
            line: header.line,
            cells: (0..header.len())
                .map(|i| header.cell(i))
                .filter(|c| !c.is_empty())
                .map(str::to_string)
                .collect(),
        });
    }
    Ok(names)
}

/// True when a header cell names a single speed (`v (m/s)`, `speed`, `v_x`,
/// `Geschwindigkeit`), not v_cm or v_t.
fn one_speed(cell: &str) -> bool {
    let h = clean(cell);
    let name = h.split(['(', '[', '/']).next().unwrap_or("").trim();
    ["v", "vx", "v_x", "v_{x}", "speed", "velocity"].contains(&name)
}

/// `track` with the mark read from `table`'s `columns` (its own time column) and
/// matched to the centre's frames by time.
fn with_own_time_mark(
    track: Track,
    table: &Table,
    columns: &Columns,
    name: String,
) -> Result<Track, DataProblem> {
    let mut rim = TrackParts {
        centre_name: name,
        ..TrackParts::default()
    };
    let mut rows = table.rows().peekable();
    let header = find_header(&mut rows)?.1;
    units_under(header, &mut rows);
    read_rows(rows, columns, &mut rim)?;
    let format = track.format();
    let track = track.with_mark(&Track::new(rim)?)?;
    Ok(Track::new(TrackParts {
        format,
        ..track.into_parts()
    })?)
}

/// Where a track's values are in a row, and their SI factors.
struct Columns {
    /// The header (its rows are no wider) and the file's separator.
    header: (TableRow, Sep),
    t: (usize, f64),
    x: (usize, f64),
    y: Option<(usize, f64)>,
    mark: Option<((usize, f64), (usize, f64))>,
}

/// Appends the data rows to `track`: rows without a time are dropped, an empty or
/// `NaN` cell is a missing value (NaN).
fn read_rows(
    rows: impl Iterator<Item = TableRow>,
    columns: &Columns,
    track: &mut TrackParts,
) -> Result<(), RowError> {
    // The last time kept, as written (an error quotes it).
    let mut prev = String::new();
    for row in rows {
        if track.t.len() == MAX_ROWS {
            return Err(RowError::TooMany { line: row.line });
        }
        if let Some(e) = RowError::wider(&row, &columns.header.0, columns.header.1) {
            return Err(e);
        }
        let value = |(i, f): (usize, f64), name: &'static str| -> Result<f64, RowError> {
            let c = row.cell(i);
            if missing(c) {
                return Ok(f64::NAN);
            }
            let v = number(c).ok_or_else(|| RowError::NotANumber {
                line: row.line,
                name,
                cell: c.to_string(),
            })?;
            if v.abs() > super::problem::MOST_CELL {
                return Err(RowError::Beyond {
                    line: row.line,
                    name,
                    value: v,
                });
            }
            Ok(v * f)
        };
        let time = value(columns.t, "t")?;
        if time.is_nan() {
            continue;
        }
        let (it, factor) = columns.t;
        if track.t.last().is_some_and(|&last| time <= last) {
            return Err(RowError::not_increasing(
                row.line,
                row.cell(it),
                &prev,
                factor,
            ));
        }
        prev.clear();
        prev.push_str(row.cell(it));
        track.t.push(time);
        track.x.push(value(columns.x, "x")?);
        track.y.push(match columns.y {
            Some(c) => value(c, "y")?,
            None => f64::NAN,
        });
        if let (Some((a, b)), Some((mx, my))) = (columns.mark, track.mark.as_mut()) {
            mx.push(value(a, "mark x")?);
            my.push(value(b, "mark y")?);
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn read(text: &str, reading: &Reading) -> Result<Track, DataError> {
        parse(text, "f.txt", reading)
    }

    #[test]
    fn header_cells_name_track_axis_and_unit() {
        let c = |s: &str| position_column(s);
        assert_eq!(c("t").unwrap().axis, Axis::T);
        assert_eq!(c("t/ms").unwrap().factor, Some(1e-3));
        assert_eq!(c("x (cm)").unwrap().factor, Some(1e-2));
        assert_eq!(c("x [mm]").unwrap().factor, Some(1e-3));
        assert_eq!(c("y_cm").unwrap().factor, Some(1e-2));
        assert_eq!(c("y_cm").unwrap().track, "");
        let m = c("x_mark (mm)").unwrap();
        assert_eq!(
            (m.track.as_str(), m.axis, m.factor),
            ("mark", Axis::X, Some(1e-3))
        );
        assert_eq!(c("mass B y").unwrap().track, "mass b");
        assert!(c("v_{x}").is_none());
        assert!(c("vx").is_none());
        assert!(c("x (kg)").is_none());
    }

    #[test]
    fn tracker_single_track_with_scientific_numbers_and_gaps() {
        let text = "mass A\nt\tx\ty\tv_{x}\n0.000000000E0\t1.0E-1\t2.0E-2\t\n3.200000000E-2\t\t2.0E-2\t1.5\n6.4E-2\t1.2E-1\t2.0E-2\t\n";
        let t = read(text, &Reading::default()).unwrap();
        assert_eq!(t.format(), "Tracker single-track");
        assert_eq!(t.centre_name(), "mass A");
        assert_eq!(t.t(), vec![0.0, 0.032, 0.064]);
        assert!(t.x()[1].is_nan());
        assert_eq!(t.x()[2], 0.12);
        assert!(t.mark().is_none());
    }

    #[test]
    fn tracker_multi_track_names_centre_and_mark() {
        let text =
            "#multi:\n\tmass A\t\tmass B\t\n t\tx\ty\tx\ty\n0\t1\t2\t1\t2,5\n0,01\t1,001\t2\t\t\n";
        let t = read(text, &Reading::default()).unwrap();
        assert_eq!(t.format(), "Tracker multi-track");
        assert_eq!(t.centre_name(), "mass A");
        assert_eq!(t.mark_name(), Some("mass B"));
        let (mx, my) = t.mark().unwrap();
        assert_eq!(my[0], 2.5);
        assert!(mx[1].is_nan());
        assert_eq!(t.t()[1], 0.01);
        // Named the other way round by options.
        let swapped = Reading {
            centre: Some("mass b".into()),
            mark: Some("mass A".into()),
            ..Reading::default()
        };
        let t = read(text, &swapped).unwrap();
        assert_eq!(t.x()[0], 1.0);
        assert_eq!(t.y()[0], 2.5);
    }

    #[test]
    fn csv_with_units_semicolons_and_decimal_commas() {
        let text = "t/ms;x (cm);y (cm);x_mark (cm);y_mark (cm)\n0;1,5;0;1,5;2\n10;2,5;0;2,5;2\n";
        let t = read(text, &Reading::default()).unwrap();
        assert_eq!(t.format(), "CSV");
        assert_eq!(t.t(), vec![0.0, 0.01]);
        assert!((t.x()[1] - 0.025).abs() < 1e-15);
        assert_eq!(t.mark_name(), Some("mark"));
        // Units from options where the header has none.
        let text = "t,x\n0,1\n20,2\n";
        let r = Reading {
            time_unit: Some(1e-3),
            length_unit: Some(1e-2),
            ..Reading::default()
        };
        let t = read(text, &r).unwrap();
        assert_eq!((t.t()[1], t.x()[1]), (0.02, 0.02));
    }

    #[test]
    fn errors_say_what_is_missing() {
        let bad = [
            ("", "no header"),
            ("t\tv_{x}\tv_{y}\n0\t1\t2\n", "no position column x"),
            ("t,x\n0,1\n0.1,abc\n", "line 3: x = 'abc'"),
            ("t,x\n0,1\n0,2\n", "line 3: t = 0 s does not increase"),
            ("t,x\n", "no frame with a position"),
            ("#multi:\nt x y\n", "track names"),
        ];
        for (text, want) in bad {
            let e = read(text, &Reading::default()).unwrap_err().to_string();
            assert!(e.contains(want), "{e} / {want}");
        }
        let named = Reading {
            centre: Some("mass C".into()),
            ..Reading::default()
        };
        let e = read("#multi:\n\tmass A\t\n t\tx\ty\n0\t1\t2\n", &named).unwrap_err();
        assert!(
            e.to_string().contains("no track 'mass C' for the centre"),
            "{e}"
        );
    }
}
