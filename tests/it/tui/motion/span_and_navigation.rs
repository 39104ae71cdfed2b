//! The span follows the physics, and navigation: events, measured frames, clicks and drags on the chart.

use super::*;

// ---- 1. The span follows the physics ----------------------------------------------

#[test]
fn paper_b4_9_with_low_friction_shows_all_twenty_impacts_up_to_t_inf() {
    let mut a = app("paper-b4.9");
    select(&mut a, Key::Mu);
    press(&mut a, "enter 0 . 0 5 enter");
    assert_eq!(a.lab.scene.mu, 0.05);
    let sol = a.lab.solution.clone();
    let t_inf = sol.accumulation.expect("the impacts accumulate");
    assert!((t_inf - 2.939).abs() < 5e-4, "T∞ {t_inf}");
    assert_eq!(sol.impacts, 20);
    // Every impact is inside the span, and the span reaches past T∞.
    let shown = sol
        .visible_events()
        .filter(|e| e.kind == EventKind::Collision)
        .count();
    let all = sol
        .events
        .iter()
        .filter(|e| e.kind == EventKind::Collision)
        .count();
    assert_eq!(shown, all);
    assert!(sol.t_end > t_inf, "{} > {t_inf}", sol.t_end);
    // The animation's last frame is after T∞; the chart's axis reaches it.
    press(&mut a, "end");
    assert!(a.t > t_inf);
    let s = text(&a, (120, 40), false);
    assert!(last_x_tick(&s, 40) >= 3.0, "{s}");
    assert!(chart_rows(&s, 40).concat().contains("T∞"));
    // The same through `render`, which also accepts any time in the span.
    let r = render("paper-b4.9", mu(0.05), Some(3.0), (120, 40), false, "").unwrap();
    assert!(r.contains("t = 3.000 s"), "{r}");
    assert!(last_x_tick(&r, 40) >= 3.0);
    let err = render("paper-b4.9", mu(0.05), Some(5.0), (120, 40), false, "").unwrap_err();
    assert!(err.contains("outside the simulated span"), "{err}");
}

#[test]
fn paper_b4_4_shows_its_nine_impacts_up_to_t_inf() {
    let a = app("paper-b4.4");
    let sol = &a.lab.solution;
    let t_inf = sol.accumulation.expect("recollides");
    assert!((t_inf - 2.126).abs() < 5e-4, "T∞ {t_inf}");
    assert_eq!(sol.impacts, 9);
    assert!(sol.t_end > t_inf);
    assert_eq!(
        sol.visible_events()
            .filter(|e| e.kind == EventKind::Collision)
            .count(),
        9
    );
    for (w, h) in SIZES {
        let s = render(
            "paper-b4.4",
            SceneSpec::default(),
            None,
            (w, h),
            false,
            "end",
        )
        .unwrap();
        assert!(last_x_tick(&s, h) >= 2.0, "{w}x{h}: {s}");
        assert!(chart_rows(&s, h).concat().contains("T∞"), "{w}x{h}: {s}");
        assert!(s.contains("impacts 9"), "{w}x{h}");
    }
}

#[test]
fn the_automatic_span_also_covers_the_measured_points() {
    // paper-b4.9 (μ_k 0.17) is over at 0.86 s; its measured series runs to 0.88 s.
    let a = app("paper-b4.9");
    let last = *a.lab.measured().unwrap().t().last().unwrap();
    assert!(a.lab.solution.t_end >= last);
    assert_eq!(a.lab.span_end, SpanEnd::Auto);
}

#[test]
fn a_presets_t_end_holds_until_a_parameter_changes() {
    let p = preset_with_t_end();
    let mut a = App::new(Lab::of_preset(p).unwrap(), no_user_presets());
    assert_eq!(a.lab.solution.t_end, 0.5);
    assert!(matches!(
        a.lab.span_end,
        SpanEnd::Fixed {
            from_preset: true,
            ..
        }
    ));
    select(&mut a, Key::Mu);
    press(&mut a, "right");
    assert_eq!(a.lab.span_end, SpanEnd::Auto);
    let sol = &a.lab.solution;
    assert!(sol.t_end > sol.accumulation.unwrap(), "{}", sol.t_end);
}

