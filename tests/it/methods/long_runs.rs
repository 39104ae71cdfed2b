//! Long analyses are bounded and can be stopped: `compare` covers at most its window
//! of simulated time (saying where it cut the span) and skips levels over a smaller
//! step budget (saying why), `fit` thins a long series to at most `MAX_MODEL_POINTS`, both
//! stop soon after a `Progress` asks and give the same result as before when it never
//! does; Ctrl-C on the command line exits 130 and writes nothing.

use std::process::{Command, Stdio};
use std::sync::atomic::{AtomicU64, Ordering};
use std::time::Duration;

use groovelab::methods::{Method, Stepping};
use groovelab::physics::scene::{Scene, Span};
use groovelab::study::measured::Measured;
use groovelab::study::{Cancelled, Progress, Quiet, compare, fit};

/// Counts ticks and asks to stop once `after` of them have passed; counts the looks at
/// the stop that came after it was asked (a run looks once every few thousand steps,
/// so they count the work done after the stop).
struct StopAfter {
    ticks: AtomicU64,
    after: u64,
    looks_after_stop: AtomicU64,
}

impl Progress for StopAfter {
    fn tick(&self, _done: u64, _total: u64) {
        self.ticks.fetch_add(1, Ordering::Relaxed);
    }
    fn cancelled(&self) -> bool {
        let stop = self.ticks.load(Ordering::Relaxed) >= self.after;
        if stop {
            self.looks_after_stop.fetch_add(1, Ordering::Relaxed);
        }
        stop
    }
}

fn stop_after(after: u64) -> StopAfter {
    StopAfter {
        ticks: AtomicU64::new(0),
        after,
        looks_after_stop: AtomicU64::new(0),
    }
}

fn paper() -> (groovelab::physics::scene::Scene, Span, Measured) {
    let preset = groovelab::input::preset::load("paper-b4.9").unwrap();
    let (scene, span) = preset.spec.resolve().unwrap();
    (scene, span, preset.measured.unwrap())
}

#[test]
fn compare_skips_levels_over_its_budget_and_says_why() {
    let (scene, span, _) = paper();
    // A small budget (the settings' own step budget lowers compare's) on the paper's
    // 1.2 s span: h = 1e-4 s and finer need over 10 000 steps and are skipped unrun.
    let base = Stepping {
        max_steps: 10_000,
        ..Stepping::default()
    };
    let rows = compare::sweep(
        &scene,
        &span,
        &[Method::Exact, Method::Euler],
        &base,
        &Quiet,
    )
    .unwrap();
    let skipped: Vec<_> = rows
        .iter()
        .filter(|r| {
            r.note
                .is_some_and(|n| n.to_string().starts_with("skipped:"))
        })
        .collect();
    // 10^-4, 10^-4.5, 10^-5, 10^-5.5 and 10^-6 s.
    assert_eq!(skipped.len(), 5, "{rows:#?}");
    for r in &skipped {
        assert_eq!(r.status, compare::RunStatus::Stalled);
        assert_eq!(r.steps, 0);
        let note = r.note.unwrap().to_string();
        assert!(
            note.contains("over the budget of 10000 steps per run"),
            "{note}"
        );
    }
    assert!(rows.iter().all(|r| r.steps <= 10_000));
}

/// The steps of one run of every fixed-step method at each step `h` of `steps` and of
/// rk45 at three tolerances, over `scene`'s comparison, untimed: the accuracy passes'
/// work, counted.
fn compared_steps(
    scene: &Scene,
    span: &Span,
    steps: &[f64],
) -> (compare::Reference, Vec<compare::Row>) {
    let reference = compare::Reference::new(scene, span);
    let runs: Vec<(Method, Stepping)> = Method::TIME_STEPPING
        .into_iter()
        .flat_map(|m| steps.iter().map(move |&h| (m, h)))
        .map(|(method, h)| {
            let settings = Stepping {
                step: if method.adaptive() { 1e-3 } else { h },
                tolerance: h,
                max_steps: compare::STEP_BUDGET,
                ..Stepping::default()
            };
            (method, settings)
        })
        .collect();
    let rows = runs
        .iter()
        .map(|(m, s)| compare::measure(*m, scene, s, &reference, false, &Quiet).unwrap())
        .collect();
    (reference, rows)
}

