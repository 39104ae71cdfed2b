//! The data path keeps its own rules (issue 35): odd but well-formed tables give a
//! clear answer, never a panic, and no number that the table cannot support.

use crate::common::{run_in_process, scratch_dir};

/// A Tracker multi-track export of two balls meeting (no rim marks): ball A at
/// 0.5 m/s, slowed to 0.1 m/s by the impact at t = 0.05 s, ball B the mirror image
/// from 20 cm away; `cells` writes one row from (t, x_A, x_B).
fn two_balls(rows: usize, cells: impl Fn(f64, f64, f64) -> String) -> String {
    let xa = |t: f64| {
        if t < 0.05 {
            0.5 * t
        } else {
            0.025 + 0.1 * (t - 0.05)
        }
    };
    let mut text = String::from("#multi:\n\tball A\t\tball B\t\nt\tx\ty\tx\ty\n");
    for k in 0..rows {
        let t = k as f64 * 0.01;
        text += &cells(t, xa(t), 0.2 - xa(t));
        text.push('\n');
    }
    text
}

/// `data` and `fit` on `text`, in this process: each answers (a report or one
/// `error:` line); a panic fails the test.
fn data_and_fit(name: &str, text: &str) -> [Result<String, String>; 2] {
    let dir = scratch_dir("data-rules", name);
    let file = dir.join("tracks.txt");
    std::fs::write(&file, text).unwrap();
    let f = file.to_str().unwrap();
    [
        run_in_process(&["data", f]),
        run_in_process(&["fit", "--preset", "paper-b4.9", "--data", f]),
    ]
}

#[test]
fn two_balls_without_marks_whose_second_has_no_frame_with_the_first_do_not_panic() {
    // The second ball's cells empty, or the first ball's y empty: the "mark" (ball B)
    // has no frame with a centre, which once sliced an empty range
    // (study/measured/track/derivative.rs).
    for (name, cells) in [
        ("b-empty", "{t}\t{a}\t0\t\t"),
        ("no-y", "{t}\t{a}\t\t{b}\t"),
    ] {
        for rows in [10, 12, 20] {
            let text = two_balls(rows, |t, a, b| {
                cells
                    .replace("{t}", &format!("{t:.2}"))
                    .replace("{a}", &format!("{a:.5}"))
                    .replace("{b}", &format!("{b:.5}"))
            });
            let [data, fit] = data_and_fit(&format!("{name}-{rows}"), &text);
            let report = data.unwrap_or_else(|e| panic!("{name} {rows}: data refused: {e}"));
            assert!(report.contains("Tracker multi-track"), "{report}");
            // Ball A alone is a centre with an impact: fit answers with a fit or says why.
            match fit {
                Ok(out) => assert!(out.contains("μ_k"), "{name} {rows}: {out}"),
                Err(e) => assert!(!e.is_empty() && !e.contains("panicked"), "{e}"),
            }
        }
    }
}

#[test]
fn a_second_ball_read_as_the_rim_mark_is_said_to_be_none() {
    // Both balls complete: ball B is taken for the mark, but it lies ~15 cm from A's
    // centre, far beyond twice the preset's R = 2.75 cm.
    let text = two_balls(20, |t, a, b| format!("{t:.2}\t{a:.5}\t0\t{b:.5}\t0"));
    let [data, _] = data_and_fit("second-ball", &text);
    let report = data.unwrap();
    let line = report
        .lines()
        .find(|l| l.contains("is no rim mark"))
        .unwrap_or_else(|| panic!("no doubt said: {report}"));
    assert!(
        line.contains("'ball B'") && line.contains("2.75 cm"),
        "{line}"
    );
}

#[test]
fn a_single_ball_mark_within_its_radius_raises_no_doubt() {
    // The same file with B a real rim mark, 2 cm above A's centre.
    let text = two_balls(20, |t, a, _| format!("{t:.2}\t{a:.5}\t0\t{a:.5}\t0.02"));
    let [data, _] = data_and_fit("real-mark", &text);
    let report = data.unwrap();
    assert!(!report.contains("is no rim mark"), "{report}");
}

