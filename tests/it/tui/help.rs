//! Issue 11's help, keys and small screens, and the teachers' tools: typing, saving, applying a fit.

use super::*;

// ---- issue 11: help, keys and small screens; teachers' tools ----

#[test]
fn help_is_complete_at_every_size_scrolling_where_needed() {
    for (w, h) in [(80, 24), (120, 40), (200, 63)] {
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
            if h >= 63 {
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
    for (w, h) in [(80, 24), (120, 40), (200, 63)] {
        for ascii in [false, true] {
            let s = screen("paper-b4.9", 0.2, (w, h), ascii, None);
            let bar = s.lines().last().unwrap();
            assert!(bar.ends_with("? help  q quit"), "{w}x{h}: {bar}");
            assert!(bar.contains("play") && bar.contains("change"), "{bar}");
        }
    }
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

/// Esc leaves any view for the charts, as the view's own key again does, and never
/// quits; on the charts it says that q quits. It stayed in the Forces, Map and
/// Methods views and only said "q quits" (a new user's trial).
#[test]
fn esc_leaves_any_view_for_the_charts() {
    let mut a = app("paper-b4.9");
    for (key, view) in [
        ("v", View::Forces),
        ("g", View::Map),
        ("c", View::Methods),
        ("f", View::Fit),
    ] {
        press(&mut a, key);
        assert_eq!(a.view(), view, "{key}");
        press(&mut a, "esc");
        assert_eq!(a.view(), View::Charts, "{key} esc");
        assert!(!a.quitting(), "{key} esc");
    }
    press(&mut a, "esc");
    assert_eq!(a.view(), View::Charts);
    assert!(!a.quitting());
    assert!(screen_of(&a).contains("q quits"), "{}", screen_of(&a));
}

#[test]
fn f_switches_to_the_fit_view_from_any_view() {
    let mut a = app("paper-b4.9");
    press(&mut a, "c f");
    assert_eq!(a.view(), View::Fit);
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
    // A bare number under 1 is applied in the row's unit, and the status says how
    // to write the SI value the command line would have read (`--width 0.05`: 5 cm).
    select(&mut a, Key::Width);
    press(&mut a, "enter 0 . 0 5 enter");
    assert_eq!(a.lab.scene.width, 0.0005, "0.05 cm");
    let said = "a bare number is in cm here: for 0.05 m type 0.05m";
    assert!(
        matches!(&a.status, Status::Info(i) if i.ends_with(said)),
        "{:?}",
        a.status
    );
    press(&mut a, "enter 0 . 0 5 m enter");
    assert_eq!(a.lab.scene.width, 0.05);
    assert!(
        matches!(&a.status, Status::Info(i) if !i.contains("bare")),
        "{:?}",
        a.status
    );
    select(&mut a, Key::MassLeft);
    press(&mut a, "enter 0 , 2 enter");
    assert!(
        matches!(&a.status, Status::Info(i) if i.ends_with("a bare number is in g here: for 0.2 kg type 0.2kg")),
        "{:?}",
        a.status
    );
    select(&mut a, Key::Mu);
    press(&mut a, "enter 0 , 2 enter");
    assert_eq!(a.lab.scene.mu, 0.2);
    assert!(
        matches!(&a.status, Status::Info(i) if !i.contains("bare")),
        "{:?}",
        a.status
    );
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
    let dir = crate::common::scratch_dir("tui", "suggested-name");
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
    let dir = crate::common::scratch_dir("tui", "save-bad-names");
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

/// `q` with changes to the scene that are not saved says what quitting loses, and a
/// second `q` quits; any other key between takes the question back. Unchanged, or
/// saved as a preset (`s`) or written with its run (`w`), one `q` quits; Ctrl-C always
/// quits at once. A reflex `q` lost a student's whole setup.
#[test]
fn q_with_unsaved_changes_asks_once_and_ctrl_c_quits_at_once() {
    let unsaved = "scene changed, not saved: q again quits (s saves a preset, w writes the run)";
    // Unchanged: one q.
    let mut a = app("paper-b4.9");
    press(&mut a, "q");
    assert!(a.quitting());
    // Changed by a key (b one step up): q asks, another key takes it back, q q quits.
    let mut a = app("paper-b4.9");
    select(&mut a, Key::Width);
    press(&mut a, "right q");
    assert!(!a.quitting());
    assert!(screen_of(&a).contains(unsaved), "{}", screen_of(&a));
    // Whole on the smallest common terminal too, over two rows (it was cut at 80
    // columns before "w").
    let small = crate::common::text(&a, (80, 24), false);
    for part in unsaved.split_inclusive("quits ") {
        assert!(small.contains(part.trim()), "{part}: {small}");
    }
    press(&mut a, "space q");
    assert!(!a.quitting(), "a key between takes the question back");
    press(&mut a, "q");
    assert!(a.quitting());
    // Ctrl-C: at once, changes or not, from a popup too.
    let mut a = app("paper-b4.9");
    a.set_value(Key::Mu, 0.2);
    press(&mut a, "? C-c");
    assert!(a.quitting());
    // Changed back by undo: nothing is lost, one q.
    let mut a = app("paper-b4.9");
    a.set_value(Key::Mu, 0.2);
    press(&mut a, "u q");
    assert!(a.quitting(), "undone: {}", screen_of(&a));
    // Saved as a preset, or written with its run: one q, until the next change.
    let dir = crate::common::scratch_dir("tui", "quit-saved");
    // μ_k changed, then `keys` pressed (and what they write written).
    let saved = |keys: &str| {
        let mut a = app("paper-b4.9");
        a.set_library(Library::at(Some(dir.clone())));
        a.set_export_dir(dir.clone());
        a.set_value(Key::Mu, 0.2);
        press(&mut a, keys);
        a.wait();
        a
    };
    for keys in ["s enter", "w enter"] {
        let mut a = saved(keys);
        press(&mut a, "q");
        assert!(a.quitting(), "{keys}: {}", screen_of(&a));
        let mut a = saved(keys);
        a.set_value(Key::Mu, 0.25);
        press(&mut a, "q");
        assert!(!a.quitting(), "{keys}, then a change");
    }
    let _ = std::fs::remove_dir_all(&dir);
}
