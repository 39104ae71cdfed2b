//! The command line's raw flags (clap): commands, their options, and the scene
//! options made from the parameter table. Checked values come out of `SceneArgs`
//! (its methods are in `open`).

use clap::{Args, Parser, Subcommand, ValueEnum};

use crate::methods::Method;
use crate::settings::params::PARAMS;
use crate::settings::quote::clip;
use crate::settings::spec::SceneSpec;
use crate::settings::units::{Dimension, UnitError, parse_option, significant};
use crate::study::fit::Free;

/// Most samples `--sample` may ask for.
pub const MAX_SAMPLES: usize = 1_000_000;

#[derive(Parser, Debug)]
#[command(
    name = "groovelab",
    version,
    about = "Two balls colliding in a groove: exact simulation, charts and lab tools",
    long_about = "Two balls (identical in the paper; masses and speeds may differ) roll toward \
                  each other in a horizontal groove, collide, and then depart, stop, or come \
                  back again and again. groovelab solves the motion exactly (Gröber & \
                  Sniatecki) and shows why."
)]
pub struct Cli {
    #[command(subcommand)]
    pub command: Option<Command>,
    #[command(flatten)]
    pub scene: SceneArgs,
    /// Pure 7-bit ASCII drawing (app and render) instead of Unicode.
    #[arg(long, global = true)]
    pub ascii: bool,
    /// Colours for a dark or a light terminal background (app and render); auto asks
    /// the terminal (OSC 11), then reads COLORFGBG, else dark; render's auto is dark
    /// [default: $GROOVELAB_THEME, else auto].
    #[arg(long, value_name = "THEME", value_enum, global = true)]
    pub theme: Option<crate::tui::theme::ThemeChoice>,
    #[command(flatten)]
    pub data: DataArgs,
}

/// The command line as it is parsed and its help written: clap lists every global
/// option under every command (`presets --help` listed the 31 scene and data options
/// it refuses), so each command's own list hides the global options it does not
/// take. Hidden, they are still parsed, and one given is refused by name
/// (`cli::used_options`), never ignored.
pub fn command() -> clap::Command {
    use clap::CommandFactory;
    let cmd = Cli::command();
    let ids = |c: clap::Command| -> Vec<String> {
        c.get_arguments().map(|a| a.get_id().to_string()).collect()
    };
    let scene = ids(SceneArgs::augment_args(clap::Command::new("scene")));
    let data = ids(DataArgs::augment_args(clap::Command::new("data")));
    let globals: Vec<clap::Arg> = cmd
        .get_arguments()
        .filter(|a| a.is_global_set())
        .cloned()
        .collect();
    let names: Vec<String> = cmd
        .get_subcommands()
        .map(|s| s.get_name().to_string())
        .collect();
    names.into_iter().fold(cmd, |cmd, name| {
        let takes = |id: &str| {
            let in_scene = scene.iter().any(|s| s == id);
            let in_data = data.iter().any(|d| d == id);
            let drawing = matches!(id, "ascii" | "theme");
            match name.as_str() {
                "tui" | "render" => in_scene || in_data || drawing,
                "simulate" => in_scene,
                // A sweep solves each point to its end: no span (`used_options`).
                "sweep" => in_scene && !matches!(id, "t_start" | "t_end"),
                "compare" | "fit" => in_scene || in_data,
                // R for the scale, and the tracker's own data options (`used_options`).
                "track" => matches!(
                    id,
                    "preset" | "radius" | "scale" | "fps" | "roi" | "ball_at"
                ),
                // Its files are its arguments; a video's R as for `track`.
                "data" => matches!(id, "preset" | "radius") || (in_data && id != "data"),
                _ => !(in_scene || in_data || drawing),
            }
        };
        // A hidden copy in the command itself: clap propagates a global option only
        // where the command has none of that id (a hidden one is parsed all the same).
        let hidden: Vec<clap::Arg> = globals
            .iter()
            .filter(|a| !takes(a.get_id().as_str()))
            .map(|a| a.clone().hide(true))
            .collect();
        cmd.mut_subcommand(&name, |sub| sub.args(hidden))
    })
}

