//! Balls sunk behind a tall rail, only their top half or less showing (issue 34,
//! tracker 31): small looks the tracker was not tuned on, whose scales were
//! confidently wrong. The rail's straight edge closed a ball's visible cap into a
//! smaller circle (48: 9.2 px for 12.5, μ_k 0.231 for 0.170) or was taken into a
//! larger one (87: 16.8 px for 11.9); a disc of clutter standing still on the
//! balls' line was followed as a ball (72: 14.8 px for 12.75). Now each is within
//! 2 of its ± of the truth, or refused: never a scale beyond its ±.

use groovelab::vision;

use crate::film::looks::Size;

#[test]
fn sunk_balls_are_measured_right_or_refused() {
    for (seed, must_track) in [(48, false), (72, true), (87, true)] {
        let Some((clip, frames)) = super::decoded_look("video_sunk_balls", seed, Size::Small)
        else {
            return;
        };
        let (r, truth, times) = super::look_truth(&clip, frames.len());
        let tracker = vision::track(&frames, vision::Params::default());
        match vision::tracks(&tracker, times, r, None) {
            Ok(t) => {
                let c = t.calibration;
                let z = (c.px_per_m - truth) / c.px_per_m_sigma;
                assert!(
                    z.abs() <= 2.0,
                    "look {seed}: scale {:.1} ± {:.1} px/m for {truth:.1} ({z:+.1} ±)",
                    c.px_per_m,
                    c.px_per_m_sigma
                );
            }
            Err(e) => assert!(!must_track, "look {seed} refused: {e}"),
        }
    }
}

/// Small look 87 drawn without compression (as the property tests' PNG folders):
/// its sharp frames show the rail's lower edge beside each ball as strongly as its
/// top edge, and the wall's stripes break the step beside the circle that the
/// edge under each single fit is judged by, so that judge found no rail in most
/// frames and the circles took in the rail (+43 %: 17 px for 11.94). The rail's
/// edges found once in the learned background (`vision::rail`), each judged per
/// ball by the frame matching the background below it, leave the rail out: the
/// scale is within 2 of its ± of the truth. Without any rail rule (`rail_moves`
/// infinite switches off both) it is not; with tracker 31's rule alone (the
/// background's edges not passed to the fit, tried by hand) it was +5.2 ±.
#[test]
fn a_sunk_ball_drawn_sharp_is_measured_without_its_rail() {
    let clip = crate::film::looks::random(&crate::common::paper_scene(), 87, Size::Small);
    let (w, h) = (clip.film.look.width, clip.film.look.height);
    let frames: Vec<vision::Frame> = (0..clip.frames)
        .map(|k| {
            let img = image::RgbImage::from_raw(w as u32, h as u32, clip.film.rgb(k)).unwrap();
            vision::Frame::from_rgb(&img)
        })
        .collect();
    let (r, truth, times) = super::look_truth(&clip, frames.len());
    let z = |p: vision::Params| {
        let tracker = vision::track(&frames, p);
        vision::tracks(&tracker, times.clone(), r, None)
            .map(|t| (t.calibration.px_per_m - truth) / t.calibration.px_per_m_sigma)
    };
    let with = z(vision::Params::default()).unwrap();
    assert!(with.abs() <= 2.0, "scale {with:+.1} ± from the truth");
    let without = z(vision::Params {
        rail_moves: f64::INFINITY,
        ..vision::Params::default()
    });
    assert!(
        without.as_ref().is_ok_and(|z| z.abs() > 2.0),
        "without the rail rules: {without:?}"
    );
}
