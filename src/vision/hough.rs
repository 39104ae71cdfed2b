//! Balls of a known radius inside a window of the frame, by a circular Hough
//! transform at that one radius (as OpenCV's `HoughCircles` on a difference image, but
//! on the frame's own edges): each strong edge pixel votes for the centre one radius
//! along its gradient. A ball's visible arc sends its votes to one point; a wall's
//! straight edges, a compression smear's blocks and the rail's top spread theirs
//! along lines. Used where a blob is wider than a ball (a moving ball and the smear
//! of changed blocks it drags in a compressed clip) or gives no outline about its
//! middle: the outline is then fitted about each centre found (`circle`).

use super::circle::Circle;
use super::gray::Gray;

/// Where to look: the window's corners, px (left, top, right, bottom).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HoughArea {
    pub left: f64,
    pub top: f64,
    pub right: f64,
    pub bottom: f64,
}

/// Up to `most` centres of circles of radius `r` px whose centre lies in `area`,
/// strongest first; `polarity` +1 for a ball brighter than around it, −1 darker,
/// anything else either. `min_step` is the smallest brightness step (levels) an
/// edge must have to vote; a centre needs votes from at least `min_arc` of the
/// circle (a share of its length: the rail hides the lower part).
#[allow(clippy::indexing_slicing)] // accumulator cells inside its aw × ah, pixels inside the frame (the box is clipped)
pub fn centres(
    img: &Gray,
    area: HoughArea,
    r: f64,
    polarity: f64,
    min_step: f64,
    min_arc: f64,
    most: usize,
) -> Vec<Circle> {
    if !(r.is_finite() && r >= 2.0) || img.width < 3 || img.height < 3 {
        return Vec::new();
    }
    // Edge pixels that can vote for a centre in the window: within r + 1 of the area.
    let reach = r + 1.0;
    let clip = |v: f64, hi: usize| v.max(1.0).min(hi as f64 - 2.0);
    let (x0, x1) = (
        clip((area.left - reach).floor(), img.width),
        clip((area.right + reach).ceil(), img.width),
    );
    let (y0, y1) = (
        clip((area.top - reach).floor(), img.height),
        clip((area.bottom + reach).ceil(), img.height),
    );
    let (cx0, cy0) = (area.left.floor(), area.top.floor());
    let aw = (area.right.ceil() - cx0).max(0.0) as usize + 1;
    let ah = (area.bottom.ceil() - cy0).max(0.0) as usize + 1;
    if x1 <= x0 || y1 <= y0 || aw * ah > 4_000_000 {
        return Vec::new();
    }
    let mut acc = vec![0.0f32; aw * ah];
    // A step of h levels gives a Sobel gradient of 4h.
    let strong = (4.0 * min_step) as f32;
    let signs: &[f64] = if polarity == 1.0 {
        &[1.0]
    } else if polarity == -1.0 {
        &[-1.0]
    } else {
        &[1.0, -1.0]
    };
    for y in y0 as usize..=y1 as usize {
        for x in x0 as usize..=x1 as usize {
            let p = |dx: isize, dy: isize| {
                img.at((x as isize + dx) as usize, (y as isize + dy) as usize)
            };
            let gx = p(1, -1) + 2.0 * p(1, 0) + p(1, 1) - p(-1, -1) - 2.0 * p(-1, 0) - p(-1, 1);
            let gy = p(-1, 1) + 2.0 * p(0, 1) + p(1, 1) - p(-1, -1) - 2.0 * p(0, -1) - p(1, -1);
            // Sobel sums of whole levels: gx² + gy² ≤ 2·1020² is exact in f32, so
            // its square root is the correctly rounded length, as `hypot` gives
            // (at a fraction of its cost, once per pixel of the window).
            let g = (gx * gx + gy * gy).sqrt();
            if g < strong {
                continue;
            }
            let (ux, uy) = (f64::from(gx / g), f64::from(gy / g));
            for &s in signs {
                // A brighter ball: the gradient points into it, toward its centre.
                let (cx, cy) = (x as f64 + s * r * ux, y as f64 + s * r * uy);
                // Only the visible part votes: the edge at or above the centre's
                // height (below it the rail's top would vote for centres under it).
                if (y as f64) > cy + 0.3 * r {
                    continue;
                }
                let (i, j) = ((cx - cx0).round(), (cy - cy0).round());
                if i < 0.0 || j < 0.0 || i >= aw as f64 || j >= ah as f64 {
                    continue;
                }
                acc[j as usize * aw + i as usize] += 1.0;
            }
        }
    }
    let need = (min_arc * std::f64::consts::TAU * r) as f32;
    strongest(&acc, (aw, ah), (cx0, cy0), r, need, most)
}

