//! The tracker on looks the project's default film does not have (issue 34): a ball
//! that differs from the wall only in colour, a rail board far brighter than the
//! wall, clutter outside `--roi`, and a seed (`--ball-at`); each drawn here in small
//! frames with the truth known (a disc anti-aliased by its pixels' coverage, moving
//! along a level groove), and tracked in memory.

use groovelab::vision::{self, Frame, Params, Roi};

/// A small scene: wall colour, an optional rail board (top row, colour), balls
/// (centre x at frame k, y, radius, colour), extra clutter discs that stay put.
#[derive(Clone)]
struct Look {
    wall: [f64; 3],
    rail: Option<(f64, [f64; 3])>,
    balls: Vec<Disc>,
    clutter: Vec<Disc>,
    /// Pixels each ball moves along x per frame (signed).
    speed: Vec<f64>,
}

const W: u32 = 320;
const H: u32 = 120;

/// Frame `k` of `look`, and each ball's true centre.
fn frame(look: &Look, k: usize) -> (Frame, Vec<(f64, f64)>) {
    let centres: Vec<(f64, f64)> = look
        .balls
        .iter()
        .zip(&look.speed)
        .map(|(b, v)| (b.0 + v * k as f64, b.1))
        .collect();
    let discs: Vec<Disc> = look
        .balls
        .iter()
        .zip(&centres)
        .map(|(b, c)| (c.0, c.1, b.2, b.3))
        .chain(look.clutter.iter().copied())
        .collect();
    // Seeded noise of ±2 levels, so a flat wall has a scatter.
    let seed = 0x2545_f491_u64.wrapping_add(k as u64 * 7919);
    let frame = super::drawn_frame((W, H), seed, 2, |x, y| {
        let mut c = look.wall;
        for &(cx, cy, r, col) in &discs {
            let cover = super::disc_cover((f64::from(x), f64::from(y)), (cx, cy), r);
            for i in 0..3 {
                c[i] = c[i] * (1.0 - cover) + col[i] * cover;
            }
        }
        if let Some((top, col)) = look.rail {
            let cover = (f64::from(y) + 0.5 - top).clamp(0.0, 1.0);
            for i in 0..3 {
                c[i] = c[i] * (1.0 - cover) + col[i] * cover;
            }
        }
        c
    });
    (frame, centres)
}

/// Tracks `frames` frames of `look` with `params`: per frame and ball, the distance
/// of the nearest tracked centre from the truth (None when not tracked).
fn errors(look: &Look, frames: usize, params: Params) -> Vec<Vec<Option<f64>>> {
    let (imgs, truth): (Vec<Frame>, Vec<Vec<(f64, f64)>>) =
        (0..frames).map(|k| frame(look, k)).unzip();
    let t = vision::track(&imgs, params);
    t.frames
        .iter()
        .zip(&truth)
        .map(|(fixes, tr)| {
            tr.iter()
                .map(|c| {
                    fixes
                        .iter()
                        .flatten()
                        .map(|f| (f.outline.circle.x - c.0).hypot(f.outline.circle.y - c.1))
                        .min_by(f64::total_cmp)
                        .filter(|d| *d < 5.0)
                })
                .collect()
        })
        .collect()
}

fn rms(e: &[Vec<Option<f64>>]) -> (f64, usize) {
    let d: Vec<f64> = e.iter().flatten().flatten().copied().collect();
    let s = d.iter().map(|v| v * v).sum::<f64>() / d.len().max(1) as f64;
    (s.sqrt(), d.len())
}

/// A disc: centre x, y, radius (px) and colour.
type Disc = (f64, f64, f64, [f64; 3]);

impl Look {
    /// `balls` moving at `speed` on a plain `wall`, no rail board, no clutter.
    fn plain(wall: [f64; 3], (balls, speed): (Vec<Disc>, Vec<f64>)) -> Look {
        Look {
            wall,
            rail: None,
            balls,
            clutter: vec![],
            speed,
        }
    }
}

/// Two balls meeting slowly (never touching within `frames`), one moving.
fn two_balls(colour: [f64; 3]) -> (Vec<Disc>, Vec<f64>) {
    (
        vec![(70.0, 55.0, 18.0, colour), (240.0, 55.0, 18.0, colour)],
        vec![4.0, 0.0],
    )
}

