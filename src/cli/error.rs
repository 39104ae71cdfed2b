//! What can go wrong on the command line, kept typed up to the edge: each failure
//! holds the values it is about (numbers in SI, the option by its clap id), and its
//! one `error:` line is made only where it is printed (`entry`).

use std::fmt;
use std::path::PathBuf;

use super::args::{Cli, MAX_SAMPLES, SweepFormat};
use crate::methods::Method;
use crate::settings::units::{Dimension, UnitError, show, show_exact};

/// An option of the command line by its clap id (the derive's field name), shown as
/// clap defines it (`--NAME`) where a message is printed, so a renamed option is
/// renamed in its messages too.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Flag(pub &'static str);

impl Flag {
    /// The option's long name as clap defines it, if `id` is an option's id.
    fn long(self) -> Option<String> {
        use clap::CommandFactory;
        let cmd = Cli::command();
        cmd.get_arguments()
            .chain(cmd.get_subcommands().flat_map(|c| c.get_arguments()))
            .find(|a| a.get_id() == self.0)
            .and_then(|a| a.get_long())
            .map(str::to_string)
    }
}

impl fmt::Display for Flag {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let long = self.long();
        debug_assert!(long.is_some(), "{} is no option's id", self.0);
        write!(f, "--{}", long.unwrap_or_else(|| self.0.replace('_', "-")))
    }
}

/// A byte count for people: 9.3 GiB, 286 MiB, 12 KiB.
pub(crate) fn size_text(bytes: u64) -> String {
    let b = bytes as f64;
    let (k, m, g) = (1024.0, 1024.0 * 1024.0, 1024.0 * 1024.0 * 1024.0);
    if b >= g {
        format!("{:.1} GiB", b / g)
    } else if b >= m {
        format!("{:.0} MiB", b / m)
    } else {
        format!("{:.0} KiB", b / k)
    }
}

/// A sample count as the `--sample` error shows it: none for a step ≤ 0, in
/// scientific notation when too large to read.
fn count_text(dt: f64, count: f64) -> String {
    if dt > 0.0 && count < 1e15 {
        format!("{count}")
    } else if dt > 0.0 {
        format!("{count:e}")
    } else {
        "no".into()
    }
}

/// A failure the user can act on: printed as one `error:` line, exit status 2. The
/// errors of the layers below are kept whole.
#[derive(Debug, thiserror::Error)]
pub enum CliError {
    #[error(transparent)]
    Scene(#[from] crate::settings::spec::SceneError),
    #[error(transparent)]
    Preset(#[from] crate::input::preset::LoadError),
    #[error(transparent)]
    File(#[from] crate::input::FileError),
    #[error(transparent)]
    Data(#[from] crate::input::data::DataError),
    #[error(transparent)]
    Video(#[from] crate::input::video::VideoError),
    /// A video's tracks whose speeds or frame spacing are of no ball in a groove:
    /// their scale (from R, or `--scale`) or their rate is off, not a unit of the
    /// file's (`scaled`: the tracks' own line on their scale, as written).
    #[error(
        "{file}: as tracked, {seen}, no ball in a groove: its scale ({scaled}) or its frame rate is off; check --radius (a number without a unit is metres: 2.75 is 2.75 m, 2.75cm a ball's), --scale and --fps"
    )]
    TracksOffScale {
        file: String,
        seen: OffScale,
        scaled: String,
    },
    /// The tracking was refused, and what the tracker found is drawn in `overlay`.
    #[error(
        "{error}; what the tracker found is drawn over a pixel grid in {}",
        overlay.display()
    )]
    RefusedDrawn {
        error: Box<crate::input::video::VideoError>,
        overlay: PathBuf,
    },
    #[error(transparent)]
    Output(crate::output::OutputError),
    #[error(transparent)]
    Fit(crate::study::fit::FitError),
    #[error(transparent)]
    Sweep(crate::study::sweep::SweepError),
    #[error(transparent)]
    Usage(#[from] Usage),
    #[error(transparent)]
    Value(#[from] BadValue),
    /// A figure plotters could not draw (`what`: "map", "diagram", "figure").
    #[error("cannot draw the {what}: {source}")]
    Draw {
        what: &'static str,
        source: crate::study::figures::FigureError,
    },
    /// The measured series of `file` holds a number no lab measures.
    #[error("{file}: {source}")]
    Implausible {
        file: String,
        source: crate::study::measured::OutOfLabRange,
    },
    #[error("cannot write {}: {source}", path.display())]
    Write {
        path: PathBuf,
        source: std::io::Error,
    },
    #[error("{0}")]
    Io(#[from] std::io::Error),
    #[error("interrupted: nothing was written")]
    Interrupted,
}

impl From<crate::output::OutputError> for CliError {
    fn from(e: crate::output::OutputError) -> CliError {
        match e {
            crate::output::OutputError::Interrupted => CliError::Interrupted,
            other => CliError::Output(other),
        }
    }
}

impl From<crate::study::sweep::SweepError> for CliError {
    fn from(e: crate::study::sweep::SweepError) -> CliError {
        match e {
            crate::study::sweep::SweepError::Interrupted => CliError::Interrupted,
            other => CliError::Sweep(other),
        }
    }
}

/// An option given where it does nothing: refused, never ignored silently.
#[derive(Debug, thiserror::Error)]
pub enum Usage {
    #[error("{flag} is not used by {by}, allowed only with {allowed}")]
    Unused {
        flag: Flag,
        by: &'static str,
        allowed: &'static str,
    },
    #[error(
        "{flag} describes a {data} file and none is given, allowed only with {data} FILE",
        data = Flag("data")
    )]
    WithoutData { flag: Flag },
    /// A data option for what none of the files given holds (`--length-unit` for
    /// velocities, `--speed-unit` for a position track).
    #[error("{flag} does not apply to {file}: it holds {holds}")]
    NotForFile {
        flag: Flag,
        file: String,
        holds: &'static str,
    },
    #[error("{flag} is not used by the {} method, allowed only with {allowed}", method.name())]
    NotForMethod {
        flag: Flag,
        method: Method,
        allowed: UsedBy,
    },
}

/// The methods that use a method's option.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum UsedBy {
    TimeStepping,
    Method(Method),
}

impl fmt::Display for UsedBy {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            UsedBy::TimeStepping => f.write_str("a time-stepping method (the first step of rk45)"),
            UsedBy::Method(m) => write!(f, "{} {}", Flag("method"), m.name()),
        }
    }
}

