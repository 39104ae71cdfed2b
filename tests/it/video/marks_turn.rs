//! Which marks the tracker keeps (`vision::mark_check`, issue 34): a mark drawn on a
//! ball turns with it, by Δx / (kR) as it rolls on the rails' edges and by less while it slides, at one
//! distance from the centre; a glossy highlight stays at one spot of the disc while
//! the ball rolls on, and spots found anywhere in the disc are no one mark. Only the
//! drawn mark's positions may reach the tracks (a wrong mark gives a wrong spin, or
//! `fit` refuses the "rim mark" lying off the ball). Numbers only, no pictures: cheap.

use groovelab::vision::circle::{Circle, Outline};
use groovelab::vision::mark::Mark;
use groovelab::vision::mark_check::checked;
use groovelab::vision::params::MarkChecks;
use groovelab::vision::tracker::{Fix, FrameFixes, LeftOut};
use proptest::prelude::*;

/// The rails' top edge below a ball's centre, in radii (paper-b4.9's k): a ball
/// rolling on them turns by Δx / (kR).
const K: f64 = 0.45;

/// A ball at `(x, y)` of radius `r` with its mark (if any) at `mark`, px, as the
/// tracker's outline fit and mark finder would report it (also `marks_stay`'s).
pub(super) fn fix(x: f64, y: f64, r: f64, mark: Option<(f64, f64)>) -> Result<Fix, LeftOut> {
    Ok(Fix {
        outline: Outline {
            circle: Circle { x, y, r },
            sigma: [0.05; 3],
            covariance: [[0.0; 3]; 3],
            rms: 0.2,
            points: 100,
            // The upper half of the circle (sectors 18–35): the rail hides the rest.
            sectors: 0xF_FFFC_0000,
            lowest: y + K * r,
            polarity: 1.0,
        },
        sigma: 0.05,
        mark: mark.map(|(x, y)| Mark {
            x,
            y,
            sigma: 0.1,
            contrast: -40.0,
        }),
        spots: [None; groovelab::vision::mark::SPOTS],
        colour: None,
    })
}

/// Where a mark at `d` radii from the centre, turned by `angle` rad from the top,
/// lies on the ball at `(x, y)` of radius `r` (image y down).
fn drawn(x: f64, y: f64, r: f64, d: f64, angle: f64) -> (f64, f64) {
    (x + d * r * angle.sin(), y - d * r * angle.cos())
}

/// The marks of `slot` in `frames`, with their frames.
pub(crate) fn marks_of(frames: &[FrameFixes], slot: usize) -> Vec<(usize, (f64, f64))> {
    frames
        .iter()
        .enumerate()
        .filter_map(|(k, f)| {
            let m = f[slot].as_ref().ok()?.mark?;
            Some((k, (m.x, m.y)))
        })
        .collect()
}

/// The marks kept of `slot`, with their frames.
fn kept(frames: &[FrameFixes], slot: usize) -> Vec<(usize, (f64, f64))> {
    marks_of(&checked(frames, &MarkChecks::default()), slot)
}

/// The left ball rolls 200 px (8 radii) to the right; in every other frame the spot
/// found is a highlight at one place of its disc, in the others its drawn mark. The
/// right ball rests, its mark at one place (it does not move, so it need not turn).
#[test]
fn a_highlight_that_stays_while_the_ball_rolls_is_left_out_the_drawn_mark_kept() {
    let r = 25.0;
    let highlight = (-0.3 * r, -0.4 * r);
    let frames: Vec<FrameFixes> = (0..40)
        .map(|k| {
            let x = 100.0 + 5.0 * k as f64;
            let mark = if k % 2 == 0 {
                drawn(x, 200.0, r, 0.55, (x - 100.0) / (K * r))
            } else {
                (x + highlight.0, 200.0 + highlight.1)
            };
            let rest = drawn(500.0, 200.0, r, 0.55, 0.4);
            [
                fix(x, 200.0, r, Some(mark)),
                fix(500.0, 200.0, r, Some(rest)),
            ]
        })
        .collect();
    let left = kept(&frames, 0);
    for (k, m) in &left {
        let x = 100.0 + 5.0 * *k as f64;
        let truth = drawn(x, 200.0, r, 0.55, (x - 100.0) / (K * r));
        assert!(
            (m.0 - truth.0).hypot(m.1 - truth.1) < 1e-9,
            "frame {k}: kept {m:?}, not the drawn mark {truth:?}"
        );
    }
    assert!(left.len() >= 15, "the drawn marks kept: {}", left.len());
    assert_eq!(kept(&frames, 1).len(), 40, "the resting ball's mark");
}

