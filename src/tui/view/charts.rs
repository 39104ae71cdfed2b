//! The charts: v_cm(t) and v_t(t) like the paper's figures (left ball, right ball or
//! both), or x(t) of both balls; labelled event lines, the time cursor, and the
//! measured points when the preset carries them.

use std::sync::Arc;

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::style::Style;
use ratatui::widgets::Widget;

use super::info;
use super::panel::block;
use super::withheld::Withheld;
use crate::lab::jobs::State;
use crate::lab::{MeasuredPoints, value_range};
use crate::physics::model::BallState;
use crate::physics::solution::{EnergySplit, EventKind, Snapshot, Who};
use crate::settings::units::Dimension;
use crate::tui::app::{App, ChartBall};
use crate::tui::chart::Chart;
use crate::tui::component::{Component, Ctx, MainView, Place, Prepared};
use crate::tui::plot::{Draw, Plot, PlotLine, VLine, nice_ticks};
use crate::tui::theme::Theme;
use crate::tui::view_cache::ViewCache;
use crate::tui::vocabulary::View;
use marks::{line_fit_marks, measured_velocities};

mod marks;

fn event_lines(app: &App, balls: &[Who], theme: &Theme) -> Vec<VLine> {
    app.lab
        .solution
        .visible_events()
        .filter(|e| e.ball == Who::Both || balls.contains(&e.ball))
        .filter_map(|e| {
            // ASCII spells T∞ "Tinf", as everywhere else.
            let label = theme.glyphs.text(e.kind.label()?);
            let zeno = matches!(e.kind, EventKind::ZenoRest | EventKind::ZenoContact);
            Some(VLine {
                x: e.t,
                label: Some(label),
                style: theme.event,
                // The accumulation point outranks the burst of impacts before it.
                priority: u8::from(zeno),
            })
        })
        .collect()
}

/// What a view's chart shows beside the runs and the data.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Extras {
    /// Nothing more (the Charts view).
    None,
    /// The line fits over the sliding phase, where a fit is ready (the Fit view).
    LineFits,
}

/// The chart shown in `area` (before drawing, with the screen's caches), and whether
/// measured series were thinned for it now.
pub fn build(
    app: &App,
    cache: &mut ViewCache,
    area: Rect,
    theme: &Theme,
    extras: Extras,
) -> (Chart, bool) {
    let (mut titles, mut plot) = if app.charts().energy() {
        energy(app, cache, area, theme)
    } else if app.charts().positions() {
        positions(app, cache, area, theme)
    } else {
        velocities(app, cache, area, theme, extras)
    };
    let factor = app.charts().zoom().factor(app.chart_span());
    if factor > 1.0 + 1e-9 {
        // Each wording keeps its room: the zoom is said first, briefly.
        let zoomed = format!(
            "zoom {}{}  ",
            theme.glyphs.text("×"),
            crate::tui::layer::main::zoom::text(factor)
        );
        for t in &mut titles {
            t.insert_str(0, &zoomed);
        }
    }
    // The title sits on the border: the inside is the same whatever it says.
    let inner = block("", theme).inner(area);
    let thinned = thin_measured(app, cache, &mut plot, inner, theme);
    // The curves and event labels past the cursor show the outcome: while it is to
    // be predicted (b hidden, a prediction pending) the chart grows as the run plays.
    // Its y range then comes from what is shown: the whole run's would tell (a
    // velocity that turns negative is a ball that comes back), and a velocity axis
    // is symmetric about zero, so that the sign of what is to come is not implied.
    if app.hidden().derived() {
        plot.until(app.t);
        let velocities = !(app.charts().energy() || app.charts().positions());
        if !app.charts().energy() {
            let rows = usize::from(area.height.saturating_sub(4));
            plot.y_range = shown_y_range(&plot.series, velocities, rows);
        }
    }
    let data = plot.data_area(inner, theme);
    (Chart { titles, plot, data }, thinned)
}

/// Draws `chart` (built for `area`), changing nothing.
fn render(chart: &Chart, area: Rect, buf: &mut Buffer, theme: &Theme) {
    let title = super::panel::title_of(&chart.titles, area, theme);
    let blk = block(title, theme);
    let inner = blk.inner(area);
    blk.render(area, buf);
    chart.plot.render(inner, buf, theme);
}

