//! The plot widget's tests: ticks, thinning, extreme ranges, clicks.

use super::*;

#[test]
fn crowded_ticks_are_thinned_evenly_from_zero() {
    let decades: Vec<(f64, String)> = (-10..=1)
        .map(|e| (f64::from(e), format!("1e{e}")))
        .collect();
    let labels =
        |kept: Vec<(f64, String)>| -> Vec<String> { kept.into_iter().map(|(_, l)| l).collect() };
    // Room for six: every other decade, 1e0 among them.
    let kept = labels(evenly(decades.clone(), |k| k.len() <= 6));
    assert_eq!(kept, ["1e-10", "1e-8", "1e-6", "1e-4", "1e-2", "1e0"]);
    // Room for all: all.
    assert_eq!(evenly(decades.clone(), |_| true).len(), 12);
    // Room for one: the one at 0.
    assert_eq!(labels(evenly(decades, |k| k.len() <= 1)), ["1e0"]);
}

/// Draws `plot` into buffers of several sizes: it must not panic.
fn draw_everywhere(plot: &Plot) {
    let theme = Theme::new(crate::tui::theme::Glyphs::new(true), true);
    for (w, h) in [(80, 24), (120, 40), (12, 4), (13, 5), (20, 6), (300, 8)] {
        let area = Rect::new(0, 0, w, h);
        let mut buf = Buffer::empty(area);
        plot.render(area, &mut buf, &theme);
    }
}

#[test]
fn thinned_markers_mark_the_same_cells_as_all_of_them() {
    // A dense noisy series (a spike, values outside the range, NaN), as markers
    // over a line: thinned to one point per cell, the screen is the same.
    let points: Vec<(f64, f64)> = (0..200_000)
        .map(|i| {
            let t = i as f64 / 200_000.0;
            let noise = ((i * 7919) % 101) as f64 / 101.0 - 0.5;
            let v = match i {
                77_777 => 5.0,
                99_999 => f64::NAN,
                150_000 => 9.0,
                _ => (6.0 * t).sin() + 0.3 * noise,
            };
            (t, v)
        })
        .collect();
    let marks = |points: Vec<(f64, f64)>| PlotLine {
        name: "measured".into(),
        points: points.into(),
        style: Style::default(),
        glyph: "x",
        draw: Draw::Points,
    };
    let mut plot = Plot {
        x_range: (0.0, 1.0),
        y_range: (-2.0, 6.0),
        x_title: "t (s)".into(),
        y_title: "v (m/s)".into(),
        series: vec![
            PlotLine {
                draw: Draw::Line,
                glyph: "*",
                ..marks(vec![(0.0, -1.0), (1.0, 1.0)])
            },
            marks(points.clone()),
        ],
        vlines: Vec::new(),
        cursor: None,
        x_ticks: None,
        y_ticks: None,
    };
    for ascii in [true, false] {
        let theme = Theme::new(crate::tui::theme::Glyphs::new(ascii), true);
        for (w, h) in [(80, 24), (120, 40), (13, 5)] {
            let area = Rect::new(0, 0, w, h);
            let cells = plot.cells(area, &theme).unwrap();
            let (mut all, mut thin) = (Buffer::empty(area), Buffer::empty(area));
            plot.series[1].points = points.clone().into();
            plot.render(area, &mut all, &theme);
            let thinned = cells.thin(&points);
            assert!(thinned.len() <= cells.cols() * cells.rows());
            plot.series[1].points = thinned.into();
            plot.render(area, &mut thin, &theme);
            assert_eq!(all, thin, "{w}x{h}, ascii {ascii}");
        }
    }
}

