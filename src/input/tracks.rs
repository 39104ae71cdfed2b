//! Reading position tracks exported by video-analysis tools: Tracker's single-track
//! (track name, then `t x y …`) and multi-track (`#multi:`, track names, column names)
//! data files, and plain CSV/TSV with named columns. Finds the time, the ball's centre
//! and an optional rim mark by name, converts to SI, keeps empty cells as NaN. The
//! velocities are derived elsewhere (`study::track`); this module only reads.

use crate::input::data::{DataError, Reading, Sep, cells, clean, number, separator, unit_factor};
use crate::input::units::Dimension;

/// A position track in the file's own frame (origin, axis directions and time origin
/// as the user set them), SI units. Rows without a time are dropped; a missing cell
/// is NaN.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Track {
    /// Times, s, strictly increasing.
    pub t: Vec<f64>,
    /// The ball's centre, m.
    pub x: Vec<f64>,
    /// All NaN when the file has no y column for the centre.
    pub y: Vec<f64>,
    /// A mark on the ball's rim (x, y), m, when the file has one.
    pub mark: Option<(Vec<f64>, Vec<f64>)>,
    /// Name of the centre's track ("" for a plain `x, y` file).
    pub centre_name: String,
    pub mark_name: Option<String>,
    /// The format found: "Tracker multi-track", "Tracker single-track" or "CSV".
    pub format: &'static str,
}

