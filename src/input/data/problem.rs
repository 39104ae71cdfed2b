//! Why a data file cannot be used, as values: the line, the column, the unit, the
//! text the file has where it has it; the sentence is made only by `Display`, where
//! the error is printed. The readers' own errors that a `DataProblem` holds live here
//! too (the row, accelerations-only and approach errors), so that this file imports
//! no reader and every reader imports it.

use super::layout::LayoutError;
use super::misfit::Implausible;
use super::options::MAX_ROWS;
use super::roles::Swapped;
use super::scales::{ScaleError, TIMES, unit_name};
use super::table::{Sep, TableRow};
use super::xml::XmlError;
use crate::settings::params::{Key, PARAMS};
use crate::settings::quote::clip;
use crate::settings::units::UnitError;
use crate::study::measured::{NoCommonFrame, OutOfLabRange, TrackError};

/// Why the data file `file` cannot be used; each message names the line.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error("{}: {what}", file.display())]
pub struct DataError {
    pub file: std::path::PathBuf,
    pub what: DataProblem,
}

impl DataError {
    /// `what` is wrong with the file named `file`.
    pub fn new(file: &str, what: impl Into<DataProblem>) -> DataError {
        DataError {
            file: file.into(),
            what: what.into(),
        }
    }
}

/// What is wrong with a data file (the file itself is named by `DataError`).
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum DataProblem {
    #[error(transparent)]
    Xml(#[from] XmlError),
    #[error(transparent)]
    Layout(#[from] LayoutError),
    #[error(transparent)]
    Row(#[from] RowError),
    #[error(transparent)]
    Scale(#[from] ScaleError),
    #[error(transparent)]
    AccelerationsOnly(#[from] AccelerationsOnly),
    #[error(transparent)]
    TooFewBefore(#[from] TooFewBefore),
    #[error(transparent)]
    OutOfLabRange(#[from] OutOfLabRange),
    #[error(transparent)]
    Implausible(#[from] Implausible),
    #[error(transparent)]
    NoCommonFrame(#[from] NoCommonFrame),
    #[error(transparent)]
    Track(#[from] TrackError),
    #[error(transparent)]
    Rule(#[from] crate::study::measured::Rule),
    #[error(transparent)]
    ImpactOutside(#[from] ImpactOutside),
    #[error(transparent)]
    Swapped(#[from] Swapped),
    #[error(
        "an XML file, but neither a Tracker project (.trk) nor a Logger Pro file (.cmbl), expected one of those or a table of t and x (and y), or t, v_cm and v_t"
    )]
    OtherXml,
    /// A position file's mark, by the name the option gave, without x and y.
    #[error(
        "the mark '{}' needs x and y columns, and the centre a y column, to give the spin angle",
        clip(mark)
    )]
    MarkWithoutXy { mark: String },
    /// No frame with a position of the centre's track (`centre`: its name, maybe empty).
    #[error(
        "no frame with a position x of '{}', expected rows of numbers below the header",
        clip(if centre.is_empty() { "x" } else { centre })
    )]
    NoPosition { centre: String },
    #[error("the file is empty, expected a header with t, v_cm and v_t")]
    Empty,
    /// A velocity file's header (its cells) without the column `name`.
    #[error(
        "line {line}: no column '{name}' in the header '{}', expected columns t, v_cm and v_t (units in brackets or as options)",
        clip(&header.join(" "))
    )]
    NoColumn {
        line: usize,
        name: &'static str,
        header: Vec<String>,
    },
    /// A velocity file's cell of column `name`, as written, is no finite number.
    #[error("line {line}: {name} = '{}' is not a finite number", clip(cell))]
    NotANumber {
        line: usize,
        name: &'static str,
        cell: String,
    },
    #[error("{rows} data row{}, allowed at least 3", if *rows == 1 { "" } else { "s" })]
    TooFewRows { rows: usize },
    #[error("no impact found (v_cm never drops sharply); give its time with --impact-at")]
    NoImpact,
    /// Data row `row` (from 1) of column `name` overflows once scaled or shifted.
    #[error(
        "data row {row}: {name} is not finite once in SI units with the impact at t = 0, allowed finite values"
    )]
    NotFiniteInSi { row: usize, name: &'static str },
    #[error("not a Tracker project: its root is not a TrackerPanel object")]
    NotTracker,
    #[error(
        "the project gives no frame duration (clipcontrol's delta_t): open it in Tracker and save it again"
    )]
    NoFrameDuration,
    #[error(
        "track '{}' has more than {max} frames, allowed at most {max}",
        clip(track),
        max = MAX_ROWS
    )]
    TooManyFrames { track: String },
    #[error(
        "the project has no point-mass track with marked frames: mark the ball's centre in Tracker (a point mass) and save"
    )]
    NoPointMass,
    #[error(
        "the video was not calibrated (the project's scale is 1 pixel per unit): its positions are pixels; calibrate it in Tracker (a calibration stick or tape of known length) and save, or give the length one pixel shows with --scale (e.g. --scale 1.105mm)"
    )]
    Uncalibrated,
    /// A Tracker project's length unit, as it names it.
    #[error(
        "the project's length unit '{}' is not one groovelab reads (m, cm, mm): give the unit of its numbers with --length-unit (e.g. --length-unit m)",
        clip(unit)
    )]
    ProjectUnit { unit: String },
    #[error("not a Logger Pro file: its root is not <Document>")]
    NotLoggerPro,
    /// A Logger Pro file without a data set of positions (`found`: its data sets).
    #[error(
        "no data set with a time and a position column (X, Position) that holds numbers; data sets found: {}: groovelab needs the positions of the ball's centre over time (a video analysis or a motion detector)",
        if found.is_empty() { "none".to_string() } else { clip(&found.join(", ")).to_string() }
    )]
    NoDataSet { found: Vec<String> },
    /// A Logger Pro data set whose positions have no unit, and the video's scale as
    /// the file states it.
    #[error(
        "the positions of data set '{}' have no unit: the video was not scaled in Logger Pro{}; set its scale in Logger Pro and save, or give the length one of the file's units shows with --scale (e.g. --scale 1.105mm), or their unit with --length-unit",
        clip(set),
        scale.as_ref().map(|s| format!(" ({s})")).unwrap_or_default()
    )]
    Unscaled {
        set: String,
        scale: Option<VideoScale>,
    },
    /// What is wrong in the Logger Pro data set `set`, read as a table whose header
    /// is line 1: its `line N` is the data set's row N − 1.
    #[error("data set '{}': {}", clip(set), rows_not_lines(&problem.to_string()))]
    InDataSet {
        set: String,
        problem: Box<DataProblem>,
    },
    /// A `# scene` comment line without `=` (`text`: the line, trimmed).
    #[error(
        "line {line}: '{}' is not a scene value, expected '# scene NAME = VALUE'",
        clip(text)
    )]
    NotSceneValue { line: usize, text: String },
    /// A `# scene` comment line naming no parameter of the scene.
    #[error(
        "line {line}: scene value '{}' is not a parameter, allowed {}",
        clip(name),
        scene_names()
    )]
    NotParameter { line: usize, name: String },
    /// A `# scene` comment line whose value does not read (`value`: as written).
    #[error("line {line}: scene {} = {}: {error}", key.name(), clip(value))]
    SceneValue {
        line: usize,
        key: Key,
        value: String,
        error: Box<UnitError>,
    },
}

