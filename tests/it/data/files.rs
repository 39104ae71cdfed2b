//! A student's own files (issue 19), each made here by a generator from the exact
//! solution with the truth known: Tracker's one-track export (alone, and the centre
//! and the rim mark as two files), a Logger Pro / Graphical Analysis two-point export,
//! a velocity file recorded with x reversed, and one without units in ms and cm/s.

use crate::common;
use std::path::{Path, PathBuf};

use groovelab::input::data::{self, Reading};
use groovelab::physics::engine;
use groovelab::physics::scene::{Scene, Span};
use groovelab::study::measured::{Derive, Track};
use groovelab::study::video::{self, Video};

const MU: f64 = 0.17;

fn scene() -> Scene {
    crate::common::paper_scene()
}

fn scratch(test: &str) -> PathBuf {
    crate::common::scratch_dir("files", test)
}

fn groovelab(args: &[&str]) -> (bool, String, String) {
    let out = common::groovelab(args);
    (
        out.status.success(),
        String::from_utf8(out.stdout).unwrap(),
        String::from_utf8(out.stderr).unwrap(),
    )
}

fn fit_json(data: &[&Path], extra: &[&str]) -> serde_json::Value {
    let mut args = vec!["fit", "--preset", "paper-b4.9", "--format", "json"];
    for d in data {
        args.extend(["--data", d.to_str().unwrap()]);
    }
    args.extend(extra);
    let (ok, out, err) = groovelab(&args);
    assert!(ok, "{err}");
    serde_json::from_str(&out).unwrap()
}

/// A velocity from neighbouring positions, as Tracker computes it: none (NaN) at the
/// first and last frames.
fn central(t: &[f64], x: &[f64], i: usize) -> f64 {
    if i == 0 || i + 1 == t.len() {
        f64::NAN
    } else {
        (x[i + 1] - x[i - 1]) / (t[i + 1] - t[i - 1])
    }
}

/// Tracker's Export Data of one track: the track's name with spaces as underscores,
/// then `t x y v_x v_y`, tab-separated, scientific numbers, `NaN` where it cannot
/// differentiate (the first and last rows; the last row's v_y left empty).
fn tracker_export(name: &str, t: &[f64], x: &[f64], y: &[f64]) -> String {
    let mut out = format!("{}\nt\tx\ty\tv_x\tv_y\n", name.replace(' ', "_"));
    for i in 0..t.len() {
        let (vx, vy) = (central(t, x, i), central(t, y, i));
        let cell = |v: f64| {
            if v.is_finite() {
                format!("{v:.9E}")
            } else {
                "NaN".into()
            }
        };
        let vy = if i + 1 == t.len() {
            String::new()
        } else {
            cell(vy)
        };
        out += &format!(
            "{}\t{}\t{}\t{}\t{vy}\n",
            cell(t[i]),
            cell(x[i]),
            cell(y[i]),
            cell(vx)
        );
    }
    out
}

/// Logger Pro / Graphical Analysis's CSV export of a video analysis with two points
/// (the centre, and the rim mark as the second point), CRLF line ends.
fn logger_pro_export(track: &Track) -> String {
    let (mx, my) = track.mark().unwrap();
    let mut text = String::from(
        "\"Latest: Time (s)\",\"Latest: X (m)\",\"Latest: Y (m)\",\"Latest: X2 (m)\",\"Latest: Y2 (m)\"\r\n",
    );
    for i in 0..track.t().len() {
        text += &format!(
            "{:.4},{:.5},{:.5},{:.5},{:.5}\r\n",
            track.t()[i],
            track.x()[i],
            track.y()[i],
            mx[i],
            my[i]
        );
    }
    text
}

/// The README's student files, made from the committed example video: Tracker's
/// one-track exports of the centre and of the rim mark, and a Logger Pro export.
fn student_files() -> Vec<(&'static str, String)> {
    let example = std::fs::read_to_string("docs/video/paper-b4.9-tracker.txt").unwrap();
    let track =
        groovelab::input::data::read_track(&example, "example", &Default::default()).unwrap();
    let (mx, my) = track.mark().unwrap();
    vec![
        (
            "docs/video/ball.txt",
            tracker_export("ball", track.t(), track.x(), track.y()),
        ),
        (
            "docs/video/mark.txt",
            tracker_export("rim mark", track.t(), mx, my),
        ),
        ("docs/video/logger-pro.csv", logger_pro_export(&track)),
    ]
}