/// One header cell of a position file: which track, which axis, its SI factor.
#[derive(Clone, Debug, PartialEq)]
struct Col {
    track: String,
    axis: Axis,
    factor: Option<f64>,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Axis {
    T,
    X,
    Y,
}

/// Reads a header cell such as `t`, `t/ms`, `x (cm)`, `mass A x`, `x_mark [mm]`,
/// `y_cm` (unit as suffix). `None` for other columns (`v_{x}`, `frame`, …) and for
/// a unit that does not fit the axis.
fn position_column(cell: &str) -> Option<Col> {
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
    let axis_of = |t: &str| match t {
        "t" | "time" => Some(Axis::T),
        "x" => Some(Axis::X),
        "y" => Some(Axis::Y),
        _ => None,
    };
    let mut axes = tokens
        .iter()
        .enumerate()
        .filter_map(|(i, t)| axis_of(t).map(|a| (i, a)));
    let (at, axis) = axes.next()?;
    if axes.next().is_some() {
        return None;
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
    let mut factor = unit_factor(unit, dim)?;
    // `x_cm`, `t_s`: a trailing unit token rather than a track name.
    if factor.is_none()
        && rest.len() == 1
        && let Some(Some(f)) = unit_factor(rest[0], dim)
    {
        factor = Some(f);
        rest.clear();
    }
    Some(Col {
        track: rest.join(" "),
        axis,
        factor,
    })
}

/// Names that say "the centre" or "the mark" when no option does.
const CENTRE_NAMES: [&str; 6] = ["centre", "center", "ball", "cm", "c", "mass a"];
const MARK_NAMES: [&str; 5] = ["mark", "rim", "spot", "m", "mass b"];

fn same(a: &str, b: &str) -> bool {
    let norm = |s: &str| s.to_lowercase().replace([' ', '_'], "");
    norm(a) == norm(b)
}

/// Parses a position file (see the module doc) into a [`Track`] in SI units.
pub fn parse(text: &str, file: &str, reading: &Reading) -> Result<Track, DataError> {
    let err = |what: String| DataError {
        file: file.to_string(),
        what,
    };
    let mut lines = text
        .lines()
        .enumerate()
        .filter(|(_, l)| !l.trim().is_empty());
    // Up to three lines before the column header: `#multi:`, track names, or the
    // single track's name.
    let mut before: Vec<(usize, &str)> = Vec::new();
    let (header_no, header) = loop {
        let Some((n, line)) = lines.next() else {
            return Err(err(
                "no header with a time column t found, expected columns t and x (and y), or t, v_cm and v_t"
                    .into(),
            ));
        };
        let sep = separator(line);
        let has_t = cells(line, sep)
            .iter()
            .any(|c| position_column(c).is_some_and(|c| c.axis == Axis::T));
        if has_t {
            break (n, line);
        }
        if before.len() == 3 {
            return Err(err(format!(
                "line {}: no header with a time column t in the first lines, expected columns t and x (and y)",
                n + 1
            )));
        }
        before.push((n, line));
    };
    let sep = separator(header);
    let head = cells(header, sep);
    let multi = before
        .first()
        .is_some_and(|(_, l)| l.trim_start().to_lowercase().starts_with("#multi"));
    let mut cols: Vec<Option<Col>> = head.iter().map(|c| position_column(c)).collect();
    let format = if multi {
        // The names line puts each track's name above its first column.
        let Some((n, names)) = before.get(1) else {
            return Err(err(
                "a '#multi:' file needs a line of track names before the column names".into(),
            ));
        };
        if sep == Sep::Space {
            return Err(err(format!(
                "line {}: a multi-track file must be tab, comma or semicolon separated (Tracker writes tabs)",
                n + 1
            )));
        }
        let names = cells(names, sep);
        let mut current = String::new();
        for (j, col) in cols.iter_mut().enumerate() {
            let name = names
                .get(j)
                .map(|s| s.trim().trim_matches('"'))
                .unwrap_or("");
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
        "Tracker multi-track"
    } else if let Some((_, name)) = before.last() {
        // Tracker's single-track export: the track's name above the header.
        let name = name.trim().trim_matches('"').to_string();
        for c in cols.iter_mut().flatten() {
            if c.axis != Axis::T && c.track.is_empty() {
                c.track = name.clone();
            }
        }
        "Tracker single-track"
    } else {
        "CSV"
    };
    let found: Vec<String> = head
        .iter()
        .map(|c| c.trim().to_string())
        .filter(|c| !c.is_empty())
        .collect();
    let it = cols
        .iter()
        .position(|c| c.as_ref().is_some_and(|c| c.axis == Axis::T))
        .expect("the header has a t column");
    // Tracks with an x column, in file order.
    let mut names: Vec<String> = Vec::new();
    for c in cols.iter().flatten() {
        if c.axis == Axis::X && !names.contains(&c.track) {
            names.push(c.track.clone());
        }
    }
    if names.is_empty() {
        return Err(err(format!(
            "line {}: no position column x in '{}', expected t and x (and y) for a position track, or t, v_cm and v_t for velocities",
            header_no + 1,
            found.join(" ")
        )));
    }
    let pick = |want: &Option<String>,
                defaults: &[&str],
                role: &str|
     -> Result<Option<String>, DataError> {
        match want {
            Some(w) => names
                .iter()
                .find(|n| same(n, w))
                .cloned()
                .map(Some)
                .ok_or_else(|| {
                    err(format!(
                        "no track '{w}' for the {role} in the file, tracks found: {}",
                        names
                            .iter()
                            .map(|n| if n.is_empty() {
                                "(unnamed)"
                            } else {
                                n.as_str()
                            })
                            .collect::<Vec<_>>()
                            .join(", ")
                    ))
                }),
            None => Ok(names
                .iter()
                .find(|n| defaults.iter().any(|d| same(n, d)))
                .cloned()),
        }
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
        return Err(err("the mark and the centre name the same track".into()));
    }
    let index = |track: &str, axis: Axis| {
        cols.iter().position(|c| {
            c.as_ref()
                .is_some_and(|c| c.axis == axis && c.track == track)
        })
    };
    let factor = |i: usize, unit: Option<f64>| {
        cols[i]
            .as_ref()
            .and_then(|c| c.factor)
            .or(unit)
            .unwrap_or(1.0)
    };
    let ix = index(&centre, Axis::X).expect("the centre has an x column");
    let iy = index(&centre, Axis::Y);
    let im = match &mark {
        Some(m) => match (index(m, Axis::X), index(m, Axis::Y), iy) {
            (Some(a), Some(b), Some(_)) => Some((a, b)),
            _ if reading.mark.is_some() => {
                return Err(err(format!(
                    "the mark '{m}' needs x and y columns, and the centre a y column, to give the spin angle"
                )));
            }
            _ => None,
        },
        None => None,
    };
    let ft = factor(it, reading.time_unit);
    let fl = |i: usize| factor(i, reading.length_unit);
    let mut track = Track {
        centre_name: centre.clone(),
        mark_name: im.and(mark.clone()),
        format,
        mark: im.map(|_| (Vec::new(), Vec::new())),
        ..Track::default()
    };
    for (n, line) in lines {
        if line.trim_start().starts_with('#') {
            continue;
        }
        let row = cells(line, sep);
        let cell = |i: usize| row.get(i).map_or("", |c| c.trim());
        let value = |i: usize, name: &str| -> Result<f64, DataError> {
            let c = cell(i);
            if c.is_empty() {
                return Ok(f64::NAN);
            }
            number(c).ok_or_else(|| {
                err(format!(
                    "line {}: {name} = '{c}' is not a finite number (an empty cell counts as missing)",
                    n + 1
                ))
            })
        };
        let time = value(it, "t")?;
        if time.is_nan() {
            continue;
        }
        let time = time * ft;
        if let Some(&prev) = track.t.last()
            && time <= prev
        {
            return Err(err(format!(
                "line {}: t = {time} s does not increase (previous {prev} s), allowed strictly increasing times",
                n + 1
            )));
        }
        track.t.push(time);
        track.x.push(value(ix, "x")? * fl(ix));
        track.y.push(match iy {
            Some(i) => value(i, "y")? * fl(i),
            None => f64::NAN,
        });
        if let (Some((a, b)), Some((mx, my))) = (im, track.mark.as_mut()) {
            mx.push(value(a, "mark x")? * fl(a));
            my.push(value(b, "mark y")? * fl(b));
        }
    }
    if track.x.iter().filter(|x| x.is_finite()).count() == 0 {
        return Err(err(format!(
            "no frame with a position x of '{}', expected rows of numbers below the header",
            if centre.is_empty() { "x" } else { &centre }
        )));
    }
    Ok(track)
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
        assert_eq!(t.format, "Tracker single-track");
        assert_eq!(t.centre_name, "mass A");
        assert_eq!(t.t, vec![0.0, 0.032, 0.064]);
        assert!(t.x[1].is_nan());
        assert_eq!(t.x[2], 0.12);
        assert!(t.mark.is_none());
    }

    #[test]
    fn tracker_multi_track_names_centre_and_mark() {
        let text =
            "#multi:\n\tmass A\t\tmass B\t\n t\tx\ty\tx\ty\n0\t1\t2\t1\t2,5\n0,01\t1,1\t2\t\t\n";
        let t = read(text, &Reading::default()).unwrap();
        assert_eq!(t.format, "Tracker multi-track");
        assert_eq!(t.centre_name, "mass A");
        assert_eq!(t.mark_name.as_deref(), Some("mass B"));
        let (mx, my) = t.mark.unwrap();
        assert_eq!(my[0], 2.5);
        assert!(mx[1].is_nan());
        assert_eq!(t.t[1], 0.01);
        // Named the other way round by options.
        let swapped = Reading {
            centre: Some("mass b".into()),
            mark: Some("mass A".into()),
            ..Reading::default()
        };
        let t = read(text, &swapped).unwrap();
        assert_eq!(t.x[0], 1.0);
        assert_eq!(t.y[0], 2.5);
    }

    #[test]
    fn csv_with_units_semicolons_and_decimal_commas() {
        let text = "t/ms;x (cm);y (cm);x_mark (cm);y_mark (cm)\n0;1,5;0;1,5;2\n10;2,5;0;2,5;2\n";
        let t = read(text, &Reading::default()).unwrap();
        assert_eq!(t.format, "CSV");
        assert_eq!(t.t, vec![0.0, 0.01]);
        assert!((t.x[1] - 0.025).abs() < 1e-15);
        assert_eq!(t.mark_name.as_deref(), Some("mark"));
        // Units from options where the header has none.
        let text = "t,x\n0,1\n20,2\n";
        let r = Reading {
            time_unit: Some(1e-3),
            length_unit: Some(1e-2),
            ..Reading::default()
        };
        let t = read(text, &r).unwrap();
        assert_eq!((t.t[1], t.x[1]), (0.02, 0.02));
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
