//! Reading a user's measured series (CSV from video-analysis tools): columns found by
//! header, comma, semicolon or tab separated, decimal commas tolerated, units from the
//! header or given, and the time origin moved to the first impact. Velocity files are
//! read here; position tracks by `input::tracks`, which shares the cell, number and
//! unit helpers below. [`read`] tells the two kinds apart.

use crate::input::tracks::{self, Track};
use crate::input::units::{self, Dimension};

/// Most data rows a file may have: far more than a video gives (a minute at 1000
/// frames/s is 60,000), and a bound on the memory and time a fit can take.
pub const MAX_ROWS: usize = 1_000_000;

/// A measured series of the left ball: time (s, first impact at 0), v_cm and v_t (m/s).
///
/// Velocity files fill `t`, `v_cm` and `v_t` only. A series derived from a position
/// track (`study::track`) also carries each derived point's standard uncertainty and
/// the tracked positions; its `v_t` is NaN where no rim mark was tracked.
#[derive(Clone, Debug, Default, PartialEq, serde::Serialize)]
pub struct Measured {
    pub t: Vec<f64>,
    pub v_cm: Vec<f64>,
    pub v_t: Vec<f64>,
    /// Standard uncertainty of each `v_cm`, m/s (from the local fit's residuals).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub v_cm_sigma: Option<Vec<f64>>,
    /// Standard uncertainty of each `v_t`, m/s (NaN where `v_t` is).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub v_t_sigma: Option<Vec<f64>>,
    /// The tracked centre, m: its displacement from where it was at the first impact,
    /// positive toward the other ball (the model's left ball is at `x − R`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub x: Option<Vec<f64>>,
    /// The rim mark's angle about the centre, rad, from its angle at the first impact,
    /// signed like the spin (`d angle/dt · r = v_t`); NaN where the mark is missing.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub angle: Option<Vec<f64>>,
}

impl Measured {
    /// A velocity series without uncertainties or positions.
    pub fn velocities(t: Vec<f64>, v_cm: Vec<f64>, v_t: Vec<f64>) -> Measured {
        Measured {
            t,
            v_cm,
            v_t,
            ..Measured::default()
        }
    }

    /// A lab measurement's numbers stay within lab sizes: times within ±1e6 s, speeds
    /// within ±1000 m/s, positions within ±1000 m (NaN marks a missing value). Beyond
    /// them a series is not a measurement of this experiment, and squares of its
    /// numbers (residuals, energies) would overflow.
    pub fn check_magnitudes(&self) -> Result<(), String> {
        let series: [(&str, Option<&[f64]>, f64, &str); 5] = [
            ("t", Some(&self.t), 1e6, "1e6 s"),
            ("v_cm", Some(&self.v_cm), 1e3, "1000 m/s"),
            ("v_t", Some(&self.v_t), 1e3, "1000 m/s"),
            ("x", self.x.as_deref(), 1e3, "1000 m"),
            ("angle", self.angle.as_deref(), 1e9, "1e9 rad"),
        ];
        for (name, values, limit, text) in series {
            if let Some((i, v)) = values
                .into_iter()
                .flatten()
                .enumerate()
                .find(|(_, v)| v.abs() > limit)
            {
                return Err(format!(
                    "{name} = {v:e} (point {}) is out of range, allowed |{name}| ≤ {text}",
                    i + 1
                ));
            }
        }
        Ok(())
    }

    /// True when at least one v_t was measured (a velocity file, or a track with a mark).
    pub fn has_v_t(&self) -> bool {
        self.v_t.iter().any(|v| v.is_finite())
    }
}

/// Why a data file cannot be used; each message names the line.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error("{file}: {what}")]
pub struct DataError {
    pub file: String,
    pub what: String,
}

/// How to read a file beyond what its header says.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Reading {
    /// Seconds per time unit of the file, when the header does not say (1 = s).
    pub time_unit: Option<f64>,
    /// m/s per speed unit of the file, when the header does not say.
    pub speed_unit: Option<f64>,
    /// Metres per length unit of a position file, when the header does not say.
    pub length_unit: Option<f64>,
    /// Time of the first impact in the file's time (after units); detected if absent.
    pub impact_at: Option<f64>,
    /// Which track (Tracker) or column prefix holds the ball's centre, e.g. "mass A"
    /// [default: a track named centre/center/ball, else the first].
    pub centre: Option<String>,
    /// Which track holds the mark on its rim, e.g. "mass B" [default: a track named
    /// mark/rim/spot, else the second; none: v_t is not measured].
    pub mark: Option<String>,
}

/// What a data file holds.
#[derive(Clone, Debug, PartialEq)]
pub enum Series {
    /// Velocities (t, v_cm, v_t), impact at t = 0.
    Velocities(Measured),
    /// Positions of the centre (and a rim mark) in the file's frame, SI units; the
    /// velocities are derived by `study::track` (they need the scene's contact radius).
    Positions(Track),
}

