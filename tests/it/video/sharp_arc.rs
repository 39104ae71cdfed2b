//! A ball whose outline shows only along a short arc, sharply: a dark ball on a wall
//! of its own brightness, a light band behind its top (the looks table's seed 9, a
//! black ball on a cluttered wall of its brightness, lost for the want of a third of
//! its outline). Once the balls' radius is known, such an arc of that radius is a
//! ball (`Params::min_coverage_sharp`); its centre lies where the truth says.

use groovelab::vision::{self, Frame, Params};

const W: u32 = 240;
const H: u32 = 90;
/// The ball: radius, the centre's height, its x in the first frame and its step per
/// frame (px), and its level; the wall left of `SPLIT` is light, right of it of the
/// ball's level but for a light band across the ball's top.
const R: f64 = 16.0;
const CY: f64 = 50.0;
const X0: f64 = 40.0;
const STEP: f64 = 5.0;
const DARK: f64 = 40.0;
const LIGHT: f64 = 160.0;
const SPLIT: f64 = 120.0;
const FRAMES: usize = 36;

/// Frame `k` and the ball's true centre: the ball anti-aliased by its pixels'
/// coverage, seeded noise of ±2 levels.
fn frame(k: usize) -> (Frame, (f64, f64)) {
    let c = (X0 + STEP * k as f64, CY);
    let seed = 0x9e37_79b9_u64.wrapping_add(k as u64 * 7919);
    let frame = super::drawn_frame((W, H), seed, 2, |x, y| {
        let (fx, fy) = (f64::from(x) + 0.5, f64::from(y) + 0.5);
        let band = fy > CY - R - 4.0 && fy < CY - R + 5.0;
        let wall = if fx < SPLIT || band { LIGHT } else { DARK };
        let cover = super::disc_cover((fx - 0.5, fy - 0.5), c, R);
        [wall * (1.0 - cover) + DARK * cover; 3]
    });
    (frame, c)
}

/// Per frame where the ball lies wholly over the dark wall: the tracked centre's
/// distance from the truth, `None` where not tracked.
fn errors_over_the_dark_wall(params: Params) -> Vec<Option<f64>> {
    let (frames, truth): (Vec<Frame>, Vec<(f64, f64)>) = (0..FRAMES).map(frame).unzip();
    let t = vision::track(&frames, params);
    t.frames
        .iter()
        .zip(&truth)
        .filter(|(_, c)| c.0 - R > SPLIT + 2.0)
        .map(|(fixes, c)| {
            fixes
                .iter()
                .flatten()
                .map(|f| (f.outline.circle.x - c.0).hypot(f.outline.circle.y - c.1))
                .min_by(f64::total_cmp)
        })
        .collect()
}

#[test]
fn a_sharp_short_arc_of_the_known_radius_is_the_ball() {
    let e = errors_over_the_dark_wall(Params::default());
    let found: Vec<f64> = e.iter().flatten().copied().collect();
    assert!(
        found.len() * 4 >= e.len() * 3,
        "found in {} of {} frames over the dark wall",
        found.len(),
        e.len()
    );
    // The arc spans about 100°: its centre is less sure than a half circle's, still
    // well under a pixel at ±2 levels of noise.
    assert!(found.iter().all(|&d| d < 0.5), "{found:?}");
    // Without the rule (the arc under `min_coverage_known`) the ball is lost there.
    let without = errors_over_the_dark_wall(Params {
        min_coverage_sharp: 1.0,
        ..Params::default()
    });
    assert!(
        without.iter().flatten().count() * 4 < e.len(),
        "found without the rule: {without:?}"
    );
}