/// Measured data from a file, for `fit`, the app and `render`.
#[derive(Args, Debug, Clone, Default)]
pub struct DataArgs {
    /// A file of the left ball: velocities (t, v_cm, v_t) or a position track (Tracker,
    /// Logger Pro, CSV/TSV with t, x, y), columns found by header. Given twice: two
    /// one-track exports, the ball's centre then its rim mark, matched by time
    /// [default: the preset's series].
    #[arg(long, value_name = "FILE", global = true)]
    pub data: Vec<std::path::PathBuf>,
    /// Time unit of the file (e.g. ms, us; wins over the header's) [default: the
    /// header's, else s].
    #[arg(long, value_name = "UNIT", global = true)]
    pub time_unit: Option<String>,
    /// Speed unit of a velocity file (e.g. cm/s; wins over the header's) [default: the
    /// header's, else m/s].
    #[arg(long, value_name = "UNIT", global = true)]
    pub speed_unit: Option<String>,
    /// Time of the first impact in the file [default: detected from v_cm, or from the
    /// motion of a position track].
    #[arg(long, value_name = "T", value_parser = time, allow_hyphen_values = true, global = true)]
    pub impact_at: Option<f64>,
    /// Which track of a position file is what: `centre=NAME` (the ball's centre) and
    /// `mark=NAME` (a mark on its rim), by the track's name in the file (e.g. --track
    /// "centre=mass A" --track "mark=mass B") [default: tracks named centre/ball and
    /// mark/rim, else the first and second].
    #[arg(long, value_name = "ROLE=NAME", value_parser = track, global = true)]
    pub track: Vec<(TrackRole, String)>,
    /// Length unit of a position file (e.g. mm; wins over the header's) [default: the
    /// header's, else m].
    #[arg(long, value_name = "UNIT", global = true)]
    pub length_unit: Option<String>,
    /// The length one pixel shows (e.g. 1.105mm for a 1 m ruler 905 pixels long in
    /// the picture): for a video (`track`, `--data VIDEO`) whose balls' outlines give
    /// no sure scale, or a track in pixels (a Tracker or Logger Pro file whose video
    /// was not calibrated) [default: a video's from the balls' radius, a file's own
    /// calibration].
    #[arg(long, value_name = "LENGTH", value_parser = length, allow_hyphen_values = true, global = true, conflicts_with = "length_unit")]
    pub scale: Option<f64>,
    /// Half-width of the local fit that derives velocities from positions (e.g. 20ms)
    /// [default: chosen from the frame rate and the scatter].
    #[arg(long, value_name = "T", value_parser = time, allow_hyphen_values = true, global = true)]
    pub window: Option<f64>,
    /// Frames per second of a video (`track`, `--data VIDEO`), 1 to 100000 [default: a
    /// slow-motion capture rate in the file's metadata, else the container's; a
    /// folder of frames needs it].
    #[arg(long, value_name = "F", global = true, allow_negative_numbers = true,
          value_parser = super::track_args::positive("frames per second", 1.0, 1e5))]
    pub fps: Option<f64>,
    /// Where the tracker looks in a video (`track`, `--data VIDEO`): a rectangle of
    /// the frame in pixels, X,Y,W,H from the top-left corner (e.g. 0,300,1920,250:
    /// only the groove) [default: the whole frame].
    // Negative numbers are taken as the value (and refused by it, saying what is
    // allowed), not as an unknown option.
    #[arg(long, value_name = "X,Y,W,H", value_parser = roi, global = true,
          allow_hyphen_values = true)]
    pub roi: Option<crate::vision::Roi>,
    /// A point on one ball in the video's first frame, pixels X,Y from the top-left
    /// corner (`track`, `--data VIDEO`): the tracker's seed, the ball's radius taken
    /// from it [default: the balls found by themselves].
    #[arg(long, value_name = "X,Y", value_parser = ball_at, global = true,
          allow_hyphen_values = true)]
    pub ball_at: Option<(f64, f64)>,
}

