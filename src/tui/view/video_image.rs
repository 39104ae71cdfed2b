//! The video panel (`V`) as a real picture where the terminal has a graphics protocol
//! (kitty, sixel, iTerm2, through `ratatui-image`): the frame at the cursor's time with
//! the tracked centres (+) and marks (×) and the model's balls (rings) drawn into its
//! pixels (text cannot lie over a graphic). The protocol is chosen once at startup
//! ([`detect`]); `GROOVELAB_GRAPHICS=off` keeps the half-blocks. The encoded picture
//! is kept here, in the screen's video state, and made anew, on a worker (a sixel takes
//! tens of milliseconds), only when what it shows (the frame, the marks' pixels, the
//! panel's size) changes; headless drawing and the tests never have a picker, so they
//! draw half-blocks only.

use std::sync::mpsc::{self, Receiver, Sender};
use std::sync::{Arc, Mutex};
use std::time::Duration;

use image::{DynamicImage, Rgb, RgbImage};
use ratatui::buffer::Buffer;
use ratatui::layout::{Rect, Size};
use ratatui::style::Style;
use ratatui::widgets::{Block, Clear, Widget};
use ratatui_image::picker::cap_parser::QueryStdioOptions;
use ratatui_image::picker::{Picker, ProtocolType};
use ratatui_image::protocol::Protocol;
use ratatui_image::{Image, Resize};

use super::video::{band, model_centres, picture_rect, shown_frame};
use crate::tui::app::App;
use crate::tui::theme::Theme;
use crate::vision::thumbs::VideoView;

/// The environment variable that chooses the graphics: `off`, `auto` (the default) or
/// a protocol forced (`kitty`, `sixel`, `iterm2`).
pub const SWITCH: &str = "GROOVELAB_GRAPHICS";

/// How long startup waits for the terminal to answer the query.
const QUERY_TIMEOUT: Duration = Duration::from_millis(800);

/// The largest picture sent, px (long side): a bigger panel gets it scaled up by the
/// terminal, never a slower encoding.
const MAX_SIDE: u32 = 640;

/// What `GROOVELAB_GRAPHICS` asks for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Switch {
    Auto,
    Off,
    Force(ProtocolType),
}

/// A `GROOVELAB_GRAPHICS` value that is none of the allowed ones.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("{SWITCH}={value:?}: expected off, auto, kitty, sixel or iterm2")]
pub struct BadSwitch {
    value: String,
}

impl Switch {
    /// The switch of the variable's value (unset: auto).
    pub fn parse(value: Option<&str>) -> Result<Switch, BadSwitch> {
        Ok(match value.map(str::trim) {
            None | Some("" | "auto") => Switch::Auto,
            Some("off" | "0" | "no" | "halfblocks") => Switch::Off,
            Some("kitty") => Switch::Force(ProtocolType::Kitty),
            Some("sixel") => Switch::Force(ProtocolType::Sixel),
            Some("iterm2") => Switch::Force(ProtocolType::Iterm2),
            Some(v) => {
                return Err(BadSwitch {
                    value: v.to_string(),
                });
            }
        })
    }

    /// The switch from the environment.
    pub fn from_env() -> Result<Switch, BadSwitch> {
        Switch::parse(std::env::var(SWITCH).ok().as_deref())
    }

    /// Whether to ask the terminal at all: not when off, nor by default inside tmux or
    /// screen (they pass graphics on only when set to, and a query wrapped for the
    /// terminal outside that nobody answers would take the app's first key).
    pub fn queries(self, multiplexed: bool) -> bool {
        match self {
            Switch::Off => false,
            Switch::Auto => !multiplexed,
            Switch::Force(_) => true,
        }
    }

    /// The protocol to draw with, given what the terminal answered; `None`: half-blocks.
    pub fn choose(self, detected: ProtocolType) -> Option<ProtocolType> {
        let p = match self {
            Switch::Off => return None,
            Switch::Auto => detected,
            Switch::Force(p) => p,
        };
        (p != ProtocolType::Halfblocks).then_some(p)
    }
}

