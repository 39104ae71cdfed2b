//! The command line (interface.md): raw flags parsed by clap, then turned into a
//! validated scene, then one command run into a string that is printed at once (so a
//! failure never leaves partial output).

use std::fmt::Write as _;

use serde::Serialize;

use crate::lab::{Lab, Resolved};
use crate::methods::Method;
use crate::physics::derived::{Derived, Summary};
use crate::physics::scene::{Scene, Span};
use crate::physics::solution::{Snapshot, Solution};
use crate::physics::story::After;
use crate::study::preset::{self, Preset};
use crate::study::story;
use crate::tui::{
    self,
    app::{App, Library},
    look,
    theme::ThemeChoice,
};

mod args;
mod data;
mod deliver;
pub mod entry;
mod error;
mod fit;
mod manual;
mod methods;
mod open;
mod progress;
mod states;
mod sweep;
mod track;
mod track_args;
mod video_data;
pub use crate::output::{self, write_atomically};
use crate::settings::params::{Key, PARAMS};
use crate::settings::units::{Dimension, fixed, show, show_below, sig_figs};
pub use args::*;
use deliver::deliver;
pub use error::{BadValue, CliError, Flag, Usage};
pub use open::{app, lab, opened, opened_tracking, scene_of_data};
use states::{csv_output, samples, state_rows};
pub use sweep::run_with_stop as sweep_with_stop;
pub use video_data::pending as pending_video;

/// What a command line asks for once it is valid.
pub enum Response {
    /// Text for stdout.
    Print(String),
    /// The interactive app on this scene.
    Interactive(Box<App>),
}

/// Runs a parsed command line.
pub fn run(cli: &Cli) -> Result<Response, CliError> {
    used_options(cli)?;
    outputs_apart(cli)?;
    video_units(cli)?;
    if matches!(cli.command, None | Some(Command::Tui | Command::Render(_))) {
        theme_choice(cli)?;
    }
    // A data file that names its scene gives it, under the options.
    let scene = &open::with_file_scene(&cli.scene, &cli.data)?;
    match &cli.command {
        None | Some(Command::Tui) => Ok(Response::Interactive(Box::new(app(scene, &cli.data)?))),
        Some(Command::Simulate(args)) => {
            deliver(args.output.as_deref(), || simulate(&cli.scene, args)).map(Response::Print)
        }
        Some(Command::Render(args)) => deliver(args.output.as_deref(), || {
            render(scene, &cli.data, args, cli.ascii)
        })
        .map(Response::Print),
        Some(Command::Compare(args)) => {
            methods::compare(scene, &cli.data, args).map(Response::Print)
        }
        Some(Command::Fit(args)) => deliver(args.output.as_deref(), || {
            fit::run(scene, &cli.scene, &cli.data, args)
        })
        .map(Response::Print),
        Some(Command::Sweep(args)) => sweep::run(&cli.scene, args).map(Response::Print),
        Some(Command::Track(args)) => track::run(&cli.scene, &cli.data, args).map(Response::Print),
        Some(Command::Data(args)) => data::run(args, &cli.scene, &cli.data).map(Response::Print),
        Some(Command::Presets) => Ok(Response::Print(presets())),
        Some(Command::Completions { shell }) => Ok(Response::Print(manual::completions(*shell))),
        Some(Command::Manpage) => Ok(Response::Print(manual::manpage())),
    }
}

/// What `cli`'s command takes: its name, and whether it takes scene options, data
/// options and the drawing options (`--ascii`, `--theme`).
fn takes(cli: &Cli) -> (&'static str, bool, bool, bool) {
    match &cli.command {
        None | Some(Command::Tui) => ("the app", true, true, true),
        Some(Command::Simulate(_)) => ("simulate", true, false, false),
        Some(Command::Render(_)) => ("render", true, true, true),
        Some(Command::Compare(_)) => ("compare", true, true, false),
        Some(Command::Fit(_)) => ("fit", true, true, false),
        Some(Command::Sweep(_)) => ("sweep", true, false, false),
        Some(Command::Track(_)) => ("track", true, false, false),
        // A video among its files is tracked for balls of R (the scene's).
        Some(Command::Data(a)) => (
            "data",
            a.files.iter().any(|p| video_data::is_video(p)),
            true,
            false,
        ),
        Some(Command::Presets) => ("presets", false, false, false),
        Some(Command::Completions { .. }) => ("completions", false, false, false),
        Some(Command::Manpage) => ("manpage", false, false, false),
    }
}

