//! Issue 10's regressions, of input: paths that are no regular files, size limits, extreme exponents, CSV headers and units, figures of endless ranges, axis labels of any span.

use super::*;

// Item 3: `--data` and preset files are regular files of sane size.

#[test]
fn data_and_preset_paths_that_are_not_regular_files_fail_at_once() {
    let dir = scratch("nonregular");
    let fifo = dir.join("fifo.csv");
    let made = Command::new("mkfifo").arg(&fifo).status();
    let mut paths = vec!["/dev/zero".to_string(), "/dev/urandom".to_string()];
    paths.push(s(&dir).to_string());
    if made.is_ok_and(|s| s.success()) {
        paths.push(s(&fifo).to_string());
    }
    let limit = Duration::from_secs(10);
    // With an output too, one that exists: it is held against the inputs without
    // opening them (a FIFO's open waits for a writer).
    let out = dir.join("out.txt");
    std::fs::write(&out, "keep").unwrap();
    for p in &paths {
        for args in [
            vec!["fit", "--preset", "paper-b4.9", "--data", p.as_str()],
            vec![
                "fit",
                "--preset",
                "paper-b4.9",
                "--data",
                p.as_str(),
                "--output",
                s(&out),
            ],
            vec!["render", "--data", p.as_str(), "--size", "80x24"],
            vec!["simulate", "--preset", p.as_str()],
        ] {
            let r = groovelab_within(&args, limit);
            assert_eq!(r.code, Some(2), "{args:?}: {}", r.stderr);
            // A folder as `--data` is read as one of frames (it holds none here).
            let says = if args.contains(&"--data") && p == s(&dir) {
                "holds 0 PNG/JPEG frames"
            } else {
                "allowed a regular file"
            };
            assert!(
                r.stderr.starts_with("error: ") && r.stderr.contains(says),
                "{args:?}: {}",
                r.stderr
            );
            assert_eq!(r.stderr.lines().count(), 1, "{args:?}: {}", r.stderr);
        }
    }
    assert_eq!(std::fs::read_to_string(&out).unwrap(), "keep");
}

/// A FIFO or a device named as a video (`fifo.mp4`, a link `zero.mp4` to /dev/zero)
/// given to `data` or `fit --data` is refused in one line at once, as `track`
/// refuses it: a new user's `fit --data fifo.mp4` waited for ever (the track cache
/// opened the FIFO to hash its bytes) and ignored SIGTERM.
#[test]
fn a_fifo_or_device_named_as_a_video_fails_at_once() {
    let dir = scratch("nonregular-video");
    let fifo = dir.join("fifo.mp4");
    let made = Command::new("mkfifo").arg(&fifo).status();
    assert!(made.is_ok_and(|s| s.success()), "mkfifo failed");
    let zero = dir.join("zero.mp4");
    std::os::unix::fs::symlink("/dev/zero", &zero).unwrap();
    for p in [s(&fifo), s(&zero)] {
        for args in [
            vec!["data", p],
            vec!["fit", "--radius", "2.75cm", "--data", p],
            vec!["track", p, "--radius", "2.75cm"],
        ] {
            let r = groovelab_within(&args, Duration::from_secs(20));
            assert_eq!(r.code, Some(2), "{args:?}: {}", r.stderr);
            assert!(
                r.stderr.starts_with("error: ") && r.stderr.contains("is not a regular file"),
                "{args:?}: {}",
                r.stderr
            );
            assert_eq!(r.stderr.lines().count(), 1, "{args:?}: {}", r.stderr);
        }
    }
}

#[test]
fn data_files_over_the_size_limit_are_refused_before_reading() {
    let dir = scratch("big");
    let big = dir.join("big.csv");
    // A sparse file: 64 MiB + 1 byte on disk costs nothing.
    let f = std::fs::File::create(&big).unwrap();
    f.set_len(groovelab::input::MAX_FILE_BYTES + 1).unwrap();
    assert_refused(
        &["fit", "--preset", "paper-b4.9", "--data", s(&big)],
        "at most 67108864 bytes (64 MiB)",
    );
    assert_refused(&["simulate", "--preset", s(&big)], "at most 67108864 bytes");
}

#[test]
fn a_symlink_to_a_regular_data_file_is_followed() {
    let dir = scratch("symlink");
    let real = dir.join("real.csv");
    std::fs::write(&real, GOOD_CSV).unwrap();
    let link = dir.join("link.csv");
    std::os::unix::fs::symlink(&real, &link).unwrap();
    let r = groovelab(&[
        "fit",
        "--preset",
        "paper-b4.9",
        "--data",
        s(&link),
        "--format",
        "json",
    ]);
    assert_eq!(r.code, Some(0), "{}", r.stderr);
}