/// Asks the real terminal (once, before the event loop; at most [`QUERY_TIMEOUT`]) what
/// it can draw; `None` when it has no graphics protocol or the switch is off.
pub fn detect(switch: Switch) -> Option<Picker> {
    let multiplexed = ["TMUX", "STY"]
        .iter()
        .any(|v| std::env::var_os(v).is_some())
        || std::env::var("TERM").is_ok_and(|t| t.starts_with("tmux") || t.starts_with("screen"));
    if !switch.queries(multiplexed) {
        return None;
    }
    let options = QueryStdioOptions {
        timeout: QUERY_TIMEOUT,
        ..QueryStdioOptions::default()
    };
    let mut picker = Picker::from_query_stdio_with_options(options).ok()?;
    let p = switch.choose(picker.protocol_type())?;
    picker.set_protocol_type(p);
    Some(picker)
}

/// What a picture shows: when it is equal, the encoded picture is reused.
#[derive(Clone, Debug, PartialEq)]
struct PictureKey {
    frame: usize,
    area: Rect,
    size: (u32, u32),
    /// The model's ball centres, px of the picture (they move between frames).
    model: Option<[(i64, i64); 2]>,
}

/// A picture to make: frame, marks, size.
struct PictureJob {
    key: PictureKey,
    view: Arc<VideoView>,
    marks: Marks,
}

/// The thread that draws and encodes pictures (a sixel takes tens of milliseconds or
/// more: never on the key's path). It takes the newest job waiting, and tells the
/// event loop (`wake`) when a picture is ready.
struct Worker {
    jobs: Sender<PictureJob>,
    done: Mutex<Receiver<(PictureKey, Protocol)>>,
}

impl Worker {
    fn start(picker: Picker, wake: Box<dyn Fn() + Send>) -> Option<Worker> {
        let (jobs, inbox) = mpsc::channel::<PictureJob>();
        let (outbox, done) = mpsc::channel();
        std::thread::Builder::new()
            .name("groovelab-video-picture".into())
            .spawn(move || {
                while let Ok(first) = inbox.recv() {
                    let job = inbox.try_iter().last().unwrap_or(first);
                    let img = picture(&job.view, job.key.frame, job.key.size, &job.marks);
                    let size = Size::new(job.key.area.width, job.key.area.height);
                    let image = DynamicImage::ImageRgb8(img);
                    let Ok(p) = picker.new_protocol(image, size, Resize::Fit(None)) else {
                        continue;
                    };
                    if outbox.send((job.key, p)).is_err() {
                        break;
                    }
                    wake();
                }
            })
            .ok()?;
        Some(Worker {
            jobs,
            done: Mutex::new(done),
        })
    }
}

/// The screen's video state: the terminal's picker (`None`: half-blocks), the worker
/// that encodes, the picture asked for last and the one encoded last (shown until
/// the next is ready, if of the same panel).
#[derive(Clone, Default)]
pub struct VideoImage {
    picker: Option<Picker>,
    worker: Option<Arc<Worker>>,
    asked: Option<PictureKey>,
    shown: Option<(PictureKey, Protocol)>,
    /// Shown only while the panel shows the video.
    on: bool,
    /// How many pictures were asked for (to check that a redraw asks for none).
    pub encoded: usize,
}

impl std::fmt::Debug for VideoImage {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("VideoImage")
            .field("protocol", &self.picker.as_ref().map(Picker::protocol_type))
            .field("asked", &self.asked)
            .field("shown", &self.shown.as_ref().map(|s| &s.0))
            .field("encoded", &self.encoded)
            .finish()
    }
}

impl VideoImage {
    /// Drawing with `picker`'s protocol, on a worker that calls `wake` when a picture
    /// is ready (the screen is to be drawn again).
    pub fn new(picker: Option<Picker>, wake: Box<dyn Fn() + Send>) -> VideoImage {
        let worker = picker
            .clone()
            .and_then(|p| Worker::start(p, wake))
            .map(Arc::new);
        VideoImage {
            worker,
            picker,
            ..VideoImage::default()
        }
    }

