//! Issue 28, the charts' time zoom: at b = 4.3 cm the run lasts ~13 s and its impact
//! phase fits in two chart columns. `z` / `Z` zoom in and out around the cursor, the
//! mouse wheel over a chart around the pointer, `0` shows the whole run again; the
//! x axis' ticks and the event lines follow.

use groovelab::lab::Lab;
use groovelab::settings::params::Key;
use groovelab::settings::spec::SceneSpec;
use groovelab::tui::app::App;
use groovelab::tui::on_mouse;
use groovelab::tui::screen::chart_time_at;
use groovelab::tui::theme::{Glyphs, Theme};
use ratatui::crossterm::event::{KeyModifiers, MouseEvent, MouseEventKind};
use ratatui::layout::Rect;

use crate::common::{no_user_presets, press, render_text, scene_of};

/// The screen `render` prints at b = 4.3 cm after `keys`.
fn at_4_3(keys: &str, size: (u16, u16), ascii: bool) -> String {
    let scene = scene_of("paper-b4.9", SceneSpec::default().with(Key::Width, 0.043));
    render_text(
        &scene,
        None,
        size,
        ascii,
        Some(keys),
        no_user_presets("zoom"),
    )
    .unwrap()
}

/// The x tick labels of the chart (the row ending in "t (s)"), as numbers.
fn x_ticks(screen: &str) -> Vec<f64> {
    let row = screen.lines().find(|l| l.contains("t (s)")).unwrap();
    let row = &row[..row.find("t (s)").unwrap()];
    row.split(|c: char| !(c.is_ascii_digit() || c == '.' || c == '-'))
        .filter_map(|w| w.parse().ok())
        .collect()
}

/// The chart of a 120-column screen: its 74 columns, from its title to its tick row.
fn chart_rows(screen: &str) -> String {
    let lines: Vec<&str> = screen.lines().collect();
    let top = lines.iter().position(|l| l.contains("v_cm(t)")).unwrap();
    let bottom = lines.iter().position(|l| l.contains("t (s)")).unwrap();
    let left = |l: &&str| l.chars().take(74).collect::<String>();
    lines[top..=bottom]
        .iter()
        .map(left)
        .collect::<Vec<_>>()
        .join("\n")
}

#[test]
fn zooming_in_spreads_the_impact_phase_over_the_chart() {
    let whole = at_4_3(">", (120, 40), false);
    let ticks = x_ticks(&whole);
    assert!(
        ticks.last().unwrap() >= &10.0,
        "the run lasts ~13 s: {ticks:?}"
    );
    // Five doublings around the impact (the cursor at t = 0): ×32.
    let zoomed = at_4_3("> z z z z z", (120, 40), false);
    let ticks = x_ticks(&zoomed);
    assert!(
        ticks.len() >= 3 && ticks.iter().all(|t| (-0.1..=0.45).contains(t)),
        "the axis follows the zoom: {ticks:?}\n{zoomed}"
    );
    assert!(zoomed.contains("zoom ×32"), "{zoomed}");
    // The left ball slips from the impact until it turns (t_t = 0.296 s), both
    // event lines labelled; over the whole run they share two columns.
    let chart = chart_rows(&zoomed);
    assert!(
        chart.contains("┊impact") && chart.contains("│slipping"),
        "{chart}"
    );
    assert!(!chart_rows(&whole).contains("slipping"), "{whole}");
    insta::assert_snapshot!("zoom-b4.3-x32-120x40", zoomed);
    insta::assert_snapshot!(
        "zoom-b4.3-x32-80x24-ascii",
        at_4_3("> z z z z z", (80, 24), true)
    );
    // Out again, and `0`: the whole run as before (only the status line differs).
    let back = |keys: &str| {
        let s = at_4_3(keys, (120, 40), false);
        s.lines().take(37).collect::<Vec<_>>().join("\n")
    };
    let before = back(">");
    assert_eq!(back("> z z z z z Z Z Z Z Z"), before);
    assert_eq!(back("> z z z 0"), before);
}

/// The zoom keys are rows of the one key table: the help names them.
#[test]
fn the_help_names_the_zoom_keys() {
    let help = at_4_3("?", (200, 60), false);
    for line in [
        "charts: zoom in on time",
        "charts: zoom out on time",
        "the whole run again",
    ] {
        assert!(help.contains(line), "{line}\n{help}");
    }
}

fn wheel(kind: MouseEventKind, column: u16, row: u16) -> MouseEvent {
    MouseEvent {
        kind,
        column,
        row,
        modifiers: KeyModifiers::NONE,
    }
}

fn app_at_4_3() -> App {
    let mut lab = Lab::of_preset(groovelab::input::preset::load("paper-b4.9").unwrap()).unwrap();
    lab.set(Key::Width, 0.043).unwrap();
    App::new(lab, no_user_presets("zoom"))
}

/// The wheel over the chart zooms around the time under the pointer: that time stays
/// under the pointer (within a column's time), the cursor where it was.
#[test]
fn the_wheel_over_the_chart_zooms_around_the_pointer() {
    let area = Rect::new(0, 0, 120, 40);
    let theme = Theme::new(Glyphs::UNICODE, true);
    let mut a = app_at_4_3();
    let (column, row) = (30, 25);
    let under = chart_time_at(&a, area, column, row).unwrap();
    let t = a.t;
    for _ in 0..3 {
        assert!(on_mouse(
            &mut a,
            area,
            &theme,
            wheel(MouseEventKind::ScrollUp, column, row)
        ));
    }
    let span = a.chart_span();
    let (lo, hi) = a.chart_range();
    assert!(
        ((span.1 - span.0) / (hi - lo) - 8.0).abs() < 1e-9,
        "{lo} {hi}"
    );
    let column_time = (hi - lo) / 60.0;
    let now = chart_time_at(&a, area, column, row).unwrap();
    assert!((now - under).abs() <= column_time, "{under} → {now}");
    assert_eq!(a.t, t, "the wheel zooms, it does not seek");
    // Down zooms out; over the parameters the wheel still nudges, not zooms.
    on_mouse(
        &mut a,
        area,
        &theme,
        wheel(MouseEventKind::ScrollDown, column, row),
    );
    let (lo, hi) = a.chart_range();
    assert!(((span.1 - span.0) / (hi - lo) - 4.0).abs() < 1e-9);
}

/// Played past the zoomed window, the chart follows the cursor.
#[test]
fn a_zoomed_chart_follows_playback() {
    let mut a = app_at_4_3();
    press(&mut a, "> z z z z z space");
    let (_, hi) = a.chart_range();
    a.tick((hi - a.t) / a.speed_factor() + 0.1);
    let (lo, hi) = a.chart_range();
    assert!(lo <= a.t && a.t <= hi, "{lo} … {hi} misses t = {}", a.t);
}