/// Reads `text` (the file named `file`): a velocity file when its header names t, v_cm
/// and v_t, else a position track (Tracker export or CSV/TSV with t, x, y).
pub fn read(text: &str, file: &str, reading: &Reading) -> Result<Series, DataError> {
    let header = text
        .lines()
        .find(|l| !l.trim().is_empty() && !l.trim_start().starts_with('#'));
    let names: Vec<&'static str> = header
        .map(|h| {
            cells(h, separator(h))
                .iter()
                .filter_map(|c| column(c).map(|(n, _)| n))
                .collect()
        })
        .unwrap_or_default();
    if names.contains(&"v_cm") {
        parse(text, file, reading).map(Series::Velocities)
    } else {
        tracks::parse(text, file, reading).map(Series::Positions)
    }
}

/// How the cells of a line are separated.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Sep {
    Tab,
    Semicolon,
    Comma,
    /// Runs of spaces (Tracker's space-separated export).
    Space,
}

/// The separator a header line uses: tabs, else semicolons (then commas are decimal
/// commas), else commas, else spaces.
pub(crate) fn separator(line: &str) -> Sep {
    if line.contains('\t') {
        Sep::Tab
    } else if line.contains(';') {
        Sep::Semicolon
    } else if line.contains(',') {
        Sep::Comma
    } else {
        Sep::Space
    }
}

/// The cells of `line`; with tabs, semicolons and commas an empty cell stays a cell.
pub(crate) fn cells(line: &str, sep: Sep) -> Vec<&str> {
    let line = line.trim_end_matches(['\r', '\n']);
    match sep {
        Sep::Tab => line.split('\t').collect(),
        Sep::Semicolon => line.split(';').collect(),
        Sep::Comma => line.split(',').collect(),
        Sep::Space => line.split_whitespace().collect(),
    }
}

/// A header cell in lower case, without quotes and surrounding blanks.
pub(crate) fn clean(cell: &str) -> String {
    cell.trim().trim_matches('"').trim().to_lowercase()
}

/// The SI factor of a unit written after a column name: `(ms)`, `[cm/s]`, `/ms`,
/// `_m_per_s`; `Some(None)` when there is none, `None` when it is not a unit of `dim`.
pub(crate) fn unit_factor(rest: &str, dim: Dimension) -> Option<Option<f64>> {
    let unit = rest
        .trim()
        .trim_start_matches(['_', '(', '[', '/', ' '])
        .trim_end_matches([')', ']', ' '])
        .replace("_per_", "/");
    if unit.is_empty() {
        return Some(None);
    }
    // Only a unit name counts: `t2`, `t_1` or `time0` are other columns, not times in
    // units of 12, 11 or 10 s.
    units::unit_factor(&unit, dim).ok().map(Some)
}