#[test]
#[ignore = "issue 34 open (tracker of 2026-11-28, one pass): the colour-only outline fit succeeds in 4 of 32 frames"]
fn a_red_ball_on_green_felt_of_its_brightness_is_found_by_its_colour() {
    // Equal BT.601 luma: red (200, 60, 60) ≈ 101.5, green (60, 130, 80) ≈ 103.5.
    let look = Look::plain([60.0, 130.0, 80.0], two_balls([200.0, 60.0, 60.0]));
    let e = errors(&look, 16, Params::default());
    let (r, n) = rms(&e);
    // Found in most frames (both balls, 32 in all), to well under a pixel: the colour
    // planes are half size, so 0.5 px, not the brightness edge's 0.1.
    assert!(n >= 24, "found {n} of 32: {e:?}");
    assert!(r < 0.5, "centre RMS {r:.3} px");
}

#[test]
#[ignore = "issue 34 open (tracker of 2026-11-28, one pass): a ball at rest through the whole clip is part of the background, and the bright board hides it from the look against a smooth surface: found in 16 of 32"]
fn a_rail_board_far_brighter_than_the_wall_leaves_the_balls_found() {
    // Grey balls on a dark wall, a near-white board hiding their lower third.
    let (balls, speed) = two_balls([170.0, 170.0, 170.0]);
    let look = Look {
        wall: [50.0, 50.0, 55.0],
        rail: Some((67.0, [235.0, 230.0, 225.0])),
        balls,
        clutter: vec![],
        speed,
    };
    let e = errors(&look, 16, Params::default());
    let (r, n) = rms(&e);
    assert!(n >= 28, "found {n} of 32: {e:?}");
    assert!(r < 0.3, "centre RMS {r:.3} px");
}

#[test]
fn clutter_outside_the_roi_is_not_taken_for_a_ball() {
    // A third, bigger disc that moves too, above the groove: outside the ROI.
    let (mut balls, mut speed) = two_balls([200.0, 200.0, 200.0]);
    balls.push((100.0, 22.0, 16.0, [200.0, 200.0, 200.0]));
    speed.push(3.0);
    let look = Look::plain([40.0, 40.0, 40.0], (balls, speed));
    let roi = Roi {
        x: 0.0,
        y: 40.0,
        width: f64::from(W),
        height: 80.0,
    };
    let params = Params {
        roi: Some(roi),
        ..Params::default()
    };
    let imgs: Vec<Frame> = (0..12).map(|k| frame(&look, k).0).collect();
    let t = vision::track(&imgs, params);
    for fixes in &t.frames {
        for f in fixes.iter().flatten() {
            assert!(
                roi.contains(f.outline.circle.x, f.outline.circle.y),
                "{:?} outside the ROI",
                f.outline.circle
            );
        }
    }
    let found = t.frames.iter().flatten().flatten().count();
    assert!(found >= 20, "found {found} of 24 in the ROI");
}

#[test]
fn a_seed_on_a_ball_keeps_a_smaller_round_thing_out() {
    // A small round spot the size of a mark (r 9 px) moves along with the balls;
    // the seed on the left ball says the balls' radius is 18 px.
    let (mut balls, mut speed) = two_balls([210.0, 200.0, 190.0]);
    balls.push((150.0, 60.0, 9.0, [20.0, 20.0, 20.0]));
    speed.push(-2.0);
    let look = Look::plain([90.0, 90.0, 90.0], (balls, speed));
    let params = Params {
        ball_at: Some((72.0, 50.0)),
        ..Params::default()
    };
    let imgs: Vec<Frame> = (0..12).map(|k| frame(&look, k).0).collect();
    let t = vision::track(&imgs, params);
    let radii: Vec<f64> = t
        .frames
        .iter()
        .flatten()
        .flatten()
        .map(|f| f.outline.circle.r)
        .collect();
    assert!(radii.len() >= 18, "{} fits", radii.len());
    assert!(
        radii.iter().all(|r| (r - 18.0).abs() < 1.0),
        "a fit not of the seeded radius: {radii:?}"
    );
}

