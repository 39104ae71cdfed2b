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
        // Moving toward −x: speeds, not signed velocities (it said "from -0.600").
        (-0.6, -0.9, "speeds the ball up from 0.600 to 0.8"),
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

/// A filmed track of the paper's scene (centre and rim mark, 0.2 mm scatter) as CSV
/// `t,x,y,x_mark,y_mark`, the two points' columns swapped when `swap`.
fn filmed_csv(swap: bool, fps: f64, from: f64, to: f64) -> String {
    use groovelab::study::video::{self, Video};
    let track = video::track(
        &crate::common::paper_scene(),
        &Video {
            seed: 3,
            noise: 2e-4,
            fps,
            from,
            to,
            ..Video::default()
        },
    )
    .unwrap();
    let (mx, my) = track.mark().expect("a mark");
    let mut s = String::from("t,x,y,x_mark,y_mark\n");
    for i in 0..track.t().len() {
        let (c, m) = ((track.x()[i], track.y()[i]), (mx[i], my[i]));
        let (a, b) = if swap { (m, c) } else { (c, m) };
        s += &format!(
            "{:.5},{:.6},{:.6},{:.6},{:.6}\n",
            track.t()[i],
            a.0,
            a.1,
            b.0,
            b.1
        );
    }
    s
}

#[test]
fn swapped_centre_and_mark_are_noticed_and_the_right_order_is_not() {
    let dir = crate::common::scratch_dir("data_hints", "swapped");
    let file = dir.join("track.csv");
    let f = file.to_str().unwrap();
    // The mark strays ~17 mm from a straight line, the centre by its scatter.
    for (fps, from, to) in [(120.0, -0.2, 0.8), (240.0, -0.1, 0.3), (60.0, -0.3, 1.0)] {
        std::fs::write(&file, filmed_csv(false, fps, from, to)).unwrap();
        let (code, _, err) = groovelab(&["data", f]);
        assert_eq!(code, Some(0), "{fps}: {err}");
        std::fs::write(&file, filmed_csv(true, fps, from, to)).unwrap();
        for args in [
            vec!["data", f],
            vec!["fit", "--preset", "paper-b4.9", "--data", f],
        ] {
            let (code, _, err) = groovelab(&args);
            assert_eq!(code, Some(2), "{fps}");
            assert!(
                err.contains("the track taken for the ball's centre strays")
                    && err.contains("the two look swapped")
                    && err.contains("swap the columns")
                    && err.lines().count() == 1,
                "{fps}: {err}"
            );
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn small_messages_say_what_happened() {
    let dir = crate::common::scratch_dir("data_hints", "small");
    // One frame left out (a jump in time): "1 frame missing", not "1 frames".
    let file = dir.join("gap.csv");
    let text: String = filmed_csv(false, 120.0, -0.2, 0.8)
        .lines()
        .enumerate()
        .filter(|&(i, _)| i != 60)
        .map(|(_, l)| format!("{l}\n"))
        .collect();
    std::fs::write(&file, text).unwrap();
    let f = file.to_str().unwrap();
    let (code, out, err) = groovelab(&["data", f]);
    assert_eq!(code, Some(0), "{err}");
    assert!(out.contains("  1 frame missing: 1 at t = "), "{out}");
    let (code, out, err) = groovelab(&["fit", "--preset", "paper-b4.9", "--data", f]);
    assert_eq!(code, Some(0), "{err}");
    assert!(out.contains("1 frame missing from the file"), "{out}");
    // One row without a position is one time: "1 at t = 0.3000 s", not a range from
    // it to itself ("0.3000 … 0.3000 s"); a single run left over is "1 more run".
    let file = dir.join("holes.csv");
    let text: String = filmed_csv(false, 120.0, -0.2, 0.8)
        .lines()
        .enumerate()
        .map(|(i, l)| match i {
            10 | 20 | 30 | 40 | 50 | 60 => {
                let cells: Vec<&str> = l.split(',').collect();
                format!("{},,,{},{}\n", cells[0], cells[3], cells[4])
            }
            _ => format!("{l}\n"),
        })
        .collect();
    std::fs::write(&file, text).unwrap();
    let (code, out, err) = groovelab(&["data", file.to_str().unwrap()]);
    assert_eq!(code, Some(0), "{err}");
    let line = out
        .lines()
        .find(|l| l.contains("frames missing"))
        .unwrap_or_else(|| panic!("{out}"));
    assert!(
        line.contains("6 frames missing: 1 at t = ")
            && !line.contains(" … ")
            && line.ends_with(", and 1 more run"),
        "{line}"
    );
    // An impact given far outside the times names its flag and the times allowed.
    let (code, _, err) = groovelab(&[
        "fit",
        "--preset",
        "paper-b4.9",
        "--data",
        f,
        "--impact-at",
        "1e308",
    ]);
    assert_eq!(code, Some(2));
    assert!(
        err.contains("--impact-at 1e308 s leaves fewer than 3 frames on one side")
            && err.contains("t = 0 … 1 s")
            && err.lines().count() == 1,
        "{err}"
    );
    // A negative scale without `=`: the value's error, not "unexpected argument '-1'".
    for args in [
        vec!["data", f, "--scale", "-1mm"],
        vec!["track", f, "--scale", "-1mm"],
    ] {
        let (code, _, err) = groovelab(&args);
        assert_eq!(code, Some(2));
        assert!(
            err.contains("'-1mm' is not a pixel's length, expected a length above 0"),
            "{err}"
        );
    }
    // A scale typed as pixels per metre (a bare number is metres a pixel): refused,
    // saying what it was read as, never 958 m a pixel.
    for (value, read) in [
        ("957.86", "957.9 m a pixel"),
        ("2m", "2 m a pixel"),
        ("0.0001mm", "1.000e-7 m a pixel"),
    ] {
        let (code, _, err) = groovelab(&["track", f, "--scale", value]);
        assert_eq!(code, Some(2), "{err}");
        assert!(
            err.contains(&format!("'{value}' ({read})")) && err.contains("allowed 0.001mm … 10cm"),
            "{err}"
        );
        assert!(err.lines().count() == 1, "{err}");
    }
    let (code, _, err) = groovelab(&["data", f, "--window", "-1ms"]);
    assert_eq!(code, Some(2));
    assert!(err.contains("--window -0.001 s is out of range"), "{err}");
    let _ = std::fs::remove_dir_all(&dir);
}

/// A velocity file with an approach too short for v0 (two frames before the impact,
/// three needed) said "approach speed 0.79 m/s" and then "the scene takes nothing
/// from it (no approach before an impact)", a contradiction a new user read; it now
/// says why the approach it shows is not taken. With three frames before, v0 is.
#[test]
fn an_approach_too_short_for_v0_says_so() {
    let dir = crate::common::scratch_dir("data_hints", "short-approach");
    let rows = |before: usize| -> String {
        let mut text = String::from("t,v_cm,v_t\n");
        for k in 0..before {
            text += &format!("{:.2},0.79,0.79\n", -0.01 * (before - k) as f64);
        }
        for k in 0..6 {
            text += &format!(
                "{:.2},{:.2},{:.2}\n",
                0.01 * k as f64,
                -0.7 + 0.04 * k as f64,
                0.79 - 0.02 * k as f64
            );
        }
        text
    };
    let said = |before: usize| {
        let file = dir.join(format!("before-{before}.csv"));
        std::fs::write(&file, rows(before)).unwrap();
        let (code, out, err) = groovelab(&["data", file.to_str().unwrap()]);
        assert_eq!(code, Some(0), "{err}");
        out
    };
    let short = said(2);
    assert!(short.contains("approach speed 0.79 m/s"), "{short}");
    assert!(
        short.contains("the scene takes nothing from it (too few frames before the impact to take v0 from, at least 3)"),
        "{short}"
    );
    assert!(!short.contains("no approach before an impact"), "{short}");
    let long = said(4);
    assert!(
        long.contains("the scene takes from it: v0 = 0.79"),
        "{long}"
    );
    // A position track in cm with no unit, 7 frames before its impact: shown in its
    // own unit, and its v0 not taken for that reason, not "too few frames" (a new
    // user's trial). The unit's line gives the speed between frames, not the approach.
    let mut track = String::from("t,x\n");
    for k in 0..14 {
        let t = f64::from(k) / 30.0;
        let x = if k <= 7 {
            80.0 * t
        } else {
            80.0 * 7.0 / 30.0 - 60.0 * (t - 7.0 / 30.0)
        };
        track += &format!("{t:.4},{x:.3}\n");
    }
    let file = dir.join("cm-no-unit.csv");
    std::fs::write(&file, track).unwrap();
    let (code, out, err) = groovelab(&["data", file.to_str().unwrap()]);
    assert_eq!(code, Some(0), "{err}");
    assert!(out.contains("not known to be metres"), "{out}");
    assert!(out.contains("as m the ball moves at up to 80"), "{out}");
    assert!(
        out.contains("the scene takes nothing from it (its lengths' unit is not known"),
        "{out}"
    );
    assert!(!out.contains("too few frames"), "{out}");
}

/// Seconds under a header that says ms: 0.6 s of a ball's approach and slide read as
/// 0.6 ms at 100 000 frames/s, which no recording of balls in a groove is. Refused
/// naming the time unit that fits (it passed, and `fit` then blamed the speeds'
/// unit: a new user's trial). The same numbers under `t (s)`, and the times written
/// in ms under `t (ms)`, are read.
#[test]
fn seconds_under_a_ms_header_are_refused_naming_the_time_unit() {
    let dir = crate::common::scratch_dir("data_hints", "seconds-as-ms");
    let file = |name: &str, header: &str, per_s: f64| {
        let mut text = format!("{header},v_cm (m/s),v_t (m/s)\n");
        for k in 0..61 {
            let t = -0.2 + 0.01 * f64::from(k);
            let (v, u) = if t < 0.0 {
                (0.79, 0.79)
            } else {
                (-0.79 + 3.7 * t, 0.79 - 1.9 * t)
            };
            text += &format!("{:.3},{v:.4},{u:.4}\n", t * per_s);
        }
        let path = dir.join(name);
        std::fs::write(&path, text).unwrap();
        groovelab(&["data", path.to_str().unwrap()])
    };
    let (code, _, err) = file("wrong.csv", "t (ms)", 1.0);
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.contains("frames 0.01 apart (as ms: 100000 frames/s; as s: 100 frames/s)")
            && err.contains("if they are s, fix the header (t (s)) or give --time-unit s"),
        "{err}"
    );
    assert_eq!(err.trim_end().lines().count(), 1, "{err}");
    for (name, header, per_s) in [("s.csv", "t (s)", 1.0), ("ms.csv", "t (ms)", 1e3)] {
        let (code, out, err) = file(name, header, per_s);
        assert_eq!(code, Some(0), "{name}: {err}");
        assert!(out.contains("61 frames at 100 frames/s"), "{name}: {out}");
    }
}

/// Runs `args` in this process: its exit status and what it printed.
fn run(args: &[&str]) -> groovelab::cli::entry::Exit {
    let argv: Vec<std::ffi::OsString> = std::iter::once("groovelab")
        .chain(args.iter().copied())
        .map(std::ffi::OsString::from)
        .collect();
    groovelab::cli::entry::main_with(&argv)
}

/// The paper scene's track (R 2.75 cm, b 4.9 cm, μ_k 0.17, v0 0.7 m/s, e 1) as the
/// rows of its Tracker multi-track export: t, then x, y of the centre and of the rim
/// mark, in s and m.
fn paper_rows() -> Vec<[f64; 5]> {
    use groovelab::study::video::{self, TrackFormat, Video};
    let scene = crate::common::symmetric(0.0275, 0.049, 0.17, 0.7, 1.0);
    let track = video::track(&scene, &Video::default()).unwrap();
    video::write(&track, TrackFormat::TrackerMulti)
        .lines()
        .skip(3)
        .map(|r| {
            let c: Vec<f64> = r.split('\t').map(|c| c.parse().unwrap()).collect();
            [c[0], c[1], c[2], c[3], c[4]]
        })
        .collect()
}

/// `fit` of the file `f` in the paper's groove (`--radius 2.75cm --width 4.9cm`).
fn fit_in_paper_groove(f: &str) -> groovelab::cli::entry::Exit {
    run(&["fit", "--data", f, "--radius", "2.75cm", "--width", "4.9cm"])
}

/// A fit's headline: its second line (μ_k, the model, the verdict).
fn headline(fit: &groovelab::cli::entry::Exit) -> String {
    fit.stdout.lines().nth(1).unwrap_or_default().to_string()
}

/// `file` written as `head` over `lines`: what `data` says of it, and the headline
/// of its fit in the paper's groove.
fn data_and_headline(file: &std::path::Path, head: &str, lines: &[String]) -> (String, String) {
    std::fs::write(file, format!("{head}\n{}\n", lines.join("\n"))).unwrap();
    let f = file.to_str().unwrap();
    (run(&["data", f]).stdout, headline(&fit_in_paper_groove(f)))
}

/// Units in a row of their own under the column names (`t,x,y` over `ms,mm,mm`, as
/// spreadsheets and some loggers write them) are read as the header's: the file
/// reads as the same file with `t (ms),x (mm),y (mm)`, whatever the separator and
/// however the units are bracketed. It was refused: "t = 'ms' is not a finite
/// number". A row with a number in it is data, not units; an unknown unit there is
/// named as in a header.
#[test]
fn a_units_row_under_the_names_is_read_as_their_units() {
    let dir = crate::common::scratch_dir("data_hints", "units-row");
    let file = dir.join("track.csv");
    let f = file.to_str().unwrap();
    // The track of `two_speeds` (an impact at 0.3 s) in ms and mm.
    let rows: Vec<(f64, f64)> = two_speeds(0.5, -0.15)
        .lines()
        .skip(1)
        .map(|l| {
            let c: Vec<f64> = l.split(',').map(|c| c.parse().unwrap()).collect();
            (c[0] * 1e3, c[1] * 1e3)
        })
        .collect();
    let write = |head: &[&str], sep: &str, comma: bool| {
        let mut text: String = head.iter().map(|l| format!("{l}\n")).collect();
        for (t, x) in &rows {
            let line = format!("{t:.1}{sep}{x:.4}{sep}100");
            text += &if comma { line.replace('.', ",") } else { line };
            text.push('\n');
        }
        std::fs::write(&file, text).unwrap();
        run(&["data", f])
    };
    let want = write(&["t (ms),x (mm),y (mm)"], ",", false);
    assert_eq!(want.code, 0, "{}", want.stderr);
    assert!(want.stdout.contains("time in ms") && want.stdout.contains("length in mm"));
    let heads: [(&[&str], &str, bool); 4] = [
        (&["t,x,y", "ms,mm,mm"], ",", false),
        (&["t;x;y", "(ms);(mm);[mm]"], ";", true),
        (&["t\tx\ty", "ms\tmm"], "\t", false),
        (&["Zeit,x,y", "ms,mm,mm"], ",", false),
    ];
    for (head, sep, comma) in heads {
        let got = write(head, sep, comma);
        assert_eq!(got.code, 0, "{head:?}: {}", got.stderr);
        assert_eq!(got.stdout, want.stdout, "{head:?}");
    }
    // Without the units row's units, the same numbers are read in s and m.
    let bare = write(&["t,x,y"], ",", false);
    assert_ne!(bare.stdout, want.stdout);
    // A row with a number is the first row of data.
    let numbered = write(&["t,x,y", "ms,5,mm"], ",", false);
    assert!(
        numbered.code == 2
            && numbered
                .stderr
                .contains("line 2: t = 'ms' is not a finite number"),
        "{}",
        numbered.stderr
    );
    let minutes = write(&["t,x,y", "min,mm,mm"], ",", false);
    assert!(
        minutes.code == 2 && minutes.stderr.contains("unknown time unit 'min'"),
        "{}",
        minutes.stderr
    );
    let _ = std::fs::remove_dir_all(&dir);
}

/// A file of one speed over time (`Zeit (s),Geschwindigkeit (m/s)`, or `t,v`) is
/// refused naming that speed and the two a file of speeds needs. It said only that
/// no position column x was found.
#[test]
fn one_speed_is_named_with_the_two_a_velocity_file_needs() {
    let dir = crate::common::scratch_dir("data_hints", "one-speed");
    let file = dir.join("speed.csv");
    let f = file.to_str().unwrap();
    for (head, cell) in [
        ("Zeit (s),Geschwindigkeit (m/s)", "Geschwindigkeit (m/s)"),
        ("t;v", "v"),
        ("time (s),speed (cm/s)", "speed (cm/s)"),
    ] {
        let sep = if head.contains(';') { ";" } else { "," };
        let text = format!("{head}\n0{sep}0.5\n0.01{sep}0.49\n0.02{sep}0.48\n");
        std::fs::write(&file, text).unwrap();
        let got = run(&["data", f]);
        assert!(
            got.code == 2
                && got
                    .stderr
                    .contains(&format!("line 1: '{cell}' is one speed"))
                && got.stderr.contains("t, v_cm and v_t")
                && got.stderr.trim_end().lines().count() == 1,
            "{head}: {}",
            got.stderr
        );
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// A velocity file's first impact is said where it lies in the file's own time (its
/// times are shown from the impact): a file from t = 1.2 s with the impact between
/// the frames at 1.49 and 1.50 s says "found at t = 1.4950 s of the file", in s or
/// ms, and JSON `impact_in_file`; an impact given says "given at" the time given. It
/// said only "first impact found; the times above are from it (t = 0)".
#[test]
fn a_velocity_files_impact_is_said_in_the_files_own_time() {
    let dir = crate::common::scratch_dir("data_hints", "impact-in-file");
    let file = dir.join("v.csv");
    let f = file.to_str().unwrap();
    for (unit, factor) in [("s", 1.0), ("ms", 1e3)] {
        let mut text = format!("t ({unit}),v_cm (m/s),v_t (m/s)\n");
        for k in 0..60 {
            let t = 1.2 + f64::from(k) * 0.01;
            let (v_cm, v_t) = if t < 1.495 {
                (0.6, 0.6)
            } else {
                (-0.1 + 0.5 * (t - 1.5), 0.5 - 1.2 * (t - 1.5))
            };
            text += &format!("{:.3},{v_cm:.5},{v_t:.5}\n", t * factor);
        }
        std::fs::write(&file, text).unwrap();
        let said = run(&["data", f]);
        let at: f64 = said
            .stdout
            .split("first impact found at t = ")
            .nth(1)
            .and_then(|r| r.split(" s of the file").next())
            .unwrap_or_else(|| panic!("{unit}: {}", said.stdout))
            .parse()
            .unwrap();
        // Between the last frame before (1.49 s) and the first after (1.50 s).
        assert!((1.49..=1.50).contains(&at), "{unit}: {at}");
        let json: serde_json::Value =
            serde_json::from_str(&run(&["data", "--format", "json", f]).stdout).unwrap();
        let in_file = json[0]["impact_in_file"].as_f64().unwrap();
        assert!((in_file - at).abs() < 1e-4, "{in_file} {at}");
        let given = run(&[
            "data",
            "--impact-at",
            &format!("{}{unit}", 1.47 * factor),
            f,
        ]);
        assert!(
            given
                .stdout
                .contains("first impact given at t = 1.4700 s of the file"),
            "{}",
            given.stdout
        );
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// Columns named for Tracker's mass A and B by a letter after the axis (`x_A`,
/// `y_B`) or after a word (`mass A x`) are tracks A and B: a centre and its rim mark
/// read as the same file with `x`, `x_mark`, and the same fit. `x_A` was read as an
/// acceleration (the letter `a` of `a_x`), so the A columns were dropped without a
/// word and B became the centre. A letter leading the name (`v_x`, `a_y`) is still a
/// quantity, not a position.
#[test]
fn a_letter_after_the_axis_names_a_track() {
    let file = crate::common::scratch_dir("data_hints", "track-letters").join("t.csv");
    // The rows of the multi-track export (t, x, y of A, x, y of B), under our headers.
    let rows = paper_rows();
    let fit_of = |head: &str, sep: char| {
        let lines: Vec<String> = rows
            .iter()
            .map(|r| r.map(|c| c.to_string()).join(&sep.to_string()))
            .collect();
        data_and_headline(&file, head, &lines)
    };
    let (_, want) = fit_of("t,x,y,x_mark,y_mark", ',');
    assert!(
        want.contains("μ_k = 0.1") && want.contains("agrees"),
        "{want}"
    );
    for (head, sep) in [
        ("t (s),x_A (m),y_A (m),x_B (m),y_B (m)", ','),
        ("t;x_A;y_A;x_B;y_B", ';'),
        ("t\tmass A x\tmass A y\tmass B x\tmass B y", '\t'),
        ("t (s),xA (m),yA (m),xB (m),yB (m)", ','),
    ] {
        let (data, fit) = fit_of(head, sep);
        assert!(
            data.contains("centre 'a', rim mark 'b'")
                || data.contains("centre 'mass a', rim mark 'mass b'"),
            "{head}: {data}"
        );
        assert_eq!(fit, want, "{head}");
    }
    // A quantity's letter before the axis: velocities and accelerations, not
    // positions, after a track's name too.
    let (data, _) = fit_of("t,x,y,v_x,a_y", ',');
    assert!(
        data.contains("centre x, y (unnamed), no rim mark"),
        "{data}"
    );
    let (data, _) = fit_of("t,x,y,ball v x,ball a y", ',');
    assert!(
        data.contains("centre x, y (unnamed), no rim mark"),
        "{data}"
    );
    let _ = std::fs::remove_file(&file);
}

/// Each point's own time column, `t1,x1,y1,t2,x2,y2` as a sheet of two points
/// tracked one after the other writes it: point 1 is the centre on t1, point 2 the
/// rim mark matched to it by t2, and `fit` says what the plain `t,x,y,x_mark,y_mark`
/// file says. It was refused: "no header with a time column t".
#[test]
fn each_points_own_time_column_reads_as_its_track() {
    let file = crate::common::scratch_dir("data_hints", "own-times").join("t.csv");
    let rows = paper_rows();
    let fit_of = |head: &str, cells: &dyn Fn(&[f64; 5]) -> Vec<f64>| {
        let lines: Vec<String> = rows
            .iter()
            .map(|r| {
                let cells: Vec<String> = cells(r).iter().map(f64::to_string).collect();
                cells.join(",")
            })
            .collect();
        data_and_headline(&file, head, &lines)
    };
    let plain = |r: &[f64; 5]| r.to_vec();
    let (_, want) = fit_of("t,x,y,x_mark,y_mark", &plain);
    assert!(
        want.contains("μ_k = 0.1") && want.contains("agrees"),
        "{want}"
    );
    let own = |r: &[f64; 5]| vec![r[0], r[1], r[2], r[0], r[3], r[4]];
    let (data, fit) = fit_of("t1 (s),x1 (m),y1 (m),t2 (s),x2 (m),y2 (m)", &own);
    assert!(
        data.contains("centre 'point 1', rim mark 'point 2'"),
        "{data}"
    );
    assert_eq!(fit, want);
    let _ = std::fs::remove_file(&file);
}

/// A track's second point more than 2R from the centre is no rim mark, and `data`
/// says so with its distance; but not while the lengths' unit is not known: a rim
/// mark written in cm under a header with no unit lay "276.3 cm" from the centre,
/// no rim mark, where it is the mark at R once `--length-unit cm` is given.
#[test]
fn a_mark_is_judged_by_its_distance_only_in_a_known_unit() {
    let dir = crate::common::scratch_dir("data_hints", "mark-distance");
    let rows = paper_rows();
    // The file with `head`, every length × `scale`, the mark moved `out` m along x.
    let data = |head: &str, scale: f64, out: f64, more: &[&str]| {
        let file = dir.join("t.csv");
        let mut body = format!("{head}\n");
        for r in &rows {
            let cells = [
                r[0],
                r[1] * scale,
                r[2] * scale,
                (r[3] + out) * scale,
                r[4] * scale,
            ];
            body += &format!("{}\n", cells.map(|c| c.to_string()).join(","));
        }
        std::fs::write(&file, body).unwrap();
        let f = file.to_str().unwrap();
        run(&[&["data", f], more].concat()).stdout
    };
    let doubt = "is no rim mark: it lies";
    // In cm, no unit said: the unit's doubt, no word on the mark's distance.
    let cm = data("t,x,y,x_mark,y_mark", 100.0, 0.0, &[]);
    assert!(
        cm.contains("not known to be metres") && !cm.contains(doubt),
        "{cm}"
    );
    let given = data("t,x,y,x_mark,y_mark", 100.0, 0.0, &["--length-unit", "cm"]);
    assert!(
        given.contains("rim mark 'mark'") && !given.contains(doubt),
        "{given}"
    );
    // A second point 20 cm off, in metres said: no rim mark, its distance said.
    let far = data("t (s),x (m),y (m),x_mark (m),y_mark (m)", 1.0, 0.2, &[]);
    assert!(far.contains(&format!("track 'mark' {doubt} 2")), "{far}");
    let _ = std::fs::remove_dir_all(&dir);
}

/// A unit written after a track's name (`x_mark_cm`, as after an axis, `x_cm`) is
/// that column's unit, and a spreadsheet's "not available" (`#N/A`, German `#NV`) is
/// a missing cell: both read as the plain file does. `x_mark_cm` was a track 'mark
/// cm' 24 m from the centre; `#N/A` refused the file.
#[test]
fn a_unit_after_a_tracks_name_and_not_available_cells_read_as_the_plain_file() {
    let dir = crate::common::scratch_dir("data_hints", "unit-after-name");
    let rows = paper_rows();
    // The file with `head`, lengths × `scale`, the mark of rows 40–42 written `gone`.
    let said = |head: &str, scale: f64, gone: &str| {
        let file = dir.join("t.csv");
        let mut body = format!("{head}\n");
        for (k, r) in rows.iter().enumerate() {
            let mark = if (40..43).contains(&k) {
                format!("{gone},{gone}")
            } else {
                format!("{},{}", r[3] * scale, r[4] * scale)
            };
            body += &format!("{},{},{},{mark}\n", r[0], r[1] * scale, r[2] * scale);
        }
        std::fs::write(&file, body).unwrap();
        let f = file.to_str().unwrap();
        let fit = fit_in_paper_groove(f);
        assert_eq!(fit.code, 0, "{head} {gone}: {}", fit.stderr);
        headline(&fit)
    };
    let want = said("t,x,y,x_mark,y_mark", 1.0, "");
    assert!(want.contains("agrees"), "{want}");
    for (head, scale) in [
        ("t_s,x_m,y_m,x_mark_m,y_mark_m", 1.0),
        ("t_s,x_cm,y_cm,x_mark_cm,y_mark_cm", 100.0),
        ("t,x_mm,y_mm,x_rim_mm,y_rim_mm", 1000.0),
    ] {
        let got = said(head, scale, "");
        // μ_k to its four digits: the numbers as written in another unit round apart.
        assert_eq!(got[..20], want[..20], "{head}: {got}");
    }
    for gone in ["#N/A", "#NV", "NaN"] {
        assert_eq!(said("t,x,y,x_mark,y_mark", 1.0, gone), want, "{gone}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// A second track whose distance from the centre comes and goes (another run of the
/// ball side by side, taken for the rim mark) is left out as no mark, saying how its
/// distance changed, and the centre alone is fitted; a rim mark on the ball (0.3 mm
/// noise, any seed) is kept. The run was read as a mark "at 6.8 mm from the centre",
/// and the fits disagreed.
#[test]
fn a_second_run_taken_for_the_mark_is_left_out_as_no_mark() {
    use groovelab::study::measured::Track;
    use groovelab::study::video::{self, TrackFormat, Video};
    let dir = crate::common::scratch_dir("data_hints", "second-run");
    let file = dir.join("t.txt");
    let f = file.to_str().unwrap();
    let scene = crate::common::symmetric(0.0275, 0.049, 0.17, 0.7, 1.0);
    for seed in 1..4 {
        let video = Video {
            seed,
            ..Video::default()
        };
        let track = video::track(&scene, &video).unwrap();
        std::fs::write(&file, video::write(&track, TrackFormat::TrackerMulti)).unwrap();
        let kept = run(&["data", f]);
        assert!(
            !kept.stdout.contains("left out"),
            "seed {seed}: {}",
            kept.stdout
        );
        // The mark's columns hold the ball's own centre 4 frames later: a second run.
        let mut run2 = track.into_parts();
        let (xs, ys) = (run2.x.clone(), run2.y.clone());
        let (mx, my) = run2.mark.as_mut().unwrap();
        for k in 0..xs.len() {
            mx[k] = xs.get(k + 4).copied().unwrap_or(f64::NAN);
            my[k] = ys.get(k + 4).copied().unwrap_or(f64::NAN);
        }
        std::fs::write(
            &file,
            video::write(&Track::new(run2).unwrap(), TrackFormat::TrackerMulti),
        )
        .unwrap();
        let said = run(&["data", f]);
        assert!(
            said.stdout
                .contains("left out by the fits: its distance from the centre changes from"),
            "seed {seed}: {}",
            said.stdout
        );
        let fit = fit_in_paper_groove(f);
        assert!(headline(&fit).contains("agrees"), "{}", fit.stdout);
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// Lines of notes above the header (experiment, date, group) and Excel's `sep=;`
/// line are no track's name: the file reads as plain CSV with its centre unnamed, as
/// without them. They made it "Tracker single-track" with the centre named 'Gruppe
/// 3' or 'sep='. A file with no header near its top names its first line.
#[test]
fn notes_and_excels_sep_line_above_the_header_name_no_track() {
    let dir = crate::common::scratch_dir("data_hints", "notes-above");
    let file = dir.join("t.csv");
    let f = file.to_str().unwrap();
    let body = two_speeds(0.6, -0.2).replace(',', ";");
    let read = |above: &str| {
        std::fs::write(&file, format!("{above}{body}")).unwrap();
        run(&["data", f])
    };
    let plain = read("");
    assert!(
        plain.stdout.contains(": CSV, position track"),
        "{}",
        plain.stdout
    );
    for above in [
        "Experiment: Kugeln in Rinne\nDatum: 12.03.2024\nGruppe 3\n\n",
        "sep=;\n",
        "Run 4\nGruppe 3\n",
    ] {
        let got = read(above);
        let without_name = |s: &str| s.lines().skip(1).collect::<Vec<_>>().join("\n");
        assert_eq!(
            without_name(&got.stdout),
            without_name(&plain.stdout),
            "{above:?}: {}",
            got.stdout
        );
        assert!(got.stdout.contains(": CSV, position track"), "{above:?}");
    }
    // One title line is Tracker's single-track export, as before.
    let titled = read("mass_A\n");
    assert!(
        titled.stdout.contains("Tracker single-track") && titled.stdout.contains("centre 'mass_A'")
    );
    std::fs::write(&file, "Versuch 1\nDatum\nGruppe\nMessung;Wert\n0;1\n").unwrap();
    let none = run(&["data", f]);
    assert!(
        none.code == 2
            && none
                .stderr
                .contains("no header with a time column t in lines 1 to 4 (line 1: 'Versuch 1')"),
        "{}",
        none.stderr
    );
    let _ = std::fs::remove_dir_all(&dir);
}