#[test]
fn a_comparison_covers_at_most_its_window_whatever_the_span() {
    let (scene, span, _) = paper();
    // The default scene (1.28 s) is compared whole.
    let default = compare::Reference::new(&scene, &span);
    assert_eq!(default.cut, None);
    assert!(default.exact.t_end - default.exact.t_start < compare::WINDOW);
    // μ = 1e-6: the balls slide for 147,000 s; a 10 kg right ball: 2.25 s; a span
    // set to 19.7 s. Each is compared over its first WINDOW seconds only, and every
    // row says where it was cut.
    let slippery = Scene { mu: 1e-6, ..scene };
    let heavy = Scene {
        right: groovelab::physics::scene::Ball {
            mass: 10.0,
            ..scene.right
        },
        ..scene
    };
    let long = Span {
        t_end: Some(19.7),
        ..span
    };
    for (what, scene, span) in [
        ("mu 1e-6", slippery, span),
        ("10 kg", heavy, span),
        ("t_end 19.7 s", scene, long),
    ] {
        let whole = groovelab::physics::engine::solve(&scene, &span);
        assert!(whole.t_end - whole.t_start > compare::WINDOW, "{what}");
        let (reference, rows) = compared_steps(&scene, &span, &[1e-2, 1e-3]);
        let end = span.t_start + compare::WINDOW;
        assert_eq!(reference.cut, Some(end), "{what}");
        assert_eq!(reference.exact.t_end, end, "{what}");
        for r in &rows {
            assert_eq!(r.cut, Some(end), "{what}: {r:?}");
            // Every fixed-step run takes exactly the window's steps: run, not refused
            // (20 million steps at h = 1 µs would have been), and no more.
            if let Some(h) = r.step {
                let want = (compare::WINDOW / h).ceil() as usize;
                assert_eq!(r.steps, want, "{what}: {r:?}");
            }
            assert!(r.steps <= compare::STEP_BUDGET, "{what}: {r:?}");
        }
    }
}

#[test]
fn the_slowest_scene_does_the_work_of_a_default_comparison_at_most_twice() {
    // Counted in steps at the Methods view's coarse levels (the sweep's finer levels
    // scale alike, every level over the same stretch): μ = 1e-6 spans 147,000 s, yet
    // its runs take no more than twice the default scene's steps.
    let (scene, span, _) = paper();
    let levels = [1e-2, 1e-3];
    let total = |rows: &[compare::Row]| rows.iter().map(|r| r.steps).sum::<usize>();
    let (_, default) = compared_steps(&scene, &span, &levels);
    let (_, slippery) = compared_steps(&Scene { mu: 1e-6, ..scene }, &span, &levels);
    let (d, s) = (total(&default), total(&slippery));
    assert!(s <= 2 * d, "{s} steps against the default's {d}");
    // The fixed-step methods' share: exactly the window over the default span.
    let fixed = |rows: &[compare::Row]| {
        rows.iter()
            .filter(|r| r.step.is_some())
            .map(|r| r.steps)
            .sum::<usize>() as f64
    };
    let ratio = fixed(&slippery) / fixed(&default);
    let spans = compare::WINDOW / (default_end(&scene, &span) - span.t_start);
    assert!(
        (ratio - spans).abs() <= 0.01 * spans,
        "{ratio} against {spans}"
    );
}

fn default_end(scene: &Scene, span: &Span) -> f64 {
    groovelab::physics::engine::solve(scene, span).t_end
}

