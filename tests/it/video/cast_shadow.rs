//! A ball's cast shadow beside its dark limb is no part of its outline
//! (`vision::tracker::in_the_walls_shadow`): an edge point whose inside, 2 px in, is
//! the wall in shadow (darker, its colour dimmed alike) is the shadow's edge. Steel
//! balls on a plain wall with moving shadows (small looks 135 and 156, never tuned
//! on) had the shadow and the limb make one dark ring, its outer edge fitted as the
//! ball: radii of 16.8 px for 14.4 and a scale 3.2 of its ± off, μ_k 0.024 low.

use super::decoded_look;
use crate::film::looks::Size;
use groovelab::vision::background::Small;
use groovelab::vision::tracker::in_the_walls_shadow;
use groovelab::vision::{self, Frame, Params};
use image::{Rgb, RgbImage};
use proptest::prelude::*;

/// A frame 16 px square of one colour.
fn plain(rgb: [u8; 3]) -> Frame {
    Frame::from_rgb(&RgbImage::from_pixel(16, 16, Rgb(rgb)))
}

/// `rgb` dimmed to `k` of its light, channel by channel (a shadow).
fn dimmed(rgb: [u8; 3], k: f64) -> [u8; 3] {
    rgb.map(|c| (f64::from(c) * k).round() as u8)
}

/// Whether a frame all of `now` reads, against a background all of `wall`, as the
/// wall in shadow at its middle.
fn reads_as_shadow(wall: [u8; 3], now: [u8; 3]) -> bool {
    let bg = Small::of(&plain(wall), 1);
    in_the_walls_shadow(&plain(now), &bg, (8.0, 8.0), &Params::default())
}

proptest! {
    /// The wall dimmed to 55–90 % of its light is its shadow; the wall itself is
    /// not, nor a grey ball on a coloured wall, however bright, nor anything
    /// brighter than the wall or darker than half of it.
    #[test]
    fn the_walls_shadow_is_told_from_a_ball(
        wall in prop::array::uniform3(60u8..=230),
        k in 0.55f64..0.9,
        grey in 20u8..=230,
        dark in 0.05f64..0.4,
    ) {
        let lit = f64::from(wall.iter().map(|&c| u32::from(c)).sum::<u32>()) / 3.0;
        // Darker by at least the test's 4 levels of luma (video range: 219/255).
        prop_assume!(lit * (1.0 - k) * 219.0 / 255.0 > 6.0);
        prop_assert!(reads_as_shadow(wall, dimmed(wall, k)), "{wall:?} at {k}");
        prop_assert!(!reads_as_shadow(wall, wall));
        prop_assert!(!reads_as_shadow(wall, wall.map(|c| c.saturating_add(20))));
        prop_assert!(!reads_as_shadow(wall, dimmed(wall, dark)), "{wall:?} at {dark}");
        let spread = wall.iter().max().unwrap() - wall.iter().min().unwrap();
        if spread >= 60 {
            prop_assert!(!reads_as_shadow(wall, [grey; 3]), "grey {grey} on {wall:?}");
        }
    }
}

/// The balls' radius the tracker learns from the small look `seed` (all its frames)
/// with the default parameters and with `shadow_outside` infinite (the rule off),
/// each over the true radius; `None` without ffmpeg.
fn radius_over_truth(seed: u64) -> Option<(f64, f64)> {
    let (clip, frames) = decoded_look("cast_shadow", seed, Size::Small)?;
    let truth = crate::common::paper_scene().radius * clip.film.px_per_m();
    let ratio = |params: Params| {
        let tracker = vision::track(&frames, params);
        groovelab::vision::tracker::median(tracker.radii()).map_or(f64::NAN, |r| r / truth)
    };
    let without = Params {
        shadow_outside: f64::INFINITY,
        ..Params::default()
    };
    Some((ratio(Params::default()), ratio(without)))
}

/// Steel balls beside their cast shadows are fitted within 8 % of their radius
/// (the median of the frames' fits): 0.94 and 1.03 of it. Without the rule
/// (`shadow_outside` infinite) 1.17 and 1.14: the shadow's edge taken in.
#[test]
fn a_steel_balls_cast_shadow_is_not_its_outline() {
    for seed in [135, 156] {
        let Some((with, without)) = radius_over_truth(seed) else {
            return;
        };
        assert!(
            (with - 1.0).abs() < 0.08 && without > 1.08,
            "small look {seed}: radius {with:.3} of the truth, {without:.3} without the rule"
        );
    }
}
