//! Regression tests of issue 10 (reliability): hostile input never hangs, panics,
//! fills memory, leaves files behind or yields inf/NaN; each test is named after
//! what it guards.

use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// What a run of the binary gave.
struct Ran {
    code: Option<i32>,
    stdout: String,
    stderr: String,
}

/// Runs the binary with no stdin; a run longer than `limit` is killed and fails the
/// test (these are the hangs of issue 10).
fn groovelab_within(args: &[&str], limit: Duration) -> Ran {
    let mut child = Command::new(env!("CARGO_BIN_EXE_groovelab"))
        .args(args)
        .env("GROOVELAB_PRESETS", "/nonexistent-groovelab-presets")
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let start = Instant::now();
    // Read the pipes on threads so a chatty child cannot block on a full pipe.
    let mut out = child.stdout.take().unwrap();
    let mut err = child.stderr.take().unwrap();
    let out = std::thread::spawn(move || {
        let mut s = Vec::new();
        std::io::Read::read_to_end(&mut out, &mut s).unwrap();
        s
    });
    let err = std::thread::spawn(move || {
        let mut s = Vec::new();
        std::io::Read::read_to_end(&mut err, &mut s).unwrap();
        s
    });
    loop {
        if let Some(status) = child.try_wait().unwrap() {
            return Ran {
                code: status.code(),
                stdout: String::from_utf8_lossy(&out.join().unwrap()).into_owned(),
                stderr: String::from_utf8_lossy(&err.join().unwrap()).into_owned(),
            };
        }
        if start.elapsed() > limit {
            let _ = child.kill();
            let _ = child.wait();
            panic!("{args:?} still running after {limit:?}");
        }
        std::thread::sleep(Duration::from_millis(20));
    }
}

fn groovelab(args: &[&str]) -> Ran {
    groovelab_within(args, Duration::from_secs(30))
}

/// Exit 2, nothing on stdout, one `error:` line that mentions `mentions`.
fn assert_refused(args: &[&str], mentions: &str) -> String {
    let r = groovelab(args);
    assert_eq!(r.code, Some(2), "{args:?}: {}", r.stderr);
    assert!(r.stdout.is_empty(), "{args:?} printed {}", r.stdout);
    let first = r.stderr.lines().next().unwrap_or("");
    assert!(first.starts_with("error: "), "{args:?}: {}", r.stderr);
    assert!(
        first.contains(mentions),
        "{args:?}: {first:?} lacks {mentions:?}"
    );
    for bad in ["= inf", "= -inf", " inf ", "NaN", "panicked"] {
        assert!(!first.contains(bad), "{args:?}: {first:?} says {bad}");
    }
    first.to_string()
}

/// A fresh scratch directory for one test.
fn scratch(test: &str) -> PathBuf {
    crate::common::scratch_dir("reliability", test)
}

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

