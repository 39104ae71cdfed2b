//! Reading a velocity file (t, v_cm, v_t by header name, units from the header or
//! given): the direction of the motion found (a file recorded with x reversed is
//! turned), the time origin moved to the first impact, and numbers that are plainly
//! in other units than the header says named in the error.

use super::layout::LayoutError;
use super::misfit::Units;
use super::notes::Notes;
use super::options::{MAX_ROWS, Reading};
use super::problem::{
    DataError, DataProblem, FRAMES_BEFORE, ImpactOutside, RowError, TooFewBefore,
};
use super::table::{Table, TableRow, UnreadUnit, clean, header_unit, number, units_under};
use crate::settings::units::Dimension;
use crate::study::measured::{Measured, MeasuredParts};

/// Which quantity a velocity-file header cell names, and the SI factor its unit implies.
fn column(header: &str) -> Option<(&'static str, Option<f64>)> {
    named(header).and_then(|(name, unit)| unit.ok().map(|f| (name, f)))
}

/// [`column`], or the unit as written where one in brackets or after a slash is none
/// of the quantity's (`t (min)`, `v_cm [in/s]`).
fn named(header: &str) -> Option<(&'static str, Result<Option<f64>, UnreadUnit>)> {
    let h = clean(header).replace(' ', "");
    // The app's export and `simulate --format csv` name the model's left ball (the
    // one measured) `v_left` and `u_left`.
    let (name, rest) = if let Some(r) = h
        .strip_prefix("v_cm")
        .or(h.strip_prefix("vcm"))
        .or(h.strip_prefix("v_left"))
    {
        ("v_cm", r)
    } else if let Some(r) = h.strip_prefix("u_left") {
        ("v_t", r)
    } else if let Some(r) = h.strip_prefix("v_t").or(h.strip_prefix("vt")) {
        ("v_t", r)
    } else if let Some(r) = h.strip_prefix("time").or(h.strip_prefix('t')) {
        ("t", r)
    } else {
        return None;
    };
    // A unit in brackets ("t (ms)", "v_cm [cm/s]") or as a suffix ("t_s",
    // "v_cm_m_per_s", "v_t_cm_per_s"); a suffix not a unit is another name
    // ("temperature", "v_t7").
    let dim = if name == "t" {
        Dimension::Time
    } else {
        Dimension::Speed
    };
    match header_unit(rest, dim) {
        Err(_) if !rest.starts_with(['(', '[', '/']) => None,
        unit => Some((name, unit)),
    }
}

/// The error naming the header's cell of column `want` whose unit is none of its
/// quantity's, if it has one.
fn unknown_unit(header: &TableRow, want: &str) -> Option<DataProblem> {
    (0..header.len()).find_map(|i| match named(header.cell(i)) {
        Some((name, Err(UnreadUnit { unit, dim }))) if name == want => Some(
            LayoutError::UnknownUnit {
                line: header.line,
                cell: header.cell(i).to_string(),
                unit,
                dim,
            }
            .into(),
        ),
        _ => None,
    })
}

/// True when a header cell names v_cm: the file holds velocities.
pub(super) fn names_v_cm(cell: &str) -> bool {
    named(cell).is_some_and(|(n, _)| n == "v_cm")
}

#[cfg(test)]
/// Parses `text` (the file named `file`) into a series with the impact at t = 0,
/// moving toward the other ball (+x) before it.
pub fn parse(text: &str, file: &str, reading: &Reading) -> Result<Measured, DataError> {
    read_table(&Table::new(text), file, reading).map(|(m, _)| m)
}

/// A velocity table's t, v_cm and v_t, SI.
type VelocityColumns = (Vec<f64>, Vec<f64>, Vec<f64>);

