//! The Methods view: each time-stepping method's error against its work, on log axes
//! drawn by transforming the data and labelling the ticks, with the rows beside it.

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::text::{Line, Span};
use ratatui::widgets::Widget;

use super::panel::{Ranked, block, by_priority, draw_lines};
use super::withheld::Withheld;
use crate::lab::jobs::State;
use crate::methods::Method;
use crate::settings::units::{Dimension, fit_number, show};
use crate::study::compare::{Row, RunStatus, fitted_order, outcome_until};
use crate::tui::app::App;
use crate::tui::component::{Component, Ctx, MainView, Place};
use crate::tui::plot::{Draw, Plot, PlotLine};
use crate::tui::theme::Theme;
use crate::tui::vocabulary::{View, WorkAxis};

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
/// Decade ticks 1e{lo} … 1e{hi}, every k-th decade so that there are at most about
/// 20 (an overflowing run once asked for 2^31 of them).
fn decades(lo: f64, hi: f64) -> Vec<(f64, String)> {
    if !(lo.is_finite() && hi.is_finite()) {
        return Vec::new();
    }
    let (lo, hi) = (lo.floor().max(-400.0) as i32, hi.ceil().min(400.0) as i32);
    let every = ((hi - lo) / 20).max(1) as usize;
    (lo..=hi)
        .step_by(every)
        .map(|e| (f64::from(e), format!("1e{e}")))
        .collect()
}

/// A run's work on the chosen axis: steps, right-hand-side evaluations or seconds.
fn work(axis: WorkAxis, r: &Row) -> f64 {
    match axis {
        WorkAxis::Steps => r.steps as f64,
        WorkAxis::RhsEvals => r.rhs_evals as f64,
        WorkAxis::Time => r.time_median_s,
    }
}

/// Draws the panel's frame titled `title`; the rows of every method's runs and the
/// area inside the frame, or `None` with the progress of the runs drawn there.
fn framed_rows<'a>(
    app: &'a App,
    title: impl Into<Line<'a>>,
    area: Rect,
    buf: &mut Buffer,
    theme: &Theme,
) -> Option<(&'a [Row], Rect)> {
    let blk = block(title, theme);
    let inner = blk.inner(area);
    blk.render(area, buf);
    match app.methods().state() {
        State::Ready(rows) => Some((rows, inner)),
        other => {
            super::panel::computing(&other, "running every method", inner, buf, theme);
            None
        }
    }
}

