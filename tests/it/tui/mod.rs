//! The lab without a terminal: key → action → state, and the headless screen that
//! `render` prints (insta snapshots, checked by eye when recorded).
//! The lab's key and screen tests are split over `lab_keys`, `screens`, `help` and
//! `tables_and_mouse`, with their shared helpers here; each other module is one view
//! or quality of the app.

mod chart_zoom;
mod exports;
mod forces;
mod headless;
mod help;
mod lab_jobs;
mod lab_keys;
mod motion;
mod numbers;
mod picker_hides;
mod screens;
mod settings_layers;
mod small_screens;
mod tables_and_mouse;
mod view_answers;

use groovelab::cli::DataArgs;
use groovelab::lab::jobs::State;
use groovelab::physics::derived::Regime;
use groovelab::settings::params::Key;
use groovelab::settings::spec::SceneSpec;
use groovelab::study::preset::Preset;
use groovelab::tui::app::{App, Library, Mode, ROWS, Status, View};
use groovelab::tui::keys;
use groovelab::tui::on_mouse;
use groovelab::tui::theme::{Glyphs, Theme};
use ratatui::crossterm::event::{KeyModifiers, MouseButton, MouseEvent, MouseEventKind};
use ratatui::layout::Rect;

use crate::common::{self, press, scene_of, select, text};

fn no_user_presets() -> Library {
    common::no_user_presets("tui")
}

fn app(preset: &str) -> App {
    common::app(preset, no_user_presets())
}

fn screen(preset: &str, at: f64, size: (u16, u16), ascii: bool, keys: Option<&str>) -> String {
    let scene = scene_of(preset, SceneSpec::default());
    common::render_text(&scene, Some(at), size, ascii, keys, no_user_presets()).unwrap()
}

fn screen_of(a: &App) -> String {
    text(a, (120, 40), false)
}

/// Rows of the chart panel at 120×40 (between the top panels, one row per parameter,
/// and the status line).
fn chart_rows(screen: &str) -> Vec<&str> {
    let top = ROWS.len() + 2;
    screen.lines().skip(top).take(38 - top).collect()
}

fn cursor_column(screen: &str) -> usize {
    chart_rows(screen)
        .iter()
        .filter_map(|row| row.chars().position(|c| c == '┊'))
        .next()
        .expect("cursor drawn")
}

/// Times that show each phase: rolling in, sliding after the impact, rolling again,
/// and the end (after the accumulation point where there is one).
fn phase_times(preset: &str) -> Vec<f64> {
    let p = groovelab::input::preset::load(preset).unwrap();
    let (scene, span) = p.spec.resolve().unwrap();
    let sol = groovelab::physics::engine::solve(&scene, &span);
    let first_roll = sol
        .events
        .iter()
        .find(|e| {
            e.t > 0.0
                && matches!(
                    e.kind,
                    groovelab::physics::solution::EventKind::Rolling
                        | groovelab::physics::solution::EventKind::Rest
                )
        })
        .map_or(0.1, |e| e.t);
    vec![-0.1, 0.5 * first_roll, first_roll + 0.02, sol.t_end]
}

/// The app `render --preset PRESET --at AT --keys KEYS` draws, ready to be drawn at any
/// size and glyph set.
fn shown(preset: &str, at: f64, keys: Option<&str>) -> App {
    let scene = scene_of(preset, SceneSpec::default());
    common::rendered(
        &scene,
        &DataArgs::default(),
        Some(at),
        keys,
        no_user_presets(),
    )
}

/// The screen of `a` as the terminal draws it: laid out, the keys told what they need
/// of the frame (how far a popup scrolls at this size), drawn.
fn text_of(a: &mut App, w: u16, h: u16, ascii: bool) -> String {
    let theme = Theme::new(Glyphs::new(ascii), true);
    let mut screen = groovelab::tui::screen::Screen::default();
    let (text, _) = screen.text(a, w, h, &theme);
    a.laid_out(screen.frame().unwrap().scroll_max);
    text
}

/// The rows of a panel on the right (Why, Fit, Runs) at 80×24: right of column 44.
fn right_panel(s: &str) -> String {
    s.lines()
        .skip(9)
        .take(13)
        .map(|l| l.chars().skip(44).collect::<String>())
        .collect::<Vec<_>>()
        .join("\n")
}

/// A mouse event of `kind` at (`column`, `row`), no modifier keys.
fn mouse(kind: MouseEventKind, column: u16, row: u16) -> MouseEvent {
    MouseEvent {
        kind,
        column,
        row,
        modifiers: KeyModifiers::NONE,
    }
}

/// Where `text` starts on `screen`: (column, row).
fn cell_of(screen: &str, text: &str) -> (u16, u16) {
    screen
        .lines()
        .enumerate()
        .find_map(|(row, l)| {
            let at = l.find(text)?;
            Some((l[..at].chars().count() as u16, row as u16))
        })
        .unwrap_or_else(|| panic!("{text} not on\n{screen}"))
}