#[test]
fn an_explicit_t_end_holds_through_parameter_changes() {
    // In the app: t_end set through the lab.
    let mut a = app("paper-b4.9");
    a.lab.set(Key::TEnd, 0.5).unwrap();
    select(&mut a, Key::Mu);
    press(&mut a, "left left");
    assert_eq!(a.lab.solution.t_end, 0.5);
    // On the command line: --t-end is explicit, in `render` and after keys.
    let values = SceneSpec::default().with(Key::TEnd, 0.5);
    let s = render(
        "paper-b4.9",
        values.clone(),
        None,
        (120, 40),
        false,
        "down down down right",
    )
    .unwrap();
    assert!(s.contains("of -0.200 … 0.500 s"), "{s}");
    // A scene option on the command line ends a preset's t_end (there, none).
    let s = render("paper-b4.9", mu(0.05), None, (120, 40), false, "").unwrap();
    assert!(s.contains("… 3.567 s"), "{s}");
}

#[test]
fn the_span_key_cycles_auto_double_half() {
    let mut a = app("paper-b4.4");
    let (t0, auto) = (a.lab.solution.t_start, a.lab.solution.t_end);
    let close = |x: f64, y: f64| (x - y).abs() < 1e-12;
    press(&mut a, "end t");
    assert_eq!(a.lab.span_end, SpanEnd::Scaled(2.0));
    assert!(close(a.lab.solution.t_end, t0 + 2.0 * (auto - t0)));
    assert!(matches!(&a.status, Status::Info(s) if s.contains("span auto ×2")));
    // The scaled span still follows the physics.
    select(&mut a, Key::Mu);
    press(&mut a, "right");
    let auto2 = {
        let mut b = a.clone();
        b.lab.set_span_end(SpanEnd::Auto).unwrap();
        b.lab.solution.t_end
    };
    assert!(close(a.lab.solution.t_end, t0 + 2.0 * (auto2 - t0)));
    press(&mut a, "t");
    assert!(close(a.lab.solution.t_end, t0 + 0.5 * (auto2 - t0)));
    assert!(a.t <= a.lab.solution.t_end, "the cursor stays in the span");
    press(&mut a, "t");
    assert_eq!(a.lab.span_end, SpanEnd::Auto);
    assert!(close(a.lab.solution.t_end, auto2));
}

#[test]
fn saving_keeps_only_a_set_span_end() {
    let dir = crate::common::scratch_dir("tui", "save-span-end");
    let mut a = app("paper-b4.9");
    let path = save(&a, &dir, "auto-span");
    let text = std::fs::read_to_string(&path).unwrap();
    assert!(!text.contains("t_end"), "{text}");
    a.lab.set(Key::TEnd, 0.7).unwrap();
    let path = save(&a, &dir, "fixed-span");
    let text = std::fs::read_to_string(&path).unwrap();
    assert!(text.contains("t_end"), "{text}");
    let _ = std::fs::remove_dir_all(&dir);
}

// ---- 2. Navigation ------------------------------------------------------------------

#[test]
fn event_keys_visit_every_marked_event_in_order() {
    let mut a = app("paper-b4.4");
    let sol = a.lab.solution.clone();
    // The burst of impacts within 1/50 of the span before T∞ is one stop, T∞.
    let t_inf = sol
        .visible_events()
        .find(|e| e.kind.label() == Some("T∞"))
        .map_or(f64::INFINITY, |e| e.t);
    let burst = |t: f64| t < t_inf && t_inf - t < (sol.t_end - sol.t_start) / 50.0;
    let marked: Vec<f64> = sol
        .visible_events()
        .filter(|e| e.kind.label().is_some() && !burst(e.t))
        .map(|e| e.t)
        // Events within a nanosecond (the burst before T∞) are one stop.
        .fold(Vec::new(), |mut v, t| {
            if v.last().is_none_or(|&l| t > l + 1e-9) {
                v.push(t);
            }
            v
        });
    assert!(marked.len() >= 6, "{marked:?}");
    let mut seen = Vec::new();
    for _ in 0..marked.len() {
        press(&mut a, ">");
        seen.push(a.t);
    }
    assert_eq!(seen, marked);
    press(&mut a, ">");
    assert_eq!(a.t, *marked.last().unwrap(), "no later event: stays");
    assert!(matches!(&a.status, Status::Info(s) if s.contains("no later event")));
    press(&mut a, "<");
    let last = *marked.last().unwrap();
    let before = a
        .lab
        .solution
        .visible_events()
        .filter(|e| e.kind.label().is_some() && e.t < last - 1e-9 && !burst(e.t))
        .map(|e| e.t)
        .fold(f64::NEG_INFINITY, f64::max);
    assert_eq!(a.t, before);
    press(&mut a, "home >");
    assert_eq!(a.t, 0.0, "the first event is the impact at 0");
    assert!(matches!(&a.status, Status::Info(s) if s.starts_with("impact at t = 0.0000 s")));
    press(&mut a, "end >");
    assert!(matches!(&a.status, Status::Info(s) if s.contains("no later event")));
}

