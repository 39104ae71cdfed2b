//! The charts: v_cm(t) and v_t(t) like the paper's figures (left ball, right ball or
//! both), or x(t) of both balls; labelled event lines, the time cursor, and the
//! measured points when the preset carries them.

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::style::Style;
use ratatui::widgets::Widget;

use super::block;
use crate::lab::jobs::State;
use crate::physics::model::BallState;
use crate::physics::solution::{EventKind, Snapshot, Who};
use crate::tui::app::{App, ChartBall};
use crate::tui::plot::{Draw, Plot, Series, VLine, nice_ticks};
use crate::tui::theme::Theme;

fn event_lines(app: &App, balls: &[Who], theme: &Theme) -> Vec<VLine> {
    app.lab
        .solution
        .visible_events()
        .filter(|e| e.ball == Who::Both || balls.contains(&e.ball))
        .filter_map(|e| {
            let label = e.kind.label()?;
            let zeno = matches!(e.kind, EventKind::ZenoRest | EventKind::ZenoContact);
            let label = if zeno && !theme.glyphs.ascii {
                "T∞"
            } else {
                label
            };
            Some(VLine {
                x: e.t,
                label: Some(label.to_string()),
                style: theme.event,
                // The accumulation point outranks the burst of impacts before it.
                priority: u8::from(zeno),
            })
        })
        .collect()
}

pub fn render(app: &App, area: Rect, buf: &mut Buffer, theme: &Theme) {
    let (title, plot) = if app.show_positions {
        positions(app, area, theme)
    } else {
        velocities(app, area, theme)
    };
    let title = super::title_within(&title, area, theme);
    let blk = block(title, theme);
    let inner = blk.inner(area);
    blk.render(area, buf);
    plot.render(inner, buf, theme);
}

fn series_of(
    name: &str,
    samples: &[Snapshot],
    value: impl Fn(&Snapshot) -> f64,
    style: Style,
    glyph: &'static str,
) -> Series {
    Series {
        name: name.to_string(),
        points: samples.iter().map(|s| (s.t, value(s))).collect(),
        style,
        glyph,
        draw: Draw::Line,
    }
}

fn bounds(series: &[Series], rows: usize) -> ((f64, f64), Vec<f64>) {
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for p in series.iter().flat_map(|s| &s.points) {
        if p.1.is_finite() {
            lo = lo.min(p.1);
            hi = hi.max(p.1);
        }
    }
    nice_ticks(lo, hi, (rows / 3).max(2))
}

