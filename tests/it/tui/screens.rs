//! The headless screen `render` prints: charts, cursor, ASCII, small terminals, snapshots, mouse, the Methods and Map views.

use super::*;

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
            // Each time at one size, the sizes taking turns (the four times meet all
            // three sizes for every preset and key, without the whole cross product).
            let sizes = [(80, 24), (120, 40), (60, 20)];
            for (k, t) in [-0.1f64, 0.05, 0.3, 10.0].into_iter().enumerate() {
                a.t = t.clamp(a.lab.solution.t_start, a.lab.solution.t_end);
                let size = sizes[(k + keys.len()) % 3];
                // One drawing: the cells that needed a stand-in, and the text.
                let (s, cells) =
                    groovelab::tui::screen::to_text_and_non_ascii_cells(&a, size.0, size.1, &theme);
                if !cells.is_empty() {
                    failures.push(format!("{} at {t} {size:?} {keys:?}: {cells:?}", p.name));
                }
                assert!(s.is_ascii());
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
