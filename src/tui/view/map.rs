//! The Map view: the regime over groove width and restitution for the current balls
//! as a coloured character grid with the scene marked, and the paper's figure of
//! |a_cm|/(μ_k g), |a_t|/(μ_k g) and D against b/R with the current b marked.

use ratatui::buffer::Buffer;
use ratatui::layout::{Constraint, Layout, Rect};

use super::info;
use super::panel::block;
use super::withheld::Withheld;
use crate::physics::closed_form;
use crate::physics::derived::Regime;
use crate::tui::app::App;
use crate::tui::component::{Component, Ctx, MainView, Place, Prepared};
use crate::tui::plot::{Draw, Plot, PlotLine, VLine};
use crate::tui::theme::Theme;
use crate::tui::view_cache::ViewCache;
use crate::tui::vocabulary::View;

/// The regime map's half of `area` and the paper figure's.
fn halves(area: Rect) -> [Rect; 2] {
    Layout::horizontal([Constraint::Percentage(55), Constraint::Percentage(45)]).areas(area)
}

/// The regime grid's cells (columns, rows) in the map view drawn in `area`; `None`
/// when too small to draw one.
pub fn grid_size(area: Rect) -> Option<(usize, usize)> {
    let inner =
        block("", &Theme::new(crate::tui::theme::Glyphs::UNICODE, true)).inner(halves(area)[0]);
    if inner.width < 12 || inner.height < 4 {
        return None;
    }
    // Bottom row: legend; left column: e ticks (4 wide).
    Some((usize::from(inner.width - 5), usize::from(inner.height - 2)))
}

/// Draws the map view with its regime `grid` (made before drawing, [`grid_size`]).
pub fn render(app: &App, grid: &[Regime], area: Rect, buf: &mut Buffer, theme: &Theme) {
    let [left, right] = halves(area);
    regime_map(app, grid, left, buf, theme);
    paper_figure(app, right, buf, theme);
}

fn regime_map(app: &App, grid: &[Regime], area: Rect, buf: &mut Buffer, theme: &Theme) {
    let g = theme.glyphs;
    let inner = super::panel::framed(
        &[
            "Regime: b/R across, e up  [g] back",
            "Regime: b/R, e up  [g]",
            "Regime b/R, e [g]",
            "Regime [g]",
        ],
        area,
        buf,
        theme,
    );
    if inner.width < 12 || inner.height < 4 {
        return;
    }
    // Bottom row: legend; left column: e ticks (4 wide).
    let cols = usize::from(inner.width - 5);
    let rows = usize::from(inner.height - 2);
    let radius = app.lab.scene.radius;
    let glyph = |r: Regime| match (r, g.ascii) {
        (Regime::Depart, _) => ".",
        (Regime::Rest, _) => "=",
        (Regime::Recollide, false) => "▒",
        (Regime::Recollide, true) => "#",
    };
    let style = |r: Regime| match r {
        Regime::Depart => theme.left,
        Regime::Rest => theme.dim,
        Regime::Recollide => theme.accent,
    };
    let b_max = 2.0 * radius * 0.99;
    if grid.len() != cols * rows {
        return;
    }
    for rr in 0..rows {
        let e = 1.0 - rr as f64 / (rows - 1).max(1) as f64;
        let label = if rr == 0 || rr == rows - 1 || rr == rows / 2 {
            format!("{e:>4.1}")
        } else {
            "    ".to_string()
        };
        buf.set_string(inner.x, inner.y + rr as u16, label, theme.dim);
        for c in 0..cols {
            let r = grid[rr * cols + c];
            buf.set_string(
                inner.x + 5 + c as u16,
                inner.y + rr as u16,
                glyph(r),
                style(r),
            );
        }
    }
    // The scene itself (not while b is hidden: its column would give b away).
    let c = (app.lab.scene.width / b_max * (cols - 1) as f64).round() as u16;
    let r = ((1.0 - app.lab.scene.restitution) * (rows - 1) as f64).round() as u16;
    if usize::from(c) < cols && usize::from(r) < rows && !app.hidden().derived() {
        buf.set_string(
            inner.x + 5 + c,
            inner.y + r,
            if g.ascii { "@" } else { "◆" },
            theme.cursor,
        );
    }
    b_over_r_axis(inner, (cols, b_max / radius), buf, theme);
    // The full legend where it fits, else the marks alone (never a word cut silently).
    let marker = if g.ascii { "@" } else { "◆" };
    let recollide = glyph(Regime::Recollide);
    let long = format!(
        "0 … b/R {:.2}   . depart  = rest  {recollide} recollide  {marker} this scene",
        b_max / radius
    );
    let short = format!(". depart = rest {recollide} back {marker} here");
    let tiny = format!("{recollide}back .apart =rest {marker}");
    let width = usize::from(inner.width);
    let legend = [long, short, tiny]
        .into_iter()
        .map(|l| g.text(&l))
        .find(|l| l.chars().count() <= width)
        .unwrap_or_else(|| g.ellipsize(". depart = rest", width));
    buf.set_stringn(
        inner.x,
        inner.bottom() - 1,
        legend,
        usize::from(inner.width),
        theme.dim,
    );
}

