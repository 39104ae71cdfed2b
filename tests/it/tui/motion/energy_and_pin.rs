//! The energy chart, the A/B comparison of a pinned run, snapshots, and huge measured series.

use super::*;

// ---- 3. The energy chart --------------------------------------------------------------

#[test]
fn the_energy_chart_splits_the_initial_energy_at_every_sample() {
    let mut a = app("inelastic");
    press(&mut a, "e");
    assert!(a.charts().energy());
    let split = ViewCache::default().energies(&a.lab, (100, a.chart_span()));
    let total = split[0].1.total();
    assert!(total > 0.0);
    for (t, e) in split.iter() {
        // The ledger is exact: the parts add up to the start's energy to rounding.
        assert!((e.total() - total).abs() <= 1e-9 * total, "{t}: {e:?}");
    }
    assert!(
        split.last().unwrap().1.lost.impacts > 0.0,
        "e < 1 loses in impacts"
    );
    let s = screen::to_text(&a, 120, 40, &Theme::new(Glyphs::UNICODE, false));
    assert!(s.contains("Energy of both balls"));
    for name in ["total", "trans", "rot", "friction", "impacts", "c_rr 0"] {
        assert!(s.contains(name), "{name}: {s}");
    }
    // `x` and `e` replace each other; `e` again goes back to the velocities.
    press(&mut a, "x");
    assert!(a.charts().positions() && !a.charts().energy());
    press(&mut a, "e e");
    assert!(!a.charts().positions() && !a.charts().energy());
}

#[test]
fn the_energy_chart_tells_its_curves_apart_without_colour() {
    let mut a = app("inelastic");
    press(&mut a, "e");
    a.t = 0.1;
    for ascii in [false, true] {
        let s = text(&a, (120, 40), ascii);
        let rows = chart_rows(&s, 40);
        // Row 0 is the border, row 1 the legend, then the plot, the ticks, the border.
        let plot: String = rows[2..rows.len() - 2].concat();
        // Letters in the legend and on the curves: t, r, f, i.
        for (legend, mark) in [("t trans", 't'), ("r rot", 'r'), ("f friction", 'f')] {
            assert!(rows[1].contains(legend), "{legend}: {}", rows[1]);
            assert!(plot.contains(mark), "{mark} drawn ({ascii})");
        }
        if ascii {
            assert!(s.is_ascii());
        }
    }
}

// ---- 4. A/B comparison ----------------------------------------------------------------

#[test]
fn a_pinned_run_is_drawn_beside_the_current_one_with_what_changed() {
    let mut a = app("paper-b4.9");
    press(&mut a, "P");
    assert!(a.lab.pinned.is_some());
    select(&mut a, Key::Width);
    press(&mut a, "enter 4 . 4 c m enter");
    let changes = a.lab.pinned_changes.clone();
    assert_eq!(
        changes,
        vec![("b", "4.9 cm".to_string(), "4.4 cm".to_string())]
    );
    a.t = 0.5;
    let theme = Theme::new(Glyphs::UNICODE, true);
    let s = screen::to_text(&a, 120, 40, &theme);
    assert!(
        s.contains("pinned paper-b4.9 (dashed): b 4.9 cm → 4.4 cm"),
        "{s}"
    );
    assert!(s.contains("pinned run"), "the chart's legend");
    // The pinned run's span is covered: it ends later than the 4.4 cm run's own.
    let pinned_end = a.lab.pinned.as_ref().unwrap().solution.t_end;
    assert!(a.lab.solution.t_end >= pinned_end);
    // The scene shows more ink than the same scene unpinned (the ghost balls).
    let mut b = a.clone();
    press(&mut b, "P");
    assert!(b.lab.pinned.is_none());
    let unpinned = screen::to_text(&b, 120, 40, &theme);
    let scene = |s: &str| -> usize {
        s.lines()
            .take(9)
            .map(|l| {
                l.chars()
                    .skip(42)
                    .filter(|c| ('\u{2801}'..='\u{28ff}').contains(c))
                    .count()
            })
            .sum()
    };
    assert!(scene(&s) > scene(&unpinned), "ghosts drawn");
    assert!(!unpinned.contains("pinned run") && !unpinned.contains("(dashed)"));
    // Positions and energy charts draw the pinned run too.
    press(&mut a, "x");
    assert!(screen::to_text(&a, 120, 40, &theme).contains("pinned run"));
    press(&mut a, "e");
    assert!(screen::to_text(&a, 120, 40, &theme).contains("pinned kinetic"));
}

#[test]
fn a_long_list_of_changes_is_cut_with_an_ellipsis() {
    let mut a = app("paper-b4.9");
    press(&mut a, "P");
    for (key, v) in [
        (Key::Width, 0.044),
        (Key::Mu, 0.2),
        (Key::Restitution, 0.8),
        (Key::RollingResistance, 0.01),
        (Key::Mass, 0.2),
    ] {
        a.lab.set(key, v).unwrap();
    }
    let s = text(&a, (80, 24), true);
    assert!(s.is_ascii());
    let line = s.lines().nth(8).unwrap();
    assert!(line.contains("pinned paper-b4.9"), "{line}");
    assert!(line.contains("..."), "{line}");
}

// ---- Snapshots ----------------------------------------------------------------------

