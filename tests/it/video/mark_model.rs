//! A mark measured by a model of the drawn disc (issue 34, tracker 27). The centroid
//! of a mark's contrast weighs each of its pixels by how much it stands out from the
//! ball's shading there, so where a matte ball's shading darkens across a dark mark
//! the mark's better-lit side weighs more and the centroid leans that way: a few
//! tenths of a pixel on drawn balls, up to 3.5 px on the looks table's compressed
//! clips (seed 22's frame 36, a dark mark low on a wooden ball, the shading
//! darkening toward the rail). The disc model (`vision::mark_fit`: one level for the
//! mark, a plane for the shading, a soft edge) places the disc by its edge.

use super::{decoded_look, marks_against_truth};
use crate::film::looks::Size;
use crate::film::paint::{self, Finish, Paint};
use groovelab::vision::circle::{Circle, Outline};
use groovelab::vision::gray::Gray;
use groovelab::vision::{self, Params, mark};
use proptest::prelude::*;

/// A drawn ball: radius and centre, px; the mark's place and radius, px; the ball's
/// matte ambient share; a dark mark on a light ball (else a light one on a dark
/// ball); and the rail's top edge, px.
struct Drawn {
    r: f64,
    centre: (f64, f64),
    mark: (f64, f64, f64),
    ambient: f64,
    dark_mark: bool,
    rail: f64,
}

/// The picture of `d`, 120 × 110: the ball shaded as the films' matte balls (lit
/// from the upper left), its mark of one level, a wall and the rail below `d.rail`;
/// each pixel the mean of 4 × 4 samples plus a fixed pattern of ±2 levels.
fn picture(d: &Drawn) -> Gray {
    let (w, h) = (120, 110);
    let (ball, ink, wall, rail) = if d.dark_mark {
        (225.0, 40.0, 90.0, 60.0)
    } else {
        (80.0, 220.0, 170.0, 120.0)
    };
    let look = Paint {
        ball: [ball; 3],
        finish: Finish::Matte { ambient: d.ambient },
        ..Paint::default()
    };
    let (cx, cy) = d.centre;
    super::supersampled((w, h), |px, py| {
        let q = ((px - cx) / d.r, (py - cy) / d.r);
        if py > d.rail {
            rail
        } else if q.0.hypot(q.1) > 1.0 {
            wall
        } else if (px - d.mark.0).hypot(py - d.mark.1) < d.mark.2 {
            ink
        } else {
            paint::luma(look.shade(q.0, q.1))
        }
    })
}

/// The mark found on `d`'s picture with the edge softness `soft` (`Params::mark_soft`;
/// 0: the centroid alone), px from the drawn one.
fn found_off(d: &Drawn, soft: f64) -> Option<f64> {
    let p = Params::default();
    let ball = Outline {
        circle: Circle {
            x: d.centre.0,
            y: d.centre.1,
            r: d.r,
        },
        sigma: [0.05; 3],
        covariance: [[0.0; 3]; 3],
        rms: 0.2,
        points: 100,
        // The upper half of the circle (sectors 18–35): the rail hides the rest.
        sectors: 0xF_FFFC_0000,
        lowest: d.rail,
        polarity: if d.dark_mark { 1.0 } else { -1.0 },
    };
    let levels = (p.mark_sigmas, p.mark_levels, p.mark_cut, soft);
    let m = mark::find(&picture(d), &ball, 1.5, 0.0, levels).mark?;
    Some((m.x - d.mark.0).hypot(m.y - d.mark.1))
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 24, ..ProptestConfig::default() })]

    /// A drawn mark anywhere on the visible disc of a matte ball, dark or light, is
    /// placed within 0.15 px of its centre (the centroid alone: 0.1–0.6 px off for
    /// dark marks, where the shading's gradient across the mark is steepest).
    #[test]
    fn a_drawn_mark_on_a_shaded_ball_is_placed_by_its_disc(
        r in 20.0f64..40.0,
        at in 0.4f64..0.6,
        size in 0.1f64..0.2,
        angle in -3.6f64..0.5,
        ambient in 0.35f64..0.6,
        dark_mark in any::<bool>(),
    ) {
        let centre = (60.3, 55.6);
        let d = Drawn {
            r,
            centre,
            mark: (centre.0 + at * r * angle.cos(), centre.1 + at * r * angle.sin(), size * r),
            ambient,
            dark_mark,
            rail: centre.1 + 0.7 * r,
        };
        let off = found_off(&d, Params::default().mark_soft)
            .ok_or_else(|| TestCaseError::fail("no mark found"))?;
        prop_assert!(off < 0.15, "mark {off:.2} px off");
    }
}

/// The same drawn balls, a fixed sample of dark marks: the centroid alone (mark_soft
/// 0) is more than 0.15 px off on some, so the test above asks what only the model
/// gives.
#[test]
fn the_centroid_alone_leans_toward_the_lit_side() {
    let mut worst: f64 = 0.0;
    for i in 0..12 {
        let t = f64::from(i) / 12.0;
        let (r, angle) = (20.0 + 20.0 * t, -3.6 + 4.1 * t);
        let centre = (60.3, 55.6);
        let d = Drawn {
            r,
            centre,
            mark: (
                centre.0 + 0.5 * r * angle.cos(),
                centre.1 + 0.5 * r * angle.sin(),
                0.15 * r,
            ),
            ambient: 0.4,
            dark_mark: true,
            rail: centre.1 + 0.7 * r,
        };
        let with = found_off(&d, Params::default().mark_soft).expect("a mark");
        let without = found_off(&d, 0.0).expect("a mark");
        assert!(with < 0.15, "case {i}: {with:.2} px off with the model");
        worst = worst.max(without);
    }
    assert!(
        worst > 0.15,
        "the centroid alone: at most {worst:.2} px off"
    );
}

/// Looks 20 and 34 of the looks table (a wooden ball with a dark mark at 60 frames/s
/// in 480p, a light mark on wooden balls at 30 frames/s in 720p), decoded from their
/// H.264 copies and tracked: the marks kept are within 0.15 px RMS of the drawn ones.
/// (The centroid alone gave 0.2–0.35 px on them when this was written; that it leans,
/// the test above shows on drawn balls, not tracking each look twice.)
#[test]
fn the_looks_marks_are_placed_by_their_discs() {
    let mut with = Vec::new();
    for seed in [20, 34] {
        let Some((clip, frames)) = decoded_look("mark_model", seed, Size::Full) else {
            return;
        };
        let params = Params::default();
        let tracker = vision::track(&frames, params);
        with.extend(marks_against_truth(&clip, &tracker, &params.marks));
    }
    let rms = (with.iter().map(|p| p.0 * p.0).sum::<f64>() / with.len().max(1) as f64).sqrt();
    assert!(with.len() >= 30, "{} marks kept", with.len());
    assert!(rms < 0.15, "with the model: {rms:.3} px RMS");
}