// Item 11: extreme exponents.

#[test]
fn extreme_exponents_are_out_of_range_errors() {
    assert_refused(
        &[
            "simulate",
            "--sample",
            "1e-2147483648ms",
            "--format",
            "json",
        ],
        "out of range",
    );
    assert_refused(&["simulate", "--radius", "1e-2147483648cm"], "out of range");
    assert_refused(&["simulate", "--width", "1e-2147483649"], "out of range");
    assert_refused(&["simulate", "--t-end", "1e-400"], "out of range");
    let dir = scratch("exponent");
    let p = dir.join("p.toml");
    std::fs::write(
        &p,
        "name = \"x\"\ndescription = \"d\"\n[scene]\nradius = \"1e-2147483648cm\"\n",
    )
    .unwrap();
    assert_refused(&["simulate", "--preset", s(&p)], "out of range");
}

// Item 13: CSV headers and unit options.

#[test]
fn csv_column_names_with_digits_are_not_units() {
    let dir = scratch("headers");
    for header in ["t2", "t_1", "time0"] {
        let p = dir.join(format!("{header}.csv"));
        let body = GOOD_CSV.split_once('\n').unwrap().1;
        std::fs::write(&p, format!("{header},v_cm,v_t\n{body}")).unwrap();
        assert_refused(
            &["fit", "--preset", "paper-b4.9", "--data", s(&p)],
            "no column 't'",
        );
    }
}

#[test]
fn unit_options_take_unit_names_only() {
    let dir = scratch("unitopts");
    let p = dir.join("d.csv");
    std::fs::write(
        &p,
        GOOD_CSV.replace("t_s,v_cm_m_per_s,v_t_m_per_s", "t,v_cm,v_t"),
    )
    .unwrap();
    for (flag, unit) in [
        ("--time-unit", "e5"),
        ("--time-unit", "0"),
        ("--speed-unit", "7"),
        ("--speed-unit", "1e300"),
    ] {
        assert_refused(
            &["fit", "--preset", "paper-b4.9", "--data", s(&p), flag, unit],
            "unknown unit",
        );
    }
    let r = groovelab(&[
        "fit",
        "--preset",
        "paper-b4.9",
        "--data",
        s(&p),
        "--time-unit",
        "s",
        "--speed-unit",
        "m/s",
    ]);
    assert_eq!(r.code, Some(0), "{}", r.stderr);
}

#[test]
fn a_utf8_byte_order_mark_does_not_hide_the_header() {
    let dir = scratch("bom");
    let p = dir.join("bom.csv");
    std::fs::write(&p, format!("\u{feff}{GOOD_CSV}")).unwrap();
    let with = groovelab(&[
        "fit",
        "--preset",
        "paper-b4.9",
        "--data",
        s(&p),
        "--format",
        "json",
    ]);
    assert_eq!(with.code, Some(0), "{}", with.stderr);
    let q = dir.join("plain.csv");
    std::fs::write(&q, GOOD_CSV).unwrap();
    let without = groovelab(&[
        "fit",
        "--preset",
        "paper-b4.9",
        "--data",
        s(&q),
        "--format",
        "json",
    ]);
    // The same but for the file named as the data's source.
    let json = |out: &str| {
        let mut j: serde_json::Value = serde_json::from_str(out).unwrap();
        j["sources"]["data"] = serde_json::Value::Null;
        j
    };
    assert_eq!(json(&with.stdout), json(&without.stdout));
}

// Items 1 and 2: figures never loop on infinite or empty ranges.

/// The run ends in time with exit 0 (an SVG on stdout) or 2 (one `error:` line).
fn assert_svg_or_one_error(args: &[&str]) {
    let r = groovelab_within(args, Duration::from_secs(30));
    match r.code {
        Some(0) => assert!(r.stdout.starts_with("<svg"), "{args:?}"),
        Some(2) => {
            assert!(r.stdout.is_empty(), "{args:?}");
            assert!(r.stderr.starts_with("error: "), "{args:?}: {}", r.stderr);
            assert_eq!(r.stderr.lines().count(), 1, "{args:?}: {}", r.stderr);
            assert!(
                !r.stderr.contains("NaN") && !r.stderr.contains("= inf"),
                "{}",
                r.stderr
            );
        }
        other => panic!("{args:?}: exit {other:?}: {}", r.stderr),
    }
}

#[test]
fn compare_exact_alone_as_svg_is_an_error_not_a_hang() {
    assert_refused(
        &["compare", "--methods", "exact", "--format", "svg"],
        "no time-stepping run",
    );
}

