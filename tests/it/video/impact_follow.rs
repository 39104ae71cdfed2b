//! The follower near the impact (tracker 15): a ball not found by its blob is looked
//! for where its last two fits put it now, and the two balls' predictions run on
//! across their impact (each as it moved before, into the other). Where the two
//! predictions overlap, neither is followed (`Tracker::follow`): the looks table's
//! seed 39 (a white ball on a checkered wall, 100 frames/s, crf 36) had a circle
//! fitted 32 px from its left ball, where that ball was headed one frame after it
//! bounced back, and kept (centre RMS 4.70 px; 1.89 with the rule).

use crate::common::paper_scene;
use crate::film::looks::Size;
use groovelab::input::video::tracked;

/// The full-size look `seed` of the looks table (its `first` frames where given) in
/// its H.264 copy, tracked as the command line tracks it: per centre given, its frame
/// and its distance from the nearest true ball in radii (`None` without ffmpeg).
pub(crate) fn centres_off(seed: u64, first: Option<usize>) -> Option<Vec<(usize, f64)>> {
    let scene = paper_scene();
    let (clip, path) = super::h264_first("impact_follow", seed, Size::Full, first)?;
    let options = super::look_options(&clip);
    let done = tracked::track(&path, &options, &groovelab::study::Quiet)
        .unwrap()
        .unwrap();
    let r = scene.radius * clip.film.px_per_m();
    let mut out = Vec::new();
    for b in &done.view.balls {
        for (k, c) in b.centre.iter().enumerate() {
            let Some(c) = c else { continue };
            let c = (f64::from(c.0), f64::from(c.1));
            let truth = clip.film.ball_nearest(k, c).centre;
            out.push((k, (c.0 - truth.0).hypot(c.1 - truth.1) / r));
        }
    }
    Some(out)
}

/// Checks that the full-size look `seed` (its `first` frames where given), tracked as
/// the command line tracks it, gives more than `at_least` centres, each within
/// `within` radii of its ball.
pub(crate) fn assert_on_their_balls(
    (seed, first): (u64, Option<usize>),
    at_least: usize,
    within: f64,
) {
    let Some(centres) = centres_off(seed, first) else {
        return;
    };
    assert!(centres.len() > at_least, "{} centres", centres.len());
    let far: Vec<&(usize, f64)> = centres.iter().filter(|(_, off)| *off > within).collect();
    assert!(
        far.is_empty(),
        "centres off their ball (frame, radii): {far:?}"
    );
}

/// Every centre of seed 39 lies within 0.35 of a radius of its ball. On the look's
/// first 50 frames of its 86 (720p, the suite's minute; the impact at frame 39): the
/// worst 0.31 R off, the left ball's fit in the impact's frame (tracker 48; 0.12 R on
/// tracker 47, which kept no fit there). Up to tracker 47, without the rule the
/// follower's fit where the left ball was headed, at frame 40, lay 0.70 R off (on the
/// whole clip 0.75 R); since tracker 48 (a ball seen once followed into the next
/// frame only) the clip no longer reaches the rule: without it the worst is 0.12 R.
/// Kept as seed 39's check; the rule itself is not guarded here.
#[test]
fn no_ball_is_followed_into_the_other_across_the_impact() {
    assert_on_their_balls((39, Some(50)), 30, 0.35);
}
