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

pub use params::param_at;
pub use popups::data_rows;
mod popups;
mod scene;

use ratatui::buffer::Buffer;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::text::{Line, Span};
use ratatui::widgets::{Paragraph, Widget};

use super::app::{App, Mode, ROWS, Status, View};
use super::keys;
use super::theme::{Theme, force_ascii};
use crate::settings::params::Param;
use crate::settings::units::Dimension;

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
            status(app, p.status, buf, theme);
            hints(p.hints, buf, theme);
            popups::render(app, area, buf, theme);
        }
    }
}

/// The status line: playback (time, playing or paused, speed) and beside it the last
/// message, cut with an ellipsis where it does not fit (playback shortens first, down
/// to the time and the play state, which a message never hides); the typing prompt while a
/// value is typed; the preset's name at the right, always shown (itself cut if very
/// long).
fn status(app: &App, area: Rect, buf: &mut Buffer, theme: &Theme) {
    let g = theme.glyphs;
    let width = usize::from(area.width);
    let right = g.ellipsize(&format!("preset {}", app.lab.preset().name), width / 3);
    let right_len = right.chars().count();
    let room = width.saturating_sub(right_len + 1);
    buf.set_string(area.right() - right_len as u16, area.y, &right, theme.dim);
    let (message, style) = match (&app.mode, &app.status) {
        (Mode::Edit(_), _) => {
            let prompt = typing_prompt(ROWS[app.selected]).replace("mu_k", "μ_k");
            buf.set_stringn(area.x, area.y, g.ellipsize(&prompt, room), room, theme.info);
            return;
        }
        (_, Status::Error(e)) => (e.as_str(), theme.error),
        (_, Status::Info(i)) => (i.as_str(), theme.text),
        (_, Status::None) => ("", theme.text),
    };
    // The longest playback that leaves the message whole, else the shortest.
    let fits = |playback: &String| playback.chars().count() + 3 + message.chars().count() <= room;
    let playback = [app.playback(), app.playback_short(true)]
        .into_iter()
        .find(|p| message.is_empty() || fits(p))
        .unwrap_or_else(|| app.playback_short(false));
    let playback = g.ellipsize(&playback, room);
    let used = playback.chars().count();
    buf.set_stringn(area.x, area.y, &playback, room, theme.text);
    if !message.is_empty() && used + 3 < room {
        let message = g.ellipsize(message, room - used - 3);
        buf.set_stringn(
            area.x + used as u16 + 3,
            area.y,
            message,
            room - used - 3,
            style,
        );
    }
}

fn hints(area: Rect, buf: &mut Buffer, theme: &Theme) {
    let mut spans = Vec::new();
    for (key, label) in keys::hints_within(usize::from(area.width), theme.glyphs.ascii) {
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

/// The prompt of the typing field for parameter `p`: which unit a bare number is in.
fn typing_prompt(p: &Param) -> String {
    let (unit, _) = p.dim.display_unit();
    let example = match p.dim {
        Dimension::Length => "44mm",
        Dimension::Mass => "0.2kg",
        Dimension::Speed => "60cm/s",
        Dimension::Time => "200ms",
        Dimension::Acceleration => "9.81",
        Dimension::Ratio => "",
    };
    let name = p.label;
    if unit.is_empty() {
        format!("{name}: a plain number (e.g. 0.17), Enter applies, Esc cancels")
    } else {
        format!("{name} in {unit} (or with a unit, e.g. {example}), Enter applies, Esc cancels")
    }
}
