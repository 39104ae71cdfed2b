//! What `data` and the readers say when a file is not what they expect (issue 27): a
//! track with no impact says what its sharpest change was; swapped centre and mark
//! tracks are noticed; small messages say what happened.

fn groovelab(args: &[&str]) -> (Option<i32>, String, String) {
    let out = crate::common::groovelab(args);
    (
        out.status.code(),
        String::from_utf8(out.stdout).unwrap(),
        String::from_utf8(out.stderr).unwrap(),
    )
}

/// A plain CSV track (`t,x,y` in s and m) at 100 frames/s of a ball moving at `v1`
/// for 0.3 s, then at `v2` for 0.3 s (the change at t = 0.3 s, between frames).
fn two_speeds(v1: f64, v2: f64) -> String {
    let mut text = String::from("t (s),x (m),y (m)\n");
    for k in 0..60 {
        let t = f64::from(k) * 0.01 + 0.005;
        let x = if t < 0.3 {
            v1 * t
        } else {
            0.3 * v1 + v2 * (t - 0.3)
        };
        text += &format!("{t:.3},{x:.6},0.1\n");
    }
    text
}

#[test]
fn a_track_without_an_impact_says_what_its_sharpest_change_did() {
    let dir = crate::common::scratch_dir("data_hints", "no-impact");
    let file = dir.join("track.csv");
    let f = file.to_str().unwrap();
    // A push from 0.1 to 0.6 m/s was quoted as if an impact had been seen there.
    // (The speed after is a line's over frames that straddle the change.)
    let cases = [
        (0.1, 0.6, "speeds the ball up from 0.100 to 0.5"),
        (-0.6, -0.9, "speeds the ball up from -0.600 to -0.8"),
        (0.6, 0.5, "slows the ball by only 1"),
    ];
    for (v1, v2, want) in cases {
        std::fs::write(&file, two_speeds(v1, v2)).unwrap();
        let (code, out, err) = groovelab(&["data", f]);
        assert_eq!(code, Some(0), "{err}");
        assert!(
            out.contains(
                "no impact found: the sharpest change of the centre's velocity, at t = 0."
            ) && out.contains(want)
                && out.contains("an impact would slow it by at least a third"),
            "{v1} → {v2}: {out}"
        );
        // fit refuses it with the same words, in one line.
        let (code, _, err) = groovelab(&["fit", "--preset", "paper-b4.9", "--data", f]);
        assert_eq!(code, Some(2));
        assert!(err.contains(want) && err.lines().count() == 1, "{err}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}
