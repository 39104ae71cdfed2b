//! The lab shows the whole motion (issue 11): the span follows the physics, events and
//! measured frames can be stepped through, the chart seeks on a click, the energy
//! chart, and the A/B comparison with a pinned run. App logic and `render` snapshots.

use groovelab::cli::DataArgs;
use groovelab::lab::{Lab, SpanEnd};
use groovelab::physics::solution::EventKind;
use groovelab::settings::params::Key;
use groovelab::settings::spec::SceneSpec;
use groovelab::study::preset::{Origin, Preset};
use groovelab::tui::app::{App, Library, Status};
use groovelab::tui::screen;
use groovelab::tui::screen::Screen;
use groovelab::tui::theme::{Glyphs, Theme};
use groovelab::tui::view;
use groovelab::tui::view_cache::ViewCache;
use ratatui::layout::Rect;

use crate::common::{self, press, scene_of, select, text};

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
    let last = *a.lab.measured().unwrap().t.last().unwrap();
    assert!(a.lab.solution.t_end >= last);
    assert_eq!(a.lab.span_end, SpanEnd::Auto);
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
    Preset::parse(text, "short", Origin::BuiltIn).unwrap()
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

#[test]
fn saving_keeps_only_a_set_span_end() {
    let dir = std::env::temp_dir().join(format!("groovelab-motion-save-{}", std::process::id()));
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
    let m = a.lab.measured().unwrap().t.clone();
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
    // Not while another view is shown.
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
    let m = Measured {
        t,
        v_cm,
        v_t,
        ..Measured::default()
    };
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
