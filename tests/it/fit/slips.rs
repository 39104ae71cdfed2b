//! Tracking slips (issue 34): frames of a track whose picture the encoder did not
//! update show the ball where the frame before has it, far off the model while the
//! ball moves. Such frames are left out of both fits and said, and the fits then find
//! the truth; a clean track loses none.

use groovelab::input::data::{self, Reading};
use groovelab::physics::scene::Scene;
use groovelab::study::fit::{self, Ask, Fits};
use groovelab::study::measured::{self, Derive, Found, Track};
use groovelab::study::video::{self, TrackFormat, Video};

use crate::common::{preset_scene, run_in_process, scratch_dir};

const MU: f64 = 0.17;

/// The paper's b = 4.9 cm scene filmed as `video`, each frame of `frozen` showing
/// the centre and mark of the frame before it (a run of them, that frame's).
fn filmed(scene: &Scene, video: &Video, frozen: &[usize]) -> Track {
    let mut p = video::track(scene, video).unwrap().into_parts();
    for &k in frozen {
        p.x[k] = p.x[k - 1];
        p.y[k] = p.y[k - 1];
        if let Some((mx, my)) = p.mark.as_mut() {
            mx[k] = mx[k - 1];
            my[k] = my[k - 1];
        }
    }
    Track::new(p).unwrap()
}

/// `fit`'s fits of the track as a file is read (Tracker's multi-track export).
fn fits_of(scene: &Scene, track: &Track) -> (Fits, Found) {
    let text = video::write(track, TrackFormat::TrackerMulti);
    let series = data::load(&text, "video.txt", &Reading::default(), &Derive::default()).unwrap();
    let m = measured::for_scene(&series, scene).measured;
    let fits = fit::fit_all(scene, &m, &Ask::default(), &groovelab::study::Quiet).unwrap();
    (fits, series.found().cloned().unwrap())
}

/// The moving ball's frozen frames after the impact (sliding back at 0.4 m/s, or
/// rolling at 0.25 m/s: 4–7 mm a frame at 50–60 frames/s, where the centres scatter
/// by 0.1–0.3 mm) are the slips, exactly, and both fits are then as on the track
/// unfrozen: at two frame rates and noises, runs of one to three frames.
#[test]
fn frozen_frames_are_left_out_as_slips_and_the_fits_agree_on_the_truth() {
    let scene = preset_scene("paper-b4.9");
    let cases: [(f64, f64, u64, &[usize]); 2] = [
        (60.0, 3e-4, 1, &[18, 19, 36]),
        (50.0, 1e-4, 2, &[28, 29, 30]),
    ];
    for (fps, noise, seed, frozen) in cases {
        let video = Video {
            fps,
            noise,
            seed,
            ..Video::default()
        };
        let track = filmed(&scene, &video, frozen);
        let (fits, found) = fits_of(&scene, &track);
        let what = format!("{fps} frames/s, noise {noise} m, frozen {frozen:?}");
        let slips = fits
            .slips
            .as_ref()
            .unwrap_or_else(|| panic!("{what}: no slips"));
        // The slips' file times are the frozen frames', in order.
        let at: Vec<f64> = slips.t.iter().map(|t| t + found.impact_t).collect();
        let want: Vec<f64> = frozen.iter().map(|&k| track.t()[k]).collect();
        assert_eq!(at.len(), want.len(), "{what}: slips at {at:?}");
        for (a, w) in at.iter().zip(&want) {
            assert!(
                (a - w).abs() < 1e-9,
                "{what}: slips at {at:?}, frozen at {want:?}"
            );
        }
        // Each lies at least half a frame's motion off (0.25 m/s or more).
        for r in &slips.residual {
            assert!(r.abs() > 0.5 * 0.25 / fps, "{what}: residual {r}");
        }
        // Without them, both fits are those of the same track unfrozen, within
        // their ± (the position fit's, of σ; the velocity fit's, of 2σ: it loses
        // each slip's neighbours too, up to a third of its points, which moves its
        // μ_k by up to about 0.7σ by chance), and the position fit holds the truth.
        let (clean, _) = fits_of(&scene, &filmed(&scene, &video, &[]));
        assert!(clean.slips.is_none(), "{what}: unfrozen, {:?}", clean.slips);
        let p = &fits.model_fit;
        assert!(p.fits_disagree.is_none(), "{what}: {:?}", p.fits_disagree);
        let pairs = [
            ("position", p, &clean.model_fit, 1.0),
            (
                "velocity",
                fits.velocity_fit.as_ref().unwrap(),
                clean.velocity_fit.as_ref().unwrap(),
                2.0,
            ),
        ];
        for (fit, f, c, within) in pairs {
            assert!(
                (f.mu - c.mu).abs() <= within * c.mu_se,
                "{what}: {fit} fit μ_k {} ± {}, unfrozen {} ± {}",
                f.mu,
                f.mu_se,
                c.mu,
                c.mu_se
            );
        }
        assert!(
            (p.mu - MU).abs() <= 2.5 * p.mu_se,
            "{what}: μ_k {} ± {}",
            p.mu,
            p.mu_se
        );
    }
}

/// A track with no frame off its motion loses none, whatever its frame rate and
/// noise (beside the two unfrozen tracks above): the bound is five robust spreads of
/// the residuals (or the data's scatter), and exact positions have none to speak of.
#[test]
fn a_clean_track_loses_no_frame() {
    let scene = preset_scene("paper-b4.9");
    for (fps, noise, seed) in [(30.0, 5e-4, 5), (120.0, 0.0, 9)] {
        let video = Video {
            fps,
            noise,
            seed,
            ..Video::default()
        };
        let (fits, _) = fits_of(&scene, &filmed(&scene, &video, &[]));
        assert!(
            fits.slips.is_none(),
            "{fps} frames/s, noise {noise} m: {:?}",
            fits.slips
        );
    }
}

/// `fit` says which frames it left out, when and how far off, in the table and in
/// the JSON's `slips`.
#[test]
fn fit_says_which_frames_it_left_out() {
    let scene = preset_scene("paper-b4.9");
    let video = Video {
        fps: 50.0,
        ..Video::default()
    };
    let track = filmed(&scene, &video, &[28, 29]);
    let dir = scratch_dir("fit", "slips_said");
    let file = dir.join("frozen.txt");
    std::fs::write(&file, video::write(&track, TrackFormat::TrackerMulti)).unwrap();
    let file = file.to_str().unwrap();
    let args = ["fit", "--preset", "paper-b4.9", "--data", file];
    let table = run_in_process(&args).unwrap();
    // The frames at their file times (t_impact 0.2 s after the first frame at 50/s).
    let times = format!(
        "t = {:.3}, {:.3} s of the file",
        track.t()[28],
        track.t()[29]
    );
    assert!(
        table.contains("2 of ") && table.contains("as tracking slips") && table.contains(&times),
        "{times}:\n{table}"
    );
    let j: serde_json::Value = serde_json::from_str(
        &run_in_process(&[&args[..], &["--format", "json"]].concat()).unwrap(),
    )
    .unwrap();
    let slips = &j["slips"];
    assert_eq!(slips["t"].as_array().map(Vec::len), Some(2), "{slips}");
    assert!(
        slips["beyond"]
            .as_f64()
            .is_some_and(|b| b > 0.0 && b < 5e-3),
        "{slips}"
    );
}