#[test]
fn a_seed_sets_the_first_radius_and_the_balls_fits_the_rest() {
    // The first frame's balls drawn 10 % large (what a seed's one outline can be off
    // by: a lit part, a fringe joined to the ball), the rest at their 18 px: the
    // radius is learned from the balls' fits as without a seed, not fixed by it.
    let look = Look::plain([90.0, 90.0, 90.0], two_balls([210.0, 200.0, 190.0]));
    let first = Look {
        balls: look.balls.iter().map(|b| (b.0, b.1, 19.8, b.3)).collect(),
        ..look.clone()
    };
    let params = Params {
        ball_at: Some((72.0, 50.0)),
        ..Params::default()
    };
    let imgs: Vec<Frame> = (0..12)
        .map(|k| frame(if k == 0 { &first } else { &look }, k).0)
        .collect();
    let t = vision::track(&imgs, params);
    let r = t.radius().unwrap_or(f64::NAN);
    assert!((r - 18.0).abs() < 0.3, "the radius {r:.2} px for 18");
    assert!(t.radii().len() >= 20, "{} fits", t.radii().len());
}

#[test]
fn a_seed_or_roi_off_the_frame_is_one_line_naming_the_frame() {
    // Three frames of 64×48 px in a folder (no ffmpeg needed): a point or rectangle
    // off them, or the point outside the rectangle, is refused before tracking.
    let dir = super::blank_frames("video_off_frame", 3);
    let folder = dir.to_str().unwrap();
    for (args, want) in [
        (
            &["--ball-at", "64,10"][..],
            "--ball-at 64,10 lies outside the frame",
        ),
        (&["--ball-at", "10,48"][..], "outside the frame"),
        (
            &["--roi", "70,0,10,10"][..],
            "--roi 70,0,10,10 lies wholly outside",
        ),
        (&["--roi", "0,48,64,20"][..], "wholly outside"),
        (
            &["--roi", "0,20,64,20", "--ball-at", "5,5"][..],
            "--ball-at 5,5 lies outside --roi 0,20,64,20",
        ),
    ] {
        let mut all = vec!["track", folder, "--fps", "30"];
        all.extend_from_slice(args);
        let out = crate::common::groovelab(&all);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
        assert_eq!(err.trim().lines().count(), 1, "{args:?}: {err}");
        assert!(err.contains(want), "{args:?}: {err}");
        assert!(
            want.contains("--roi 0,20") || err.contains("64×48"),
            "{args:?}: {err}"
        );
    }
}

#[test]
fn a_bad_roi_or_seed_is_one_line_naming_the_form() {
    for (flag, value, want) in [
        ("--roi", "1,2,3", "X,Y,W,H"),
        ("--roi", "0,0,0,10", "X,Y,W,H"),
        ("--roi", "a,b,c,d", "X,Y,W,H"),
        ("--roi", "-5,0,100,100", "X,Y,W,H"),
        ("--ball-at", "-5,3", "X,Y"),
        ("--ball-at", "nan,1", "X,Y"),
    ] {
        // As `--roi=-5,…` and as `--roi -5,…` (a value starting with '-' was taken
        // for an unknown option and answered with every option of `track`).
        let joined = format!("{flag}={value}");
        for args in [vec![joined.as_str()], vec![flag, value]] {
            let mut all = vec!["track", "frames-that-do-not-exist"];
            all.extend(&args);
            let out = crate::common::groovelab(&all);
            let err = String::from_utf8_lossy(&out.stderr);
            assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
            assert!(err.contains(want), "{args:?}: {err}");
            assert!(
                err.contains(value) && !err.contains("--output"),
                "{args:?}: {err}"
            );
        }
    }
}

#[test]
fn a_seeded_refusal_says_it_was_seeded_and_to_try_without() {
    // Frames with no ball (no ffmpeg needed): refused either way; with a seed, the
    // line names the seed (its outline sets the first radius, so a clip refused
    // with it may track without it: the looks table's seed 39).
    let dir = super::blank_frames("video_seeded_refusal", 6);
    let folder = dir.to_str().unwrap();
    for (seed, said) in [(None, false), (Some("20,30"), true)] {
        let mut all = vec!["track", folder, "--fps", "30"];
        if let Some(at) = seed {
            all.extend(["--ball-at", at]);
        }
        let out = crate::common::groovelab(&all);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{seed:?}: {err}");
        assert_eq!(err.trim().lines().count(), 1, "{seed:?}: {err}");
        assert!(err.contains("no ball found"), "{seed:?}: {err}");
        assert_eq!(
            err.contains("tracked with the seed --ball-at 20,30: try without it too"),
            said,
            "{seed:?}: {err}"
        );
    }
}

