//! Balls of a known radius inside a window of the frame, by a circular Hough
//! transform at that one radius (as OpenCV's `HoughCircles` on a difference image, but
//! on the frame's own edges): each strong edge pixel votes for the centre one radius
//! along its gradient. A ball's visible arc sends its votes to one point; a wall's
//! straight edges, a compression smear's blocks and the rail's top spread theirs
//! along lines. Used where a blob is wider than a ball (a moving ball and the smear
//! of changed blocks it drags in a compressed clip) or gives no outline about its
//! middle: the outline is then fitted about each centre found (`circle`).

use super::circle::Circle;
use super::gray::{Gray, sobel_sums};

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
pub fn centres(
    img: &Gray,
    area: HoughArea,
    r: f64,
    polarity: f64,
    min_step: f64,
    min_arc: f64,
    most: usize,
) -> Vec<Circle> {
    let Some(v) = votes(img, area, r, polarity, min_step) else {
        return Vec::new();
    };
    let need = (min_arc * std::f64::consts::TAU * r) as f32;
    strongest(&v.cells, (v.aw, v.ah), v.origin, r, need, most)
}

/// The votes for centres in an area: `aw × ah` cells, cell (0, 0) at `origin`, px.
struct Votes {
    cells: Vec<f32>,
    aw: usize,
    ah: usize,
    origin: (f64, f64),
}

