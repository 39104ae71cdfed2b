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
/// Each byte's terms come from [`BT601`]'s tables in 16-bit fixed point: no
/// division, library call or branch per pixel (by floats, the conversion was
/// two-fifths of `--overlay`'s time on a 1080p clip).
#[allow(clippy::indexing_slicing)] // a byte indexes a table of 256
fn to_rgb(f: &Frame) -> RgbImage {
    let t = &*BT601;
    let (w, h, cw) = (f.width(), f.height(), f.chroma_width);
    let mut out = vec![0; 3 * w * h];
    // A frame of no width has no rows (and a chunk of none would panic).
    let rows = out
        .chunks_exact_mut((3 * w).max(1))
        .zip(f.luma.data.chunks_exact(w.max(1)));
    for (y, (row, luma)) in rows.enumerate() {
        let span = (y / 2) * cw..(y / 2 + 1) * cw;
        let us = f.u.get(span.clone()).unwrap_or(&[]);
        let vs = f.v.get(span).unwrap_or(&[]);
        for (x, (px, &l)) in row.chunks_exact_mut(3).zip(luma).enumerate() {
            let l = t.luma[usize::from(l)];
            let cb = usize::from(us.get(x / 2).copied().unwrap_or(128));
            let cr = usize::from(vs.get(x / 2).copied().unwrap_or(128));
            px.copy_from_slice(&[
                level(l + t.r_cr[cr]),
                level(l - t.g_cb[cb] - t.g_cr[cr]),
                level(l + t.b_cb[cb]),
            ]);
        }
    }
    // `out` holds exactly 3·w·h values, so `from_raw` always succeeds.
    RgbImage::from_raw(w as u32, h as u32, out).unwrap_or_default()
}

/// Fixed point's one, for [`Bt601`]'s terms.
const ONE: f64 = 65536.0;

/// A colour's level 0–255 from its value in fixed point, rounded half up.
fn level(c: i32) -> u8 {
    ((c + (1 << 15)) >> 16).clamp(0, 255) as u8
}

/// BT.601's video-range conversion to RGB, term by term for each byte value, in
/// fixed point ([`ONE`]): luma's level, and each chroma byte's share in red, green
/// and blue.
struct Bt601 {
    luma: [i32; 256],
    r_cr: [i32; 256],
    g_cb: [i32; 256],
    g_cr: [i32; 256],
    b_cb: [i32; 256],
}

static BT601: std::sync::LazyLock<Bt601> = std::sync::LazyLock::new(|| {
    let table =
        |f: &dyn Fn(f64) -> f64| std::array::from_fn(|i| (f(i as f64) * ONE).round() as i32);
    let chroma = |c: f64| (c - 128.0) * 255.0 / 224.0;
    Bt601 {
        luma: table(&|y| (y - 16.0) * 255.0 / 219.0),
        r_cr: table(&|c| 1.402 * chroma(c)),
        g_cb: table(&|c| 0.344_136 * chroma(c)),
        g_cr: table(&|c| 0.714_136 * chroma(c)),
        b_cb: table(&|c| 1.772 * chroma(c)),
    }
});

#[cfg(test)]
mod tests {
    use super::*;

    /// BT.601 video range to RGB as its formula reads, per pixel.
    fn formula(y: u8, u: u8, v: u8) -> [u8; 3] {
        let l = (f32::from(y) - 16.0) * 255.0 / 219.0;
        let cb = (f32::from(u) - 128.0) * 255.0 / 224.0;
        let cr = (f32::from(v) - 128.0) * 255.0 / 224.0;
        [
            l + 1.402 * cr,
            l - 0.344_136 * cb - 0.714_136 * cr,
            l + 1.772 * cb,
        ]
        .map(|c| c.round().clamp(0.0, 255.0) as u8)
    }

    /// A 2×2 frame of luma `ys` (row by row) and one chroma pair.
    fn frame(ys: [u8; 4], u: u8, v: u8) -> Frame {
        let mut bytes = ys.to_vec();
        bytes.extend([u, v]);
        Frame::from_yuv420p(2, 2, bytes).unwrap()
    }

    /// Within a level of the formula (fixed point rounds a level's half apart).
    #[test]
    fn every_luma_and_chroma_is_converted_as_the_formula_says() {
        // Every chroma pair on a grid of 5 levels (and both ends), every luma.
        let chroma: Vec<u8> = (0..=255).step_by(5).chain([255]).collect();
        for &u in &chroma {
            for &v in &chroma {
                for y in (0..=255u16).step_by(4) {
                    let ys = [y, y + 1, y + 2, y + 3].map(|k| k.min(255) as u8);
                    let img = to_rgb(&frame(ys, u, v));
                    for (k, &yk) in ys.iter().enumerate() {
                        let got = img.get_pixel((k % 2) as u32, (k / 2) as u32).0;
                        let want = formula(yk, u, v);
                        let apart = got.iter().zip(want).map(|(g, w)| g.abs_diff(w)).max();
                        assert!(apart <= Some(1), "y {yk} u {u} v {v}: {got:?}, {want:?}");
                    }
                }
            }
        }
    }

    #[test]
    fn a_frame_of_no_width_is_a_picture_of_no_width() {
        let f = Frame::from_yuv420p(0, 2, Vec::new()).unwrap();
        assert_eq!(to_rgb(&f).dimensions(), (0, 2));
    }

    #[test]
    fn video_range_black_white_and_red_are_as_a_player_shows_them() {
        let px = |y, u, v| to_rgb(&frame([y; 4], u, v)).get_pixel(1, 1).0;
        assert_eq!(px(16, 128, 128), [0, 0, 0]);
        assert_eq!(px(235, 128, 128), [255, 255, 255]);
        assert_eq!(px(126, 128, 128), [128, 128, 128]);
        // BT.601 red, (255, 0, 0) → Y 81, Cb 90, Cr 240.
        let [r, g, b] = px(81, 90, 240);
        assert!(r >= 253 && g <= 2 && b <= 2, "{r} {g} {b}");
    }
}
