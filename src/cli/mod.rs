//! The command line (interface.md): raw flags parsed by clap, then turned into a
//! validated scene, then one command run into a string that is printed at once (so a
//! failure never leaves partial output).

use std::fmt::Write as _;

use clap::{Args, Parser, Subcommand, ValueEnum};
use serde::Serialize;

use crate::input::params::{Key, SceneSpec};
use crate::input::preset::{self, Preset};
use crate::methods::Method;
use crate::physics::derived::{Derived, Summary};
use crate::physics::engine;
use crate::physics::scene::{Scene, Span};
use crate::physics::solution::{Snapshot, Solution};
use crate::tui::{self, app::App};

pub mod entry;
mod fit;
mod methods;
mod progress;
mod sweep;
use crate::input::units::{Dimension, parse_quantity, show, significant};
pub use methods::write_atomically;

/// Most samples `--sample` may ask for.
pub const MAX_SAMPLES: usize = 1_000_000;

#[derive(Parser, Debug)]
#[command(
    name = "groovelab",
    version,
    about = "Two balls colliding in a groove: exact simulation, charts and lab tools",
    long_about = "Two identical balls roll toward each other in a horizontal groove, collide, and \
                  then depart, stop, or come back again and again. groovelab solves the motion \
                  exactly (Gröber & Sniatecki) and shows why."
)]
pub struct Cli {
    #[command(subcommand)]
    pub command: Option<Command>,
    #[command(flatten)]
    pub scene: SceneArgs,
    /// Pure 7-bit ASCII drawing (app and render) instead of Unicode.
    #[arg(long, global = true)]
    pub ascii: bool,
    #[command(flatten)]
    pub data: DataArgs,
}

/// Measured data from a file, for `fit`, the app and `render`.
#[derive(Args, Debug, Clone, Default)]
pub struct DataArgs {
    /// A CSV of the left ball: columns t, v_cm, v_t found by header (comma or
    /// semicolon, decimal commas allowed) [default: the preset's series].
    #[arg(long, value_name = "FILE", global = true)]
    pub data: Option<std::path::PathBuf>,
    /// Time unit of the file when its header gives none (e.g. ms) [default: s].
    #[arg(long, value_name = "UNIT", global = true)]
    pub time_unit: Option<String>,
    /// Speed unit of the file when its header gives none (e.g. cm/s) [default: m/s].
    #[arg(long, value_name = "UNIT", global = true)]
    pub speed_unit: Option<String>,
    /// Time of the first impact in the file [default: detected from v_cm].
    #[arg(long, value_name = "T", value_parser = time, allow_hyphen_values = true, global = true)]
    pub impact_at: Option<f64>,
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
    /// Fit the model to measured data (a preset's, or a CSV file).
    Fit(FitArgs),
    /// Regime map over one or two scene parameters.
    Sweep(SweepArgs),
    /// List the built-in and user presets.
    Presets,
}

#[derive(Args, Debug)]
pub struct SimulateArgs {
    /// Output format.
    #[arg(long, value_enum, default_value_t = Format::Table)]
    pub format: Format,
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
    pub free: Option<Vec<crate::study::fit::Free>>,
    /// Output: a table, JSON, or an SVG figure (data, fitted model, residuals).
    #[arg(long, value_enum, default_value_t = FitFormat::Table)]
    pub format: FitFormat,
    /// Write the output to this file (atomically) instead of stdout.
    #[arg(long, value_name = "FILE")]
    pub output: Option<std::path::PathBuf>,
}

#[derive(Args, Debug)]
pub struct SweepArgs {
    /// First parameter and range, NAME=LO..HI with units (e.g. width=0..5.4cm).
    #[arg(long, value_name = "NAME=LO..HI", allow_hyphen_values = true)]
    pub x: String,
    /// Second parameter and range (e.g. restitution=0.3..1); omit for a 1-D sweep.
    #[arg(long, value_name = "NAME=LO..HI", allow_hyphen_values = true)]
    pub y: Option<String>,
    /// Grid points, NX or NXxNY.
    #[arg(long, value_name = "NXxNY", default_value = "200x100")]
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
}