#[test]
fn a_plot_of_extreme_ranges_does_not_panic() {
    let ranges = [
        (-0.2, 1e38),
        (-1e308, 1e308),
        (-f64::MAX, f64::MAX),
        (0.0, 1e300),
        (1e-300, 2e-300),
        (1.0, 1.0),
        (f64::NAN, f64::INFINITY),
    ];
    for x_range in ranges {
        for y_range in ranges {
            let series = PlotLine {
                name: "v_cm".into(),
                points: vec![x_range, y_range, (x_range.0, y_range.1), (f64::NAN, 0.0)].into(),
                style: Style::default(),
                glyph: "*",
                draw: Draw::Line,
            };
            let plot = Plot {
                x_range,
                y_range,
                x_title: "t (s)".into(),
                y_title: "v (m/s)".into(),
                series: vec![
                    series.clone(),
                    PlotLine {
                        draw: Draw::Points,
                        ..series
                    },
                ],
                vlines: vec![
                    VLine {
                        x: x_range.0,
                        label: Some("a very long event label indeed".into()),
                        style: Style::default(),
                        priority: 0,
                    },
                    VLine {
                        x: x_range.1,
                        label: Some("T∞".into()),
                        style: Style::default(),
                        priority: 1,
                    },
                ],
                cursor: Some(x_range.1),
                x_ticks: None,
                y_ticks: None,
            };
            draw_everywhere(&plot);
            // Given ticks wider than the plot, too.
            let wide = Plot {
                x_ticks: Some(vec![(x_range.0, "x".repeat(500))]),
                y_ticks: Some(vec![(y_range.0, "y".repeat(500))]),
                ..plot
            };
            draw_everywhere(&wide);
        }
    }
}

#[test]
fn a_column_maps_back_to_the_value_drawn_there() {
    // 101 columns from x = 40 over -0.2 … 0.8 s: one column is 10 ms.
    let t = |c| time_at_column((-0.2, 0.8), 40, 101, c);
    assert_eq!(t(39), None, "left of the plot");
    assert_eq!(t(141), None, "right of the plot");
    assert!((t(40).unwrap() + 0.2).abs() < 1e-12);
    assert!((t(140).unwrap() - 0.8).abs() < 1e-12);
    assert!((t(60).unwrap() - 0.0).abs() < 1e-12);
    // And it inverts the column the plot draws a value in.
    let col_of = |x: f64| ((x + 0.2) / 1.0 * 100.0).round() as u16 + 40;
    for x in [-0.2, -0.05, 0.31, 0.79] {
        let back = t(col_of(x)).unwrap();
        assert!((back - x).abs() <= 0.5 / 100.0 + 1e-12, "{x} -> {back}");
    }
    assert_eq!(
        time_at_column((0.0, 1.0), 0, 1, 0),
        None,
        "one column: no range"
    );
}

#[test]
fn legend_rows_push_the_data_area_down_and_clicks_follow() {
    let line = |name: &str| PlotLine {
        name: name.into(),
        points: vec![(0.0, 0.0), (1.0, 1.0)].into(),
        style: Style::default(),
        glyph: "*",
        draw: Draw::Line,
    };
    let plot = |n: usize| Plot {
        x_range: (0.0, 1.0),
        y_range: (0.0, 1.0),
        x_title: "t (s)".into(),
        y_title: "v (m/s)".into(),
        series: (0..n).map(|i| line(&format!("curve number {i}"))).collect(),
        vlines: Vec::new(),
        cursor: None,
        x_ticks: None,
        y_ticks: None,
    };
    for ascii in [false, true] {
        let theme = Theme::new(crate::tui::theme::Glyphs::new(ascii), true);
        let area = Rect::new(3, 2, 60, 20);
        let one = plot(1).data_area(area, &theme).unwrap();
        let many = plot(6).data_area(area, &theme).unwrap();
        // Six entries of 18 columns need three rows of 60: two more than one entry.
        assert_eq!(many.y, one.y + 2, "ascii {ascii}");
        assert_eq!(many.bottom(), one.bottom());
        // The drawn plot starts where data_area says: the axis begins on its first
        // row, and the row above it holds legend text, not the axis.
        let mut buf = Buffer::empty(Rect::new(0, 0, 70, 25));
        plot(6).render(area, &mut buf, &theme);
        let axis = buf[(many.x - 1, many.y)].symbol().to_string();
        assert!(
            axis == theme.glyphs.vline || axis == "┤" || axis == "+",
            "{axis}"
        );
        let above = buf[(many.x - 1, many.y - 1)].symbol().to_string();
        assert_ne!(above, theme.glyphs.vline, "ascii {ascii}");
        let legend_row: String = (area.x..area.right())
            .map(|x| buf[(x, many.y - 1)].symbol().to_string())
            .collect();
        assert!(legend_row.contains("curve number"), "{legend_row}");
        // A click on a legend row is not a seek; one on the first data row is.
        assert_eq!(plot(6).x_at(area, &theme, many.x + 5, many.y - 1), None);
        assert!(plot(6).x_at(area, &theme, many.x + 5, many.y).is_some());
    }
}
