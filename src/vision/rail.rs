//! The near rail's edges, found once per learned background: long straight
//! edges across the bench whose luma steps the same way along most of their
//! length (a rail board's top or lower edge), in full-frame pixels. The balls roll
//! behind the near rail, so what of a ball's outline lies on or below its top edge
//! is the rail's (`circle::fit`, `Tracker::rails_hiding`).

use super::background::Small;
use super::circle::StraightEdge;

/// Most rail edges kept: a board's top and lower edge, a second board's.
const MOST: usize = 4;
/// Steepest edge taken for a rail's, rise over run: a camera tilted by 11°.
const STEEPEST: f64 = 0.2;
/// Share of the columns along the edge whose step has the edge's sign and at least
/// half its mean: a rail's edge steps all along (where the wall behind it varies,
/// by more or less); a checker's rows and a stripe's edges change sign along it.
const ALONG: f64 = 0.7;
/// Smallest mean step across a rail's edge, levels of luma per coarse row: a
/// rail "alike" the wall (within a few levels) closes no circle of a ball.
const LEAST_STEP: f64 = 6.0;

/// The rail edges in the background `bg` (coarse luma, `bg.factor` px per coarse
/// pixel), strongest first, at most [`MOST`]: straight lines no steeper than
/// [`STEEPEST`] along which the luma steps by [`LEAST_STEP`] or more on average,
/// with that sign in [`ALONG`] of the columns; each refined through its columns'
/// sub-pixel steps.
pub fn edges(bg: &Small) -> Vec<StraightEdge> {
    let (w, h) = (bg.width, bg.height);
    if w < 8 || h < 4 || bg.y.len() < w * h {
        return Vec::new();
    }
    // The step between each row and the next, per column: row r holds L(r+1) − L(r),
    // found once (every line tried reads them).
    let rows = h - 1;
    let steps: Vec<f32> =
        bg.y.windows(w + 1)
            .take(rows * w)
            .map(|p| p.last().copied().unwrap_or(0.0) - p.first().copied().unwrap_or(0.0))
            .collect();
    let step = |x: usize, r: usize| f64::from(steps.get(r * w + x).copied().unwrap_or(0.0));
    let rise = (STEEPEST * w as f64).floor() as i64;
    let mut found: Vec<(f64, i64, i64)> = Vec::new();
    let mut along: Vec<f64> = Vec::with_capacity(w);
    for d in -rise..=rise {
        // Each column's row on a line that rises by `d` rows across: the same
        // offsets from its left end whichever row that is.
        let offsets: Vec<i64> = (0..w)
            .map(|x| (d as f64 * x as f64 / (w - 1) as f64).round() as i64)
            .collect();
        for left in (-d).max(0)..(rows as i64 - d.max(0)) {
            let at = |x: usize, off: i64| step(x, (left + off) as usize);
            // Every fourth column first: most lines step by nothing like a rail.
            let some = offsets
                .iter()
                .enumerate()
                .step_by(4)
                .map(|(x, &o)| at(x, o))
                .sum::<f64>()
                / w.div_ceil(4) as f64;
            if some.abs() < 0.5 * LEAST_STEP {
                continue;
            }
            along.clear();
            along.extend(offsets.iter().enumerate().map(|(x, &o)| at(x, o)));
            let mean = along.iter().sum::<f64>() / w as f64;
            if mean.abs() < LEAST_STEP {
                continue;
            }
            let with = along
                .iter()
                .filter(|&&s| s * mean.signum() >= 0.5 * mean.abs())
                .count();
            if with as f64 >= ALONG * w as f64 {
                found.push((mean, left, left + d));
            }
        }
    }
    found.sort_by(|a, b| b.0.abs().total_cmp(&a.0.abs()));
    let mut kept: Vec<(f64, i64, i64)> = Vec::new();
    for f in found {
        let near = kept
            .iter()
            .any(|k| (k.1 - f.1).abs() <= 2 && (k.2 - f.2).abs() <= 2);
        if !near {
            kept.push(f);
        }
        if kept.len() >= MOST {
            break;
        }
    }
    kept.iter()
        .filter_map(|&(mean, left, right)| refined(bg, &step, mean.signum(), (left, right)))
        .collect()
}

