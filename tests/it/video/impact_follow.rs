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

/// Seed 39's whole clip (86 frames, 720p; the impact at frame 39), tracked as the
/// command line tracks it: every centre of its first 55 frames lies within 0.35 of a
/// radius of its ball (the worst 0.31 R, the left ball at the impact). Without the
/// rule above, the follower's fit where the left ball was headed lies 0.75 R off one
/// frame after it bounced back; followed 3 frames on from a single fit (tracker 47),
/// the left ball, seen once at frame 8 and lost, was taken at frame 11 as a circle of
/// the wall where it had been, 0.79 R behind it (`Tracker::follow`). After frame 55
/// the right ball, rolling back from rest, is held 0.72 R behind itself for 8 frames
/// by the fits about where it lay: not yet judged here.
#[test]
fn no_ball_is_followed_into_the_other_across_the_impact_nor_from_one_fit() {
    let Some(centres) = centres_off(39, None) else {
        return;
    };
    let early: Vec<&(usize, f64)> = centres.iter().filter(|(k, _)| *k < 55).collect();
    assert!(early.len() > 40, "{} centres", early.len());
    let far: Vec<&&(usize, f64)> = early.iter().filter(|(_, off)| *off > 0.35).collect();
    assert!(
        far.is_empty(),
        "centres off their ball (frame, radii): {far:?}"
    );
}
