//! A ball seen in one frame only has no velocity yet: the follower predicts it where
//! it was, which a rolling ball has left a few frames on. Followed 3 frames on (tracker
//! 47), the window there held a circle of the wall (full look 39: the left ball, seen
//! once at frame 8 and lost, taken at frame 11 as a circle 33 px behind it; nothing
//! there gave a fit in frames 9 and 10). Here the wall's circle is a disc faintly
//! lighter than the wall (too faint for the coarse look, not for a fit: a spot of
//! light) that shows from the third frame after a ball is seen once, where it was
//! seen: a ball seen once is followed into the next frame only (tracker 48), and the
//! disc is never taken for it; followed 3 frames on, it was, and then, two fits of a
//! ball at rest, in every frame after.

// The balls' radius, their centres' height and level, the wall's and the faint disc's.
use super::follow_gap::{BALL, CY, FAINT, R, WALL};
use groovelab::vision::{self, Frame, Params};

const W: u32 = 600;
const H: u32 = 120;
/// The left ball, rolling right by `STEP` a frame, is seen in frame `ONCE` only of
/// the frames up to `ONCE + 3`, then from `BACK` on; the right ball stands still
/// at `RIGHT_X` throughout.
const STEP: f64 = 12.0;
const ONCE: usize = 8;
const BACK: usize = 14;
const X0: f64 = 60.0;
const RIGHT_X: f64 = 520.0;
const FRAMES: usize = 22;

fn left_x(k: usize) -> f64 {
    X0 + STEP * k as f64
}

/// The balls' true centres in frame `k`.
fn balls(k: usize) -> Vec<(f64, f64)> {
    let mut out = vec![(RIGHT_X, CY)];
    if k == ONCE || k >= BACK {
        out.push((left_x(k), CY));
    }
    out
}

/// Frame `k`: the balls, and from `ONCE + 3` on the faint disc where the left ball
/// was seen once.
fn frame(k: usize) -> Frame {
    let centres = balls(k);
    let seed = 0x0f01_10ee_u64.wrapping_add(k as u64 * 7919);
    super::drawn_frame((W, H), seed, 1, |x, y| {
        let at = (f64::from(x), f64::from(y));
        let faint = if k >= ONCE + 3 {
            super::disc_cover(at, (left_x(ONCE), CY), R)
        } else {
            0.0
        };
        let mut v = WALL * (1.0 - faint) + FAINT * faint;
        for &c in &centres {
            let b = super::disc_cover(at, c, R);
            v = v * (1.0 - b) + BALL * b;
        }
        [v; 3]
    })
}

#[test]
fn a_ball_seen_once_is_followed_into_the_next_frame_only() {
    let frames: Vec<Frame> = (0..FRAMES).map(frame).collect();
    let t = vision::track(&frames, Params::default());
    let on_disc: Vec<usize> = t
        .frames
        .iter()
        .enumerate()
        .filter(|(k, fixes)| {
            !balls(*k).iter().any(|b| (b.0 - left_x(ONCE)).abs() < R)
                && fixes.iter().flatten().any(|f| {
                    let c = f.outline.circle;
                    (c.x - left_x(ONCE)).hypot(c.y - CY) < 2.0
                })
        })
        .map(|(k, _)| k)
        .collect();
    assert!(
        on_disc.is_empty(),
        "frames with the faint disc taken for the ball: {on_disc:?}"
    );
    // The ball is seen once and again from `BACK` (the disc did not stop it).
    let seen = |k: usize| {
        t.frames.get(k).is_some_and(|f| {
            f.iter()
                .flatten()
                .any(|f| (f.outline.circle.x - left_x(k)).abs() < 2.0)
        })
    };
    assert!(
        seen(ONCE) && (BACK..FRAMES).all(seen),
        "the left ball not tracked"
    );
}