/// The edge through each column's sub-pixel step (the steps of sign `sign` about
/// their peak within a row of the line from `left` to `right`, coarse rows), least
/// squares, in full-frame pixels (a pixel's middle at its index).
fn refined(
    bg: &Small,
    step: &impl Fn(usize, usize) -> f64,
    sign: f64,
    (left, right): (i64, i64),
) -> Option<StraightEdge> {
    let (w, h) = (bg.width, bg.height);
    let f = bg.factor.max(1) as f64;
    let mut pts: Vec<[f64; 2]> = Vec::new();
    for x in 0..w {
        let t = x as f64 / (w - 1) as f64;
        let y = left as f64 + t * (right - left) as f64;
        let r = y.round() as i64;
        let best = (r - 1..=r + 1)
            .filter(|&r| r >= 0 && (r as usize) + 1 < h)
            .max_by(|&a, &b| {
                (sign * step(x, a as usize)).total_cmp(&(sign * step(x, b as usize)))
            })?;
        let at = |r: i64| {
            if r >= 0 && (r as usize) + 1 < h {
                sign * step(x, r as usize)
            } else {
                0.0
            }
        };
        // The steps' centroid over five rows about the peak: a block mean of a
        // sharp edge spreads its step over two rows in the share the edge splits
        // them, so their first moment is where the edge lies.
        let around: Vec<(f64, f64)> = (-2..=2)
            .map(|k| (k as f64, at(best + k).max(0.0)))
            .collect();
        let mass: f64 = around.iter().map(|a| a.1).sum();
        if at(best) <= 0.0 || mass <= 0.0 {
            continue;
        }
        let off = around.iter().map(|a| a.0 * a.1).sum::<f64>() / mass;
        // Row r's step lies between the rows' middles r and r + 1; a coarse row's
        // middle is (f − 1) / 2 full pixels into it.
        let yc = best as f64 + 0.5 + off;
        let xf = x as f64 * f + 0.5 * (f - 1.0);
        pts.push([xf, yc * f + 0.5 * (f - 1.0)]);
    }
    if pts.len() < 4 {
        return None;
    }
    StraightEdge::through(&pts)
}

#[cfg(test)]
mod tests {
    use super::*;

    use proptest::prelude::*;

    /// A background `w`×`h` coarse px (factor `f`): a wall of `wall` with a board
    /// of `board` from the line `top` (y = top.0 + top.1 x, coarse) down `depth` rows,
    /// plus a fixed pattern of ±`noise` levels.
    fn bench(
        (w, h, f): (usize, usize, usize),
        (wall, board): (f32, f32),
        top: (f64, f64),
        depth: f64,
        noise: u32,
    ) -> Small {
        let mut y = vec![wall; w * h];
        for r in 0..h {
            for x in 0..w {
                let edge = top.0 + top.1 * x as f64;
                // A coarse row's share under the edge (a block mean of a sharp edge).
                let cover = |e: f64| ((r as f64 + 1.0 - e).clamp(0.0, 1.0)) as f32;
                let share = cover(edge) - cover(edge + depth);
                let n = ((r * 31 + x * 17) as u32 % (2 * noise + 1)) as f32 - noise as f32;
                y[r * w + x] = wall + (board - wall) * share + n;
            }
        }
        Small {
            width: w,
            height: h,
            factor: f,
            y,
            u: vec![128; w * h],
            v: vec![128; w * h],
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(64))]

        /// A board lighter or darker than the wall, at any tilt up to the steepest
        /// taken, any depth and any coarse factor: its top edge is found where it is
        /// drawn, to a tenth of a coarse pixel, and at its slope.
        #[test]
        fn a_board_s_top_edge_is_found_where_drawn(
            f in 1usize..=6,
            top in 15.0f64..50.0,
            slope in -0.15f64..0.15,
            depth in 4.0f64..25.0,
            wall in 20.0f32..230.0,
            step in prop_oneof![-150.0f32..-20.0, 20.0f32..150.0],
            noise in 0u32..4,
        ) {
            let board = (wall + step).clamp(0.0, 255.0);
            prop_assume!((board - wall).abs() >= 20.0);
            // The board stays inside the frame across it.
            prop_assume!(top + slope.min(0.0) * 160.0 > 2.0);
            prop_assume!(top + slope.max(0.0) * 160.0 + depth < 88.0);
            let bg = bench((160, 90, f), (wall, board), (top, slope), depth, noise);
            let e = edges(&bg);
            let f64f = f as f64;
            // Full-frame y of the drawn top edge at full-frame x (a pixel's middle
            // at its index: coarse column c's middle lies at c f + (f − 1) / 2, and
            // an edge where coarse rows start at e lies at e f − 1/2).
            let drawn = |x: f64| {
                let c = (x - 0.5 * (f64f - 1.0)) / f64f;
                (top + slope * c) * f64f - 0.5
            };
            let x = 80.0 * f64f;
            let found = e.iter().find(|l| {
                (l.at(x) - drawn(x)).abs() < 0.1 * f64f && (l.slope - slope).abs() < 0.01
            });
            prop_assert!(found.is_some(), "top {:.2} at x {x}: {e:?}", drawn(x));
        }
    }

    #[test]
    fn a_checker_has_no_rail_edge() {
        let (w, h) = (160, 90);
        let mut y = vec![0.0f32; w * h];
        for r in 0..h {
            for x in 0..w {
                y[r * w + x] = if (r / 6 + x / 6) % 2 == 0 {
                    40.0
                } else {
                    200.0
                };
            }
        }
        let bg = Small {
            width: w,
            height: h,
            factor: 1,
            y,
            u: vec![128; w * h],
            v: vec![128; w * h],
        };
        assert!(edges(&bg).is_empty());
    }
}
