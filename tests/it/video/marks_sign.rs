//! The marks' sign is not voted by a highlight (issue 34, the small looks' seed 27:
//! steel balls with a dark mark, 50 frames/s, 270p). The first marks found, before
//! their sign is settled, were mostly the steel's light highlight, so the sign was
//! settled light and the highlight, at one place of the disc while the ball rolled,
//! was taken for the mark in the frames after (kept 4.8–16.5 px from the drawn one).
//! A vote of a spot that stayed put in its disc while its ball rolled is left out.

use super::{decoded_look, marks_against_truth};
use crate::film::looks::Size;
use groovelab::vision::{self, Params};

#[test]
fn a_highlight_does_not_settle_the_marks_sign() {
    let Some((clip, frames)) = decoded_look("marks_sign", 27, Size::Small) else {
        return;
    };
    // Tracker 43's cast shadow rule left out: with it the steel's shaded limb,
    // read as the wall in shadow, moves the first outlines, and the votes before
    // the sign is settled are others (a mechanism this look no longer shows).
    let params = Params {
        shadow_outside: f64::INFINITY,
        ..Params::default()
    };
    let tracker = vision::track(&frames, params);
    // Each mark kept: its error against the drawn one, px, its frame and contrast.
    let kept = marks_against_truth(&clip, &tracker, &tracker.params.marks);
    let worst = kept.iter().map(|p| p.0).fold(0.0, f64::max);
    assert!(
        worst < 3.0,
        "a mark {worst:.1} px from the drawn one: {kept:?}"
    );
    // Whatever was found after the vote is of the drawn mark's sign (darker).
    let found: Vec<f64> = tracker
        .frames
        .iter()
        .flatten()
        .flatten()
        .filter_map(|f| f.mark.map(|m| m.contrast))
        .collect();
    let light = found.iter().filter(|c| **c > 0.0).count();
    assert!(
        light <= params.mark_votes,
        "{light} of {} marks found lighter than the ball",
        found.len()
    );
}