/// Pixel numbers separated by commas: `n` of them, each finite and ≥ 0.
fn pixels(text: &str, n: usize) -> Option<Vec<f64>> {
    let v: Vec<f64> = text
        .split(',')
        .map(|p| p.trim().parse::<f64>())
        .collect::<Result<_, _>>()
        .ok()?;
    (v.len() == n && v.iter().all(|x| x.is_finite() && *x >= 0.0 && *x <= 1e5)).then_some(v)
}

fn roi(text: &str) -> Result<crate::vision::Roi, ArgError> {
    let bad = || ArgError::Roi {
        text: text.to_string(),
    };
    match pixels(text, 4).as_deref() {
        Some(&[x, y, width, height]) if width >= 1.0 && height >= 1.0 => Ok(crate::vision::Roi {
            x,
            y,
            width,
            height,
        }),
        _ => Err(bad()),
    }
}

fn ball_at(text: &str) -> Result<(f64, f64), ArgError> {
    match pixels(text, 2).as_deref() {
        Some(&[x, y]) => Ok((x, y)),
        _ => Err(ArgError::BallAt {
            text: text.to_string(),
        }),
    }
}

/// What a named track of a position file holds.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TrackRole {
    Centre,
    Mark,
}

/// Why an option's text is not a value of it (clap prints it after the option's name).
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum ArgError {
    #[error("'{}' is not ROLE=NAME, allowed centre=NAME or mark=NAME", clip(text))]
    Track { text: String },
    /// A screen below the app's smallest (`min`, COLSxROWS).
    #[error(
        "'{}' is smaller than the app's smallest screen, allowed at least {}x{} (up to {MAX_SCREEN}x{MAX_SCREEN})",
        clip(text),
        min.0,
        min.1
    )]
    SmallScreen { text: String, min: (u16, u16) },
    /// A screen beyond the largest `render` draws (`min`: the smallest, COLSxROWS).
    #[error(
        "'{}' is larger than render draws, allowed COLSxROWS from {}x{} to {MAX_SCREEN}x{MAX_SCREEN}",
        clip(text),
        min.0,
        min.1
    )]
    LargeScreen { text: String, min: (u16, u16) },
    #[error(
        "'{}' is not a size, expected COLSxROWS such as 120x40 (from {}x{} to {MAX_SCREEN}x{MAX_SCREEN})",
        clip(text),
        min.0,
        min.1
    )]
    NotASize { text: String, min: (u16, u16) },
    #[error(
        "'{}' is not a pixel's length, expected a length above 0 such as 1.105mm",
        clip(text)
    )]
    NotAPixel { text: String },
    #[error(
        "'{}' ({} m a pixel) is not a pixel's length in a lab video, allowed 0.001mm … 10cm (e.g. 1.105mm: the length one pixel shows, not pixels per metre)",
        clip(text),
        significant(*metres, 4)
    )]
    PixelOutOfRange { text: String, metres: f64 },
    #[error(
        "'{}' is not a rectangle of the frame, expected X,Y,W,H in pixels such as 0,300,1920,250 (X, Y ≥ 0; W, H ≥ 1)",
        clip(text)
    )]
    Roi { text: String },
    #[error(
        "'{}' is not a point of the frame, expected X,Y in pixels such as 640,330 (both ≥ 0)",
        clip(text)
    )]
    BallAt { text: String },
    #[error(transparent)]
    Unit(#[from] UnitError),
}

fn track(text: &str) -> Result<(TrackRole, String), ArgError> {
    let bad = || ArgError::Track {
        text: text.to_string(),
    };
    let (role, name) = text.split_once('=').ok_or_else(bad)?;
    let role = match role.trim().to_ascii_lowercase().as_str() {
        "centre" | "center" => TrackRole::Centre,
        "mark" | "rim" => TrackRole::Mark,
        _ => return Err(bad()),
    };
    let name = name.trim();
    if name.is_empty() {
        return Err(bad());
    }
    Ok((role, name.to_string()))
}