/// Two balls moving toward each other, and a disc of the balls' colour and about
/// their size that stands still between them on their line (clutter on the wall:
/// the small looks' seed 72, whose right "ball" was such a disc, 14.8 px for the
/// balls' 12.75, tracker 31). A thing that stands still on the balls' line may be
/// a target ball at rest, but not while two balls are seen moving: it is the
/// bench, so no frame holds three balls and no fit lies on the disc.
#[test]
fn a_still_disc_on_the_line_while_two_balls_move_is_the_bench() {
    let grey = [200.0, 200.0, 200.0];
    let look = Look {
        clutter: vec![(160.0, 55.0, 20.0, grey)],
        ..Look::plain(
            [40.0, 40.0, 40.0],
            (
                vec![(22.0, 55.0, 18.0, grey), (298.0, 55.0, 18.0, grey)],
                vec![5.0, -5.0],
            ),
        )
    };
    let imgs: Vec<Frame> = (0..16).map(|k| frame(&look, k).0).collect();
    let t = vision::track(&imgs, Params::default());
    assert_eq!(t.counts.crowded, 0, "frames with three balls");
    let on_disc: Vec<_> = t
        .frames
        .iter()
        .flatten()
        .flatten()
        .filter(|f| (f.outline.circle.x - 160.0).abs() < 5.0)
        .collect();
    assert!(on_disc.is_empty(), "fits on the still disc: {on_disc:?}");
    let e = errors(&look, 16, Params::default());
    let (r, n) = rms(&e);
    assert!(n >= 30, "found {n} of 32: {e:?}");
    assert!(r < 0.3, "centre RMS {r:.3} px");
}

/// A disc that stands still through the whole clip, and no ball found moving (the
/// full looks' seed 80: black balls on a dark cluttered wall, where a brown disc of
/// clutter on their line was tracked in all 47 frames as the one ball, 28 px for
/// the balls' 41, its scale 32 % off with a ± of 0.4 %). Whatever size the disc and
/// wherever it stands, tracked it gives no tracks but a refusal naming it; with a
/// ball rolling slowly beside it (the same size, 15–45 px in the clip: under a
/// radius for some), tracks are given.
fn a_thing_that_never_moves_gives_no_scale(r: f64, x: f64, speed: f64) {
    let grey = [200.0, 200.0, 200.0];
    let disc = (x, 55.0, r, grey);
    let still = Look {
        clutter: vec![disc],
        ..Look::plain([40.0, 40.0, 40.0], (vec![], vec![]))
    };
    let rolling = Look {
        clutter: vec![disc],
        ..Look::plain(
            [40.0, 40.0, 40.0],
            (vec![(x - 3.0 * r, 55.0, r, grey)], vec![-speed]),
        )
    };
    for (look, refused) in [(still, true), (rolling, false)] {
        let imgs: Vec<Frame> = (0..16).map(|k| frame(&look, k).0).collect();
        // Pushed with nothing learned: the disc is a blob in luma, not the bench.
        let mut t = vision::Tracker::new(Params::default());
        imgs.iter().for_each(|f| t.push(f));
        let times: Vec<f64> = (0..16).map(|k| f64::from(k) / 60.0).collect();
        match vision::tracks(&t, times, 0.0125, None) {
            Err(e @ vision::TracksError::StandsStill { .. }) => {
                assert!(refused, "r {r:.1} x {x:.0}: a rolling ball refused: {e}");
                assert!(e.to_string().contains("nothing found moves"), "{e}");
                assert!(e.helped_by().ball_at && e.helped_by().roi, "{e}");
            }
            Err(e) => panic!("r {r:.1} x {x:.0} still={refused}: {e}"),
            Ok(tr) => {
                assert!(!refused, "r {r:.1} x {x:.0}: the still disc tracked");
                let ratio = tr.calibration.radius_px / r;
                assert!((ratio - 1.0).abs() < 0.03, "r {r:.1}: radius {ratio}");
            }
        }
    }
}

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig::with_cases(6))]
    #[test]
    fn a_thing_tracked_that_never_moves_gives_no_scale(
        r in 12.0f64..24.0, x in 130.0f64..280.0, speed in 1.0f64..3.0,
    ) {
        a_thing_that_never_moves_gives_no_scale(r, x, speed);
    }
}