/// A measured series in the shared CSV format (paper-b4.9's first frames).
const GOOD_CSV: &str = "t_s,v_cm_m_per_s,v_t_m_per_s\n-0.04,0.80,0.79\n-0.02,0.79,0.78\n0,0.0925,0.78\n0.02,-0.64,0.70\n0.04,-0.63,0.68\n0.06,-0.60,0.64\n0.08,-0.57,0.60\n";

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
    for p in &paths {
        for args in [
            vec!["fit", "--preset", "paper-b4.9", "--data", p.as_str()],
            vec!["render", "--data", p.as_str(), "--size", "80x24"],
            vec!["simulate", "--preset", p.as_str()],
        ] {
            let r = groovelab_within(&args, limit);
            assert_eq!(r.code, Some(2), "{args:?}: {}", r.stderr);
            assert!(
                r.stderr.starts_with("error: ") && r.stderr.contains("allowed a regular file"),
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

// Item 9: `--output` writes only regular files, atomically, keeping their mode.

fn temp_files(dir: &Path) -> Vec<String> {
    std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n.ends_with(".tmp"))
        .collect()
}

#[test]
fn output_refuses_devices_fifos_symlinks_and_directories() {
    let dir = scratch("output-targets");
    let real = dir.join("real.json");
    std::fs::write(&real, "keep").unwrap();
    let link = dir.join("link.json");
    std::os::unix::fs::symlink(&real, &link).unwrap();
    let fifo = dir.join("fifo.json");
    let has_fifo = Command::new("mkfifo")
        .arg(&fifo)
        .status()
        .is_ok_and(|s| s.success());
    let mut cases = vec![
        ("/dev/null".to_string(), "a device"),
        (s(&link).to_string(), "a symlink"),
        (s(&dir).to_string(), "a directory"),
    ];
    if has_fifo {
        cases.push((s(&fifo).to_string(), "a FIFO"));
    }
    for (target, kind) in &cases {
        for args in [
            vec!["fit", "--format", "json", "--output", target.as_str()],
            vec!["compare", "--methods", "euler", "--output", target.as_str()],
            vec!["simulate", "--format", "csv", "--output", target.as_str()],
            vec!["render", "--size", "80x24", "--output", target.as_str()],
            vec![
                "sweep",
                "--x",
                "width=0..5cm",
                "--grid",
                "3",
                "--output",
                target.as_str(),
            ],
        ] {
            let first = assert_refused(&args, kind);
            assert!(
                first.contains("allowed a regular file or a new path"),
                "{first}"
            );
        }
    }
    assert_eq!(std::fs::read_to_string(&real).unwrap(), "keep");
    assert!(
        std::fs::symlink_metadata(&link)
            .unwrap()
            .file_type()
            .is_symlink()
    );
    assert!(temp_files(&dir).is_empty(), "{:?}", temp_files(&dir));
}

#[test]
fn output_keeps_the_mode_of_a_replaced_file() {
    use std::os::unix::fs::PermissionsExt;
    let dir = scratch("output-mode");
    let out = dir.join("fit.json");
    std::fs::write(&out, "old").unwrap();
    std::fs::set_permissions(&out, std::fs::Permissions::from_mode(0o640)).unwrap();
    let r = groovelab(&["fit", "--format", "json", "--output", s(&out)]);
    assert_eq!(r.code, Some(0), "{}", r.stderr);
    assert_eq!(r.stdout, format!("wrote {}\n", out.display()));
    let text = std::fs::read_to_string(&out).unwrap();
    assert!(text.starts_with('{'), "{text}");
    let mode = std::fs::metadata(&out).unwrap().permissions().mode() & 0o7777;
    assert_eq!(mode, 0o640);
    assert!(temp_files(&dir).is_empty());
}

/// Issue 19: `simulate` and `render` take `--output` like the other commands: the same
/// bytes as on stdout, written atomically, and a line saying where.
#[test]
fn simulate_and_render_write_their_output_to_a_file() {
    let dir = scratch("output-simulate-render");
    for (args, name) in [
        (vec!["simulate", "--format", "json"], "run.json"),
        (
            vec!["simulate", "--format", "csv", "--sample", "10ms"],
            "run.csv",
        ),
        (
            vec!["render", "--size", "80x24", "--at", "0.1"],
            "screen.txt",
        ),
    ] {
        let out = dir.join(name);
        let printed = groovelab(&args);
        assert_eq!(printed.code, Some(0), "{}", printed.stderr);
        let mut with = args.clone();
        with.extend(["--output", s(&out)]);
        let r = groovelab(&with);
        assert_eq!(r.code, Some(0), "{}", r.stderr);
        assert_eq!(r.stdout, format!("wrote {}\n", out.display()));
        assert_eq!(
            std::fs::read_to_string(&out).unwrap(),
            printed.stdout,
            "{args:?}"
        );
    }
    // A bad scene is refused before anything is written.
    let out = dir.join("never.csv");
    let r = groovelab(&["simulate", "--mu", "-1", "--output", s(&out)]);
    assert_eq!(r.code, Some(2));
    assert!(!out.exists());
    assert!(temp_files(&dir).is_empty());
}

// Items 4 and 10: a sweep streams with bounded memory, and a stop signal before the
// output is committed means exit 130 and nothing written.

fn sweep_args(extra: &[&str]) -> groovelab::cli::Cli {
    use clap::Parser;
    let mut full = vec![
        "groovelab",
        "sweep",
        "--x",
        "width=0..5cm",
        "--y",
        "restitution=0.3..1",
    ];
    full.extend_from_slice(extra);
    groovelab::cli::Cli::try_parse_from(&full).unwrap()
}

fn sweep_in_process(
    cli: &groovelab::cli::Cli,
    stop: bool,
) -> Result<String, groovelab::cli::CliError> {
    let Some(groovelab::cli::Command::Sweep(args)) = &cli.command else {
        unreachable!()
    };
    let flag = std::sync::atomic::AtomicBool::new(stop);
    groovelab::cli::sweep_with_stop(&cli.scene, args, &flag)
}

#[test]
fn a_stopped_sweep_writes_nothing_to_stdout_or_a_file() {
    let dir = scratch("sweep-stop");
    let out = dir.join("map.csv");
    for format in ["csv", "json", "svg"] {
        let cli = sweep_args(&["--grid", "20x10", "--format", format]);
        assert!(matches!(
            sweep_in_process(&cli, true),
            Err(groovelab::cli::CliError::Interrupted)
        ));
        let cli = sweep_args(&["--grid", "20x10", "--format", format, "--output", s(&out)]);
        assert!(matches!(
            sweep_in_process(&cli, true),
            Err(groovelab::cli::CliError::Interrupted)
        ));
        assert!(!out.exists());
        assert!(temp_files(&dir).is_empty(), "{:?}", temp_files(&dir));
    }
    // Not stopped: the same call writes the file.
    let cli = sweep_args(&["--grid", "20x10", "--output", s(&out)]);
    assert_eq!(
        sweep_in_process(&cli, false).unwrap(),
        format!("wrote {}\n", out.display())
    );
    assert_eq!(std::fs::read_to_string(&out).unwrap().lines().count(), 201);
}

#[test]
fn a_streamed_sweep_equals_the_whole_map() {
    // CSV and JSON are written batch by batch; they must be what the whole map gives.
    use groovelab::study::sweep;
    let base = groovelab::input::preset::load("paper-b4.9").unwrap().spec;
    let x = sweep::parse_axis("width=0..5cm", 181).unwrap();
    let y = sweep::parse_axis("restitution=0.3..1", 97).unwrap();
    let stop = std::sync::atomic::AtomicBool::new(false);
    let points = sweep::run(&base, &x, Some(&y), &stop, &|| {}).unwrap();
    assert!(points.len() > sweep::BATCH, "the test spans batches");
    let cli = sweep_args(&["--grid", "181x97", "--format", "json"]);
    let json = sweep_in_process(&cli, false).unwrap();
    // What the command wrote before streaming: one serde_json document.
    #[derive(serde::Serialize)]
    struct Whole<'a> {
        x: &'a sweep::SweepAxis,
        y: Option<&'a sweep::SweepAxis>,
        points: &'a [sweep::GridPoint],
    }
    let whole = Whole {
        x: &x,
        y: Some(&y),
        points: &points,
    };
    let want = format!("{}\n", serde_json::to_string(&whole).unwrap());
    assert!(
        json == want,
        "the streamed JSON differs from the whole document"
    );
    let cli = sweep_args(&["--grid", "181x97"]);
    let csv = sweep_in_process(&cli, false).unwrap();
    let rows: Vec<&str> = csv.lines().skip(1).collect();
    assert_eq!(rows.len(), points.len());
    for (row, p) in rows.iter().zip(&points).step_by(997) {
        assert!(
            row.starts_with(&format!("{},{},{},", p.x, p.y.unwrap(), p.regime.name())),
            "{row}"
        );
    }
}

#[test]
fn huge_sweeps_are_refused_on_stdout_and_svg_before_any_work() {
    // Refused from the arguments alone: exit 2 and nothing printed (a 10^8-point
    // sweep that started would run into the command's watchdog).
    assert_refused(
        &[
            "sweep",
            "--x",
            "width=0..5cm",
            "--y",
            "restitution=0.3..1",
            "--grid",
            "10000x10000",
        ],
        "allowed at most 256 MiB on stdout; write it with --output FILE",
    );
    assert_refused(
        &[
            "sweep",
            "--x",
            "width=0..5cm",
            "--y",
            "restitution=0.3..1",
            "--grid",
            "1001x10",
            "--format",
            "svg",
        ],
        "allowed at most 1000x1000",
    );
}

#[test]
fn sigint_or_sigterm_during_a_sweep_to_a_file_leaves_nothing() {
    for signal in ["-INT", "-TERM"] {
        let dir = scratch(&format!("sweep-signal{signal}"));
        let out = dir.join("map.csv");
        let mut child = Command::new(env!("CARGO_BIN_EXE_groovelab"))
            .args(["sweep", "--x", "width=0..5cm", "--y", "restitution=0.3..1"])
            .args(["--grid", "2000x1000", "--output", s(&out)])
            .stdin(Stdio::null())
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .unwrap();
        // Wait for the temporary file: the work and the writing have started.
        let start = Instant::now();
        while temp_files(&dir).is_empty() {
            assert!(
                start.elapsed() < Duration::from_secs(30),
                "no temp file appeared"
            );
            std::thread::sleep(Duration::from_millis(10));
        }
        std::thread::sleep(Duration::from_millis(200));
        let killed = Command::new("kill")
            .args([signal, &child.id().to_string()])
            .status()
            .unwrap();
        assert!(killed.success());
        let start = Instant::now();
        let status = loop {
            if let Some(status) = child.try_wait().unwrap() {
                break status;
            }
            assert!(start.elapsed() < Duration::from_secs(30), "did not stop");
            std::thread::sleep(Duration::from_millis(20));
        };
        let mut err = String::new();
        std::io::Read::read_to_string(&mut child.stderr.take().unwrap(), &mut err).unwrap();
        assert_eq!(status.code(), Some(130), "{signal}: {err}");
        assert_eq!(err, "error: interrupted: nothing was written\n");
        assert!(!out.exists());
        assert!(temp_files(&dir).is_empty(), "{:?}", temp_files(&dir));
    }
}

#[test]
fn a_stop_after_the_last_point_is_computed_still_writes_nothing() {
    // Once, Ctrl-C after the computation had finished was ignored (exit 0, file
    // written). Now a stop at any time before the commit wins.
    use groovelab::study::sweep;
    use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
    let base = groovelab::input::preset::load("paper-b4.9").unwrap().spec;
    let x = sweep::parse_axis("width=0..5cm", 40).unwrap();
    let stop = AtomicBool::new(false);
    let done = AtomicUsize::new(0);
    let tick = || {
        if done.fetch_add(1, Ordering::SeqCst) + 1 == 40 {
            stop.store(true, Ordering::SeqCst);
        }
    };
    assert_eq!(
        sweep::run(&base, &x, None, &stop, &tick),
        Err(sweep::SweepError::Interrupted)
    );
    assert_eq!(done.load(Ordering::SeqCst), 40, "every point was computed");
}

/// Item 14: an option that a command (or its method) would ignore is an error.
#[test]
fn options_a_command_would_ignore_are_errors() {
    for (args, mentions) in [
        (
            &["presets", "--width", "7cm", "--preset", "/nonexistent"][..],
            "not used by presets",
        ),
        (
            &["sweep", "--ascii", "--x", "width=0..5cm"][..],
            "--ascii is not used by sweep",
        ),
        (
            &["sweep", "--data", "x.csv", "--x", "width=0..5cm"][..],
            "--data is not used by sweep",
        ),
        (
            &["simulate", "--time-unit", "ms"][..],
            "--time-unit is not used by simulate",
        ),
        (&["fit", "--time-unit", "ms"][..], "none is given"),
        // track takes R for the scale, and nothing else of the scene.
        (
            &["track", "clip.mp4", "--width", "4cm"][..],
            "--width is not used by track",
        ),
        (
            &["track", "clip.mp4", "--radius", "2cm", "--g", "1.62"][..],
            "--g is not used by track",
        ),
        (
            &["simulate", "--dt", "1ms"][..],
            "--dt is not used by the exact method",
        ),
        (
            &["simulate", "--tol", "1e-3"][..],
            "--tol is not used by the exact method",
        ),
        (
            &["simulate", "--method", "euler", "--tol", "1e-3"][..],
            "only with --method rk45",
        ),
        (
            &["simulate", "--method", "rk45", "--epsilon", "1mm/s"][..],
            "only with --method rk4",
        ),
        (
            &["simulate", "--method", "euler", "--dt", "1e-12"][..],
            "cannot run this span",
        ),
    ] {
        assert_refused(args, mentions);
    }
}

/// Item 15: every error is one line, and what it prints is what was given.
#[test]
fn errors_are_one_line_and_values_are_shown_as_given() {
    for (args, mentions) in [
        (
            &["simulate", "--height", "10cm", "--v0", "0.6"][..],
            "cannot be used with",
        ),
        (&["simulate", "--radius", "abc"][..], "not a number"),
        (&["simulate", "--format", "xml"][..], "possible values"),
        (&["sweep"][..], "--x"),
        (&["simulate", "--v0", "1\ncm"][..], "unknown unit"),
        (&["simulate", "--preset", "a\nb"][..], "a\\nb"),
        (
            &["simulate", "--restitution", "1.0000001"][..],
            "e = 1.0000001 is out of range",
        ),
        (
            &["simulate", "--method", "rk45", "--tol", "1e-300"][..],
            "--tol 1e-300 is",
        ),
        (
            &["simulate", "--sample", "1e-6", "--t-end", "1"][..],
            "gives 1200001 samples",
        ),
    ] {
        let r = groovelab(args);
        assert_eq!(r.stderr.lines().count(), 1, "{args:?}: {}", r.stderr);
        assert_refused(args, mentions);
    }
}

/// Item 15: the summary counts the impacts inside the span shown, not after `--t-end`.
#[test]
fn the_impact_count_stops_at_t_end() {
    let all = groovelab(&["simulate", "--preset", "paper-b4.4", "--format", "json"]);
    let cut = groovelab(&[
        "simulate",
        "--preset",
        "paper-b4.4",
        "--t-end",
        "0.5",
        "--format",
        "json",
    ]);
    let impacts = |out: &str| -> u64 {
        let doc: serde_json::Value = serde_json::from_str(out).unwrap();
        doc["summary"]["impacts"].as_u64().unwrap()
    };
    let collisions = |out: &str| -> u64 {
        let doc: serde_json::Value = serde_json::from_str(out).unwrap();
        let events = doc["events"].as_array().unwrap();
        events.iter().filter(|e| e["kind"] == "collision").count() as u64
    };
    assert_eq!(impacts(&all.stdout), 9);
    assert_eq!(impacts(&cut.stdout), collisions(&cut.stdout));
    assert!(impacts(&cut.stdout) < 9);
}

/// Found by the long fuzz run: a finite but absurd measured speed (1e306 m/s) made
/// the residuals' squares overflow ("RMS residual inf" on screen).
#[test]
fn measured_values_beyond_lab_sizes_are_refused() {
    let dir = scratch("magnitudes");
    let p = dir.join("d.csv");
    std::fs::write(
        &p,
        "t [ms]\tv_cm_cm_per_s\tvt\n-0.2000\t1e308\t0.3239\n-0.1114\t0.3239\t0.3239\n-0.0228\t0.3239\t0.3239\n",
    )
    .unwrap();
    let p = p.to_str().unwrap();
    for cmd in ["render", "fit"] {
        assert_refused(
            &[
                cmd,
                "--preset",
                "paper-b4.9",
                "--data",
                p,
                // Within the file's times (an impact after them is refused
                // naming --impact-at).
                "--impact-at",
                "-0.1ms",
            ],
            "allowed |v_cm| ≤ 1000 m/s",
        );
    }
    let preset = dir.join("p.toml");
    std::fs::write(
        &preset,
        "name = \"x\"\ndescription = \"d\"\n[scene]\n[measured]\nt = [0.0, 0.01, 2e6]\nv_cm = [1.0, 1.0, 1.0]\nv_t = [1.0, 1.0, 1.0]\n",
    )
    .unwrap();
    assert_refused(
        &["simulate", "--preset", preset.to_str().unwrap()],
        "allowed |t| ≤ 1e6 s",
    );
}