#[test]
fn fit_figures_of_overflowing_scenes_or_data_end() {
    assert_svg_or_one_error(&["fit", "--format", "svg", "--v0", "1e308"]);
    assert_svg_or_one_error(&["fit", "--v0", "1e308"]);
    let dir = scratch("fitsvg");
    // inf in a preset's measured v_cm is refused when the preset is read.
    let p = dir.join("inf.toml");
    std::fs::write(
        &p,
        "name = \"x\"\ndescription = \"d\"\n[scene]\n[measured]\nt = [-0.02, 0.0, 0.02, 0.04]\nv_cm = [0.8, inf, -0.6, -0.6]\nv_t = [0.8, 0.8, 0.7, 0.7]\n",
    )
    .unwrap();
    assert_refused(&["fit", "--format", "svg", "--preset", s(&p)], "not finite");
    // Huge but finite measured speeds: a figure or one error, in time.
    let q = dir.join("huge.csv");
    std::fs::write(
        &q,
        GOOD_CSV
            .replace("-0.63", "-1e308")
            .replace("0.79,", "1e300,"),
    )
    .unwrap();
    assert_svg_or_one_error(&[
        "fit",
        "--preset",
        "paper-b4.9",
        "--format",
        "svg",
        "--data",
        s(&q),
    ]);
    assert_svg_or_one_error(&[
        "fit",
        "--preset",
        "paper-b4.9",
        "--format",
        "svg",
        "--data",
        s(&q),
        "--v0",
        "1e300",
    ]);
}

// Item 6: the charts' axis labels never panic, whatever the span.

fn render_in_process(args: &[&str]) -> Result<String, String> {
    use clap::Parser;
    let mut full = vec!["groovelab", "render"];
    full.extend_from_slice(args);
    let cli = groovelab::cli::Cli::try_parse_from(&full).map_err(|e| e.to_string())?;
    match groovelab::cli::run(&cli) {
        Ok(groovelab::cli::Response::Print(text)) => Ok(text),
        Ok(_) => Err("render gave no text".into()),
        Err(e) => Err(e.to_string()),
    }
}

#[test]
fn render_of_huge_or_tiny_spans_does_not_panic() {
    let dir = scratch("spans");
    let p = dir.join("long.toml");
    std::fs::write(
        &p,
        "name = \"long\"\ndescription = \"d\"\n[scene]\nt_end = 1e300\n",
    )
    .unwrap();
    let cases: Vec<Vec<&str>> = vec![
        vec!["--t-end", "1e38"],
        vec!["--t-start", "-1e308"],
        vec!["--t-start", "-1e308", "--t-end", "1e308"],
        vec!["--preset", s(&p)],
        vec!["--preset", "flat-table", "--mu", "1e-300"],
        vec!["--preset", "flat-table", "--mu", "1e-300", "--keys", "x"],
        vec!["--t-end", "1e-300"],
        // Overflowing energies: shares once overflowed u32, the methods view once
        // asked for 2^31 decade ticks (64 GB).
        vec!["--mass-right", "1e308"],
        vec!["--mass-right", "1e308", "--keys", "c"],
        vec!["--mass-right", "1e308", "--keys", "g"],
    ];
    for case in &cases {
        for size in ["80x24", "120x40", "12x4", "20x8"] {
            let mut args = case.clone();
            args.extend(["--size", size]);
            // Each must give a screen, or (once the parameter ranges tighten) one
            // error line, never a panic.
            let got = std::panic::catch_unwind(|| render_in_process(&args));
            match got {
                Ok(Ok(text)) => {
                    let (w, h) = size.split_once('x').unwrap();
                    assert_eq!(
                        text.lines().count(),
                        h.parse::<usize>().unwrap(),
                        "{args:?}"
                    );
                    assert!(
                        text.lines()
                            .all(|l| l.chars().count() <= w.parse::<usize>().unwrap()),
                        "{args:?}"
                    );
                }
                Ok(Err(e)) => assert!(!e.contains('\n') || e.starts_with("error"), "{args:?}: {e}"),
                Err(_) => panic!("render {args:?} panicked"),
            }
        }
    }
}

#[test]
fn typing_a_tiny_friction_in_the_app_does_not_panic() {
    // flat-table, select μ_k, Enter, type 1e-300, Enter (the app path).
    let keys = "down down down enter 1 e - 3 0 0 enter";
    for size in ["80x24", "120x40"] {
        let got = std::panic::catch_unwind(|| {
            render_in_process(&["--preset", "flat-table", "--keys", keys, "--size", size])
        });
        let screen = got
            .unwrap_or_else(|_| panic!("panicked at {size}"))
            .unwrap();
        assert!(screen.contains("μ_k       1.000e-300"), "{screen}");
    }
}