/// Largest screen `render` draws.
pub const MAX_SCREEN: u16 = 1000;

fn screen_size(text: &str) -> Result<(u16, u16), String> {
    let bad = || {
        format!("'{text}' is not a size, expected COLSxROWS such as 120x40 (1..={MAX_SCREEN} each)")
    };
    let (c, r) = text.split_once(['x', 'X']).ok_or_else(bad)?;
    let c: u16 = c.trim().parse().map_err(|_| bad())?;
    let r: u16 = r.trim().parse().map_err(|_| bad())?;
    if c == 0 || r == 0 || c > MAX_SCREEN || r > MAX_SCREEN {
        return Err(bad());
    }
    Ok((c, r))
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum Format {
    Table,
    Json,
    Csv,
}

fn quantity(text: &str, dim: Dimension) -> Result<f64, String> {
    parse_quantity(text, dim).map_err(|e| e.to_string())
}
fn length(s: &str) -> Result<f64, String> {
    quantity(s, Dimension::Length)
}
fn mass(s: &str) -> Result<f64, String> {
    quantity(s, Dimension::Mass)
}
fn speed(s: &str) -> Result<f64, String> {
    quantity(s, Dimension::Speed)
}
fn time(s: &str) -> Result<f64, String> {
    quantity(s, Dimension::Time)
}
fn ratio(s: &str) -> Result<f64, String> {
    quantity(s, Dimension::Ratio)
}
fn acceleration(s: &str) -> Result<f64, String> {
    quantity(s, Dimension::Acceleration)
}

/// Scene options shared by every command that takes a scene.
#[derive(Args, Debug, Clone, Default)]
pub struct SceneArgs {
    /// Start from a built-in preset or a preset file [default: paper-b4.9].
    #[arg(long, value_name = "NAME|FILE", global = true)]
    pub preset: Option<String>,
    /// Ball radius R (e.g. 2.75cm).
    #[arg(long, value_name = "Q", value_parser = length, allow_hyphen_values = true, global = true)]
    pub radius: Option<f64>,
    /// Groove width b, 0 ≤ b < 2R (e.g. 4.9cm).
    #[arg(long, value_name = "Q", value_parser = length, allow_hyphen_values = true, global = true)]
    pub width: Option<f64>,
    /// Mass of both balls (e.g. 167g).
    #[arg(long, value_name = "Q", value_parser = mass, allow_hyphen_values = true, global = true)]
    pub mass: Option<f64>,
    /// Mass of the left ball.
    #[arg(long, value_name = "Q", value_parser = mass, allow_hyphen_values = true, global = true)]
    pub mass_left: Option<f64>,
    /// Mass of the right ball.
    #[arg(long, value_name = "Q", value_parser = mass, allow_hyphen_values = true, global = true)]
    pub mass_right: Option<f64>,
    /// Kinetic friction coefficient μ_k ≥ 0.
    #[arg(long, value_name = "X", value_parser = ratio, allow_hyphen_values = true, global = true)]
    pub mu: Option<f64>,
    /// Speed of both balls toward the impact point just before it (e.g. 60cm/s).
    #[arg(long, value_name = "Q", value_parser = speed, allow_hyphen_values = true, global = true,
          conflicts_with = "height")]
    pub v0: Option<f64>,
    /// Speed of the left ball toward the impact point.
    #[arg(long, value_name = "Q", value_parser = speed, allow_hyphen_values = true, global = true,
          conflicts_with = "height")]
    pub v0_left: Option<f64>,
    /// Speed of the right ball toward the impact point.
    #[arg(long, value_name = "Q", value_parser = speed, allow_hyphen_values = true, global = true,
          conflicts_with = "height")]
    pub v0_right: Option<f64>,
    /// Release height on the run-up instead of v0 (both balls).
    #[arg(long, value_name = "Q", value_parser = length, allow_hyphen_values = true, global = true)]
    pub height: Option<f64>,
    /// Coefficient of restitution e, 0..1 [default: 1].
    #[arg(long, value_name = "X", value_parser = ratio, allow_hyphen_values = true, global = true)]
    pub restitution: Option<f64>,
    /// Rolling-resistance coefficient c_rr ≥ 0 [default: 0].
    #[arg(long, value_name = "X", value_parser = ratio, allow_hyphen_values = true, global = true)]
    pub rolling_resistance: Option<f64>,
    /// Gravity [default: 9.81 m/s²].
    #[arg(long, value_name = "Q", value_parser = acceleration, allow_hyphen_values = true, global = true)]
    pub g: Option<f64>,
    /// Start of the simulated span, ≤ 0 [default: -0.2 s].
    #[arg(long, value_name = "Q", value_parser = time, allow_hyphen_values = true, global = true)]
    pub t_start: Option<f64>,
    /// End of the simulated span [default: the preset's, or past the last event].
    #[arg(long, value_name = "Q", value_parser = time, allow_hyphen_values = true, global = true)]
    pub t_end: Option<f64>,
}

