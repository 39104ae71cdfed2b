//! A scene option that does not fit the data (a wrong `--width`) must not be reported
//! as agreeing: the two line fits' μ_k (from v_cm and from v_t) then disagree beyond
//! their ±, which the verdict says.

use groovelab::physics::engine;
use groovelab::physics::scene::Span;
use groovelab::study::video::Noise;

fn groovelab(args: &[&str]) -> (Option<i32>, String, String) {
    let out = crate::common::groovelab(args);
    (
        out.status.code(),
        String::from_utf8(out.stdout).unwrap(),
        String::from_utf8(out.stderr).unwrap(),
    )
}

/// The paper's scene (b = 4.9 cm) at 120 frames/s with 0.01 m/s of noise, in m/s.
fn velocity_file() -> String {
    let sol = engine::solve(
        &crate::common::paper_scene(),
        &Span {
            t_start: -0.3,
            t_end: Some(0.8),
        },
    );
    let mut noise = Noise::new(5);
    let mut text = String::from("t (s),v_cm (m/s),v_t (m/s)\n");
    for k in -24..=84 {
        let t = (f64::from(k) + 0.3) / 120.0;
        let st = sol.at(t);
        text += &format!(
            "{t:.5},{:.4},{:.4}\n",
            st.left.v + 0.01 * noise.gauss(),
            st.left.u + 0.01 * noise.gauss()
        );
    }
    text
}

#[test]
fn a_wrong_width_is_not_reported_as_agreeing() {
    let dir = crate::common::scratch_dir("wrong_scene", "width");
    let file = dir.join("v.csv");
    std::fs::write(&file, velocity_file()).unwrap();
    let f = file.to_str().unwrap();
    let fit = |width: &str| {
        let (code, out, err) = groovelab(&[
            "fit",
            "--preset",
            "paper-b4.9",
            "--data",
            f,
            "--width",
            width,
        ]);
        assert_eq!(code, Some(0), "{err}");
        out
    };
    // The true width: both line fits give μ_k = 0.17, and the fit agrees.
    let out = fit("4.9cm");
    assert!(
        out.contains("the model predicts what was observed"),
        "{out}"
    );
    // Widths within 10× the RMS of the data's scatter (once "agrees"): k enters
    // μ_k,cm as k and μ_k,t as 1/k, so they split (0.26 and 0.11 at 4 cm; 0.12 and
    // 0.24 at 5.2 cm) and there is no verdict.
    for width in ["4cm", "4.5cm", "5.2cm"] {
        let out = fit(width);
        let headline = out.lines().nth(1).unwrap();
        assert!(
            headline.contains("μ_k,cm ≠ μ_k,t") && !headline.contains("agrees"),
            "{width}: {headline}"
        );
        assert!(
            out.contains("μ_k,cm and μ_k,t of the line fits disagree")
                && out.contains("check --width and --radius")
                && !out.contains("the model predicts what was observed"),
            "{width}: {out}"
        );
    }
    let (_, out, _) = groovelab(&[
        "fit",
        "--preset",
        "paper-b4.9",
        "--data",
        f,
        "--width",
        "4cm",
        "--format",
        "json",
    ]);
    let j: serde_json::Value = serde_json::from_str(&out).unwrap();
    let pair = &j["model_fit"]["lines_disagree"];
    let (cm, t) = (pair[0].as_f64().unwrap(), pair[1].as_f64().unwrap());
    assert!(cm > 2.0 * t, "{cm} {t}");
    let _ = std::fs::remove_dir_all(&dir);
}
