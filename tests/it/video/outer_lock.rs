//! A ball lit from the upper left, small in the picture, over a darker rail: its lit
//! part, a disc of 0.7 of its radius touching its outline at the upper left, is
//! brighter than the wall, the rest of it (the shaded right and lower limb) darker.
//! The edges of the lit sign give a circle of 0.7 R inside the ball, a clear one
//! whose radius agrees from frame to frame (the small looks' seed 38: 8.5 px for
//! 12.3, the scale 28 % off with a ± of 3 %). A ball's outline is the outermost
//! closed circular edge of the blob that moves (`circle::outermost`): the first
//! lock is checked against it, and the ball's whole outline is taken instead.

use groovelab::vision::{self, Frame, Params};

const W: u32 = 240;
const H: u32 = 80;
/// The ball: radius, the centre's height, its x in the first frame and its step per
/// frame (px); its lit part's radius and how far its centre lies toward the upper
/// left (radii); the levels of the wall, the rail, the lit part and the shaded limb.
const R: f64 = 13.0;
const CY: f64 = 40.0;
const X0: f64 = 30.0;
const STEP: f64 = 4.0;
const LIT_R: f64 = 0.7;
const LIT_OFF: f64 = 0.3;
const WALL: f64 = 189.0;
const RAIL: f64 = 148.0;
const LIT: f64 = 230.0;
const SHADED: f64 = 132.0;
/// The rail's top edge, below the centre (radii).
const RAIL_TOP: f64 = 0.3;
const FRAMES: usize = 40;

/// Frame `k`: the ball anti-aliased by its pixels' coverage, its lit part fading to
/// the shade over 2 px, the rail in front of its lower part, seeded noise of ±2.
fn frame(k: usize) -> Frame {
    let c = (X0 + STEP * k as f64, CY);
    let off = LIT_OFF * R / std::f64::consts::SQRT_2;
    let lit_c = (c.0 - off, c.1 - off);
    let seed = 0x2545_f491_u64.wrapping_add(k as u64 * 7919);
    super::drawn_frame((W, H), seed, 2, |x, y| {
        let (fx, fy) = (f64::from(x) + 0.5, f64::from(y) + 0.5);
        let cover = super::disc_cover((fx, fy), c, R);
        let lit = (0.5 + (LIT_R * R - (fx - lit_c.0).hypot(fy - lit_c.1)) / 2.0).clamp(0.0, 1.0);
        let ball = SHADED + (LIT - SHADED) * lit;
        let v = if fy > CY + RAIL_TOP * R {
            RAIL
        } else {
            WALL * (1.0 - cover) + ball * cover
        };
        [v; 3]
    })
}

/// Every radius fitted, px.
fn radii(params: Params) -> Vec<f64> {
    let frames: Vec<Frame> = (0..FRAMES).map(frame).collect();
    vision::track(&frames, params).radii().to_vec()
}

#[test]
fn the_lit_part_of_a_ball_is_not_its_outline() {
    let r = radii(Params::default());
    // The ball's whole outline, in most frames: its radius within 5 % (a shaded
    // limb's edge of a dozen pixels' radius, noise ±2 levels), never the lit part's.
    assert!(
        r.len() * 2 >= FRAMES,
        "found in {} of {FRAMES} frames",
        r.len()
    );
    assert!(
        r.iter().all(|&v| (v - R).abs() < 0.05 * R),
        "radii {r:?} for {R}"
    );
    // Without the check (the outermost edge always taken to agree), the lock is the
    // lit part, and every later fit keeps to its radius.
    let without = radii(Params {
        outer_agree: f64::INFINITY,
        ..Params::default()
    });
    let small = without
        .iter()
        .filter(|&&v| (v - LIT_R * R).abs() < 0.1 * R)
        .count();
    assert!(
        small * 2 >= without.len() && !without.is_empty(),
        "without the check: {without:?}"
    );
}