/// The cells of the accumulator `acc` (`aw × ah`, its cell (0, 0) at `origin`, px)
/// with the most votes within a pixel, at least `need`, no two within `r`; up to
/// `most`, strongest first.
#[allow(clippy::indexing_slicing)] // cells inside the aw × ah accumulator
fn strongest(
    acc: &[f32],
    (aw, ah): (usize, usize),
    (cx0, cy0): (f64, f64),
    r: f64,
    need: f32,
    most: usize,
) -> Vec<Circle> {
    // Votes within a pixel of each cell (a ball's edge is two or three pixels thick,
    // its centre found within a pixel).
    let sum = |i: usize, j: usize| -> f32 {
        let mut s = 0.0;
        for jj in j.saturating_sub(1)..(j + 2).min(ah) {
            for ii in i.saturating_sub(1)..(i + 2).min(aw) {
                s += acc[jj * aw + ii];
            }
        }
        s
    };
    let mut summed = vec![0.0f32; aw * ah];
    for j in 0..ah {
        for i in 0..aw {
            summed[j * aw + i] = sum(i, j);
        }
    }
    let mut out: Vec<Circle> = Vec::new();
    while out.len() < most {
        let Some((best, &v)) = summed.iter().enumerate().max_by(|a, b| a.1.total_cmp(b.1)) else {
            break;
        };
        if v < need {
            break;
        }
        let c = Circle {
            x: cx0 + (best % aw) as f64,
            y: cy0 + (best / aw) as f64,
            r,
        };
        // No second centre within a radius of this one: only cells within r of it
        // each way can be (a length is at least either of its offsets).
        let reach = r.ceil() as usize;
        let (bi, bj) = (best % aw, best / aw);
        for j in bj.saturating_sub(reach)..(bj + reach + 1).min(ah) {
            for i in bi.saturating_sub(reach)..(bi + reach + 1).min(aw) {
                let (x, y) = (cx0 + i as f64, cy0 + j as f64);
                if (x - c.x).hypot(y - c.y) < r {
                    summed[j * aw + i] = 0.0;
                }
            }
        }
        out.push(c);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A disc of radius `r` at (`cx`, `cy`), `level` on `back`, the rows from `rail`
    /// down painted `rail_level` (hiding the lower part).
    fn disc(w: usize, h: usize, (cx, cy, r): (f64, f64, f64), level: u8, back: u8) -> Gray {
        let mut g = Gray::filled(w, h, back);
        for y in 0..h {
            for x in 0..w {
                if (x as f64 - cx).hypot(y as f64 - cy) <= r {
                    g.data[y * w + x] = level;
                }
            }
        }
        g
    }

    #[test]
    fn the_centre_of_a_disc_beside_a_smear_is_found_within_a_pixel() {
        let (w, h) = (200, 80);
        let mut g = disc(w, h, (60.3, 40.0, 15.0), 200, 100);
        // A smear: blocks of ±12 levels to the right of the ball.
        for y in 25..50 {
            for x in 80..150 {
                let b = ((x / 8 + y / 8) % 3) as i32 - 1;
                g.data[y * w + x] = (100 + 12 * b) as u8;
            }
        }
        for y in 52..h {
            for x in 0..w {
                g.data[y * w + x] = 60;
            }
        }
        let win = HoughArea {
            left: 20.0,
            top: 20.0,
            right: 180.0,
            bottom: 60.0,
        };
        for polarity in [1.0, 0.0] {
            let found = centres(&g, win, 15.0, polarity, 10.0, 0.2, 2);
            let c = found.first().expect("a centre");
            assert!(
                (c.x - 60.3).abs() <= 1.0 && (c.y - 40.0).abs() <= 1.0,
                "{polarity}: {c:?}"
            );
        }
    }

    #[test]
    fn a_plain_frame_has_no_centre() {
        let g = Gray::filled(100, 60, 120);
        let win = HoughArea {
            left: 10.0,
            top: 10.0,
            right: 90.0,
            bottom: 50.0,
        };
        assert!(centres(&g, win, 12.0, 0.0, 10.0, 0.2, 2).is_empty());
    }
}
