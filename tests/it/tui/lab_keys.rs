//! The lab's keys without a terminal: parameters, typing, prompts, playback, the picker, saving.

use super::*;

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
    let dir = crate::common::scratch_dir("tui", "save-never-overwrites");
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
