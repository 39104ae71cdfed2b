//! Drawing the lab: one layout, one function per panel, all reading the [`App`] and
//! writing into a [`Buffer`]. The terminal and the headless `render` both call
//! [`draw`], so a script sees exactly what a user sees.

mod charts;
mod fit;
mod info;
mod map;
mod methods;
mod params;

pub use params::param_at;
mod popups;
mod scene;

use ratatui::buffer::Buffer;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::text::{Line, Span};
use ratatui::widgets::{Block, Paragraph, Widget};

use super::app::{App, Mode, Status, View};
use super::keys;
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
    let panels = layout(area)?;
    if app.view != View::Charts || app.mode != Mode::Normal {
        return None;
    }
    charts::time_at(app, panels.chart, column, row)
}

/// A bordered block in the theme's glyph set.
pub(crate) fn block<'a>(title: impl Into<Line<'a>>, theme: &Theme) -> Block<'a> {
    Block::bordered()
        .border_set(theme.glyphs.border)
        .border_style(theme.dim)
        .title(title.into().style(theme.title))
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
            if app.view == View::Map {
                map::render(app, p.chart, buf, theme);
                info::render(app, p.info, buf, theme);
            } else if app.view == View::Methods {
                methods::render_diagram(app, p.chart, buf, theme);
                methods::render_rows(app, p.info, buf, theme);
            } else {
                charts::render(app, p.chart, buf, theme);
                if app.fit_view {
                    fit::render(app, p.info, buf, theme);
                } else {
                    info::render(app, p.info, buf, theme);
                }
            }
            status(app, p.status, buf, theme);
            hints(p.hints, buf, theme);
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

fn status(app: &App, area: Rect, buf: &mut Buffer, theme: &Theme) {
    let right = format!("preset {}", app.lab.preset.name);
    let (text, style) = match (&app.mode, &app.status) {
        (Mode::Edit(_), _) => (
            "type a value with its unit (e.g. 4.4cm), Enter applies, Esc cancels".to_string(),
            theme.info,
        ),
        (_, Status::Error(e)) => (e.clone(), theme.error),
        (_, Status::Info(i)) => (format!("{}   {i}", app.playback()), theme.text),
        (_, Status::None) => (app.playback(), theme.text),
    };
    let text = theme.glyphs.text(&text);
    let room = area.width.saturating_sub(right.len() as u16 + 1) as usize;
    buf.set_stringn(area.x, area.y, &text, room, style);
    if text.chars().count() < room {
        buf.set_string(area.right() - right.len() as u16, area.y, &right, theme.dim);
    }
}

fn hints(area: Rect, buf: &mut Buffer, theme: &Theme) {
    let mut spans = Vec::new();
    for (key, label) in keys::hints(theme.glyphs.ascii) {
        spans.push(Span::styled(key, theme.key));
        spans.push(Span::styled(format!(" {label}  "), theme.dim));
    }
    Paragraph::new(Line::from(spans)).render(area, buf);
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
