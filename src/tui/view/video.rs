//! The Scene panel's video (`V`, `--data VIDEO`): the frame at the cursor's time in
//! half-blocks (`▀`, the upper pixel's grey in front, the lower's behind; in two
//! tones `▀▄█` without colours; a ramp of ASCII characters in the ASCII glyph set),
//! its tracked centres (+) and marks (x), and the model's balls (o) where the exact
//! solution puts them at that time, in the video's pixels through the scale and the
//! groove's direction the tracker found. The pictures were made while tracking:
//! nothing is decoded here.

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::style::{Color, Style};
use ratatui::text::Line;
use ratatui::widgets::{Paragraph, Widget, Wrap};

use super::panel::{block, title_of};
use crate::tui::app::App;
use crate::tui::theme::Theme;
use crate::vision::thumbs::VideoView;

/// Characters from dark to bright for the ASCII glyph set (none of the marks: + x o).
const RAMP: &[u8] = b" .:-=*#%@";

/// Draws the video panel into `area`.
pub fn render(app: &App, area: Rect, buf: &mut Buffer, theme: &Theme) {
    let name = app.video().name.as_deref().unwrap_or("");
    let Some(view) = app.video().picture().map(|v| &**v) else {
        let what = match app.video().progress() {
            Some((done, total)) => {
                format!("tracking {name}: frame {done} of {total}")
            }
            None => format!("no pictures of {name} (tracking failed, or its cache was lost)"),
        };
        let blk = block(title_of(&[" Video "], area, theme), theme);
        let inner = blk.inner(area);
        blk.render(area, buf);
        if inner.height > 0 {
            let line = theme.glyphs.ellipsize(&what, usize::from(inner.width));
            let y = inner.y + inner.height / 2;
            buf.set_stringn(inner.x, y, line, usize::from(inner.width), theme.dim);
        }
        return;
    };
    if let Some(note) = &view.first_only {
        let tracking = app.video().progress().map(|(done, total)| match total {
            0 => format!("tracking again: frame {done}"),
            _ => format!("tracking again: frame {done} of {total}"),
        });
        render_first_only(view, note, (name, tracking), area, buf, theme);
        return;
    }
    let link = Link::of(app);
    let frame = link.and_then(|l| view.frame_at(l.file_time(app.t)));
    let titles = titles(app, view, frame);
    let legend = Line::styled(
        theme.glyphs.text(" + centre  × mark (tracked)  o model "),
        theme.dim,
    )
    .right_aligned();
    let blk = block(title_of(&titles, area, theme), theme).title_bottom(legend);
    let inner = blk.inner(area);
    blk.render(area, buf);
    if inner.height < 2 || inner.width < 8 {
        return;
    }
    let fit = Fit::new(view, inner);
    let Some(k) = frame else {
        let says = match link {
            Some(_) => "no frame of the video at this time",
            None => "the video's data are not in use (D dropped them): no time to show",
        };
        let line = theme.glyphs.ellipsize(says, usize::from(inner.width));
        buf.set_stringn(
            inner.x,
            inner.y + inner.height / 2,
            line,
            usize::from(inner.width),
            theme.dim,
        );
        return;
    };
    draw_picture(view, k, &fit, buf, theme);
    draw_model(app, view, &fit, buf, theme);
    draw_tracked(view, k, &fit, buf, theme);
}

/// A video's first frame alone, with what the tracker found there, and the text: that
/// a click on a ball seeds the tracking again, and the view's note (why the video was
/// not tracked, or how to go back).
fn render_first_only(
    view: &VideoView,
    note: &str,
    (name, tracking): (&str, Option<String>),
    area: Rect,
    buf: &mut Buffer,
    theme: &Theme,
) {
    let file = crate::tui::layer::main::video::short(name);
    let what = tracking.unwrap_or_else(|| "first frame".into());
    let titles = [
        format!(" Video {file}  {what} "),
        format!(" Video  {what} "),
        " Video  first frame ".to_string(),
        " Video ".to_string(),
    ];
    let legend = Line::styled(theme.glyphs.text(" + found  × mark "), theme.dim).right_aligned();
    let blk = block(title_of(&titles, area, theme), theme).title_bottom(legend);
    let inner = blk.inner(area);
    blk.render(area, buf);
    if inner.height < 2 || inner.width < 8 {
        return;
    }
    let fit = Fit::new(view, picture_rect(view, inner));
    draw_picture(view, 0, &fit, buf, theme);
    draw_tracked(view, 0, &fit, buf, theme);
    if let Some(text) = text_rect(view, inner) {
        let lines = vec![
            Line::styled("Click a ball to track the video from it.", theme.text),
            Line::styled(note.to_string(), theme.dim),
        ];
        Paragraph::new(lines)
            .wrap(Wrap { trim: true })
            .render(text, buf);
    }
}

