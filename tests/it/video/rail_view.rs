//! What a ball behind a rail shows (issue 34, tracker 26): its top, down to the
//! rail, or the whole of it; never its bottom without its sides. Two level edges (a
//! moving shadow's or a compression block's along the rail's lower edge, or a ball's
//! top and that edge) fit a circle through their top and bottom; taken for the first
//! lock, its radius and polarity lose the balls (`Params::rail_view_deg`,
//! `circle::Outline::seen_over_a_rail`).

use super::drawn_frame;
use crate::film::looks::Size;
use groovelab::vision::{Params, circle};
use proptest::prelude::*;

/// Small looks 28 (black balls with a light mark on a light plain wall, a darker
/// rail, moving shadows, 270p at 60 frames/s, crf 36) and 165 (white balls with a
/// dark mark on a light striped wall, a darker rail, uneven light, a static shadow,
/// tilted −2.3°, 270p at 60 frames/s): with the rule both scales are within 2 of
/// their ± of the truth; without it one of them is refused. Which one turns on the
/// machine's encoding: on some machines look 28's first lock is a circle of 9.5 px
/// below the rail; on others (2026-12-03, Debian's ffmpeg 5.1.9 on AVX2) look 165's
/// is one of 26.8 px for the balls' 14.6, through the right ball's top and the
/// rail's lower edge (its centre 11 px below the ball's), and no ball is found in a
/// third of the frames; on the AVX-512 machine of 2026-12-04, look 28's again (and
/// none of small looks 0–719 but 28).
#[test]
fn a_circle_of_two_level_edges_below_the_rail_is_no_first_lock() {
    super::scaled_with_one_refused_without(
        "rail_view",
        &[(28, Size::Small, None), (165, Size::Small, None)],
        Params {
            rail_view_deg: 0.0,
            ..Params::default()
        },
    );
}

proptest! {
    #![proptest_config(ProptestConfig {
        cases: 48,
        failure_persistence: None,
        ..ProptestConfig::default()
    })]

    /// A ball of any size, lighter or darker than the wall, behind a rail whose top
    /// edge lies anywhere from a third of a radius above its centre to below the
    /// ball (all of it seen): its fitted outline is one a ball over a rail shows.
    #[test]
    fn every_ball_over_a_rail_is_seen_as_one(
        r in 10.0f64..48.0,
        rail in -0.35f64..1.3,
        (ball, wall) in (20.0f64..235.0, 20.0f64..235.0)
            .prop_filter("a ball that differs from the wall", |(b, w)| (b - w).abs() >= 40.0),
        (fx, fy) in (0.0f64..1.0, 0.0f64..1.0),
        seed in 1u64..u64::MAX,
    ) {
        let (w, h) = ((4.0 * r) as u32 + 8, (4.0 * r) as u32 + 8);
        let (cx, cy) = (f64::from(w) / 2.0 + fx, f64::from(h) / 2.0 + fy);
        let top = cy + rail * r;
        let frame = drawn_frame((w, h), seed, 2, |x, y| {
            let (px, py) = (f64::from(x) + 0.5, f64::from(y) + 0.5);
            let level = if py >= top {
                90.0
            } else {
                let cover = super::disc_cover((px, py), (cx, cy), r);
                cover * ball + (1.0 - cover) * wall
            };
            [level; 3]
        });
        let guess = circle::Circle { x: cx + 1.5, y: cy - 1.0, r: 0.9 * r };
        let fitted = circle::fit(&frame.luma, guess, 4.0, 0.0, Params::default().rail_moves, &[]);
        prop_assume!(fitted.is_some_and(|o| (o.circle.r - r).abs() < 0.05 * r));
        let o = fitted.unwrap();
        prop_assert!(
            o.seen_over_a_rail(Params::default().rail_view_deg),
            "r {r:.1}, rail {rail:.2} r below the centre: sectors {:036b}",
            o.sectors
        );
    }

    /// A ball of little contrast with the wall behind a rail of much more, its top
    /// edge from the ball's centre to 0.6 R below it (tracker 31): the rail's edge,
    /// a straight edge running on past the ball both ways, is not the ball's, so
    /// the circle is neither its visible part closed by that edge (the small looks'
    /// seed 48: 9.2 px for 12.5) nor one taking in the rail. Sought from a blob's
    /// guess (as wide as the ball or a tenth narrower), the outline, where one is
    /// found clear, has the ball's radius. Without the refit (`rail_moves`
    /// infinite) a case fails only now and then on drawn balls; `video::sunk_balls`
    /// is the look where it always did.
    #[test]
    fn a_rail_edge_does_not_close_a_ball_into_a_smaller_circle(
        r in 10.0f64..30.0,
        rail in 0.0f64..0.6,
        wall in 40.0f64..200.0,
        contrast in prop_oneof![-25.0f64..-12.0, 12.0f64..25.0],
        (rail_step, up) in (3.0f64..5.0, any::<bool>()),
        narrow in 0.9f64..1.0,
        seed in 1u64..u64::MAX,
    ) {
        let (w, h) = ((6.0 * r) as u32 + 8, (4.0 * r) as u32 + 8);
        let (cx, cy) = (f64::from(w) / 2.0 + 0.3, f64::from(h) / 2.0 - 0.2);
        let top = cy + rail * r;
        // The rail steps from the wall by 3–5 times the ball's contrast, lighter
        // or darker (whichever the levels leave room for).
        let step = rail_step * contrast.abs();
        let rail_level = if (up && wall + step <= 250.0) || wall - step < 5.0 {
            wall + step
        } else {
            wall - step
        };
        let ball = wall + contrast;
        let frame = drawn_frame((w, h), seed, 2, |x, y| {
            let (px, py) = (f64::from(x) + 0.5, f64::from(y) + 0.5);
            let rail_cover = (py - top + 0.5).clamp(0.0, 1.0);
            let cover = super::disc_cover((px, py), (cx, cy), r);
            let behind = cover * ball + (1.0 - cover) * wall;
            [rail_cover * rail_level + (1.0 - rail_cover) * behind; 3]
        });
        // A blob's guess (half its width, that far below its top), the blob as
        // wide as the ball or narrower (its faint sides lost).
        let half = narrow * r;
        let guess = circle::Circle { x: cx + 1.0, y: cy - r + half, r: half };
        let p = Params::default();
        if let Some(o) = circle::fit(&frame.luma, guess, (0.15 * r).max(4.0), 0.0, p.rail_moves, &[])
            && o.coverage() >= p.min_coverage
            && o.rms <= p.max_rms
        {
            prop_assert!(
                (o.circle.r - r).abs() < 0.05 * r,
                "r {r:.1}, rail {rail:.2} R below the centre, wall {wall:.0}, ball {ball:.0}, rail {rail_level:.0}: fitted {:?} ({} points, coverage {:.2}, rms {:.2}, polarity {})",
                o.circle, o.points, o.coverage(), o.rms, o.polarity
            );
        }
    }
}
