//! A coloured ball whose outline in brightness takes in what lies about it (the
//! looks table's seed 26: glossy magenta balls of 12.35 px on a dark rail, before a
//! light cluttered wall, at 1080p and crf 34; their outlines in brightness were
//! circles of 14.9–16.9 px through the ball's top and the rail's edge, and the
//! first lock set the radius at 14.9 px, so the balls' own outlines were left out
//! as too small): where its outline in colour is clear (`Params::colour_clear_rms`)
//! and lies farther from it than two circles of one ball differ, the outline in
//! colour is the ball's.

use groovelab::vision::Params;

/// The scale within 2 of its ± of the truth; without the rule (no outline in colour
/// clear enough), and without tracker 31's refit clear of the rail's edge
/// (`rail_moves`), which finds these balls' outlines too, the clip is refused.
#[test]
fn a_coloured_ball_is_its_outline_in_colour_where_brightness_takes_in_the_rail() {
    super::scaled_with_refused_without(
        "coloured_ball",
        (26, crate::film::looks::Size::Full, None),
        Params {
            colour_clear_rms: 0.0,
            rail_moves: f64::INFINITY,
            ..Params::default()
        },
    );
}