impl SceneArgs {
    /// The command line as a settings layer.
    pub fn spec(&self) -> SceneSpec {
        let mut spec = SceneSpec::default();
        let given = [
            (Key::Radius, self.radius),
            (Key::Width, self.width),
            (Key::Mass, self.mass),
            (Key::MassLeft, self.mass_left),
            (Key::MassRight, self.mass_right),
            (Key::Mu, self.mu),
            (Key::V0, self.v0),
            (Key::V0Left, self.v0_left),
            (Key::V0Right, self.v0_right),
            (Key::Height, self.height),
            (Key::Restitution, self.restitution),
            (Key::RollingResistance, self.rolling_resistance),
            (Key::G, self.g),
            (Key::TStart, self.t_start),
            (Key::TEnd, self.t_end),
        ];
        for (key, value) in given {
            if let Some(v) = value {
                spec.set(key, v);
            }
        }
        spec
    }

    /// The preset these options start from, and the scene they make.
    pub fn resolve(&self) -> Result<(Preset, Scene, Span), CliError> {
        let preset = Preset::load(self.preset.as_deref().unwrap_or(preset::DEFAULT))
            .map_err(|e| CliError::Invalid(e.to_string()))?;
        let (scene, span) = preset
            .spec
            .over(&self.spec())
            .resolve()
            .map_err(|e| CliError::Invalid(e.to_string()))?;
        Ok((preset, scene, span))
    }
}