#[derive(Subcommand, Debug)]
pub enum Command {
    /// The interactive terminal app (the default).
    Tui,
    /// One run of a scene, printed as a table, JSON or CSV.
    Simulate(SimulateArgs),
    /// The app's screen at one simulated time, as plain text (headless).
    Render(RenderArgs),
    /// Speed against accuracy of the solution methods (work–precision).
    Compare(CompareArgs),
    /// Fit the model to measured data (a preset's, or --data: a CSV, Tracker, Logger Pro,
    /// Graphical Analysis or phyphox file, or a video).
    Fit(FitArgs),
    /// What groovelab reads in data files, without fitting: format, tracks, units,
    /// frames, missing frames, scatter, approach speed, impacts.
    Data(DataCmdArgs),
    /// Regime map over one or two scene parameters.
    Sweep(SweepArgs),
    /// Track both balls and their marks in a video (or a folder of frames): a
    /// Tracker-style file for --data, or JSON.
    Track(super::track_args::TrackArgs),
    /// List the built-in and user presets.
    Presets,
    /// Print a shell completion script (e.g. `groovelab completions bash > groovelab.bash`).
    Completions {
        /// The shell to complete in.
        #[arg(value_enum)]
        shell: clap_complete::Shell,
    },
    /// Print the man page groovelab(1) in roff (e.g. `groovelab manpage | man -l -`).
    Manpage,
}

#[derive(Args, Debug)]
pub struct SimulateArgs {
    /// Output format.
    #[arg(long, value_enum, default_value_t = SimulateFormat::Table)]
    pub format: SimulateFormat,
    /// Also give states on a uniform time grid with this step (e.g. 10ms).
    #[arg(long, value_name = "DT", value_parser = time, allow_hyphen_values = true)]
    pub sample: Option<f64>,
    /// Solution method (time-stepping methods report the events they detect).
    #[arg(long, value_enum, default_value_t = Method::Exact)]
    pub method: Method,
    /// Step size of a fixed-step method or moreau (e.g. 0.1ms) [default: 0.1 ms].
    #[arg(long, value_name = "S", value_parser = time, allow_hyphen_values = true)]
    pub dt: Option<f64>,
    /// Tolerance of rk45 [default: 1e-6].
    #[arg(long, value_name = "X", value_parser = ratio, allow_hyphen_values = true)]
    pub tol: Option<f64>,
    /// Regularisation speed ε of rk4's tanh(s/ε) friction [default: 1mm/s].
    #[arg(long, value_name = "Q", value_parser = speed, allow_hyphen_values = true)]
    pub epsilon: Option<f64>,
    /// Write the output to this file (atomically) instead of stdout.
    #[arg(long, value_name = "FILE")]
    pub output: Option<std::path::PathBuf>,
}

#[derive(Args, Debug)]
pub struct CompareArgs {
    /// Output: a table, JSON rows, or an SVG work–precision diagram.
    #[arg(long, value_enum, default_value_t = CompareFormat::Table)]
    pub format: CompareFormat,
    /// Methods to compare, comma-separated [default: all].
    #[arg(long, value_enum, value_delimiter = ',')]
    pub methods: Option<Vec<Method>>,
    /// Regularisation speed ε of rk4's tanh(s/ε) friction [default: 1mm/s].
    #[arg(long, value_name = "Q", value_parser = speed, allow_hyphen_values = true)]
    pub epsilon: Option<f64>,
    /// Write the output to this file (atomically) instead of stdout.
    #[arg(long, value_name = "FILE")]
    pub output: Option<std::path::PathBuf>,
}

#[derive(Args, Debug)]
pub struct FitArgs {
    /// Start of the line-fit window (after the impact) [default: first frame after it].
    #[arg(long, value_name = "T", value_parser = time, allow_hyphen_values = true)]
    pub from: Option<f64>,
    /// End of the line-fit window [default: the last frame before v_cm and v_t meet].
    #[arg(long, value_name = "T", value_parser = time, allow_hyphen_values = true)]
    pub to: Option<f64>,
    /// What the model fit may change, comma-separated [default: mu].
    #[arg(long, value_enum, value_delimiter = ',')]
    pub free: Option<Vec<Free>>,
    /// Output: a table, JSON, or an SVG figure (data, fitted model, residuals).
    #[arg(long, value_enum, default_value_t = FitFormat::Table)]
    pub format: FitFormat,
    /// Write the output to this file (atomically) instead of stdout.
    #[arg(long, value_name = "FILE")]
    pub output: Option<std::path::PathBuf>,
}

