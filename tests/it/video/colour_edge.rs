//! The balls' edge in colour (tracker 17, issue 34): a coloured ball of the wall's
//! brightness shows its outline in colour where its brightness shows little, so a
//! circle fitted in brightness to its lit part, or to the wall's faint edges about
//! it, lies pixels off the edge its colour draws (`circle::colour_offset`). Where
//! the two lie apart by more than two circles of one ball may (`outer_agree`, 10 %
//! of the radius) the tracker gives no scale (`TracksError::ColourEdge`); by more
//! than a pixel of the colour planes, the radius's ± takes the difference in.

use super::decoded_look;
use crate::common::paper_scene;
use crate::film::looks::Size;
use groovelab::vision::{self, Params, TracksError};

/// The small look `seed` of the property tests, its H.264 copy decoded (once), and
/// a tracking of it: with `params`, the tracks (or why none); and the true radius, px.
fn look(seed: u64) -> Option<(impl Fn(Params) -> Result<vision::Tracks, TracksError>, f64)> {
    let (clip, frames) = decoded_look("colour_edge", seed, Size::Small)?;
    let scene = paper_scene();
    let truth = scene.radius * clip.film.px_per_m();
    let fps = clip.film.look.fps;
    let track = move |params: Params| {
        let t = vision::track(&frames, params);
        let times = (0..frames.len()).map(|k| k as f64 / fps).collect();
        vision::tracks(&t, times, scene.radius, None)
    };
    Some((track, truth))
}

/// The rule judged alone: tracker 20's outline in colour of a coloured ball
/// (`Params::colour_clear_rms`) and tracker 31's refit clear of the rail's edge
/// (`Params::rail_moves`) left out. With it, small look 6's outlines are in
/// colour (13.54 ± 0.67 px for 13.52: its edge in colour no longer a pixel off) and
/// small look 13's are circles of 14.7 px for 12.3, its edge in colour 2.6 px inside
/// them (no scale given either way).
fn with() -> Params {
    Params {
        colour_clear_rms: 0.0,
        rail_moves: f64::INFINITY,
        ..Params::default()
    }
}

/// The rule left out: colour never judged.
fn without() -> Params {
    Params {
        colour_edge_within: f64::INFINITY,
        ..with()
    }
}

/// Small look 13 (a green-blue ball on a dark cluttered wall of its brightness):
/// every outline in brightness is the ball's lit part, 8.2–9.2 px for 12.3, whose
/// radii agree from frame to frame. Its edge in colour lies some 1.7 px outside
/// them: no scale. Without the rule: a scale 28 % off, beyond 2 of its ±.
#[test]
fn a_lit_part_off_the_balls_edge_in_colour_gives_no_scale() {
    let Some((track, truth)) = look(13) else {
        return;
    };
    let with = track(with());
    assert!(
        matches!(with, Err(TracksError::ColourEdge { offset_px, .. }) if offset_px > 1.0),
        "{with:?}"
    );
    let Ok(t) = track(without()) else {
        panic!("tracked without the rule");
    };
    let c = t.calibration;
    assert!(
        (c.radius_px - truth).abs() > 2.0 * c.radius_px_sigma,
        "without the rule: {} ± {} px for {truth}",
        c.radius_px,
        c.radius_px_sigma
    );
}

/// Small look 6 (a glossy coloured ball on a dark grainy wall): its edge in colour
/// lies about a pixel inside its outlines (under 10 %): tracked, the radius's ± at
/// least that far; without the rule the ± is under 0.6 px (0.57 since tracker 43,
/// whose outlines leave out edges inside which the wall lies in shadow).
#[test]
fn an_edge_in_colour_a_pixel_off_widens_the_radius_s_plus_minus() {
    let Some((track, truth)) = look(6) else {
        return;
    };
    let with = track(with());
    let c = with.expect("tracked").calibration;
    assert!(
        c.radius_px_sigma >= 1.0 && (c.radius_px - truth).abs() <= 2.0 * c.radius_px_sigma,
        "{} ± {} px for {truth}",
        c.radius_px,
        c.radius_px_sigma
    );
    let Ok(t) = track(without()) else {
        panic!("tracked without the rule");
    };
    assert!(
        t.calibration.radius_px_sigma < 0.6,
        "without the rule: ± {}",
        t.calibration.radius_px_sigma
    );
}

/// Small look 71 (glossy balls of 13.2 px on a light striped wall, 300p at 100
/// frames/s): their edge in colour lies 3.3 px inside their outlines (25 % of
/// their radius), but the outlines are the balls' (within 1 % of the truth): the
/// colour fades before the glossy limb, and both balls' stacked pictures (13.15,
/// 13.16 px) agree with them. A scale is given (tracker 62), the radius within its
/// ±, which holds the colour's offset; before, none (`ColourEdge`). (The command line
/// takes the radius from the stacked pictures first, where they give tracks, as it
/// did before: 0.160 ± 0.008 for 0.17 on this look; the next test is one where they
/// give none.)
#[test]
fn an_edge_in_colour_inside_outlines_the_pictures_confirm_widens_the_plus_minus() {
    let Some((clip, frames, tracker)) = super::colour_settled::small_71() else {
        return;
    };
    let (r, _, times) = super::look_truth(clip, frames.len());
    let truth = r * clip.film.px_per_m();
    let c = vision::tracks(tracker, times, r, None)
        .expect("tracked")
        .calibration;
    let off = c.colour_edge_px.expect("the colour's offset let through");
    assert!(off < -0.1 * c.radius_px, "{off} px");
    assert!(
        c.radius_px_sigma >= off.abs() && (c.radius_px - truth).abs() <= c.radius_px_sigma,
        "{} ± {} px for {truth}",
        c.radius_px,
        c.radius_px_sigma
    );
}

/// Small look 34 (a wooden ball on a light wood grain, uneven light, 300p at 30
/// frames/s), tracked as the command line tracks it: its edge in colour lies 2.5 px
/// inside outlines of 11.62 px (the truth 11.44), which both balls' stacked pictures
/// confirm (11.63, 11.56 px) but which give no tracks of their own. Refused before
/// tracker 62; now a scale within its ± (and 5 %) of the truth, whose line says why
/// its ± is wide.
#[test]
fn a_look_whose_pictures_confirm_its_outlines_is_tracked_with_a_wide_plus_minus() {
    let Some((clip, t)) =
        super::tracked_as_the_command_line("colour_edge_cli", (34, Size::Small, None))
    else {
        return;
    };
    super::assert_scale_within(&clip, &t, 1.0, 0.05);
    let c = &t.tracks.calibration;
    assert!(
        c.colour_edge_px.is_some_and(|o| o < -0.1 * c.radius_px),
        "{c:?}"
    );
    assert!(
        t.notes
            .iter()
            .any(|n| n.starts_with("scale ") && n.contains("their edge in colour lies 2.")),
        "{:?}",
        t.notes
    );
}
