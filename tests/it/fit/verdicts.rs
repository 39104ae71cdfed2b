//! Verdicts that name the likely mistake (issue 27's trial): a μ_k beyond 1 (a file's
//! speeds in cm/s under a header that says m/s), or below 0.01 (the other way), never
//! "agrees", and a `--width` that
//! the measured a_t/a_cm contradicts is named in the summary.

use groovelab::physics::engine::solve;
use groovelab::physics::scene::{Scene, Span};

use crate::common::{json, scratch_dir, stdout, symmetric};

/// A noise-free velocity file of `scene` at 120 frames/s from 0.1 s before the
/// impact to 0.8 s after, its speeds multiplied by `factor` under an m/s header.
fn velocity_file(scene: &Scene, factor: f64) -> String {
    let sol = solve(
        scene,
        &Span {
            t_start: -0.2,
            t_end: None,
        },
    );
    let mut out = String::from("t (s),v_cm (m/s),v_t (m/s)\n");
    for k in 0..=108 {
        let t = -0.1 + f64::from(k) / 120.0 + 0.3 / 120.0;
        let s = sol.at(t);
        out += &format!(
            "{:.6},{:.6},{:.6}\n",
            t,
            factor * s.left.v,
            factor * s.left.u
        );
    }
    out
}

/// A slow ball (μ_k = 0.03, v0 = 8 cm/s) written in cm/s under an m/s header fits
/// μ_k = 100 × 0.03 = 3 and v0 = 8 m/s (every deceleration read 100× too large):
/// no verdict that agrees, in the table and in JSON, and the unit to give is named.
#[test]
fn a_mu_beyond_one_does_not_agree_and_names_the_unit() {
    let scene = symmetric(0.0275, 0.049, 0.03, 0.08, 1.0);
    let dir = scratch_dir("fit_verdicts", "mu_beyond_one");
    let path = dir.join("slow.csv");
    std::fs::write(&path, velocity_file(&scene, 100.0)).unwrap();
    let path = path.display().to_string();
    let args = [
        "fit", "--data", &path, "--radius", "2.75cm", "--width", "4.9cm",
    ];
    let text = stdout(&args);
    let head = text.lines().nth(1).unwrap();
    assert!(head.contains("μ_k > 1: units?"), "{text}");
    assert!(!head.contains("agrees"), "{text}");
    assert!(text.contains("--speed-unit cm/s"), "{text}");
    let j = json(&[&args[..], &["--format", "json"]].concat());
    let mf = &j["model_fit"];
    assert!(mf["mu"].as_f64().unwrap() > 1.0, "{mf}");
    assert_eq!(mf["mu_implausible"], true, "{mf}");
    // The same ball in m/s: μ_k 0.03, no such field.
    std::fs::write(dir.join("right.csv"), velocity_file(&scene, 1.0)).unwrap();
    let right = dir.join("right.csv").display().to_string();
    let j = json(&[
        "fit", "--data", &right, "--radius", "2.75cm", "--width", "4.9cm", "--format", "json",
    ]);
    assert!(
        (j["model_fit"]["mu"].as_f64().unwrap() - 0.03).abs() < 1e-3,
        "{j}"
    );
    assert!(j["model_fit"].get("mu_implausible").is_none());
}

/// The mirror: the paper's ball (μ_k = 0.17, v0 = 0.79 m/s) written in m/s under a
/// cm/s header fits μ_k = 0.17 / 100 and v0 = 8 mm/s (every deceleration read 100×
/// too small): no verdict that agrees, the unit to give named, and μ_k as it would
/// be. It said "agrees" of μ_k = 0.0017. A slow, slippery ball (μ_k = 0.03, its ± well
/// above 0.01) written right keeps its verdict.
#[test]
fn a_mu_below_a_hundredth_does_not_agree_and_names_the_unit() {
    let scene = symmetric(0.0275, 0.049, 0.17, 0.79, 1.0);
    let dir = scratch_dir("fit_verdicts", "mu_below_a_hundredth");
    let path = dir.join("fast.csv");
    let text = velocity_file(&scene, 1.0).replacen("(m/s)", "(cm/s)", 2);
    std::fs::write(&path, text).unwrap();
    let path = path.display().to_string();
    let args = [
        "fit", "--data", &path, "--radius", "2.75cm", "--width", "4.9cm",
    ];
    let text = stdout(&args);
    let head = text.lines().nth(1).unwrap();
    assert!(head.contains("μ_k < 0.01: units?"), "{text}");
    assert!(!head.contains("agrees"), "{text}");
    assert!(text.contains("--speed-unit m/s"), "{text}");
    assert!(text.contains("then μ_k ≈ 0.17)"), "{text}");
    let j = json(&[&args[..], &["--format", "json"]].concat());
    let mf = &j["model_fit"];
    assert!((mf["mu"].as_f64().unwrap() - 0.0017).abs() < 1e-5, "{mf}");
    assert_eq!(mf["mu_implausible"], true, "{mf}");
    let slow = symmetric(0.0275, 0.049, 0.03, 0.08, 1.0);
    std::fs::write(dir.join("slow.csv"), velocity_file(&slow, 1.0)).unwrap();
    let slow = dir.join("slow.csv").display().to_string();
    let j = json(&[
        "fit", "--data", &slow, "--radius", "2.75cm", "--width", "4.9cm", "--format", "json",
    ]);
    assert!(j["model_fit"].get("mu_implausible").is_none(), "{j}");
}

