//! Issue 10's regressions, of output and stopping: `--output` writes regular files atomically, sweeps stream and stop, ignored options, one-line errors, bounded counts.

use super::*;

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

/// An output that is a file the command reads (the video tracked, the data fitted,
/// the preset), by any name of it (`./`, a hard link), or both outputs of `track`
/// one new file, is refused before any work: one line naming what it is, exit 2,
/// the input as it was. (A new user's `track b.mp4 --output b.mp4` replaced the
/// video with its tracks; `--overlay a.mp4` on `a.mp4` cut it to 9 frames.)
#[test]
fn an_output_never_replaces_a_file_the_command_reads() {
    let dir = scratch("output-inputs");
    let keep = |name: &str| {
        let p = dir.join(name);
        std::fs::write(&p, format!("keep {name}")).unwrap();
        s(&p).to_string()
    };
    let (video, data, preset) = (keep("clip.mp4"), keep("data.csv"), keep("mine.toml"));
    let linked = dir.join("linked.csv");
    std::fs::hard_link(&data, &linked).unwrap();
    let dotted = s(&dir.join(".").join("clip.mp4")).to_string();
    let new = s(&dir.join("new.mp4")).to_string();
    let cases: Vec<(Vec<&str>, &str)> = vec![
        (
            vec!["track", &video, "--radius", "2.75cm", "--output", &video],
            "the video",
        ),
        (
            vec!["track", &video, "--radius", "2.75cm", "--overlay", &dotted],
            "the video",
        ),
        (
            vec![
                "track",
                &video,
                "--radius",
                "2.75cm",
                "--output",
                &new,
                "--overlay",
                &new,
            ],
            "the --overlay file",
        ),
        (
            vec!["fit", "--data", &data, "--output", &data],
            "the data file",
        ),
        (
            vec!["fit", "--data", &data, "--output", s(&linked)],
            "the data file",
        ),
        (
            vec!["simulate", "--preset", &preset, "--output", &preset],
            "the preset file",
        ),
    ];
    for (args, what) in &cases {
        let first = assert_refused(args, "it is also");
        assert!(first.contains(what), "{args:?}: {first}");
    }
    for name in ["clip.mp4", "data.csv", "mine.toml"] {
        let text = std::fs::read_to_string(dir.join(name)).unwrap();
        assert_eq!(text, format!("keep {name}"));
    }
    assert!(!dir.join("new.mp4").exists());
    assert!(temp_files(&dir).is_empty(), "{:?}", temp_files(&dir));
}

/// A picture written inside a folder of frames the command reads (a frame of it, or
/// a new one there) is refused before any work, the frames as they were: a new user's
/// `track fo --overlay fo/base0001.png` replaced a frame with the contact sheet, and
/// `--overlay fo/check.png` made the folder unreadable next time ("no frame
/// number"). A file beside the folder is still written.
#[test]
fn an_output_never_lands_in_a_folder_of_frames_the_command_reads() {
    let dir = scratch("output-in-frames");
    let frames = dir.join("frames");
    let sub = frames.join("sub");
    std::fs::create_dir_all(&sub).unwrap();
    for k in 1..=3 {
        std::fs::write(frames.join(format!("f{k:04}.png")), format!("frame {k}")).unwrap();
    }
    let folder = s(&frames).to_string();
    let inside = |name: &str| s(&frames.join(name)).to_string();
    let (first, new, deeper) = (
        inside("f0001.png"),
        inside("check.PNG"),
        s(&sub.join("t.jpg")).to_string(),
    );
    let cases: Vec<Vec<&str>> = vec![
        vec!["track", &folder, "--fps", "30", "--overlay", &first],
        vec!["track", &folder, "--fps", "30", "--output", &first],
        vec!["track", &folder, "--fps", "30", "--overlay", &new],
        vec!["track", &folder, "--fps", "30", "--output", &deeper],
        vec![
            "fit", "--data", &folder, "--fps", "30", "--radius", "2.75cm", "--output", &new,
        ],
    ];
    for args in &cases {
        let line = assert_refused(args, "lies in the folder of frames");
        assert!(line.contains(&folder), "{args:?}: {line}");
    }
    for k in 1..=3 {
        let text = std::fs::read_to_string(frames.join(format!("f{k:04}.png"))).unwrap();
        assert_eq!(text, format!("frame {k}"));
    }
    assert!(!frames.join("check.PNG").exists() && !sub.join("t.jpg").exists());
    // Beside the folder, or a text file in it (which the folder's reader passes
    // over): past the check (the fake frames then refused).
    let beside = s(&dir.join("t.txt")).to_string();
    let text = inside("tracks.txt");
    let (code, _, err) = crate::common::run(&["track", &folder, "--fps", "30", "--output", &text]);
    assert_eq!(code, 2);
    assert!(!err.contains("lies in the folder"), "{err}");
    let (code, _, err) =
        crate::common::run(&["track", &folder, "--fps", "30", "--output", &beside]);
    assert_eq!(code, 2);
    assert!(!err.contains("lies in the folder"), "{err}");
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
        // A little longer, so rows are being streamed into it (the 2000×1000 map takes
        // seconds; each ms here costs both cores' work).
        std::thread::sleep(Duration::from_millis(50));
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

/// The line fits' standard errors once changed in their last digits from run to run of
/// the same command (a hash map's order in the sums over shared frames): the same
/// `fit` prints the same bytes every time.
#[test]
fn the_same_fit_prints_the_same_bytes_every_run() {
    let args = [
        "fit",
        "--preset",
        "paper-b4.9",
        "--data",
        concat!(env!("CARGO_MANIFEST_DIR"), "/docs/video/ball.txt"),
        "--data",
        concat!(env!("CARGO_MANIFEST_DIR"), "/docs/video/mark.txt"),
        "--format",
        "json",
    ];
    let first = crate::common::stdout(&args);
    assert!(first.contains("\"a_cm_se\""), "{first}");
    assert_eq!(crate::common::stdout(&args), first);
}
