//! The screen: one frame laid out once, then drawn. [`Screen::prepare`] computes the
//! layout and everything the frame draws that depends on the terminal's size (the
//! chart built, the regime grid, how far a popup scrolls), keeping what depends only
//! on the snapshot and the size in its [`ViewCache`]; drawing then only reads, and
//! mouse hit-testing reads the same layout. The terminal's runner and the headless
//! `render` both hold one, so a script sees exactly what a user sees.

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;

use super::app::App;
use super::component::{Component, Ctx, Laid, Place, Prepared};
use super::layer::Layer;
use super::layer::main::Pointer;
use super::theme::{Theme, force_ascii};
use super::view;
use super::view::video_image::VideoImage;
use super::view_cache::ViewCache;

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
    frame: Option<Laid>,
    /// The video panel's picture in a graphics protocol (none headless).
    video: VideoImage,
}

impl Screen {
    /// A screen whose video panel draws pictures with `picker`'s graphics protocol,
    /// made on a worker that calls `wake` when one is ready.
    pub fn with_graphics(
        picker: Option<ratatui_image::picker::Picker>,
        wake: Box<dyn Fn() + Send>,
    ) -> Screen {
        Screen {
            video: VideoImage::new(picker, wake),
            ..Screen::default()
        }
    }

    /// Lays out the frame of `app` on `area`: the one layout, the chart and the grid
    /// of the view shown, a popup's scroll limit; what only a new snapshot or size
    /// changes is taken from the cache.
    pub fn prepare(&mut self, app: &App, area: Rect, theme: &Theme) -> Work {
        let panels = view::layout(area);
        let mut work = Work::default();
        // The view shown prepares its own: the chart, the regime grid.
        let prepared = panels.map_or_else(Prepared::default, |p| {
            view::shown(app).prepare(app, &mut self.cache, p.chart, theme)
        });
        work.marks_thinned += usize::from(prepared.marks_thinned);
        let Prepared { chart, regimes, .. } = prepared;
        // A popup lies over the panels: no graphic then (text cannot cover it).
        let scene = panels.filter(|_| !app.layers().covers());
        self.video.prepare(app, scene.map(|p| p.scene), theme);
        self.frame = Some(Laid {
            area,
            panels,
            chart,
            regimes,
            scroll_max: view::scroll_max(app, area, theme),
        });
        work
    }

    /// How many pictures of the video panel were asked of the graphics worker.
    pub fn video_pictures(&self) -> usize {
        self.video.encoded
    }

    /// The frame prepared last, if any.
    pub fn frame(&self) -> Option<&Laid> {
        self.frame.as_ref()
    }

    /// Draws the frame prepared last into `buf` (its area), changing nothing.
    pub fn render(&self, app: &App, buf: &mut Buffer, theme: &Theme) {
        if let Some(frame) = &self.frame {
            render(app, frame, buf, theme);
            self.video.render(buf);
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

    /// What lies under the mouse at (`column`, `row`) of the frame prepared last: the
    /// chart's time, the video's pixel (while the Scene panel shows its picture).
    pub fn pointer_at(&self, app: &App, column: u16, row: u16) -> Pointer {
        let picture = (|| {
            let video = app.video();
            let scene = self.frame.as_ref()?.panels?.scene;
            if !video.shown || !app.layers().is_empty() {
                return None;
            }
            let view = video.picture()?;
            let pixel = view::video::pixel_at(view, scene, column, row)?;
            Some((pixel, view::video::shown_frame(app, view)))
        })();
        Pointer {
            time: self.chart_time_at(app, column, row),
            pixel: picture.map(|p| p.0),
            frame: picture.and_then(|p| p.1),
        }
    }

    /// The time under a click at (`column`, `row`) of the frame prepared last: inside
    /// the chart's plot while the view shown drew one (it prepared it: Charts, Fit) and
    /// no popup is open.
    pub fn chart_time_at(&self, app: &App, column: u16, row: u16) -> Option<f64> {
        if !app.layers().is_empty() {
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
fn render(app: &App, frame: &Laid, buf: &mut Buffer, theme: &Theme) {
    draw_panels(app, frame, buf, theme);
    stand_ins(buf, theme);
}

/// In ASCII mode, a stand-in for any symbol outside 7-bit ASCII.
fn stand_ins(buf: &mut Buffer, theme: &Theme) {
    if theme.glyphs.ascii {
        force_ascii(buf);
    }
}

/// A new frame of `width` × `height` of `app`, drawn without the ASCII stand-ins
/// (what the two functions below look at).
fn drawn_bare(app: &App, width: u16, height: u16, theme: &Theme) -> Buffer {
    let area = Rect::new(0, 0, width, height);
    let mut buf = Buffer::empty(area);
    let mut screen = Screen::default();
    screen.prepare(app, area, theme);
    if let Some(frame) = screen.frame() {
        draw_panels(app, frame, &mut buf, theme);
    }
    buf
}

/// The cells of an ASCII screen that would have needed a stand-in: `(x, y, symbol)`.
pub fn non_ascii_cells(
    app: &App,
    width: u16,
    height: u16,
    theme: &Theme,
) -> Vec<(u16, u16, String)> {
    non_ascii(&drawn_bare(app, width, height, theme))
}

/// [`to_text`] and [`non_ascii_cells`] of one drawing (a test of every screen draws
/// each once).
pub fn to_text_and_non_ascii_cells(
    app: &App,
    width: u16,
    height: u16,
    theme: &Theme,
) -> (String, Vec<(u16, u16, String)>) {
    let mut buf = drawn_bare(app, width, height, theme);
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

/// The component of a popup open (every layer draws itself: a new popup is a new
/// arm here, which the compiler asks for).
fn component_of(layer: &Layer) -> &dyn Component {
    match layer {
        Layer::Help(help) => help,
        Layer::Table(table) => table,
        Layer::Models(models) => models,
        Layer::Picker(picker) => picker,
        Layer::Prompt(prompt) => prompt,
        Layer::Confirm(confirm) => confirm,
        Layer::Question(question) => question,
    }
}

/// The compositor: the panels, the view shown, the status bar, then the popups open
/// as layers over them, bottom first.
fn draw_panels(app: &App, frame: &Laid, buf: &mut Buffer, theme: &Theme) {
    let area = frame.area;
    let Some(p) = frame.panels else {
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
        return;
    };
    let cx = Ctx { app, frame, theme };
    view::params::ParamsPanel.render(p.params, buf, &cx);
    view::scene::ScenePanel.render(p.scene, buf, &cx);
    for (part, place) in view::shown(app).parts(app) {
        let at = match place {
            Place::Chart => p.chart,
            Place::Side => p.info,
            Place::Middle => p.chart.union(p.info),
        };
        part.render(at, buf, &cx);
    }
    view::status::StatusBar.render(p.status.union(p.hints), buf, &cx);
    for layer in app.layers().iter() {
        component_of(layer).render(area, buf, &cx);
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