/// A Logger Pro video's scale as its file states it: `actual` (in `unit`, empty when
/// it names none) per `pixels` of the movie.
#[derive(Clone, Debug, PartialEq)]
pub struct VideoScale {
    pub actual: String,
    pub unit: String,
    pub pixels: String,
}

impl std::fmt::Display for VideoScale {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let unit = if self.unit.is_empty() {
            "(no unit)"
        } else {
            &self.unit
        };
        write!(
            f,
            "its scale says {} {} per {} of the movie's distance",
            clip(&self.actual),
            clip(unit),
            clip(&self.pixels)
        )
    }
}

/// The names of the scene's parameters, as a `# scene` line may give them.
fn scene_names() -> String {
    let names: Vec<&str> = PARAMS
        .iter()
        .filter(|p| p.of_scene())
        .map(|p| p.name)
        .collect();
    names.join(", ")
}

/// A table error's `line N` (of the table made from a data set: the header is line 1)
/// as the data set's row N − 1.
fn rows_not_lines(what: &str) -> String {
    match what.strip_prefix("line ").and_then(|r| r.split_once(':')) {
        Some((n, rest)) if n.parse::<usize>().is_ok() => {
            format!(
                "row {}:{rest}",
                n.parse::<usize>().unwrap_or(1).saturating_sub(1)
            )
        }
        _ => what.to_string(),
    }
}