    /// Asks the worker for the picture the video panel in `scene` shows now, unless
    /// it was asked for last; takes the pictures it finished.
    pub fn prepare(&mut self, app: &App, scene: Option<Rect>, theme: &Theme) {
        let (Some(picker), Some(worker)) = (&self.picker, &self.worker) else {
            return;
        };
        if let Ok(done) = worker.done.lock()
            && let Some(last) = done.try_iter().last()
        {
            self.shown = Some(last);
        }
        let wanted = scene.and_then(|s| wanted(app, s, picker));
        self.on = wanted.is_some();
        let Some((key, view)) = wanted else {
            return;
        };
        // The picture of another panel's size is not shown meanwhile.
        if self.shown.as_ref().is_some_and(|(k, _)| k.area != key.area) {
            self.shown = None;
        }
        if self.asked.as_ref() == Some(&key) {
            return;
        }
        let centres = model_centres(app, view);
        let ring = app.lab.scene.radius * view.px_per_m;
        let job = PictureJob {
            key: key.clone(),
            view: Arc::clone(view),
            marks: Marks::of(theme, centres, ring),
        };
        if worker.jobs.send(job).is_ok() {
            self.encoded += 1;
            self.asked = Some(key);
        }
    }

    /// Draws the picture encoded last over the video panel's half-blocks.
    pub fn render(&self, buf: &mut Buffer) {
        let Some((key, protocol)) = self.shown.as_ref().filter(|_| self.on) else {
            return;
        };
        Clear.render(key.area, buf);
        let s = protocol.size();
        let (w, h) = (s.width.min(key.area.width), s.height.min(key.area.height));
        let at = Rect::new(
            key.area.x + (key.area.width - w) / 2,
            key.area.y + (key.area.height - h) / 2,
            w,
            h,
        );
        Image::new(protocol).render(at, buf);
    }
}

/// The key of the picture wanted in the video panel of `scene`, and the video.
fn wanted<'a>(
    app: &'a App,
    scene: Rect,
    picker: &Picker,
) -> Option<(PictureKey, &'a Arc<VideoView>)> {
    if !app.video().shown {
        return None;
    }
    let view = app.video().picture()?;
    let inner = Block::bordered().inner(scene);
    if inner.height < 2 || inner.width < 8 {
        return None;
    }
    let area = picture_rect(view, inner);
    let frame = shown_frame(app, view)?;
    let font = picker.font_size();
    let size = fitted(view, area, (u32::from(font.width), u32::from(font.height)));
    let fit = PixelFit::new(view, size);
    let model = model_centres(app, view).map(|c| {
        c.map(|p| fit.at(p))
            .map(|(x, y)| (x.round() as i64, y.round() as i64))
    });
    let key = PictureKey {
        frame,
        area,
        size,
        model,
    };
    Some((key, view))
}

/// The picture's size, px: the band about the groove (its aspect kept) as large as the
/// panel's `area` is at the terminal's `font` size, at most [`MAX_SIDE`].
fn fitted(view: &VideoView, area: Rect, font: (u32, u32)) -> (u32, u32) {
    let (top, bottom) = band(view);
    let (vw, vh) = (view.thumbs.video.0 as f64, bottom - top);
    let (w, h) = (
        f64::from(u32::from(area.width) * font.0.max(1)),
        f64::from(u32::from(area.height) * font.1.max(1)),
    );
    let k = (w / vw).min(h / vh).min(f64::from(MAX_SIDE) / vw.max(vh));
    (
        ((vw * k).floor() as u32).max(1),
        ((vh * k).floor() as u32).max(1),
    )
}

/// The video's pixels to the picture's: the band about the groove, scaled.
struct PixelFit {
    k: f64,
    top: f64,
}

impl PixelFit {
    fn new(view: &VideoView, size: (u32, u32)) -> PixelFit {
        let (top, _) = band(view);
        PixelFit {
            k: f64::from(size.0) / view.thumbs.video.0 as f64,
            top,
        }
    }

    /// The picture's pixel of the video's pixel `(x, y)`.
    fn at(&self, (x, y): (f64, f64)) -> (f64, f64) {
        (x * self.k, (y - self.top) * self.k)
    }
}

/// What is drawn over the frame, and in which colours.
struct Marks {
    model: Option<[(f64, f64); 2]>,
    /// The model's balls' radius, video px.
    ring: f64,
    left: Rgb<u8>,
    right: Rgb<u8>,
    tracked: Rgb<u8>,
}