/// The columns of a first frame shown alone, beside its note, in the panel's
/// `inner` area: as wide as the frame's aspect wants at the panel's height, at most
/// half the panel (none in a panel too narrow for text beside it).
fn first_only_columns(view: &VideoView, inner: Rect) -> Option<u16> {
    if inner.width < 30 {
        return None;
    }
    let (vw, vh) = (
        view.thumbs.video.0 as f64,
        view.thumbs.video.1.max(1) as f64,
    );
    let wanted = (2.0 * f64::from(inner.height) * vw / vh).ceil();
    Some((wanted.min(f64::from(inner.width / 2)) as u16).max(8))
}

/// Where the picture goes in the panel's `inner` area: all of it, but for a first frame
/// shown alone its left part ([`first_only_columns`]).
pub(super) fn picture_rect(view: &VideoView, inner: Rect) -> Rect {
    match view
        .first_only
        .as_ref()
        .and(first_only_columns(view, inner))
    {
        Some(width) => Rect { width, ..inner },
        None => inner,
    }
}

/// Where the note goes beside a first frame shown alone, if anywhere.
fn text_rect(view: &VideoView, inner: Rect) -> Option<Rect> {
    let width = first_only_columns(view, inner)?;
    Some(Rect {
        x: inner.x + width + 1,
        width: inner.width - width - 1,
        ..inner
    })
}

/// The panel's titles, longest first.
fn titles(app: &App, view: &VideoView, frame: Option<usize>) -> Vec<String> {
    let name = app.video().name.as_deref().unwrap_or("");
    let file = std::path::Path::new(name)
        .file_name()
        .map_or(name.into(), |f| f.to_string_lossy().into_owned());
    let n = view.t.len();
    let at = frame.map_or("no frame".to_string(), |k| {
        format!("frame {} of {n}", k + 1)
    });
    vec![
        format!(" Video {file}  t = {:.3} s  {at} ", app.t),
        format!(" Video  t = {:.3} s  {at} ", app.t),
        format!(" Video  t = {:.3} s ", app.t),
        " Video ".to_string(),
    ]
}

/// How the lab's time and the model's x are the video's: from what the derivation
/// found in the video's own track (its first impact's time and place, and which way
/// the other ball lies).
#[derive(Clone, Copy)]
struct Link {
    impact_t: f64,
    impact_x: f64,
    direction: f64,
    /// False for a video whose tracks no fit can use (no impact in the clip): the
    /// lab's time is the video's own, and no model ball is drawn on it (nothing
    /// places the model in its picture).
    aligned: bool,
}

impl Link {
    /// The link while the data in use are this video's.
    fn of(app: &App) -> Option<Link> {
        let video = app.video().name.as_deref();
        let Some(own) = app.lab.own_data() else {
            let unfit = app.lab.unfit()?;
            return (Some(unfit.name.as_str()) == video).then_some(Link {
                impact_t: 0.0,
                impact_x: 0.0,
                direction: 1.0,
                aligned: false,
            });
        };
        if Some(own.name.as_str()) != video {
            return None;
        }
        let f = app.lab.series()?.found()?;
        Some(Link {
            impact_t: f.impact_t,
            impact_x: f.impact_x,
            direction: f.direction,
            aligned: true,
        })
    }

    /// The video's time (s from its first frame) of the lab's time `t`.
    fn file_time(&self, t: f64) -> f64 {
        self.impact_t + t
    }

    /// The video track's x (m) of a model ball's centre at `x` (the left ball touches
    /// the right at x = 0, its centre at −R: the track's x is the left centre's
    /// displacement from its place at the impact).
    fn file_x(&self, x: f64, radius: f64) -> f64 {
        self.impact_x + self.direction * (x + radius)
    }
}

/// Where the picture goes in the panel: the band of the video about the groove (the
/// balls' rows: a panel is wide and low) to cells, the aspect kept (a cell is two
/// half-block pixels tall).
struct Fit {
    /// Cells across per video pixel (half-block rows down: the same).
    k: f64,
    /// The band's top, video px (its left is the video's).
    top: f64,
    x0: f64,
    y0: f64,
    cols: u16,
    rows: u16,
    area: Rect,
}

