//! Units checked beyond the speeds (issue 27): a velocity file whose speed unit makes
//! the ball's spin change faster than friction can (a slow ball's cm/s under an m/s
//! header) is refused naming the unit that fits, while genuine noisy files open; and
//! options that do not apply to what a file holds are refused.

use groovelab::physics::engine;
use groovelab::physics::scene::{Scene, Span};
use groovelab::study::video::Noise;

fn groovelab(args: &[&str]) -> (Option<i32>, String, String) {
    let out = crate::common::groovelab(args);
    (
        out.status.code(),
        String::from_utf8(out.stdout).unwrap(),
        String::from_utf8(out.stderr).unwrap(),
    )
}

/// The paper's groove (R = 2 cm, b = 4.9 cm, μ_k = 0.16 … ) with both balls at `v0`.
fn scene(v0: f64) -> Scene {
    let mut s = crate::common::paper_scene();
    s.left.v0 = v0;
    s.right.v0 = v0;
    s
}

/// The left ball's v_cm and v_t from −0.2 s to 0.6 s at `fps`, the impact between two
/// frames, with Gaussian noise `sigma` (m/s), written multiplied by `scale` (100: cm/s)
/// under `header`.
fn velocity_file(v0: f64, fps: f64, sigma: f64, scale: f64, header: &str) -> String {
    let sol = engine::solve(
        &scene(v0),
        &Span {
            t_start: -0.3,
            t_end: Some(0.7),
        },
    );
    let mut noise = Noise::new(7);
    let mut text = format!("{header}\n");
    let first = (-0.2 * fps).round() as i32;
    for k in first..=(0.6 * fps).round() as i32 {
        let t = (f64::from(k) + 0.4) / fps;
        let st = sol.at(t);
        let v = st.left.v + sigma * noise.gauss();
        let u = st.left.u + sigma * noise.gauss();
        text += &format!("{t:.5},{:.4},{:.4}\n", v * scale, u * scale);
    }
    text
}