/// An option's value that cannot be used, with what is allowed.
#[derive(Debug, thiserror::Error)]
pub enum BadValue {
    /// A number outside its range (`allowed` in words, e.g. "0 < dt ≤ 1 s").
    #[error("{flag} {} is out of range, allowed {allowed}", show_exact(*value, *dim))]
    OutOfRange {
        flag: Flag,
        value: f64,
        dim: Dimension,
        allowed: &'static str,
    },
    #[error("{flag} {}: {source}", crate::settings::quote::clip(text))]
    Unit {
        flag: Flag,
        text: String,
        source: UnitError,
    },
    #[error("{flag} {source}")]
    Axis {
        flag: Flag,
        source: crate::study::sweep::AxisError,
    },
    #[error(
        "{} {} is not a grid, expected NX or NXxNY (1 ..= 10000 each), e.g. 400x200",
        Flag("grid"),
        crate::settings::quote::clip(text)
    )]
    Grid { text: String },
    /// NXxNY with NY over 1 where only `--x` is swept: the second count has no axis.
    #[error(
        "{} {text} counts {ny} values of a second parameter, but only {} is swept: give {} {nx}, or a second parameter with {}",
        Flag("grid"),
        Flag("x"),
        Flag("grid"),
        Flag("y")
    )]
    GridWithoutY { text: String, nx: usize, ny: usize },
    #[error(
        "{} {grid} is too fine for {} svg (one rectangle per point), allowed at most {max}x{max}; use csv or json for finer grids",
        Flag("grid"),
        Flag("format")
    )]
    GridTooFineForSvg { grid: String, max: usize },
    #[error(
        "{} {grid} gives {points} points, about {} of {}, allowed at most {} on stdout; write it with {} FILE (streamed, no limit)",
        Flag("grid"),
        size_text(*bytes),
        format!("{format:?}").to_uppercase(),
        size_text(*limit),
        Flag("output")
    )]
    TooLargeForStdout {
        grid: String,
        points: u64,
        bytes: u64,
        format: SweepFormat,
        limit: u64,
    },
    #[error(
        "{} {} cannot run this span: {why}, allowed a larger {} or a shorter span",
        Flag("method"),
        method.name(),
        Flag("dt")
    )]
    MethodCannotRun {
        method: Method,
        why: crate::methods::Stall,
    },
    #[error(
        "preset {preset} has no measured data, allowed: a paper-b* preset or {} FILE",
        Flag("data")
    )]
    NoMeasuredData { preset: String },
    #[error(
        "{} given {count} times, allowed once (one file) or twice (the centre's track, then the rim mark's)",
        Flag("data")
    )]
    DataTooOften { count: usize },
    #[error(
        "{} {} names no scene: give the one it was measured in, {} NAME or the scene options ({}, {}, {}, {} …)",
        Flag("data"),
        path.display(),
        Flag("preset"),
        Flag("radius"),
        Flag("width"),
        Flag("mass"),
        Flag("v0")
    )]
    DataWithoutScene { path: PathBuf },
    #[error(
        "the rim mark lies {} from the centre, farther than the ball's R = {} (allowed up to R + 3× the position scatter = {}): give the ball's {} or name the mark's track ({} mark=NAME){}",
        show(*mark, Dimension::Length),
        show(*radius, Dimension::Length),
        show(*limit, Dimension::Length),
        Flag("radius"),
        Flag("track"),
        mark_unit_hint(*mark, *radius)
    )]
    MarkOffTheBall { mark: f64, radius: f64, limit: f64 },
    #[error(
        "{} names {name} twice, allowed each value once (of mu, v0, restitution, rolling_resistance)",
        Flag("free")
    )]
    FreeTwice { name: &'static str },
    /// `--free` without `mu`: every model the fit knows fits μ_k.
    #[error(
        "{} {list} leaves out mu, allowed lists that free μ_k (every model fits it): give {} mu,{list}",
        Flag("free"),
        Flag("free")
    )]
    FreeWithoutMu { list: String },
    #[error("{} {from} s must be before {} {to} s", Flag("from"), Flag("to"))]
    FitWindowBackwards { from: f64, to: f64 },
    #[error(
        "{} {} is not after the first impact, allowed t > 0 s (the data's times count from the impact; the line fits are of the sliding after it)",
        Flag(flag),
        show(*value, Dimension::Time)
    )]
    FitWindowBeforeImpact { flag: &'static str, value: f64 },
    #[error(
        "{} {} is outside the simulated span, allowed {} … {}",
        Flag("at"),
        show(*at, Dimension::Time),
        show(*start, Dimension::Time),
        show(*end, Dimension::Time)
    )]
    OutsideSpan { at: f64, start: f64, end: f64 },
    #[error(
        "{} {} gives {} samples over {} … {}, allowed a step > 0 giving at most {MAX_SAMPLES} samples",
        Flag("sample"),
        show_exact(*dt, Dimension::Time),
        count_text(*dt, *count),
        show(*start, Dimension::Time),
        show(*end, Dimension::Time)
    )]
    TooManySamples {
        dt: f64,
        count: f64,
        start: f64,
        end: f64,
    },
    #[error("{}: {source}", Flag("keys"))]
    Keys {
        source: crate::tui::keys::UnknownKey,
    },
    /// `GROOVELAB_THEME` (`--theme`'s default) is none of its words.
    #[error("{source}")]
    ThemeSwitch { source: crate::tui::look::BadTheme },
}