/// Spots found anywhere in the disc (the wall's texture, the shading, compression)
/// keep to no circle about the centre: no mark at all.
#[test]
fn spots_anywhere_in_the_disc_give_no_mark() {
    let r = 20.0;
    let frames: Vec<FrameFixes> = (0..30)
        .map(|k| {
            let x = 100.0 + 4.0 * k as f64;
            // A spread of distances 0.1 … 0.85 R and of angles, frame to frame.
            let d = 0.1 + 0.75 * ((k * 7) % 11) as f64 / 10.0;
            let a = (k * 5 % 13) as f64;
            [
                fix(x, 150.0, r, Some(drawn(x, 150.0, r, d, a))),
                Err(LeftOut::Unseen),
            ]
        })
        .collect();
    assert_eq!(kept(&frames, 0), vec![]);
}

/// Seed 0 of the looks table: a ball at 60 frames/s turning a sixth of a turn a frame;
/// in one frame the spot found is at the top of the disc, where the drawn mark was
/// four frames before and two frames after (a turn every 6 frames), while the drawn
/// mark is hidden below the centre. Its neighbours are too far off in roll to judge it
/// one by one (`confirm_frames`); the spin told by the pairs of marks around it is not.
/// Left in, it also makes the drawn marks at the top look like a spot that stays
/// while the ball rolls, and they were left out with it.
#[test]
fn a_spot_where_the_mark_was_a_turn_ago_is_left_out() {
    let r = 29.0;
    let step = std::f64::consts::TAU / 6.0 * K * r; // px a frame for a sixth of a turn
    let wrong = 9;
    let frames: Vec<FrameFixes> = (0..24)
        .map(|k| {
            let x = 100.0 + step * k as f64;
            let a = (x - 100.0) / (K * r);
            let mark = if k == wrong {
                Some(drawn(x, 200.0, r, 0.7, 0.0))
            } else {
                let m = drawn(x, 200.0, r, 0.7, a);
                (m.1 < 200.0).then_some(m)
            };
            [fix(x, 200.0, r, mark), Err(LeftOut::Unseen)]
        })
        .collect();
    let kept = kept(&frames, 0);
    assert!(!kept.iter().any(|(k, _)| *k == wrong), "{kept:?}");
    // Every drawn mark above the centre is kept.
    let drawn_marks = frames
        .iter()
        .enumerate()
        .filter(|(k, f)| *k != wrong && f[0].as_ref().is_ok_and(|x| x.mark.is_some()))
        .count();
    assert_eq!(kept.len(), drawn_marks, "{kept:?}");
}