#[test]
fn compare_stops_when_asked_and_matches_when_not() {
    let (scene, span, _) = paper();
    let methods = [Method::Exact, Method::Rk45, Method::Moreau];
    let stop = stop_after(3);
    let cancelled = compare::sweep(&scene, &span, &methods, &Stepping::default(), &stop);
    assert_eq!(cancelled, Err(Cancelled));
    // The first tick is 0 of N, then one per finished run; the stop is seen within
    // each run still going (the accuracy runs share the cores): at its first look
    // (after at most 4096 steps) and once more on the way out, and no row is timed.
    let threads = rayon::current_num_threads() as u64;
    assert!(stop.ticks.load(Ordering::Relaxed) <= 2 + threads);
    let looks = stop.looks_after_stop.load(Ordering::Relaxed);
    assert!(
        (1..=2 * threads).contains(&looks),
        "{looks} looks after the stop"
    );

    // Untimed rows are deterministic: the same with and without a watching Progress.
    let reference = compare::Reference::new(&scene, &span);
    let settings = Stepping {
        step: 1e-4,
        ..Stepping::default()
    };
    let watched = compare::measure(
        Method::Moreau,
        &scene,
        &settings,
        &reference,
        false,
        &stop_after(u64::MAX),
    )
    .unwrap();
    let quiet =
        compare::measure(Method::Moreau, &scene, &settings, &reference, false, &Quiet).unwrap();
    assert_eq!(watched, quiet);
}

#[test]
fn a_cancelled_measure_stops_inside_the_run() {
    let (scene, span, _) = paper();
    let reference = compare::Reference::new(&scene, &span);
    // 1.2 million Euler steps; cancelled from the start, it returns after the first
    // check (4096 steps), long before the run would end: one look inside the run and
    // one after it, where the whole run would look about 290 times.
    let settings = Stepping {
        step: 1e-6,
        ..Stepping::default()
    };
    let stop = stop_after(0);
    let r = compare::measure(Method::Euler, &scene, &settings, &reference, true, &stop);
    assert_eq!(r, Err(Cancelled));
    assert_eq!(stop.looks_after_stop.load(Ordering::Relaxed), 2);
}

/// The paper's series resampled `factor` times finer (linear interpolation).
fn finer(m: &Measured, factor: usize) -> Measured {
    let mut out = groovelab::study::measured::MeasuredParts::default();
    for i in 0..m.t().len() - 1 {
        for k in 0..factor {
            let f = k as f64 / factor as f64;
            out.t.push(m.t()[i] + f * (m.t()[i + 1] - m.t()[i]));
            out.v_cm
                .push(m.v_cm()[i] + f * (m.v_cm()[i + 1] - m.v_cm()[i]));
            out.v_t.push(m.v_t()[i] + f * (m.v_t()[i + 1] - m.v_t()[i]));
        }
    }
    Measured::new(out).unwrap()
}

#[test]
fn fit_thins_a_long_series_and_says_so() {
    let (scene, _, m) = paper();
    // The paper's series has 50-odd frames: used whole, and the JSON has no `every`.
    let short = fit::fit_all(
        &scene,
        &m,
        &fit::Ask {
            free: Some(vec![fit::Free::Mu]),
            ..Default::default()
        },
        &Quiet,
    )
    .unwrap();
    assert_eq!(short.model_fit.every, None);
    let json = serde_json::to_string(&short).unwrap();
    assert!(!json.contains("\"every\""), "{json}");

    let long = finer(&m, 500);
    assert!(long.t().len() > fit::MAX_MODEL_POINTS);
    let (thin, k) = fit::thinned(&long).unwrap();
    assert!(thin.t().len() <= fit::MAX_MODEL_POINTS);
    assert_eq!(k, long.t().len().div_ceil(fit::MAX_MODEL_POINTS));
    let f = fit::model_fit(&scene, &long, &[fit::Free::Mu], &Quiet).unwrap();
    assert_eq!(f.every, Some(k));
    assert!(f.points <= fit::MAX_MODEL_POINTS);
    // The fit is exactly the fit of every k-th frame, and stays physical (the
    // interpolated frames across the impact jumps pull μ a little off the paper's 0.17).
    let direct = fit::model_fit(&scene, &thin, &[fit::Free::Mu], &Quiet).unwrap();
    assert_eq!(direct.every, None);
    assert_eq!(
        fit::ModelFit {
            every: None,
            ..f.clone()
        },
        direct
    );
    assert!((0.1..0.25).contains(&f.mu), "μ = {}", f.mu);
}

