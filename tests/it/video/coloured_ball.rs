//! A coloured ball whose outline in brightness takes in what lies about it (the
//! looks table's seed 26: glossy magenta balls of 12.35 px on a dark rail, before a
//! light cluttered wall, at 1080p and crf 34; their outlines in brightness were
//! circles of 14.9–16.9 px through the ball's top and the rail's edge, and the
//! first lock set the radius at 14.9 px, so the balls' own outlines were left out
//! as too small): where its outline in colour is clear (`Params::colour_clear_rms`)
//! and lies farther from it than two circles of one ball differ, the outline in
//! colour is the ball's.

use super::decoded_look;
use crate::common::paper_scene;
use crate::film::looks::Size;
use groovelab::vision::{self, Params};

#[test]
fn a_coloured_ball_is_its_outline_in_colour_where_brightness_takes_in_the_rail() {
    let Some((clip, frames)) = decoded_look("coloured_ball", 26, Size::Full) else {
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
    // Without it (no outline in colour clear enough), the clip is refused.
    let without = vision::track(
        &frames,
        Params {
            colour_clear_rms: 0.0,
            ..Params::default()
        },
    );
    let refused = vision::tracks(&without, times, r, None);
    assert!(refused.is_err(), "without the outline in colour: tracked");
}