#[test]
fn snapshots_of_the_whole_motion_energy_and_pin() {
    let cases: [(&str, &str, SceneSpec, Option<f64>, &str); 4] = [
        ("b4.9-mu0.05-end", "paper-b4.9", mu(0.05), None, "end"),
        (
            "b4.4-t-inf",
            "paper-b4.4",
            SceneSpec::default(),
            None,
            "end <",
        ),
        ("energy", "inelastic", SceneSpec::default(), Some(0.1), "e"),
        (
            "pinned",
            "paper-b4.9",
            SceneSpec::default(),
            Some(0.4),
            "P down down down right right right right right",
        ),
    ];
    for (name, preset, values, at, keys) in cases {
        // One app per case, drawn at every size and glyph set.
        let scene = scene_of(preset, values);
        let data = DataArgs::default();
        let a = common::rendered(&scene, &data, at, Some(keys), no_user_presets());
        for (w, h) in SIZES {
            for ascii in [false, true] {
                let mode = if ascii { "ascii" } else { "unicode" };
                insta::assert_snapshot!(format!("{name}-{w}x{h}-{mode}"), text(&a, (w, h), ascii));
            }
        }
    }
}

#[test]
fn pinning_does_not_stretch_a_scaled_span_again() {
    let mut a = app("paper-b4.4");
    press(&mut a, "t");
    let doubled = a.lab.solution.t_end;
    press(&mut a, "P");
    assert_eq!(a.lab.solution.t_end, doubled, "same scene: same span");
    press(&mut a, "P t t P");
    assert_eq!(a.lab.span_end, SpanEnd::Auto);
    let auto = a.lab.solution.t_end;
    // A pinned slower run (more friction ends it sooner) keeps the longer span.
    select(&mut a, Key::Mu);
    press(&mut a, "S-right S-right");
    assert!(
        a.lab.solution.t_end >= auto - 1e-12,
        "{} {auto}",
        a.lab.solution.t_end
    );
}

#[test]
fn new_screens_need_no_ascii_stand_ins() {
    // `force_ascii` would hide a stray symbol; the views must draw ASCII themselves.
    let theme = Theme::new(Glyphs::ASCII, true);
    for preset in ["paper-b4.9", "inelastic", "paper-b4.4"] {
        for keys in [
            "e",
            "P right right",
            "P S-right e",
            "P S-right x",
            "t",
            "> > >",
        ] {
            let mut a = app(preset);
            press(&mut a, keys);
            a.wait();
            for (w, h) in SIZES {
                let cells = screen::non_ascii_cells(&a, w, h, &theme);
                assert!(cells.is_empty(), "{preset} {keys:?} {w}x{h}: {cells:?}");
            }
        }
    }
}

#[test]
fn unpinning_keeps_the_cursor_inside_the_span() {
    // End, pin, a narrower groove (a shorter run), end, unpin: the span shrinks back.
    let mut a = app("paper-b4.9");
    press(&mut a, "end P enter 3 . 5 enter end P");
    let sol = &a.lab.solution;
    assert!(
        a.t >= sol.t_start && a.t <= sol.t_end,
        "{} of {} … {}",
        a.t,
        sol.t_start,
        sol.t_end
    );
}

#[test]
fn a_million_measured_rows_draw_as_a_few_points_per_column_thinned_once() {
    let theme = Theme::new(Glyphs::UNICODE, true);
    let mut a = with_big_series(1_000_000);
    // What a screen draws of `a`: the text, the points handed to the plot, and how
    // many series it thinned for this frame.
    let drawn = |screen: &mut Screen, a: &App, (w, h): (u16, u16)| {
        let (text, work) = screen.text(a, w, h, &theme);
        let points = screen.frame().unwrap().chart.as_ref().unwrap().points();
        (text, points, work.marks_thinned)
    };
    let (mut screen, mut bare_screen) = (Screen::default(), Screen::default());
    let mut without = a.clone();
    without.lab.drop_data();
    for size in [(120, 40), (200, 60)] {
        let columns = view::layout(Rect::new(0, 0, size.0, size.1))
            .unwrap()
            .chart
            .width as usize;
        let (_, bare, _) = drawn(&mut bare_screen, &without, size);
        let (text, points, thinned) = drawn(&mut screen, &a, size);
        assert!(text.contains("big.csv"), "the user's series is drawn");
        // The exact curves draw about 4 points per column each; the million rows add
        // no more than a few per column (one per cell they mark: a smooth curve).
        assert!(
            points - bare <= 4 * columns,
            "{size:?}: {} measured points drawn for {columns} columns",
            points - bare
        );
        assert_eq!(thinned, 1, "thinned once");
        // Nothing changed, or only the time: no thinning again, the same points.
        let again = drawn(&mut screen, &a, size);
        a.seek(0.3);
        let moved = drawn(&mut screen, &a, size);
        assert_eq!((again.1, moved.1), (points, points));
        assert_eq!((again.2, moved.2), (0, 0), "not again");
        a.seek(a.lab.solution.t_start);
    }
    // The spike survives thinning: the y axis reaches it (1.5 m/s, the largest value
    // drawn), and it is marked on the plot's top row.
    let (text, _, _) = drawn(&mut screen, &a, (120, 40));
    let mut rows = text.lines().skip_while(|l| !l.contains("v (m/s)"));
    let top = rows.nth(1).unwrap();
    let plot = &top[..top.find("││").unwrap()];
    assert!(plot.contains('×'), "{text}");
    // An edit is a new snapshot: its points are thinned again.
    press(&mut a, "right");
    assert_eq!(drawn(&mut screen, &a, (120, 40)).2, 1);
}