#[test]
fn event_keys_step_over_an_accumulating_burst_as_one() {
    // μ_k = 0.05 on paper-b4.9: 20 impacts accumulate at T∞ = 2.939 s, the last ones
    // microseconds apart. `>` goes from the last impact a chart shows apart to T∞ in
    // one step, and says how many impacts it stepped over; `<` comes back the same way.
    let mut a = app("paper-b4.9");
    a.lab.set(Key::Mu, 0.05).unwrap();
    let sol = a.lab.solution.clone();
    let impacts = sol
        .visible_events()
        .filter(|e| e.kind.label() == Some("impact"))
        .count();
    assert_eq!(impacts, 20);
    let t_inf = sol
        .visible_events()
        .find(|e| e.kind.label() == Some("T∞"))
        .expect("T∞ is an event")
        .t;
    assert!((t_inf - 2.939).abs() < 1e-3, "{t_inf}");
    press(&mut a, "home");
    let mut stops = Vec::new();
    while a.t < t_inf && stops.len() < 100 {
        press(&mut a, ">");
        stops.push(a.t);
    }
    assert_eq!(*stops.last().unwrap(), t_inf);
    let before = stops[stops.len() - 2];
    // The stop before T∞ is a visible step away (1/50 of the span or more), and the
    // impacts past it are stepped over: fewer stops than impacts with their slips.
    let span = sol.t_end - sol.t_start;
    assert!(t_inf - before >= span / 50.0, "{before} {t_inf}");
    let skipped = sol
        .visible_events()
        .filter(|e| e.kind.label() == Some("impact") && e.t > before)
        .count();
    assert!(skipped >= 10, "{skipped}");
    assert!(
        matches!(&a.status, Status::Info(s) if s.starts_with("T∞ at t = 2.939") && s.contains(&format!("{skipped} impacts"))),
        "{:?}",
        a.status
    );
    press(&mut a, "<");
    assert_eq!(a.t, before);
    press(&mut a, "end < <");
    assert_eq!(
        a.t, before,
        "from past T∞: T∞, then the stop before the burst"
    );
}

#[test]
fn a_pinned_run_is_compared_side_by_side_and_keeps_its_own_glyph() {
    // Pin paper-b4.9 (μ_k 0.17), then μ_k 0.22: the Why panel gives both runs' key
    // numbers in two columns, each from its own run.
    let mut a = app("paper-b4.9");
    press(&mut a, "P");
    a.lab.set(Key::Mu, 0.22).unwrap();
    a.t = 0.4;
    let pinned = a.lab.pinned.as_ref().unwrap().solution.clone();
    let now = a.lab.solution.clone();
    assert_ne!(pinned.accumulation, now.accumulation);
    for size in [(80, 24), (120, 40), (200, 60)] {
        for ascii in [false, true] {
            let s = text(&a, size, ascii);
            let row = |name: &str| {
                s.lines()
                    .find_map(|l| {
                        l.split_once(&format!("||{name} "))
                            .or(l.split_once(&format!("││{name} ")))
                    })
                    .map(|(_, rest)| rest.split_whitespace().collect::<Vec<_>>().join(" "))
                    .unwrap_or_else(|| panic!("{size:?} {ascii}: no {name} row\n{s}"))
            };
            assert!(row("A/B").starts_with("pinned now"), "{size:?}\n{s}");
            assert!(row("outcome").starts_with("recollide recollide"), "{s}");
            let t_inf = if ascii { "Tinf" } else { "T∞" };
            let want = format!(
                "{:.4} s {:.4} s",
                pinned.accumulation.unwrap(),
                now.accumulation.unwrap()
            );
            assert!(
                row(t_inf).starts_with(&want),
                "{size:?}: {} vs {want}",
                row(t_inf)
            );
            // The chart keeps its event labels.
            assert!(
                s.contains("|impact") || s.contains("│impact"),
                "{size:?} {ascii}\n{s}"
            );
            // Without colour the pinned run has its own glyph, shown in the legend.
            let dot = if ascii {
                ".. pinned run"
            } else {
                "· pinned run"
            };
            assert!(s.contains(dot), "{size:?} {ascii}\n{s}");
        }
    }
    // The dots are drawn where the pinned run is, under the current run's curves.
    let s = text(&a, (120, 40), false);
    let chart: String = s.lines().skip(16).take(20).collect();
    assert!(chart.matches('·').count() > 20, "{s}");
}