/// Why a data row of a position file cannot be read (`line`: the file's line).
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum RowError {
    #[error("line {line}: more than {MAX_ROWS} data rows, allowed at most {MAX_ROWS}")]
    TooMany { line: usize },
    /// The cell of column `name`, as written, is no finite number.
    #[error(
        "line {line}: {name} = '{}' is not a finite number (an empty cell counts as missing)",
        clip(cell)
    )]
    NotANumber {
        line: usize,
        name: &'static str,
        cell: String,
    },
    /// The time `time` and the one before it `prev` as the file writes them, in its
    /// time unit `unit` (none where it is no unit of [`TIMES`]).
    #[error(
        "line {line}: t = {} does not increase (previous {}), allowed strictly increasing times",
        with_unit(time, *unit),
        with_unit(prev, *unit)
    )]
    NotIncreasing {
        line: usize,
        time: String,
        prev: String,
        unit: Option<&'static str>,
    },
    /// A data row with more filled cells (`fields`) than its header, at
    /// `header_line`, names (`header`): which number is which cannot be told. A
    /// comma-separated file written with decimal commas splits each number in two
    /// (`decimal_commas`: the file's separator is the comma).
    #[error(
        "line {line}: {fields} filled cells where the header (line {header_line}) names {header} columns, so which number is which cannot be told{}",
        if *decimal_commas { "; decimal commas in a comma-separated file? Write the numbers with a point, or separate the columns with ;" } else { "" }
    )]
    Wider {
        line: usize,
        fields: usize,
        header_line: usize,
        header: usize,
        decimal_commas: bool,
    },
    /// A number beyond [`MOST_CELL`] in the file's own unit: no experiment's.
    #[error(
        "line {line}: {name} = {value:e} is beyond any measurement, allowed |{name}| ≤ 1e12 in the file's unit"
    )]
    Beyond {
        line: usize,
        name: &'static str,
        value: f64,
    },
}

impl RowError {
    /// Why the data row `row` cannot be read against `header` (in a file separated
    /// by `sep`): more filled cells than the header names (trailing empty cells, as
    /// a spreadsheet's export leaves them, are none).
    pub(super) fn wider(row: &TableRow, header: &TableRow, sep: Sep) -> Option<RowError> {
        let fields = (0..row.len()).filter(|&i| !row.cell(i).is_empty()).count();
        (fields > header.len()).then(|| RowError::Wider {
            line: row.line,
            fields,
            header_line: header.line,
            header: header.len(),
            decimal_commas: sep == Sep::Comma,
        })
    }

    /// Line `line`'s time, `time` as written, is not after the time before it, `prev`
    /// as written, in a time unit of SI factor `factor`.
    pub(super) fn not_increasing(line: usize, time: &str, prev: &str, factor: f64) -> RowError {
        RowError::NotIncreasing {
            line,
            time: time.to_string(),
            prev: prev.to_string(),
            unit: unit_name(&TIMES, factor),
        }
    }
}

/// A cell as written, and its unit after a space where there is one.
fn with_unit(cell: &str, unit: Option<&str>) -> String {
    match unit {
        Some(u) => format!("{} {u}", clip(cell)),
        None => clip(cell).to_string(),
    }
}

/// The largest magnitude a cell of a track may have in the file's own unit (pixels,
/// µs, mm …): 1e12 is more than any clip's pixels or microseconds; beyond it the
/// numbers are no measurement, and their differences would overflow (±1e308
/// alternating gave "largest change 0.000 m/s").
pub const MOST_CELL: f64 = 1e12;

/// A table of accelerations only (phyphox's accelerometer), at its header's `line`
/// with those `columns`: what groovelab needs instead.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error(
    "line {line}: the file holds accelerations only ({}), no positions or velocities: groovelab needs the ball's position over time (a video track: t, x, y) or its velocities (t, v_cm, v_t); a phone's accelerometer (phyphox) cannot give them",
    clip(columns)
)]
pub struct AccelerationsOnly {
    pub line: usize,
    pub columns: String,
}

/// A velocity file with fewer than [`FRAMES_BEFORE`] frames up to its first impact
/// (`impact`: its time in the file's time, s).
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error(
    "only {before} frame{} before the impact at t = {} s, at least {FRAMES_BEFORE} needed to see the approach (start the recording before the balls meet)",
    if *before == 1 { "" } else { "s" },
    crate::settings::units::significant(*impact, 4)
)]
pub struct TooFewBefore {
    pub before: usize,
    pub impact: f64,
}

/// Fewest frames up to the first impact (a frame at it counts) a velocity file needs:
/// the approach must be seen, not only guessed from one frame.
pub(super) const FRAMES_BEFORE: usize = 2;

/// `--impact-at` outside a velocity file's times (s).
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error(
    "--impact-at {} lies outside the file's times, t = {} … {} s: allowed a time within them",
    crate::settings::units::show_exact(*at, crate::settings::units::Dimension::Time),
    crate::settings::units::significant(*first, 6),
    crate::settings::units::significant(*last, 6)
)]
pub struct ImpactOutside {
    pub at: f64,
    pub first: f64,
    pub last: f64,
}