impl Fit {
    fn new(view: &VideoView, area: Rect) -> Fit {
        let vw = view.thumbs.video.0 as f64;
        let (top, bottom) = band(view);
        let (w, h) = (f64::from(area.width), f64::from(area.height));
        let k = (w / vw).min(2.0 * h / (bottom - top));
        let (cols, rows) = ((vw * k).floor(), ((bottom - top) * k / 2.0).floor());
        Fit {
            k,
            top,
            x0: ((w - cols) / 2.0).floor(),
            y0: ((h - rows) / 2.0).floor(),
            cols: cols as u16,
            rows: rows as u16,
            area,
        }
    }

    /// The video's pixel at the middle of the picture's half-cell (`col`, `half_row`).
    fn pixel(&self, col: f64, half_row: f64) -> (f64, f64) {
        ((col + 0.5) / self.k, self.top + (half_row + 0.5) / self.k)
    }

    /// The video's pixel at the middle of the terminal cell (`column`, `row`), if the
    /// picture covers it (the inverse of [`Fit::cell`]).
    fn pixel_of_cell(&self, column: u16, row: u16) -> Option<(f64, f64)> {
        let c = f64::from(column) - f64::from(self.area.x) - self.x0;
        let r = f64::from(row) - f64::from(self.area.y) - self.y0;
        let inside = c >= 0.0 && r >= 0.0 && c < f64::from(self.cols) && r < f64::from(self.rows);
        // The cell's two half-block pixel rows meet at its middle.
        inside.then(|| self.pixel(c, 2.0 * r + 0.5))
    }

    /// The cell of the video's pixel `(x, y)`, if inside the picture.
    fn cell(&self, (x, y): (f64, f64)) -> Option<(u16, u16)> {
        let c = x * self.k;
        let r = (y - self.top) * self.k / 2.0;
        let inside = c >= 0.0 && r >= 0.0 && c < f64::from(self.cols) && r < f64::from(self.rows);
        inside.then(|| {
            (
                self.area.x + (self.x0 + c) as u16,
                self.area.y + (self.y0 + r) as u16,
            )
        })
    }
}

/// The video's pixel under the cell (`column`, `row`) of a Scene panel drawn in
/// `area` showing `view` (a click on a ball seeds the tracker there): `None` off the
/// picture. The graphics protocols place the same band about the groove, scaled to the
/// panel and centred, so this holds for their pictures too, to within a cell.
pub fn pixel_at(view: &VideoView, area: Rect, column: u16, row: u16) -> Option<(f64, f64)> {
    let inner = ratatui::widgets::Block::bordered().inner(area);
    if inner.height < 2 || inner.width < 8 {
        return None;
    }
    Fit::new(view, picture_rect(view, inner)).pixel_of_cell(column, row)
}

/// The cell of the Scene panel drawn in `area` showing `view` where the video's pixel
/// `(x, y)` is drawn, if inside the picture.
pub fn cell_at(view: &VideoView, area: Rect, (x, y): (f64, f64)) -> Option<(u16, u16)> {
    let inner = ratatui::widgets::Block::bordered().inner(area);
    Fit::new(view, picture_rect(view, inner)).cell((x, y))
}

/// The video's rows about the groove, px: from three radii above its line (at both
/// edges of the picture: a tilted phone) to two and a half below (the rail); the
/// whole height when the radius is not known.
pub(super) fn band(view: &VideoView) -> (f64, f64) {
    let (vw, vh) = (view.thumbs.video.0 as f64, view.thumbs.video.1 as f64);
    let r = view.radius_px;
    if !(r.is_finite() && r > 0.0 && view.origin.1.is_finite()) {
        return (0.0, vh);
    }
    let line = |x: f64| view.origin.1 + (x - view.origin.0) * view.groove.tan();
    let (a, b) = (line(0.0), line(vw));
    let top = (a.min(b) - 3.0 * r).clamp(0.0, vh - 1.0);
    let bottom = (a.max(b) + 2.5 * r).clamp(top + 1.0, vh);
    (top, bottom)
}