/// The scene options given on the command line, named as typed (`--mass` sets both
/// masses and is named `--mass`, not `--mass-left`), in the parameter table's order.
fn scene_options_given(cli: &Cli) -> Vec<&'static str> {
    let values = &cli.scene.values;
    values
        .given()
        .map(|(k, _)| values.given_as(k.param()).name)
        .collect()
}

/// Refuses a command whose output (`--output`, `--overlay`) is one of the files it
/// reads (the video, a data file, a preset file), or both outputs one file: the
/// input would be replaced by what is made of it, or half read.
fn outputs_apart(cli: &Cli) -> Result<(), CliError> {
    use crate::output::Clash;
    let reads = |kind: &'static str, file: &std::path::Path| Clash::Reads {
        kind,
        file: file.to_path_buf(),
    };
    let mut others: Vec<Clash> = cli
        .data
        .data
        .iter()
        .map(|p| reads("data file", p))
        .collect();
    if let Some(p) = cli.scene.preset.as_deref() {
        others.push(reads("preset file", std::path::Path::new(p)));
    }
    let mut outputs: Vec<(&std::path::Path, &'static str)> = Vec::new();
    let output = match &cli.command {
        Some(Command::Simulate(a)) => a.output.as_deref(),
        Some(Command::Render(a)) => a.output.as_deref(),
        Some(Command::Compare(a)) => a.output.as_deref(),
        Some(Command::Fit(a)) => a.output.as_deref(),
        Some(Command::Sweep(a)) => a.output.as_deref(),
        Some(Command::Track(a)) => {
            others.push(reads("video", &a.video));
            outputs.extend(a.overlay.as_deref().map(|o| (o, "--overlay")));
            a.output.as_deref()
        }
        _ => None,
    };
    outputs.extend(output.map(|o| (o, "--output")));
    for (path, flag) in outputs {
        crate::output::check_apart(path, crate::input::video::is_image(path), &others)?;
        // The outputs checked before it are read by no one, but one would replace
        // the other.
        others.push(Clash::Writes {
            flag,
            file: path.to_path_buf(),
        });
    }
    Ok(())
}

/// `--length-unit` and `--time-unit` with a video to read (`--data VIDEO`, or
/// `data` of videos only) are refused before it is tracked
/// (`open::units_of_a_video`).
fn video_units(cli: &Cli) -> Result<(), CliError> {
    let is_video = |p: &std::path::PathBuf| video_data::is_video(p);
    let video = match &cli.command {
        Some(Command::Data(a)) if a.files.iter().all(is_video) => a.files.first(),
        _ => cli.data.data.iter().find(|p| is_video(p)),
    };
    match video {
        Some(p) => open::units_of_a_video(&cli.data, p),
        None => Ok(()),
    }
}

