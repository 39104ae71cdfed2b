//! The lean of a shaded ball's edge in the scale's ±: on the small looks where the
//! fitted radius lies a little inside a light ball on a dark wall (or outside a
//! dark one on a light wall), the scale is within 2 of its ± of the truth; without
//! the lean (`Params::edge_lean` 0) it was beyond.

use groovelab::vision;

use crate::film::looks::Size;

/// Small looks 4 (a wooden ball on a dark cluttered wall) and 29 (a glossy one on a
/// dark plain wall), H.264 as the looks table writes them: radii 1.1–1.3 % small,
/// 2.2 of the ± without the lean.
#[test]
fn a_shaded_balls_lean_is_in_the_scales_plus_minus() {
    for seed in [4, 29] {
        let Some((clip, frames)) = super::decoded_look("video_edge_lean", seed, Size::Small) else {
            return;
        };
        let (r, truth, times) = super::look_truth(&clip, frames.len());
        let mut tracker = vision::track(&frames, vision::Params::default());
        let z = |tracker: &vision::Tracker| {
            let c = vision::tracks(tracker, times.clone(), r, None)
                .unwrap()
                .calibration;
            (c.px_per_m - truth) / c.px_per_m_sigma
        };
        let with = z(&tracker);
        assert!(with.abs() <= 2.0, "look {seed}: scale {with:+.2} ± off");
        tracker.params.edge_lean = 0.0;
        let without = z(&tracker);
        assert!(
            without.abs() > 2.0,
            "look {seed} without the lean: {without:+.2} ± off"
        );
    }
}