#[test]
fn a_row_cut_short_at_the_end_of_the_file_is_dropped_and_said() {
    // A single-track export stopped mid-row: "0.20\t0" of "0.20\t0.0712\t0.1".
    let mut text = String::from("mass_A\nt\tx\ty\n");
    for k in 0..20 {
        let t = f64::from(k) * 0.01;
        text += &format!("{t:.2}\t{:.5}\t0.1\n", 0.3 + 0.5 * t);
    }
    text += "0.20\t0";
    let [data, _] = data_and_fit("cut-short", &text);
    let report = data.unwrap();
    assert!(
        report.contains("20 frames"),
        "the cut row is not a frame: {report}"
    );
    assert!(
        report.contains("line 23, the last, is cut short") && report.contains("dropped"),
        "{report}"
    );
    // A complete last row without a line end is a row like any other.
    let whole = text.replace("0.20\t0", "0.20\t0.40000\t0.1");
    let report = data_and_fit("whole-last", &whole)[0].clone().unwrap();
    assert!(
        report.contains("21 frames") && !report.contains("cut short"),
        "{report}"
    );
}

#[test]
fn positions_no_experiment_has_are_refused_in_one_line() {
    for huge in ["1e308", "-1.7e308", "2e12"] {
        let mut text = String::from("t,x,y\n");
        for k in 0..30 {
            let x = if k % 2 == 0 {
                huge.to_string()
            } else {
                format!("-{huge}").replace("--", "")
            };
            text += &format!("{},{x},0\n", f64::from(k) * 0.01);
        }
        for result in data_and_fit("huge", &text) {
            let e = result.unwrap_err();
            assert!(
                e.contains("line 2: x = ")
                    && e.contains("beyond any measurement")
                    && !e.contains('\n'),
                "{huge}: {e}"
            );
        }
    }
}

#[test]
fn an_exact_track_is_a_perfect_fit_never_a_poor_one() {
    use groovelab::study::fit::{Agreement, Free, position_fit};
    use groovelab::study::measured::{self, Derive, RawSeries};
    use groovelab::study::video::{self, Video};
    // Noise-free positions of the paper's ball at μ_k = 0.18: the scatter is about
    // zero, so "ten times the scatter" is no yardstick; the absolute floor decides.
    let scene = groovelab::physics::scene::Scene {
        mu: 0.18,
        ..crate::common::paper_scene()
    };
    let track = video::track(
        &scene,
        &Video {
            noise: 0.0,
            fps: 100.0,
            ..Video::default()
        },
    );
    let series =
        measured::prepare(RawSeries::Positions(track.unwrap()), &Derive::default()).unwrap();
    let m = measured::for_scene(&series, &scene).measured;
    let f = position_fit(&scene, &m, &[Free::Mu], &groovelab::study::Quiet).unwrap();
    assert!((f.mu - 0.18).abs() < 1e-3, "μ_k = {}", f.mu);
    assert!(f.rms < f.perfect_rms(), "rms {} m", f.rms);
    assert_ne!(f.agreement(), Agreement::PoorFit, "{f:?}");
    // The floor is a floor, not a blindfold: 1 mm off with the same tiny scatter is poor.
    let off = groovelab::study::fit::ModelFit {
        rms: 1e-3,
        scatter: Some(1e-9),
        ..f
    };
    assert_eq!(off.agreement(), Agreement::PoorFit);
}