/// Data made at b = 4.26 cm (R = 2.75 cm) fitted with --width 3cm: the summary says
/// the b that D = |a_t|/|a_cm| = 5/2 (1 − b²/4R²) gives; with the right width it
/// says nothing.
#[test]
fn a_wrong_width_is_named_in_the_summary() {
    let scene = symmetric(0.0275, 0.0426, 0.15, 0.7, 1.0);
    let dir = scratch_dir("fit_verdicts", "wrong_width");
    let path = dir.join("vel.csv");
    std::fs::write(&path, velocity_file(&scene, 1.0)).unwrap();
    let path = path.display().to_string();
    let fit = |width: &str| {
        stdout(&[
            "fit", "--data", &path, "--radius", "2.75cm", "--width", width,
        ])
    };
    let wrong = fit("3cm");
    let summary: Vec<&str> = wrong.lines().take(4).collect();
    let line = summary
        .iter()
        .find(|l| l.contains("check --width"))
        .unwrap_or_else(|| panic!("{wrong}"));
    // Exact data: the width to the ± rule's places (4.2599996 ± 0.0000023 cm).
    let b: f64 = line
        .split("b ≈ ")
        .nth(1)
        .and_then(|r| r.split(' ').next())
        .and_then(|v| v.parse().ok())
        .unwrap_or_else(|| panic!("{line}"));
    assert!(
        (b - 4.26).abs() < 1e-3 && line.contains("not 3 cm"),
        "{line}"
    );
    assert!(!fit("4.26cm").contains("check --width"));
    let j = json(&[
        "fit", "--data", &path, "--radius", "2.75cm", "--width", "3cm", "--format", "json",
    ]);
    let b = j["line_fit"]["width_from_lines"]["width"].as_f64().unwrap();
    assert!((b - 0.0426).abs() < 2e-4, "{b}");
}

/// The width the measured lines give is written with its ± by the one rule every ±
/// follows (`with_uncertainty`): both to the same places. paper-b4.4's measured data
/// said "b ≈ 4.12 cm ± 0.144 cm", a ± with more places than its value.
#[test]
fn the_width_from_the_lines_and_its_pm_share_their_places() {
    let out = stdout(&["fit", "--preset", "paper-b4.4"]);
    let line = out
        .lines()
        .find(|l| l.contains("check --width"))
        .unwrap_or_else(|| panic!("{out}"));
    let after = line.split("b ≈ ").nth(1).unwrap();
    let (value, rest) = after.split_once(" ± ").unwrap();
    let pm = rest.split_whitespace().next().unwrap();
    let places = |s: &str| s.split_once('.').map_or(0, |(_, d)| d.len());
    assert_eq!(places(value), places(pm), "{line}");
    assert!(rest.starts_with(&format!("{pm} cm, not 4.4 cm")), "{line}");
    // The ± is twice the standard error the JSON gives, in cm.
    let j = json(&["fit", "--preset", "paper-b4.4", "--format", "json"]);
    let se = j["line_fit"]["width_from_lines"]["width_se"]
        .as_f64()
        .unwrap();
    let shown: f64 = pm.parse().unwrap();
    assert!(
        (shown - 200.0 * se).abs() <= 0.5 * 10f64.powi(-(places(pm) as i32)) + 1e-12,
        "{line}: se {se}"
    );
}

