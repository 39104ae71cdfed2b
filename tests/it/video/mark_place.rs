//! Where the mark finder puts a drawn mark (`vision::mark::find`, issue 34): at the
//! mark's centre, to a fraction of a pixel, whatever its size (0.1–0.2 R), its place
//! (0.4–0.7 R from the centre, above the rail), its sign against the ball and the
//! ball's shading. What once broke (looks table, tracker version 6, seeds 14 and 40): a
//! mark larger than the finder's box stood out from the box's mean only about its
//! rim, and its centroid, over a disc the rim's size, stayed there: 3–6 px toward the
//! ball's centre. One small picture per case, no video: cheap.

use groovelab::vision::circle::{Circle, Outline};
use groovelab::vision::gray::Gray;
use groovelab::vision::mark;
use proptest::prelude::*;

/// A ball of radius `r` at `(cx, cy)` on a wall of `wall`, shaded from `centre` in
/// its middle to `limb` at its edge (quadratically), with a mark of level `ink` and
/// radius `rho` at `(mx, my)`; every pixel the mean of 4 × 4 samples (edges
/// anti-aliased, as a camera's) plus a fixed pattern of ±2 levels of noise.
#[allow(clippy::too_many_arguments)]
fn picture(
    (w, h): (usize, usize),
    (cx, cy, r): (f64, f64, f64),
    (wall, centre, limb): (f64, f64, f64),
    (mx, my, rho, ink): (f64, f64, f64, f64),
) -> Gray {
    super::supersampled((w, h), |px, py| {
        let d = (px - cx).hypot(py - cy) / r;
        if d > 1.0 {
            wall
        } else if (px - mx).hypot(py - my) < rho {
            ink
        } else {
            centre + (limb - centre) * d * d
        }
    })
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 24, ..ProptestConfig::default() })]

    /// A drawn mark is found at its centre within 0.4 px (the pixel noise and the
    /// anti-aliased edge move a centroid by a few tenths), light on a dark ball or
    /// dark on a light one.
    #[test]
    fn a_drawn_mark_is_found_at_its_centre(
        r in 20.0f64..40.0,
        at in 0.4f64..0.65,
        size in 0.1f64..0.2,
        angle in -2.4f64..-0.75,
        light_mark in any::<bool>(),
    ) {
        let (cx, cy) = (60.3, 55.6);
        let (mx, my) = (cx + at * r * angle.cos(), cy + at * r * angle.sin());
        let (wall, centre, limb, ink) = if light_mark {
            (170.0, 70.0, 35.0, 200.0)
        } else {
            (90.0, 215.0, 160.0, 40.0)
        };
        let img = picture(
            (120, 110),
            (cx, cy, r),
            (wall, centre, limb),
            (mx, my, size * r, ink),
        );
        let ball = Outline {
            circle: Circle { x: cx, y: cy, r },
            sigma: [0.05; 3],
            covariance: [[0.0; 3]; 3],
            rms: 0.2,
            points: 100,
            // The upper half of the circle (sectors 18–35): the rail hides the rest.
            sectors: 0xF_FFFC_0000,
            lowest: cy + 0.45 * r,
            polarity: if light_mark { -1.0 } else { 1.0 },
        };
        let found = mark::find(&img, &ball, 1.5, 0.0, (6.0, 10.0, 0.3, 1.4)).mark;
        let m = found.ok_or_else(|| TestCaseError::fail("no mark found"))?;
        let err = (m.x - mx).hypot(m.y - my);
        prop_assert!(err < 0.4, "mark at ({:.2}, {:.2}), drawn at ({mx:.2}, {my:.2}): {err:.2} px off", m.x, m.y);
        prop_assert_eq!(m.contrast.signum(), if light_mark { 1.0 } else { -1.0 });
    }
}