/// The files the README walks through: regenerate with `GROOVELAB_REGENERATE=1 cargo
/// test --test it data_files::student`.
#[test]
fn student_files_are_what_the_generator_makes() {
    for (path, text) in student_files() {
        if std::env::var_os("GROOVELAB_REGENERATE").is_some() {
            std::fs::write(path, &text).unwrap();
        }
        let committed = std::fs::read_to_string(path).unwrap_or_default();
        assert!(
            committed == text,
            "{path} differs from the generator's output; regenerate it"
        );
    }
}

/// The synthetic video of the preset's scene, centre and rim mark.
fn video_track(seed: u64) -> Track {
    video::track(
        &scene(),
        &Video {
            seed,
            noise: 2e-4,
            ..Video::default()
        },
    )
    .unwrap()
}

#[test]
fn a_tracker_one_track_export_reads_its_positions_only() {
    let track = video_track(3);
    let dir = scratch("tracker-one");
    let ball = dir.join("ball.txt");
    std::fs::write(
        &ball,
        tracker_export("mass A", track.t(), track.x(), track.y()),
    )
    .unwrap();
    let j = fit_json(&[&ball], &[]);
    // The velocity columns are not taken for a rim mark: the centre alone.
    assert_eq!(j["track"]["format"], "Tracker single-track");
    assert_eq!(j["track"]["centre"], "mass_A");
    assert!(j["track"]["mark"].is_null(), "{}", j["track"]);
    assert_eq!(j["track"]["frames"].as_u64(), Some(track.t().len() as u64));
    let mu = j["model_fit"]["mu"].as_f64().unwrap();
    assert!((mu - MU).abs() < 0.003, "μ_k = {mu}");
    // What a centre alone cannot give is null with a reason, and never NaN on screen.
    assert!(j["line_fit"]["mu_t"].is_null());
    let why = j["not_measured"].as_array().unwrap();
    assert!(
        why.iter().any(|w| w["quantity"] == "line_fit.mu_t"
            && w["reason"].as_str().unwrap().contains("no rim mark")),
        "{why:?}"
    );
    let f = ball.to_str().unwrap();
    let (ok, table, err) = groovelab(&["fit", "--preset", "paper-b4.9", "--data", f]);
    assert!(ok, "{err}");
    assert!(
        !table.contains("NaN") && table.contains("not measured"),
        "{table}"
    );
    for keys in ["", "f"] {
        let (ok, screen, err) = groovelab(&[
            "render",
            "--preset",
            "paper-b4.9",
            "--data",
            f,
            "--keys",
            keys,
        ]);
        assert!(ok, "{err}");
        assert!(!screen.contains("NaN"), "keys '{keys}':\n{screen}");
        assert!(screen.contains("not measured"), "keys '{keys}':\n{screen}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn the_centre_and_the_mark_as_two_tracker_files() {
    let track = video_track(4);
    let (mx, my) = track.mark().unwrap();
    let dir = scratch("tracker-two");
    let (ball, mark) = (dir.join("ball.txt"), dir.join("mark.txt"));
    std::fs::write(
        &ball,
        tracker_export("ball", track.t(), track.x(), track.y()),
    )
    .unwrap();
    // The mark's file starts two frames later: matched by time, not by row.
    std::fs::write(
        &mark,
        tracker_export("rim mark", &track.t()[2..], &mx[2..], &my[2..]),
    )
    .unwrap();
    let j = fit_json(&[&ball, &mark], &[]);
    assert_eq!(j["track"]["format"], "two Tracker single-track files");
    assert_eq!(j["track"]["mark"], "rim_mark");
    let r = j["track"]["mark_radius"].as_f64().unwrap();
    assert!((r - scene().radius).abs() < 1e-3, "mark radius {r}");
    let mu = j["model_fit"]["mu"].as_f64().unwrap();
    assert!((mu - MU).abs() < 0.003, "μ_k = {mu}");
    // v_t is measured now: the line fit's μ_k,t is a number.
    assert!(
        j["line_fit"]["mu_t"].as_f64().is_some(),
        "{}",
        j["line_fit"]
    );
    // The app and render take the pair as well.
    let (ok, screen, err) = groovelab(&[
        "render",
        "--preset",
        "paper-b4.9",
        "--data",
        ball.to_str().unwrap(),
        "--data",
        mark.to_str().unwrap(),
        "--at",
        "0.1",
    ]);
    assert!(ok, "{err}");
    assert!(screen.contains("measured ball"), "{screen}");
    // A third file is refused in one line.
    let (ok, _, err) = groovelab(&[
        "fit",
        "--preset",
        "paper-b4.9",
        "--data",
        ball.to_str().unwrap(),
        "--data",
        mark.to_str().unwrap(),
        "--data",
        mark.to_str().unwrap(),
    ]);
    assert!(!ok && err.contains("--data given 3 times"), "{err}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_logger_pro_two_point_export_gives_centre_and_mark() {
    let text = logger_pro_export(&video_track(5));
    let dir = scratch("loggerpro");
    let file = dir.join("run.csv");
    std::fs::write(&file, &text).unwrap();
    let j = fit_json(&[&file], &[]);
    assert_eq!(j["track"]["format"], "Logger Pro / Graphical Analysis");
    assert_eq!(j["track"]["mark"], "point 2");
    let mu = j["model_fit"]["mu"].as_f64().unwrap();
    assert!((mu - MU).abs() < 0.003, "μ_k = {mu}");
    // "Run 1:" is a run prefix as well.
    std::fs::write(&file, text.replace("Latest:", "Run 1:")).unwrap();
    let j = fit_json(&[&file], &[]);
    assert_eq!(j["track"]["mark"], "point 2");
    let _ = std::fs::remove_dir_all(&dir);
}

/// The exact left ball's v_cm and v_t at 100 frames/s from −0.1 s to 0.5 s, the frame
/// at the impact left out.
fn velocities() -> Vec<(f64, f64, f64)> {
    let s = scene();
    let sol = engine::solve(
        &s,
        &Span {
            t_start: -0.2,
            t_end: Some(0.6),
        },
    );
    (-10..=50)
        .filter(|&k| k != 0)
        .map(|k| {
            let t = k as f64 * 0.01;
            let st = sol.at(t);
            (t, st.left.v, st.left.u)
        })
        .collect()
}

#[test]
fn a_velocity_file_recorded_with_x_reversed_is_turned() {
    let dir = scratch("reversed");
    let file = dir.join("reversed.csv");
    let mut text = String::from("t (s),v_cm (m/s),v_t (m/s)\n");
    for (t, v, u) in velocities() {
        text += &format!("{:.3},{:.5},{:.5}\n", t + 1.0, -v, -u);
    }
    std::fs::write(&file, &text).unwrap();
    let j = fit_json(&[&file], &[]);
    let mu = j["model_fit"]["mu"].as_f64().unwrap();
    assert!((mu - MU).abs() < 0.002, "μ_k = {mu}");
    // Turned, and said so (once turned without a word): JSON `mirrored`, the table's
    // line under the scene, the app's status line.
    assert_eq!(j["mirrored"], true);
    // With the impact given, too (once an overflow error).
    let path = file.to_str().unwrap();
    let (ok, table, err) = groovelab(&[
        "fit",
        "--preset",
        "paper-b4.9",
        "--data",
        path,
        "--impact-at",
        "1",
    ]);
    assert!(ok, "{err}");
    let mu: f64 = table
        .split("μ_k = ")
        .nth(1)
        .and_then(|r| r.split_whitespace().next())
        .and_then(|v| v.parse().ok())
        .unwrap_or_else(|| panic!("{table}"));
    assert!((mu - MU).abs() < 0.002, "μ_k = {mu}");
    assert!(
        table.contains(&format!("x runs toward −x in {path}: read mirrored")),
        "{table}"
    );
    let (ok, screen, err) = groovelab(&["render", "--preset", "paper-b4.9", "--data", path]);
    assert!(ok, "{err}");
    assert!(screen.contains("reversed.csv (read mirrored)"), "{screen}");
    // The same motion recorded toward +x is read as it is, not mirrored.
    let mut forward = String::from("t (s),v_cm (m/s),v_t (m/s)\n");
    for (t, v, u) in velocities() {
        forward += &format!("{:.3},{:.5},{:.5}\n", t + 1.0, v, u);
    }
    let mirrored = |text: &str| {
        let (r, d) = (Reading::default(), Derive::default());
        data::load(text, "f.csv", &r, &d).unwrap().mirrored()
    };
    assert!(mirrored(&text) && !mirrored(&forward));
    let _ = std::fs::remove_dir_all(&dir);
}

/// Issue 19: headers in German, French or Spanish read like English ones (time and
/// position by name, in the one place header cells are read); a header with only a
/// velocity column is refused by an error that names the columns expected.
#[test]
fn headers_in_other_languages_are_read_or_the_error_names_the_columns() {
    let (r, d) = (Reading::default(), Derive::default());
    let english = {
        let mut text = String::from("t (s),v_cm (m/s),v_t (m/s)\n");
        for (t, v, u) in velocities() {
            text += &format!("{t:.3},{v:.5},{u:.5}\n");
        }
        data::load(&text, "en.csv", &r, &d).unwrap()
    };
    // A German spreadsheet: semicolons, decimal commas, "Zeit".
    let mut text = String::from("Zeit (ms);v_cm (cm/s);v_t (cm/s)\n");
    for (t, v, u) in velocities() {
        text += &format!("{:.0};{:.3};{:.3}\n", 1e3 * t, 100.0 * v, 100.0 * u).replace('.', ",");
    }
    let german = data::load(&text, "de.csv", &r, &d).unwrap();
    let (a, b) = (english.measured(), german.measured());
    assert_eq!(a.t().len(), b.t().len());
    assert!(a.t().iter().zip(b.t()).all(|(x, y)| (x - y).abs() < 1e-9));
    assert!(
        a.v_cm()
            .iter()
            .zip(b.v_cm())
            .all(|(x, y)| (x - y).abs() < 1e-5)
    );
    // Position tracks: French and Spanish names for time and position.
    let track = video_track(6);
    for (head, sep) in [
        ("temps (s),position (m)", ','),
        ("tiempo (s);posición (m)", ';'),
    ] {
        let mut text = format!("{head}\n");
        for (t, x) in track.t().iter().zip(track.x()) {
            text += &format!("{t:.5}{sep}{x:.6}\n");
        }
        let series = data::load(&text, "pos.csv", &r, &d).unwrap_or_else(|e| panic!("{head}: {e}"));
        let found = series.found().unwrap();
        assert_eq!(found.frames, track.t().len(), "{head}");
    }
    // Time and a velocity only: which columns would do is said.
    let e = data::load(
        "Zeit (s);Geschwindigkeit (m/s)\n0;0,5\n0,01;0,5\n",
        "v.csv",
        &r,
        &d,
    )
    .unwrap_err()
    .to_string();
    assert!(
        e.contains("'Geschwindigkeit (m/s)' is one speed")
            && e.contains("as columns t, v_cm and v_t; a position track needs t and x (and y)"),
        "{e}"
    );
}

#[test]
fn a_header_without_units_over_ms_and_cm_per_s_names_the_options() {
    let dir = scratch("unitless");
    let file = dir.join("unitless.csv");
    let mut text = String::from("t,v_cm,v_t\n");
    for (t, v, u) in velocities() {
        text += &format!("{:.1},{:.3},{:.3}\n", 1e3 * t, 100.0 * v, 100.0 * u);
    }
    std::fs::write(&file, &text).unwrap();
    let f = file.to_str().unwrap();
    let (ok, out, err) = groovelab(&["fit", "--preset", "paper-b4.9", "--data", f]);
    assert!(!ok && out.is_empty());
    assert!(
        err.contains("frames 10 apart")
            && err.contains("speeds up to")
            && err.contains("--time-unit ms --speed-unit cm/s")
            && err.lines().count() == 1,
        "{err}"
    );
    // Following the advice fits the truth.
    let j = fit_json(&[&file], &["--time-unit", "ms", "--speed-unit", "cm/s"]);
    let mu = j["model_fit"]["mu"].as_f64().unwrap();
    assert!((mu - MU).abs() < 0.002, "μ_k = {mu}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_rim_mark_beyond_the_ball_is_refused_and_a_narrow_window_is_widened() {
    let track = video_track(6);
    let (mx, my) = track.mark().unwrap();
    let dir = scratch("mark-off");
    let (ball, mark) = (dir.join("ball.txt"), dir.join("mark.txt"));
    std::fs::write(
        &ball,
        tracker_export("ball", track.t(), track.x(), track.y()),
    )
    .unwrap();
    std::fs::write(&mark, tracker_export("rim mark", track.t(), mx, my)).unwrap();
    let (b, m) = (ball.to_str().unwrap(), mark.to_str().unwrap());
    // The mark was tracked on a ball of R = 2.75 cm; told R = 2.5 cm (b = 4.9 cm still
    // fits), it lies 2.5 mm beyond the ball: 12 times the 0.2 mm scatter.
    for command in ["fit", "render"] {
        let out = common::groovelab(&[
            command,
            "--preset",
            "paper-b4.9",
            "--radius",
            "2.5cm",
            "--data",
            b,
            "--data",
            m,
        ]);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{command}: {err}");
        assert!(
            err.contains("the rim mark lies 2.75")
                && err.contains("from the centre, farther than the ball's R = 2.5 cm")
                && err.lines().count() == 1,
            "{command}: {err}"
        );
    }
    // A half-window under two frames is widened to two, and the output says so.
    let j = fit_json(&[&ball, &mark], &["--window", "1ms"]);
    assert_eq!(j["track"]["half_window_frames"], 2, "{}", j["track"]);
    assert_eq!(j["track"]["half_window_widened_from"].as_f64(), Some(0.001));
    let (ok, table, err) = groovelab(&[
        "fit",
        "--preset",
        "paper-b4.9",
        "--data",
        b,
        "--data",
        m,
        "--window",
        "1ms",
    ]);
    assert!(ok, "{err}");
    assert!(table.contains("(the ±0.001 s asked for widened"), "{table}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_track_without_units_in_cm_or_mm_names_the_length_unit() {
    let track = video_track(5);
    let dir = scratch("track-units");
    let scaled = |k: f64| {
        let x: Vec<f64> = track.x().iter().map(|v| v * k).collect();
        let y: Vec<f64> = track.y().iter().map(|v| v * k).collect();
        tracker_export("ball", track.t(), &x, &y)
    };
    for (unit, k) in [("cm", 100.0), ("mm", 1000.0)] {
        let file = dir.join(format!("ball_{unit}.txt"));
        std::fs::write(&file, scaled(k)).unwrap();
        let f = file.to_str().unwrap();
        let out = common::groovelab(&["fit", "--preset", "paper-b4.9", "--data", f]);
        let err = String::from_utf8_lossy(&out.stderr);
        // Read as metres the ball would approach at 100 or 1000 times its v0 = 0.608 m/s.
        assert_eq!(out.status.code(), Some(2), "{unit}: {err}");
        assert!(
            err.contains("do not look like metres")
                && err.contains(&format!("give --length-unit {unit}"))
                && err.lines().count() == 1,
            "{unit}: {err}"
        );
        // Following the advice fits the truth.
        let j = fit_json(&[&file], &["--length-unit", unit]);
        let mu = j["model_fit"]["mu"].as_f64().unwrap();
        assert!((mu - MU).abs() < 0.003, "{unit}: μ_k = {mu}");
    }
    // The units of an SI file given wrongly: said in words, not as an overflow.
    let file = dir.join("ball.txt");
    std::fs::write(&file, scaled(1.0)).unwrap();
    let f = file.to_str().unwrap();
    let out = common::groovelab(&[
        "fit",
        "--preset",
        "paper-b4.9",
        "--data",
        f,
        "--time-unit",
        "ms",
    ]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(
        err.contains("in the units given the frames are") && !err.contains("overflow"),
        "{err}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

/// The exact left ball's velocities of `scene` at 100 frames/s with seeded noise of
/// 1 cm/s, the frame at the impact left out.
fn noisy_velocities(scene: &Scene, seed: u64) -> groovelab::study::measured::Measured {
    let sol = engine::solve(
        scene,
        &Span {
            t_start: -0.2,
            t_end: Some(0.8),
        },
    );
    let mut noise = video::Noise::new(seed);
    let (mut t, mut v, mut u) = (vec![], vec![], vec![]);
    for k in (-15..=70).filter(|&k| k != 0) {
        let s = sol.at(k as f64 * 0.01);
        t.push(k as f64 * 0.01);
        v.push(s.left.v + 0.01 * noise.gauss());
        u.push(s.left.u + 0.01 * noise.gauss());
    }
    groovelab::study::measured::Measured::velocities(t, v, u).unwrap()
}

#[test]
fn a_fit_far_beyond_the_datas_scatter_never_agrees() {
    use groovelab::study::fit::{Agreement, Free, POOR_FIT, model_fit};
    let truth = scene();
    // Measured at twice the scene's v0: the regime depends on k and e only, so the
    // regimes agree, yet no μ_k brings the model near the data.
    let mut fast = truth;
    fast.left.v0 *= 2.0;
    fast.right.v0 *= 2.0;
    let m = noisy_velocities(&fast, 7);
    let quiet = &groovelab::study::Quiet;
    let f = model_fit(&truth, &m, &[Free::Mu], quiet).unwrap();
    let scatter = f.scatter.unwrap();
    // The noise is 1 cm/s: the scatter says so within a quarter.
    assert!((scatter - 0.01).abs() < 0.0025, "scatter {scatter}");
    assert!(
        f.rms > POOR_FIT * scatter,
        "rms {} scatter {scatter}",
        f.rms
    );
    assert_eq!(f.regime_predicted, f.regime_observed);
    assert_eq!(f.agreement(), Agreement::PoorFit);
    // The same data in their own scene: residuals of about the scatter, and agreed.
    let g = model_fit(&fast, &m, &[Free::Mu], quiet).unwrap();
    assert!(g.rms < 2.0 * scatter, "rms {}", g.rms);
    assert_eq!(g.agreement(), Agreement::Agrees);
}

#[test]
fn the_fit_names_the_simplest_model_the_data_support() {
    use groovelab::study::fit::compare_models;
    let truth = scene();
    let supported = |s: &Scene, seed: u64| {
        let models =
            compare_models(&truth, &noisy_velocities(s, seed), &groovelab::study::Quiet).unwrap();
        assert!(
            models.len() == 8,
            "v0 is a candidate: the approach is measured"
        );
        assert!(
            models
                .iter()
                .all(|c| c.aic.is_finite() && c.bic.is_finite())
        );
        let picked: Vec<_> = models.iter().filter(|c| c.supported).collect();
        assert_eq!(picked.len(), 1);
        picked[0].name.clone()
    };
    // Friction alone made the data: μ_k alone is named, whatever the noise.
    for seed in 1..=2 {
        assert_eq!(supported(&truth, seed), "mu", "seed {seed}");
    }
    // With rolling resistance in the truth, the data ask for c_rr.
    let resisted = Scene {
        rolling_resistance: 0.02,
        ..truth
    };
    let name = supported(&resisted, 3);
    assert!(name.contains("rolling_resistance"), "{name}");
}

#[test]
fn fit_json_has_one_entry_per_model_with_aic_and_bic() {
    let (ok, out, err) = groovelab(&["fit", "--format", "json"]);
    assert!(ok, "{err}");
    let j: serde_json::Value = serde_json::from_str(&out).unwrap();
    let models = j["models"].as_array().unwrap();
    assert!(models.len() >= 4);
    for m in models {
        assert!(
            m["aic"].as_f64().is_some() && m["bic"].as_f64().is_some(),
            "{m}"
        );
        assert!(m["parameters"][0]["parameter"] == "mu", "{m}");
    }
    assert_eq!(models.iter().filter(|m| m["supported"] == true).count(), 1);
    let (ok, table, _) = groovelab(&["fit"]);
    assert!(
        ok && table.contains("which model the data support")
            && table.contains("the data support: ")
    );
}

/// Two plausibility checks on a track (the trial): the same file given as centre and
/// as mark puts a "rim mark" 0.0 mm from the centre, and metres read as mm make a
/// ball approach at 0.6 mm/s; both passed every check and fitted noise. Refused,
/// one line, exit 2.
#[test]
fn a_mark_at_the_centre_and_metres_read_as_mm_are_refused() {
    let track = video_track(5);
    let dir = scratch("implausible");
    let ball = dir.join("ball.txt");
    std::fs::write(
        &ball,
        tracker_export("mass A", track.t(), track.x(), track.y()),
    )
    .unwrap();
    let f = ball.to_str().unwrap();
    let (ok, _, err) = groovelab(&["fit", "--preset", "paper-b4.9", "--data", f, "--data", f]);
    assert!(
        !ok && err.contains("rim mark lies 0.00 mm from the centre"),
        "{err}"
    );
    assert_eq!(err.lines().count(), 1, "{err}");
    let (ok, _, err) = groovelab(&[
        "fit",
        "--preset",
        "paper-b4.9",
        "--data",
        f,
        "--length-unit",
        "mm",
    ]);
    assert!(
        !ok && err.contains("slower than any ball") && err.contains("--length-unit"),
        "{err}"
    );
    assert_eq!(err.lines().count(), 1, "{err}");
    // Read as metres (as written) it fits.
    let (ok, _, err) = groovelab(&["fit", "--preset", "paper-b4.9", "--data", f]);
    assert!(ok, "{err}");
}

/// A data row with more filled cells than its header names is refused, naming its
/// line: which number is which cannot be told. A comma-separated file written with
/// decimal commas (`0,1,0,5,0,2` under `t,v_cm,v_t`) read each number's integer
/// part as a column and was refused for times that do not increase, or, for a
/// position track, read silently wrong; the error now says so and suggests the fix.
/// Trailing empty cells (a spreadsheet's export) are no extra fields.
#[test]
fn a_row_wider_than_its_header_is_refused_naming_the_line() {
    let (r, d) = (Reading::default(), Derive::default());
    let velocities_rows: String = velocities()
        .iter()
        // Decimal points written as commas, the columns separated by commas too.
        .map(|(t, v, u)| format!("{t:.3},{v:.5},{u:.5}\n").replace('.', ","))
        .collect();
    let positions = video_track(3);
    let rows = |sep: char| -> String {
        positions
            .t()
            .iter()
            .zip(positions.x())
            .map(|(t, x)| format!("{t:.5}{sep}{x:.6}\n"))
            .collect()
    };
    for (name, text, line, decimal) in [
        (
            "velocities with decimal commas",
            format!("t,v_cm,v_t\n{velocities_rows}"),
            2,
            true,
        ),
        (
            "positions with decimal commas",
            format!("t,x\n{}", rows(',').replace('.', ",")),
            2,
            true,
        ),
        (
            "a tab file with a stray cell",
            {
                let mut t = format!("t\tx\n{}", rows('\t'));
                let third = t.lines().nth(3).unwrap().to_string();
                t = t.replacen(&third, &format!("{third}\t7"), 1);
                t
            },
            4,
            false,
        ),
    ] {
        let e = data::load(&text, "f.csv", &r, &d)
            .map(|_| ())
            .unwrap_err()
            .to_string();
        assert!(e.contains(&format!("line {line}: ")), "{name}: {e}");
        assert!(
            e.contains("so which number is which cannot be told"),
            "{name}: {e}"
        );
        assert_eq!(
            e.contains("decimal commas in a comma-separated file?"),
            decimal,
            "{name}: {e}"
        );
    }
    // Trailing empty cells, as a spreadsheet leaves them, are read as before.
    let trailing = format!("t,x,,\n{}", rows(',').replace('\n', ",,\n"));
    let plain = format!("t,x\n{}", rows(','));
    let (a, b) = (
        data::load(&trailing, "f.csv", &r, &d).unwrap(),
        data::load(&plain, "f.csv", &r, &d).unwrap(),
    );
    assert_eq!(a.measured().t(), b.measured().t());
    assert_eq!(a.measured().v_cm(), b.measured().v_cm());
}