#[test]
fn dot_and_comma_step_by_measured_frames_when_data_are_shown() {
    let mut a = app("paper-b4.9");
    let m = a.lab.measured().unwrap().t().to_vec();
    assert_eq!(a.t, a.lab.solution.t_start);
    assert!(a.t < m[0]);
    press(&mut a, ". .");
    assert_eq!(a.t, m[1]);
    press(&mut a, ",");
    assert_eq!(a.t, m[0]);
    // Between frames the next one is the next measured time.
    a.t = 0.013;
    press(&mut a, ".");
    assert_eq!(a.t, 0.02);
    press(&mut a, ",");
    assert_eq!(a.t, 0.0);
    // Past the last frame: one animation frame.
    a.t = *m.last().unwrap();
    press(&mut a, ".");
    assert!((a.t - (m.last().unwrap() + a.frame_step())).abs() < 1e-12);
}

#[test]
fn a_click_on_the_chart_seeks_to_the_time_under_it() {
    let mut a = app("paper-b4.9");
    let area = Rect::new(0, 0, 120, 40);
    let theme = Theme::new(Glyphs::UNICODE, true);
    for at in [-0.15, 0.0, 0.3, 0.85] {
        a.t = at;
        let s = screen::to_text(&a, 120, 40, &theme);
        let rows = chart_rows(&s, 40);
        let (row, col) = rows
            .iter()
            .enumerate()
            .find_map(|(r, l)| l.chars().position(|c| c == '┊').map(|c| (r, c)))
            .expect("the cursor is drawn");
        let top = view::layout(area).unwrap().chart.y;
        let t = screen::chart_time_at(&a, area, col as u16, top + row as u16).unwrap();
        // One column of the plot is (t_end − t_start) / (columns − 1) ≈ 13 ms here.
        let column = (a.lab.solution.t_end - a.lab.solution.t_start) / 70.0;
        assert!((t - at).abs() <= 0.5 * column, "{at}: {t}");
        let mut b = a.clone();
        b.playing = true;
        b.seek(t);
        assert_eq!(b.t, t);
        assert!(!b.playing);
    }
    // Outside the plot (the info panel, the axis labels, the params): no seek.
    assert_eq!(screen::chart_time_at(&a, area, 110, 20), None);
    assert_eq!(screen::chart_time_at(&a, area, 1, 20), None);
    assert_eq!(screen::chart_time_at(&a, area, 30, 3), None);
    // The Fit view's chart seeks too (the guide: "click or drag on the chart").
    let inside = screen::chart_time_at(&a, area, 40, 20);
    press(&mut a, "f");
    assert!(inside.is_some());
    assert_eq!(screen::chart_time_at(&a, area, 40, 20), inside);
    // Not while a view without the chart is shown.
    press(&mut a, "g");
    assert_eq!(screen::chart_time_at(&a, area, 40, 20), None);
}

#[test]
fn a_drag_on_the_chart_does_not_build_the_chart_again() {
    let mut a = app("paper-b4.9");
    press(&mut a, "x");
    let area = Rect::new(0, 0, 120, 40);
    let theme = Theme::new(Glyphs::UNICODE, true);
    let top = view::layout(area).unwrap().chart.y;
    // Never drawn: the chart is laid out to answer.
    let fresh: Vec<Option<f64>> = (0..120)
        .map(|c| screen::chart_time_at(&a, area, c, top + 10))
        .collect();
    // Drawn: a drag hit-tests the frame on screen (`Screen::chart_time_at` reads it
    // and cannot build a chart), and finds the same times while it moves the cursor.
    let mut screen = Screen::default();
    screen.text(&a, 120, 40, &theme);
    for (c, want) in fresh.iter().enumerate() {
        let t = screen.chart_time_at(&a, c as u16, top + 10);
        assert_eq!(t, *want, "column {c}");
        if let Some(t) = t {
            a.seek(t);
        }
    }
    // A key may change the chart: the next frame lays it out again (the energy chart
    // has a legend row of its own).
    press(&mut a, "e");
    screen.prepare(&a, area, &theme);
    let energy: Vec<Option<f64>> = (0..120)
        .map(|c| screen::chart_time_at(&a, area, c, top + 10))
        .collect();
    for (c, want) in energy.iter().enumerate() {
        assert_eq!(screen.chart_time_at(&a, c as u16, top + 10), *want);
    }
}
