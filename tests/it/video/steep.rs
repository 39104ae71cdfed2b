//! A clip shown turned (a phone's rotation tag that ffmpeg applies, a camera on its
//! side): the balls roll up and down the picture. The tracker takes the groove across
//! the picture with the rail below the balls; on a line steeper than
//! `STEEPEST_GROOVE_DEG` it gave tracks "turned to" a groove at −88° from one ball
//! found in 9 of 25 frames, and `fit` then found no impact. Such a clip is refused,
//! saying the line's angle and how to turn the video back; the same balls rolling
//! across the picture are tracked.

use groovelab::vision::tracks::STEEPEST_GROOVE_DEG;
use groovelab::vision::{self, Frame, Params, TracksError};

/// The balls' radius and level, the wall's (px, RGB levels), the frames and their rate.
const R: f64 = 16.0;
const BALL: f64 = 200.0;
const WALL: f64 = 90.0;
const FRAMES: usize = 24;
const FPS: f64 = 30.0;

/// The balls' centres in frame `k` along the groove (px from its start) and their
/// place across it: the left comes at 15 px a frame, the right at 5.
fn along(k: usize) -> [(f64, f64); 2] {
    let k = k as f64;
    [(150.0 + 15.0 * k, 100.0), (750.0 - 5.0 * k, 100.0)]
}

/// Frame `k`, 900 px along the groove and 200 across, drawn `upright` (the groove
/// running down the picture) or across it.
fn frame(k: usize, upright: bool) -> Frame {
    let size = if upright { (200, 900) } else { (900, 200) };
    let seed = 0x5ee9_u64.wrapping_add(k as u64 * 7919);
    super::drawn_frame(size, seed, 1, |x, y| {
        let at = (f64::from(x), f64::from(y));
        let mut v = WALL;
        for (s, c) in along(k) {
            let centre = if upright { (c, s) } else { (s, c) };
            let b = super::disc_cover(at, centre, R);
            v = v * (1.0 - b) + BALL * b;
        }
        [v; 3]
    })
}

fn tracked(upright: bool) -> Result<vision::Tracks, TracksError> {
    let frames: Vec<Frame> = (0..FRAMES).map(|k| frame(k, upright)).collect();
    let t = vision::track(&frames, Params::default());
    let times = (0..FRAMES).map(|k| k as f64 / FPS).collect();
    vision::tracks(&t, times, 0.0275, None)
}

#[test]
fn balls_rolling_up_the_picture_are_refused_saying_so() {
    match tracked(true) {
        Err(e @ TracksError::Steep { groove_deg }) => {
            assert!(
                (groove_deg.abs() - 90.0).abs() < 2.0 && groove_deg.abs() > STEEPEST_GROOVE_DEG,
                "{groove_deg}"
            );
            let said = e.to_string();
            assert!(
                said.contains("90° from across the picture") && said.contains("rotate=0"),
                "{said}"
            );
            assert!(
                e.helped_by() == vision::Handles::default(),
                "no handle helps"
            );
        }
        other => panic!("not refused as steep: {other:?}"),
    }
    // Across the picture the same balls are tracked, the groove level.
    let across = tracked(false).unwrap();
    let g = across.calibration.groove_deg;
    assert!(g.abs() < 1.0, "groove {g}°");
}
