//! `track --overlay FILE`: the tracked video's frames read again, each with what was
//! found drawn over it (`vision::overlay`), written as a video (`.mp4`, `.mov`,
//! `.mkv`: encoded by ffmpeg) or as a contact sheet of a few frames (`.png`).

use std::cell::RefCell;
use std::path::Path;

use image::RgbImage;

use super::tracked::{FitsFound, Tracked};
use super::write::{self, Encoding};
use super::{Limits, VideoError, VideoProblem};
use crate::vision::Frame;
use crate::vision::overlay::{self, Drawn};

/// What an overlay file is, by its name's ending.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// A contact sheet PNG.
    Sheet,
    /// A video encoded by ffmpeg.
    Video,
}

/// Frames on a contact sheet, and how many to a row.
const SHEET_FRAMES: usize = 12;
const SHEET_COLUMNS: usize = 4;
const SHEET_TILE_WIDTH: u32 = 480;

/// The kind of overlay `file` asks for, or why it is none.
pub fn kind(file: &Path) -> Result<Kind, VideoError> {
    let ext = file
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase)
        .unwrap_or_default();
    match ext.as_str() {
        "png" => Ok(Kind::Sheet),
        "mp4" | "mov" | "mkv" => Ok(Kind::Video),
        _ => Err(VideoError::new(
            file,
            VideoProblem::OverlayKind { ending: ext },
        )),
    }
}

/// What an overlay draws over the frames: each frame's balls found, in the video's
/// pixels; a pixel grid when the tracking was refused (to read `--roi` and
/// `--ball-at` off the picture); the frame rate known apart from the file's.
pub struct Drawing {
    pub found: FitsFound,
    pub grid: bool,
    /// The tracks' frame rate, or the one given (`--fps`): the frames' times are
    /// written with it (else the container's, else none), and a video overlay plays
    /// at it where the file says none (else 30 frames/s).
    pub rate: Option<f64>,
}

impl Drawing {
    /// The tracked balls (at the tracks' common radius) of `done`.
    pub fn tracked(done: &Tracked) -> Drawing {
        let view = &done.view;
        let found = (0..view.t.len())
            .map(|frame| {
                view.balls
                    .iter()
                    .map(|b| {
                        let c = b.centre.get(frame).copied().flatten()?;
                        Some(Drawn {
                            centre: (f64::from(c.0), f64::from(c.1)),
                            radius: view.radius_px,
                            mark: b
                                .mark
                                .get(frame)
                                .copied()
                                .flatten()
                                .map(|m| (f64::from(m.0), f64::from(m.1))),
                        })
                    })
                    .collect()
            })
            .collect();
        Drawing {
            found,
            grid: false,
            rate: Some(done.fps),
        }
    }

    /// What the tracker found before it refused (each fit at its own radius), over
    /// a pixel grid; `fps` the rate given (`--fps`; a folder says none).
    pub fn refused(found: FitsFound, fps: Option<f64>) -> Drawing {
        Drawing {
            found,
            grid: true,
            rate: fps,
        }
    }
}

/// Reads `video` again and writes `file` with `drawing` over its frames: a video,
/// or a contact sheet of up to 12 frames spread over the clip.
pub fn write_overlay(video: &Path, drawing: &Drawing, file: &Path) -> Result<(), VideoError> {
    let kind = kind(file)?;
    let (info, frames) = super::open(video, &Limits::default())?;
    let failed: RefCell<Option<VideoError>> = RefCell::new(None);
    // On a sheet the grid's labels are drawn as large as the tile shrinks them.
    let shrink = match kind {
        Kind::Sheet => (info.width as u32).div_ceil(SHEET_TILE_WIDTH).max(1),
        Kind::Video => 1,
    };
    let none = Vec::new();
    let rate = drawing.rate.or(info.container_fps);
    let drawn = frames.enumerate().map_while(|(i, frame)| match frame {
        Ok((_, img)) => {
            let mut rgb = to_rgb(&img);
            if drawing.grid {
                overlay::pixel_grid(&mut rgb, shrink);
            }
            overlay::draw(&mut rgb, drawing.found.get(i).unwrap_or(&none));
            overlay::caption(&mut rgb, &overlay::frame_caption(i, rate), shrink);
            Some(rgb)
        }
        Err(e) => {
            *failed.borrow_mut() = Some(e);
            None
        }
    });
    match kind {
        Kind::Sheet => {
            let chosen = overlay::sheet_frames(drawing.found.len(), SHEET_FRAMES);
            let tiles: Vec<RgbImage> = drawn
                .enumerate()
                .filter(|(i, _)| chosen.contains(i))
                .map(|(_, f)| f)
                .collect();
            if let Some(e) = failed.into_inner() {
                return Err(e);
            }
            let sheet = overlay::sheet(&tiles, SHEET_COLUMNS, SHEET_TILE_WIDTH);
            write::png(
                file,
                sheet.as_raw(),
                sheet.width() as usize,
                sheet.height() as usize,
            )
        }
        Kind::Video => {
            let enc = Encoding {
                width: info.width - info.width % 2,
                height: info.height - info.height % 2,
                fps: info.container_fps.or(drawing.rate).unwrap_or(30.0),
                crf: 20,
                metadata: Vec::new(),
            };
            let (w, h) = (enc.width as u32, enc.height as u32);
            // x264 wants even sizes: an odd last column or row is cut.
            let frames = drawn.map(|f| {
                if (f.width(), f.height()) == (w, h) {
                    f.into_raw()
                } else {
                    image::imageops::crop_imm(&f, 0, 0, w, h)
                        .to_image()
                        .into_raw()
                }
            });
            write::video(file, &enc, frames)?;
            match failed.into_inner() {
                Some(e) => Err(e),
                None => Ok(()),
            }
        }
    }
}

/// A decoded frame (yuv420p, BT.601 video range) as RGB, as a player shows it.
fn to_rgb(f: &Frame) -> RgbImage {
    let (w, h) = (f.width(), f.height());
    let mut out = Vec::with_capacity(3 * w * h);
    for y in 0..h {
        for x in 0..w {
            let j = (y / 2) * f.chroma_width + x / 2;
            let l = (f32::from(f.luma.data.get(y * w + x).copied().unwrap_or(16)) - 16.0) * 255.0
                / 219.0;
            let cb = (f32::from(f.u.get(j).copied().unwrap_or(128)) - 128.0) * 255.0 / 224.0;
            let cr = (f32::from(f.v.get(j).copied().unwrap_or(128)) - 128.0) * 255.0 / 224.0;
            for c in [
                l + 1.402 * cr,
                l - 0.344_136 * cb - 0.714_136 * cr,
                l + 1.772 * cb,
            ] {
                out.push(c.round().clamp(0.0, 255.0) as u8);
            }
        }
    }
    // `out` holds exactly 3·w·h values, so `from_raw` always succeeds.
    RgbImage::from_raw(w as u32, h as u32, out).unwrap_or_default()
}
