//! The lab without a terminal: key → action → state, and the headless screen that
//! `render` prints (insta snapshots, checked by eye when recorded).

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

#[test]
fn arrows_change_the_selected_parameter_and_resolve() {
    let mut a = app("paper-b3.5");
    select(&mut a, Key::Width);
    assert_eq!(a.lab.derived.regime, Regime::Depart);
    press(&mut a, "right");
    assert!(
        (a.lab.scene.width - 0.0355).abs() < 1e-12,
        "{}",
        a.lab.scene.width
    );
    // Coarse steps go to the next 5 mm mark, past b* = 4.26 cm: the balls now come back.
    press(&mut a, "S-right pgup");
    assert!(
        (a.lab.scene.width - 0.045).abs() < 1e-12,
        "{}",
        a.lab.scene.width
    );
    assert_eq!(a.lab.derived.regime, Regime::Recollide);
    assert!(a.lab.solution.impacts > 1, "re-solved at once");
    press(&mut a, "pgdn left");
    assert!(
        (a.lab.scene.width - 0.0395).abs() < 1e-12,
        "{}",
        a.lab.scene.width
    );
}

#[test]
fn a_step_past_a_limit_stops_at_the_limit() {
    // Seen: Shift-Right at b = 4.90 cm (R = 2.75 cm) was refused as "b = 5.5 cm"; it
    // goes to the last fine step below 2R = 5.5 cm, and says it stopped there.
    let mut a = app("paper-b4.9");
    select(&mut a, Key::Width);
    let two_r = 2.0 * a.lab.scene.radius;
    assert!((two_r - 0.055).abs() < 1e-12, "{two_r}");
    press(&mut a, "S-right");
    assert!(
        (a.lab.scene.width - 0.0545).abs() < 1e-12,
        "{}",
        a.lab.scene.width
    );
    assert!(
        matches!(&a.status, Status::Info(s) if s.contains("b = 5.45 cm") && s.contains("at the limit") && s.contains("2R")),
        "{:?}",
        a.status
    );
    // The whole message fits beside the time and play state at 80 columns.
    let screen = text(&a, (80, 24), false);
    let status = screen.lines().nth(22).unwrap();
    assert!(
        status.starts_with("t = -0.200 s  paused   b = 5.45 cm, at the limit (0 ≤ b < 2R)"),
        "{status}"
    );
    // From the limit a step cannot move: the scene unchanged, and it says so.
    let before = a.lab.scene;
    press(&mut a, "pgup right");
    assert_eq!(a.lab.scene, before, "b ≥ 2R must not be applied");
    assert!(
        matches!(&a.status, Status::Info(e) if e.contains("at its limit") && e.contains("2R")),
        "{:?}",
        a.status
    );
    // A limit of the row's own range: e stops at 1 (allowed), from below by a fine
    // step too; at 1 a further step is refused.
    select(&mut a, Key::Restitution);
    a.set_value(Key::Restitution, 0.995);
    press(&mut a, "right");
    assert_eq!(a.lab.scene.restitution, 1.0);
    assert!(
        matches!(&a.status, Status::Info(s) if s.contains("at the limit")),
        "{:?}",
        a.status
    );
    press(&mut a, "right");
    assert_eq!(a.lab.scene.restitution, 1.0);
    assert!(matches!(&a.status, Status::Info(s) if s.contains("e is at its limit")));
    // Downward too: μ_k at 0.004 and a fine step (0.01) down stops at 0.
    select(&mut a, Key::Mu);
    a.set_value(Key::Mu, 0.004);
    press(&mut a, "left");
    assert_eq!(a.lab.scene.mu, 0.0);
    assert!(
        matches!(&a.status, Status::Info(s) if s.contains("at the limit")),
        "{:?}",
        a.status
    );
    // With b hidden, the refused value is not named (it would give b away).
    let mut a = app("paper-b4.9");
    select(&mut a, Key::Width);
    press(&mut a, "B S-right");
    assert!(
        matches!(&a.status, Status::Info(s) if s.contains("at the limit") && !s.contains("cm")),
        "{:?}",
        a.status
    );
}

#[test]
fn typing_errors_state_the_apps_unit_rule() {
    // In the app a bare number is in the row's display unit; the error must not say
    // "bare number = SI" (following it set b to 0.049 cm).
    let mut a = app("paper-b4.9");
    select(&mut a, Key::Width);
    for typed in ["enter x enter", "enter 4 k g enter"] {
        press(&mut a, typed);
        let Status::Error(e) = &a.status else {
            panic!("{typed}: {:?}", a.status)
        };
        assert!(!e.contains("SI"), "{typed}: {e}");
        assert!(e.contains("a bare number is in cm"), "{typed}: {e}");
    }
    select(&mut a, Key::MassLeft);
    press(&mut a, "enter 1 m enter");
    assert!(
        matches!(&a.status, Status::Error(e) if e.contains("a bare number is in g")),
        "{:?}",
        a.status
    );
    // And what the error says works: a bare number in the unit shown.
    select(&mut a, Key::Width);
    press(&mut a, "enter 4 . 9 enter");
    assert_eq!(a.lab.scene.width, 0.049);
}

#[test]
fn typed_values_take_units_and_escape_cancels() {
    let mut a = app("paper-b4.9");
    select(&mut a, Key::Width);
    press(&mut a, "enter 4 . 4 c m enter");
    assert_eq!(a.lab.scene.width, 0.044);
    press(&mut a, "enter 3 c m esc");
    assert_eq!(a.lab.scene.width, 0.044, "Esc cancels typing");
    assert_eq!(a.mode(), Mode::Normal);
    assert!(!a.quitting());
    press(&mut a, "enter 3 k g enter");
    assert_eq!(a.lab.scene.width, 0.044);
    assert!(matches!(&a.status, Status::Error(e) if e.contains("unknown unit")));
    // Each ball's height sets its speed through the run-up formula.
    select(&mut a, Key::HeightLeft);
    press(&mut a, "enter 5 c m enter");
    assert!((a.lab.derived.release_height - 0.05).abs() < 1e-12);
    select(&mut a, Key::HeightRight);
    press(&mut a, "enter 5 c m enter");
    assert!((a.lab.value(Key::HeightRight) - 0.05).abs() < 1e-12);
    assert_eq!(a.lab.scene.left.v0, a.lab.scene.right.v0);
}

#[test]
fn prompts_edit_like_a_terminal_line() {
    let mut a = app("paper-b4.9");
    select(&mut a, Key::Width);
    let b = |a: &App| a.lab.scene.width;
    // ←/→ move the cursor; typing goes in at it.
    press(&mut a, "enter 4 c m left left . 5 enter");
    assert_eq!(b(&a), 0.045);
    // Home/End, Backspace/Delete.
    press(&mut a, "enter c m home 4 . 6 end enter");
    assert_eq!(b(&a), 0.046);
    press(&mut a, "enter x 4 . 2 home delete end backspace 3 enter");
    assert_eq!(b(&a), 0.043);
    // Ctrl-U clears the line, Ctrl-W the word before the cursor, Ctrl-A/E go to the
    // start and end, Ctrl-K deletes to the end: none of them is typed as a letter.
    press(&mut a, "enter 9 9 C-u 4 . 1");
    assert_eq!(a.mode(), Mode::Edit("4.1".into()));
    press(&mut a, "enter");
    assert_eq!(b(&a), 0.041);
    press(&mut a, "enter 4 . 4 space x y z C-w");
    assert!(
        matches!(&a.mode(), Mode::Edit(f) if f.value() == "4.4 "),
        "{:?}",
        a.mode()
    );
    press(&mut a, "enter");
    assert_eq!(b(&a), 0.044);
    press(&mut a, "enter 7 c m C-a 4 . C-e C-a right right right C-k");
    assert!(
        matches!(&a.mode(), Mode::Edit(f) if f.value() == "4.7"),
        "{:?}",
        a.mode()
    );
    press(&mut a, "enter");
    assert_eq!(b(&a), 0.047);
    // ↑/↓ bring back the values confirmed earlier this session, newest first; ↓ past
    // the newest gives back the line being typed.
    press(&mut a, "enter up enter");
    assert_eq!(b(&a), 0.047, "the last value again");
    press(&mut a, "enter up up up enter");
    assert_eq!(b(&a), 0.041);
    press(&mut a, "enter 3 up up down down");
    assert_eq!(a.mode(), Mode::Edit("3".into()));
    press(&mut a, "esc");
    // The save and export prompts are the same line editor, with their own history.
    press(&mut a, "s C-u n e w left left C-k");
    assert_eq!(a.mode(), Mode::SaveName("n".into()));
    press(&mut a, "esc w C-a delete delete delete delete delete");
    assert!(
        // Suggested "b4.1cm-run.csv" (named for the b it holds), five characters gone.
        matches!(&a.mode(), Mode::Export(_, f) if f.value() == "m-run.csv"),
        "{:?}",
        a.mode()
    );
    press(&mut a, "up");
    assert!(
        // Suggested "b4.1cm-run.csv" (named for the b it holds), five characters gone.
        matches!(&a.mode(), Mode::Export(_, f) if f.value() == "m-run.csv"),
        "no file name was confirmed yet, so ↑ has nothing to bring: {:?}",
        a.mode()
    );
    press(&mut a, "esc");
    assert!(!a.quitting());
}

