//! Drawing the lab: one layout, one function per panel, all reading the [`App`] and
//! writing into a [`Buffer`]. The terminal and the headless `render` both call
//! [`draw`], so a script sees exactly what a user sees.

mod cache;
mod charts;
mod fit;
mod forces;
mod info;
mod map;
mod methods;
mod params;

pub use cache::ViewCache;
pub use forces::ANSWERS;
pub use params::param_at;
pub use popups::data_rows;
mod popups;
mod scene;
mod status;

use ratatui::buffer::Buffer;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::style::Style;
use ratatui::text::{Line, Span};
use ratatui::widgets::Block;

use super::app::{App, Mode, View};
use super::theme::{Theme, force_ascii};
use crate::lab::jobs::State;

/// Smallest terminal the layout is made for.
pub const MIN_SIZE: (u16, u16) = (80, 24);

/// Where each panel goes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Panels {
    pub params: Rect,
    pub scene: Rect,
    pub chart: Rect,
    pub info: Rect,
    pub status: Rect,
    pub hints: Rect,
}

/// The layout for a screen of `area`; `None` if it is too small.
pub fn layout(area: Rect) -> Option<Panels> {
    if area.width < MIN_SIZE.0 || area.height < MIN_SIZE.1 {
        return None;
    }
    // Tall screens show every parameter; short ones scroll the list (7 rows) so the
    // charts keep room.
    let top_height = if area.height >= 32 {
        super::app::ROWS.len() as u16 + 2
    } else {
        9
    };
    let [top, middle, status, hints] = Layout::vertical([
        Constraint::Length(top_height),
        Constraint::Min(8),
        Constraint::Length(1),
        Constraint::Length(1),
    ])
    .areas(area);
    let params_width = if area.width >= 110 { 41 } else { 32 };
    let [params, scene] =
        Layout::horizontal([Constraint::Length(params_width), Constraint::Min(30)]).areas(top);
    // Wide screens give the side panel more room (the runs list, the fit's two columns).
    let info_width = if area.width >= 180 {
        60
    } else if area.width >= 110 {
        46
    } else {
        36
    };
    let [chart, info] =
        Layout::horizontal([Constraint::Min(30), Constraint::Length(info_width)]).areas(middle);
    Some(Panels {
        params,
        scene,
        chart,
        info,
        status,
        hints,
    })
}

/// The time under a click at (`column`, `row`) of a screen of `area`: inside the
/// chart's plot while the charts are shown and no popup is open.
pub fn chart_time_at(app: &App, area: Rect, column: u16, row: u16) -> Option<f64> {
    chart_time_at_in(app, area, charts::theme_for_layout(), column, row)
}

/// [`chart_time_at`] for a screen drawn with `theme` (the legend's rows depend on it).
pub fn chart_time_at_in(
    app: &App,
    area: Rect,
    theme: &Theme,
    column: u16,
    row: u16,
) -> Option<f64> {
    let panels = layout(area)?;
    if app.view != View::Charts || app.mode != Mode::Normal {
        return None;
    }
    charts::time_at(app, panels.chart, theme, column, row)
}

/// A bordered block in the theme's glyph set.
pub(crate) fn block<'a>(title: impl Into<Line<'a>>, theme: &Theme) -> Block<'a> {
    Block::bordered()
        .border_set(theme.glyphs.border)
        .border_style(theme.dim)
        .title(title.into().style(theme.title))
}

/// A block title (` text `) that fits on the border of `area`, cut with an ellipsis.
pub(crate) fn title_within(title: &str, area: Rect, theme: &Theme) -> String {
    let room = usize::from(area.width.saturating_sub(4));
    format!(" {} ", theme.glyphs.ellipsize(title.trim(), room))
}

/// Draws the whole screen (in ASCII mode, any symbol a widget still drew outside
/// 7-bit ASCII gets a stand-in; [`non_ascii_cells`] lets tests see that none was needed).
pub fn draw(app: &App, area: Rect, buf: &mut Buffer, theme: &Theme) {
    draw_panels(app, area, buf, theme);
    if theme.glyphs.ascii {
        force_ascii(buf);
    }
}

/// The cells of an ASCII screen that would have needed a stand-in: `(x, y, symbol)`.
pub fn non_ascii_cells(
    app: &App,
    width: u16,
    height: u16,
    theme: &Theme,
) -> Vec<(u16, u16, String)> {
    let area = Rect::new(0, 0, width, height);
    let mut buf = Buffer::empty(area);
    draw_panels(app, area, &mut buf, theme);
    let mut cells = Vec::new();
    for y in 0..height {
        for x in 0..width {
            let sym = buf[(x, y)].symbol();
            if !sym.is_ascii() {
                cells.push((x, y, sym.to_string()));
            }
        }
    }
    cells
}

fn draw_panels(app: &App, area: Rect, buf: &mut Buffer, theme: &Theme) {
    match layout(area) {
        None => {
            let (w, h) = MIN_SIZE;
            let times = if theme.glyphs.ascii { "x" } else { "×" };
            let msg = format!("terminal too small (need {w}{times}{h})");
            let y = area.y + area.height / 2;
            let x = area.x + area.width.saturating_sub(msg.chars().count() as u16) / 2;
            buf.set_stringn(x, y, &msg, area.width as usize, theme.error);
        }
        Some(p) => {
            params::render(app, p.params, buf, theme);
            scene::render(app, p.scene, buf, theme);
            if app.view == View::Forces {
                // The Forces view takes the chart's and the info panel's room.
                forces::render(app, p.chart.union(p.info), buf, theme);
            } else if app.view == View::Map {
                map::render(app, p.chart, buf, theme);
                info::render(app, p.info, buf, theme);
            } else if app.view == View::Methods {
                methods::render_diagram(app, p.chart, buf, theme);
                methods::render_rows(app, p.info, buf, theme);
            } else {
                charts::render(app, p.chart, buf, theme);
                if app.fit_view() {
                    fit::render(app, p.info, buf, theme);
                } else {
                    info::render(app, p.info, buf, theme);
                }
            }
            status::render(app, p.status, p.hints, buf, theme);
            popups::render(app, area, buf, theme);
        }
    }
}

