//! What was tracked, drawn over the frames (`track --overlay`): each found ball's
//! outline, centre and mark, and a contact sheet of a few such frames, so a student
//! checks the tracking at a glance, as in Tracker. Pure: pictures in, pictures out.
//! Drawn by hand rather than with imageproc, whose circles sit on whole pixels: the
//! fitted centres are sub-pixel, and the drawing is anti-aliased by distance.

use image::{Rgb, RgbImage};

/// One ball found in one frame, pixels: its centre, radius and mark (if found).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Drawn {
    pub centre: (f64, f64),
    pub radius: f64,
    pub mark: Option<(f64, f64)>,
}

/// The colours of the two balls' drawings (first, second), bright on the dark halo
/// drawn under them so they show on any background.
pub const COLOURS: [[u8; 3]; 2] = [[255, 220, 0], [0, 220, 255]];
const HALO: [u8; 3] = [0, 0, 0];

/// Draws each ball of `found` (the i-th in `COLOURS[i]`) onto `img`: its outline, a
/// cross at its centre, a line to its mark and a ring around the mark.
pub fn draw(img: &mut RgbImage, found: &[Option<Drawn>]) {
    for (i, f) in found.iter().enumerate() {
        let Some(f) = f else { continue };
        let colour = if i % 2 == 0 { COLOURS[0] } else { COLOURS[1] };
        let width = (f.radius / 25.0).clamp(1.2, 4.0);
        let arm = (0.25 * f.radius).max(4.0);
        let (cx, cy) = f.centre;
        let mark_ring = (0.15 * f.radius).max(3.0);
        // The halo first, then the colour over it.
        for (c, w) in [(HALO, width + 2.0), (colour, width)] {
            ring(img, f.centre, f.radius, w, c);
            segment(img, (cx - arm, cy), (cx + arm, cy), w, c);
            segment(img, (cx, cy - arm), (cx, cy + arm), w, c);
            if let Some(m) = f.mark {
                ring(img, m, mark_ring, w, c);
                // The line from the centre to the mark's ring (the spin angle).
                let (dx, dy) = (m.0 - cx, m.1 - cy);
                let d = dx.hypot(dy);
                if d > mark_ring {
                    let s = (d - mark_ring) / d;
                    segment(img, f.centre, (cx + s * dx, cy + s * dy), w, c);
                }
            }
        }
    }
}

/// Blends `colour` into the pixel `(x, y)` by `alpha` (0–1).
fn blend(img: &mut RgbImage, x: i64, y: i64, colour: [u8; 3], alpha: f64) {
    if alpha <= 0.0 || x < 0 || y < 0 || x >= i64::from(img.width()) || y >= i64::from(img.height())
    {
        return;
    }
    let p = img.get_pixel_mut(x as u32, y as u32);
    let a = alpha.min(1.0);
    for (v, c) in p.0.iter_mut().zip(colour) {
        *v = (f64::from(*v) * (1.0 - a) + f64::from(c) * a).round() as u8;
    }
}

/// The pixels within `reach` of the box `(x0, y0)–(x1, y1)`, clipped to the picture.
fn pixels(img: &RgbImage, lo: (f64, f64), hi: (f64, f64), reach: f64) -> Vec<(i64, i64)> {
    let clip = |v: f64, n: u32| (v.max(-1.0) as i64).min(i64::from(n));
    let (x0, x1) = (
        clip((lo.0 - reach).floor(), img.width()),
        clip((hi.0 + reach).ceil(), img.width()),
    );
    let (y0, y1) = (
        clip((lo.1 - reach).floor(), img.height()),
        clip((hi.1 + reach).ceil(), img.height()),
    );
    (y0..=y1)
        .flat_map(|y| (x0..=x1).map(move |x| (x, y)))
        .collect()
}

/// A circle of radius `r` about `c`, `width` px wide, anti-aliased.
fn ring(img: &mut RgbImage, c: (f64, f64), r: f64, width: f64, colour: [u8; 3]) {
    if !(c.0.is_finite() && c.1.is_finite() && r.is_finite()) {
        return;
    }
    for (x, y) in pixels(img, (c.0 - r, c.1 - r), (c.0 + r, c.1 + r), width + 1.0) {
        let d = ((x as f64 - c.0).hypot(y as f64 - c.1) - r).abs();
        blend(img, x, y, colour, 0.5 * width + 0.5 - d);
    }
}

/// A line from `a` to `b`, `width` px wide, anti-aliased.
fn segment(img: &mut RgbImage, a: (f64, f64), b: (f64, f64), width: f64, colour: [u8; 3]) {
    if !(a.0.is_finite() && a.1.is_finite() && b.0.is_finite() && b.1.is_finite()) {
        return;
    }
    let (lo, hi) = ((a.0.min(b.0), a.1.min(b.1)), (a.0.max(b.0), a.1.max(b.1)));
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let len2 = (dx * dx + dy * dy).max(1e-12);
    for (x, y) in pixels(img, lo, hi, width + 1.0) {
        let (px, py) = (x as f64 - a.0, y as f64 - a.1);
        let t = ((px * dx + py * dy) / len2).clamp(0.0, 1.0);
        let d = (px - t * dx).hypot(py - t * dy);
        blend(img, x, y, colour, 0.5 * width + 0.5 - d);
    }
}

