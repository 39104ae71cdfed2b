//! Exports, the data table, issue 11's screens, the map legend, the fit window, the mouse over popups, a component drawn alone.

use super::*;

#[test]
fn export_writes_the_run_as_csv_and_the_chart_as_svg() {
    use groovelab::cli::{SimulateArgs, SimulateFormat, simulate};
    let dir = crate::common::scratch_dir("tui", "export");
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
    let x = m.x().unwrap();
    for (r, i) in rows.iter().zip(0..) {
        // The tracked centre where the model's left ball would be: x − R, aligned
        // by the impact's time and place shift the position fit profiles out (about a
        // millimetre here, 1.1 mm before the impact with the track's own v0 and the
        // preset's μ_k: the 0.3 mm noise moves the detected place).
        let model = a.lab.solution.at(m.t()[i]).left.x;
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
    assert_eq!(rows.len(), m.t().len());
    for (r, i) in rows.iter().zip(0..) {
        let model = a.lab.solution.at(m.t()[i]).left;
        assert_eq!(
            (r[0], r[1], r[2], r[4], r[5]),
            (m.t()[i], m.v_cm()[i], model.v, m.v_t()[i], model.u)
        );
        assert!((r[3] - (m.v_cm()[i] - model.v)).abs() < 1e-15);
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

/// Found by a new-user trial: the map's b/R axis had no numbers (its range was only
/// in the long legend, which fits a wide map alone); a row under the map gives its
/// ticks: 0, 1 (b = R) at its column, and the right end (b = 1.98 R), at every size.
#[test]
fn the_maps_b_over_r_axis_has_its_ticks_at_every_size() {
    for (w, h) in [(80, 24), (120, 40), (200, 60)] {
        for ascii in [false, true] {
            let s = screen("paper-b3.5", 0.0, (w, h), ascii, Some("g"));
            let axis = s
                .lines()
                .find(|l| l.contains("b/R  0"))
                .unwrap_or_else(|| panic!("no b/R axis at {w}x{h}:\n{s}"));
            // The map's own panel: the first of the row's panels.
            let border = if ascii { '|' } else { '│' };
            let map: String = axis.chars().skip(1).take_while(|&c| c != border).collect();
            let at = |tick: &str| {
                map.find(&format!(" {tick} "))
                    .or_else(|| {
                        map.trim_end()
                            .ends_with(tick)
                            .then(|| map.trim_end().len() - tick.len())
                    })
                    .unwrap_or_else(|| panic!("{tick} missing at {w}x{h}: {map:?}"))
            };
            let (zero, one, end) = (at("0"), at("1"), at("1.98"));
            assert!(zero < one && one < end, "{w}x{h}: {map:?}");
            // b/R = 1 at about half the way from 0 to 1.98.
            let half = zero as f64 + (end + 4 - zero) as f64 / 1.98;
            assert!((one as f64 + 1.0 - half).abs() <= 2.0, "{w}x{h}: {map:?}");
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

/// Found by a new-user trial: a key that means nothing (`j`, `K`, Ctrl-J) did
/// nothing visible; the status line now says so and where the keys are listed, in
/// the terminal and in `render` alike (one replay). A line being typed takes its
/// keys itself: no such message there.
#[test]
fn a_key_that_means_nothing_says_so() {
    for (script, name) in [("j", "j"), ("K", "K"), ("~", "~"), ("C-j", "Ctrl-j")] {
        let mut a = app("paper-b4.9");
        press(&mut a, script);
        assert!(
            matches!(&a.status, Status::Info(m) if m == &format!("no key {name} here: ? lists the keys")),
            "{script}: {:?}",
            a.status
        );
        // A key that means something replaces the message.
        press(&mut a, "down");
        assert!(
            !matches!(&a.status, Status::Info(m) if m.starts_with("no key")),
            "{:?}",
            a.status
        );
    }
    let mut a = app("paper-b4.9");
    press(&mut a, "enter");
    press(&mut a, "j");
    assert!(
        !matches!(&a.status, Status::Info(m) if m.starts_with("no key")),
        "typing: {:?}",
        a.status
    );
}