#[test]
fn the_typing_field_shows_its_cursor_as_a_reversed_cell() {
    use groovelab::tui::theme::{Glyphs, Theme};
    use ratatui::buffer::Buffer;
    use ratatui::layout::Rect;
    use ratatui::style::Modifier;
    let mut a = app("paper-b4.9");
    select(&mut a, Key::Width);
    press(&mut a, "enter 4 c m left left");
    let theme = Theme::new(Glyphs::new(false), true);
    let area = Rect::new(0, 0, 120, 40);
    let mut buf = Buffer::empty(area);
    groovelab::tui::screen::draw(&a, area, &mut buf, &theme);
    let (x, y) = (0..area.height)
        .find_map(|y| {
            let row: String = (0..area.width).map(|x| buf[(x, y)].symbol()).collect();
            row.find("[4cm]")
                .map(|i| (row[..i].chars().count() as u16, y))
        })
        .expect("the field on screen");
    let reversed = |dx: u16| {
        buf[(x + dx, y)]
            .style()
            .add_modifier
            .contains(Modifier::REVERSED)
    };
    // The row is highlighted (reversed); the cursor's cell, on the c, is not.
    assert!(reversed(1) && reversed(3), "the rest of the row");
    assert!(!reversed(2), "the cursor on the c");
    // A line longer than the field shows its end around the cursor.
    press(&mut a, "end 1 2 3 4 5 6 7 8 9");
    let screen = common::text(&a, (120, 40), false);
    assert!(screen.contains("[23456789_]"), "{screen}");
}

#[test]
fn status_messages_never_hide_the_time_and_the_play_state() {
    // Before, a message that did not fit beside playback went first and pushed the
    // time off the line; an error replaced it.
    let mut a = app("paper-b4.9");
    select(&mut a, Key::Width);
    let status_row = |a: &App, size: (u16, u16)| {
        let screen = text(a, size, true);
        screen
            .lines()
            .nth(usize::from(size.1) - 2)
            .unwrap()
            .to_string()
    };
    for keys in ["S-right", "enter x y z enter", "a", "esc", "> space"] {
        press(&mut a, keys);
        assert!(!matches!(a.status, Status::None), "{keys}");
        for size in [(80, 24), (120, 40), (200, 60)] {
            let row = status_row(&a, size);
            let state = if a.playing { "playing" } else { "paused" };
            assert!(row.starts_with("t = "), "{keys} {size:?}: {row}");
            assert!(row.contains(state), "{keys} {size:?}: {row}");
            assert!(row.ends_with("preset paper-b4.9"), "{keys} {size:?}: {row}");
        }
    }
    // Where it all fits, the message is whole beside the full playback line.
    let row = status_row(&a, (200, 60));
    assert!(row.contains(" of -0.200 "), "{row}");
    assert!(row.contains("impact at t = 0.0000 s"), "{row}");
}

#[test]
fn playback_runs_on_the_clock_at_the_chosen_speed() {
    // No measured data: `.` and `,` step by one animation frame.
    let mut a = app("unequal-speeds");
    let t0 = a.lab.solution.t_start;
    assert_eq!(a.t, t0);
    press(&mut a, "space");
    assert!(a.playing);
    let speed = a.speed_factor();
    a.tick(0.5);
    assert!((a.t - (t0 + 0.5 * speed)).abs() < 1e-12);
    press(&mut a, "+");
    assert_eq!(a.speed_factor(), 2.0 * speed);
    press(&mut a, "space");
    assert!(!a.playing);
    let t = a.t;
    press(&mut a, ". .");
    assert!((a.t - (t + 2.0 * a.frame_step())).abs() < 1e-12);
    press(&mut a, ",");
    assert!((a.t - (t + a.frame_step())).abs() < 1e-12);
    press(&mut a, "end");
    assert_eq!(a.t, a.lab.solution.t_end);
    press(&mut a, "home");
    assert_eq!(a.t, a.lab.solution.t_start);
    press(&mut a, "r");
    assert!(a.playing);
    // Playing past the end stops there.
    a.tick(1e6);
    assert_eq!(a.t, a.lab.solution.t_end);
    assert!(!a.playing);
}

#[test]
fn the_picker_takes_home_end_and_the_page_keys() {
    let mut a = app("paper-b4.9");
    let n = a.library().presets.len();
    assert!(n > 3, "presets to move through: {n}");
    press(&mut a, "p home");
    assert_eq!(a.mode(), Mode::Picker(0));
    press(&mut a, "end");
    assert_eq!(a.mode(), Mode::Picker(n - 1));
    // A page is ten rows, and stops at either end (no wrap, unlike the arrows).
    press(&mut a, "pgup");
    assert_eq!(a.mode(), Mode::Picker((n - 1).saturating_sub(10)));
    press(&mut a, "home down pgdn");
    assert_eq!(a.mode(), Mode::Picker(11.min(n - 1)));
    press(&mut a, "pgdn");
    assert_eq!(a.mode(), Mode::Picker(n - 1));
    press(&mut a, "home enter");
    assert_eq!(a.lab.preset().name, a.library().presets[0].name);
}

#[test]
fn picker_loads_presets_and_quit_keys_quit() {
    let mut a = app("paper-b4.9");
    press(&mut a, "p down enter");
    assert_eq!(a.lab.preset().name, a.library().presets[3].name);
    press(&mut a, "p up up esc");
    assert_eq!(a.mode(), Mode::Normal);
    assert_eq!(a.lab.preset().name, a.library().presets[3].name);
    press(&mut a, "?");
    assert_eq!(a.mode(), Mode::Help);
    press(&mut a, "esc");
    assert_eq!(a.mode(), Mode::Normal);
    assert!(!a.quitting());
    press(&mut a, "q");
    assert!(a.quitting());
    let mut a = app("paper-b4.9");
    press(&mut a, "enter 4 C-c");
    assert!(a.quitting(), "Ctrl-C quits even while typing");
    // Esc on the main screen never quits (a reflex Esc ended the session): it says
    // how to quit instead.
    let mut a = app("paper-b4.9");
    press(&mut a, "esc esc");
    assert!(!a.quitting());
    assert!(
        matches!(&a.status, Status::Info(s) if s.contains("q quits")),
        "{:?}",
        a.status
    );
    press(&mut a, "q");
    assert!(a.quitting());
}