/// The grid's spacing for a frame `width` px wide: a round number of pixels giving
/// about ten lines across.
pub fn grid_step(width: u32) -> u32 {
    const STEPS: [u32; 8] = [10, 20, 50, 100, 200, 250, 500, 1000];
    let want = width.div_ceil(10);
    STEPS.iter().copied().find(|&s| s >= want).unwrap_or(1000)
}

/// Draws a pixel grid over `img` with each line's pixel coordinate written beside it
/// (x along the top, y down the left), so a student reads `--roi X,Y,W,H` and
/// `--ball-at X,Y` off the picture. `scale`: pixels per font pixel and line width,
/// the factor the picture will be shrunk by (a contact sheet's tile), so the labels
/// stay 8 px tall there.
pub fn pixel_grid(img: &mut RgbImage, scale: u32) {
    let k = scale.max(1);
    let step = grid_step(img.width());
    let (w, h) = (img.width(), img.height());
    // Half-transparent lines `k` px wide: pixel column x (row y) and the next k − 1.
    let white = [255, 255, 255];
    for x in (step..w).step_by(step as usize) {
        for (c, y) in (x..(x + k).min(w)).flat_map(|c| (0..h).map(move |y| (c, y))) {
            blend(img, i64::from(c), i64::from(y), white, 0.5);
        }
    }
    for y in (step..h).step_by(step as usize) {
        for (x, r) in (0..w).flat_map(|x| (y..(y + k).min(h)).map(move |r| (x, r))) {
            blend(img, i64::from(x), i64::from(r), white, 0.5);
        }
    }
    // A label that would not fit whole is left out: a cut "120" reads as 120.
    for x in (step..w).step_by(step as usize) {
        let text = x.to_string();
        if x + (8 * text.len() as u32 + 3) * k <= w {
            label(img, &text, (x + 2 * k, 2 * k), k);
        }
    }
    for y in (step..h).step_by(step as usize) {
        if y + 12 * k <= h {
            label(img, &y.to_string(), (2 * k, y + 2 * k), k);
        }
    }
}

/// Writes `text` (ASCII) in the bottom right corner of `img`, as [`pixel_grid`]'s
/// labels (`scale` as there): a frame's number and time on the overlay, as Tracker
/// shows them, clear of the grid's labels along the top and the left.
pub fn caption(img: &mut RgbImage, text: &str, scale: u32) {
    let k = scale.max(1);
    let (w, h) = (8 * k * text.len() as u32 + 2 * k, 10 * k);
    if let (Some(x), Some(y)) = (img.width().checked_sub(w), img.height().checked_sub(h)) {
        label(img, text, (x, y + k), k);
    }
}

/// The caption of frame `frame` (the clip's first is 0) of a clip at `fps` frames/s:
/// its number counted from 1, as the app's video view counts ("frame 17 of 25"),
/// and its time from the first frame (the number alone at no known rate).
pub fn frame_caption(frame: usize, fps: Option<f64>) -> String {
    let n = frame + 1;
    match fps.filter(|f| f.is_finite() && *f > 0.0) {
        Some(f) => format!("frame {n}  {:.3} s", frame as f64 / f),
        None => format!("frame {n}"),
    }
}

/// Writes `text` (ASCII) at `at` (its top left), each font pixel `k` × `k`, white on
/// a black box.
fn label(img: &mut RgbImage, text: &str, at: (u32, u32), k: u32) {
    let glyph_w = 8 * k;
    let box_w = glyph_w * text.len() as u32 + 2 * k;
    let box_h = 10 * k;
    for dy in 0..box_h {
        for dx in 0..box_w {
            let (x, y) = (i64::from(at.0 + dx), i64::from(at.1 + dy));
            blend(img, x - i64::from(k), y - i64::from(k), HALO, 0.7);
        }
    }
    for (i, ch) in text.bytes().enumerate() {
        let Some(rows) = font8x8::legacy::BASIC_LEGACY.get(usize::from(ch)) else {
            continue;
        };
        for (row, bits) in rows.iter().enumerate() {
            for col in 0..8u32 {
                if bits & (1 << col) == 0 {
                    continue;
                }
                for (dx, dy) in (0..k).flat_map(|a| (0..k).map(move |b| (a, b))) {
                    let x = at.0 + i as u32 * glyph_w + col * k + dx;
                    let y = at.1 + row as u32 * k + dy;
                    blend(img, i64::from(x), i64::from(y), [255, 255, 255], 1.0);
                }
            }
        }
    }
}

/// The frames to show on a contact sheet of `frames` frames: at most `count`, evenly
/// spread from the first to the last.
pub fn sheet_frames(frames: usize, count: usize) -> Vec<usize> {
    if frames == 0 || count == 0 {
        return Vec::new();
    }
    let n = count.min(frames);
    if n == 1 {
        return vec![0];
    }
    (0..n).map(|i| i * (frames - 1) / (n - 1)).collect()
}