/// A video's tracks refused for speeds or a frame spacing of no ball in a groove:
/// said of their scale and rate (R in the wrong unit, a wrong `--scale` or `--fps`),
/// not of a file's units, which a video's tracks do not take (`units_of_a_video`).
pub(super) fn video_scale(e: crate::input::data::DataError, file: &str, text: &str) -> CliError {
    use crate::input::data::{DataProblem, ScaleError};
    let seen = match &e.what {
        DataProblem::Scale(
            ScaleError::TooSlow { speed, .. }
            | ScaleError::LengthsNotMetres { speed, .. }
            | ScaleError::TooFast { speed, .. },
        ) => OffScale::Speed(*speed),
        DataProblem::Scale(
            ScaleError::TimesNotSeconds { frame } | ScaleError::FramesTooSlow { frame, .. },
        ) => OffScale::Spacing(*frame),
        _ => return CliError::from(e),
    };
    // The tracks' own line on their scale (`tracked::scale_note`).
    let scaled = text
        .lines()
        .take_while(|l| l.starts_with('#'))
        .find_map(|l| l.strip_prefix("# scale ").filter(|r| r.contains("px/m:")))
        .map(|r| r.split(';').next().unwrap_or(r).to_string())
        .unwrap_or_else(|| "as the tracks' file says".into());
    CliError::TracksOffScale {
        file: file.to_string(),
        seen,
        scaled,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every `Flag("id")` written in the command line's source names an option clap
    /// defines (a renamed field would otherwise show a guessed name).
    #[test]
    fn every_flag_id_in_the_source_is_an_option() {
        let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/src/cli");
        let mut seen = 0;
        // The files of src/cli and of its folders (cli/fit/).
        let mut files = Vec::new();
        let mut dirs = vec![std::path::PathBuf::from(dir)];
        while let Some(d) = dirs.pop() {
            for entry in std::fs::read_dir(d).unwrap() {
                let path = entry.unwrap().path();
                if path.is_dir() {
                    dirs.push(path);
                } else {
                    files.push(path);
                }
            }
        }
        for path in files {
            let text = std::fs::read_to_string(path).unwrap();
            for piece in text.split("Flag(\"").skip(1) {
                let id = piece.split('"').next().unwrap();
                if id == "id" {
                    continue; // this test's own pattern
                }
                let id: &'static str = Box::leak(id.to_string().into_boxed_str());
                assert!(Flag(id).long().is_some(), "Flag(\"{id}\") is no option");
                seen += 1;
            }
        }
        assert!(seen > 10, "found only {seen} flags");
        assert_eq!(Flag("time_unit").to_string(), "--time-unit");
    }
}

#[cfg(test)]
mod messages {
    use super::*;

    /// The one-line messages, made from the typed values where they are printed, read
    /// as they did when they were built as strings at each site.
    #[test]
    fn typed_errors_print_the_messages_of_before() {
        let cases: [(CliError, &str); 6] = [
            (
                BadValue::OutOfRange {
                    flag: Flag("dt"),
                    value: 2.0,
                    dim: Dimension::Time,
                    allowed: "0 < dt ≤ 1 s",
                }
                .into(),
                "--dt 2 s is out of range, allowed 0 < dt ≤ 1 s",
            ),
            (
                BadValue::Grid { text: "3x".into() }.into(),
                "--grid 3x is not a grid, expected NX or NXxNY (1 ..= 10000 each), e.g. 400x200",
            ),
            (
                BadValue::TooLargeForStdout {
                    grid: "10000x10000".into(),
                    points: 100_000_000,
                    bytes: 10_000_000_000,
                    format: SweepFormat::Csv,
                    limit: 256 * 1024 * 1024,
                }
                .into(),
                "--grid 10000x10000 gives 100000000 points, about 9.3 GiB of CSV, allowed at most 256 MiB on stdout; write it with --output FILE (streamed, no limit)",
            ),
            (
                BadValue::FitWindowBackwards { from: 1.0, to: 0.5 }.into(),
                "--from 1 s must be before --to 0.5 s",
            ),
            (
                BadValue::FitWindowBeforeImpact {
                    flag: "from",
                    value: -0.15,
                }
                .into(),
                "--from -0.15 s is not after the first impact, allowed t > 0 s (the data's times count from the impact; the line fits are of the sliding after it)",
            ),
            (
                Usage::WithoutData {
                    flag: Flag("window"),
                }
                .into(),
                "--window describes a --data file and none is given, allowed only with --data FILE",
            ),
        ];
        for (error, message) in cases {
            assert_eq!(error.to_string(), message);
        }
    }
}

/// What a video's tracks show that no ball in a groove does.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum OffScale {
    /// The ball's approach speed, m/s.
    Speed(f64),
    /// The frames' spacing, s.
    Spacing(f64),
}

impl std::fmt::Display for OffScale {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        use crate::settings::units::significant;
        match self {
            OffScale::Speed(v) => write!(f, "the ball approaches at {} m/s", significant(*v, 3)),
            OffScale::Spacing(s) => write!(f, "its frames are {} s apart", significant(*s, 3)),
        }
    }
}

/// Where a rim mark lies 10, 100 or 1000 times R from the centre (within a fifth):
/// the lengths' unit named as the likelier mistake (mm read as cm, cm or mm as m).
fn mark_unit_hint(mark: f64, radius: f64) -> String {
    let ratio = mark / radius;
    crate::settings::units::MIX_UPS
        .into_iter()
        .find(|(p, _, _)| (0.8..1.25).contains(&(ratio / p)))
        .map(|(p, meant, read)| {
            format!(
                "; at {p}× R, the lengths may be {meant} read as {read}: give {} {meant}",
                Flag("length_unit")
            )
        })
        .unwrap_or_default()
}
