//! Drawing the lab: one layout, one function per panel, all reading the [`App`] and
//! writing into a [`Buffer`]. The terminal and the headless `render` both call
//! [`draw`], so a script sees exactly what a user sees. What depends on the terminal's
//! size is kept in the app's [`crate::tui::view_cache::ViewCache`]; what every panel
//! draws with is in `panel`.

mod charts;
mod fit;
mod forces;
mod info;
mod map;
mod methods;
mod panel;
mod params;

pub use forces::answer_at;
pub use params::param_at;
pub use popups::{data_rows, picker_row_at};
mod popups;
mod scene;
mod status;

use ratatui::buffer::Buffer;
use ratatui::layout::{Constraint, Layout, Rect};

use super::app::{App, Mode, View};
use super::theme::{Theme, force_ascii};

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

/// Draws the whole screen (in ASCII mode, any symbol a widget still drew outside
/// 7-bit ASCII gets a stand-in; [`non_ascii_cells`] lets tests see that none was needed).
pub fn draw(app: &App, area: Rect, buf: &mut Buffer, theme: &Theme) {
    draw_panels(app, area, buf, theme);
    stand_ins(buf, theme);
}

/// In ASCII mode, a stand-in for any symbol outside 7-bit ASCII.
fn stand_ins(buf: &mut Buffer, theme: &Theme) {
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
    non_ascii(&buf)
}

/// [`to_text`] and [`non_ascii_cells`] of one drawing (a test of every screen draws
/// each once).
pub fn to_text_and_non_ascii_cells(
    app: &App,
    width: u16,
    height: u16,
    theme: &Theme,
) -> (String, Vec<(u16, u16, String)>) {
    let area = Rect::new(0, 0, width, height);
    let mut buf = Buffer::empty(area);
    draw_panels(app, area, &mut buf, theme);
    let cells = non_ascii(&buf);
    stand_ins(&mut buf, theme);
    (text_of(&buf), cells)
}

/// The cells of a drawing outside 7-bit ASCII: `(x, y, symbol)`.
fn non_ascii(buf: &Buffer) -> Vec<(u16, u16, String)> {
    let area = buf.area;
    let mut cells = Vec::new();
    for y in area.top()..area.bottom() {
        for x in area.left()..area.right() {
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
            // The size it has and the size it needs; on two short lines where one does
            // not fit, so that a narrow terminal still shows both numbers whole.
            let (has, needs) = (
                format!("{}{times}{}", area.width, area.height),
                format!("{w}{times}{h}"),
            );
            let one = format!("terminal {has} is too small: groovelab needs {needs}");
            let lines = if one.chars().count() <= area.width as usize {
                vec![one]
            } else {
                vec![format!("terminal {has}"), format!("needs {needs}")]
            };
            let top = area.y + area.height.saturating_sub(2) / 2;
            for (y, msg) in (top..area.bottom()).zip(&lines) {
                let x = area.x + area.width.saturating_sub(msg.chars().count() as u16) / 2;
                buf.set_stringn(x, y, msg, area.width as usize, theme.error);
            }
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

/// The screen as plain text, one line per row, trailing blanks trimmed (for
/// `groovelab render` and snapshot tests).
pub fn to_text(app: &App, width: u16, height: u16, theme: &Theme) -> String {
    let area = Rect::new(0, 0, width, height);
    let mut buf = Buffer::empty(area);
    draw(app, area, &mut buf, theme);
    text_of(&buf)
}

/// A drawn screen as plain text, one line per row, trailing blanks trimmed.
fn text_of(buf: &Buffer) -> String {
    let area = buf.area;
    let mut out = String::with_capacity((area.width as usize + 1) * area.height as usize);
    for y in area.top()..area.bottom() {
        let mut line = String::new();
        for x in area.left()..area.right() {
            line.push_str(buf[(x, y)].symbol());
        }
        out.push_str(line.trim_end());
        out.push('\n');
    }
    out
}