/// The snapshot's measured series in `plot` (a file may hold a million rows, drawn
/// as markers) in their thinned form, one point per cell they mark, made once per
/// snapshot and grid (the view cache): a frame draws what the cells show, not every
/// row, and the same cells are marked. True if they were thinned now.
fn thin_measured(
    app: &App,
    cache: &mut ViewCache,
    plot: &mut Plot,
    inner: Rect,
    theme: &Theme,
) -> bool {
    let (Some(m), Some(cells)) = (app.lab.points.as_ref(), plot.cells(inner, theme)) else {
        return false;
    };
    // Markers only: a line through thinned points would be another line.
    let index = |s: &PlotLine| {
        (s.draw != Draw::Line)
            .then(|| m.series().position(|p| Arc::ptr_eq(p, &s.points)))
            .flatten()
    };
    let drawn = plot
        .series
        .iter()
        .filter_map(index)
        .fold(0u8, |bits, i| bits | 1 << i);
    if drawn == 0 {
        return false;
    }
    let (marks, thinned) = cache.measured_marks(app.lab.resolved(), cells, drawn);
    for s in &mut plot.series {
        if let Some(thinned) = index(s).and_then(|i| marks.get(i).cloned().flatten()) {
            s.points = thinned;
        }
    }
    thinned
}

/// The default theme (Unicode, colours), for callers that do not say which one draws.
pub(crate) fn theme_for_layout() -> &'static Theme {
    static THEME: std::sync::LazyLock<Theme> =
        std::sync::LazyLock::new(|| Theme::new(crate::tui::theme::Glyphs::UNICODE, true));
    &THEME
}