#[test]
fn saving_writes_a_loadable_preset_and_never_overwrites_silently() {
    let dir = std::env::temp_dir().join(format!("groovelab-save-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    let mut a = app("inelastic");
    a.set_library(Library::at(Some(dir.clone())));
    select(&mut a, Key::Mu);
    press(&mut a, "right");
    press(&mut a, "s enter");
    let path = dir.join("my-inelastic.toml");
    let saved = groovelab::input::preset::load(path.to_str().unwrap()).unwrap();
    let (scene, _) = saved.spec.resolve().unwrap();
    assert_eq!(
        scene, a.lab.scene,
        "the saved file gives back the same scene"
    );
    // Saving again asks first; anything but y keeps the file.
    std::fs::write(&path, "sentinel").unwrap();
    press(&mut a, "s enter");
    assert!(matches!(a.mode(), Mode::ConfirmOverwrite(_)));
    press(&mut a, "n");
    assert_eq!(std::fs::read_to_string(&path).unwrap(), "sentinel");
    press(&mut a, "s enter y");
    assert!(std::fs::read_to_string(&path).unwrap().contains("[scene]"));
    // Bad names are refused, and the dialog stays open with the name and why.
    press(
        &mut a,
        "s backspace backspace backspace backspace backspace backspace backspace backspace backspace backspace backspace backspace / enter",
    );
    assert!(
        matches!(&a.status, Status::Error(e) if e.contains("name")),
        "{:?}",
        a.status
    );
    assert_eq!(a.mode(), Mode::SaveName("/".into()));
    press(&mut a, "esc");
    assert_eq!(a.mode(), Mode::Normal);
    assert!(
        !dir.join(".my-inelastic.toml.tmp").exists(),
        "no temporary file left"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn chart_toggles() {
    let mut a = app("paper-b4.9");
    press(&mut a, "b");
    let right = screen_of(&a);
    assert!(right.contains("right ball"));
    press(&mut a, "b");
    assert!(screen_of(&a).contains("both balls"));
    press(&mut a, "x");
    assert!(screen_of(&a).contains("x(t) of both balls"));
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

#[test]
fn a_parameter_change_moves_the_chart_and_the_regime_text() {
    let before = screen("paper-b3.5", 0.3, (120, 40), false, None);
    // Three coarse steps of b (the selected row): 3.5 → 5.0 cm, past b* = 4.26 cm.
    let after = screen(
        "paper-b3.5",
        0.3,
        (120, 40),
        false,
        Some("S-right S-right S-right"),
    );
    assert!(before.contains("DEPART"));
    assert!(after.contains("RECOLLIDE"), "{after}");
    assert_ne!(chart_rows(&before), chart_rows(&after));
    assert!(after.contains("5.00 cm"));
}

fn cursor_column(screen: &str) -> usize {
    chart_rows(screen)
        .iter()
        .filter_map(|row| row.chars().position(|c| c == '┊'))
        .next()
        .expect("cursor drawn")
}

#[test]
fn the_time_cursor_moves_with_at() {
    let cols: Vec<usize> = [-0.1, 0.2, 0.5, 0.9]
        .iter()
        .map(|&t| cursor_column(&screen("paper-b4.9", t, (120, 40), false, None)))
        .collect();
    assert!(cols.windows(2).all(|w| w[0] < w[1]), "{cols:?}");
}

#[test]
fn ascii_mode_emits_only_seven_bit_characters() {
    // Every view draws ASCII by itself: the last-line-of-defence stand-ins of
    // `force_ascii` are never needed (they would show as '?' or a cruder glyph).
    let theme = groovelab::tui::theme::Theme::new(groovelab::tui::theme::Glyphs::ASCII, true);
    let mut failures: Vec<String> = Vec::new();
    for p in Preset::built_in() {
        for keys in [
            "", "?", "p", "c", "g", "f", "x", "b b", "o", "s", "enter", "d", "e", "w", "W",
            "? end", "o b b",
        ] {
            let mut a = app(&p.name);
            press(&mut a, keys);
            a.wait();
            for t in [-0.1f64, 0.05, 0.3, 10.0] {
                a.t = t.clamp(a.lab.solution.t_start, a.lab.solution.t_end);
                for size in [(80, 24), (120, 40), (60, 20)] {
                    // One drawing: the cells that needed a stand-in, and the text.
                    let (s, cells) = groovelab::tui::screen::to_text_and_non_ascii_cells(
                        &a, size.0, size.1, &theme,
                    );
                    if !cells.is_empty() {
                        failures.push(format!("{} at {t} {size:?} {keys:?}: {cells:?}", p.name));
                    }
                    assert!(s.is_ascii());
                }
            }
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn a_small_terminal_gets_a_clear_message() {
    // The size it has and the size it needs (issue 28: it said only the latter).
    let s = screen("paper-b4.9", 0.0, (79, 30), false, None);
    assert!(
        s.contains("terminal 79×30 is too small: groovelab needs 80×24"),
        "{s}"
    );
    let s = screen("paper-b4.9", 0.0, (100, 23), true, None);
    assert!(
        s.contains("terminal 100x23 is too small: groovelab needs 80x24"),
        "{s}"
    );
    // Narrow: both numbers still whole, each on its line.
    let s = screen("paper-b4.9", 0.0, (16, 5), false, None);
    assert!(s.contains("terminal 16×5"), "{s}");
    assert!(s.contains("needs 80×24"), "{s}");
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

#[test]
fn drawing_one_app_at_every_size_is_render_at_every_size() {
    // The snapshot tests draw one app at every size and glyph set (its analyses computed
    // once); `render` makes a new one each time. Drawing leaves state behind (a popup's
    // scroll limit, the views' caches), so this holds them to the same bytes.
    for keys in ["? end", "d end", "w", "o"] {
        let a = shown("paper-b4.9", 0.3, Some(keys));
        for size in [(80, 24), (120, 40), (200, 60), (80, 24)] {
            for ascii in [false, true] {
                assert_eq!(
                    text(&a, size, ascii),
                    screen("paper-b4.9", 0.3, size, ascii, Some(keys)),
                    "{keys:?} {size:?} ascii {ascii}"
                );
            }
        }
    }
}

#[test]
fn snapshots_of_every_preset() {
    let combos = [
        ((120, 40), false),
        ((80, 24), true),
        ((80, 24), false),
        ((120, 40), true),
    ];
    for p in Preset::built_in() {
        let times = phase_times(&p.name);
        let apps: Vec<App> = times.iter().map(|&t| shown(&p.name, t, None)).collect();
        for ((w, h), ascii) in combos {
            let mode = if ascii { "ascii" } else { "unicode" };
            let screens: String = times
                .iter()
                .zip(&apps)
                .map(|(t, a)| format!("--- at {t:.4} s ---\n{}", text(a, (w, h), ascii)))
                .collect();
            insta::assert_snapshot!(format!("screen-{}-{w}x{h}-{mode}", p.name), screens);
        }
    }
}

#[test]
fn snapshots_of_popups() {
    for (name, keys) in [
        ("help", "?"),
        ("picker", "p down"),
        ("typing", "enter 4 . 4"),
    ] {
        let a = shown("paper-b4.9", 0.2, Some(keys));
        insta::assert_snapshot!(
            format!("popup-{name}-120x40-unicode"),
            text(&a, (120, 40), false)
        );
        insta::assert_snapshot!(
            format!("popup-{name}-80x24-ascii"),
            text(&a, (80, 24), true)
        );
    }
}

#[test]
fn mouse_clicks_select_and_scrolls_change_parameters() {
    use groovelab::tui::app::Action;
    use groovelab::tui::view::{layout, param_at};
    use ratatui::layout::Rect;
    let panels = layout(Rect::new(0, 0, 120, 40)).unwrap();
    let p = panels.params;
    // Row of the 5th parameter (μ_k): one below the border, four below the first.
    let hit = param_at(p, 1, p.x + 3, p.y + 1 + 4);
    assert_eq!(hit, Some(4));
    assert_eq!(
        param_at(p, 1, p.x, p.y + 1),
        None,
        "the border is not a row"
    );
    assert_eq!(param_at(p, 1, p.x + 3, p.y + 30), None);
    // On a short screen the list scrolls with the selection.
    let short = layout(Rect::new(0, 0, 80, 24)).unwrap().params;
    assert_eq!(param_at(short, 9, short.x + 3, short.y + 1), Some(3));
    let mut a = app("paper-b4.9");
    a.apply(Action::Select(4));
    assert_eq!(ROWS[a.selected()].key, Key::Mu);
    a.apply(Action::ScrollParam(4, true));
    assert!((a.lab.scene.mu - 0.18).abs() < 1e-12);
    let e_row = ROWS.iter().position(|p| p.key == Key::Restitution).unwrap();
    a.apply(Action::ScrollParam(e_row, false));
    assert_eq!(ROWS[a.selected()].key, Key::Restitution);
    assert!((a.lab.scene.restitution - 0.99).abs() < 1e-12);
}

#[test]
fn no_color_means_no_colours() {
    use groovelab::tui::theme::{Glyphs, Theme};
    let t = Theme::new(Glyphs::UNICODE, true);
    let styles = [
        t.text, t.dim, t.title, t.selected, t.error, t.info, t.left, t.right, t.accent, t.measured,
        t.event, t.cursor, t.flash, t.groove, t.key,
    ];
    for s in styles {
        assert!(s.fg.is_none() && s.bg.is_none(), "{s:?}");
    }
    // With colour the two balls differ, and no text is forced to white or black.
    let c = Theme::new(Glyphs::UNICODE, false);
    assert_ne!(c.left.fg, c.right.fg);
    use ratatui::style::Color;
    for s in [c.text, c.left, c.right, c.accent, c.title, c.key] {
        assert!(!matches!(s.fg, Some(Color::White | Color::Black)));
    }
}

#[test]
fn methods_view_and_overlay() {
    let mut a = app("paper-b4.9");
    press(&mut a, "c");
    assert_eq!(a.view(), View::Methods);
    a.wait();
    let State::Ready(rows) = a.methods().state() else {
        panic!("the rows are there once the lab has waited")
    };
    assert_eq!(rows.len(), 20, "five methods at four levels");
    let s = screen_of(&a);
    assert!(s.contains("Methods: max |v_cm - exact| against steps per run"));
    for name in ["euler", "symplectic-euler", "rk4", "rk45", "moreau"] {
        assert!(s.contains(name), "{name}");
    }
    // Deterministic: the view plots work in steps, not measured time (a second run of
    // the rows, by `render`, draws the same screen).
    let t = a.t;
    a.t = 0.3;
    assert_eq!(
        text(&a, (120, 40), false),
        screen("paper-b4.9", 0.3, (120, 40), false, Some("c"))
    );
    a.t = t;
    press(&mut a, "c o");
    a.wait();
    let State::Ready(o) = a.overlay().state() else {
        panic!("an overlay")
    };
    assert_eq!(o.method, groovelab::methods::Method::Euler);
    assert_eq!(o.row.status, groovelab::study::compare::RunStatus::Chatter);
    assert!(screen_of(&a).contains("euler h 1e-3 (chatter)"));
    press(&mut a, "[ [");
    a.wait();
    let overlay = |a: &App| match a.overlay().state() {
        State::Ready(o) => Some(o.clone()),
        _ => None,
    };
    assert_eq!(overlay(&a).unwrap().settings.step, 1e-2);
    // A scene change re-runs the overlay.
    select(&mut a, Key::Mu);
    press(&mut a, "right");
    a.wait();
    assert_eq!(
        overlay(&a).unwrap().row.method,
        groovelab::methods::Method::Euler
    );
    press(&mut a, "o o o o o");
    assert!(overlay(&a).is_none(), "cycling ends with the overlay off");
}

/// A span far longer than the comparison's window (μ = 1e-6: the balls slide for
/// 147,000 s): the Methods view runs every method over the window only, each run
/// taking the window's steps (it took minutes before, the coarsest run alone 14.7
/// million steps), and says where the runs were cut.
#[test]
fn the_methods_view_of_a_long_span_is_cut_and_says_where() {
    use groovelab::study::compare::WINDOW;
    let p = groovelab::input::preset::load("paper-b4.9").unwrap();
    let (_, span) = p.spec.resolve().unwrap();
    let flags = groovelab::settings::spec::SceneSpec::default()
        .with(groovelab::settings::params::Key::Mu, 1e-6);
    let lab = groovelab::lab::Lab::new(groovelab::lab::Layers::new(p, flags), None).unwrap();
    let mut a = App::new(lab, no_user_presets());
    assert!(a.lab.solution.t_end > 1e5);
    press(&mut a, "c");
    a.wait();
    let State::Ready(rows) = a.methods().state() else {
        panic!("the rows are there once the lab has waited")
    };
    let end = span.t_start + WINDOW;
    for r in rows {
        assert_eq!(r.cut, Some(end), "{r:?}");
        if let Some(h) = r.step {
            assert_eq!(r.steps, (WINDOW / h).ceil() as usize, "{r:?}");
        }
    }
    let s = text(&a, (120, 40), false);
    assert!(
        s.contains("runs cut at t = 1.8 s by the step budget"),
        "{s}"
    );
}

/// The Methods view's work axis: `u` cycles steps → right-hand-side evaluations →
/// time; the key is in the one key table (help, hint bar, `--keys`); the rows say
/// whether each run gets the outcome right and each fixed-step method's fitted order.
#[test]
fn methods_view_work_axis_outcome_and_order() {
    let mut a = app("paper-b4.9");
    press(&mut a, "c");
    a.wait();
    let s = screen_of(&a);
    assert!(s.contains("against steps per run"), "{s}");
    assert!(s.contains("= outcome right (recollide, 20 impacts)"), "{s}");
    assert!(s.contains("order: e "), "{s}");
    // Untimed until the time axis asks (the timing runs cost more than the rest);
    // timed on the narrow groove, whose runs are fewer.
    let (mut a, counted) = common::counted("paper-b3.5", no_user_presets());
    press(&mut a, "c");
    a.wait();
    let times = |a: &App| match a.methods().state() {
        State::Ready(rows) => rows.iter().map(|r| r.time_median_s).collect::<Vec<_>>(),
        _ => panic!("the rows are there once the lab has waited"),
    };
    let runs = counted.get();
    assert!(times(&a).iter().all(|&t| t == 0.0));
    press(&mut a, "X");
    a.wait();
    let s = screen_of(&a);
    assert!(s.contains("against rhs evaluations per run"), "{s}");
    assert_eq!(counted.get(), runs, "the rhs axis needs no new rows");
    press(&mut a, "X");
    a.wait();
    let s = screen_of(&a);
    assert!(s.contains("against time per run"), "{s}");
    assert!(times(&a).iter().all(|&t| t > 0.0), "{:?}", times(&a));
    assert_eq!(counted.get(), runs + 1, "timed once");
    press(&mut a, "X");
    a.wait();
    assert!(screen_of(&a).contains("against steps per run"));
    assert_eq!(
        counted.get(),
        runs + 1,
        "the timed rows serve the steps axis too"
    );
    assert!(
        keys::TABLE
            .iter()
            .any(|b| b.keys == ["X"] && b.help.contains("work axis"))
    );
}

#[test]
fn map_view_marks_the_scene_on_the_regime_grid() {
    let s = screen("paper-b3.5", 0.0, (120, 40), false, Some("g"));
    assert!(s.contains("Regime: b/R across, e up"));
    assert!(s.contains("◆"), "the scene is marked");
    assert!(s.contains("Paper fig."));
    let ascii = screen("paper-b3.5", 0.0, (80, 24), true, Some("g"));
    assert!(ascii.is_ascii() && ascii.contains('@'));
    // The marker moves with the width: b/R across, so a wider groove is further right.
    let col = |s: &str| {
        s.lines()
            .find_map(|l| l.chars().position(|c| c == '◆'))
            .unwrap()
    };
    let wider = screen(
        "paper-b3.5",
        0.0,
        (120, 40),
        false,
        Some("S-right S-right g"),
    );
    assert!(col(&wider) > col(&s));
}

#[test]
fn every_view_draws_at_many_sizes_without_panicking() {
    // The layout adapts from the minimum to large screens; any panic fails the test.
    let mut a = app("unequal-speeds");
    for keys in [
        "", "c", "g", "f", "x", "b b", "o", "?", "p", "d", "e", "w", "s",
    ] {
        let mut b = a.clone();
        press(&mut b, keys);
        for (w, h) in [
            (80, 24),
            (81, 25),
            (100, 30),
            (133, 41),
            (200, 60),
            (79, 24),
            (40, 10),
            (1, 1),
        ] {
            let theme =
                groovelab::tui::theme::Theme::new(groovelab::tui::theme::Glyphs::ASCII, false);
            let s = groovelab::tui::screen::to_text(&b, w, h, &theme);
            assert_eq!(s.lines().count(), usize::from(h), "{keys:?} at {w}x{h}");
            assert!(s.is_ascii());
        }
    }
    a.t = a.lab.solution.t_end;
    assert!(screen_of(&a).contains("impacts"));
}

// ---- issue 11: help, keys and small screens; teachers' tools ----

/// The screen of `a` as the terminal draws it: laid out, the keys told what they need
/// of the frame (how far a popup scrolls at this size), drawn.
fn text_of(a: &mut App, w: u16, h: u16, ascii: bool) -> String {
    let theme = Theme::new(Glyphs::new(ascii), true);
    let mut screen = groovelab::tui::screen::Screen::default();
    let (text, _) = screen.text(a, w, h, &theme);
    a.laid_out(screen.frame().unwrap().scroll_max);
    text
}

#[test]
fn help_is_complete_at_every_size_scrolling_where_needed() {
    for (w, h) in [(80, 24), (120, 40), (200, 60)] {
        for ascii in [false, true] {
            let mut a = app("paper-b4.9");
            press(&mut a, "?");
            // Page down until nothing is below, collecting every screen.
            let mut seen = text_of(&mut a, w, h, ascii);
            for _ in 0..20 {
                if !seen.lines().any(|l| l.contains("more ")) {
                    break;
                }
                press(&mut a, "pgdn");
                seen.push_str(&text_of(&mut a, w, h, ascii));
                if !text_of(&mut a, w, h, ascii).contains("more v")
                    && !text_of(&mut a, w, h, ascii).contains("more ↓")
                {
                    break;
                }
            }
            assert_eq!(a.mode(), Mode::Help, "scrolling keeps the help open");
            let flat = seen.split_whitespace().collect::<Vec<_>>().join(" ");
            for b in keys::TABLE {
                let first: String = b
                    .help
                    .split_whitespace()
                    .take(3)
                    .collect::<Vec<_>>()
                    .join(" ");
                let first = first.replace('μ', "mu");
                assert!(
                    flat.contains(&first)
                        || flat.contains(&b.help.split_whitespace().next().unwrap().to_string()),
                    "{w}x{h} ascii {ascii}: '{first}' missing"
                );
                // The keys by the names the hint bar uses (↑, PgUp, Shift-→).
                assert!(
                    flat.contains(&keys::display_keys(b, ascii)),
                    "{w}x{h}: keys {:?}",
                    b.keys
                );
            }
            assert!(flat.contains("Mouse: click a parameter"), "{w}x{h} {ascii}");
            // Where it all fits there is nothing to scroll to.
            if h >= 60 {
                assert!(!seen.contains("more "), "{w}x{h}: {seen}");
            }
            press(&mut a, "q");
            assert_eq!(a.mode(), Mode::Normal);
            assert!(!a.quitting(), "q in the help closes the help, not the app");
        }
    }
    // The help's ↑ takes back what ↓ did; it never scrolls past the end.
    let mut a = app("paper-b4.9");
    press(&mut a, "?");
    let _ = text_of(&mut a, 80, 24, false);
    press(&mut a, "end");
    let bottom = text_of(&mut a, 80, 24, false);
    assert!(bottom.contains("Mouse: click"));
    press(&mut a, "down down down up");
    let _ = text_of(&mut a, 80, 24, false);
    press(&mut a, "down");
    assert_eq!(text_of(&mut a, 80, 24, false), bottom);
    press(&mut a, "home");
    assert!(text_of(&mut a, 80, 24, false).contains("play / pause"));
}

#[test]
fn q_closes_every_popup_and_quits_only_the_main_screen() {
    let mut a = app("paper-b4.9");
    for open in ["?", "p", "d"] {
        press(&mut a, open);
        assert_ne!(a.mode(), Mode::Normal, "{open}");
        press(&mut a, "q");
        assert_eq!(a.mode(), Mode::Normal, "{open}");
        assert!(!a.quitting(), "{open} q");
        press(&mut a, open);
        press(&mut a, "esc");
        assert_eq!(a.mode(), Mode::Normal, "{open} esc");
        assert!(!a.quitting());
    }
    // In text fields q is a letter.
    press(&mut a, "s q");
    assert!(matches!(&a.mode(), Mode::SaveName(t) if t.value().ends_with('q')));
    press(&mut a, "esc w q");
    assert!(matches!(&a.mode(), Mode::Export(_, t) if t.value().ends_with('q')));
    press(&mut a, "esc");
    assert!(!a.quitting());
    press(&mut a, "? C-c");
    assert!(a.quitting(), "Ctrl-C quits from a popup");
    let mut a = app("paper-b4.9");
    press(&mut a, "q");
    assert!(a.quitting());
}

#[test]
fn the_hint_bar_always_ends_with_help_and_quit() {
    for (w, h) in [(80, 24), (120, 40), (200, 60)] {
        for ascii in [false, true] {
            let s = screen("paper-b4.9", 0.2, (w, h), ascii, None);
            let bar = s.lines().last().unwrap();
            assert!(bar.ends_with("? help  q quit"), "{w}x{h}: {bar}");
            assert!(bar.contains("play") && bar.contains("change"), "{bar}");
        }
    }
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

#[test]
fn small_screens_keep_the_important_lines() {
    // The Why panel keeps the regime, the impacts and the energy split.
    for ascii in [false, true] {
        let s = screen("paper-b4.4", 0.3, (80, 24), ascii, None);
        let why = right_panel(&s);
        for want in ["RECOLLIDE", "impacts 9", "energy", "friction"] {
            assert!(why.contains(want), "{want}:\n{why}");
        }
    }
    // The runs list shows every method, once at least, with its error.
    let s = screen("paper-b4.9", 0.3, (80, 24), false, Some("c"));
    let runs = right_panel(&s);
    for (marker, name) in [
        ("e", "euler"),
        // Names longer than their column end with an ellipsis ("s symp…").
        ("s", "symp"),
        ("4", "rk4"),
        ("5", "rk45"),
        ("m", "more"),
    ] {
        let line = runs
            .lines()
            .find(|l| l.contains(&format!("{marker} {name}")))
            .unwrap_or_else(|| panic!("{name}:\n{runs}"));
        let err = line
            .trim_end_matches(['│', ' '])
            .rsplit(' ')
            .next()
            .unwrap();
        assert!(
            err.parse::<f64>().is_ok(),
            "{name}: err_v '{err}' in {line}"
        );
    }
    // The Fit panel keeps μ_k (the supported model's, μ_k + v0 + c_rr, as `fit`
    // prints it) and the regime verdict.
    let s = screen("paper-b4.9", 0.3, (80, 24), false, Some("f"));
    let fit = right_panel(&s);
    assert!(fit.contains("μ_k 0.1484"), "{fit}");
    // The verdict (with its margin) and what was observed (issue 11b's one verdict).
    assert!(fit.contains("predicted recollide"), "{fit}");
    assert!(fit.contains("observed recollide"), "{fit}");
    assert!(fit.contains("the model predicts what was seen"), "{fit}");
}

#[test]
fn f_switches_to_the_fit_view_from_any_view() {
    let mut a = app("paper-b4.9");
    press(&mut a, "c f");
    assert_eq!(a.view(), View::Fit);
    assert!(a.fit_view());
    a.wait();
    assert!(screen_of(&a).contains("model fit: μ_k+v0+c_rr"));
    press(&mut a, "g");
    assert_eq!(a.view(), View::Map, "g leaves the Fit view for the map");
    press(&mut a, "f f");
    assert_eq!(a.view(), View::Charts, "f again goes back to the charts");
    press(&mut a, "f c");
    assert_eq!(a.view(), View::Methods);
}

#[test]
fn typed_numbers_are_in_the_rows_unit_and_lenient() {
    let mut a = app("paper-b4.9");
    select(&mut a, Key::Width);
    press(&mut a, "enter");
    let s = screen_of(&a);
    assert!(s.contains("b in cm (or with a unit, e.g. 44mm)"), "{s}");
    press(&mut a, "4 . 4 enter");
    assert_eq!(a.lab.scene.width, 0.044, "a bare number is in cm");
    press(&mut a, "enter 4 , 6 c m enter");
    assert_eq!(a.lab.scene.width, 0.046);
    press(&mut a, "enter 4 . 5 C M enter");
    assert_eq!(a.lab.scene.width, 0.045);
    select(&mut a, Key::MassLeft);
    press(&mut a, "enter 1 6 7 G enter");
    assert_eq!(a.lab.scene.left.mass, 0.167);
    press(&mut a, "enter 2 0 0 enter");
    assert_eq!(a.lab.scene.left.mass, 0.2, "grams");
    select(&mut a, Key::Mu);
    press(&mut a, "enter 0 , 2 enter");
    assert_eq!(a.lab.scene.mu, 0.2);
    press(&mut a, "enter");
    assert!(screen_of(&a).contains("μ_k: a plain number"));
}

#[test]
fn overlay_measured_and_ghost_marks_differ_and_have_a_legend() {
    use groovelab::tui::theme::{Glyphs, Theme};
    let c = Theme::new(Glyphs::UNICODE, false);
    let fgs = [
        c.measured.fg,
        c.overlay.fg,
        c.overlay_t.fg,
        c.left.fg,
        c.accent.fg,
    ];
    for i in 0..fgs.len() {
        for j in 0..i {
            assert_ne!(fgs[i], fgs[j], "{i} {j}");
        }
    }
    let m = Theme::new(Glyphs::UNICODE, true);
    assert_ne!(m.overlay, m.overlay_t);
    assert_ne!(m.overlay, m.measured);
    // ASCII: distinct glyphs for the overlay's v_cm and v_t and the data, each in the
    // legend.
    // One overlay run, drawn at both sizes.
    let a = shown("paper-b4.9", 0.3, Some("o"));
    let s = text(&a, (120, 40), true);
    let chart: String = chart_rows(&s).join("\n");
    for mark in ["% euler", "~ v_t", "x measured v_cm", "o measured v_t"] {
        assert!(chart.contains(mark), "{mark}:\n{chart}");
    }
    // 80×24 puts the legend on more rows rather than dropping marks.
    let s = text(&a, (80, 24), true);
    for mark in ["% euler", "~ v_t", "x measured v_cm", "o measured v_t"] {
        assert!(s.contains(mark), "{mark}:\n{s}");
    }
    // The scene says what the ghost is.
    let s = screen("paper-b4.9", 0.1, (80, 24), true, None);
    assert!(
        s.lines().take(9).any(|l| l.contains(": measured ball")),
        "{s}"
    );
    let s = screen("flat-table", 0.1, (80, 24), false, None);
    assert!(!s.contains("measured ball"), "no data, no ghost");
}

#[test]
fn typing_replaces_a_suggested_name_and_enter_on_nothing_cancels() {
    let dir = std::env::temp_dir().join(format!("groovelab-suggest-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    let mut a = app("paper-b4.9");
    a.set_library(Library::at(Some(dir.clone())));
    // The save prompt offers a name; typing replaces it (it once appended:
    // my-paper-b4.9x), and a name typed as its file's is not doubled.
    press(&mut a, "s x . t o m l");
    assert!(
        matches!(&a.mode(), Mode::SaveName(n) if n.value() == "x.toml"),
        "{:?}",
        a.mode()
    );
    press(&mut a, "enter");
    assert!(dir.join("x.toml").is_file() && !dir.join("x.toml.toml").exists());
    // The export prompt likewise.
    press(&mut a, "w r . c s v");
    assert!(
        matches!(&a.mode(), Mode::Export(_, f) if f.value() == "r.csv"),
        "{:?}",
        a.mode()
    );
    // Enter on an empty line closes a prompt as Esc does, with no error.
    press(&mut a, "C-u enter");
    assert_eq!(a.mode(), Mode::Normal);
    assert!(
        matches!(&a.status, Status::Info(i) if i.starts_with("cancelled")),
        "{:?}",
        a.status
    );
    select(&mut a, Key::Width);
    let b = a.lab.scene.width;
    press(&mut a, "enter C-u enter");
    assert_eq!((a.mode(), a.lab.scene.width), (Mode::Normal, b));
    assert!(
        matches!(&a.status, Status::Info(i) if i.starts_with("cancelled")),
        "{:?}",
        a.status
    );
    // A typing error quotes what was typed, not the text with the row's unit glued on.
    press(&mut a, "enter C-u n a n enter");
    assert!(
        matches!(&a.status, Status::Error(e) if e.contains("'nan'") && !e.contains("nancm")),
        "{:?}",
        a.status
    );
    // R below b/2 names b as what to change first.
    select(&mut a, Key::Radius);
    press(&mut a, "enter C-u 2 enter");
    assert!(
        matches!(&a.status, Status::Error(e) if e.contains("needs b < 2R = 4 cm, and b = 4.9 cm: set b first")),
        "{:?}",
        a.status
    );
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn save_keeps_the_data_and_the_description_and_explains_bad_names() {
    let dir = std::env::temp_dir().join(format!("groovelab-save11-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    let mut a = app("paper-b4.4");
    a.set_library(Library::at(Some(dir.clone())));
    // A name with a space: refused, the dialog stays open and says why.
    press(&mut a, "s end space x enter");
    assert!(matches!(&a.mode(), Mode::SaveName(n) if n.value() == "my-paper-b4.4 x"));
    let s = screen_of(&a);
    assert!(s.contains("allowed letters, digits"), "{s}");
    press(&mut a, "backspace backspace enter");
    assert_eq!(a.mode(), Mode::Normal);
    let path = dir.join("my-paper-b4.4.toml");
    let saved = groovelab::input::preset::load(path.to_str().unwrap()).unwrap();
    assert_eq!(
        saved.measured,
        a.lab.preset().measured,
        "the measured series is saved"
    );
    assert!(saved.measured.is_some());
    // Overwriting keeps the description of the file it replaces.
    let text = std::fs::read_to_string(&path).unwrap().replace(
        "Saved from groovelab (started from paper-b4.4)",
        "my class, lesson 3",
    );
    std::fs::write(&path, text).unwrap();
    select(&mut a, Key::Mu);
    press(&mut a, "right s enter y");
    let again = groovelab::input::preset::load(path.to_str().unwrap()).unwrap();
    assert_eq!(again.description, "my class, lesson 3");
    assert_eq!(again.spec.resolve().unwrap().0.mu, a.lab.scene.mu);
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn long_messages_go_on_in_the_hint_row_and_the_preset_name_stays() {
    let mut a = app("paper-b4.9");
    let long =
        "a very long message about what just happened to the scene and why it matters to a class";
    a.status = Status::Info(long.into());
    for ascii in [false, true] {
        let s = text_of(&mut a, 80, 24, ascii);
        let (line, next) = (s.lines().nth(22).unwrap(), s.lines().nth(23).unwrap());
        assert!(
            line.starts_with("t = -0.200 s  paused   a very long"),
            "{line}"
        );
        assert!(line.ends_with("preset paper-b4.9"), "{line}");
        // Begun beside the time, ended on the next row, before help and quit.
        assert!(
            next.starts_with("matters to a class") || next.contains("to a class "),
            "{next}"
        );
        assert!(next.ends_with("? help  q quit"), "{next}");
        let words = format!(
            "{} {}",
            &line[23..line.len() - 17],
            &next[..next.len() - 14]
        );
        let words: Vec<&str> = words.split_whitespace().collect();
        assert_eq!(words.join(" "), long);
    }
    // Longer than both rows: cut with an ellipsis, and the preset name stays.
    a.status = Status::Error("x".repeat(200));
    let s = text_of(&mut a, 80, 24, false);
    assert!(s.lines().nth(22).unwrap().ends_with("preset paper-b4.9"));
    let next = s.lines().nth(23).unwrap();
    assert!(
        next.contains('…') && next.ends_with("? help  q quit"),
        "{next}"
    );
    // Picker descriptions are cut with an ellipsis too.
    let s = screen("paper-b4.9", 0.0, (80, 24), true, Some("p"));
    assert!(s.lines().any(|l| l.contains("...")), "{s}");
}

#[test]
fn one_v0_control_sets_both_balls() {
    let mut a = app("unequal-speeds");
    assert_ne!(a.lab.scene.left.v0, a.lab.scene.right.v0);
    select(&mut a, Key::V0);
    let s = screen_of(&a);
    let row = s.lines().find(|l| l.contains("v0 (both)")).unwrap();
    assert!(row.contains("differ"), "{row}");
    press(&mut a, "right");
    assert_eq!(a.lab.scene.left.v0, a.lab.scene.right.v0);
    let v = a.lab.scene.left.v0;
    let row = screen_of(&a)
        .lines()
        .find(|l| l.contains("v0 (both)"))
        .unwrap()
        .to_string();
    assert!(row.contains(&format!("{v:.3} m/s")), "{row}");
    press(&mut a, "enter 6 0 c m / s enter");
    assert_eq!((a.lab.scene.left.v0, a.lab.scene.right.v0), (0.6, 0.6));
}

#[test]
fn a_applies_the_fitted_mu_in_the_fit_view() {
    let mut a = app("paper-b4.9");
    press(&mut a, "a");
    assert!(matches!(&a.status, Status::Error(e) if e.contains("Fit view")));
    press(&mut a, "f");
    a.wait();
    let State::Ready(Ok(f)) = a.fit().fits() else {
        panic!("a fit")
    };
    let mu = f.model_fit.mu;
    assert!(
        (mu - a.lab.scene.mu).abs() > 1e-4,
        "the test needs a change"
    );
    press(&mut a, "a");
    assert_eq!(a.lab.scene.mu, mu);
    assert!(
        matches!(&a.status, Status::Info(i) if i.contains("applied the fit: μ_k = ")),
        "{:?}",
        a.status
    );
    let mut b = app("flat-table");
    press(&mut b, "f a");
    assert!(matches!(&b.status, Status::Error(_)));
}

/// Trial finding 12: of a position track, `a` applied the velocity fit's μ_k while the
/// panel says to quote the position fit's: it applies the position fit, and says so.
#[test]
fn a_applies_the_position_fit_of_a_track() {
    let track = DataArgs {
        data: vec!["docs/video/paper-b4.9-tracker.txt".into()],
        ..DataArgs::default()
    };
    let scene = scene_of("paper-b4.9", SceneSpec::default());
    let mut a = common::rendered(
        &scene,
        &track,
        None,
        Some("f"),
        common::no_user_presets("tui"),
    );
    a.wait();
    let State::Ready(Ok(f)) = a.fit().fits() else {
        panic!("the fits")
    };
    let velocity = f.velocity_fit.as_ref().map(|v| v.mu).unwrap();
    let position = f.model_fit.mu;
    // The two differ in the 4th digit here: the test tells them apart.
    assert!((velocity - position).abs() > 1e-5, "{velocity} {position}");
    press(&mut a, "a");
    assert_eq!(a.lab.scene.mu, position);
    assert!(
        matches!(&a.status, Status::Info(i) if i.contains("applied the position fit: μ_k = ")),
        "{:?}",
        a.status
    );
}

#[test]
fn export_writes_the_run_as_csv_and_the_chart_as_svg() {
    use groovelab::cli::{SimulateArgs, SimulateFormat, simulate};
    let dir = std::env::temp_dir().join(format!("groovelab-export-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let mut a = app("paper-b4.9");
    a.set_export_dir(dir.clone());
    press(&mut a, "w");
    assert!(matches!(&a.mode(), Mode::Export(_, n) if n.value() == "paper-b4.9-run.csv"));
    press(&mut a, "enter");
    // The file is written off the key press; the status line says so, then where.
    assert!(matches!(&a.status, Status::Info(i) if i.starts_with("writing")));
    a.wait();
    let path = dir.join("paper-b4.9-run.csv");
    let csv = std::fs::read_to_string(&path).unwrap();
    assert!(matches!(&a.status, Status::Info(i) if i.contains(&path.display().to_string())));
    // The same bytes as `simulate --format csv --sample 1ms`.
    let scene = scene_of("paper-b4.9", SceneSpec::default());
    let cli = simulate(
        &scene,
        &SimulateArgs {
            format: SimulateFormat::Csv,
            sample: Some(1e-3),
            method: groovelab::methods::Method::Exact,
            dt: None,
            tol: None,
            epsilon: None,
            output: None,
        },
    )
    .unwrap();
    // Its scene in comment lines first (issue 19), then the same bytes as `simulate`.
    let (scene, run) = csv.split_at(csv.find("\nt,").unwrap() + 1);
    assert!(scene.lines().all(|l| l.starts_with('#')), "{scene}");
    assert_eq!(run, cli);
    // The chart as SVG, with the data points.
    press(&mut a, "W enter");
    a.wait();
    assert!(matches!(&a.status, Status::Info(i) if i.contains("paper-b4.9-chart.svg")));
    let svg = std::fs::read_to_string(dir.join("paper-b4.9-chart.svg")).unwrap();
    assert!(
        svg.starts_with("<svg") && svg.contains("measured v_cm"),
        "{}",
        &svg[..200]
    );
    // A file that cannot be written: the prompt stays open and says why; no temp file.
    press(&mut a, "w");
    let typed: Vec<String> = "no/such/dir/x.csv".chars().map(String::from).collect();
    press(&mut a, &format!("C-u {}", typed.join(" ")));
    press(&mut a, "enter");
    assert!(matches!(a.mode(), Mode::Export(..)));
    assert!(matches!(&a.status, Status::Error(e) if e.contains("cannot write")));
    press(&mut a, "esc");
    let left: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    assert_eq!(left.len(), 2, "{left:?}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn the_data_table_of_a_position_track_shows_x_in_cm() {
    let track = DataArgs {
        data: vec!["docs/video/paper-b4.9-tracker.txt".into()],
        ..DataArgs::default()
    };
    let scene = scene_of("paper-b4.9", SceneSpec::default());
    let a = common::rendered(
        &scene,
        &track,
        None,
        Some("d"),
        common::no_user_presets("tui"),
    );
    let rows = groovelab::tui::view::data_rows(&a);
    let m = a.lab.measured().unwrap();
    let x = m.x.as_ref().unwrap();
    for (r, i) in rows.iter().zip(0..) {
        // The tracked centre where the model's left ball would be: x − R, aligned
        // by the impact's time and place shift the position fit profiles out (about a
        // millimetre here, 1.1 mm before the impact with the track's own v0 and the
        // preset's μ_k: the 0.3 mm noise moves the detected place).
        let model = a.lab.solution.at(m.t[i]).left.x;
        let want = a.lab.track_x.as_ref().unwrap()[i];
        assert!(
            want.is_nan() || (want - (x[i] - a.lab.scene.radius)).abs() < 1.5e-3,
            "row {i}: {want} vs {}",
            x[i] - a.lab.scene.radius
        );
        assert!(r[7] == want || (r[7].is_nan() && want.is_nan()), "row {i}");
        assert_eq!(r[8], model);
        assert!(r[9] == want - model || want.is_nan(), "row {i}");
    }
    let first = rows.iter().find(|r| r[7].is_finite()).unwrap();
    for (w, h) in [(120, 40), (80, 24)] {
        let s = text(&a, (w, h), false);
        assert!(s.contains("x (cm)") && s.contains("v_cm (m/s)"), "{s}");
        // In cm, beside the model's.
        let cells = format!("{:+9.3} {:+9.3}", 100.0 * first[7], 100.0 * first[8]);
        assert!(s.contains(&cells), "{cells}: {s}");
    }
    // A velocity file has no x: the table is as it was (its snapshot).
    let b = app("paper-b4.9");
    assert!(
        groovelab::tui::view::data_rows(&b)
            .iter()
            .all(|r| r[7].is_nan())
    );
}

#[test]
fn the_data_table_shows_the_model_beside_every_measured_point() {
    let mut a = app("paper-b4.9");
    press(&mut a, "d");
    assert_eq!(a.mode(), Mode::Table);
    let rows = groovelab::tui::view::data_rows(&a);
    let m = a.lab.measured().unwrap().clone();
    assert_eq!(rows.len(), m.t.len());
    for (r, i) in rows.iter().zip(0..) {
        let model = a.lab.solution.at(m.t[i]).left;
        assert_eq!(
            (r[0], r[1], r[2], r[4], r[5]),
            (m.t[i], m.v_cm[i], model.v, m.v_t[i], model.u)
        );
        assert!((r[3] - (m.v_cm[i] - model.v)).abs() < 1e-15);
    }
    let s = screen_of(&a);
    assert!(s.contains("v_cm (m/s)") && s.contains("t (s)"), "{s}");
    assert!(s.contains(&format!("{:+.3}", rows[0][1])));
    // It scrolls to the last row (at the size last drawn).
    let _ = text_of(&mut a, 80, 24, false);
    press(&mut a, "end");
    let s = text_of(&mut a, 80, 24, false);
    assert!(
        s.contains(&format!("{:+.4}", rows.last().unwrap()[0])),
        "{s}"
    );
    press(&mut a, "q");
    assert_eq!(a.mode(), Mode::Normal);
    let mut b = app("flat-table");
    press(&mut b, "d");
    assert_eq!(b.mode(), Mode::Normal);
    assert!(matches!(&b.status, Status::Error(e) if e.contains("no measured data")));
}

#[test]
fn the_data_table_marks_the_frames_the_fit_leaves_out_and_says_why() {
    // Seen: the row at t = 0 (residual +0.885) looked like a misfit; the fit leaves it
    // out, as it straddles the impact.
    let mut a = app("paper-b4.9");
    press(&mut a, "d");
    let impacts: Vec<f64> = a
        .lab
        .solution
        .events
        .iter()
        .filter(|e| e.kind == groovelab::physics::solution::EventKind::Collision)
        .map(|e| e.t)
        .collect();
    for ascii in [false, true] {
        let s = text(&a, (120, 40), ascii);
        assert!(
            s.contains("* left out of the fit: within a frame of an impact, where v jumps"),
            "{s}"
        );
        // Every row on screen: marked exactly when less than a frame (0.02 s) from
        // an impact of the model.
        let rows: Vec<(bool, f64)> = s
            .lines()
            .filter_map(|l| {
                // A border, the mark, then a time like -0.0200 and a space.
                let c: Vec<char> = l.chars().collect();
                c.windows(10).find_map(|w| {
                    let t: String = w[2..9].iter().collect();
                    let row = matches!(w[0], '│' | '|') && matches!(w[1], '*' | ' ');
                    (row && w[9] == ' ' && t.starts_with(['+', '-']))
                        .then(|| Some((w[1] == '*', t.parse::<f64>().ok()?)))
                        .flatten()
                })
            })
            .collect();
        assert!(rows.len() > 20, "{s}");
        assert!(rows.contains(&(true, 0.0)), "{rows:?}");
        for (marked, t) in rows {
            let near = impacts.iter().any(|&i| (t - i).abs() < 0.02 - 1e-9);
            assert_eq!(marked, near, "t = {t}");
        }
        assert!(
            s.contains(" -0.0200 "),
            "a frame beside the impact is kept: {s}"
        );
    }
}

#[test]
fn snapshots_of_issue_11_screens() {
    for (name, preset, keys) in [
        ("help", "paper-b4.9", "?"),
        ("help-end", "paper-b4.9", "? end"),
        ("data-table", "paper-b4.9", "d"),
        ("methods", "paper-b4.9", "c"),
        ("fit", "paper-b4.9", "f"),
        ("overlay", "paper-b4.9", "o"),
        ("save-bad-name", "paper-b4.9", "s end space x enter"),
        ("export", "paper-b4.9", "w"),
        ("v0-differ", "unequal-speeds", "down down down down"),
    ] {
        // One app per screen: its analyses (Methods rows, fits, overlay) computed once.
        let a = shown(preset, 0.3, Some(keys));
        for (w, h) in [(80, 24), (120, 40), (200, 60)] {
            for ascii in [false, true] {
                let mode = if ascii { "ascii" } else { "unicode" };
                // The test's preset folder has the process id in its name.
                let s = text(&a, (w, h), ascii)
                    .lines()
                    .map(|l| match l.find(" saved in ") {
                        Some(i) if l.contains("groovelab-tui-presets-") => {
                            format!("{} saved in <the test's preset folder>", &l[..i])
                        }
                        _ => l.to_string(),
                    })
                    .collect::<Vec<_>>()
                    .join("\n");
                insta::assert_snapshot!(format!("issue11-{name}-{w}x{h}-{mode}"), s);
            }
        }
    }
}

#[test]
fn the_map_legend_names_every_mark_at_every_size() {
    // Found by a new-user trial: at 120×40 the legend ended "▒ reco" (cut mid-word).
    for (w, h) in [(80, 24), (120, 40), (200, 60)] {
        for ascii in [false, true] {
            let s = screen("paper-b3.5", 0.0, (w, h), ascii, Some("g"));
            let legend = s
                .lines()
                .find(|l| l.contains("depart") || l.contains(".apart"));
            let legend = legend.unwrap_or_else(|| panic!("no legend at {w}x{h}:\n{s}"));
            assert!(
                legend.contains("back") || legend.contains("recollide"),
                "{legend}"
            );
            assert!(legend.contains(if ascii { '@' } else { '◆' }), "{legend}");
        }
    }
}

#[test]
fn the_fit_window_stays_after_the_impact_and_never_runs_backwards() {
    // Found by a new-user trial: twenty presses of `{` or `)` gave "0.02 … -0.08 s"
    // and the whole Fit panel vanished.
    let mut a = app("paper-b4.9");
    press(&mut a, "f");
    for keys in ["{", ")", "("] {
        for _ in 0..25 {
            press(&mut a, keys);
        }
        a.wait();
        let (from, to) = (a.fit().window.0.unwrap(), a.fit().window.1.unwrap());
        assert!(from > 0.0 && from < to, "{keys}: {from} … {to}");
        assert!(
            matches!(a.fit().fits(), State::Ready(Ok(_))),
            "{keys}: the fit stays"
        );
    }
    assert!(matches!(&a.status, Status::Error(e) if e.contains("at least 3 frames")));
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

#[test]
fn a_click_selects_a_preset_and_a_click_on_the_selected_one_loads_it() {
    // Seen: a click in the preset picker did nothing.
    let area = Rect::new(0, 0, 120, 40);
    let theme = Theme::new(Glyphs::UNICODE, true);
    let click = MouseEventKind::Down(MouseButton::Left);
    let mut a = app("paper-b4.9");
    press(&mut a, "p");
    let flat = a
        .library()
        .presets
        .iter()
        .position(|p| p.name == "flat-table")
        .unwrap();
    let (x, y) = cell_of(&text(&a, (120, 40), false), " flat-table ");
    assert!(on_mouse(&mut a, area, &theme, mouse(click, x + 5, y)));
    assert_eq!(a.mode(), Mode::Picker(flat), "a first click selects");
    assert_eq!(a.lab.preset().name, "paper-b4.9", "and loads nothing");
    assert!(text(&a, (120, 40), false).contains("▸flat-table"));
    on_mouse(&mut a, area, &theme, mouse(click, x + 5, y));
    assert_eq!(
        (a.mode(), a.lab.preset().name.as_str()),
        (Mode::Normal, "flat-table")
    );
    // The wheel moves through the list; a click beside the popup does nothing.
    press(&mut a, "p");
    let Mode::Picker(at) = a.mode() else { panic!() };
    on_mouse(
        &mut a,
        area,
        &theme,
        mouse(MouseEventKind::ScrollDown, 60, 20),
    );
    assert_eq!(a.mode(), Mode::Picker(at + 1));
    assert!(!on_mouse(&mut a, area, &theme, mouse(click, 0, 0)));
    assert_eq!(a.mode(), Mode::Picker(at + 1));
}

#[test]
fn over_a_popup_the_mouse_acts_on_the_popup_alone() {
    let area = Rect::new(0, 0, 120, 40);
    let theme = Theme::new(Glyphs::UNICODE, true);
    let click = MouseEventKind::Down(MouseButton::Left);
    // The help: a click on a parameter row behind it neither closes it nor selects;
    // the wheel scrolls it.
    let mut a = app("paper-b4.9");
    let (x, y) = cell_of(&text(&a, (120, 40), false), " R  ");
    press(&mut a, "?");
    let _ = text(&a, (120, 40), false);
    assert!(!on_mouse(&mut a, area, &theme, mouse(click, x + 1, y)));
    assert_eq!((a.mode(), a.selected()), (Mode::Help, 1));
    on_mouse(
        &mut a,
        area,
        &theme,
        mouse(MouseEventKind::ScrollDown, 60, 20),
    );
    let scrolled = a.layers().top().map(|l| match l {
        groovelab::tui::layer::Layer::Help(h) => h.scroll().first(),
        _ => 0,
    });
    assert_eq!(scrolled, Some(1));
    // The data table: a click on the chart behind it does not seek.
    press(&mut a, "esc d");
    let t = a.t;
    assert!(!on_mouse(&mut a, area, &theme, mouse(click, 30, 25)));
    assert_eq!((a.mode(), a.t), (Mode::Table, t));
    // The prediction: a click on an answer answers.
    press(&mut a, "esc y");
    let (x, y) = cell_of(&text(&a, (120, 40), false), " 2 they come to rest");
    on_mouse(&mut a, area, &theme, mouse(click, x + 4, y));
    assert_eq!(a.mode(), Mode::Normal);
    assert_eq!(a.prediction().map(|p| p.guess), Some(Regime::Rest));
    // A prompt takes no click: the typing goes on.
    press(&mut a, "enter");
    assert!(!on_mouse(&mut a, area, &theme, mouse(click, x, y)));
    assert!(matches!(a.mode(), Mode::Edit(_)));
}

/// A step from the limit says the row is at its limit (issue 19: "a coarse step past
/// a limit stops at the limit"), never naming a value nobody typed: PgUp at b = 5.45
/// cm said "b = 6 cm is out of range", and → at the limit left the status blank.
#[test]
fn a_step_from_the_limit_says_so() {
    for keys in ["pgup pgup", "pgup pgup right", "pgup pgup pgup"] {
        let out = common::groovelab(&["render", "--keys", keys, "--size", "120x40"]);
        let s = String::from_utf8(out.stdout).unwrap();
        let status = s.lines().rev().nth(1).unwrap();
        assert!(
            status.contains("b is at its limit (5.45 cm)"),
            "{keys}: {status}"
        );
        assert!(!status.contains("6 cm"), "{keys}: {status}");
    }
}

/// A component renders alone, headless, into any area: the Forces view drawn by
/// itself is the very drawing the screen makes in the view's place (the compositor
/// adds the panels around it, nothing inside it), so a test of the Forces view does
/// not depend on the parameters panel.
#[test]
fn a_component_renders_alone_as_on_the_screen() {
    use groovelab::tui::component::{Component, Ctx};
    use groovelab::tui::screen::Screen;
    use groovelab::tui::view::forces::ForcesView;
    use ratatui::buffer::Buffer;
    let mut a = app("paper-b4.9");
    press(&mut a, "v");
    a.t = 0.05;
    let theme = Theme::new(Glyphs::UNICODE, true);
    let area = Rect::new(0, 0, 120, 40);
    let mut screen = Screen::default();
    let mut whole = Buffer::empty(area);
    screen.draw(&a, area, &mut whole, &theme);
    let frame = screen.frame().unwrap();
    let p = frame.panels.unwrap();
    let middle = p.chart.union(p.info);
    let cx = Ctx {
        app: &a,
        frame,
        theme: &theme,
    };
    let mut alone = Buffer::empty(middle);
    ForcesView.render(middle, &mut alone, &cx);
    let text: String = (middle.top()..middle.bottom())
        .flat_map(|y| (middle.left()..middle.right()).map(move |x| (x, y)))
        .map(|(x, y)| alone[(x, y)].symbol().to_string())
        .collect();
    assert!(text.contains("Forces: side view"), "{text}");
    for y in middle.top()..middle.bottom() {
        for x in middle.left()..middle.right() {
            assert_eq!(alone[(x, y)], whole[(x, y)], "cell ({x}, {y})");
        }
    }
    // Alone in an area of its own (a small one), it draws there and nowhere else.
    let small = Rect::new(0, 0, 80, 16);
    let mut buf = Buffer::empty(small);
    ForcesView.render(small, &mut buf, &cx);
    assert!(buf.content.iter().any(|c| c.symbol() != " "));
}