#[test]
fn a_slow_ball_in_cm_per_s_under_an_m_per_s_header_is_refused_naming_cm_per_s() {
    let dir = crate::common::scratch_dir("units_checked", "slow");
    // A ball at 8 cm/s: its numbers (8 → 0) are below 10 m/s, so the speeds alone
    // passed; its spin changes at (5/2) k μ_k g ≈ 3 m/s², 300 "m/s²" as written.
    for fps in [60.0, 100.0, 240.0] {
        let file = dir.join(format!("slow{fps}.csv"));
        let text = velocity_file(0.08, fps, 0.0, 100.0, "t (s),v_cm (m/s),v_t (m/s)");
        std::fs::write(&file, &text).unwrap();
        let f = file.to_str().unwrap();
        for command in ["data", "fit"] {
            let args: Vec<&str> = if command == "data" {
                vec!["data", f]
            } else {
                vec!["fit", "--preset", "paper-b4.9", "--data", f]
            };
            let (code, out, err) = groovelab(&args);
            assert_eq!(code, Some(2), "{fps} {command}: {out}");
            assert!(
                err.contains("v_t changing by up to")
                    && err.contains(
                        "fix the header (v_cm (cm/s), v_t (cm/s)) or give --speed-unit cm/s"
                    )
                    && err.lines().count() == 1,
                "{fps} {command}: {err}"
            );
        }
        // The option it names reads the file as the ball was.
        let (code, out, err) = groovelab(&["data", f, "--speed-unit", "cm/s"]);
        assert_eq!(code, Some(0), "{fps}: {err}");
        assert!(out.contains("v_cm in cm/s: --speed-unit"), "{out}");
        // Without units the hint names cm/s too.
        let bare = dir.join(format!("bare{fps}.csv"));
        std::fs::write(
            &bare,
            text.replacen("t (s),v_cm (m/s),v_t (m/s)", "t,v_cm,v_t", 1),
        )
        .unwrap();
        let (code, _, err) = groovelab(&["data", bare.to_str().unwrap()]);
        assert_eq!(code, Some(2));
        assert!(err.contains("give --speed-unit cm/s"), "{err}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn genuine_noisy_velocity_files_open_whatever_their_speed() {
    let dir = crate::common::scratch_dir("units_checked", "genuine");
    // Slow and fast balls in m/s and in cm/s (stated), with a tracker's scatter of
    // derived velocities (0.01 m/s to 0.15 m/s between frames): none is refused.
    for (v0, fps, sigma) in [
        (0.08, 240.0, 0.02),
        (0.08, 60.0, 0.01),
        (0.45, 240.0, 0.15),
        (0.8, 120.0, 0.1),
        (2.0, 240.0, 0.15),
        (0.8, 30.0, 0.05),
    ] {
        for (scale, header) in [
            (1.0, "t (s),v_cm (m/s),v_t (m/s)"),
            (100.0, "t (s),v_cm (cm/s),v_t (cm/s)"),
        ] {
            let file = dir.join("genuine.csv");
            std::fs::write(&file, velocity_file(v0, fps, sigma, scale, header)).unwrap();
            let (code, _, err) = groovelab(&["data", file.to_str().unwrap()]);
            assert_eq!(
                code,
                Some(0),
                "v0 {v0} at {fps} ± {sigma} in {header}: {err}"
            );
        }
    }
    // One glitch of the tracked v_t (3 m/s up and back, a mark mistaken for a frame)
    // is no change of the spin.
    for (fps, row) in [100.0, 240.0]
        .into_iter()
        .flat_map(|f| [5, 20, 21, 22, 30, 40, 41, 60].map(|r| (f, r)))
    {
        let text = velocity_file(0.5, fps, 0.01, 1.0, "t (s),v_cm (m/s),v_t (m/s)");
        let glitched: String = text
            .lines()
            .enumerate()
            .map(|(i, l)| {
                if i != row {
                    return format!("{l}\n");
                }
                let c: Vec<&str> = l.split(',').collect();
                let u: f64 = c[2].parse().unwrap();
                format!("{},{},{:.4}\n", c[0], c[1], u + 3.0)
            })
            .collect();
        let file = dir.join("glitch.csv");
        std::fs::write(&file, glitched).unwrap();
        let (code, _, err) = groovelab(&["data", file.to_str().unwrap()]);
        assert_eq!(code, Some(0), "glitch in row {row} at {fps}: {err}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn an_option_for_what_the_file_does_not_hold_is_refused_naming_both() {
    let dir = crate::common::scratch_dir("units_checked", "options");
    let velocities = dir.join("v.csv");
    std::fs::write(
        &velocities,
        velocity_file(0.5, 100.0, 0.0, 1.0, "t (s),v_cm (m/s),v_t (m/s)"),
    )
    .unwrap();
    let track = dir.join("track.csv");
    let mut text = String::from("t (s),x (m),y (m)\n");
    for k in 0..40 {
        let t = f64::from(k) * 0.01;
        // Toward the other ball at 0.5 m/s, back at 0.1 m/s after an impact at 0.2 s.
        let x = if t < 0.2 {
            0.5 * t
        } else {
            0.1 - 0.1 * (t - 0.2)
        };
        text += &format!("{t:.2},{x:.4},0\n");
    }
    std::fs::write(&track, &text).unwrap();
    let (v, p) = (velocities.to_str().unwrap(), track.to_str().unwrap());
    let cases: [(&[&str], &str); 5] = [
        (
            &["data", v, "--length-unit", "cm"],
            "--length-unit does not apply to",
        ),
        (
            &["data", v, "--scale", "0.5mm"],
            "--scale does not apply to",
        ),
        (
            &[
                "fit",
                "--preset",
                "paper-b4.9",
                "--data",
                v,
                "--length-unit",
                "mm",
            ],
            "--length-unit does not apply to",
        ),
        (
            &["data", p, "--speed-unit", "cm/s"],
            "--speed-unit does not apply to",
        ),
        (
            &[
                "fit",
                "--preset",
                "paper-b4.9",
                "--data",
                p,
                "--speed-unit",
                "cm/s",
            ],
            "--speed-unit does not apply to",
        ),
    ];
    for (args, want) in cases {
        let (code, _, err) = groovelab(args);
        assert_eq!(code, Some(2), "{args:?}: {err}");
        assert!(
            err.contains(want) && err.lines().count() == 1,
            "{args:?}: {err}"
        );
        let holds = if want.contains("speed") {
            "it holds a position track"
        } else {
            "it holds velocities (t, v_cm, v_t)"
        };
        assert!(err.contains(holds), "{err}");
    }
    // With both kinds among data's files each option applies to one of them.
    let (code, _, err) = groovelab(&["data", v, p, "--speed-unit", "m/s", "--length-unit", "m"]);
    assert_eq!(code, Some(0), "{err}");
    let _ = std::fs::remove_dir_all(&dir);
}

/// A video's tracks are made in metres and seconds: `--length-unit` and
/// `--time-unit` with a video are refused before it is tracked (a new user's
/// `fit --data clip.mp4 --length-unit cm` gave μ_k a hundred times small, "agrees").
/// The clip here is no video at all: the refusal must come before it is read.
#[test]
fn a_length_or_time_unit_for_a_video_is_refused_before_tracking() {
    let dir = crate::common::scratch_dir("units_checked", "video");
    let clip = dir.join("clip.mp4");
    std::fs::write(&clip, "no video: never read").unwrap();
    let c = clip.to_str().unwrap();
    let cases: [(&[&str], &str); 4] = [
        (
            &[
                "fit",
                "--radius",
                "2.75cm",
                "--data",
                c,
                "--length-unit",
                "cm",
            ],
            "--length-unit",
        ),
        (
            &[
                "fit",
                "--radius",
                "2.75cm",
                "--data",
                c,
                "--time-unit",
                "ms",
            ],
            "--time-unit",
        ),
        (
            &["data", c, "--radius", "2.75cm", "--time-unit", "ms"],
            "--time-unit",
        ),
        (
            &["data", c, "--radius", "2.75cm", "--length-unit", "mm"],
            "--length-unit",
        ),
    ];
    for (args, flag) in cases {
        let (code, _, err) = groovelab(args);
        assert_eq!(code, Some(2), "{args:?}: {err}");
        let want = format!(
            "{flag} does not apply to {c}: it holds a video, tracked in metres and seconds"
        );
        assert!(
            err.contains(&want) && err.lines().count() == 1,
            "{args:?}: {err}"
        );
    }
}

/// A Tracker single-track export (its track's name, then `t x y`, numbers as Tracker
/// writes them: 1.234567890E2) of a ball approaching at `v` units per s for 0.2 s and
/// rolling back at v/5, at 100 frames/s: pixels when the video was never calibrated.
fn tracker_export(v: f64) -> String {
    let mut text = String::from("mass_A\nt x y\n");
    for k in 0..50 {
        let t = f64::from(k) * 0.01;
        let x = if t < 0.2 {
            v * t
        } else {
            0.2 * v - 0.2 * v * (t - 0.2)
        };
        text += &format!("{t:.9E} {:.9E} {:.9E}\n", 320.0 + x, 240.0);
    }
    text
}

#[test]
fn pixels_of_a_video_never_calibrated_are_named_with_scale_not_only_a_length_unit() {
    let dir = crate::common::scratch_dir("units_checked", "pixels");
    // 0.6 m/s at 2 pixels per mm: 1200 pixels/s (as mm 1.2 m/s, which fits too).
    let file = dir.join("px.txt");
    std::fs::write(&file, tracker_export(1200.0)).unwrap();
    // `fit` refuses it; `data` shows it in the file's own unit with the same words.
    let (code, out, _) = groovelab(&["data", file.to_str().unwrap()]);
    assert_eq!(code, Some(0));
    assert!(
        out.contains("lengths shown in the file's own unit") && out.contains("--scale"),
        "{out}"
    );
    let fit = [
        "fit",
        "--preset",
        "paper-b4.9",
        "--data",
        file.to_str().unwrap(),
    ];
    let (code, _, err) = groovelab(&fit);
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.contains("give --length-unit mm")
            && err.contains("if they are pixels of a video never calibrated, give the length one pixel shows with --scale (e.g. --scale 0.5mm)")
            && err.lines().count() == 1,
        "{err}"
    );
    // The option it names reads it: 0.5 mm a pixel, 0.6 m/s.
    let (code, out, err) = groovelab(&["data", file.to_str().unwrap(), "--scale", "0.5mm"]);
    assert_eq!(code, Some(0), "{err}");
    assert!(out.contains("approach speed 0.6"), "{out}");
    // A high-resolution video: 24,000 pixels/s is beyond even mm; no length unit
    // guessed, pixels and both options named.
    std::fs::write(&file, tracker_export(24_000.0)).unwrap();
    let (code, _, err) = groovelab(&fit);
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.contains("they are not m, cm or mm: if they are pixels")
            && err.contains("--scale (e.g. --scale 0.5mm), or their unit with --length-unit")
            && !err.contains("give --length-unit mm"),
        "{err}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}