/// A failure the user can act on: printed as one `error:` line, exit status 2.
#[derive(Debug, thiserror::Error)]
pub enum CliError {
    #[error("{0}")]
    Invalid(String),
    #[error("{0}")]
    Io(#[from] std::io::Error),
    #[error("interrupted: nothing was written")]
    Interrupted,
}

/// What a command line asks for once it is valid.
pub enum Outcome {
    /// Text for stdout.
    Print(String),
    /// The interactive app on this scene.
    Interactive(Box<App>),
}

/// Runs a parsed command line.
pub fn run(cli: &Cli) -> Result<Outcome, CliError> {
    match &cli.command {
        None | Some(Command::Tui) => {
            Ok(Outcome::Interactive(Box::new(app(&cli.scene, &cli.data)?)))
        }
        Some(Command::Simulate(args)) => simulate(&cli.scene, args).map(Outcome::Print),
        Some(Command::Render(args)) => {
            render(&cli.scene, &cli.data, args, cli.ascii).map(Outcome::Print)
        }
        Some(Command::Compare(args)) => methods::compare(&cli.scene, args).map(Outcome::Print),
        Some(Command::Fit(args)) => fit::run(&cli.scene, &cli.data, args).map(Outcome::Print),
        Some(Command::Sweep(args)) => sweep::run(&cli.scene, args).map(Outcome::Print),
        Some(Command::Presets) => Ok(Outcome::Print(presets())),
    }
}

/// The app on the scene the options describe, with `--data` replacing the preset's
/// measured series.
pub fn app(scene_args: &SceneArgs, data: &DataArgs) -> Result<App, CliError> {
    let (mut preset, scene, span) = scene_args.resolve()?;
    if data.data.is_some() {
        preset.measured = Some(fit::measured(&preset, data)?);
    }
    Ok(App::new(preset, scene, span))
}

/// `render`: the app's screen after `--keys`, at `--at`, as text.
pub fn render(
    scene_args: &SceneArgs,
    data: &DataArgs,
    args: &RenderArgs,
    ascii: bool,
) -> Result<String, CliError> {
    let mut app = app(scene_args, data)?;
    let keys = match &args.keys {
        Some(script) => tui::keys::parse_script(script).map_err(CliError::Invalid)?,
        None => Vec::new(),
    };
    tui::replay(&mut app, &keys);
    if let Some(at) = args.at {
        let (lo, hi) = (app.solution.t_start, app.solution.t_end);
        if !(lo..=hi).contains(&at) {
            return Err(CliError::Invalid(format!(
                "--at {} is outside the simulated span, allowed {} … {}",
                show(at, Dimension::Time),
                show(lo, Dimension::Time),
                show(hi, Dimension::Time)
            )));
        }
        app.t = at;
    }
    app.playing = false;
    let (cols, rows) = args.size;
    // Headless output has no colours; NO_COLOR does not change the text.
    let theme = tui::theme::Theme::new(tui::theme::Glyphs::new(ascii), true);
    Ok(tui::view::to_text(&app, cols, rows, &theme))
}

pub fn simulate(scene_args: &SceneArgs, args: &SimulateArgs) -> Result<String, CliError> {
    let (preset, scene, span) = scene_args.resolve()?;
    if args.method != Method::Exact {
        let settings = methods::settings(args.dt, args.tol, args.epsilon)?;
        return methods::simulate_method(&scene, &span, args, &settings);
    }
    let solution = engine::solve(&scene, &span);
    let samples = match args.sample {
        None => None,
        Some(dt) => Some(samples(&solution, dt)?),
    };
    let derived = Derived::of(&scene);
    Ok(match args.format {
        Format::Json => json(&solution, &derived, samples.as_deref()),
        Format::Csv => csv_output(&solution, samples.as_deref())?,
        Format::Table => table(&preset, &solution, &derived, samples.as_deref()),
    })
}

fn samples(solution: &Solution, dt: f64) -> Result<Vec<Snapshot>, CliError> {
    let count = (solution.t_end - solution.t_start) / dt;
    if dt <= 0.0 || count > MAX_SAMPLES as f64 {
        return Err(CliError::Invalid(format!(
            "--sample {} gives {} samples over {} … {}, allowed a step > 0 giving at most {MAX_SAMPLES} samples",
            show(dt, Dimension::Time),
            if dt > 0.0 {
                significant(count, 3)
            } else {
                "no".into()
            },
            show(solution.t_start, Dimension::Time),
            show(solution.t_end, Dimension::Time),
        )));
    }
    Ok(solution.sample(dt))
}

#[derive(Serialize)]
struct SimulationJson<'a> {
    scene: &'a Scene,
    span: Span,
    derived: &'a Derived,
    summary: Summary,
    method: &'a str,
    events: Vec<&'a crate::physics::solution::Event>,
    #[serde(skip_serializing_if = "Option::is_none")]
    samples: Option<&'a [Snapshot]>,
    #[serde(rename = "final")]
    final_state: Snapshot,
}