/// The columns t, v_cm and v_t of a velocity table in SI units, as the file has
/// them (no impact sought), and how their units were decided.
fn columns(
    table: &Table,
    file: &str,
    reading: &Reading,
) -> Result<(VelocityColumns, Units), DataError> {
    let err = |what: DataProblem| DataError::new(file, what);
    let mut rows = table.rows().peekable();
    let header = rows.next().ok_or_else(|| err(DataProblem::Empty))?;
    let header = units_under(header, &mut rows);
    let find = |want: &str| {
        (0..header.len()).find_map(|i| {
            column(header.cell(i))
                .filter(|(n, _)| *n == want)
                .map(|(_, f)| (i, f))
        })
    };
    let missing = |name: &'static str| {
        err(
            unknown_unit(&header, name).unwrap_or_else(|| DataProblem::NoColumn {
                line: header.line,
                name,
                header: (0..header.len())
                    .map(|i| header.cell(i).to_string())
                    .collect(),
            }),
        )
    };
    let (it, ft) = find("t").ok_or_else(|| missing("t"))?;
    let (ic, fc) = find("v_cm").ok_or_else(|| missing("v_cm"))?;
    let (iv, fv) = find("v_t").ok_or_else(|| missing("v_t"))?;
    let units = Units::decide(reading, ft, fc, fv);
    let (mut t, mut v_cm, mut v_t) = (Vec::new(), Vec::new(), Vec::new());
    // The last time, as written (an error quotes it).
    let mut prev = String::new();
    for row in rows {
        if t.len() == MAX_ROWS {
            return Err(err(RowError::TooMany { line: row.line }.into()));
        }
        if let Some(e) = RowError::wider(&row, &header, table.sep) {
            return Err(err(e.into()));
        }
        let get = |i: usize, name: &'static str| {
            let cell = row.cell(i);
            number(cell).ok_or_else(|| {
                err(DataProblem::NotANumber {
                    line: row.line,
                    name,
                    cell: cell.to_string(),
                })
            })
        };
        let time = get(it, "t")? * units.time.0;
        if t.last().is_some_and(|&last| time <= last) {
            let e = RowError::not_increasing(row.line, row.cell(it), &prev, units.time.0);
            return Err(err(e.into()));
        }
        prev.clear();
        prev.push_str(row.cell(it));
        t.push(time);
        v_cm.push(get(ic, "v_cm")? * units.v_cm.0);
        v_t.push(get(iv, "v_t")? * units.v_t.0);
    }
    if t.len() < 3 {
        return Err(err(DataProblem::TooFewRows { rows: t.len() }));
    }
    Ok(((t, v_cm, v_t), units))
}

/// A velocity table read as the file has it, its times not moved (for `data` on a
/// file with no impact in it: a single ball's velocities).
pub(super) fn without_impact(
    table: &Table,
    file: &str,
    reading: &Reading,
) -> Result<(Measured, Notes), DataError> {
    let ((t, v_cm, v_t), units) = columns(table, file, reading)?;
    units
        .check_plausible(&t, &v_cm, &v_t)
        .map_err(|e| DataError::new(file, e))?;
    let notes = Notes {
        cut_row: None,
        impact_in_file: None,
        format: "table (t, v_cm, v_t)".into(),
        tracks: Vec::new(),
        units: units.notes(),
    };
    let m = Measured::velocities(t, v_cm, v_t)
        .map_err(|e| DataError::new(file, DataProblem::from(e)))?;
    Ok((m, notes))
}