/// The first global option given that `command` does not use, if any (clap's global
/// options are accepted anywhere; a command must not ignore one silently).
fn used_options(cli: &Cli) -> Result<(), CliError> {
    let (name, scene, data, ascii) = takes(cli);
    let d = &cli.data;
    let data_given = [
        ("data", !d.data.is_empty()),
        ("time_unit", d.time_unit.is_some()),
        ("speed_unit", d.speed_unit.is_some()),
        ("impact_at", d.impact_at.is_some()),
        ("track", !d.track.is_empty()),
        ("length_unit", d.length_unit.is_some()),
        ("scale", d.scale.is_some()),
        ("window", d.window.is_some()),
        ("fps", d.fps.is_some()),
        ("roi", d.roi.is_some()),
        ("ball_at", d.ball_at.is_some()),
    ];
    let given = scene_options_given(cli);
    let scene_given = cli
        .scene
        .preset
        .as_ref()
        .map(|_| "preset")
        .or_else(|| given.first().copied());
    // `track` reads --scale (the length a pixel shows), --fps, --roi and --ball-at,
    // its only data options.
    let track_scale = |id: &str| {
        matches!(id, "scale" | "fps" | "roi" | "ball_at")
            && matches!(cli.command, Some(Command::Track(_)))
    };
    let data_flag = data_given
        .iter()
        .find(|(id, g)| *g && !track_scale(id))
        .map(|(id, _)| *id);
    let data_command = matches!(cli.command, Some(Command::Data(_)));
    let unused = |id: &'static str, allowed| Usage::Unused {
        flag: Flag(id),
        by: name,
        allowed,
    };
    // `track` (and `data` on a video) takes R (for the scale) from a preset or
    // --radius, and nothing else of the scene: it tracks what was filmed, it
    // simulates nothing.
    let track_unused = matches!(cli.command, Some(Command::Track(_) | Command::Data(_)))
        .then(|| given.iter().copied().find(|&n| n != "radius"))
        .flatten();
    let span_given = given
        .iter()
        .copied()
        .find(|&n| matches!(n, "t_start" | "t_end"));
    let error = match (scene_given, data_flag) {
        (Some(id), _) if !scene => unused(id, "commands that take a scene"),
        _ if track_unused.is_some() => unused(
            track_unused.unwrap_or_default(),
            "commands that simulate a scene (track, and data on a video, take --radius and --preset only)",
        ),
        (_, Some(id)) if !data => unused(id, "compare, fit, render, data and the app"),
        // `data` takes its files as arguments.
        (_, Some(_)) if data_command && !d.data.is_empty() => unused(
            "data",
            "compare, fit, render and the app (data takes its files as arguments)",
        ),
        // Only --data gives these a file to read.
        (_, Some(id)) if d.data.is_empty() && !data_command => {
            Usage::WithoutData { flag: Flag(id) }
        }
        // A sweep solves each point from its impact to its end: no span.
        _ if matches!(cli.command, Some(Command::Sweep(_))) && span_given.is_some() => unused(
            span_given.unwrap_or_default(),
            "simulate, render, compare, fit and the app (a sweep solves each point to its end)",
        ),
        _ if !ascii && cli.ascii => unused("ascii", "render and the app"),
        _ if !ascii && cli.theme.is_some() => unused("theme", "render and the app"),
        // --fps is a video's: a data file has its times.
        _ if d.fps.is_some()
            && !matches!(cli.command, Some(Command::Track(_) | Command::Data(_)))
            && !d.data.iter().any(|p| video_data::is_video(p)) =>
        {
            unused("fps", "track, and --data VIDEO or a folder of frames")
        }
        // --roi and --ball-at are the tracker's: a data file is tracked already.
        _ if (d.roi.is_some() || d.ball_at.is_some())
            && !matches!(cli.command, Some(Command::Track(_) | Command::Data(_)))
            && !d.data.iter().any(|p| video_data::is_video(p)) =>
        {
            unused(
                if d.roi.is_some() { "roi" } else { "ball_at" },
                "track, and --data VIDEO or a folder of frames",
            )
        }
        _ => return Ok(()),
    };
    Err(error.into())
}

/// `--theme`, else `GROOVELAB_THEME`, else auto.
pub(crate) fn theme_choice(cli: &Cli) -> Result<ThemeChoice, CliError> {
    match cli.theme {
        Some(choice) => Ok(choice),
        None => look::parse_switch(std::env::var(look::SWITCH).ok().as_deref())
            .map_err(|source| BadValue::ThemeSwitch { source }.into()),
    }
}

/// `render`: the app's screen after `--keys`, at `--at`, as text.
pub fn render(
    scene_args: &SceneArgs,
    data: &DataArgs,
    args: &RenderArgs,
    ascii: bool,
) -> Result<String, CliError> {
    render_with(scene_args, data, args, ascii, Library::user())
}

/// [`render`] with the presets of `library` (tests use a folder of their own).
pub fn render_with(
    scene_args: &SceneArgs,
    data: &DataArgs,
    args: &RenderArgs,
    ascii: bool,
    library: Library,
) -> Result<String, CliError> {
    let mut app = opened(scene_args, data, library)?;
    // A screen dump writes no files: `w`, `W` and `s` say what they would write.
    app.write_no_files();
    let keys = match &args.keys {
        Some(script) => {
            tui::keys::parse_script(script).map_err(|source| BadValue::Keys { source })?
        }
        None => Vec::new(),
    };
    // Headless output waits for every analysis a key may act on: same input, same bytes.
    tui::replay_settled(&mut app, &keys);
    if let Some(at) = args.at {
        let (lo, hi) = (app.lab.solution.t_start, app.lab.solution.t_end);
        if !(lo..=hi).contains(&at) {
            return Err(BadValue::OutsideSpan {
                at,
                start: lo,
                end: hi,
            }
            .into());
        }
        app.t = at;
    }
    app.playing = false;
    let (cols, rows) = args.size;
    // Headless output is text without colours: the monochrome theme, whose curves are
    // told apart by letters, whatever `--theme` (headless, its auto is dark) or
    // NO_COLOR say; the same input gives the same bytes.
    let theme = tui::theme::Theme::new(tui::theme::Glyphs::new(ascii), true);
    Ok(tui::screen::to_text(&app, cols, rows, &theme))
}