fn json(solution: &Solution, derived: &Derived, samples: Option<&[Snapshot]>) -> String {
    let doc = SimulationJson {
        scene: &solution.scene,
        span: Span {
            t_start: solution.t_start,
            t_end: Some(solution.t_end),
        },
        derived,
        summary: Summary::of(solution),
        method: solution.method,
        events: solution.visible_events().collect(),
        samples,
        final_state: solution.at(solution.t_end),
    };
    let mut s = serde_json::to_string_pretty(&doc).expect("plain data serializes");
    s.push('\n');
    s
}

/// CSV: the samples if `--sample` is given, else the events. SI units.
fn csv_output(solution: &Solution, samples: Option<&[Snapshot]>) -> Result<String, CliError> {
    let mut w = csv::Writer::from_writer(Vec::new());
    let state_cols = [
        "x_left", "v_left", "u_left", "x_right", "v_right", "u_right",
    ];
    let values = |s: &Snapshot| {
        [
            s.left.x, s.left.v, s.left.u, s.right.x, s.right.v, s.right.u,
        ]
        .map(|v| v.to_string())
    };
    let io = |e: csv::Error| CliError::Io(e.into());
    match samples {
        Some(samples) => {
            w.write_record(std::iter::once("t").chain(state_cols))
                .map_err(io)?;
            for s in samples {
                w.write_record(std::iter::once(s.t.to_string()).chain(values(s)))
                    .map_err(io)?;
            }
        }
        None => {
            w.write_record(["t", "kind", "ball"].into_iter().chain(state_cols))
                .map_err(io)?;
            for e in solution.visible_events() {
                let snap = Snapshot {
                    t: e.t,
                    left: e.left,
                    right: e.right,
                };
                let head = [e.t.to_string(), e.kind.name().into(), e.ball.name().into()];
                w.write_record(head.into_iter().chain(values(&snap)))
                    .map_err(io)?;
            }
        }
    }
    let bytes = w.into_inner().map_err(|e| CliError::Io(e.into_error()))?;
    Ok(String::from_utf8(bytes).expect("csv of ASCII numbers"))
}

