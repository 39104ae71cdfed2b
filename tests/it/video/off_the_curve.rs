//! A single fit along the groove off its ball's smooth motion (tracker 15,
//! `Params::off_the_curve`): held against the parabola through its ball's
//! neighbouring fits, not only the straight line between two of them with a
//! deceleration of 10 m/s² allowed (`max_deceleration`), which a few frames' gap
//! widens beyond the fits' scatter. The looks table's seed 6 (a glossy ball on a
//! dark grainy wall, 30 frames/s) kept one fit 7.8 px (0.32 R) along the groove
//! from its ball, its neighbours within a pixel.

/// Every centre of seed 6 lies within 0.15 R of its ball (the worst on tracker 26:
/// frame 16's right ball, 0.138 R, 3.3 px along the groove; then frame 12's, 0.055 R).
#[test]
fn a_fit_off_its_balls_smooth_motion_is_left_out() {
    super::impact_follow::assert_on_their_balls((6, None), 25, 0.15);
}