/// A track with a rim mark fitted at a wrong width: the b its line fits give is the
/// groove's, within its ± (± 2σ), whatever b was given. Its v_t is r θ' with the
/// scene's r, so D = |a_t|/|a_cm| holds the given k: read as a velocity file's D, the
/// b said lay halfway between the given and the truth (4.44 ± 0.04 cm for a 4.9 cm
/// groove fitted at 3.5 cm, a new user's trial). Tracks of the engine's motion at
/// 120 frames/s, 0.1 mm noise.
#[test]
fn a_tracks_rim_mark_gives_the_grooves_width_whatever_width_was_given() {
    use groovelab::study::video::{self, TrackFormat, Video};
    let dir = scratch_dir("fit_verdicts", "mark_width");
    let path = dir.join("track.txt");
    let f = path.display().to_string();
    for (truth, given) in [
        (0.049, "3.5cm"),
        (0.049, "4cm"),
        (0.049, "4.4cm"),
        (0.0426, "3cm"),
    ] {
        let scene = symmetric(0.0275, truth, 0.17, 0.7, 1.0);
        let video = Video {
            noise: 1e-4,
            ..Video::default()
        };
        let track = video::track(&scene, &video).unwrap();
        std::fs::write(&path, video::write(&track, TrackFormat::TrackerMulti)).unwrap();
        let j = json(&[
            "fit", "--data", &f, "--radius", "2.75cm", "--width", given, "--mu", "0.17",
            "--format", "json",
        ]);
        let w = &j["line_fit"]["width_from_lines"];
        let (b, se) = (w["width"].as_f64(), w["width_se"].as_f64());
        let (Some(b), Some(se)) = (b, se) else {
            panic!(
                "b = {truth} m given {given}: no width said: {}",
                j["line_fit"]
            );
        };
        assert!(
            (b - truth).abs() <= 2.0 * se && se < 0.002,
            "b = {truth} m given {given}: {b} ± {se}"
        );
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// A track whose header states a unit its numbers are not in: the hint names the
/// unit that brings μ_k to the truth, whatever the header said. mm under a `(cm)`
/// header fit μ_k 10× too large, and the hint said "give --length-unit cm", the unit
/// already in force (a loop); mm under `(m)` is 1000×. With a rim mark, the mark
/// lies 10× (1000×) R from the centre, and that refusal names the unit too.
#[test]
fn the_unit_hint_names_the_unit_that_fits_whatever_the_header_said() {
    use groovelab::study::video::{self, TrackFormat, Video};
    let dir = scratch_dir("fit_verdicts", "unit_hint");
    let path = dir.join("track.csv");
    let f = path.display().to_string();
    let scene = symmetric(0.0275, 0.049, 0.17, 0.7, 1.0);
    for mark in [false, true] {
        let video = Video {
            mark,
            ..Video::default()
        };
        let track = video::track(&scene, &video).unwrap();
        // `t (s)`, `x (mm)`: the numbers in mm.
        let text = video::write(&track, TrackFormat::CsvComma);
        assert!(text.contains("(mm)"), "{}", &text[..100]);
        for (header, p, read) in [("(cm)", 10, "cm"), ("(m)", 1000, "m")] {
            std::fs::write(&path, text.replace("(mm)", header)).unwrap();
            let args = [
                "fit",
                "--data",
                &f,
                "--radius",
                "2.75cm",
                "--width",
                "4.9cm",
                "--length-unit",
                read,
            ];
            let (code, out, err) = crate::common::run(&args);
            if p == 1000 {
                // 718 m/s between frames: refused before any fit, naming mm.
                assert!(
                    code == 2 && err.contains("give --length-unit mm"),
                    "{header}: {err}"
                );
            } else if mark {
                assert!(
                    code == 2
                        && err.contains(&format!(
                            "at {p}× R, the lengths may be mm read as {read}: give --length-unit mm"
                        )),
                    "{header}: {err}"
                );
            } else {
                let hint = format!(
                    "{p}× too large (mm read as {read}? then μ_k ≈ 0.17): give --length-unit mm"
                );
                assert!(code == 0 && out.contains(&hint), "{header}: {out}");
            }
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// A track in cm under an `x (mm)` header fits μ_k 0.017, ten times too small but
/// above the 0.01 under which no verdict is given: the verdict stands (the regime
/// does not depend on the length unit) and a line says that μ_k is under what the
/// slipperiest solids slide at, naming the mix-up that would make it and the flag.
/// It said "agrees" and nothing else.
#[test]
fn a_mu_under_the_slipperiest_solids_names_the_unit_that_would_make_it() {
    use groovelab::study::video::{self, TrackFormat, Video};
    let dir = scratch_dir("fit_verdicts", "slipperiest");
    let path = dir.join("track.csv");
    let f = path.display().to_string();
    let scene = symmetric(0.0275, 0.049, 0.17, 0.7, 1.0);
    let video = Video {
        mark: false,
        ..Video::default()
    };
    let track = video::track(&scene, &video).unwrap();
    let text = video::write(&track, TrackFormat::CsvComma);
    // The numbers in cm under the header's mm: every length a tenth.
    let tenth = |line: &str| {
        let cells: Vec<String> = line
            .split(',')
            .enumerate()
            .map(|(i, c)| match c.parse::<f64>() {
                Ok(v) if i > 0 => format!("{}", v / 10.0),
                _ => c.to_string(),
            })
            .collect();
        cells.join(",")
    };
    let body: Vec<String> = text.lines().map(tenth).collect();
    assert!(body[0].contains("x (mm)"), "{}", body[0]);
    let args = [
        "fit", "--data", &f, "--radius", "2.75cm", "--width", "4.9cm",
    ];
    for (lines, hint) in [
        (body, true),
        (text.lines().map(str::to_string).collect(), false),
    ] {
        std::fs::write(&path, lines.join("\n") + "\n").unwrap();
        let (code, out, err) = crate::common::run(&args);
        assert_eq!(code, 0, "{err}");
        let head: Vec<&str> = out.lines().take(3).collect();
        assert!(head[1].contains("; agrees ("), "{out}");
        let said = "μ_k under 0.04 is less than the slipperiest solids slide at: if the lengths are 10× too small (cm read as mm? then μ_k ≈ 0.17), give --length-unit cm, or fix the header";
        assert_eq!(out.contains(said), hint, "{out}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// A velocity file whose v_t is signed the other way round (−v_cm while the ball
/// rolls before the impact) is read turned, said by `data` and `fit`, and fits as the
/// file signed as the model signs it; mirrored too (x toward −x) it is both. It gave
/// "μ_k not determined … check --width", and `data` noticed nothing.
#[test]
fn a_v_t_signed_the_other_way_is_read_turned_and_said() {
    let dir = scratch_dir("fit_verdicts", "v_t_turned");
    let path = dir.join("v.csv");
    let f = path.display().to_string();
    for scene in [
        symmetric(0.0275, 0.049, 0.17, 0.7, 1.0),
        symmetric(0.0275, 0.035, 0.2, 0.6, 1.0),
    ] {
        let text = velocity_file(&scene, 1.0);
        let fit = |text: &str| {
            std::fs::write(&path, text).unwrap();
            let out = stdout(&[
                "fit",
                "--data",
                &f,
                "--radius",
                "2.75cm",
                "--width",
                &format!("{}cm", scene.width * 100.0),
            ]);
            let data = stdout(&["data", &f]);
            (out, data)
        };
        let (want, plain) = fit(&text);
        assert!(
            !want.contains("read turned") && !plain.contains("read turned"),
            "{want}"
        );
        // (t, v_cm, v_t) with v_t negated; and with both negated (mirrored too).
        let turned = |both: bool| -> String {
            text.lines()
                .enumerate()
                .map(|(i, l)| {
                    if i == 0 {
                        return format!("{l}\n");
                    }
                    let c: Vec<f64> = l.split(',').map(|c| c.parse().unwrap()).collect();
                    let v_cm = if both { -c[1] } else { c[1] };
                    format!("{},{v_cm},{}\n", c[0], -c[2])
                })
                .collect()
        };
        let (got, data) = fit(&turned(false));
        assert!(
            got.contains("v_t runs opposite to v_cm") && data.contains("read turned, v_t → −v_t"),
            "{got}\n{data}"
        );
        let mu = |out: &str| {
            out.lines()
                .find(|l| l.starts_with("μ_k = "))
                .unwrap()
                .to_string()
        };
        assert_eq!(mu(&got), mu(&want));
        // Mirrored (v_cm < 0) with v_t the model's way round after mirroring: no turn.
        let (got, data) = fit(&turned(true));
        assert!(
            data.contains("read mirrored") && !data.contains("read turned"),
            "{data}"
        );
        assert_eq!(mu(&got), mu(&want));
    }
    let _ = std::fs::remove_dir_all(&dir);
}
