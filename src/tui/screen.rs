//! The screen: one frame laid out once, then drawn. [`Screen::prepare`] computes the
//! layout and everything the frame draws that depends on the terminal's size (the
//! chart built, the regime grid, how far a popup scrolls), keeping what depends only
//! on the snapshot and the size in its [`ViewCache`]; drawing then only reads, and
//! mouse hit-testing reads the same layout. The terminal's runner and the headless
//! `render` both hold one, so a script sees exactly what a user sees.

use std::rc::Rc;

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;

use super::app::{App, Mode, View};
use super::theme::{Theme, force_ascii};
use super::view::{self, Panels, charts::Chart};
use super::view_cache::ViewCache;
use crate::physics::derived::Regime;

/// One frame, laid out: what drawing and hit-testing share.
#[derive(Clone, Debug)]
pub struct Frame {
    pub area: Rect,
    /// Where each panel goes (`None`: the terminal is too small).
    pub panels: Option<Panels>,
    /// The chart, in the views that show one.
    pub chart: Option<Chart>,
    /// The Map view's regime grid.
    pub regimes: Option<Rc<[Regime]>>,
    /// How far the open help or data table scrolls at this size.
    pub scroll_max: usize,
}

/// What preparing a frame computed anew (work counted, for the tests: a frame that
/// only moves the time thins nothing again).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Work {
    /// Measured series thinned to the chart's cells (once per snapshot and grid).
    pub marks_thinned: usize,
}

/// The frames of one terminal (or one headless screen) and their caches.
#[derive(Clone, Debug, Default)]
pub struct Screen {
    cache: ViewCache,
    frame: Option<Frame>,
}

impl Screen {
    /// Lays out the frame of `app` on `area`: the one layout, the chart and the grid
    /// of the view shown, a popup's scroll limit; what only a new snapshot or size
    /// changes is taken from the cache.
    pub fn prepare(&mut self, app: &App, area: Rect, theme: &Theme) -> Work {
        let panels = view::layout(area);
        let mut work = Work::default();
        let (mut chart, mut regimes) = (None, None);
        if let Some(p) = panels {
            match app.view {
                View::Charts | View::Fit => {
                    let (built, thinned) =
                        view::charts::build(app, &mut self.cache, p.chart, theme);
                    work.marks_thinned += usize::from(thinned);
                    chart = Some(built);
                }
                View::Map => {
                    regimes = view::map::grid_size(p.chart)
                        .map(|(cols, rows)| self.cache.regime_grid(&app.lab, cols, rows));
                }
                View::Methods | View::Forces => {}
            }
        }
        self.frame = Some(Frame {
            area,
            panels,
            chart,
            regimes,
            scroll_max: view::scroll_max(app, area, theme),
        });
        work
    }

    /// The frame prepared last, if any.
    pub fn frame(&self) -> Option<&Frame> {
        self.frame.as_ref()
    }

    /// Draws the frame prepared last into `buf` (its area), changing nothing.
    pub fn render(&self, app: &App, buf: &mut Buffer, theme: &Theme) {
        if let Some(frame) = &self.frame {
            render(app, frame, buf, theme);
        }
    }

    /// Prepares and draws a frame of `app` on `area`; what it computed anew.
    pub fn draw(&mut self, app: &App, area: Rect, buf: &mut Buffer, theme: &Theme) -> Work {
        let work = self.prepare(app, area, theme);
        self.render(app, buf, theme);
        work
    }

    /// The screen as plain text (a new frame of `width` × `height`), one line per row,
    /// trailing blanks trimmed; and what the frame computed anew.
    pub fn text(&mut self, app: &App, width: u16, height: u16, theme: &Theme) -> (String, Work) {
        let area = Rect::new(0, 0, width, height);
        let mut buf = Buffer::empty(area);
        let work = self.draw(app, area, &mut buf, theme);
        (text_of(&buf), work)
    }

    /// The time under a click at (`column`, `row`) of the frame prepared last: inside
    /// the chart's plot while the charts are shown and no popup is open.
    pub fn chart_time_at(&self, app: &App, column: u16, row: u16) -> Option<f64> {
        if app.view != View::Charts || app.mode != Mode::Normal {
            return None;
        }
        self.frame.as_ref()?.chart.as_ref()?.time_at(column, row)
    }
}

/// The time under a click at (`column`, `row`) of a screen of `area` (laid out anew,
/// in the default theme): inside the chart's plot while the charts are shown and no
/// popup is open. The terminal asks its [`Screen`]'s last frame instead.
pub fn chart_time_at(app: &App, area: Rect, column: u16, row: u16) -> Option<f64> {
    let mut screen = Screen::default();
    screen.prepare(app, area, view::charts::theme_for_layout());
    screen.chart_time_at(app, column, row)
}

/// Draws the whole screen on a frame of its own (a caller that keeps no [`Screen`]).
pub fn draw(app: &App, area: Rect, buf: &mut Buffer, theme: &Theme) {
    Screen::default().draw(app, area, buf, theme);
}

/// Draws the prepared `frame` (in ASCII mode, any symbol a widget still drew outside
/// 7-bit ASCII gets a stand-in; [`non_ascii_cells`] lets tests see that none was needed).
fn render(app: &App, frame: &Frame, buf: &mut Buffer, theme: &Theme) {
    draw_panels(app, frame, buf, theme);
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
    let mut screen = Screen::default();
    screen.prepare(app, area, theme);
    if let Some(frame) = screen.frame() {
        draw_panels(app, frame, &mut buf, theme);
    }
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
    let mut screen = Screen::default();
    screen.prepare(app, area, theme);
    if let Some(frame) = screen.frame() {
        draw_panels(app, frame, &mut buf, theme);
    }
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

fn draw_panels(app: &App, frame: &Frame, buf: &mut Buffer, theme: &Theme) {
    let area = frame.area;
    match frame.panels {
        None => {
            let (w, h) = view::MIN_SIZE;
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
            view::params::render(app, p.params, buf, theme);
            view::scene::render(app, p.scene, buf, theme);
            match app.view {
                // The Forces view takes the chart's and the info panel's room.
                View::Forces => view::forces::render(app, p.chart.union(p.info), buf, theme),
                View::Map => {
                    if let Some(grid) = &frame.regimes {
                        view::map::render(app, grid, p.chart, buf, theme);
                    } else {
                        view::map::render(app, &[], p.chart, buf, theme);
                    }
                    view::info::render(app, p.info, buf, theme);
                }
                View::Methods => {
                    view::methods::render_diagram(app, p.chart, buf, theme);
                    view::methods::render_rows(app, p.info, buf, theme);
                }
                View::Charts | View::Fit => {
                    if let Some(chart) = &frame.chart {
                        view::charts::render(chart, p.chart, buf, theme);
                    }
                    if app.view == View::Fit {
                        view::fit::render(app, p.info, buf, theme);
                    } else {
                        view::info::render(app, p.info, buf, theme);
                    }
                }
            }
            view::status::render(app, p.status, p.hints, buf, theme);
            view::popups::render(app, area, buf, theme);
        }
    }
}

/// The screen as plain text, one line per row, trailing blanks trimmed (for
/// `groovelab render` and snapshot tests).
pub fn to_text(app: &App, width: u16, height: u16, theme: &Theme) -> String {
    Screen::default().text(app, width, height, theme).0
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
