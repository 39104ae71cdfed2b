//! Helpers shared by the integration tests.
#![allow(dead_code)]

use groovelab::cli::{self, CliError, DataArgs, RenderArgs, SceneArgs};
use groovelab::lab::Lab;
use groovelab::physics::scene::{Ball, Scene, Span};
use groovelab::settings::params::Key;
use groovelab::settings::spec::SceneSpec;
use groovelab::tui::app::{App, Library, ROWS};
use groovelab::tui::screen;
use groovelab::tui::theme::{Glyphs, Theme};
use groovelab::tui::{keys, replay, replay_settled};

/// The paper's symmetric scene with the given width, friction, speed and restitution.
pub fn symmetric(radius: f64, width: f64, mu: f64, v0: f64, e: f64) -> Scene {
    Scene {
        radius,
        width,
        mu,
        restitution: e,
        left: Ball { mass: 0.167, v0 },
        right: Ball { mass: 0.167, v0 },
        ..Scene::default()
    }
}

pub fn span() -> Span {
    Span {
        t_start: -0.2,
        t_end: None,
    }
}

/// `|a − b| ≤ rel · max(|a|, |b|, scale)`: relative, but not below `scale` for values
/// that are differences of larger numbers.
pub fn close(a: f64, b: f64, rel: f64, scale: f64) -> bool {
    (a - b).abs() <= rel * a.abs().max(b.abs()).max(scale)
}

#[macro_export]
macro_rules! assert_close {
    ($a:expr, $b:expr, $rel:expr, $scale:expr, $($msg:tt)*) => {{
        let (a, b) = ($a, $b);
        assert!(
            $crate::common::close(a, b, $rel, $scale),
            "{} vs {} (rel {:e}): {}",
            a,
            b,
            ((a - b) / b).abs(),
            format!($($msg)*)
        );
    }};
}

/// A property test's settings: `PROPTEST_CASES` cases if set (a long run asks for
/// more), else `default`, chosen for what one case of that property costs.
pub fn cases(default: u32) -> proptest::test_runner::Config {
    let cases = std::env::var("PROPTEST_CASES")
        .ok()
        .and_then(|c| c.parse().ok())
        .unwrap_or(default);
    proptest::test_runner::Config::with_cases(cases)
}

// ---- The command ---------------------------------------------------------------------

/// Runs the binary with `args`, without the user's presets (a folder that does not
/// exist) or cache, and returns what it printed.
pub fn groovelab(args: &[&str]) -> std::process::Output {
    std::process::Command::new(env!("CARGO_BIN_EXE_groovelab"))
        .args(args)
        .env("GROOVELAB_PRESETS", "/nonexistent-groovelab-presets")
        // Tracked videos are kept under the test's target, never the user's cache.
        .env(
            "XDG_CACHE_HOME",
            concat!(env!("CARGO_TARGET_TMPDIR"), "/user-cache"),
        )
        .output()
        .unwrap()
}