pub fn render_diagram(app: &App, area: Rect, buf: &mut Buffer, theme: &Theme) {
    let axis = app.methods_state().axis();
    let (per_run, short, x_title) = match axis {
        WorkAxis::Steps => ("steps per run", "steps", "steps"),
        WorkAxis::RhsEvals => ("rhs evaluations per run", "rhs evals", "rhs evals"),
        WorkAxis::Time => ("time per run", "time", "s"),
    };
    let title = super::panel::title_of(
        &[
            format!("Methods: max |v_cm - exact| against {per_run}  [X] axis  [c] back"),
            format!("Methods: error against {per_run}  [X] [c]"),
            format!("Methods: error against {short}  [X]"),
            format!("Methods: error against {short}"),
        ],
        area,
        theme,
    );
    let Some((rows, inner)) = framed_rows(app, title, area, buf, theme) else {
        return;
    };
    // Work below one unit (a run refused before its first step, or a time under a
    // nanosecond) sits at the axis' floor rather than at −∞.
    let floor = if axis == WorkAxis::Time { 1e-9 } else { 1.0 };
    let point = |r: &Row| (work(axis, r).max(floor).log10(), r.err_v.max(1e-16).log10());
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
        series.push(PlotLine {
            name: m.name().to_string(),
            points: pts.clone().into(),
            style,
            glyph: ".",
            draw: Draw::Line,
        });
        series.push(PlotLine {
            name: String::new(),
            points: pts.into(),
            style,
            glyph: glyph(m),
            draw: Draw::Points,
        });
    }
    // The range from finite points only: a run that overflowed has err_v = inf.
    let all: Vec<(f64, f64)> = rows
        .iter()
        .map(point)
        .filter(|p| p.0.is_finite() && p.1.is_finite())
        .collect();
    let (x0, x1) = all.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |a, p| {
        (a.0.min(p.0), a.1.max(p.0))
    });
    let (y0, y1) = all.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |a, p| {
        (a.0.min(p.1), a.1.max(p.1))
    });
    let (x0, x1) = if x0 <= x1 { (x0, x1) } else { (0.0, 1.0) };
    let (y0, y1) = if y0 <= y1 { (y0, y1) } else { (-16.0, 0.0) };
    let (x0, x1) = (x0.floor(), x1.ceil().max(x0.floor() + 1.0));
    let (y0, y1) = (y0.floor(), y1.ceil().max(y0.floor() + 1.0));
    let plot = Plot {
        x_range: (x0, x1),
        y_range: (y0, y1),
        x_title: x_title.into(),
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
    // The outcome marks where the panel has room for them (44 columns and more).
    let title = if area.width < 44 {
        " Runs: setting, status, err_v "
    } else if area.width < 52 {
        " Runs: setting, status, outcome, err_v "
    } else {
        " Runs (marker, setting, status, outcome, err_v) "
    };
    let Some((rows, inner)) = framed_rows(app, title, area, buf, theme) else {
        return;
    };
    let width = usize::from(inner.width);
    let marks = width >= 42;
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
    lines.extend(run_lines(rows, width, marks, theme));
    lines.extend(legend_lines(app, rows, marks, theme));
    draw_lines(by_priority(lines, inner), inner, buf);
}

/// Each method's best run (smallest error), one per method.
fn best_runs(rows: &[Row]) -> Vec<usize> {
    Method::TIME_STEPPING
        .iter()
        .filter_map(|&m| {
            (0..rows.len())
                .filter(|&i| rows[i].method == m)
                .min_by(|&a, &b| rows[a].err_v.total_cmp(&rows[b].err_v))
        })
        .collect()
}

/// One line per run in `width` columns: marker and method, setting, status, the
/// outcome mark (with `marks`) and err_v. Each method's best run stays on a short
/// screen, one per method; the other levels go, coarsest first.
fn run_lines(rows: &[Row], width: usize, marks: bool, theme: &Theme) -> Ranked<'static> {
    let g = theme.glyphs;
    let best = best_runs(rows);
    // Setting and status take 19 columns (a longer status word takes from the error),
    // the outcome mark 2 more where the panel is wide enough; err_v gets at least 7
    // ("2.9e-10"), taken from the name column on a narrow panel, and is fitted into
    // what it gets (fewer digits, never a cut exponent).
    let fixed = if marks { 21 } else { 19 };
    let name_w = width.saturating_sub(fixed + 7).clamp(2, 19);
    // How many runs of each method came before (the level's rank, coarse first).
    let mut seen: Vec<Method> = Vec::new();
    let mut lines: Ranked = Vec::new();
    for (i, r) in rows.iter().enumerate() {
        let setting = r.setting();
        let style = if r.status == RunStatus::Ok {
            theme.text
        } else {
            theme.error
        };
        seen.push(r.method);
        let rank = seen.iter().filter(|&&m| m == r.method).count() as u8;
        let priority = if best.contains(&i) { 8 } else { rank };
        // A name too long for its column ends with an ellipsis, never cut silently.
        let name = g.ellipsize(
            &format!("{} {}", glyph(r.method), r.method.name()),
            name_w - 1,
        );
        let status = r.status.name();
        let mark = match (marks, r.outcome_right) {
            (false, _) => "",
            (true, true) => "= ",
            (true, false) => "x ",
        };
        let err_w = width
            .saturating_sub(name_w + fixed + status.len().saturating_sub(8))
            .max(1);
        lines.push((
            priority,
            Line::from(vec![
                Span::styled(format!("{name:<name_w$}"), theme.dim),
                Span::styled(
                    format!(
                        "{setting:<9} {status:<8} {mark}{}",
                        fit_number(r.err_v, err_w)
                    ),
                    style,
                ),
            ]),
        ));
    }
    lines
}