/// [`parse`] of a file already split into rows, with what the file said about its
/// units ([`Notes`]).
pub(super) fn read_table(
    table: &Table,
    file: &str,
    reading: &Reading,
) -> Result<(Measured, Notes), DataError> {
    let err = |what: DataProblem| DataError::new(file, what);
    let ((mut t, mut v_cm, mut v_t), units) = columns(table, file, reading)?;
    let end = |v: Option<&f64>| v.copied().unwrap_or(f64::NAN);
    let (first, last) = (end(t.first()), end(t.last()));
    if let Some(at) = reading.impact_at
        && !(first..=last).contains(&at)
    {
        return Err(err(ImpactOutside { at, first, last }.into()));
    }
    let mirrored = turn_if_reversed(&t, &mut v_cm, &mut v_t, reading.impact_at);
    let impact = match reading.impact_at {
        Some(at) => at,
        None => detect_impact(&t, &v_cm).ok_or_else(|| err(DataProblem::NoImpact))?,
    };
    let spin_turned = turn_spin_if_opposite(&t, &v_cm, &mut v_t, impact);
    for x in &mut t {
        *x -= impact;
    }
    // Huge but finite values can still overflow once scaled or shifted.
    for (name, series) in [("t", &t), ("v_cm", &v_cm), ("v_t", &v_t)] {
        if let Some(i) = series.iter().position(|v| !v.is_finite()) {
            return Err(err(DataProblem::NotFiniteInSi { row: i + 1, name }));
        }
    }
    approach_seen(&t, impact).map_err(|e| err(e.into()))?;
    let m = Measured::new(MeasuredParts {
        t,
        v_cm,
        v_t,
        mirrored,
        spin_turned,
        ..MeasuredParts::default()
    })
    .map_err(|e| err(e.into()))?;
    m.check_magnitudes().map_err(|e| err(e.into()))?;
    units
        .check_plausible(m.t(), m.v_cm(), m.v_t())
        .map_err(|e| err(e.into()))?;
    let notes = Notes {
        cut_row: None,
        impact_in_file: Some(impact),
        format: "table (t, v_cm, v_t)".into(),
        tracks: Vec::new(),
        units: units.notes(),
    };
    Ok((m, notes))
}

/// A v_t signed the other way round from v_cm (a spin counted by the right-hand rule,
/// not as the contact point's speed): turned, v_t → −v_t, when before the impact
/// `impact`, while the ball rolls with v_t = v_cm, the median of v_t/v_cm over the
/// frames moving at over a third of the fastest lies between −1.5 and −0.5; true when
/// it was (said to the user).
fn turn_spin_if_opposite(t: &[f64], v_cm: &[f64], v_t: &mut [f64], impact: f64) -> bool {
    // (v_cm, v_t) of the frames before the impact with both.
    let before: Vec<(f64, f64)> = t
        .iter()
        .zip(v_cm.iter().zip(v_t.iter()))
        .filter(|(t, (c, s))| **t < impact && c.is_finite() && s.is_finite())
        .map(|(_, (c, s))| (*c, *s))
        .collect();
    let fastest = before.iter().map(|(c, _)| c.abs()).fold(0.0, f64::max);
    let mut ratios: Vec<f64> = before
        .iter()
        .filter(|(c, _)| c.abs() > fastest / 3.0)
        .map(|(c, s)| s / c)
        .collect();
    if ratios.len() < 3 {
        return false;
    }
    ratios.sort_by(f64::total_cmp);
    let turned = ratios
        .get(ratios.len() / 2)
        .is_some_and(|r| (-1.5..=-0.5).contains(r));
    if turned {
        v_t.iter_mut().for_each(|v| *v = -*v);
    }
    turned
}

/// A file recorded with x pointing away from the other ball: turned, so that the
/// ball approaches toward +x as in the model; true when it was (said to the user).
fn turn_if_reversed(t: &[f64], v_cm: &mut [f64], v_t: &mut [f64], impact_at: Option<f64>) -> bool {
    let reversed = approach_sign(t, v_cm, impact_at) < 0.0;
    if reversed {
        for v in v_cm.iter_mut().chain(v_t.iter_mut()) {
            *v = -*v;
        }
    }
    reversed
}

/// +1 when the ball approaches the other toward the file's +x, −1 when toward −x: the
/// sign of the mean v_cm before the impact (given), else before the largest jump of
/// v_cm between neighbouring frames, whichever way (the impact reverses the ball; a
/// recording that starts a few frames before it has most of its frames after).
fn approach_sign(t: &[f64], v_cm: &[f64], impact_at: Option<f64>) -> f64 {
    let n = match impact_at {
        Some(at) => t.partition_point(|&x| x < at),
        None => v_cm
            .iter()
            .zip(v_cm.iter().skip(1))
            .map(|(a, b)| (b - a).abs())
            .enumerate()
            .max_by(|a, b| a.1.total_cmp(&b.1))
            .map_or(1, |(i, _)| i + 1),
    };
    let sum: f64 = v_cm.iter().take(n.max(1)).sum();
    if sum < 0.0 { -1.0 } else { 1.0 }
}

