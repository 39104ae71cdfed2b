//! Spreadsheets with tracks side by side, each with its own time column (a Tracker
//! data tool or a spreadsheet holding `mass_A;;;mass_B;;;mass_C;;` above
//! `t;x;y;t;x;y;t;x;y`, as in a student's Excel file: semicolons, decimal commas,
//! scientific numbers, ragged lengths padded with empty cells, CRLF), and a velocity
//! file with no impact in it. Made here by generators from the exact solution.

use std::path::PathBuf;

use groovelab::study::measured::Track;
use groovelab::study::video::{self, Video};

use crate::common::{groovelab, json};

const MU: f64 = 0.17;

fn scratch(test: &str) -> PathBuf {
    crate::common::scratch_dir("side", test)
}

/// One number as a Norwegian-locale spreadsheet writes it: `3,612345E-03`.
fn comma(v: f64) -> String {
    if v.is_nan() {
        String::new()
    } else {
        format!("{v:.6E}")
            .replace('.', ",")
            .replace("E-", "E-0")
            .replace("E-00", "E-0")
    }
}

/// The three tracks side by side, each with its own t column: the centre from frame
/// 0, the rim mark from frame 2 (its rows shifted up: matched by time, not by row),
/// the other ball from frame 0 with a frame skipped; rows padded with empty cells.
fn spreadsheet(track: &Track) -> String {
    let (mx, my) = track.mark().unwrap();
    let n = track.t().len();
    let centre: Vec<usize> = (0..n).collect();
    let mark: Vec<usize> = (2..n).collect();
    let other: Vec<usize> = (0..n).filter(|&i| i != 30).collect();
    let mut out = String::from("mass_A;;;mass_B;;;mass_C;;\r\nt;x;y;t;x;y;t;x;y\r\n");
    for row in 0..n {
        let cell = |rows: &[usize], x: &[f64], y: &[f64], sign: f64| match rows.get(row) {
            Some(&i) => format!(
                "{};{};{}",
                comma(track.t()[i]),
                comma(sign * x[i]),
                comma(y[i])
            ),
            None => ";;".into(),
        };
        out += &format!(
            "{};{};{}\r\n",
            cell(&centre, track.x(), track.y(), 1.0),
            cell(&mark, mx, my, 1.0),
            cell(&other, track.x(), track.y(), -1.0),
        );
    }
    out
}

#[test]
fn tracks_side_by_side_are_read_each_with_its_own_time() {
    let scene = crate::common::paper_scene();
    let track = video::track(
        &scene,
        &Video {
            seed: 5,
            noise: 2e-4,
            ..Video::default()
        },
    )
    .unwrap();
    let dir = scratch("three");
    let file = dir.join("input.csv");
    std::fs::write(&file, spreadsheet(&track)).unwrap();
    let f = file.to_str().unwrap();
    let out = groovelab(&["data", f]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(
        text.contains(": tracks side by side, position track"),
        "{text}"
    );
    assert!(
        text.contains("tracks: centre 'mass_A', rim mark 'mass_B'; not used: 'mass_C'"),
        "{text}"
    );
    assert!(
        text.contains(&format!("{} frames", track.t().len())),
        "{text}"
    );
    let j = json(&[
        "fit",
        "--preset",
        "paper-b4.9",
        "--data",
        f,
        "--format",
        "json",
    ]);
    assert_eq!(j["track"]["format"], "tracks side by side");
    // The mark's own times matched to the centre's: it lies on the rim, and v_t is
    // measured.
    let r = j["track"]["mark_radius"].as_f64().unwrap();
    assert!((r - scene.radius).abs() < 1e-3, "mark radius {r}");
    assert!(
        j["line_fit"]["mu_t"].as_f64().is_some(),
        "{}",
        j["line_fit"]
    );
    let (mu, se) = (
        j["model_fit"]["mu"].as_f64().unwrap(),
        j["model_fit"]["mu_se"].as_f64().unwrap(),
    );
    // Within 3σ of the truth, and the ± no wider than a student's precision.
    assert!(
        (mu - MU).abs() < 3.0 * se && se < 0.003,
        "μ_k = {mu} ± {se}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_velocity_file_without_an_impact_is_described_and_not_fitted() {
    // A single ball rolling in and slowing, as a velocity export writes it.
    let mut text = String::from("t (s),v_cm (m/s),v_t (m/s)\n");
    for i in 0..60 {
        let t = f64::from(i) * 0.01;
        let v = 0.5 - 0.3 * t;
        text += &format!("{t:.2},{v:.4},{v:.4}\n");
    }
    let dir = scratch("single");
    let file = dir.join("ball.csv");
    std::fs::write(&file, text).unwrap();
    let f = file.to_str().unwrap();
    let out = groovelab(&["data", f]);
    let said = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(
        said.contains("a single ball's velocities, no impact found"),
        "{said}"
    );
    assert!(said.contains("60 frames at 100 frames/s"), "{said}");
    assert!(said.contains("|v_cm| up to 0.5 m/s"), "{said}");
    let out = groovelab(&["fit", "--data", f, "--radius", "2cm", "--width", "3.5cm"]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(
        err.starts_with("error: ")
            && err.contains("no impact found")
            && err.contains("--impact-at"),
        "{err}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}