#[test]
fn fit_stops_when_asked_and_matches_when_not() {
    let (scene, _, m) = paper();
    let stop = stop_after(5);
    let r = fit::fit_all(
        &scene,
        &m,
        &fit::Ask {
            free: Some(vec![fit::Free::Mu]),
            ..Default::default()
        },
        &stop,
    );
    assert_eq!(r, Err(fit::FitError::Cancelled));
    assert_eq!(stop.ticks.load(Ordering::Relaxed), 5);
    let watched = fit::fit_all(
        &scene,
        &m,
        &fit::Ask {
            free: Some(vec![fit::Free::Mu, fit::Free::V0]),
            ..Default::default()
        },
        &stop_after(u64::MAX),
    )
    .unwrap();
    let quiet = fit::fit_all(
        &scene,
        &m,
        &fit::Ask {
            free: Some(vec![fit::Free::Mu, fit::Free::V0]),
            ..Default::default()
        },
        &Quiet,
    )
    .unwrap();
    assert_eq!(
        serde_json::to_string(&watched).unwrap(),
        serde_json::to_string(&quiet).unwrap()
    );
}

/// Waits until the process `pid` has a handler for SIGINT (bit 2 of `SigCgt` in
/// `/proc/PID/status`); where there is no `/proc`, waits 700 ms instead.
fn catches_sigint(pid: u32) {
    let status = format!("/proc/{pid}/status");
    if !std::path::Path::new(&status).exists() {
        std::thread::sleep(Duration::from_millis(700));
        return;
    }
    let start = std::time::Instant::now();
    loop {
        let caught = std::fs::read_to_string(&status)
            .ok()
            .and_then(|s| {
                let mask = s.lines().find_map(|l| l.strip_prefix("SigCgt:"))?;
                u64::from_str_radix(mask.trim(), 16).ok()
            })
            .is_some_and(|mask| mask & (1 << (2 - 1)) != 0);
        if caught {
            return;
        }
        assert!(
            start.elapsed() < Duration::from_secs(30),
            "no SIGINT handler"
        );
        std::thread::sleep(Duration::from_millis(5));
    }
}

#[test]
fn ctrl_c_stops_compare_with_130_and_writes_nothing() {
    let dir = crate::common::scratch_dir("methods", "interrupt");
    let out = dir.join("wp.svg");
    let child = Command::new(env!("CARGO_BIN_EXE_groovelab"))
        .args(["compare", "--format", "svg", "--output"])
        .arg(&out)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    // The default sweep takes seconds (release) to a minute (debug): well past this.
    // Signalled once it catches SIGINT (else the default action would end it, not the
    // program), and a little later, so the sweep is under way; a fixed 700 ms wait
    // spent two cores on the sweep for nothing.
    catches_sigint(child.id());
    std::thread::sleep(Duration::from_millis(100));
    let kill = Command::new("kill")
        .args(["-INT", &child.id().to_string()])
        .status()
        .unwrap();
    assert!(kill.success());
    let result = child.wait_with_output().unwrap();
    let stderr = String::from_utf8_lossy(&result.stderr);
    assert_eq!(result.status.code(), Some(130), "{stderr}");
    assert!(result.stdout.is_empty());
    assert_eq!(stderr, "error: interrupted: nothing was written\n");
    assert!(!out.exists(), "the output file was written");
    let left: Vec<_> = std::fs::read_dir(&dir).unwrap().collect();
    assert!(left.is_empty(), "files left behind: {left:?}");
    // How soon it stops is counted, not timed: `compare_stops_when_asked_and_matches_
    // when_not` and `a_cancelled_measure_stops_inside_the_run` count the work done
    // after the stop (a look every 4096 steps, no run finished, no row timed).
    let _ = std::fs::remove_dir_all(&dir);
}
