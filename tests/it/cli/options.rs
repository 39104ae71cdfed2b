//! The command line as scripts use it: bad input of every option gives one `error:`
//! line, exit status 2 and nothing on stdout; good input gives parseable output.

use std::io::Write;
use std::process::{Command, Stdio};

use crate::common::{groovelab, json};

fn assert_rejected(args: &[&str], mentions: &str) {
    let out = groovelab(args);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{args:?}: {stderr}");
    assert!(out.stdout.is_empty(), "{args:?} printed on stdout");
    let first = stderr.lines().next().unwrap_or("");
    assert!(first.starts_with("error: "), "{args:?}: {stderr}");
    assert!(
        first.contains(mentions),
        "{args:?}: first line {first:?} does not mention {mentions:?}"
    );
    assert!(!stderr.contains("panicked"), "{args:?} panicked");
}

#[test]
fn every_option_rejects_bad_values() {
    let cases: &[(&[&str], &str)] = &[
        (&["--radius", "0"], "0.1 mm ≤ R ≤ 10 m"),
        (&["--radius", "-1cm"], "0.1 mm ≤ R"),
        (&["--radius", "abc"], "not a number"),
        (&["--radius", "3kg"], "unknown unit"),
        (&["--width", "6cm"], "b < 2R"),
        (&["--width", "5.5cm"], "b < 2R"),
        (&["--width", "-1mm"], "0 ≤ b"),
        (&["--mass", "0"], "1 mg ≤ m ≤ 1000 kg"),
        (&["--mass-left", "-5g"], "1 mg ≤ m"),
        (&["--mass-right", "5m"], "unknown unit"),
        (&["--mu", "-0.1"], "0 ≤ μ_k ≤ 10"),
        (&["--mu", "0.1cm"], "plain number"),
        (&["--v0", "nan"], "finite"),
        (&["--v0-left", "inf"], "finite"),
        (&["--v0-right", "1kg"], "unknown unit"),
        (&["--v0-left", "-1", "--v0-right", "0.5"], "closing speed"),
        (&["--height", "-1cm"], "0 ≤ h"),
        (&["--height", "1cm", "--v0", "1"], "cannot be used with"),
        (&["--restitution", "1.5"], "0 ≤ e ≤ 1"),
        (&["--restitution", "-0.5"], "0 ≤ e ≤ 1"),
        (&["--rolling-resistance", "-1"], "0 ≤ c_rr"),
        (&["--g", "0"], "0.01 m/s² ≤ g"),
        (&["--g", "9.81m/s"], "unknown unit"),
        (&["--t-start", "1s"], "t_start ≤ 0"),
        (&["--t-end", "-0.5s"], "t_end > t_start"),
        (&["--sample", "0"], "step > 0"),
        (&["--sample", "-1ms"], "step > 0"),
        (&["--sample", "1e-9"], "at most"),
        (&["--sample", "1ns"], "unknown unit"),
        (&["--preset", "no-such-preset"], "unknown preset"),
        (&["--format", "xml"], "invalid value"),
        (&["--method", "leapfrog"], "invalid value"),
        (&["--method", "euler", "--dt", "0"], "0 < dt"),
        (&["--method", "rk45", "--tol", "2"], "tol"),
        (&["--method", "rk4", "--epsilon", "-1mm/s"], "ε > 0"),
        (&["--bogus"], "unexpected argument"),
        // What is allowed: clap's suggestion, else every option of the command.
        (&["--wdth", "3cm"], "a similar option exists: '--width'"),
        (&["--bogus"], "allowed options of `groovelab simulate`: "),
        (&["--bogus"], "--radius, --width"),
        // Physical ranges (the parameter table): finite but absurd values are refused.
        (&["--mass-right", "1e308"], "1 mg ≤ m ≤ 1000 kg"),
        // Named as given: --mass sets both balls.
        (
            &["--mass", "1e308"],
            "error: mass = 1e308 kg is out of range",
        ),
        (&["--v0", "1e155"], "error: v0 = "),
        (&["--v0", "1e155"], "-100 m/s ≤ v0 ≤ 100 m/s"),
        (&["--mu", "11"], "0 ≤ μ_k ≤ 10"),
        (&["--radius", "11m"], "R ≤ 10 m"),
        (&["--height", "400m", "--g", "1000"], "too fast"),
        (&["--t-end", "2e6"], "t_end ≤ 1e6 s"),
        // A bare number is SI: a length or a mass meant in cm or g is said to be,
        // where the number read in that unit is allowed.
        (
            &["--width", "4.9"],
            "groove width b = 490 cm is out of range, allowed 0 ≤ b < 2R = 5.5 cm; --width 4.9 has no unit, so it is 4.9 m (a bare number is SI); in cm write 4.9cm",
        ),
        (&["--width=4.9"], "; in cm write 4.9cm"),
        (
            &["--mass", "2000"],
            "--mass 2000 has no unit, so it is 2000 kg",
        ),
        (&["--mass-left", "2000"], "; in g write 2000g"),
        (&["--radius", "275"], "; in cm write 275cm"),
    ];
    let render_cases: &[(&[&str], &str)] = &[
        (&["--size", "10"], "COLSxROWS"),
        (&["--size", "0x10"], "COLSxROWS"),
        (&["--size", "5000x10"], "COLSxROWS"),
        // A size too large is said to be, with the range (it was "not a size").
        (
            &["--size", "100000x100000"],
            "'100000x100000' is larger than render draws, allowed COLSxROWS from 80x24 to 1000x1000",
        ),
        (&["--size", "1001x40"], "is larger than render draws"),
        // render has no terminal: a screen below the app's smallest is a usage error.
        (
            &["--size", "10x5"],
            "'10x5' is smaller than the app's smallest screen, allowed at least 80x24",
        ),
        (&["--size", "79x23"], "at least 80x24"),
        (&["--size", "80x23"], "at least 80x24"),
        (&["--at", "5s"], "outside the simulated span"),
        (&["--at", "-1"], "outside the simulated span"),
        (&["--keys", "space spacebar"], "unknown key 'spacebar'"),
        (&["--width", "9cm"], "b < 2R"),
    ];
    // A mass in mg, the unit the range messages use, is a mass.
    let out = groovelab(&["simulate", "--mass-right", "200mg", "--format", "json"]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let fit_cases: &[(&[&str], &str)] = &[
        (
            &["--free", "mu,mu"],
            "--free names mu twice, allowed each value once",
        ),
        (&["--free", "v0,mu,v0"], "names v0 twice"),
        // Every model fits μ_k: a list without it is refused, naming the fix (it
        // once failed with "no finite model fit μ_k error").
        (&["--free", "v0"], "--free v0 leaves out mu"),
        (
            &["--free", "v0,restitution"],
            "give --free mu,v0,restitution",
        ),
    ];
    for (args, mentions) in fit_cases {
        let mut full = vec!["fit", "--preset", "paper-b4.9"];
        full.extend_from_slice(args);
        assert_rejected(&full, mentions);
    }
    for (args, mentions) in render_cases {
        let mut full = vec!["render"];
        full.extend_from_slice(args);
        assert_rejected(&full, mentions);
    }
    for (args, mentions) in cases {
        let mut full = vec!["simulate"];
        full.extend_from_slice(args);
        assert_rejected(&full, mentions);
    }
}

/// A unit option's error lists each unit once: `us` was listed twice (the unit table
/// has it, and the list of a data file's units added it again).
#[test]
fn a_unit_options_error_names_each_unit_once() {
    let file = concat!(env!("CARGO_MANIFEST_DIR"), "/data/gs-b4.9cm.csv");
    let out = groovelab(&["data", file, "--time-unit", "min"]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert_eq!(
        err.trim_end(),
        "error: --time-unit min: unknown unit 'min' in 'min', expected one of s, ms, us, µs, μs"
    );
}

/// A sweep's bound lent the other bound's unit is named as typed: `width=3..5kg` was
/// refused for '3kg', which nobody wrote (and `abc..5cm` for 'abccm').
#[test]
fn a_sweep_range_is_quoted_as_typed() {
    assert_rejected(
        &["sweep", "--x", "width=3..5kg"],
        "error: --x unknown unit 'kg' in '3..5kg', expected a number with unit m, cm, mm",
    );
    assert_rejected(
        &["sweep", "--x", "width=abc..5cm"],
        "error: --x 'abc' is not a number",
    );
}

/// A sweep solves each grid point from its impact to its end: `--t-start` and
/// `--t-end` changed nothing and were taken silently. Refused by name, and left out
/// of `sweep --help`.
#[test]
fn a_sweep_refuses_the_span_it_does_not_use() {
    for (flag, value) in [("--t-end", "0.05"), ("--t-start", "-1")] {
        assert_rejected(
            &["sweep", "--x", "width=3..5cm", "--grid", "2", flag, value],
            &format!("error: {flag} is not used by sweep, allowed only with simulate, render"),
        );
    }
    let help = String::from_utf8(groovelab(&["sweep", "--help"]).stdout).unwrap();
    assert!(
        help.contains("--width") && !help.contains("--t-end"),
        "{help}"
    );
}

/// A grid of two counts for a sweep of one parameter is refused, naming the count
/// that has no axis and both ways out; one count, a second count of 1, or no
/// `--grid` (the default's NX) runs. The second count was ignored without a word.
#[test]
fn a_second_grid_count_without_a_second_parameter_is_refused() {
    assert_rejected(
        &["sweep", "--x", "width=3..5cm", "--grid", "5x5"],
        "error: --grid 5x5 counts 5 values of a second parameter, but only --x is swept: give --grid 5, or a second parameter with --y",
    );
    // No --grid: the default's 200 along x.
    let out = groovelab(&["sweep", "--x", "width=3..5cm", "--format", "csv"]);
    assert_eq!(String::from_utf8_lossy(&out.stdout).lines().count(), 201);
    for grid in ["5", "5x1"] {
        let out = groovelab(&[
            "sweep",
            "--x",
            "width=3..5cm",
            "--grid",
            grid,
            "--format",
            "csv",
        ]);
        assert_eq!(out.status.code(), Some(0), "{grid}");
        assert_eq!(
            String::from_utf8_lossy(&out.stdout).lines().count(),
            6,
            "{grid}"
        );
    }
}

/// The unit hint only where it helps: not for a value with a unit, a value that is
/// out of range in cm or g too, a sign's error, or a speed (m/s is what people
/// type).
#[test]
fn a_bare_numbers_unit_hint_is_said_only_where_it_helps() {
    for args in [
        &["--width", "6cm"][..],
        &["--mass", "1e308"],
        &["--radius", "-2"],
        &["--v0", "200"],
        &["--width", "4.9cm", "--radius", "0.02"],
        // Metres meant: 6 cm, 7 cm, just wider than the 2R allowed.
        &["--width", "0.06"],
        &["--radius", "0.03", "--width", "0.07"],
    ] {
        let mut full = vec!["simulate"];
        full.extend_from_slice(args);
        let out = groovelab(&full);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {stderr}");
        assert!(!stderr.contains("has no unit"), "{args:?}: {stderr}");
    }
}

/// A length or mass given as a bare number of 1 or more is SI and runs where in
/// range, with a `note:` on stderr saying so and how to write it in cm or g, the
/// output that of the value with its unit; under 1 (metres or kilograms meant) or
/// with a unit, no note. `--mass 167` ran two 167 kg balls without a word.
#[test]
fn a_bare_number_in_range_is_said_to_be_si() {
    let run = |args: &[&str]| {
        let out = groovelab(&[&["simulate"], args].concat());
        assert_eq!(out.status.code(), Some(0), "{args:?}");
        (
            String::from_utf8_lossy(&out.stdout).to_string(),
            String::from_utf8_lossy(&out.stderr).to_string(),
        )
    };
    for (bare, unit, note) in [
        (
            "--mass",
            "kg",
            "note: --mass 167 has no unit, so it is 167 kg (a bare number is SI); in g write 167g",
        ),
        (
            "--radius",
            "m",
            "note: --radius 3 has no unit, so it is 3 m (a bare number is SI); in cm write 3cm",
        ),
    ] {
        let v = if bare == "--mass" { "167" } else { "3" };
        let (out, err) = run(&[bare, v, "--width", "5cm"]);
        assert_eq!(err.lines().collect::<Vec<_>>(), [note], "{err}");
        let with_unit = format!("{v}{unit}");
        let (same, quiet) = run(&[bare, &with_unit, "--width", "5cm"]);
        assert_eq!((out, quiet.as_str()), (same, ""));
    }
    for args in [
        &["--mass", "0.167"][..],
        &["--mass", "167g"],
        &["--radius", "0.03"],
    ] {
        let (_, err) = run(args);
        assert_eq!(err, "", "{args:?}");
    }
}

/// A grid corner outside the scene's range is named in the unit of the message that
/// follows it: "the grid corner width = 0.055 is not a valid scene: groove width
/// b = 5.5 cm is out of range" gave the same width as a bare number in metres.
#[test]
fn a_sweeps_bad_corner_is_named_in_the_units_people_read() {
    assert_rejected(
        &["sweep", "--x", "width=0..5.5cm", "--grid", "5"],
        "error: the grid corner width = 5.5 cm is not a valid scene: groove width b = 5.5 cm",
    );
}

/// A scene option that gives a value the sweep's axis sets at every point was
/// silently overwritten: `--x width=3..5cm --width 4cm` mapped 3 … 5 cm,
/// `--mass-left` under a `mass` axis and `--height` under a `v0` axis were dropped.
#[test]
fn a_sweep_refuses_a_scene_option_its_axis_overwrites() {
    for (axis, args, says) in [
        (
            "--x",
            &["--x", "width=3..5cm", "--width", "4cm"][..],
            "--x width sweeps the value --width gives",
        ),
        (
            "--x",
            &["--x", "mass=0.1..1", "--mass-left", "1"],
            "--x mass sweeps the value --mass-left gives (both set mass_left)",
        ),
        (
            "--x",
            &["--x", "v0=0.1..1", "--height", "3cm"],
            "--x v0 sweeps the value --height gives",
        ),
        (
            "--y",
            &[
                "--x",
                "width=3..5cm",
                "--y",
                "restitution=0.5..1",
                "--restitution",
                "0.9",
            ],
            "--y restitution sweeps the value --restitution gives",
        ),
    ] {
        let mut line = vec!["sweep", "--grid", "2x2"];
        line.extend(args);
        if axis == "--x" {
            line[2] = "2";
        }
        assert_rejected(&line, &format!("error: {says}"));
    }
    // An option of another value is the base of every point, as before.
    let out = groovelab(&["sweep", "--x", "width=3..5cm", "--grid", "2", "--mu", "0.2"]);
    assert_eq!(out.status.code(), Some(0));
}

/// An option whose value may be negative takes the next word whatever it is, so an
/// option left without its value swallows the next option and the word after that
/// is left over: clap said "unexpected argument 't.txt'" (or "unrecognized
/// subcommand"), pointing at the wrong word. The message names the option missing
/// its value and the option taken for it, for each such option, on the top level
/// and in subcommands.
#[test]
fn an_option_left_without_its_value_is_named_not_the_word_after() {
    let cases: &[(&[&str], &str)] = &[
        (
            &["track", "clip.mp4", "--ball-at", "--output", "t.txt"],
            "a value is required for '--ball-at <X,Y>', found the option '--output' after it",
        ),
        (
            &["track", "clip.mp4", "--roi", "--overlay", "o.png", "x"],
            "a value is required for '--roi <X,Y,W,H>', found the option '--overlay' after it",
        ),
        (
            &["fit", "--data", "x.csv", "--scale", "--fps", "30"],
            "a value is required for '--scale <LENGTH>', found the option '--fps' after it",
        ),
        (
            &["simulate", "--v0", "--mu", "0.2"],
            "a value is required for '--v0 <Q>', found the option '--mu' after it",
        ),
        // Top level: the word left over read as a subcommand.
        (
            &["--t-end", "--ascii", "x"],
            "found the option '--ascii' after it",
        ),
    ];
    for (args, says) in cases {
        assert_rejected(args, says);
    }
    // A negative value is still a value, and an unknown option still lists the
    // allowed ones.
    assert_rejected(&["simulate", "--v0", "-1", "--bogus"], "allowed options of");
}

fn preset_file(name: &str, text: &str) -> std::path::PathBuf {
    let dir = crate::common::scratch_root("cli").join("preset-files");
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(name);
    std::fs::File::create(&path)
        .unwrap()
        .write_all(text.as_bytes())
        .unwrap();
    path
}

#[test]
fn malformed_preset_files_are_rejected() {
    let cases = [
        (
            "typo.toml",
            "name = \"x\"\ndescription = \"d\"\n[scene]\nwidht = 0.01\n",
            "widht",
        ),
        (
            "unit.toml",
            "name = \"x\"\ndescription = \"d\"\n[scene]\nradius = \"2cm/s\"\n",
            "radius",
        ),
        ("broken.toml", "name = \"x\n", "malformed preset"),
        (
            "extra.toml",
            "name = \"x\"\ndescription = \"d\"\ncolor = 3\n[scene]\n",
            "color",
        ),
        (
            "series.toml",
            "name = \"x\"\ndescription = \"d\"\n[scene]\n[measured]\nt = [0.0, 1.0]\nv_cm = [1.0]\nv_t = [1.0, 2.0]\n",
            "differ in length",
        ),
        (
            "invalid.toml",
            "name = \"x\"\ndescription = \"d\"\n[scene]\nradius = 0.01\nwidth = 0.03\nmass = 0.1\nmu = 0.1\nv0 = 1\n",
            "b < 2R",
        ),
    ];
    for (file, text, mentions) in cases {
        let path = preset_file(file, text);
        assert_rejected(&["simulate", "--preset", path.to_str().unwrap()], mentions);
    }
}

#[test]
fn a_preset_file_with_units_runs() {
    let path = preset_file(
        "mine.toml",
        "name = \"mine\"\ndescription = \"my groove\"\n[scene]\nradius = \"1cm\"\nwidth = \"1.2cm\"\nmass = \"20g\"\nmu = 0.2\nv0 = \"50cm/s\"\n",
    );
    let out = groovelab(&[
        "simulate",
        "--preset",
        path.to_str().unwrap(),
        "--format",
        "json",
    ]);
    assert!(out.status.success());
    let doc: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(doc["scene"]["radius"], 0.01);
    assert_eq!(doc["scene"]["left"]["v0"], 0.5);
}

#[test]
fn json_follows_the_interface() {
    let doc = json(&[
        "simulate", "--format", "json", "--sample", "10ms", "--width", "4.4cm",
    ]);
    for key in ["scene", "derived", "method", "events", "samples", "final"] {
        assert!(!doc[key].is_null(), "missing {key}");
    }
    assert_eq!(doc["method"], "exact");
    assert_eq!(doc["scene"]["width"], 0.044);
    let samples = doc["samples"].as_array().unwrap();
    // -0.2 s … t_end in 10 ms steps; the preset's span gave way to the automatic one
    // (the width changed), which reaches past the last event.
    let t_end = doc["span"]["t_end"].as_f64().unwrap();
    let last_event = doc["events"].as_array().unwrap().last().unwrap()["t"]
        .as_f64()
        .unwrap();
    assert!(t_end > last_event, "{t_end} after {last_event}");
    assert_eq!(
        samples.len(),
        ((t_end + 0.2) / 0.01 + 1e-9).floor() as usize + 1
    );
    assert_eq!(samples[0]["t"], -0.2);
    for ev in doc["events"].as_array().unwrap() {
        for ball in ["left", "right"] {
            for q in ["x", "v", "u"] {
                assert!(ev[ball][q].is_f64(), "{ev}");
            }
        }
    }
}

#[test]
fn csv_gives_events_or_samples() {
    let out = groovelab(&["simulate", "--format", "csv", "--preset", "flat-table"]);
    let text = String::from_utf8(out.stdout).unwrap();
    let mut lines = text.lines();
    assert_eq!(
        lines.next(),
        Some("t,kind,ball,x_left,v_left,u_left,x_right,v_right,u_right")
    );
    // collision, pure gliding ×2, rolling ×2.
    assert_eq!(lines.count(), 5);
    let out = groovelab(&[
        "simulate", "--format", "csv", "--sample", "0.1", "--t-end", "0.3",
    ]);
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(text.starts_with("t,x_left,v_left,u_left,x_right,v_right,u_right\n"));
    assert_eq!(text.lines().count(), 1 + 6);
}

#[test]
fn units_on_the_command_line_mean_the_same_as_si() {
    let a = groovelab(&[
        "simulate", "--format", "json", "--width", "4.4cm", "--v0", "60cm/s", "--mass", "167g",
    ]);
    let b = groovelab(&[
        "simulate", "--format", "json", "--width", "0.044", "--v0", "0.6", "--mass", "0.167",
    ]);
    assert!(a.status.success());
    assert!(a.stdout == b.stdout, "unit and SI runs differ");
}

#[test]
fn presets_lists_every_built_in_preset() {
    let out = groovelab(&["presets"]);
    let text = String::from_utf8(out.stdout).unwrap();
    for name in [
        "paper-b3.5",
        "paper-b4.4",
        "paper-b4.9",
        "flat-table",
        "critical",
        "unequal-speeds",
        "inelastic",
        "steel-and-glass",
    ] {
        assert!(
            text.lines().any(|l| l.starts_with(name)),
            "{name} missing from\n{text}"
        );
    }
}

#[test]
fn a_closed_pipe_is_not_an_error() {
    let mut child = Command::new(env!("CARGO_BIN_EXE_groovelab"))
        .args(["simulate", "--sample", "1e-5"])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    drop(child.stdout.take());
    let out = child.wait_with_output().unwrap();
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}

#[test]
fn same_input_same_bytes() {
    let a = groovelab(&["simulate", "--preset", "unequal-speeds", "--format", "json"]);
    let b = groovelab(&["simulate", "--preset", "unequal-speeds", "--format", "json"]);
    assert!(a.stdout == b.stdout, "two runs differ");
}

#[test]
fn the_app_without_a_terminal_points_to_render_and_simulate() {
    // Under `cargo test` stdout is a pipe.
    for args in [&[][..], &["tui"][..]] {
        let out = groovelab(args);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{stderr}");
        assert!(out.stdout.is_empty());
        assert!(stderr.starts_with("error: "));
        assert!(stderr.contains("groovelab render") && stderr.contains("groovelab simulate"));
    }
    // Bad scene options are still reported as such first.
    assert_rejected(&["--width", "1m"], "b < 2R");
}

#[test]
fn render_prints_the_screen_as_plain_text() {
    let args = [
        "render",
        "--at",
        "150ms",
        "--size",
        "100x30",
        "--preset",
        "paper-b3.5",
    ];
    let out = groovelab(&args);
    assert!(out.status.success());
    let text = String::from_utf8(out.stdout).unwrap();
    assert_eq!(text.lines().count(), 30);
    assert!(text.lines().all(|l| l.chars().count() <= 100));
    assert!(!text.contains('\x1b'), "no escape codes");
    assert!(text.contains("t = 0.150 s"));
    let again = groovelab(&args);
    assert!(again.stdout == text.as_bytes(), "same input, same bytes");
    let ascii = groovelab(&["render", "--ascii", "--keys", "down down right"]);
    assert!(ascii.status.success());
    assert!(ascii.stdout.is_ascii());
    assert!(
        String::from_utf8_lossy(&ascii.stdout).contains("168.0 g"),
        "m right + 1 g"
    );
}

/// `args` run in this process as `main` runs them: exit status, stdout, stderr.
fn dispatched(args: &[&str]) -> (u8, String, String) {
    let words: Vec<std::ffi::OsString> = std::iter::once("groovelab")
        .chain(args.iter().copied())
        .map(Into::into)
        .collect();
    match groovelab::cli::entry::dispatch(&words) {
        groovelab::cli::entry::Entry::Exit(e) => (e.code, e.stdout, e.stderr),
        groovelab::cli::entry::Entry::Interactive { .. } => panic!("{args:?} opened the app"),
    }
}

/// Each command's `--help` lists the global options it takes and none it refuses
/// (clap lists every global option under every command: `presets --help` listed 31),
/// as docs/interface.md says which take what: a scene (`--preset`, `--mass`), data
/// (`--data`, `--time-unit`, the tracker's `--fps`, `--roi`, `--ball-at`,
/// `--scale`), the drawing (`--ascii`, `--theme`); `track`, and `data` on a video,
/// take R (`--preset`, `--radius`) and no other scene option; `data` takes its files
/// as arguments, not `--data`. One left out of a command's help is still refused by
/// name when given, never ignored.
#[test]
fn each_commands_help_lists_the_global_options_it_takes() {
    let scene = ["--preset", "--radius", "--mass"];
    // `--data` and the options read with it (the tracker's among them).
    let data = [
        "--data",
        "--time-unit",
        "--fps",
        "--roi",
        "--ball-at",
        "--scale",
    ];
    let drawing = ["--ascii", "--theme"];
    let options = [&scene[..], &data, &drawing].concat();
    let scene_and_data = [&scene[..], &data].concat();
    // R (`--preset`, `--radius`) for a video's scale; a track's or a file's options.
    let data_command = [&scene[..2], &data[1..]].concat();
    // R, and the tracker's own options (`--fps`, `--roi`, `--ball-at`, `--scale`).
    let track = [&scene[..2], &data[2..]].concat();
    let takes: &[(&str, &[&str])] = &[
        ("tui", &options),
        ("render", &options),
        ("simulate", &scene),
        ("sweep", &scene),
        ("compare", &scene_and_data),
        ("fit", &scene_and_data),
        ("track", &track),
        ("data", &data_command),
        ("presets", &[]),
        ("manpage", &[]),
        ("completions", &[]),
    ];
    for (command, taken) in takes {
        let (code, help, _) = dispatched(&[command, "--help"]);
        assert_eq!(code, 0, "{command} --help");
        // An option's line: `--name`, then its value's name or its help, if any.
        let listed = |o: &str| {
            help.lines().any(|l| {
                let t = l.trim_start();
                t == o || t.starts_with(&format!("{o} "))
            })
        };
        for &o in &options {
            assert_eq!(
                listed(o),
                taken.contains(&o),
                "{command} --help and {o}:\n{help}"
            );
        }
    }
    // Left out of the help, refused by name when given.
    for args in [
        &["presets", "--mass", "1kg"][..],
        &["simulate", "--data", "x.csv"],
        &["track", "clip.mp4", "--mass", "1kg"],
        &["data", "x.csv", "--data", "y.csv"],
        &["simulate", "--ascii"],
    ] {
        let (code, out, err) = dispatched(args);
        assert_eq!(code, 2, "{args:?}: {err}");
        assert!(
            out.is_empty() && err.contains("is not used by"),
            "{args:?}: {err}"
        );
    }
    // Named as typed: `--mass` (both masses), not the first ball's `--mass-left`.
    for (args, named) in [
        (&["presets", "--mass", "1kg"][..], "--mass is not used"),
        (&["track", "x.mp4", "--v0", "1"], "--v0 is not used"),
        (
            &["track", "x.mp4", "--v0-right", "1"],
            "--v0-right is not used",
        ),
    ] {
        let (_, _, err) = dispatched(args);
        assert!(
            err.starts_with(&format!("error: {named}")),
            "{args:?}: {err}"
        );
    }
    // An unknown option on a command that takes none says so.
    let (code, _, err) = dispatched(&["presets", "--mas", "1"]);
    assert_eq!(code, 2);
    assert!(
        err.contains("`groovelab presets` takes no options"),
        "{err}"
    );
}

/// A file that is not there is said in words with what is allowed, by every command
/// that reads one (the system's "No such file or directory (os error 2)" named no
/// remedy).
#[test]
fn a_missing_file_is_said_with_what_is_allowed() {
    for args in [
        &["data", "/nonexistent-groovelab/x.csv"][..],
        &["fit", "--data", "/nonexistent-groovelab/x.csv"],
        &["fit", "--data", "/nonexistent-groovelab/x.mp4"],
        &[
            "track",
            "/nonexistent-groovelab/x.mp4",
            "--radius",
            "2.75cm",
        ],
    ] {
        let (code, out, err) = dispatched(args);
        assert_eq!(code, 2, "{args:?}: {err}");
        assert!(
            out.is_empty() && err.lines().count() == 1,
            "{args:?}: {err}"
        );
        assert!(
            err.contains("/nonexistent-groovelab/x.")
                && err.contains("no such file, allowed an existing file")
                && !err.contains("os error"),
            "{args:?}: {err}"
        );
    }
}

/// A value and its unit written apart (`--width 4.9 cm`, as quantities are written
/// on paper) left the unit as an unexpected argument, followed by every option of the
/// command; it now says to write them as one word, and how.
#[test]
fn a_unit_written_apart_from_its_value_says_to_join_them() {
    for (args, says) in [
        (
            &["simulate", "--width", "4.9", "cm"][..],
            "write --width 4.9cm",
        ),
        (&["simulate", "--mass", "167", "g"], "write --mass 167g"),
        (&["simulate", "--v0", "0.8", "m/s"], "write --v0 0.8m/s"),
        (&["simulate", "--width=4.9", "cm"], "write --width=4.9cm"),
    ] {
        assert_rejected(
            args,
            &format!(
                "unexpected argument '{}' found; a value and its unit are one word: {says}",
                args[args.len() - 1]
            ),
        );
    }
    // A word that is no unit, or a unit after no finite number (`nancm` is no value
    // either), keeps the list of the command's options.
    for args in [
        &["simulate", "--width", "4.9", "xx"][..],
        &["simulate", "--width", "nan", "cm"],
    ] {
        let out = groovelab(args);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{stderr}");
        assert!(!stderr.contains("one word"), "{stderr}");
        assert!(
            stderr.contains("allowed options of `groovelab simulate`"),
            "{stderr}"
        );
    }
}

/// A radius that leaves the width too wide names itself: `--radius 0.5mm` with the
/// preset's 4.9 cm width said only that the width was out of range, never the
/// radius the user had typed. Found by a new-user trial.
#[test]
fn a_width_too_wide_for_the_radius_given_names_the_radius() {
    for (args, says) in [
        (
            &["simulate", "--radius", "0.5mm"][..],
            "groove width b = 4.9 cm is out of range, allowed 0 ≤ b < 2R = 0.1 cm (R = 0.05 cm from --radius 0.5mm)",
        ),
        (
            &["simulate", "--radius=2cm", "--width", "4.9cm"],
            "allowed 0 ≤ b < 2R = 4 cm (R = 2 cm from --radius 2cm)",
        ),
    ] {
        assert_rejected(args, says);
    }
    // No radius on the line: the message as before.
    let out = groovelab(&["simulate", "--width", "6cm"]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        stderr.trim_end().ends_with("allowed 0 ≤ b < 2R = 5.5 cm"),
        "{stderr}"
    );
}
