//! How unsure a ball's edge is, in the scale's ±: on the small looks where the
//! fitted radius lies a little inside a light ball on a dark wall (or outside a
//! dark one on a light wall), and on a full look where a large ball lies a quarter
//! of a pixel inside, the scale is within 2 of its ± of the truth; at the least
//! uncertainty the project's plain renders need (0.05 px) and without the lean of
//! a shaded ball's edge (`Params::edge_lean`), each was beyond 2 ±. (Since tracker
//! 54 the floor itself, `Params::edge_systematic` 0.2 px, covers the two small
//! looks, their balls being 12–13 px: the lean, 3 px² / R, is 0.23–0.24 px there,
//! and either alone keeps them within 2 ±.)

use groovelab::vision;

use crate::film::looks::{Clip, Size};

/// Small looks 4 (a white ball on a dark checkered wall) and 29 (a glossy one on a
/// dark plain wall), H.264 as the looks table writes them: radii about 1 % small,
/// beyond 2 of the ± without the lean at the plain renders' floor.
#[test]
fn a_shaded_balls_lean_is_in_the_scales_plus_minus() {
    for seed in [4, 29] {
        let Some((clip, frames)) = super::decoded_look("video_edge_lean", seed, Size::Small) else {
            return;
        };
        // Without the lean, and at the least uncertainty of the project's plain
        // renders (0.05 px; the default covers these looks alone).
        let (with, without) = scale_z(&clip, &frames, |p| {
            p.edge_lean = 0.0;
            p.edge_systematic = 0.05;
        });
        assert!(with.abs() <= 2.0, "look {seed}: scale {with:+.2} ± off");
        assert!(
            without.abs() > 2.0,
            "look {seed} without the lean: {without:+.2} ± off"
        );
    }
}

/// Full look 63 (a wooden ball, R 38.7 px, on a dark grainy wall, 720p at 240
/// frames/s), its first 60 frames: the fitted radius lies about 0.29 px (0.7 %)
/// inside the ball, whose other terms give a ± of some 0.12 px: 2.4 of it at the
/// plain renders' least uncertainty (0.05 px), 1.5 at the default (0.2 px).
#[test]
fn a_large_balls_edge_inside_it_is_in_the_scales_plus_minus() {
    let Some((clip, frames)) = super::decoded_first("video_edge_least", 63, Size::Full, 60) else {
        return;
    };
    let (with, without) = scale_z(&clip, &frames, |p| p.edge_systematic = 0.05);
    assert!(with.abs() <= 2.0, "scale {with:+.2} ± off");
    assert!(
        without.abs() > 2.0,
        "at 0.05 px: {without:+.2} ± off (with {with:+.2})"
    );
}

/// How far the scale of `clip`'s decoded `frames` lies from the truth, in its ±:
/// tracked with the default parameters, and the same fits calibrated again with
/// `change` made to the parameters.
fn scale_z(
    clip: &Clip,
    frames: &[vision::Frame],
    change: impl FnOnce(&mut vision::Params),
) -> (f64, f64) {
    let (r, truth, times) = super::look_truth(clip, frames.len());
    let mut tracker = vision::track(frames, vision::Params::default());
    let z = |t: &vision::Tracker| {
        let c = vision::tracks(t, times.clone(), r, None)
            .unwrap()
            .calibration;
        (c.px_per_m - truth) / c.px_per_m_sigma
    };
    let with = z(&tracker);
    change(&mut tracker.params);
    (with, z(&tracker))
}
