//! Files that `data` reads but no fit can use (issue 35, "open what can be read"): a
//! track with no impact in it, and one whose length unit nobody states and whose
//! numbers are not metres. `data` shows them (the second in the file's own unit, with
//! the doubt and the fix), the app and `render` open on them instead of refusing:
//! their rows in the table, the centre's v_cm in the file's own time on the chart, and
//! the Fit view saying why there is no fit.

use crate::common::{run, scratch_dir};

/// A Tracker single-track export of one ball and no impact: released at `v0` m/s
/// along +x and speeding up at `a` m/s² (a slope), at 100 frames/s for 0.6 s,
/// lengths in `unit` per metre (100: cm) with no unit in the header.
fn pushed_ball(v0: f64, a: f64, unit: f64) -> String {
    let mut text = String::from("mass_A\nt\tx\ty\n");
    for k in 0..60 {
        let t = f64::from(k) * 0.01;
        let x = (0.05 + v0 * t + 0.5 * a * t * t) * unit;
        text += &format!("{t:.2}\t{x:.9E}\t{:.9E}\n", 0.02 * unit);
    }
    text
}

fn written(test: &str, text: &str) -> String {
    let dir = scratch_dir("data-unfit", test);
    let file = dir.join("track.txt");
    std::fs::write(&file, text).unwrap();
    file.to_str().unwrap().to_string()
}

/// The first number after `label` in `text`.
fn number_after(text: &str, label: &str) -> f64 {
    let rest = &text[text
        .find(label)
        .unwrap_or_else(|| panic!("{label}: {text}"))
        + label.len()..];
    let n: String = rest
        .trim_start()
        .chars()
        .take_while(|c| c.is_ascii_digit() || matches!(c, '.' | '-' | '+' | 'e' | 'E'))
        .collect();
    n.parse()
        .unwrap_or_else(|_| panic!("no number after {label}: {rest}"))
}

#[test]
fn a_track_with_no_impact_opens_with_its_rows_and_says_why_there_is_no_fit() {
    for (v0, a) in [(0.4, 1.5), (0.25, 3.0)] {
        let f = written(&format!("no-impact-{v0}"), &pushed_ball(v0, a, 1.0));
        // `fit` still refuses: it needs an impact.
        let (code, _, err) = run(&["fit", "--preset", "paper-b4.9", "--data", &f]);
        assert_eq!(code, 2, "{err}");
        assert!(err.contains("no impact found"), "{err}");
        // The app's screen opens on it.
        let (code, screen, err) = run(&["render", "--data", &f, "--size", "100x30"]);
        assert_eq!(code, 0, "{err}");
        assert!(
            screen.contains("track.txt: no fit (f says why; d shows its rows)"),
            "{screen}"
        );
        // Its v_cm on the chart, said to be in the file's time; not the preset's data.
        assert!(screen.contains("v_cm, file's t"), "{screen}");
        assert!(!screen.contains("measured v_t"), "{screen}");
        // The file measures no value the scene takes: v0 is the preset's (it was
        // tagged 'd', the data's, from the preset's own series) and the masses are
        // assumed, as with any data of the user's.
        let row = |name: &str| {
            screen
                .lines()
                .find(|l| l.contains(name))
                .unwrap_or_else(|| panic!("{name}: {screen}"))
                .to_string()
        };
        assert!(row("v0 (both)").contains(" m/s p"), "{}", row("v0 (both)"));
        assert!(row("m left").contains(" g a"), "{}", row("m left"));
        // The Fit view says why, and what to give.
        let (code, fit, _) = run(&["render", "--data", &f, "--size", "100x30", "--keys", "f"]);
        assert_eq!(code, 0);
        assert!(fit.contains("no fit of"), "{fit}");
        assert!(fit.contains("no impact found"), "{fit}");
        let (_, applied, _) = run(&["render", "--data", &f, "--size", "100x30", "--keys", "f a"]);
        assert!(applied.contains("no fit to apply"), "{applied}");
        // The table: the file's own time, x from its first frame, v_cm = v0 + a t.
        let (code, table, _) = run(&["render", "--data", &f, "--size", "100x40", "--keys", "d"]);
        assert_eq!(code, 0);
        assert!(table.contains("Data, no fit"), "{table}");
        let rows: Vec<[f64; 4]> = table
            .lines()
            .filter_map(|l| {
                let cells: Vec<f64> = l
                    .split('│')
                    .nth(2)?
                    .split_whitespace()
                    .map(|c| c.parse().ok())
                    .collect::<Option<Vec<f64>>>()?;
                <[f64; 4]>::try_from(cells).ok()
            })
            .collect();
        assert!(rows.len() >= 10, "{table}");
        for [t, x_cm, v, sigma] in rows {
            // A local quadratic fit is exact on a parabola: to the table's 4 decimals.
            assert!((v - (v0 + a * t)).abs() <= 1.5e-4, "t = {t}: v_cm {v}");
            let x = v0 * t + 0.5 * a * t * t;
            assert!((x_cm - 100.0 * x).abs() <= 1.5e-4, "t = {t}: x {x_cm} cm");
            assert!(sigma >= 0.0);
        }
    }
}