fn table(
    preset: &Preset,
    solution: &Solution,
    derived: &Derived,
    samples: Option<&[Snapshot]>,
) -> String {
    let sc = &solution.scene;
    let len = |v: f64| show(v, Dimension::Length);
    let mut out = String::new();
    let _ = writeln!(out, "preset   {}: {}", preset.name, preset.description);
    let b_star = derived
        .b_star
        .map_or("none (e < 2/5)".to_string(), |b| len(b).to_string());
    let _ = writeln!(
        out,
        "scene    R = {}   b = {} (b/R = {:.3}, b* = {})   μ_k = {}   e = {}   c_rr = {}   g = {}",
        len(sc.radius),
        len(sc.width),
        sc.width / sc.radius,
        b_star,
        significant(sc.mu, 4),
        significant(sc.restitution, 4),
        significant(sc.rolling_resistance, 4),
        show(sc.g, Dimension::Acceleration),
    );
    for (name, ball) in [("left ", sc.left), ("right", sc.right)] {
        let _ = writeln!(
            out,
            "{name}    m = {}   v0 = {} toward the impact",
            show(ball.mass, Dimension::Mass),
            show(ball.v0, Dimension::Speed)
        );
    }
    let _ = writeln!(
        out,
        "derived  k = {:.4}   r = {}   D = 5k²/2 = {:.4}   regime: {} ({}; b* = {})",
        derived.k,
        len(derived.r),
        derived.d,
        derived.regime.name(),
        derived.why(),
        b_star
    );
    if let Some(rec) = derived.left_after_impact {
        let heading = if rec.v_roll > 0.0 {
            "back toward the other ball"
        } else if rec.v_roll < 0.0 {
            "away from the other ball"
        } else {
            "at rest"
        };
        let mut line = format!(
            "left ball after the first impact: rolls again after t' = {} at v' = {} ({heading}), x' = {}",
            show(rec.t_roll, Dimension::Time),
            show(rec.v_roll, Dimension::Speed),
            len(rec.x_roll)
        );
        if let Some(t) = rec.t_pure_gliding {
            let _ = write!(line, "; pure gliding at t_r = {}", show(t, Dimension::Time));
        }
        if let Some(t) = rec.t_pure_slipping {
            let _ = write!(
                line,
                "; pure slipping at t_t = {}",
                show(t, Dimension::Time)
            );
        }
        let _ = writeln!(out, "{line}");
        let f = derived.forces;
        let _ = writeln!(
            out,
            "forces   |N_A| = {:.4} N   F_net = {:.4} N (x)   τ_net = {:.3e} N m (z)   a_cm = {} m/s²   a_t = {} m/s²",
            f.normal_a.norm(),
            f.net.x,
            f.torque.z,
            significant(rec.a_cm, 4),
            significant(rec.a_t, 4)
        );
    }
    let summary = Summary::of(solution);
    let accumulation = summary.accumulation_time.map_or(String::new(), |t| {
        format!(", accumulating at T∞ = {}", show(t, Dimension::Time))
    });
    let _ = writeln!(
        out,
        "impacts  {} resolved{}{}",
        summary.impacts,
        accumulation,
        if summary.truncated {
            " (event budget reached: motion not finished)"
        } else {
            ""
        }
    );
    let (e0, e1) = (summary.energy_start, summary.energy_end);
    let _ = writeln!(
        out,
        "energy   {:.5} J at t = {}; at t = {}: kinetic {:.5} J, lost to friction {:.5} J, in impacts {:.5} J, to rolling resistance {:.5} J",
        e0.total(),
        show(solution.t_start, Dimension::Time),
        show(solution.t_end, Dimension::Time),
        e1.kinetic(),
        e1.lost.friction,
        e1.lost.impacts,
        e1.lost.rolling_resistance
    );
    let _ = writeln!(out);
    let header = state_header();
    let row = state_row;
    let _ = writeln!(out, "{header}");
    for e in solution.visible_events() {
        let _ = writeln!(
            out,
            "{}",
            row(e.t, e.kind.name(), e.ball.name(), e.left, e.right)
        );
    }
    if let Some(samples) = samples {
        let _ = writeln!(out, "\nsamples\n{header}");
        for s in samples {
            let _ = writeln!(out, "{}", row(s.t, "", "", s.left, s.right));
        }
    }
    out
}

fn presets() -> String {
    let (presets, errors) = Preset::all();
    let width = presets.iter().map(|p| p.name.len()).max().unwrap_or(0);
    let mut out = String::new();
    for p in &presets {
        let tag = match &p.origin {
            preset::Origin::BuiltIn => String::new(),
            preset::Origin::File(path) => format!(" [{}]", path.display()),
        };
        let data = if p.measured.is_some() {
            " (with measured data)"
        } else {
            ""
        };
        let _ = writeln!(out, "{:<width$}  {}{data}{tag}", p.name, p.description);
    }
    for e in errors {
        let _ = writeln!(out, "(skipped: {e})");
    }
    out
}

/// Header of the tables of both balls' states (events and samples).
pub(crate) fn state_header() -> String {
    format!(
        "{:>10}  {:<14} {:<6} {:>9} {:>9} {:>9}  {:>9} {:>9} {:>9}",
        "t (s)",
        "event",
        "ball",
        "x_L (cm)",
        "v_L (m/s)",
        "u_L (m/s)",
        "x_R (cm)",
        "v_R (m/s)",
        "u_R (m/s)"
    )
}

/// One row of those tables.
pub(crate) fn state_row(
    t: f64,
    kind: &str,
    ball: &str,
    l: crate::physics::model::BallState,
    r: crate::physics::model::BallState,
) -> String {
    format!(
        "{t:>10.6}  {kind:<14} {ball:<6} {:>9.4} {:>9.5} {:>9.5}  {:>9.4} {:>9.5} {:>9.5}",
        l.x * 100.0,
        l.v,
        l.u,
        r.x * 100.0,
        r.v,
        r.u
    )
}