impl Marks {
    fn of(theme: &Theme, model: Option<[(f64, f64); 2]>, ring: f64) -> Marks {
        // Drawn on the video's pixels, not on the terminal's background: the dark
        // palette's light colours whatever the terminal's theme (none under NO_COLOR).
        let bright = Theme::new(theme.glyphs, theme.monochrome);
        let theme = &bright;
        Marks {
            model,
            ring,
            left: rgb(theme.left, [80, 160, 255]),
            right: rgb(theme.right, [255, 160, 60]),
            tracked: rgb(theme.measured, [80, 255, 80]),
        }
    }
}

/// A style's colour as RGB (`or` when it has none the picture can use): xterm's RGB
/// of the theme's colour.
fn rgb(style: Style, or: [u8; 3]) -> Rgb<u8> {
    Rgb(style
        .fg
        .and_then(crate::tui::theme::xterm_rgb)
        .unwrap_or(or))
}

/// Frame `k` of `view` at `size` px (the band about the groove), with `marks` drawn in.
fn picture(view: &VideoView, k: usize, size: (u32, u32), marks: &Marks) -> RgbImage {
    let fit = PixelFit::new(view, size);
    let t = &view.thumbs;
    let mut img = RgbImage::new(size.0, size.1);
    if let Some(pic) = t.picture(k) {
        let (sx, sy) = (
            t.width as f64 / t.video.0 as f64,
            t.height as f64 / t.video.1 as f64,
        );
        for (px, py, p) in img.enumerate_pixels_mut() {
            let x = (f64::from(px) + 0.5) / fit.k;
            let y = fit.top + (f64::from(py) + 0.5) / fit.k;
            let tx = ((x * sx) as usize).min(t.width - 1);
            let ty = ((y * sy) as usize).min(t.height - 1);
            let v = pic[ty * t.width + tx];
            *p = Rgb([v, v, v]);
        }
    }
    if let Some(centres) = marks.model {
        let r = marks.ring * fit.k;
        for (c, colour) in centres.into_iter().zip([marks.left, marks.right]) {
            ring(&mut img, fit.at(c), r, colour);
        }
    }
    let arm = (size.0.max(size.1) / 120).max(2) as i64;
    for b in &view.balls {
        let points = [(b.centre.get(k), false), (b.mark.get(k), true)];
        for (p, diagonal) in points {
            if let Some(Some((x, y))) = p {
                let (cx, cy) = fit.at((f64::from(*x), f64::from(*y)));
                cross(
                    &mut img,
                    (cx as i64, cy as i64),
                    arm,
                    diagonal,
                    marks.tracked,
                );
            }
        }
    }
    img
}

/// Sets pixel `(x, y)` if inside.
fn put(img: &mut RgbImage, (x, y): (i64, i64), colour: Rgb<u8>) {
    if x >= 0 && y >= 0 && x < i64::from(img.width()) && y < i64::from(img.height()) {
        img.put_pixel(x as u32, y as u32, colour);
    }
}

/// A ring of radius `r` px about `c`, two pixels thick (outside the ball's edge).
fn ring(img: &mut RgbImage, c: (f64, f64), r: f64, colour: Rgb<u8>) {
    let n = ((std::f64::consts::TAU * (r + 2.0)).ceil() as usize * 2).clamp(16, 20_000);
    for i in 0..n {
        let a = i as f64 / n as f64 * std::f64::consts::TAU;
        for d in [0.5, 1.5] {
            let p = (c.0 + (r + d) * a.cos(), c.1 + (r + d) * a.sin());
            put(img, (p.0.floor() as i64, p.1.floor() as i64), colour);
        }
    }
}

/// A cross (+, or × when `diagonal`) of arms `arm` px at `c`.
fn cross(img: &mut RgbImage, c: (i64, i64), arm: i64, diagonal: bool, colour: Rgb<u8>) {
    for d in -arm..=arm {
        let (a, b) = if diagonal {
            ((d, d), (d, -d))
        } else {
            ((d, 0), (0, d))
        };
        put(img, (c.0 + a.0, c.1 + a.1), colour);
        put(img, (c.0 + b.0, c.1 + b.1), colour);
    }
}

#[cfg(test)]
#[path = "video_image_tests.rs"]
mod tests;