/// The marks of `slot` kept under the checks `p`, with their frames.
fn kept_by(frames: &[FrameFixes], slot: usize, p: &MarkChecks) -> Vec<usize> {
    checked(frames, p)
        .iter()
        .enumerate()
        .filter_map(|(k, f)| f[slot].as_ref().ok()?.mark.map(|_| k))
        .collect()
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 64, ..ProptestConfig::default() })]

    /// A drawn mark on a ball that rolls (its angle changing by Δx / (kR)) or slides
    /// with its spin growing (a share of that) is kept in every frame it is seen in
    /// (above the centre), whatever its
    /// radius, speed, direction, the mark's distance and its first angle.
    #[test]
    fn a_mark_that_turns_with_its_ball_is_kept(
        r in 10.0f64..45.0,
        speed in 0.5f64..12.0,
        dir in prop::sample::select(vec![-1.0, 1.0]),
        d in 0.3f64..0.8,
        start in 0.0f64..std::f64::consts::TAU,
        turning in 0.4f64..1.0,
        frames in 12usize..60,
    ) {
        // The mark is measured above the centre only (lower, the rail hides it or
        // its ring: near kR below the centre a rolling ball's point stands still).
        let fixes: Vec<FrameFixes> = (0..frames)
            .map(|k| {
                let x = 400.0 + dir * speed * k as f64;
                let a = start + turning * (x - 400.0) / (K * r);
                let m = drawn(x, 200.0, r, d, a);
                [fix(x, 200.0, r, (m.1 < 200.0).then_some(m)), Err(LeftOut::Unseen)]
            })
            .collect();
        let given = fixes.iter().filter(|f| f[0].as_ref().is_ok_and(|x| x.mark.is_some())).count();
        // Fewer than `fewest_marks` tell nothing: then none is kept.
        let expected = if given >= MarkChecks::default().fewest_marks { given } else { 0 };
        prop_assert_eq!(kept(&fixes, 0).len(), expected);
    }

    /// A struck ball slides with its spin growing from none at the rate friction on
    /// the rails gives (friction m μ_k g at the rails, kR below the centre, turns a
    /// ball of I = 2/5 m R² faster by 5 k μ_k g / (2R) each second) until it rolls
    /// (ω = v / (kR)), then slows rolling: the spin check leaves out none of its drawn
    /// marks, for any μ_k up to 0.5, frame rate, speed and scale.
    #[test]
    fn the_spin_check_keeps_a_sliding_balls_marks(
        mu in 0.0f64..0.5,
        fps in prop::sample::select(vec![30.0, 50.0, 60.0, 100.0, 120.0, 240.0]),
        v0 in 0.2f64..1.2,
        ppm in 500.0f64..3000.0,
        d in 0.3f64..0.8,
        start in 0.0f64..std::f64::consts::TAU,
    ) {
        let (g, radius_m) = (9.81, 0.0275);
        let r = radius_m * ppm;
        let alpha = 5.0 * K * mu * g / (2.0 * radius_m);
        // Sliding ends when v - μg t = kR α t.
        let t_roll = v0 / (mu * g + K * radius_m * alpha).max(1e-9);
        let frames: Vec<FrameFixes> = (0..(fps * 0.5) as usize)
            .map(|k| {
                let t = k as f64 / fps;
                let (x, a) = if t < t_roll {
                    (v0 * t - 0.5 * mu * g * t * t, start + 0.5 * alpha * t * t)
                } else {
                    let (x1, a1) = (v0 * t_roll - 0.5 * mu * g * t_roll * t_roll, start + 0.5 * alpha * t_roll * t_roll);
                    let v1 = v0 - mu * g * t_roll;
                    (x1 + v1 * (t - t_roll), a1 + v1 * (t - t_roll) / (K * radius_m))
                };
                let x = 300.0 + x * ppm;
                let m = drawn(x, 200.0, r, d, a);
                [fix(x, 200.0, r, (m.1 < 200.0).then_some(m)), Err(LeftOut::Unseen)]
            })
            .collect();
        let without = MarkChecks { spin_frames: 0, ..MarkChecks::default() };
        prop_assert_eq!(kept_by(&frames, 0, &MarkChecks::default()), kept_by(&frames, 0, &without));
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// A fit with no other fit of its ball within `confirm_frames` either way (the
    /// looks table's seed 24 at frame 195: 12 and 9 frames from its neighbours, its
    /// centre 8.75 px off, its "mark" 38 px from the drawn one) gives no mark: no
    /// check of a single mark can judge it, nothing being near, and a wrong mark is
    /// worse than none. The marks of the runs of fits around it are all kept.
    #[test]
    fn a_mark_of_a_fit_alone_in_time_is_left_out(
        before in 3usize..14,
        after in 3usize..14,
        angle in 0.0..std::f64::consts::TAU,
        speed in 2.0f64..6.0,
    ) {
        let r = 28.0;
        let alone = 20 + before;
        let resume = alone + after;
        let frames: Vec<FrameFixes> = (0..resume + 20)
            .map(|k| {
                let x = 100.0 + speed * k as f64;
                let seen = k <= 20 || k == alone || k >= resume;
                let mark = if k == alone {
                    drawn(x, 200.0, r, 0.55, angle)
                } else {
                    drawn(x, 200.0, r, 0.55, (x - 100.0) / (K * r))
                };
                let left = if seen { fix(x, 200.0, r, Some(mark)) } else { Err(LeftOut::Unseen) };
                [left, Err(LeftOut::Unseen)]
            })
            .collect();
        let kept: Vec<usize> = kept(&frames, 0).into_iter().map(|(k, _)| k).collect();
        prop_assert!(!kept.contains(&alone), "the lone fit's mark kept: {kept:?}");
        let runs: Vec<usize> = (0..=20).chain(resume..resume + 20).collect();
        prop_assert_eq!(kept, runs);
    }
}