/// A named curve of a run: what it plots at each sampled state.
type Curve = (&'static str, fn(&Snapshot) -> f64);

/// A part of the energy split: name, letter, style, value.
type Part = (&'static str, &'static str, Style, fn(&EnergySplit) -> f64);

/// The pinned run's curves for the chart, drawn first (under the current ones), dimmed.
fn pinned_series(
    app: &App,
    cache: &mut ViewCache,
    columns: usize,
    theme: &Theme,
    curves: &[Curve],
) -> Vec<PlotLine> {
    if app.lab.pinned.is_none() {
        return Vec::new();
    }
    let samples = cache.pinned_samples(&app.lab, (columns, app.chart_range()));
    // Without colour a dimmed braille line looks like the current run's: the pinned
    // run is drawn in dots of its own glyph then, under the current curves (ASCII draws
    // every line in its glyph).
    let (draw, glyph) = match (theme.uncoloured_curves(), theme.glyphs.ascii) {
        (_, true) => (Draw::Line, "."),
        (true, false) => (Draw::PointsUnder, "·"),
        (false, false) => (Draw::Line, "."),
    };
    curves
        .iter()
        .enumerate()
        .map(|(k, (name, value))| PlotLine {
            name: if k == 0 {
                format!("pinned {name}")
            } else {
                String::new()
            },
            points: samples.iter().map(|s| (s.t, value(s))).collect(),
            style: theme.dim,
            glyph,
            draw,
        })
        .collect()
}

fn series_of(
    name: &str,
    samples: &[Snapshot],
    value: impl Fn(&Snapshot) -> f64,
    style: Style,
    glyph: &'static str,
) -> PlotLine {
    PlotLine {
        name: name.to_string(),
        points: samples.iter().map(|s| (s.t, value(s))).collect(),
        style,
        glyph,
        draw: Draw::Line,
    }
}

/// The y range and ticks over every series' finite values (the snapshot's measured
/// series by their range made once per scene, not a pass over their rows).
fn bounds(
    series: &[PlotLine],
    measured: Option<&MeasuredPoints>,
    rows: usize,
) -> ((f64, f64), Vec<f64>) {
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for s in series
        .iter()
        .filter(|s| !measured.is_some_and(|m| m.is_bars(&s.points)))
    {
        let range = measured
            .and_then(|m| m.range_of(&s.points))
            .unwrap_or_else(|| value_range(&s.points));
        if let Some((a, b)) = range {
            lo = lo.min(a);
            hi = hi.max(b);
        }
    }
    nice_ticks(lo, hi, (rows / 3).max(2))
}

/// The y range of `series` as they are (cut at the cursor), symmetric about zero if
/// `symmetric`, with round ticks.
fn shown_y_range(series: &[PlotLine], symmetric: bool, rows: usize) -> (f64, f64) {
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for (a, b) in series.iter().filter_map(|s| value_range(&s.points)) {
        lo = lo.min(a);
        hi = hi.max(b);
    }
    if symmetric && lo <= hi {
        let m = lo.abs().max(hi.abs());
        (lo, hi) = (-m, m);
    }
    nice_ticks(lo, hi, (rows / 3).max(2)).0
}

/// The balls drawn (0 left, 1 right) and how the title names them.
fn balls_shown(chart_ball: ChartBall) -> (Vec<usize>, &'static str) {
    match chart_ball {
        ChartBall::Left => (vec![0], "left ball"),
        ChartBall::Right => (vec![1], "right ball"),
        ChartBall::Both => (vec![0, 1], "both balls"),
    }
}

/// The exact run's v_cm and v_t of each ball shown (tagged L/R when both are).
fn exact_velocities(samples: &[Snapshot], balls: &[usize], theme: &Theme) -> Vec<PlotLine> {
    let mut series = Vec::new();
    for &i in balls {
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
        let ball = move |s: &Snapshot| -> BallState { if i == 0 { s.left } else { s.right } };
        series.push(series_of(&tag("v_cm"), samples, |s| ball(s).v, style, "*"));
        let accent = if i == 0 {
            theme.accent
        } else {
            theme.right_accent
        };
        series.push(series_of(&tag("v_t"), samples, |s| ball(s).u, accent, "+"));
    }
    series
}

/// The time-stepping overlay: its progress while it runs (a legend entry), then its
/// v_cm and v_t over the exact curves, so its chatter shows.
fn overlay_velocities(app: &App, balls: &[usize], columns: usize, theme: &Theme) -> Vec<PlotLine> {
    let o = match app.overlay().state() {
        State::Computing { done, total } => {
            let name = app.overlay().choice.map_or("", |(m, _)| m.name());
            return vec![PlotLine {
                name: format!("{name} {}", super::panel::progress_text(done, total)),
                points: Vec::new().into(),
                style: theme.overlay,
                glyph: "%",
                draw: Draw::Line,
            }];
        }
        State::Ready(o) => o,
        State::Idle => return Vec::new(),
    };
    // The overlay's own colours and glyphs (never the data's red or marks); without
    // colour it is drawn as markers so that its glyphs tell it from the exact curves.
    let draw = if theme.monochrome {
        Draw::Points
    } else {
        Draw::Line
    };
    let (glyph_v, glyph_u) = if theme.glyphs.ascii {
        ("%", "~")
    } else {
        ("∘", "▵")
    };
    let setting = o.row.setting();
    let mut series = Vec::new();
    for &i in balls {
        let pts = |j: usize| {
            let p: Vec<(f64, f64)> = o.points.iter().map(|(t, y)| (*t, y[3 * i + j])).collect();
            match draw {
                Draw::Points => thin_to(p, columns / 2),
                Draw::Line | Draw::PointsUnder => p,
            }
        };
        let side = match (balls.len(), i) {
            (1, _) => "",
            (_, 0) => " L",
            _ => " R",
        };
        series.push(PlotLine {
            name: format!(
                "{} {setting} ({}) v_cm{side}",
                o.method.name(),
                o.row.status.name()
            ),
            points: pts(1).into(),
            style: theme.overlay,
            glyph: glyph_v,
            draw,
        });
        series.push(PlotLine {
            name: format!("v_t{side}"),
            points: pts(2).into(),
            style: theme.overlay_t,
            glyph: glyph_u,
            draw,
        });
    }
    series
}

fn velocities(
    app: &App,
    cache: &mut ViewCache,
    area: Rect,
    theme: &Theme,
    extras: Extras,
) -> (Vec<String>, Plot) {
    let columns = usize::from(area.width.saturating_sub(10));
    let samples = cache.samples(&app.lab, (columns, app.chart_range()));
    let (balls, which) = balls_shown(app.charts().ball());
    let curves: Vec<Curve> = balls
        .iter()
        .flat_map(|&i| -> [Curve; 2] {
            if i == 0 {
                [("run", |s| s.left.v), ("", |s| s.left.u)]
            } else {
                [("run", |s| s.right.v), ("", |s| s.right.u)]
            }
        })
        .collect();
    let mut series = pinned_series(app, cache, columns, theme, &curves);
    series.extend(exact_velocities(&samples, &balls, theme));
    series.extend(overlay_velocities(app, &balls, columns, theme));
    if let Some(m) = app.lab.points.as_ref().filter(|_| balls.contains(&0)) {
        series.extend(measured_velocities(m, theme));
    }
    let mut vlines = Vec::new();
    if let (Extras::LineFits, State::Ready(Ok(f))) = (extras, app.fit().fits())
        && let Some(l) = &f.line_fit
    {
        let (lines, ends) = line_fit_marks(l, theme);
        series.extend(lines);
        vlines.extend(ends);
    }
    let rows = usize::from(area.height.saturating_sub(4));
    let ((y0, y1), _) = bounds(&series, app.lab.points.as_deref(), rows);
    let whos: Vec<Who> = balls.iter().map(|&i| Who::ball(i)).collect();
    vlines.extend(event_lines(app, &whos, theme));
    let plot = time_plot(app, (y0, y1), "v (m/s)", series, vlines);
    // The file the points come from is named on the status line, in every view.
    let titles = vec![
        format!("v_cm(t) and v_t(t), {which}  [b] switches"),
        format!("v_cm(t) and v_t(t), {which}  [b]"),
        format!("v_cm, v_t, {which} [b]"),
    ];
    (titles, plot)
}

/// A chart against the shown time window, with the cursor at the shown time.
fn time_plot(
    app: &App,
    y_range: (f64, f64),
    y_title: impl Into<String>,
    series: Vec<PlotLine>,
    vlines: Vec<VLine>,
) -> Plot {
    Plot {
        x_range: app.chart_range(),
        y_range,
        x_title: "t (s)".into(),
        y_title: y_title.into(),
        series,
        vlines,
        cursor: Some(app.t),
        x_ticks: None,
        y_ticks: None,
    }
}

/// At most about `n` of `points`, evenly picked (markers one per two columns).
fn thin_to(points: Vec<(f64, f64)>, n: usize) -> Vec<(f64, f64)> {
    let every = points.len().div_ceil(n.max(1)).max(1);
    points.into_iter().step_by(every).collect()
}

/// What the positions chart shows: lengths, in their display unit.
const POSITION: Dimension = Dimension::Length;

fn positions(app: &App, cache: &mut ViewCache, area: Rect, theme: &Theme) -> (Vec<String>, Plot) {
    let columns = usize::from(area.width.saturating_sub(10));
    let samples = cache.samples(&app.lab, (columns, app.chart_range()));
    let mut series = pinned_series(
        app,
        cache,
        columns,
        theme,
        &[
            ("run", |s| POSITION.to_display(s.left.x)),
            ("", |s| POSITION.to_display(s.right.x)),
        ],
    );
    series.extend([
        series_of(
            "x left",
            &samples,
            |s| POSITION.to_display(s.left.x),
            theme.left,
            "*",
        ),
        series_of(
            "x right",
            &samples,
            |s| POSITION.to_display(s.right.x),
            theme.right,
            "+",
        ),
    ]);
    // A position track's centre, where the model's left ball would be (x − R).
    if let Some(x) = app.lab.points.as_ref().and_then(|m| m.x.as_ref()) {
        series.push(PlotLine {
            name: "tracked x".into(),
            points: Arc::clone(x),
            style: theme.measured,
            glyph: if theme.glyphs.ascii { "x" } else { "×" },
            draw: Draw::Points,
        });
    }
    let rows = usize::from(area.height.saturating_sub(4));
    let ((y0, y1), _) = bounds(&series, app.lab.points.as_deref(), rows);
    let plot = time_plot(
        app,
        (y0, y1),
        format!("x ({})", POSITION.display_unit().0),
        series,
        event_lines(app, &[Who::Left, Who::Right], theme),
    );
    let titles = [
        "x(t) of both balls  [x] back to velocities",
        "x(t) of both balls  [x] velocities",
        "x(t), both balls [x]",
    ];
    (titles.map(String::from).to_vec(), plot)
}

/// Energy against time: the kinetic parts and what friction, impacts and rolling
/// resistance have taken so far, with their constant sum (the initial energy).
fn energy(app: &App, cache: &mut ViewCache, area: Rect, theme: &Theme) -> (Vec<String>, Plot) {
    let columns = usize::from(area.width.saturating_sub(10));
    let split = cache.energies(&app.lab, (columns, app.chart_range()));
    let letters = theme.uncoloured_curves() || theme.glyphs.ascii;
    let draw = if letters && !theme.glyphs.ascii {
        // Braille cannot carry a letter: mark each sample cell instead.
        Draw::Points
    } else {
        Draw::Line
    };
    // Narrow charts (80 columns) get short names so the whole legend fits on its row.
    let wide = area.width >= 70;
    let name = |long: &'static str, short: &'static str| if wide { long } else { short };
    let parts: [Part; 5] = [
        (name("trans", "tr"), "t", theme.left, |e| e.translational),
        ("rot", "r", theme.accent, |e| e.rotational),
        (name("friction", "fric"), "f", theme.right, |e| {
            e.lost.friction
        }),
        (name("impacts", "imp"), "i", theme.flash, |e| e.lost.impacts),
        (name("c_rr", "rr"), "c", theme.info, |e| {
            e.lost.rolling_resistance
        }),
    ];
    let total = split.first().map_or(0.0, |(_, e)| e.total());
    let mut series = vec![PlotLine {
        name: name("total", "sum").into(),
        points: split.iter().map(|(t, e)| (*t, e.total())).collect(),
        style: theme.dim,
        glyph: "=",
        draw,
    }];
    if app.lab.pinned.is_some() {
        // The pinned run's kinetic energy, for the A/B comparison.
        series.insert(
            0,
            PlotLine {
                name: "pinned kinetic".into(),
                points: cache
                    .pinned_kinetic(&app.lab, (columns, app.chart_range()))
                    .iter()
                    .copied()
                    .collect(),
                style: theme.dim,
                glyph: ".",
                draw: Draw::Line,
            },
        );
    }
    for (name, glyph, style, value) in parts {
        let points: Vec<(f64, f64)> = split.iter().map(|(t, e)| (*t, value(e))).collect();
        // A part that stays zero (no impact loss at e = 1, no rolling resistance) is
        // named in the legend but not drawn over the axis.
        let zero = points.iter().all(|p| p.1.abs() <= 1e-9 * total.abs());
        let name = if zero {
            format!("{name} 0")
        } else {
            name.to_string()
        };
        series.push(PlotLine {
            name,
            points: if zero { Vec::new() } else { points }.into(),
            style,
            glyph,
            draw,
        });
    }
    let rows = usize::from(area.height.saturating_sub(4));
    // Room above the total for the event labels on the top row.
    let ((_, y1), _) = nice_ticks(0.0, 1.1 * total, (rows / 3).max(2));
    let plot = time_plot(
        app,
        (0.0, y1.max(f64::MIN_POSITIVE)),
        name("E (J)", "J"),
        series,
        event_lines(app, &[Who::Left, Who::Right], theme),
    );
    let titles = [
        "Energy of both balls  [e] back to velocities",
        "Energy, both balls  [e] velocities",
        "Energy, both balls [e]",
    ];
    (titles.map(String::from).to_vec(), plot)
}

/// The chart laid out in the frame as a component.
pub struct ChartPanel;

impl Component for ChartPanel {
    fn render(&self, area: Rect, buf: &mut Buffer, cx: &Ctx<'_>) {
        if let Some(chart) = &cx.frame.chart {
            render(chart, area, buf, cx.theme);
        }
    }
}

/// The energy chart while the outcome is hidden: before the impact its rotational
/// over translational energy is 2/(5k²) = 1/D, the answer (rot above trans: they
/// come back).
pub(super) const ENERGY_WITHHELD: Withheld = Withheld {
    title: "Energy",
    what: "the energy chart",
};

/// The chart of the views that show one, built on `area` ([`build`]).
pub(super) fn prepared(
    app: &App,
    cache: &mut ViewCache,
    area: Rect,
    theme: &Theme,
    extras: Extras,
) -> Prepared {
    let (chart, marks_thinned) = build(app, cache, area, theme, extras);
    Prepared {
        chart: Some(chart),
        regimes: None,
        marks_thinned,
    }
}

/// The Charts view: the chart and the Why panel beside it.
pub struct ChartsView;

impl MainView for ChartsView {
    fn view(&self) -> View {
        View::Charts
    }

    fn prepare(&self, app: &App, cache: &mut ViewCache, chart: Rect, theme: &Theme) -> Prepared {
        prepared(app, cache, chart, theme, Extras::None)
    }

    fn parts(&self, app: &App) -> Vec<(&'static dyn Component, Place)> {
        if app.hidden().derived() && app.charts().energy() {
            vec![(&ENERGY_WITHHELD, Place::Chart), (&info::Why, Place::Side)]
        } else {
            vec![(&ChartPanel, Place::Chart), (&info::Why, Place::Side)]
        }
    }
}