fn velocities(app: &App, area: Rect, theme: &Theme) -> (String, Plot) {
    let sol = &app.lab.solution;
    let columns = usize::from(area.width.saturating_sub(10));
    let samples = app.lab.samples(columns);
    let ball =
        |i: usize| move |s: &Snapshot| -> BallState { if i == 0 { s.left } else { s.right } };
    let (balls, which): (Vec<usize>, &str) = match app.chart_ball {
        ChartBall::Left => (vec![0], "left ball"),
        ChartBall::Right => (vec![1], "right ball"),
        ChartBall::Both => (vec![0, 1], "both balls"),
    };
    let mut series = Vec::new();
    for &i in &balls {
        let (style, side) = if i == 0 {
            (theme.left, "L")
        } else {
            (theme.right, "R")
        };
        let tag = |q: &str| {
            if balls.len() > 1 {
                format!("{q} {side}")
            } else {
                q.to_string()
            }
        };
        let b = ball(i);
        series.push(series_of(&tag("v_cm"), &samples, |s| b(s).v, style, "*"));
        let accent = if i == 0 {
            theme.accent
        } else {
            theme.right.patch(theme.dim)
        };
        series.push(series_of(&tag("v_t"), &samples, |s| b(s).u, accent, "+"));
    }
    if let State::Computing { done, total } = app.lab.overlay() {
        let name = app.lab.overlay_choice().map_or("", |(m, _)| m.name());
        series.push(Series {
            name: format!("{name} {}", super::progress_text(done, total)),
            points: Vec::new(),
            style: theme.overlay,
            glyph: "%",
            draw: Draw::Line,
        });
    }
    // The overlay's own colours and glyphs (never the data's red or marks); without
    // colour it is drawn as markers so that its glyphs tell it from the exact curves.
    let overlay_draw = if theme.monochrome {
        Draw::Points
    } else {
        Draw::Line
    };
    let (overlay_v, overlay_u) = if theme.glyphs.ascii {
        ("%", "~")
    } else {
        ("∘", "▵")
    };
    if let State::Ready(o) = app.lab.overlay() {
        // The time-stepping run over the exact curves, so its chatter shows.
        let setting = match (o.row.step, o.row.tolerance) {
            (Some(h), _) => format!("h {h:.0e}"),
            (_, Some(t)) => format!("tol {t:.0e}"),
            _ => String::new(),
        };
        for &i in &balls {
            let pts = |j: usize| {
                o.points
                    .iter()
                    .map(|(t, y)| (*t, y[3 * i + j]))
                    .collect::<Vec<_>>()
            };
            let thin = |p: Vec<(f64, f64)>| match overlay_draw {
                Draw::Points => thin_to(p, columns / 2),
                Draw::Line => p,
            };
            let side = match (balls.len(), i) {
                (1, _) => "",
                (_, 0) => " L",
                _ => " R",
            };
            series.push(Series {
                name: format!(
                    "{} {setting} ({}) v_cm{side}",
                    o.method.name(),
                    o.row.status.name()
                ),
                points: thin(pts(1)),
                style: theme.overlay,
                glyph: overlay_v,
                draw: overlay_draw,
            });
            series.push(Series {
                name: format!("v_t{side}"),
                points: thin(pts(2)),
                style: theme.overlay_t,
                glyph: overlay_u,
                draw: overlay_draw,
            });
        }
    }
    if let Some(m) = app.lab.measured().filter(|_| balls.contains(&0)) {
        let pts = |v: &[f64]| {
            m.t.iter()
                .copied()
                .zip(v.iter().copied())
                .collect::<Vec<_>>()
        };
        let cross = if theme.glyphs.ascii { "x" } else { "×" };
        series.push(Series {
            name: "measured v_cm".into(),
            points: pts(&m.v_cm),
            style: theme.measured,
            glyph: cross,
            draw: Draw::Points,
        });
        series.push(Series {
            name: "measured v_t".into(),
            points: pts(&m.v_t),
            style: theme.measured,
            glyph: if theme.glyphs.ascii { "o" } else { "+" },
            draw: Draw::Points,
        });
    }
    let mut vlines = Vec::new();
    if let (true, State::Ready(Ok(f)), Some(m)) =
        (app.fit_view(), app.lab.fits(), app.lab.measured())
    {
        // The paper's straight lines over the chosen window.
        let l = &f.line_fit;
        let idx: Vec<usize> = (0..m.t.len())
            .filter(|&i| m.t[i] >= l.from && m.t[i] <= l.to)
            .collect();
        let ts: Vec<f64> = idx.iter().map(|&i| m.t[i]).collect();
        for (series_data, name) in [(&m.v_cm, "fit lines"), (&m.v_t, "")] {
            let ys: Vec<f64> = idx.iter().map(|&i| series_data[i]).collect();
            let line = crate::study::fit::line(&ts, &ys);
            series.push(Series {
                name: name.to_string(),
                points: [l.from, l.to]
                    .iter()
                    .map(|&t| (t, line.intercept + line.slope * t))
                    .collect(),
                style: theme.cursor,
                glyph: "-",
                draw: Draw::Line,
            });
        }
        for (t, label) in [(l.from, "from"), (l.to, "to")] {
            vlines.push(VLine {
                x: t,
                label: Some(label.to_string()),
                style: theme.cursor,
                priority: 2,
            });
        }
    }
    let rows = usize::from(area.height.saturating_sub(4));
    let ((y0, y1), _) = bounds(&series, rows);
    let whos: Vec<Who> = balls.iter().map(|&i| Who::ball(i)).collect();
    vlines.extend(event_lines(app, &whos, theme));
    let plot = Plot {
        x_range: (sol.t_start, sol.t_end),
        y_range: (y0, y1),
        x_title: "t (s)".into(),
        y_title: "v (m/s)".into(),
        series,
        vlines,
        cursor: Some(app.t),
        x_ticks: None,
        y_ticks: None,
    };
    (format!(" v_cm(t) and v_t(t), {which}  [b] switches "), plot)
}

/// At most about `n` of `points`, evenly picked (markers one per two columns).
fn thin_to(points: Vec<(f64, f64)>, n: usize) -> Vec<(f64, f64)> {
    let every = points.len().div_ceil(n.max(1)).max(1);
    points.into_iter().step_by(every).collect()
}

fn positions(app: &App, area: Rect, theme: &Theme) -> (String, Plot) {
    let sol = &app.lab.solution;
    let columns = usize::from(area.width.saturating_sub(10));
    let samples = app.lab.samples(columns);
    let series = vec![
        series_of("x left", &samples, |s| s.left.x * 100.0, theme.left, "*"),
        series_of("x right", &samples, |s| s.right.x * 100.0, theme.right, "+"),
    ];
    let rows = usize::from(area.height.saturating_sub(4));
    let ((y0, y1), _) = bounds(&series, rows);
    let plot = Plot {
        x_range: (sol.t_start, sol.t_end),
        y_range: (y0, y1),
        x_title: "t (s)".into(),
        y_title: "x (cm)".into(),
        series,
        vlines: event_lines(app, &[Who::Left, Who::Right], theme),
        cursor: Some(app.t),
        x_ticks: None,
        y_ticks: None,
    };
    (
        " x(t) of both balls  [x] back to velocities ".to_string(),
        plot,
    )
}