/// At least [`FRAMES_BEFORE`] of the times `t` (impact at 0, `impact` in the file's
/// time) up to the impact; a frame that straddles it (the paper's convention) shows
/// the approach too.
fn approach_seen(t: &[f64], impact: f64) -> Result<(), TooFewBefore> {
    let before = t.partition_point(|&x| x <= 0.0);
    if before >= FRAMES_BEFORE {
        return Ok(());
    }
    Err(TooFewBefore { before, impact })
}

/// The first impact: where v_cm drops the most between neighbouring frames (the left
/// ball reverses), if the drop is at least a third of the speed before it. When the
/// drop is spread over two frames, the frame in between straddles the impact (the
/// paper's convention) and is the impact time; otherwise the impact is put mid-way.
pub fn detect_impact(t: &[f64], v_cm: &[f64]) -> Option<f64> {
    let drops: Vec<f64> = v_cm
        .iter()
        .zip(v_cm.iter().skip(1))
        .map(|(a, b)| a - b)
        .collect();
    let (i, &drop) = drops.iter().enumerate().max_by(|a, b| a.1.total_cmp(b.1))?;
    // A drop at i lies between frames i and i + 1, both in `t` and `v_cm`.
    let (&t0, &t1, &v0, &v1) = (t.get(i)?, t.get(i + 1)?, v_cm.get(i)?, v_cm.get(i + 1)?);
    if drop <= 0.0 || drop < v0.abs().max(v1.abs()) / 3.0 {
        return None;
    }
    let big = |j: Option<usize>| {
        j.and_then(|j| drops.get(j))
            .is_some_and(|&d| d >= drop / 3.0)
    };
    Some(if big(i.checked_sub(1)) {
        t0
    } else if big(Some(i + 1)) {
        t1
    } else {
        0.5 * (t0 + t1)
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reads_the_shared_format_and_finds_the_impact() {
        let text = "t_s,v_cm_m_per_s,v_t_m_per_s\n-0.02,0.79,0.78\n0,0.0925,0.78\n0.02,-0.64,0.70\n0.04,-0.63,0.68\n";
        let m = parse(text, "x.csv", &Reading::default()).unwrap();
        assert_eq!(m.t(), vec![-0.02, 0.0, 0.02, 0.04]);
        assert_eq!(m.v_cm()[2], -0.64);
        // One frame before an impact mid-way to the next: the approach is not seen.
        let text = "t,v_cm,v_t\n0,0.79,0.78\n0.02,-0.64,0.70\n0.04,-0.63,0.68\n";
        let e = parse(text, "x.csv", &Reading::default())
            .unwrap_err()
            .to_string();
        assert!(
            e.contains("only 1 frame before the impact at t = 0.01 s, at least 2 needed"),
            "{e}"
        );
    }

    #[test]
    fn a_recording_that_starts_just_before_the_impact_keeps_its_direction() {
        // Two frames of approach, then many of the roll back: the direction is the
        // approach's, not that of most frames.
        let mut text = String::from("t,v_cm,v_t\n-0.02,0.5,0.5\n-0.01,0.5,0.5\n");
        for i in 0..20 {
            text += &format!(
                "{},{},0.4\n",
                f64::from(i) * 0.01,
                -0.3 + 0.01 * f64::from(i)
            );
        }
        let m = parse(&text, "x.csv", &Reading::default()).unwrap();
        assert_eq!(m.v_cm()[0], 0.5, "not turned");
        assert!((m.t()[0] + 0.015).abs() < 1e-12, "{:?}", &m.t()[..3]);
    }

    #[test]
    fn semicolons_decimal_commas_and_units_in_brackets() {
        let text = "time (ms);v_cm (cm/s);v_t [cm/s]\n0;79,5;78\n10;80;78\n20;9;78\n30;-64;70\n";
        let m = parse(text, "x.csv", &Reading::default()).unwrap();
        // Impact in the frame at 20 ms (v_cm mid-way): that becomes t = 0.
        assert!((m.t()[0] + 0.02).abs() < 1e-12, "{:?}", m.t());
        assert!((m.v_cm()[0] - 0.795).abs() < 1e-12);
    }

    #[test]
    fn digits_after_a_column_name_are_not_a_unit() {
        // Once `t2` meant "t in units of 12 s".
        for header in ["t2,v_cm,v_t", "t_1,v_cm,v_t", "time0,v_cm,v_t"] {
            let text = format!("{header}\n0,1,1\n0.01,1,1\n0.02,-1,1\n");
            let e = parse(&text, "d.csv", &Reading::default()).unwrap_err();
            assert!(e.to_string().contains("no column 't'"), "{header}: {e}");
        }
        assert_eq!(column("t_ms"), Some(("t", Some(1e-3))));
        assert_eq!(column("v_cm (cm/s)"), Some(("v_cm", Some(0.01))));
        assert_eq!(column("v_t7"), None);
        assert_eq!(column("t e5"), None);
    }

    #[test]
    fn a_byte_order_mark_is_ignored() {
        let text = "\u{feff}t_s,v_cm_m_per_s,v_t_m_per_s\n-0.02,0.79,0.78\n0,0.0925,0.78\n0.02,-0.64,0.70\n0.04,-0.63,0.68\n";
        let m = parse(text, "x.csv", &Reading::default()).unwrap();
        assert_eq!(m.t(), vec![-0.02, 0.0, 0.02, 0.04]);
    }

    #[test]
    fn row_limit_and_overflow_are_errors() {
        let mut text = String::from("t,v_cm,v_t\n");
        for i in 0..=MAX_ROWS {
            text.push_str(&format!("{i},1,1\n"));
        }
        let e = parse(&text, "d.csv", &Reading::default()).unwrap_err();
        assert!(e.to_string().contains("at most 1000000"), "{e}");
        let r = Reading {
            impact_at: Some(1.5e308),
            ..Reading::default()
        };
        let e = parse(
            "t,v_cm,v_t\n-1.7e308,1,1\n0,1,1\n1.5e308,1,1\n",
            "d.csv",
            &r,
        )
        .unwrap_err();
        assert!(e.to_string().contains("not finite"), "{e}");
        // An impact given outside the file's times names the option.
        let r = Reading {
            impact_at: Some(1e308),
            ..Reading::default()
        };
        let e = parse("t,v_cm,v_t\n0,1,1\n0.01,1,1\n0.02,1,1\n", "d.csv", &r).unwrap_err();
        assert!(
            e.to_string()
                .contains("--impact-at 1e308 s lies outside the file's times, t = 0 … 0.02 s"),
            "{e}"
        );
    }

    #[test]
    fn errors_name_the_line() {
        let bad = [
            ("t,v_cm\n0,1\n", "no column 'v_t'"),
            ("t,v_cm,v_t\n0,1,1\n0.01,x,1\n", "line 3: v_cm = 'x'"),
            ("t,v_cm,v_t\n0,1,1\n", "1 data row,"),
            (
                "t,v_cm,v_t\n0,1,1\n0.02,1,1\n0.01,1,1\n",
                "line 4: t = 0.01 s does not increase",
            ),
            ("t,v_cm,v_t\n0,1,1\n0.01,NaN,1\n0.02,1,1\n", "line 3"),
            ("", "empty"),
        ];
        for (text, want) in bad {
            let e = parse(text, "d.csv", &Reading::default()).unwrap_err();
            assert!(e.to_string().contains(want), "{e} / {want}");
        }
    }
}