/// What the outcome marks compare with (up to the budget's cut, if it cut the span),
/// the cut itself, and each fixed-step method's fitted order.
fn legend_lines(app: &App, rows: &[Row], marks: bool, theme: &Theme) -> Ranked<'static> {
    let mut lines: Ranked = Vec::new();
    let cut = rows.iter().find_map(|r| r.cut);
    let (outcome, impacts) = match cut {
        Some(end) => outcome_until(&app.lab.solution, end),
        None => (app.lab.summary.outcome, app.lab.summary.impacts),
    };
    if marks {
        lines.push((
            7,
            Line::from(Span::styled(
                format!(
                    "= outcome right ({}, {impacts} {})",
                    outcome.name(),
                    if impacts == 1 { "impact" } else { "impacts" }
                ),
                theme.dim,
            )),
        ));
    }
    if let Some(end) = cut {
        lines.push((
            8,
            Line::from(Span::styled(
                format!(
                    "runs cut at t = {} by the step budget",
                    show(end, Dimension::Time)
                ),
                theme.error,
            )),
        ));
    }
    let orders: Vec<String> = Method::TIME_STEPPING
        .iter()
        .filter_map(|&m| fitted_order(rows, m).map(|p| format!("{} {p:.1}", glyph(m))))
        .collect();
    if !orders.is_empty() {
        lines.push((
            7,
            Line::from(Span::styled(
                format!("order: {}", orders.join("  ")),
                theme.dim,
            )),
        ));
    }
    lines
}

/// The Methods view's work–precision diagram as a component.
pub struct MethodsDiagram;

impl Component for MethodsDiagram {
    fn render(&self, area: Rect, buf: &mut Buffer, cx: &Ctx<'_>) {
        render_diagram(cx.app, area, buf, cx.theme);
    }
}

/// The Methods view's runs list as a component.
pub struct MethodsTable;

impl Component for MethodsTable {
    fn render(&self, area: Rect, buf: &mut Buffer, cx: &Ctx<'_>) {
        render_rows(cx.app, area, buf, cx.theme);
    }
}

/// The Methods view's panels while the outcome is hidden: its runs name it.
const METHODS_WITHHELD: [Withheld; 2] = [
    Withheld {
        title: "Methods",
        what: "error against work",
    },
    Withheld {
        title: "Runs",
        what: "each method's run and outcome",
    },
];

/// The Methods view: the work–precision diagram and the runs beside it.
pub struct MethodsView;

impl MainView for MethodsView {
    fn view(&self) -> View {
        View::Methods
    }

    fn parts(&self, app: &App) -> Vec<(&'static dyn Component, Place)> {
        if app.hidden().derived() {
            vec![
                (&METHODS_WITHHELD[0], Place::Chart),
                (&METHODS_WITHHELD[1], Place::Side),
            ]
        } else {
            vec![
                (&MethodsDiagram, Place::Chart),
                (&MethodsTable, Place::Side),
            ]
        }
    }
}

#[cfg(test)]
mod tests {
    #[test]
    fn decades_are_few_for_any_range() {
        assert_eq!(super::decades(f64::NAN, 3.0), vec![]);
        assert_eq!(super::decades(0.0, f64::INFINITY), vec![]);
        let d = super::decades(-16.0, 308.0);
        assert!(d.len() <= 21 && d[0].1 == "1e-16", "{d:?}");
        assert_eq!(super::decades(-2.0, 0.0).len(), 3);
    }
}