/// A contact sheet: `tiles` (drawn frames, all one size) shrunk to at most `tile_width`
/// px wide, `columns` to a row, on a dark grey ground with a gap between.
pub fn sheet(tiles: &[RgbImage], columns: usize, tile_width: u32) -> RgbImage {
    const GAP: u32 = 4;
    let Some(first) = tiles.first() else {
        return RgbImage::new(1, 1);
    };
    let w = first.width().min(tile_width).max(1);
    let h = ((f64::from(first.height()) * f64::from(w) / f64::from(first.width())).round() as u32)
        .max(1);
    let cols = columns.clamp(1, tiles.len()) as u32;
    let rows = (tiles.len() as u32).div_ceil(cols);
    let mut out = RgbImage::from_pixel(
        GAP + cols * (w + GAP),
        GAP + rows * (h + GAP),
        Rgb([40, 40, 40]),
    );
    for (i, t) in tiles.iter().enumerate() {
        let small = if t.width() == w {
            t.clone()
        } else {
            image::imageops::resize(t, w, h, image::imageops::FilterType::Triangle)
        };
        let (c, r) = (i as u32 % cols, i as u32 / cols);
        image::imageops::replace(
            &mut out,
            &small,
            i64::from(GAP + c * (w + GAP)),
            i64::from(GAP + r * (h + GAP)),
        );
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_grid_is_round_numbers_about_ten_across() {
        for (w, step) in [
            (1920, 200),
            (1280, 200),
            (854, 100),
            (640, 100),
            (480, 50),
            (90, 10),
        ] {
            assert_eq!(grid_step(w), step, "{w} px wide");
            assert!((4..=10).contains(&(w / step)), "{w} px: {} lines", w / step);
        }
    }

    #[test]
    fn the_grid_lines_lie_on_their_pixel_coordinates() {
        let mut img = RgbImage::from_pixel(400, 300, Rgb([0, 0, 0]));
        pixel_grid(&mut img, 1);
        // Step 50: the column x = 150 is lit along its length, its neighbours not.
        let lit = |x: u32, y: u32| img.get_pixel(x, y).0[0] > 100;
        assert!((20..300).all(|y| lit(150, y)));
        assert!(!lit(149, 220) && !lit(151, 220));
        // The row y = 250 is lit, and its label "250" is written near the left edge.
        assert!((30..400).all(|x| lit(x, 250)));
        assert!(!lit(120, 249) && !lit(120, 251));
        let ink = |x0: u32, y0: u32| {
            (x0..x0 + 28)
                .flat_map(|x| (y0..y0 + 10).map(move |y| (x, y)))
                .filter(|&(x, y)| lit(x, y))
                .count()
        };
        assert!(ink(2, 252) > 20, "the label of y = 250");
        assert!(ink(352, 2) > 20, "the label of x = 350");
        // No cut label at the right edge: on a picture 370 px wide the label of
        // x = 350 would be cut, so it is left out.
        let mut narrow = RgbImage::from_pixel(370, 300, Rgb([0, 0, 0]));
        pixel_grid(&mut narrow, 1);
        let lit_narrow = |x: u32, y: u32| narrow.get_pixel(x, y).0[0] > 100;
        assert!((351..370).all(|x| (2..10).all(|y| !lit_narrow(x, y))));
        assert!(
            (301..329).any(|x| (2..10).any(|y| lit_narrow(x, y))),
            "x = 300's label"
        );
    }

    #[test]
    fn the_outline_is_drawn_at_the_radius_and_not_inside() {
        let mut img = RgbImage::from_pixel(100, 100, Rgb([128, 128, 128]));
        let f = Drawn {
            centre: (50.3, 49.6),
            radius: 30.0,
            mark: None,
        };
        draw(&mut img, &[Some(f)]);
        // On the circle (to the right of the centre): the first ball's colour.
        // The edge is anti-aliased by coverage, so the pixel is the colour blended
        // with the grey: far from the grey, and of the colour's hue (no blue).
        let on = img.get_pixel((50.3 + 30.0f64).round() as u32, 50).0;
        let [r, g, b] = on;
        assert!(
            r > 180 && g > 150 && b < 40,
            "{on:?} against {:?}",
            COLOURS[0]
        );
        // Halfway in, between the cross and the outline: untouched.
        assert_eq!(img.get_pixel(50 + 15, 50 + 15).0, [128, 128, 128]);
    }

    #[test]
    fn a_sheet_of_frames_spreads_them_and_keeps_their_shape() {
        assert_eq!(sheet_frames(100, 4), vec![0, 33, 66, 99]);
        assert_eq!(sheet_frames(2, 12), vec![0, 1]);
        assert!(sheet_frames(0, 12).is_empty());
        let tiles = vec![RgbImage::new(1920, 1080); 5];
        let s = sheet(&tiles, 4, 480);
        // 4 columns of 480 px and 2 rows of 270 px, with 4 px gaps.
        assert_eq!((s.width(), s.height()), (4 + 4 * 484, 4 + 2 * 274));
    }
}
