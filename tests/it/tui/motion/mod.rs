//! The lab shows the whole motion (issue 11): the span follows the physics, events and
//! measured frames can be stepped through, the chart seeks on a click, the energy
//! chart, and the A/B comparison with a pinned run. App logic and `render` snapshots.

use groovelab::cli::DataArgs;
use groovelab::lab::{Lab, SpanEnd};
use groovelab::physics::solution::EventKind;
use groovelab::settings::params::Key;
use groovelab::settings::spec::SceneSpec;
use groovelab::study::preset::{Preset, PresetOrigin};
use groovelab::tui::app::{App, Library, Status};
use groovelab::tui::screen;
use groovelab::tui::screen::Screen;
use groovelab::tui::theme::{Glyphs, Theme};
use groovelab::tui::view;
use groovelab::tui::view_cache::ViewCache;
use ratatui::layout::Rect;

use crate::common::{self, press, scene_of, select, text};

mod energy_and_pin;
mod span_and_navigation;

fn no_user_presets() -> Library {
    common::no_user_presets("motion")
}

fn app(preset: &str) -> App {
    common::app(preset, no_user_presets())
}

/// `render` of `preset` with scene options `values`, at `at`, after `keys`.
fn render(
    preset: &str,
    values: SceneSpec,
    at: Option<f64>,
    size: (u16, u16),
    ascii: bool,
    keys: &str,
) -> Result<String, String> {
    let keys = (!keys.is_empty()).then_some(keys);
    common::render_text(
        &scene_of(preset, values),
        at,
        size,
        ascii,
        keys,
        no_user_presets(),
    )
    .map_err(|e| e.to_string())
}

fn mu(v: f64) -> SceneSpec {
    SceneSpec::default().with(Key::Mu, v)
}

const SIZES: [(u16, u16); 3] = [(80, 24), (120, 40), (200, 60)];

/// The chart panel's rows of a screen (below the top panels, above the status line).
fn chart_rows(screen: &str, height: u16) -> Vec<&str> {
    // The chart's rows as the layout places them (any width will do for rows).
    let area = ratatui::layout::Rect::new(0, 0, 120, height);
    let chart = view::layout(area).expect("big enough").chart;
    screen
        .lines()
        .skip(usize::from(chart.y))
        .take(usize::from(chart.height))
        .collect()
}

/// The largest x tick label on the chart's axis row.
fn last_x_tick(screen: &str, height: u16) -> f64 {
    let rows = chart_rows(screen, height);
    let axis = rows[rows.len() - 2];
    axis.split(|c: char| !(c.is_ascii_digit() || c == '.' || c == '-'))
        .filter_map(|w| w.parse::<f64>().ok())
        .fold(f64::NEG_INFINITY, f64::max)
}

/// A user preset that fixes its span to 0.5 s.
fn preset_with_t_end() -> Preset {
    let text = r#"
name = "short"
description = "paper-b4.9 cut at 0.5 s"
[scene]
radius = "2.75cm"
width = "4.9cm"
mass = "0.167kg"
mu = 0.17
v0 = 0.7928
t_start = -0.2
t_end = 0.5
"#;
    Preset::parse(text, "short", PresetOrigin::BuiltIn).unwrap()
}

/// Saves the app's scene as a user preset, as `s` in the app does.
fn save(a: &groovelab::tui::app::App, dir: &std::path::Path, name: &str) -> std::path::PathBuf {
    let spec = a.lab.saved_spec();
    let scene = groovelab::input::preset::ToSave {
        spec: &spec,
        measured: a.lab.measured(),
        started_from: &a.lab.preset().name,
    };
    groovelab::input::preset::save(scene, Some(dir), name, true).unwrap()
}

/// The app on unequal-speeds (a preset without data) with a velocity file of `rows` rows of the user's own: a
/// smooth decay with one spike.
fn with_big_series(rows: usize) -> App {
    use groovelab::lab::{Layers, OwnData};
    use groovelab::study::measured::{Measured, Series};
    let t: Vec<f64> = (0..rows)
        .map(|i| -0.2 + 1.2 * i as f64 / (rows - 1) as f64)
        .collect();
    let mut v_cm: Vec<f64> = t.iter().map(|t| 0.6 * (-2.0 * t.abs()).exp()).collect();
    v_cm[rows / 3] = 1.5;
    let v_t = t.iter().map(|t| -0.3 * (-3.0 * t.abs()).exp()).collect();
    let m = Measured::velocities(t, v_cm, v_t).unwrap();
    let own = OwnData {
        name: "big.csv".into(),
        series: Series::Velocities(std::sync::Arc::new(m)),
        groove: None,
    };
    let settings = Layers::new(
        groovelab::input::preset::load("unequal-speeds").unwrap(),
        SceneSpec::default(),
    );
    App::new(Lab::new(settings, Some(own)).unwrap(), no_user_presets())
}
