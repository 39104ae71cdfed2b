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
use super::theme::Theme;
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
                    let (built, thinned) = view::charts::build(app, &mut self.cache, p.chart, theme);
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
            view::render(app, frame, buf, theme);
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
        (view::text_of(&buf), work)
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