#[derive(Args, Debug)]
pub struct DataCmdArgs {
    /// The files to read (Tracker .trk or export, Logger Pro .cmbl or text, CSV/TSV; a
    /// video or a folder of numbered frames is tracked first, as `track` does).
    #[arg(value_name = "FILE", required = true)]
    pub files: Vec<std::path::PathBuf>,
    /// Output: text for people, or JSON (one object per file, in an array).
    #[arg(long, value_enum, default_value_t = DataFormat::Table)]
    pub format: DataFormat,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum DataFormat {
    Table,
    Json,
}

/// `sweep`'s grid when none is given: a 1-D sweep takes its NX alone.
pub const DEFAULT_GRID: &str = "200x100";

#[derive(Args, Debug)]
pub struct SweepArgs {
    /// First parameter and range, NAME=LO..HI with units (e.g. width=0..5.4cm).
    #[arg(long, value_name = "NAME=LO..HI", allow_hyphen_values = true)]
    pub x: String,
    /// Second parameter and range (e.g. restitution=0.3..1); omit for a 1-D sweep.
    #[arg(long, value_name = "NAME=LO..HI", allow_hyphen_values = true)]
    pub y: Option<String>,
    /// Grid points, NX or NXxNY.
    #[arg(long, value_name = "NXxNY", default_value = DEFAULT_GRID)]
    pub grid: String,
    /// Output: CSV rows in grid order, JSON, or an SVG map.
    #[arg(long, value_enum, default_value_t = SweepFormat::Csv)]
    pub format: SweepFormat,
    /// Write the output to this file (atomically) instead of stdout.
    #[arg(long, value_name = "FILE")]
    pub output: Option<std::path::PathBuf>,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum SweepFormat {
    Csv,
    Json,
    Svg,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum FitFormat {
    Table,
    Json,
    Svg,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum CompareFormat {
    Table,
    Json,
    Svg,
}

#[derive(Args, Debug)]
pub struct RenderArgs {
    /// Simulated time to show (e.g. 150ms) [default: the start of the span].
    #[arg(long, value_name = "T", value_parser = time, allow_hyphen_values = true)]
    pub at: Option<f64>,
    /// Screen size, COLSxROWS.
    #[arg(long, value_name = "COLSxROWS", default_value = "120x40", value_parser = screen_size)]
    pub size: (u16, u16),
    /// Keys to press first, by the names the help screen shows (e.g. "down right enter").
    #[arg(long, value_name = "K", allow_hyphen_values = true)]
    pub keys: Option<String>,
    /// Write the output to this file (atomically) instead of stdout.
    #[arg(long, value_name = "FILE")]
    pub output: Option<std::path::PathBuf>,
}

/// Largest screen `render` draws.
pub const MAX_SCREEN: u16 = 1000;

/// `N` or `NxM` (`X` too) with each count in `1..=max`: the one reader of `--size`
/// and `--grid`; `None` if `text` is not of that form.
pub(crate) fn counts(text: &str, max: usize) -> Option<(usize, Option<usize>)> {
    let count = |s: &str| {
        s.trim()
            .parse::<usize>()
            .ok()
            .filter(|n| (1..=max).contains(n))
    };
    match text.split_once(['x', 'X']) {
        Some((a, b)) => Some((count(a)?, Some(count(b)?))),
        None => Some((count(text)?, None)),
    }
}

/// `--size`: `render` has no terminal to grow, so a screen smaller than the app's
/// smallest layout is a usage error, not a screen saying "terminal too small".
fn screen_size(text: &str) -> Result<(u16, u16), ArgError> {
    let min = crate::tui::view::MIN_SIZE;
    let text_ = || text.to_string();
    match counts(text, usize::MAX) {
        Some((c, Some(r))) if c.max(r) > usize::from(MAX_SCREEN) => {
            Err(ArgError::LargeScreen { text: text_(), min })
        }
        Some((c, Some(r))) if c < usize::from(min.0) || r < usize::from(min.1) => {
            Err(ArgError::SmallScreen { text: text_(), min })
        }
        Some((c, Some(r))) => Ok((c as u16, r as u16)),
        _ => Err(ArgError::NotASize { text: text_(), min }),
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum SimulateFormat {
    Table,
    Json,
    Csv,
}

// clap shows the parser's error after the option's name.
fn speed(s: &str) -> Result<f64, UnitError> {
    parse_option(s, Dimension::Speed)
}
fn time(s: &str) -> Result<f64, UnitError> {
    parse_option(s, Dimension::Time)
}
/// The length one pixel of a video shows: above 0, and between a microscope's
/// 0.001 mm and 10 cm (a bench 10 m long across 100 pixels); a bare number is metres, so a
/// scale typed as pixels per metre (`957.86`) is refused, not taken as 958 m a pixel.
fn length(s: &str) -> Result<f64, ArgError> {
    match parse_option(s, Dimension::Length)? {
        v if (1e-6..=0.1).contains(&v) => Ok(v),
        v if v > 0.0 => Err(ArgError::PixelOutOfRange {
            text: s.to_string(),
            metres: v,
        }),
        _ => Err(ArgError::NotAPixel {
            text: s.to_string(),
        }),
    }
}
fn ratio(s: &str) -> Result<f64, UnitError> {
    parse_option(s, Dimension::Ratio)
}

/// Scene options shared by every command that takes a scene: `--preset` and one
/// option per row of the parameter table ([`PARAMS`]), made from that table.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct SceneArgs {
    /// A built-in preset's name or a preset file [default: paper-b4.9].
    pub preset: Option<String>,
    /// The values given on the command line, SI.
    pub values: SceneSpec,
}

impl clap::FromArgMatches for SceneArgs {
    fn from_arg_matches(matches: &clap::ArgMatches) -> Result<Self, clap::Error> {
        let mut args = SceneArgs::default();
        args.update_from_arg_matches(matches)?;
        Ok(args)
    }

    fn update_from_arg_matches(&mut self, matches: &clap::ArgMatches) -> Result<(), clap::Error> {
        if let Some(p) = matches.get_one::<String>("preset") {
            self.preset = Some(p.clone());
        }
        for p in &PARAMS {
            if let Some(&v) = matches.get_one::<f64>(p.name) {
                self.values.set(p.key, v);
            }
        }
        Ok(())
    }
}

impl Args for SceneArgs {
    fn augment_args(cmd: clap::Command) -> clap::Command {
        let cmd = cmd.arg(
            clap::Arg::new("preset")
                .long("preset")
                .value_name("NAME|FILE")
                .global(true)
                .help("Start from a built-in preset or a preset file [default: paper-b4.9]"),
        );
        PARAMS.iter().fold(cmd, |cmd, p| {
            let dim = p.dim;
            let arg = clap::Arg::new(p.name)
                .long(p.flag)
                .value_name(if dim == Dimension::Ratio { "X" } else { "Q" })
                .value_parser(move |s: &str| parse_option(s, dim))
                .allow_hyphen_values(true)
                .global(true)
                .help(p.help_text())
                // A run-up gives the speed: a height and a speed for one ball contradict.
                .conflicts_with_all(p.conflicts().map(|q| q.name));
            cmd.arg(arg)
        })
    }

    fn augment_args_for_update(cmd: clap::Command) -> clap::Command {
        Self::augment_args(cmd)
    }
}

impl ValueEnum for Method {
    fn value_variants<'a>() -> &'a [Self] {
        &[
            Method::Exact,
            Method::Euler,
            Method::SymplecticEuler,
            Method::Rk4,
            Method::Rk45,
            Method::Moreau,
        ]
    }

    fn to_possible_value(&self) -> Option<clap::builder::PossibleValue> {
        Some(clap::builder::PossibleValue::new(self.name()).help(self.description()))
    }
}

impl ValueEnum for Free {
    fn value_variants<'a>() -> &'a [Self] {
        &[
            Free::Mu,
            Free::V0,
            Free::Restitution,
            Free::RollingResistance,
        ]
    }

    fn to_possible_value(&self) -> Option<clap::builder::PossibleValue> {
        Some(clap::builder::PossibleValue::new(self.name()))
    }
}