/// Each strong edge pixel's vote (see [`centres`]) for the centre one radius along
/// its gradient; `None` for an area or radius that gives none.
#[allow(clippy::indexing_slicing)] // accumulator cells inside its aw × ah (checked)
fn votes(img: &Gray, area: HoughArea, r: f64, polarity: f64, min_step: f64) -> Option<Votes> {
    if !(r.is_finite() && r >= 2.0) || img.width < 3 || img.height < 3 {
        return None;
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
        return None;
    }
    let mut acc = vec![0.0f32; aw * ah];
    // A step of h levels gives a Sobel gradient of 4h.
    let strong = (4.0 * min_step) as f32;
    let least = least_square(strong);
    let signs: &[f64] = if polarity == 1.0 {
        &[1.0]
    } else if polarity == -1.0 {
        &[-1.0]
    } else {
        &[1.0, -1.0]
    };
    let (x0, x1, w) = (x0 as usize, x1 as usize, img.width);
    let (mut gx, mut gy) = (vec![0i32; x1 - x0 + 1], vec![0i32; x1 - x0 + 1]);
    // The rows of the box and a pixel each side (the box lies a pixel inside the
    // frame).
    let row = |y: usize| img.data.get(y * w + x0 - 1..y * w + x1 + 2);
    for y in y0 as usize..=y1 as usize {
        let (Some(u), Some(m), Some(d)) = (row(y - 1), row(y), row(y + 1)) else {
            continue;
        };
        if !sobel_row((u, m, d), (&mut gx, &mut gy)) {
            continue;
        }
        for (x, (&sx, &sy)) in (x0..).zip(gx.iter().zip(&gy)) {
            // Sobel sums of whole levels: gx² + gy² ≤ 2·1020² is exact, so its
            // square root is the correctly rounded length, as `hypot` gives; a
            // pixel is weak where that is under `strong`, its square under `least`.
            let s2 = sx * sx + sy * sy;
            if s2 < least {
                continue;
            }
            let g = (s2 as f32).sqrt();
            let (ux, uy) = (f64::from(sx as f32 / g), f64::from(sy as f32 / g));
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
    Some(Votes {
        cells: acc,
        aw,
        ah,
        origin: (cx0, cy0),
    })
}

/// The largest Sobel gradient's square: two sides of 4 × 255 levels.
const MOST_SQUARE: i32 = 2 * 1020 * 1020;

/// The least squared Sobel length (a whole number) whose `f32` square root is not
/// under `strong`: a pixel whose square is under it is one whose length is under
/// `strong`, so the weak are left out without a root each (0 for a `strong` no
/// length is under, NaN included).
fn least_square(strong: f32) -> i32 {
    // Roots grow with their squares: the first square whose root is not under
    // `strong`, by bisection.
    let (mut lo, mut hi) = (0, MOST_SQUARE + 1);
    while lo < hi {
        let mid = lo + (hi - lo) / 2;
        if (mid as f32).sqrt() < strong {
            lo = mid + 1;
        } else {
            hi = mid;
        }
    }
    lo
}

/// The Sobel sums (whole levels) of a run of a row's pixels, from the rows above,
/// at and below it (`u`, `m`, `d`: the run and a pixel each side), into `gx` and
/// `gy` (the run's length each); false, nothing written, for rows of other lengths.
/// Whole slices, so the compiler spreads the loop over vector lanes.
#[allow(clippy::indexing_slicing)] // each j + 2 < the rows' length, n + 2 (checked)
fn sobel_row((u, m, d): (&[u8], &[u8], &[u8]), (gx, gy): (&mut [i32], &mut [i32])) -> bool {
    let n = gx.len();
    if u.len() != n + 2 || m.len() != n + 2 || d.len() != n + 2 || gy.len() != n {
        return false;
    }
    for j in 0..n {
        (gx[j], gy[j]) = sobel_sums(&u[j..j + 3], &m[j..j + 3], &d[j..j + 3]);
    }
    true
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

    /// The votes as they were first computed, pixel by pixel (the Sobel sums and
    /// their length in `f32`), kept as the reference [`votes`] must match.
    fn votes_by_pixel(img: &Gray, area: HoughArea, r: f64, polarity: f64, step: f64) -> Vec<f32> {
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
        let mut acc = vec![0.0f32; aw * ah];
        let strong = (4.0 * step) as f32;
        let signs: &[f64] = match polarity {
            1.0 => &[1.0],
            -1.0 => &[-1.0],
            _ => &[1.0, -1.0],
        };
        for y in y0 as usize..=y1 as usize {
            for x in x0 as usize..=x1 as usize {
                let p = |dx: isize, dy: isize| {
                    img.at((x as isize + dx) as usize, (y as isize + dy) as usize)
                };
                let gx = p(1, -1) + 2.0 * p(1, 0) + p(1, 1) - p(-1, -1) - 2.0 * p(-1, 0) - p(-1, 1);
                let gy = p(-1, 1) + 2.0 * p(0, 1) + p(1, 1) - p(-1, -1) - 2.0 * p(0, -1) - p(1, -1);
                let g = (gx * gx + gy * gy).sqrt();
                if g < strong {
                    continue;
                }
                let (ux, uy) = (f64::from(gx / g), f64::from(gy / g));
                for &s in signs {
                    let (cx, cy) = (x as f64 + s * r * ux, y as f64 + s * r * uy);
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
        acc
    }

    /// The votes by rows of whole-level sums are the pixel-by-pixel votes, cell for
    /// cell, on random pictures (discs on noise, blocks, flat runs), areas (partly off
    /// the frame too), radii, polarities and steps (fractional, and none at all).
    #[test]
    fn the_votes_by_rows_are_the_votes_pixel_by_pixel() {
        let mut seed = 0x9e37_79b9_7f4a_7c15_u64;
        let mut next = || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            (seed >> 11) as f64 / (1u64 << 53) as f64
        };
        for case in 0..200 {
            let (w, h) = (
                20 + (next() * 140.0) as usize,
                20 + (next() * 90.0) as usize,
            );
            let r = 2.0 + next() * 25.0;
            let (cx, cy) = (next() * w as f64, next() * h as f64);
            let (level, back) = ((next() * 255.0) as u8, (next() * 255.0) as u8);
            let mut g = disc(w, h, (cx, cy, r), level, back);
            let noise = next() * 40.0;
            for v in &mut g.data {
                *v = (f64::from(*v) + (next() - 0.5) * noise).clamp(0.0, 255.0) as u8;
            }
            let area = HoughArea {
                left: next() * w as f64 * 1.2 - 10.0,
                top: next() * h as f64 * 1.2 - 10.0,
                right: next() * w as f64 * 1.2,
                bottom: next() * h as f64 * 1.2,
            };
            let polarity = [1.0, -1.0, 0.0][case % 3];
            let step = [10.0, 6.0, 2.5, 0.3, 0.0][case % 5] * (0.5 + next());
            let by_rows = votes(&g, area, r, polarity, step);
            let Some(v) = by_rows else {
                continue;
            };
            let reference = votes_by_pixel(&g, area, r, polarity, step);
            assert_eq!(v.cells, reference, "case {case}");
        }
    }

    /// A length is under `strong` exactly where its square is under
    /// [`least_square`], over every square a Sobel sum can have.
    #[test]
    fn a_weak_pixel_is_its_square_under_the_least() {
        for strong in [
            40.0f32,
            24.0,
            10.0 * 4.0 * 0.77,
            0.5,
            0.0,
            -1.0,
            3000.0,
            f32::NAN,
        ] {
            let least = least_square(strong);
            let wrong = (0..=MOST_SQUARE)
                .step_by(7)
                .chain(
                    [least - 1, least, least + 1]
                        .into_iter()
                        .filter(|s| (0..=MOST_SQUARE).contains(s)),
                )
                .find(|&s| (s < least) != ((s as f32).sqrt() < strong));
            assert_eq!(wrong, None, "strong {strong}, least {least}");
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