#[test]
fn lengths_in_no_stated_unit_are_shown_in_the_files_own_unit_with_the_fix() {
    // cm written with no unit: as metres the ball would move at 40–200 m/s.
    for (v0, a) in [(0.4, 1.5), (2.0, 0.5)] {
        let f = written(&format!("own-unit-{v0}"), &pushed_ball(v0, a, 100.0));
        let (code, out, err) = run(&["data", &f]);
        assert_eq!(code, 0, "{err}");
        assert!(out.contains("length in the file's own unit"), "{out}");
        assert!(out.contains("give --length-unit "), "{out}");
        // Speeds in the file's unit per second: 100 × the true m/s. "Up to about" is
        // the 90th percentile of the speeds between frames: between the speeds at
        // 80 % and at the end of the 0.59 s run (v0 + a t).
        let fastest = number_after(&out, "speed between frames up to about");
        let (lo, hi) = (100.0 * (v0 + a * 0.8 * 0.59), 100.0 * (v0 + a * 0.59));
        assert!(
            lo <= fastest && fastest <= hi,
            "{fastest} units/s, not in {lo} … {hi}: {out}"
        );
        assert!(out.contains("units/s"), "{out}");
        // No speed of the file's own is called m/s (the doubt's "as m … m/s" is).
        assert!(
            out.lines()
                .filter(|l| l.contains("speed between") || l.contains("no impact found"))
                .all(|l| !l.contains("m/s")),
            "{out}"
        );
        let json: serde_json::Value =
            serde_json::from_str(&run(&["data", "--format", "json", &f]).1).unwrap();
        assert!(
            json[0]["length_unit_doubt"]
                .as_str()
                .unwrap()
                .contains("--length-unit ")
        );
        assert!(
            json[0]["scene_values"].as_object().unwrap().is_empty(),
            "{json}"
        );
        // With the unit given, it is read as such and no doubt is said.
        let (code, out, _) = run(&["data", "--length-unit", "cm", &f]);
        assert_eq!(code, 0);
        assert!(!out.contains("own unit"), "{out}");
        // The app opens on it, draws nothing of it and says why in the Fit view.
        let (code, screen, err) = run(&["render", "--data", &f, "--size", "100x30"]);
        assert_eq!(code, 0, "{err}");
        assert!(
            screen.contains("track.txt: no fit (f says why)"),
            "{screen}"
        );
        assert!(!screen.contains("v_cm, file's t"), "{screen}");
    }
}

#[test]
fn a_stated_unit_that_cannot_be_right_is_still_refused() {
    // The header says metres; the numbers move at 40 m/s: an error, not a doubt.
    let text = pushed_ball(0.4, 1.5, 100.0).replace("t\tx\ty", "t (s)\tx (m)\ty (m)");
    let f = written("stated-unit", &text);
    let (code, out, err) = run(&["data", &f]);
    assert_eq!(code, 2, "{out}");
    assert!(
        err.starts_with("error: ") && err.trim_end().lines().count() == 1,
        "{err}"
    );
}

/// A track in the file's own unit (cm written with no unit) that speeds up, not an
/// impact: the hint writes its speeds to four digits of that unit ("from 318 to 396
/// units/s"), not a lab's three decimals of m/s ("318.000 to 396.000").
#[test]
fn a_hint_in_the_files_own_unit_writes_its_speeds_as_numbers_of_it() {
    let mut text = String::from("t\tx\ty\n");
    for k in 0..60 {
        let t = f64::from(k) * 0.01 + 0.005;
        let x = if t < 0.3 {
            3.18 * t
        } else {
            0.954 + 3.96 * (t - 0.3)
        };
        text += &format!("{t:.3}\t{:.6}\t2.0\n", 100.0 * x);
    }
    let f = written("own-unit-hint", &text);
    let (code, out, err) = run(&["data", &f]);
    assert_eq!(code, 0, "{err}");
    let hint = out
        .lines()
        .find(|l| l.contains("speeds the ball up from"))
        .unwrap_or_else(|| panic!("{out}"));
    let after = hint.split("speeds the ball up from ").nth(1).unwrap();
    let words: Vec<&str> = after.split(' ').collect();
    let (from, to) = (words[0], words[2]);
    assert!(words[1] == "to" && words[3] == "units/s", "{hint}");
    for (shown, near) in [(from, 318.0), (to, 396.0)] {
        let v: f64 = shown.parse().unwrap_or_else(|_| panic!("{hint}"));
        // A line's slope over frames straddling the change: within 10 % of the speed.
        assert!((v - near).abs() < 0.1 * near, "{hint}");
        assert!(!shown.contains('.') || shown.len() <= 5, "{hint}");
    }
}