#[test]
fn a_value_the_file_leaves_out_is_never_said_to_be_measured() {
    // The file states R only: its b is not known, so a model at another b is no
    // "data measured at b = 4.9 cm" (the preset's b, which it once said).
    let data = std::fs::read_to_string(
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("data/gs-b4.9cm.csv"),
    )
    .unwrap();
    let dir = scratch_dir("data-rules", "stated-groove");
    let only_r = dir.join("only-r.csv");
    std::fs::write(&only_r, format!("# scene radius = 2.75 cm\n{data}")).unwrap();
    let both = dir.join("both.csv");
    std::fs::write(
        &both,
        format!("# scene radius = 2.75 cm\n# scene width = 4.9 cm\n{data}"),
    )
    .unwrap();
    let fit = |f: &std::path::Path| {
        run_in_process(&["fit", "--data", f.to_str().unwrap(), "--width", "3.5cm"]).unwrap()
    };
    let out = fit(&only_r);
    assert!(!out.contains("measured at"), "{out}");
    // Where the file states b, the other groove is said.
    let out = fit(&both);
    assert!(out.contains("measured at b = 4.9 cm"), "{out}");
}

/// `groovelab track`'s tracks of both balls meeting at t = 0.15 s (40 frames at 100
/// frames/s, no marks): the left ball at 0.5 m/s, slowed to 0.1 m/s, found only from
/// t = 0.2 s; the right ball its mirror image, found in the frames `right_seen` keeps.
fn left_found_after_the_impact(right_seen: impl Fn(u32) -> bool) -> String {
    let x = |t: f64| {
        if t < 0.15 {
            0.5 * t
        } else {
            0.075 + 0.1 * (t - 0.15)
        }
    };
    let mut text = String::from(
        "\tleft ball\t\tleft mark\t\tright ball\t\tright mark\t\nt\tx\ty\tx\ty\tx\ty\tx\ty\n",
    );
    for k in 0..40 {
        let t = f64::from(k) * 0.01;
        let cell = |seen: bool, x: f64| {
            if seen {
                format!("{x:.6}\t0")
            } else {
                "\t".into()
            }
        };
        let (left, right) = (cell(t >= 0.2, x(t) - 0.2), cell(right_seen(k), 0.2 - x(t)));
        text += &format!("{t:.2}\t{left}\t\t\t{right}\t\t\n");
    }
    text
}

#[test]
fn a_left_ball_found_only_after_the_impact_gives_way_to_the_right_one() {
    // Small look 47: the left ball's own frames few and after the impact. Its
    // motion shows no impact, the right ball's does, and its series is the one
    // derived, mirrored.
    let text = left_found_after_the_impact(|_| true);
    let load = |text: &str, reading: &groovelab::input::data::Reading| {
        groovelab::input::data::load(text, "tracks.txt", reading, &Default::default())
    };
    let series = load(&text, &Default::default()).unwrap_or_else(|e| panic!("{e}"));
    let found = series.found().expect("a track");
    assert_eq!(found.centre, "right ball");
    // 0.5 m/s before the impact at 0.15 s, 0.1 m/s after, away from the left ball.
    let m = series.measured();
    let v_before: Vec<f64> = m
        .t()
        .iter()
        .zip(m.v_cm())
        .filter(|(t, _)| **t < -0.03)
        .map(|(_, v)| *v)
        .collect();
    assert!(
        !v_before.is_empty() && v_before.iter().all(|v| (v.abs() - 0.5).abs() < 0.01),
        "{v_before:?}"
    );
    // `data` names the ball `fit` fits.
    let [data, fit] = data_and_fit("right-ball", &text);
    for out in [data.unwrap(), fit.unwrap()] {
        assert!(out.contains("centre 'right ball'"), "{out}");
    }
    // The left ball named, its refusal stands.
    let left = groovelab::input::data::Reading {
        centre: Some("left ball".into()),
        mark: Some("left mark".into()),
        ..Default::default()
    };
    assert!(load(&text, &left).is_err());
    // A right ball found in under half the frames (small look 49: both balls in a
    // third, the right ball's μ_k 0.28 for 0.17) is no better: the refusal stands.
    let sparse = left_found_after_the_impact(|k| k % 3 == 0);
    let refused = load(&sparse, &Default::default());
    assert!(
        refused.is_err(),
        "{:?}",
        refused.map(|s| s.found().map(|f| f.centre.clone()))
    );
}
