//! A glossy highlight is found at its fixed place of the disc even in frames crowded
//! with stronger spots (issue 34, the looks table's seed 9: black glossy balls with a
//! light mark, a same-brightness cluttered wall, a lighter rail, 30 frames/s). Where
//! the drawn mark was behind the rail, the highlight was taken for the mark (17.9 and
//! 22.5 px off): each disc kept its 4 strongest spots only, and in the frames where
//! the rail's edge gave four stronger ones the highlight was not among them, so it
//! stood out at its place in under 70 % of the frames and was not known as fixed.
//! With 8 spots a disc it is, and no mark is taken there.

use super::{decoded_look, marks_against_truth};
use crate::film::looks::Size;
use groovelab::vision::{self, Params};

#[test]
fn a_highlight_in_discs_crowded_with_the_rails_spots_is_not_the_mark() {
    let Some((clip, frames)) = decoded_look("marks_crowded", 9, Size::Full) else {
        return;
    };
    let tracker = vision::track(&frames, Params::default());
    // Each mark kept: its error against the drawn one, px, its frame and contrast.
    let kept = marks_against_truth(&clip, &tracker, &tracker.params.marks);
    let worst = kept.iter().map(|p| p.0).fold(0.0, f64::max);
    assert!(
        worst < 3.0,
        "a mark {worst:.1} px from the drawn one: {kept:?}"
    );
    assert!(kept.len() >= 3, "{} marks kept", kept.len());
}
