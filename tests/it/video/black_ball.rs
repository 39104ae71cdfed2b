//! A black ball on a wall of its brightness that differs from it in colour (the
//! looks table's seeds 9 and 10): its outline in brightness mixes in the wall's own
//! edges (poor: scattered, or too little of it), so it is sought in the frame's
//! colour difference from the background, where the wall's colour stands against
//! none (`Params::dark_ball`, `Params::grey_levels`). Only for a dark grey ball: the
//! colour outlines of steel, white and coloured balls took in their shadows and the
//! motion's smear (seeds 15, 16 and 32 gave wrong μ_k).

use super::decoded_look;
use crate::common::paper_scene;
use crate::film::looks::Size;
use groovelab::vision::{self, Params};

#[test]
fn a_black_ball_on_a_wall_of_its_brightness_is_found_in_colour() {
    let Some((clip, frames)) = decoded_look("black_ball", 10, Size::Full) else {
        return;
    };
    let r = paper_scene().radius;
    let truth = clip.film.px_per_m();
    let times: Vec<f64> = (0..frames.len())
        .map(|k| k as f64 / clip.film.look.fps)
        .collect();
    let with = vision::track(&frames, Params::default());
    let tracks = vision::tracks(&with, times.clone(), r, None).unwrap();
    let c = tracks.calibration;
    // The scale within 2 of its ± of the truth.
    assert!(
        (c.px_per_m - truth).abs() <= 2.0 * c.px_per_m_sigma,
        "scale {:.1} ± {:.1} px/m for {truth:.1}",
        c.px_per_m,
        c.px_per_m_sigma
    );
    // Without it (no ball dark enough), the clip is refused.
    let without = vision::track(
        &frames,
        Params {
            dark_ball: 0.0,
            ..Params::default()
        },
    );
    let refused = vision::tracks(&without, times, r, None);
    assert!(refused.is_err(), "without the colour outline: tracked");
}
