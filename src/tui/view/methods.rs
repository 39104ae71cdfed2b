//! The Methods view: each time-stepping method's error against its work, on log axes
//! drawn by transforming the data and labelling the ticks, with the rows beside it.

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::text::{Line, Span};
use ratatui::widgets::Widget;

use super::{Ranked, block, by_priority, draw_lines};
use crate::lab::jobs::State;
use crate::methods::Method;
use crate::study::compare::Status;
use crate::tui::app::App;
use crate::tui::plot::{Draw, Plot, Series};
use crate::tui::theme::Theme;

fn glyph(m: Method) -> &'static str {
    match m {
        Method::Exact => "#",
        Method::Euler => "e",
        Method::SymplecticEuler => "s",
        Method::Rk4 => "4",
        Method::Rk45 => "5",
        Method::Moreau => "m",
    }
}

/// Decade ticks `10^a … 10^b` labelled `1e<n>`.
fn decades(lo: f64, hi: f64) -> Vec<(f64, String)> {
    (lo.floor() as i32..=hi.ceil() as i32)
        .map(|e| (f64::from(e), format!("1e{e}")))
        .collect()
}

pub fn render_diagram(app: &App, area: Rect, buf: &mut Buffer, theme: &Theme) {
    let title = super::title_within(
        " Methods: max |v_cm - exact| against steps per run  [c] back ",
        area,
        theme,
    );
    let blk = block(title, theme);
    let inner = blk.inner(area);
    blk.render(area, buf);
    let rows = match app.lab.method_rows() {
        State::Ready(rows) => rows,
        other => return super::computing(&other, "running every method", inner, buf, theme),
    };
    let point = |r: &crate::study::compare::Row| {
        ((r.steps.max(1) as f64).log10(), r.err_v.max(1e-16).log10())
    };
    let mut series = Vec::new();
    for m in Method::TIME_STEPPING {
        let style = match m {
            Method::Euler => theme.left,
            Method::SymplecticEuler => theme.right,
            Method::Rk4 => theme.accent,
            Method::Rk45 => theme.cursor,
            _ => theme.measured,
        };
        let pts: Vec<(f64, f64)> = rows.iter().filter(|r| r.method == m).map(point).collect();
        series.push(Series {
            name: m.name().to_string(),
            points: pts.clone(),
            style,
            glyph: ".",
            draw: Draw::Line,
        });
        series.push(Series {
            name: String::new(),
            points: pts,
            style,
            glyph: glyph(m),
            draw: Draw::Points,
        });
    }
    let all: Vec<(f64, f64)> = rows.iter().map(point).collect();
    let (x0, x1) = all.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |a, p| {
        (a.0.min(p.0), a.1.max(p.0))
    });
    let (y0, y1) = all.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |a, p| {
        (a.0.min(p.1), a.1.max(p.1))
    });
    let (x0, x1) = (x0.floor(), x1.ceil().max(x0.floor() + 1.0));
    let (y0, y1) = (y0.floor(), y1.ceil().max(y0.floor() + 1.0));
    let plot = Plot {
        x_range: (x0, x1),
        y_range: (y0, y1),
        x_title: "steps".into(),
        y_title: "m/s".into(),
        series,
        vlines: Vec::new(),
        cursor: None,
        x_ticks: Some(decades(x0, x1)),
        y_ticks: Some(decades(y0, y1)),
    };
    plot.render(inner, buf, theme);
}

pub fn render_rows(app: &App, area: Rect, buf: &mut Buffer, theme: &Theme) {
    let title = if area.width < 44 {
        " Runs: setting, status, err_v "
    } else {
        " Runs (marker, setting, status, err_v) "
    };
    let blk = block(title, theme);
    let inner = blk.inner(area);
    blk.render(area, buf);
    let rows = match app.lab.method_rows() {
        State::Ready(rows) => rows,
        other => return super::computing(&other, "running every method", inner, buf, theme),
    };
    let g = theme.glyphs;
    // Columns: marker, name (as wide as room allows, cut with an ellipsis), setting,
    // status, and err_v, which is never cut.
    let width = usize::from(inner.width);
    let fixed = 2 + 8 + 1 + 8 + 1 + 7;
    let name_width = width.saturating_sub(fixed + 1).min(17);
    // Each method's best run (smallest error) stays on a short screen, one per method;
    // the other levels go, coarsest first.
    let best: Vec<usize> = Method::TIME_STEPPING
        .iter()
        .filter_map(|&m| {
            (0..rows.len())
                .filter(|&i| rows[i].method == m)
                .min_by(|&a, &b| rows[a].err_v.total_cmp(&rows[b].err_v))
        })
        .collect();
    let mut lines: Ranked = vec![(
        9,
        Line::from(Span::styled(
            format!(
                "exact: {} segments, error 0",
                app.lab.solution.segments.len()
            ),
            theme.title,
        )),
    )];
    // How many runs of each method came before (the level's rank, coarse first).
    let mut seen: Vec<Method> = Vec::new();
    for (i, r) in rows.iter().enumerate() {
        let setting = match (r.step, r.tolerance) {
            (Some(h), _) => format!("h {h:.0e}"),
            (_, Some(t)) => format!("tol {t:.0e}"),
            _ => String::new(),
        };
        let style = if r.status == Status::Ok {
            theme.text
        } else {
            theme.error
        };
        seen.push(r.method);
        let rank = seen.iter().filter(|&&m| m == r.method).count() as u8;
        let priority = if best.contains(&i) { 8 } else { rank };
        let name = g.ellipsize(r.method.name(), name_width);
        lines.push((
            priority,
            Line::from(vec![
                Span::styled(
                    format!("{} {name:<name_width$} ", glyph(r.method)),
                    theme.dim,
                ),
                Span::styled(
                    format!("{setting:<8} {:<8} {:>7}", r.status.name(), error(r.err_v)),
                    style,
                ),
            ]),
        ));
    }
    draw_lines(by_priority(lines, inner), inner, buf);
}

/// An error with two significant digits whatever its exponent (`2.9e-10`, never cut).
fn error(v: f64) -> String {
    if v.is_finite() {
        format!("{v:.1e}")
    } else {
        "diverged".to_string()
    }
}
