//! A value's source named truly (issue 35): the groove the data were "measured at"
//! is only what their file states (JSON `data_groove`: null for the rest), and a
//! second track never seen in a frame with the centre is not called a rim mark.

use crate::common::{run_in_process, scratch_dir};

/// The paper's b = 4.9 cm series with `header` before it, written as `name`.
fn paper_series_with(dir: &std::path::Path, name: &str, header: &str) -> String {
    let data = std::fs::read_to_string(
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("data/gs-b4.9cm.csv"),
    )
    .unwrap();
    let path = dir.join(name);
    std::fs::write(&path, format!("{header}{data}")).unwrap();
    path.display().to_string()
}

/// A file stating R only, fitted in a groove of another R: `data_groove` holds the
/// file's R and a null b (the preset's b is no measurement of the data's); stating
/// both gives both.
#[test]
fn data_groove_holds_only_what_the_file_states() {
    let dir = scratch_dir("data-sources", "groove");
    let only_r = paper_series_with(&dir, "only-r.csv", "# scene radius = 2.75 cm\n");
    let both = paper_series_with(
        &dir,
        "both.csv",
        "# scene radius = 2.75 cm\n# scene width = 4.9 cm\n",
    );
    let groove = |file: &str| {
        let out = run_in_process(&[
            "fit", "--data", file, "--radius", "3cm", "--width", "4.9cm", "--format", "json",
        ])
        .unwrap();
        let j: serde_json::Value = serde_json::from_str(&out).unwrap();
        j["data_groove"].clone()
    };
    let g = groove(&only_r);
    assert!(
        (g["radius"].as_f64().unwrap() - 0.0275).abs() < 1e-12,
        "{g}"
    );
    assert!(g["width"].is_null(), "{g}");
    let g = groove(&both);
    assert!(
        (g["radius"].as_f64().unwrap() - 0.0275).abs() < 1e-12,
        "{g}"
    );
    assert!((g["width"].as_f64().unwrap() - 0.049).abs() < 1e-12, "{g}");
}

/// A Tracker multi-track export whose second track has positions only in frames
/// where the first has none: nothing shows it is a mark (no distance from the centre,
/// no spin), so `data` calls it a second track and says why, never "rim mark".
#[test]
fn a_track_never_beside_the_centre_is_not_called_a_rim_mark() {
    let dir = scratch_dir("data-sources", "apart");
    let mut text = String::from("#multi:\n\tball A\t\tball B\t\nt\tx\ty\tx\ty\n");
    for i in 0..40 {
        let t = f64::from(i) / 50.0;
        let x = -0.1 + 0.4 * t;
        // Ball A in the even frames, "ball B" in the odd ones, 1 cm above.
        if i % 2 == 0 {
            text += &format!("{t:.3}\t{x:.5}\t0.00000\t\t\n");
        } else {
            text += &format!("{t:.3}\t\t\t{x:.5}\t0.01000\n");
        }
    }
    let path = dir.join("apart.txt");
    std::fs::write(&path, text).unwrap();
    let out = match run_in_process(&["data", path.to_str().unwrap()]) {
        Ok(out) => out,
        // Refusing the file is an answer too, but then in one line naming why.
        Err(e) => {
            assert!(!e.contains('\n') && !e.contains("rim mark 'ball B'"), "{e}");
            return;
        }
    };
    assert!(!out.contains("rim mark 'ball B'"), "{out}");
    if out.contains("'ball B'") {
        assert!(
            out.contains("track 'ball B' is not known to be a rim mark"),
            "{out}"
        );
    }
}