/// "computing… 40 %" (or without a share when the total is unknown).
pub(crate) fn progress_text(done: usize, total: usize) -> String {
    match (100 * done.min(total)).checked_div(total) {
        Some(percent) => format!("computing… {percent} %"),
        None => "computing…".to_string(),
    }
}

/// What a panel shows while its analysis runs: what is being done and how far.
pub(crate) fn computing<T>(
    state: &State<'_, T>,
    what: &str,
    area: Rect,
    buf: &mut Buffer,
    theme: &Theme,
) {
    let text = match state {
        State::Computing { done, total } => format!("{what}: {}", progress_text(*done, *total)),
        _ => String::new(),
    };
    let text = theme.glyphs.text(&text);
    buf.set_stringn(area.x, area.y, text, usize::from(area.width), theme.dim);
}

/// Lines of a panel with a priority each; [`by_priority`] keeps the most important
/// ones that fit.
pub(crate) type Ranked<'a> = Vec<(u8, Line<'a>)>;

/// The lines of `ranked` that fit in `area` once wrapped at its width, in their
/// order: while they do not fit, the lowest priority goes (the last such first). A
/// small screen so shows the important lines whole rather than the first ones.
pub(crate) fn by_priority<'a>(ranked: Ranked<'a>, area: Rect) -> Vec<Line<'a>> {
    let width = usize::from(area.width).max(1);
    let mut wrapped: Vec<(u8, Vec<Line<'a>>)> = ranked
        .into_iter()
        .map(|(p, line)| (p, wrap(line, width)))
        .collect();
    let rows = |w: &[(u8, Vec<Line>)]| w.iter().map(|(_, l)| l.len()).sum::<usize>();
    while rows(&wrapped) > usize::from(area.height) && !wrapped.is_empty() {
        let lowest = wrapped.iter().map(|w| w.0).min().unwrap_or(0);
        let i = wrapped.iter().rposition(|w| w.0 == lowest).unwrap_or(0);
        wrapped.remove(i);
    }
    wrapped.into_iter().flat_map(|(_, l)| l).collect()
}

/// Draws `lines` one per row from the top of `area` (already wrapped).
pub(crate) fn draw_lines(lines: Vec<Line<'_>>, area: Rect, buf: &mut Buffer) {
    for (i, line) in lines.into_iter().enumerate().take(usize::from(area.height)) {
        buf.set_line(area.x, area.y + i as u16, &line, area.width);
    }
}

/// `line` word-wrapped to `width` columns, styles kept: breaks after spaces, a word
/// longer than a row is split, spaces that end a row are dropped.
pub(crate) fn wrap(line: Line<'_>, width: usize) -> Vec<Line<'static>> {
    let mut rows: Vec<Vec<(String, Style)>> = vec![Vec::new()];
    let mut used = 0usize;
    // Words (with the spaces before them) as (text, style) pieces.
    let mut words: Vec<Vec<(String, Style)>> = Vec::new();
    let mut current: Vec<(String, Style)> = Vec::new();
    let mut in_space = false;
    for span in &line.spans {
        for c in span.content.chars() {
            let space = c == ' ';
            if !space && in_space && current.iter().any(|p| p.0.chars().any(|c| c != ' ')) {
                words.push(std::mem::take(&mut current));
            }
            in_space = space;
            match current.last_mut() {
                Some((text, style)) if *style == span.style => text.push(c),
                _ => current.push((c.to_string(), span.style)),
            }
        }
    }
    if !current.is_empty() {
        words.push(current);
    }
    for word in words {
        // A word carries the spaces after it; they never push it to the next row.
        let chars: Vec<(char, Style)> = word
            .iter()
            .flat_map(|(t, s)| t.chars().map(move |c| (c, *s)))
            .collect();
        let len = chars
            .iter()
            .rposition(|(c, _)| *c != ' ')
            .map_or(0, |i| i + 1);
        if used > 0 && used + len > width {
            rows.push(Vec::new());
            used = 0;
        }
        for (c, style) in chars {
            if used == width {
                if c == ' ' {
                    continue;
                }
                rows.push(Vec::new());
                used = 0;
            }
            let row = rows.last_mut().expect("one row at least");
            match row.last_mut() {
                Some((t, s)) if *s == style => t.push(c),
                _ => row.push((c.to_string(), style)),
            }
            used += 1;
        }
    }
    rows.into_iter()
        .map(|r| {
            Line::from(
                r.into_iter()
                    .map(|(t, s)| Span::styled(t, s))
                    .collect::<Vec<_>>(),
            )
        })
        .collect()
}

/// The screen as plain text, one line per row, trailing blanks trimmed (for
/// `groovelab render` and snapshot tests).
pub fn to_text(app: &App, width: u16, height: u16, theme: &Theme) -> String {
    let area = Rect::new(0, 0, width, height);
    let mut buf = Buffer::empty(area);
    draw(app, area, &mut buf, theme);
    let mut out = String::with_capacity((width as usize + 1) * height as usize);
    for y in 0..height {
        let mut line = String::new();
        for x in 0..width {
            line.push_str(buf[(x, y)].symbol());
        }
        out.push_str(line.trim_end());
        out.push('\n');
    }
    out
}