/// The binary's exit code (-1 when a signal ended it), stdout and stderr for `args`
/// ([`groovelab`]).
pub fn run(args: &[&str]) -> (i32, String, String) {
    let out = groovelab(args);
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// What the binary printed for `args` ([`groovelab`]), which must succeed (else the
/// test fails with its `error:` line).
pub fn stdout(args: &[&str]) -> String {
    let out = groovelab(args);
    assert!(
        out.status.success(),
        "{args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).unwrap()
}

/// What the binary printed for `args` ([`stdout`]: it must succeed), read as JSON.
pub fn json(args: &[&str]) -> serde_json::Value {
    serde_json::from_str(&stdout(args)).unwrap()
}

/// Runs the command line `args` (a subcommand first) in this process, with the user's
/// presets as the command finds them: what it would print, or its error message.
pub fn run_in_process(args: &[&str]) -> Result<String, String> {
    use clap::Parser;
    let argv = std::iter::once("groovelab").chain(args.iter().copied());
    let cli = groovelab::cli::Cli::try_parse_from(argv).map_err(|e| e.to_string())?;
    match groovelab::cli::run(&cli) {
        Ok(groovelab::cli::Response::Print(text)) => Ok(text),
        Ok(_) => Err("the app would open: no text".into()),
        Err(e) => Err(e.to_string()),
    }
}

// ---- The app without a terminal ------------------------------------------------------

/// The scene options `--preset PRESET` with the scene options `values` over it.
pub fn scene_of(preset: &str, values: SceneSpec) -> SceneArgs {
    SceneArgs {
        preset: Some(preset.to_string()),
        values,
    }
}

/// What `render` prints for `scene` (no data file) at `at` and `size` after `keys`,
/// ASCII or Unicode, with the presets of `library`; or its error.
pub fn render_text(
    scene: &SceneArgs,
    at: Option<f64>,
    size: (u16, u16),
    ascii: bool,
    keys: Option<&str>,
    library: Library,
) -> Result<String, CliError> {
    let args = RenderArgs {
        at,
        size,
        keys: keys.map(str::to_string),
        output: None,
    };
    cli::render_with(scene, &DataArgs::default(), &args, ascii, library)
}

/// An empty preset folder of this test run's own (one per `area`, so a preset one area
/// saves never shows in another's screens), so no user preset shows up.
pub fn no_user_presets(area: &str) -> Library {
    let dir = std::env::temp_dir().join(format!("groovelab-{area}-presets-{}", std::process::id()));
    Library::at(Some(dir))
}

/// The app on a built-in preset as it starts.
pub fn app(preset: &str, library: Library) -> App {
    let p = groovelab::input::preset::load(preset).unwrap();
    App::new(Lab::of_preset(p).unwrap(), library)
}

/// How many analyses ran on an app's pool (work counted, not timed: a repeated request
/// runs none, a superseded one that had not started none).
#[derive(Clone, Debug, Default)]
pub struct Runs(std::sync::Arc<std::sync::atomic::AtomicUsize>);

impl Runs {
    pub fn get(&self) -> usize {
        self.0.load(std::sync::atomic::Ordering::SeqCst)
    }
}

/// The app on `lab`, its analyses counted on a pool of its own.
pub fn counted_lab(lab: Lab, library: Library) -> (App, Runs) {
    let runs = Runs::default();
    let r = std::sync::Arc::clone(&runs.0);
    let pool = groovelab::lab::jobs::Pool::observed(
        groovelab::lab::jobs::WORKERS,
        std::sync::Arc::new(move || {
            r.fetch_add(1, std::sync::atomic::Ordering::SeqCst);
        }),
    );
    (
        App::with_pool(lab, library, std::sync::Arc::new(pool)),
        runs,
    )
}

/// [`app`], its analyses counted.
pub fn counted(preset: &str, library: Library) -> (App, Runs) {
    let p = groovelab::input::preset::load(preset).unwrap();
    counted_lab(Lab::of_preset(p).unwrap(), library)
}

/// Presses the keys of `script` (the names the help screen shows).
pub fn press(app: &mut App, script: &str) {
    replay(app, &keys::parse_script(script).unwrap());
}

/// Selects the parameter row of `key`.
pub fn select(app: &mut App, key: Key) {
    app.apply(groovelab::tui::app::Action::Select(
        ROWS.iter().position(|p| p.key == key).unwrap(),
    ));
}

/// The app as `render` leaves it just before drawing: the lab of `scene` and `data`,
/// `keys` pressed, every analysis they asked for finished, the cursor at `at`, paused.
/// Drawn at every size and glyph set ([`text`]), its analyses are computed once; the
/// test `tui::drawing_one_app_at_every_size_is_render_at_every_size` holds it to
/// `render`.
pub fn rendered(
    scene: &SceneArgs,
    data: &DataArgs,
    at: Option<f64>,
    keys: Option<&str>,
    library: Library,
) -> App {
    let mut app = cli::opened(scene, data, library).unwrap();
    app.write_no_files();
    let keys = keys.map_or(Ok(Vec::new()), keys::parse_script).unwrap();
    replay_settled(&mut app, &keys);
    if let Some(t) = at {
        let (lo, hi) = (app.lab.solution.t_start, app.lab.solution.t_end);
        assert!((lo..=hi).contains(&t), "{t} outside {lo} … {hi}");
        app.t = t;
    }
    app.playing = false;
    app
}

/// The screen of `app` at `size` as `render` prints it (no colours), ASCII or Unicode.
pub fn text(app: &App, size: (u16, u16), ascii: bool) -> String {
    screen::to_text(app, size.0, size.1, &Theme::new(Glyphs::new(ascii), true))
}

/// The scene of the built-in preset `name`, resolved.
pub fn preset_scene(name: &str) -> groovelab::physics::scene::Scene {
    groovelab::input::preset::load(name)
        .unwrap()
        .spec
        .resolve()
        .unwrap()
        .0
}

/// The scene of the preset paper-b4.9, resolved (the data generators' truth).
pub fn paper_scene() -> groovelab::physics::scene::Scene {
    preset_scene("paper-b4.9")
}

/// Where the tests of `area` keep their files: `target/tmp/AREA` (cargo's folder for
/// integration tests' files). Each run empties the folders it uses and leaves them for
/// the next run to reuse, so runs do not pile folders up in the system's temporary
/// folder, and a failed test's files are there to look at.
pub fn scratch_root(area: &str) -> std::path::PathBuf {
    std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join(area)
}

/// A fresh, empty scratch folder for one test of an area (`target/tmp/AREA/TEST`).
pub fn scratch_dir(area: &str, test: &str) -> std::path::PathBuf {
    let dir = scratch_root(area).join(test);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}
