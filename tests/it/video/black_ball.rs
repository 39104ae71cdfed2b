//! A black ball on a wall of its brightness that differs from it in colour (the
//! looks table's seeds 9 and 10): its outline in brightness mixes in the wall's own
//! edges (poor: scattered, or too little of it), so it is sought in the frame's
//! colour difference from the background, where the wall's colour stands against
//! none (`Params::dark_ball`, `Params::grey_levels`). Only for a dark grey ball: the
//! colour outlines of steel, white and coloured balls took in their shadows and the
//! motion's smear (seeds 15, 16 and 32 gave wrong μ_k). And balls the shadow test
//! takes away (a ball of the wall's hue, darker than it, dims the wall as a shadow
//! does): tracked again with no pixel taken for a shadow. A grey ball of any
//! brightness found in too few frames is tracked once more with its outline sought
//! in colour where the wall about it is of one colour (`Params::grey_in_colour`).
//! (Each retry's test holds the note `track` writes only when the tracking before
//! was refused; tracking the clip again with the earlier settings alone, to see it
//! refused, cost four seconds of the suite's minute.)

use groovelab::vision::Params;

/// The scale within 2 of its ± of the truth; without the rule (no ball dark
/// enough), the clip is refused. On the look's first 24 frames of its 58 (720p,
/// the suite's minute): scale −0.5 ± off, and "neither ball was found in a third
/// of the frames" without the rule.
#[test]
fn a_black_ball_on_a_wall_of_its_brightness_is_found_in_colour() {
    super::scaled_with_refused_without(
        "black_ball",
        (10, crate::film::looks::Size::Full, Some(24)),
        Params {
            dark_ball: 0.0,
            ..Params::default()
        },
    );
}

/// Full look 55 (black balls of 42.8 px with a light mark on a wood-grain wall of
/// their brightness, a rail alike, 720p at 50 frames/s; its first 24 frames of 48):
/// the balls' limb differs from the wall by a few levels, so at the floor of 10 no
/// ball is found. Tracked again at the floor of `faint_levels`, as the command line
/// tracks it, it gives a scale within 2 of its ± (and 3 %) of the truth and says how:
/// the note, written only where the first tracking found no ball, shows the retry is
/// what tracks it.
/// (Small look 55, the same look at 300p, showed it on the machines the test was
/// first set on; on the machines of 2026-12-03 on, with Debian's ffmpeg 5.1.9, its clip
/// stays "no ball found".)
#[test]
fn a_dark_ball_no_ball_stands_out_of_is_tracked_again_at_a_lower_floor() {
    super::assert_tracked_to_its_scale(
        "black_ball",
        (55, crate::film::looks::Size::Full, Some(24)),
        0.03,
        "tracked twice: no ball stood out from the background by 10 levels",
    );
}

/// Full look 168 (coloured balls of 35.4 px of the wall's own hue, darker than it, on a
/// fine wood grain, a rail alike, 720p at 100 frames/s, no compression; its first 32
/// frames of 95): most of each ball is darker than the wall by less than half and of
/// its hue, which the shadow test takes for a shadow, so no ball is found at the
/// floor of 10 nor at 6. Tracked a third time with such pixels taken as the balls',
/// as the command line tracks it, it gives a scale within 2 of its ± (and 3 %) of the
/// truth and says how: the note, written only where both earlier trackings found no
/// ball, shows the third tracking is what tracks it.
#[test]
fn a_ball_of_the_walls_hue_taken_for_a_shadow_is_tracked_a_third_time() {
    super::assert_tracked_to_its_scale(
        "wall_hue",
        (168, crate::film::looks::Size::Full, Some(32)),
        0.03,
        "tracked three times: no ball stood out from the background by 10 levels, nor by 6",
    );
}

/// Small look 48 (coloured balls with a light mark on a dark grainy wall, 300p at 50
/// frames/s, no compression), whose balls are found with the shadow test in too few
/// frames: tracked again with no pixel taken for a shadow, as the command line
/// tracks it, it gives a scale within 2 of its ± (and 5 %) of the truth and says
/// how: the note, written only where the first tracking found the balls in too few
/// frames, shows the second tracking is what tracks it.
#[test]
fn a_ball_found_in_too_few_frames_is_tracked_again_without_the_shadow_test() {
    super::assert_tracked_to_its_scale(
        "wall_hue",
        (48, crate::film::looks::Size::Small, None),
        0.05,
        "tracked twice: neither ball was found in a third of the frames",
    );
}

/// Small look 11 (steel balls on a wood grain, uneven light, 270p at 50 frames/s,
/// crf 37): the outline in brightness of each ball is poor in most frames (its lit
/// rim of the wall's brightness, its shaded limb beside the grain's dark lines), so
/// neither ball is found in a third of the frames, with the shadow test or without.
/// Tracked a third time with a grey ball's outline sought in colour, as the command
/// line tracks it, it gives a scale within 2 of its ± (and 5 %) of the truth and
/// says how: the note, written only where both trackings in brightness (with the
/// shadow test and without) were refused, shows the third is what tracks it.
#[test]
fn a_grey_ball_found_in_too_few_frames_is_tracked_again_in_colour() {
    super::assert_tracked_to_its_scale(
        "grey_ball",
        (11, crate::film::looks::Size::Small, None),
        0.05,
        "tracked three times: neither ball was found in a third of the frames by its outline in brightness",
    );
}

/// Full look 217 (black balls with a light mark on a dark cluttered wall, 480p at 100
/// frames/s, no compression): each ball's body, darker than the wall and of its hue,
/// is taken for a shadow, and its highlight and mark are two things apart, so more
/// than two balls are seen in most frames. Tracked again with such pixels taken as
/// the balls', as the command line tracks it, its first fits lock on a part of a ball
/// (22.7 px for 28.7) that the clear outlines contradict; tracked a third time from
/// theirs, it gives a scale within 2 of its ± (and 3 %) of the truth and says how:
/// the note, written only where the first tracking was refused as crowded and the
/// second contradicted, shows the third is what tracks it. (Its first 32 frames need
/// no third tracking, its first 56 neither: the whole clip is what shows it.)
#[test]
fn a_dark_balls_parts_seen_as_more_balls_are_tracked_again_without_the_shadow_test() {
    let Some((clip, t)) =
        super::tracked_as_the_command_line("crowded", (217, crate::film::looks::Size::Full, None))
    else {
        return;
    };
    super::assert_scale_within(&clip, &t, 2.0, 0.03);
    assert!(
        t.notes.iter().any(
            |n| n.starts_with("tracked three times: more than two balls in")
                && n.ends_with("; tracked a third time from that radius")
        ),
        "{:?}",
        t.notes
    );
}