/// `--dt`, `--tol` and `--epsilon` only where the method uses them: a setting the run
/// would ignore is an error, not a silent no-op.
fn method_options(args: &SimulateArgs) -> Result<(), CliError> {
    let m = args.method;
    let uses = [
        (
            "dt",
            args.dt.is_some(),
            m != Method::Exact,
            error::UsedBy::TimeStepping,
        ),
        (
            "tol",
            args.tol.is_some(),
            m == Method::Rk45,
            error::UsedBy::Method(Method::Rk45),
        ),
        (
            "epsilon",
            args.epsilon.is_some(),
            m == Method::Rk4,
            error::UsedBy::Method(Method::Rk4),
        ),
    ];
    match uses.into_iter().find(|(_, given, used, _)| *given && !used) {
        Some((id, _, _, allowed)) => Err(Usage::NotForMethod {
            flag: Flag(id),
            method: m,
            allowed,
        }
        .into()),
        None => Ok(()),
    }
}

/// `simulate`: the run of the lab's snapshot of the scene the options give (the same
/// scene, span and story the app shows for them), or a time-stepping method's run over
/// the snapshot's span.
pub fn simulate(scene_args: &SceneArgs, args: &SimulateArgs) -> Result<String, CliError> {
    let lab = Lab::new(scene_args.settings()?, None)?;
    method_options(args)?;
    if args.method != Method::Exact {
        let settings = methods::settings(args.dt, args.tol, args.epsilon)?;
        return methods::simulate_method(&lab.solution, args, &settings);
    }
    let samples = match args.sample {
        None => None,
        Some(dt) => Some(samples(&lab.solution, dt)?),
    };
    Ok(match args.format {
        SimulateFormat::Json => json(&lab.solution, &lab.derived, samples.as_deref()),
        SimulateFormat::Csv => csv_output(&lab.solution, samples.as_deref())?,
        SimulateFormat::Table => table(lab.preset(), lab.resolved(), samples.as_deref()),
    })
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

/// `simulate`'s table: the scene, what the run does, and its events (and samples),
/// as the snapshot holds them.
fn table(preset: &Preset, now: &Resolved, samples: Option<&[Snapshot]>) -> String {
    let mut out = String::new();
    scene_lines(&mut out, preset, now);
    story_lines(&mut out, now);
    run_lines(&mut out, &now.solution);
    let _ = writeln!(out);
    state_rows(&mut out, &now.solution, samples);
    out
}

/// `ratio` (below `limit`) to three places, or to as many more as tell it from
/// `limit` (b/R = 1.9999999 beside 2, not 2.000).
fn ratio_below(ratio: f64, limit: f64) -> String {
    (3..=16)
        .map(|places| format!("{ratio:.places$}"))
        .find(|text| text.parse::<f64>().is_ok_and(|v| v < limit))
        .unwrap_or_else(|| format!("{ratio}"))
}

/// The preset (its description only for its own scene: it tells of that scene), the
/// scene, the balls and the derived values with the paper's regime.
fn scene_lines(out: &mut String, preset: &Preset, now: &Resolved) {
    let (sc, derived) = (&now.scene, &now.derived);
    let len = |v: f64| show(v, Dimension::Length);
    let changed = match preset.spec.resolve() {
        Ok((own, own_span)) => crate::lab::differences((&own, &own_span), (&now.scene, &now.span)),
        Err(_) => Vec::new(),
    };
    if changed.is_empty() {
        let _ = writeln!(out, "preset   {}: {}", preset.name, preset.description);
    } else {
        let changed: Vec<String> = changed
            .iter()
            // Written as the scene line below writes it (μ_k, not mu_k).
            .map(|(label, was, now)| {
                format!(
                    "{} = {now} (was {was})",
                    label.trim_end().replace("mu", "μ")
                )
            })
            .collect();
        let _ = writeln!(
            out,
            "preset   {} changed by the options: {}",
            preset.name,
            changed.join(", ")
        );
    }
    let b_star = derived
        .b_star
        .map_or("none (e < 2/5)".to_string(), |b| len(b).to_string());
    // The groove's and the scene's own values, from the parameter table (the balls'
    // follow on lines of their own).
    let values: Vec<String> = PARAMS
        .iter()
        .filter(|p| p.is_own() && p.replaces.is_none() && p.of_scene() && !p.of_ball())
        .filter_map(|p| {
            let v = (p.get)(sc, &now.span)?;
            let mut text = format!("{} = {}", p.screen_label(), show(v, p.dim));
            if p.key == Key::Width {
                // Just under 2R, b and b/R keep the digits that tell them from 2R, 2.
                text = format!(
                    "{} = {} (b/R = {}, b* = {b_star})",
                    p.screen_label(),
                    show_below(v, 2.0 * sc.radius, p.dim),
                    ratio_below(sc.width / sc.radius, 2.0)
                );
            }
            Some(text)
        })
        .collect();
    let _ = writeln!(out, "scene    {}", values.join("   "));
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
}

/// What the run does (against the paper's criterion and the measured series' rest
/// band, if the scene has one) and the left ball after the first impact with the
/// forces then.
fn story_lines(out: &mut String, now: &Resolved) {
    let (solution, derived, story) = (&now.solution, &now.derived, &now.story);
    // What this run does, beside the paper's criterion above.
    let outcome = now.summary.outcome;
    let _ = writeln!(
        out,
        "outcome  {}: {}{}",
        outcome.name(),
        story::outcome_says(outcome, solution, derived),
        story
            .criterion_note
            .as_ref()
            .map_or(String::new(), |n| format!(" ({n})"))
    );
    // Data of another groove are never compared without saying so.
    if let Some(other) = &now.other_groove {
        let _ = writeln!(out, "data     {}", other.describe());
    }
    // Against the measured series: can its data tell this regime from rest?
    // The verdict judges the paper's criterion's regime; where this run does
    // otherwise (rolling resistance stops it, friction presses the pair), both are
    // named, not "outcome stopped" over "verdict recollide" unexplained.
    if now.rest_band.is_some() {
        let v = &story.verdict;
        let verdict = match (&story.criterion_note, v.impact, v.margin("±")) {
            (Some(_), true, margin) => format!(
                "{} by the paper's criterion{}; this run: {}",
                v.regime.name(),
                if margin.is_empty() {
                    String::new()
                } else {
                    format!(" ({margin})")
                },
                outcome.name()
            ),
            _ => v.text("±"),
        };
        let _ = writeln!(out, "verdict  {verdict}");
    }
    if let Some(rec) = derived.left_after_impact {
        // The closed forms only where the exact run bears them out; else its events.
        match &story.after {
            Some(After::Interrupted(i)) => {
                let _ = writeln!(
                    out,
                    "left ball after the first impact: {}",
                    i.clauses("∞").join("; ")
                );
            }
            _ => {
                let _ = writeln!(out, "{}", recovery_line(&rec));
            }
        }
        let f = derived.forces;
        let _ = writeln!(
            out,
            "forces   |N_A| = {} N   F_net = {} N (x)   τ_net = {} N m (z)   a_cm = {} m/s²   a_t = {} m/s²",
            sig_figs(f.normal_a.norm(), 4),
            sig_figs(f.net.x, 4),
            sig_figs(f.torque.z, 4),
            sig_figs(rec.a_cm, 4),
            sig_figs(rec.a_t, 4)
        );
    }
}

/// The impacts, precision notes and the energy balance of the run.
fn run_lines(out: &mut String, solution: &Solution) {
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
    for note in story::precision_notes(solution) {
        let _ = writeln!(out, "note     {note}");
    }
    let (e0, e1) = (summary.energy_start, summary.energy_end);
    let _ = writeln!(
        out,
        "energy   {} J at t = {}; at t = {}: kinetic {} J, lost to friction {} J, in impacts {} J, to rolling resistance {} J",
        fixed(e0.total(), 5),
        show(solution.t_start, Dimension::Time),
        show(solution.t_end, Dimension::Time),
        fixed(e1.kinetic(), 5),
        fixed(e1.lost.friction, 5),
        fixed(e1.lost.impacts, 5),
        fixed(e1.lost.rolling_resistance, 5)
    );
}

/// The closed-form recovery of the left ball, in one line.
fn recovery_line(rec: &crate::physics::derived::Recovery) -> String {
    let len = |v: f64| show(v, Dimension::Length);
    // "Back" only for a ball the impact sent away: a heavy ball hitting a light one
    // (steel-and-glass) goes on, and equal balls stop first.
    let heading = if rec.v_roll > 0.0 && rec.after_impact.v < 0.0 {
        "back toward the other ball"
    } else if rec.v_roll > 0.0 {
        "toward the other ball"
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
    line
}

fn presets() -> String {
    let (presets, errors) = crate::input::preset::all();
    let width = presets.iter().map(|p| p.name.len()).max().unwrap_or(0);
    let mut out = String::new();
    for p in &presets {
        let tag = match &p.origin {
            preset::PresetOrigin::BuiltIn => String::new(),
            // `--preset NAME` finds the built-in first: say so where a file has its name.
            preset::PresetOrigin::File(path)
                if presets
                    .iter()
                    .any(|q| q.origin == preset::PresetOrigin::BuiltIn && q.name == p.name) =>
            {
                format!(
                    " [{}; hidden: --preset {} is the built-in one, give the file's path or rename it]",
                    path.display(),
                    p.name
                )
            }
            preset::PresetOrigin::File(path) => format!(" [{}]", path.display()),
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