/// The b/R axis under the map (its `cols` columns span b/R from 0 to `span`), on the
/// row above the legend: 0, 1 (b = R) at its column, and the right end (the long
/// legend, which also gives the range, fits only a wide map).
fn b_over_r_axis(inner: Rect, (cols, span): (usize, f64), buf: &mut Buffer, theme: &Theme) {
    let axis_row = inner.bottom() - 2;
    buf.set_string(inner.x, axis_row, "b/R", theme.dim);
    let one = (1.0 / span * (cols - 1) as f64).round() as usize;
    let ends = [
        (0, "0".to_string()),
        (one, "1".to_string()),
        (cols - 1, format!("{span:.2}")),
    ];
    let mut free = 0;
    for (c, text) in ends {
        // Centred on its column, the last right-aligned to the map's edge, none
        // overlapping the one before.
        let len = text.chars().count();
        let at = if c + 1 == cols {
            c + 1 - len.min(c + 1)
        } else {
            c.saturating_sub(len / 2)
        };
        if at < free || at + len > cols {
            continue;
        }
        buf.set_string(inner.x + 5 + at as u16, axis_row, text, theme.dim);
        free = at + len + 1;
    }
}

fn paper_figure(app: &App, area: Rect, buf: &mut Buffer, theme: &Theme) {
    let inner = super::panel::framed(
        &[
            "Paper fig.: a/(μ g) and D against b/R",
            "Paper fig.: a/(μ g), D vs b/R",
            "Paper fig.: a/(μ g) and D",
            "Paper fig.",
        ],
        area,
        buf,
        theme,
    );
    let n = 200;
    let xs: Vec<f64> = (0..=n).map(|i| 1.95 * i as f64 / n as f64).collect();
    let k = |x: f64| closed_form::contact_ratio(1.0, x);
    let series = |name: &str, f: &dyn Fn(f64) -> f64, style, glyph| PlotLine {
        name: name.to_string(),
        points: xs.iter().map(|&x| (x, f(x))).collect(),
        style,
        glyph,
        draw: Draw::Line,
    };
    let plot = Plot {
        x_range: (0.0, 2.0),
        y_range: (0.0, 3.0),
        x_title: "b/R".into(),
        y_title: String::new(),
        series: vec![
            series(
                &theme.glyphs.text("|a_cm|/μg"),
                &|x| 1.0 / k(x),
                theme.left,
                "*",
            ),
            series(
                &theme.glyphs.text("|a_t|/μg"),
                &|x| 2.5 * k(x),
                theme.accent,
                "+",
            ),
            series("D", &|x| closed_form::determinant(k(x)), theme.right, "o"),
        ],
        // This scene's b/R, unless b is hidden.
        vlines: [
            VLine {
                x: app.lab.scene.width / app.lab.scene.radius,
                label: Some("b".into()),
                style: theme.cursor,
                priority: 1,
            },
            VLine {
                x: (12.0f64 / 5.0).sqrt(),
                label: Some("b*".into()),
                style: theme.event,
                priority: 0,
            },
        ]
        .into_iter()
        .skip(usize::from(app.hidden().derived()))
        .collect(),
        cursor: None,
        x_ticks: None,
        y_ticks: None,
    };
    plot.render(inner, buf, theme);
}

/// The regime map and the paper's figure as a component.
pub struct Map;

impl Component for Map {
    fn render(&self, area: Rect, buf: &mut Buffer, cx: &Ctx<'_>) {
        let grid = cx.frame.regimes.as_deref().unwrap_or(&[]);
        render(cx.app, grid, area, buf, cx.theme);
    }
}

/// The Map view's panels while a prediction is pending (b shown: its place on the
/// map is the answer).
const MAP_WITHHELD: [Withheld; 2] = [
    Withheld {
        title: "Regime map",
        what: "the regime map",
    },
    Withheld {
        title: "Why",
        what: "why",
    },
];

/// The Map view: the regime map and the paper's figure, and the Why panel.
pub struct MapView;

impl MainView for MapView {
    fn view(&self) -> View {
        View::Map
    }

    /// The regime grid at this size, from the screen's cache.
    fn prepare(&self, app: &App, cache: &mut ViewCache, chart: Rect, _: &Theme) -> Prepared {
        Prepared {
            regimes: grid_size(chart).map(|(cols, rows)| cache.regime_grid(&app.lab, cols, rows)),
            ..Prepared::default()
        }
    }

    fn parts(&self, app: &App) -> Vec<(&'static dyn Component, Place)> {
        let hide = app.hidden();
        if hide.pending() && !hide.b() {
            vec![
                (&MAP_WITHHELD[0], Place::Chart),
                (&MAP_WITHHELD[1], Place::Side),
            ]
        } else {
            vec![(&Map, Place::Chart), (&info::Why, Place::Side)]
        }
    }
}