/// The picture of frame `k`.
fn draw_picture(view: &VideoView, k: usize, fit: &Fit, buf: &mut Buffer, theme: &Theme) {
    let Some(pic) = view.thumbs.picture(k) else {
        return;
    };
    let t = &view.thumbs;
    let (sx, sy) = (
        t.width as f64 / t.video.0 as f64,
        t.height as f64 / t.video.1 as f64,
    );
    // The picture's pixel at the video's pixel (x, y).
    let at = |x: f64, y: f64| -> u8 {
        let tx = ((x * sx) as usize).min(t.width - 1);
        let ty = ((y * sy) as usize).min(t.height - 1);
        pic[ty * t.width + tx]
    };
    let [dark, mid, bright] = view.levels;
    let span = f64::from(bright.saturating_sub(dark).max(1));
    for r in 0..fit.rows {
        for c in 0..fit.cols {
            let (x, y0) = fit.pixel(f64::from(c), 2.0 * f64::from(r));
            let (_, y1) = fit.pixel(f64::from(c), 2.0 * f64::from(r) + 1.0);
            let (top, bottom) = (at(x, y0), at(x, y1));
            let grey = |v: u8| Color::Rgb(v, v, v);
            let (glyph, style): (String, Style) = if theme.glyphs.ascii {
                let v = (f64::from(top) + f64::from(bottom)) / 2.0;
                let i = ((v - f64::from(dark)) / span * (RAMP.len() - 1) as f64).round();
                let ch = RAMP[i.clamp(0.0, (RAMP.len() - 1) as f64) as usize];
                let style = if theme.monochrome {
                    theme.text
                } else {
                    Style::default().fg(grey(v as u8))
                };
                (char::from(ch).to_string(), style)
            } else if theme.monochrome {
                let glyph = match (top > mid, bottom > mid) {
                    (false, false) => " ",
                    (true, false) => "▀",
                    (false, true) => "▄",
                    (true, true) => "█",
                };
                (glyph.to_string(), theme.text)
            } else {
                let style = Style::default().fg(grey(top)).bg(grey(bottom));
                ("▀".to_string(), style)
            };
            let (cx, cy) = (
                fit.area.x + fit.x0 as u16 + c,
                fit.area.y + fit.y0 as u16 + r,
            );
            buf.set_string(cx, cy, glyph, style);
        }
    }
}

/// The model's ball centres at the cursor's time in the video's pixels (left, right),
/// while the data in use are the video's.
pub fn model_centres(app: &App, view: &VideoView) -> Option<[(f64, f64); 2]> {
    let l = Link::of(app).filter(|l| l.aligned)?;
    let snap = app.lab.solution.at(app.t);
    let radius = app.lab.scene.radius;
    Some([snap.left.x, snap.right.x].map(|x| view.pixel(l.file_x(x, radius), 0.0)))
}

/// The index of the frame shown at the cursor's time, while the data in use are the
/// video's.
pub fn shown_frame(app: &App, view: &VideoView) -> Option<usize> {
    if view.first_only.is_some() {
        return Some(0);
    }
    Link::of(app).and_then(|l| view.frame_at(l.file_time(app.t)))
}

/// The lab's time of the video's frame `k`, while the data in use are the video's.
pub fn frame_time(app: &App, view: &VideoView, k: usize) -> Option<f64> {
    let l = Link::of(app)?;
    Some(view.t.get(k)? - l.impact_t)
}

/// The model's balls at the cursor's time: rings of the scene's R.
fn draw_model(app: &App, view: &VideoView, fit: &Fit, buf: &mut Buffer, theme: &Theme) {
    let Some(centres) = model_centres(app, view) else {
        return;
    };
    // Half a cell outside the ball's edge, so that a small ball stays seen inside.
    let r_px = app.lab.scene.radius * view.px_per_m + 0.5 / fit.k;
    // A dot per cell of the ring, about.
    let n = ((std::f64::consts::TAU * r_px * fit.k).ceil() as usize).clamp(8, 720);
    for (centre, style) in centres.into_iter().zip([theme.left, theme.right]) {
        for i in 0..n {
            let a = i as f64 / n as f64 * std::f64::consts::TAU;
            let p = (centre.0 + r_px * a.cos(), centre.1 + r_px * a.sin());
            if let Some((cx, cy)) = fit.cell(p) {
                buf.set_string(cx, cy, "o", style);
            }
        }
    }
}

/// The tracked centres (+) and marks (×) of frame `k`.
fn draw_tracked(view: &VideoView, k: usize, fit: &Fit, buf: &mut Buffer, theme: &Theme) {
    let mark = if theme.glyphs.ascii { "x" } else { "×" };
    for b in &view.balls {
        // The centre last: where both fall in one cell it is the one shown.
        let points = [(b.mark.get(k), mark), (b.centre.get(k), "+")];
        for (p, glyph) in points {
            if let Some(Some((x, y))) = p
                && let Some((cx, cy)) = fit.cell((f64::from(*x), f64::from(*y)))
            {
                buf.set_string(cx, cy, glyph, theme.measured);
            }
        }
    }
}