/// Which quantity a velocity-file header cell names, and the SI factor its unit implies.
fn column(header: &str) -> Option<(&'static str, Option<f64>)> {
    let h = clean(header).replace(' ', "");
    let (name, rest) = if let Some(r) = h.strip_prefix("v_cm").or(h.strip_prefix("vcm")) {
        ("v_cm", r)
    } else if let Some(r) = h.strip_prefix("v_t").or(h.strip_prefix("vt")) {
        ("v_t", r)
    } else if let Some(r) = h.strip_prefix("time").or(h.strip_prefix('t')) {
        ("t", r)
    } else {
        return None;
    };
    // A unit in brackets ("t (ms)", "v_cm [cm/s]") or as a suffix ("t_s",
    // "v_cm_m_per_s", "v_t_cm_per_s").
    let dim = if name == "t" {
        Dimension::Time
    } else {
        Dimension::Speed
    };
    unit_factor(rest, dim).map(|f| (name, f))
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

/// Parses `text` (the file named `file`) into a series with the impact at t = 0.
pub fn parse(text: &str, file: &str, reading: &Reading) -> Result<Measured, DataError> {
    let err = |what: String| DataError {
        file: file.to_string(),
        what,
    };
    // Spreadsheets often start a UTF-8 file with a byte-order mark.
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let mut lines = text
        .lines()
        .enumerate()
        .filter(|(_, l)| !l.trim().is_empty() && !l.trim_start().starts_with('#'));
    let (_, header) = lines
        .next()
        .ok_or_else(|| err("the file is empty, expected a header with t, v_cm and v_t".into()))?;
    // Semicolons win over commas: then commas are decimal commas.
    let sep = separator(header);
    let head = cells(header, sep);
    let find = |want: &str| {
        head.iter()
            .enumerate()
            .find_map(|(i, c)| column(c).filter(|(n, _)| *n == want).map(|(_, f)| (i, f)))
    };
    let missing = |name: &str| {
        err(format!(
            "line 1: no column '{name}' in the header '{}', expected columns t, v_cm and v_t (units in brackets or as options)",
            header.trim()
        ))
    };
    let (it, ft) = find("t").ok_or_else(|| missing("t"))?;
    let (ic, fc) = find("v_cm").ok_or_else(|| missing("v_cm"))?;
    let (iv, fv) = find("v_t").ok_or_else(|| missing("v_t"))?;
    let ft = ft.or(reading.time_unit).unwrap_or(1.0);
    let fc = fc.or(reading.speed_unit).unwrap_or(1.0);
    let fv = fv.or(reading.speed_unit).unwrap_or(1.0);
    let (mut t, mut v_cm, mut v_t) = (Vec::new(), Vec::new(), Vec::new());
    for (n, line) in lines {
        if t.len() == MAX_ROWS {
            return Err(err(format!(
                "line {}: more than {MAX_ROWS} data rows, allowed at most {MAX_ROWS}",
                n + 1
            )));
        }
        let row = cells(line, sep);
        let get = |i: usize, name: &str| {
            let cell = row.get(i).copied().unwrap_or("");
            number(cell).ok_or_else(|| {
                err(format!(
                    "line {}: {name} = '{}' is not a finite number",
                    n + 1,
                    cell.trim()
                ))
            })
        };
        let time = get(it, "t")? * ft;
        if let Some(&prev) = t.last()
            && time <= prev
        {
            return Err(err(format!(
                "line {}: t = {time} s does not increase (previous {prev} s), allowed strictly increasing times",
                n + 1
            )));
        }
        t.push(time);
        v_cm.push(get(ic, "v_cm")? * fc);
        v_t.push(get(iv, "v_t")? * fv);
    }
    if t.len() < 3 {
        return Err(err(format!("{} data rows, allowed at least 3", t.len())));
    }
    let impact = match reading.impact_at {
        Some(at) => at,
        None => detect_impact(&t, &v_cm).ok_or_else(|| {
            err("no impact found (v_cm never drops sharply); give its time with --impact-at".into())
        })?,
    };
    for x in &mut t {
        *x -= impact;
    }
    // Huge but finite values can still overflow once scaled or shifted.
    for (name, series) in [("t", &t), ("v_cm", &v_cm), ("v_t", &v_t)] {
        if let Some(i) = series.iter().position(|v| !v.is_finite()) {
            return Err(err(format!(
                "data row {}: {name} is not finite once in SI units with the impact at t = 0, allowed finite values",
                i + 1
            )));
        }
    }
    let m = Measured::velocities(t, v_cm, v_t);
    m.check_magnitudes().map_err(err)?;
    Ok(m)
}

/// The first impact: where v_cm drops the most between neighbouring frames (the left
/// ball reverses), if the drop is at least a third of the speed before it. When the
/// drop is spread over two frames, the frame in between straddles the impact (the
/// paper's convention) and is the impact time; otherwise the impact is put mid-way.
pub fn detect_impact(t: &[f64], v_cm: &[f64]) -> Option<f64> {
    let drops: Vec<f64> = v_cm.windows(2).map(|w| w[0] - w[1]).collect();
    let (i, &drop) = drops.iter().enumerate().max_by(|a, b| a.1.total_cmp(b.1))?;
    if drop <= 0.0 || drop < v_cm[i].abs().max(v_cm[i + 1].abs()) / 3.0 {
        return None;
    }
    let big = |j: Option<usize>| {
        j.and_then(|j| drops.get(j))
            .is_some_and(|&d| d >= drop / 3.0)
    };
    Some(if big(i.checked_sub(1)) {
        t[i]
    } else if big(Some(i + 1)) {
        t[i + 1]
    } else {
        0.5 * (t[i] + t[i + 1])
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reads_the_shared_format_and_finds_the_impact() {
        let text = "t_s,v_cm_m_per_s,v_t_m_per_s\n-0.02,0.79,0.78\n0,0.0925,0.78\n0.02,-0.64,0.70\n0.04,-0.63,0.68\n";
        let m = parse(text, "x.csv", &Reading::default()).unwrap();
        assert_eq!(m.t, vec![-0.02, 0.0, 0.02, 0.04]);
        assert_eq!(m.v_cm[2], -0.64);
    }

    #[test]
    fn semicolons_decimal_commas_and_units_in_brackets() {
        let text = "time (ms);v_cm (cm/s);v_t [cm/s]\n0;79,5;78\n10;80;78\n20;9;78\n30;-64;70\n";
        let m = parse(text, "x.csv", &Reading::default()).unwrap();
        // Impact in the frame at 20 ms (v_cm mid-way): that becomes t = 0.
        assert!((m.t[0] + 0.02).abs() < 1e-12, "{:?}", m.t);
        assert!((m.v_cm[0] - 0.795).abs() < 1e-12);
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
        assert_eq!(m.t, vec![-0.02, 0.0, 0.02, 0.04]);
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
            impact_at: Some(-1.7e308),
            ..Reading::default()
        };
        let e = parse("t,v_cm,v_t\n0,1,1\n1e308,1,1\n1.5e308,1,1\n", "d.csv", &r).unwrap_err();
        assert!(e.to_string().contains("not finite"), "{e}");
    }

    #[test]
    fn errors_name_the_line() {
        let bad = [
            ("t,v_cm\n0,1\n", "no column 'v_t'"),
            ("t,v_cm,v_t\n0,1,1\n0.01,x,1\n", "line 3: v_cm = 'x'"),
            ("t,v_cm,v_t\n0,1,1\n", "1 data rows"),
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
