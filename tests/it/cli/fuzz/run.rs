//! Running and judging the fuzz harness's cases against the contract, and its tests.

use super::cases::*;
use super::*;

// ---------------------------------------------------------------------------------
// Running and judging.

/// What a case did.
#[derive(Clone, Debug)]
pub(super) enum Verdict {
    Pass,
    Fail { class: String, detail: String },
}

impl Verdict {
    fn class(&self) -> Option<&str> {
        match self {
            Verdict::Pass => None,
            Verdict::Fail { class, .. } => Some(class),
        }
    }
}

/// The name of the thread a case runs on (its panics are recorded, not printed).
const CASE_THREAD: &str = "fuzz-case";

fn panic_message() -> &'static Mutex<String> {
    static M: OnceLock<Mutex<String>> = OnceLock::new();
    M.get_or_init(|| Mutex::new(String::new()))
}

fn limit() -> Duration {
    let secs = std::env::var("GROOVELAB_FUZZ_TIMEOUT")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(if cfg!(debug_assertions) { 60.0 } else { 10.0 });
    Duration::from_secs_f64(secs)
}

/// Runs a case on its own thread under a watchdog.
fn run(case: &Case) -> Result<Result<Exit, String>, Duration> {
    let f = fixtures();
    // Targets that --output must not turn into regular files, made afresh.
    let fifo_out = f.dir.join("fifo-out");
    let link_out = f.dir.join("link-out");
    let _ = std::fs::remove_file(&fifo_out);
    let _ = std::fs::remove_file(&link_out);
    let _ = std::process::Command::new("mkfifo").arg(&fifo_out).status();
    let _ = std::os::unix::fs::symlink(f.dir.join("target.txt"), &link_out);
    for (path, bytes) in &case.files {
        std::fs::write(path, bytes).unwrap();
    }
    let args = case.args.clone();
    let (tx, rx) = mpsc::channel();
    std::thread::Builder::new()
        .name(CASE_THREAD.into())
        .stack_size(64 << 20)
        .spawn(move || {
            let result = catch_unwind(AssertUnwindSafe(|| main_with(&args)));
            let _ = tx.send(result.map_err(|_| panic_message().lock().unwrap().clone()));
        })
        .unwrap();
    rx.recv_timeout(limit()).map_err(|_| limit())
}

/// Every command: keys of the parts several commands print (the scene, its derived
/// values, the run's summary and its solution).
const ANY: &[&str] = &COMMANDS;

/// Keys whose value may be `null` in JSON output (the `Option`s of the schema), each
/// with the commands whose output documents the `null` (docs/interface.md). A `null`
/// under a key elsewhere (say `frame_rate` from `fit`, where it is always a number)
/// is a non-finite number and fails.
const NULLABLE: &[(&str, &[&str])] = &[
    ("t_pure_gliding", ANY),
    ("t_pure_slipping", ANY),
    ("b_star", ANY),
    ("left_after_impact", ANY),
    ("accumulation_time", ANY),
    ("bridge", ANY),
    ("accumulation", ANY),
    ("t_end", ANY),
    ("label", ANY),
    // simulate --method: why a time-stepping run stalled, `null` when it did not.
    ("stalled", &["simulate"]),
    // compare's rows: the step or the tolerance (the other `null`), the errors a run
    // has no counterpart for, a stalled run's note, and where the step budget cut the
    // span (`null` when it covered it all).
    ("step", &["compare"]),
    ("tolerance", &["compare"]),
    ("err_t_roll", &["compare"]),
    ("err_t_impact", &["compare"]),
    ("note", &["compare"]),
    ("cut", &["compare"]),
    // fit's models: a value and its standard error, `null` where the data do not
    // determine it (with its reason), and the approach speed of the user's own data,
    // `null` where there are none (the preset's series) or they measure none.
    // A headline (`model_fit`, `mu_alone`) whose value the data do not determine:
    // the value and its `_se` are `null` (docs/interface.md, `not_identified`), μ_k's
    // too (seed 20261130: the preset's series fitted with v0 given as 10 mm/s).
    ("mu", &["fit"]),
    ("mu_se", &["fit"]),
    ("v0", &["fit"]),
    ("restitution", &["fit"]),
    ("rolling_resistance", &["fit"]),
    ("v0_se", &["fit"]),
    ("restitution_se", &["fit"]),
    ("rolling_resistance_se", &["fit"]),
    ("value", &["fit"]),
    ("se", &["fit"]),
    ("approach", &["fit"]),
    // sweep: a 1-D sweep's `y`; v'/v0 and t' without friction or impact; no
    // accumulation point.
    ("y", &["sweep", "track"]),
    ("v_ratio", &["sweep"]),
    ("t_roll", &["sweep"]),
    ("t_accumulation", &["sweep"]),
    // track's JSON: a ball's centre (`x`, `y`, `sigma`) or its mark (`mark_x`,
    // `mark_y`, `mark_sigma`) in a frame where it is left out, never filled in.
    ("x", &["track"]),
    ("sigma", &["track"]),
    ("mark_x", &["track"]),
    ("mark_y", &["track"]),
    ("mark_sigma", &["track"]),
    // data's report: a file with fewer than two distinct times has no frame rate.
    ("frame_rate", &["data"]),
];

/// May `key` be `null` in the JSON of `command`?
fn nullable(command: Option<&str>, key: &str) -> bool {
    NULLABLE
        .iter()
        .any(|(k, cs)| *k == key && command.is_some_and(|c| cs.contains(&c)))
}

/// The keys under which `v` holds a `null` that `command` may not print.
fn nulls(v: &serde_json::Value, command: Option<&str>, key: &str, out: &mut Vec<String>) {
    match v {
        serde_json::Value::Null if !nullable(command, key) => out.push(key.to_string()),
        serde_json::Value::Array(a) => a.iter().for_each(|x| nulls(x, command, key, out)),
        serde_json::Value::Object(o) => o.iter().for_each(|(k, x)| nulls(x, command, k, out)),
        _ => {}
    }
}

/// Words that say a number was not finite, in text output.
fn nonfinite_words(text: &str) -> Vec<String> {
    // The accumulation time's label T∞ (ASCII: Tinf) is a name,
    // also where a popup's border hides its first letters.
    // A note about the file's cells names a NaN cell it left out ("empty or NaN").
    let text = [
        "Tinf",
        "T∞",
        "|inf",
        "+inf",
        "│∞",
        "╮∞",
        "╯∞",
        "empty or NaN",
    ]
    .iter()
    .fold(text.to_string(), |t, label| t.replace(label, "T"));
    let mut found: Vec<String> = text
        .split(|c: char| !(c.is_alphanumeric() || c == '.'))
        .filter(|w| matches!(*w, "NaN" | "nan" | "inf" | "Inf" | "infinity" | "∞"))
        .map(String::from)
        .collect();
    found.dedup();
    found
}

fn judge(case: &Case, result: &Result<Result<Exit, String>, Duration>) -> Verdict {
    let fail = |class: &str, detail: String| Verdict::Fail {
        class: class.to_string(),
        detail,
    };
    let exit = match result {
        Err(limit) => return fail("timeout", format!("no result within {limit:?}")),
        Ok(Err(msg)) => {
            // Panics differ by message; the class is where (file:line) and what.
            let short: String = msg.lines().next().unwrap_or("").chars().take(90).collect();
            return fail(&format!("panic: {short}"), msg.clone());
        }
        Ok(Ok(exit)) => exit,
    };
    let shown = || {
        format!(
            "exit {}\n--- stdout\n{}\n--- stderr\n{}",
            exit.code,
            head(&exit.stdout),
            exit.stderr
        )
    };
    match exit.code {
        2 => {
            if !exit.stdout.is_empty() {
                return fail("error: text on stdout", shown());
            }
            let lines: Vec<&str> = exit.stderr.lines().collect();
            if lines.len() != 1 || !exit.stderr.ends_with('\n') {
                let class = if exit.stderr.contains("For more information, try") {
                    "error: clap's usage error spans several lines (hint, possible values, usage)"
                } else {
                    "error: message spans several lines"
                };
                return fail(class, shown());
            }
            if !lines[0].starts_with("error: ") {
                return fail("error: line does not start with 'error: '", shown());
            }
            Verdict::Pass
        }
        0 => {
            // A success writes nothing on stderr but the notes for a length or mass
            // given as a bare number of 1 or more (SI, though cm or g are meant).
            let bare_note =
                |l: &str| l.starts_with("note: --") && l.contains(" has no unit, so it is ");
            if !exit.stderr.lines().all(bare_note) {
                return fail("success: text on stderr", shown());
            }
            let wrote_to = |name: &str| case.value("--output").is_some_and(|o| o.ends_with(name));
            for special in ["fifo-out", "link-out"] {
                if wrote_to(special) {
                    let meta = std::fs::symlink_metadata(fixtures().dir.join(special));
                    if meta.is_ok_and(|m| m.file_type().is_file()) {
                        return fail(
                            "success: --output replaced a FIFO or symlink with a regular file",
                            shown(),
                        );
                    }
                }
            }
            let text = match case.value("--output") {
                Some(path) if exit.stdout.starts_with("wrote ") => {
                    std::fs::read_to_string(path).unwrap_or_default()
                }
                _ => exit.stdout.clone(),
            };
            let json_out = case.value("--format").as_deref() == Some("json")
                && !case.has("--help")
                && !case.has("-h")
                && !case.has("--version");
            if json_out {
                match serde_json::from_str::<serde_json::Value>(&text) {
                    Err(e) => {
                        return fail("success: JSON does not parse", format!("{e}\n{}", shown()));
                    }
                    Ok(v) => {
                        let mut found = Vec::new();
                        nulls(&v, case.command(), "", &mut found);
                        found.sort();
                        found.dedup();
                        if !found.is_empty() {
                            return fail(
                                &format!(
                                    "success: non-finite number (null) in JSON under {}",
                                    found.join(", ")
                                ),
                                shown(),
                            );
                        }
                    }
                }
            } else {
                let words = nonfinite_words(&text);
                if !words.is_empty() {
                    let lines: Vec<&str> = text
                        .lines()
                        .filter(|l| !nonfinite_words(l).is_empty())
                        .take(3)
                        .collect();
                    let what = if text.starts_with("<svg") || text.starts_with("<?xml") {
                        "SVG"
                    } else {
                        case.command().unwrap_or("output")
                    };
                    return fail(
                        &format!(
                            "success: non-finite number ({}) in {what} output",
                            words.join(", ")
                        ),
                        format!("at: {}\n{}", lines.join("\n"), shown()),
                    );
                }
            }
            Verdict::Pass
        }
        c => fail(&format!("exit status {c}"), shown()),
    }
}

fn head(s: &str) -> String {
    let h: String = s.chars().take(600).collect();
    if h.len() < s.len() {
        format!("{h}…")
    } else {
        h
    }
}

/// Tally of a run.
#[derive(Default)]
struct Tally {
    run: usize,
    passed: usize,
    skipped: BTreeMap<String, usize>,
    tolerated: BTreeMap<String, usize>,
    /// Failure class → (count, the shortest reproducer and its detail).
    failures: BTreeMap<String, (usize, String, String)>,
    by_kind: BTreeMap<&'static str, usize>,
    /// Per command: how many cases it accepted (exit 0) and refused (exit 2), so a run
    /// shows that each command was reached past its argument checks.
    outcomes: BTreeMap<&'static str, (usize, usize)>,
    /// Seconds spent per kind, and the slowest case.
    time_by_kind: BTreeMap<&'static str, f64>,
    slowest: (f64, String),
}

fn cases_wanted() -> usize {
    std::env::var("GROOVELAB_FUZZ_CASES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(200)
}

fn seed() -> u64 {
    std::env::var("GROOVELAB_FUZZ_SEED")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(0x9e0_07e1ab)
}

/// Runs `n` cases drawn from `strategy`, judging each.
fn fuzz(name: &'static str, strategy: BoxedStrategy<Case>, n: usize, tally: &mut Tally) {
    let mut bytes = [0u8; 32];
    bytes[..8].copy_from_slice(&seed().to_le_bytes());
    bytes[8..8 + name.len().min(24)].copy_from_slice(&name.as_bytes()[..name.len().min(24)]);
    let rng = TestRng::from_seed(RngAlgorithm::ChaCha, &bytes);
    let mut runner = TestRunner::new_with_rng(Config::default(), rng);
    let verbose = std::env::var_os("GROOVELAB_FUZZ_VERBOSE").is_some();
    for i in 0..n {
        let case = strategy.new_tree(&mut runner).unwrap().current();
        if let Some(k) = KNOWN_OPEN
            .iter()
            .find(|k| k.hang && (k.applies)(&case, None))
        {
            *tally.skipped.entry(k.label()).or_default() += 1;
            continue;
        }
        if verbose {
            eprintln!("[{name} {i}] {}", case.shell());
        }
        let started = Instant::now();
        let result = run(&case);
        let verdict = judge(&case, &result);
        tally.run += 1;
        *tally.by_kind.entry(case.kind).or_default() += 1;
        if let Ok(Ok(exit)) = &result {
            let counts = tally
                .outcomes
                .entry(case.command().unwrap_or("(none)"))
                .or_default();
            match exit.code {
                0 => counts.0 += 1,
                _ => counts.1 += 1,
            }
        }
        let took = started.elapsed().as_secs_f64();
        *tally.time_by_kind.entry(case.kind).or_default() += took;
        if took > tally.slowest.0 {
            tally.slowest = (took, case.shell());
        }
        match &verdict {
            Verdict::Pass => tally.passed += 1,
            Verdict::Fail { class, detail } => {
                if let Some(k) = KNOWN_OPEN
                    .iter()
                    .find(|k| !k.hang && (k.applies)(&case, Some(&verdict)))
                {
                    *tally.tolerated.entry(k.label()).or_default() += 1;
                } else {
                    let repro = case.shell();
                    let entry = tally.failures.entry(class.clone()).or_insert((
                        0,
                        repro.clone(),
                        detail.clone(),
                    ));
                    entry.0 += 1;
                    if repro.len() < entry.1.len() {
                        entry.1 = repro;
                        entry.2 = detail.clone();
                    }
                }
            }
        }
        if result.is_err() {
            // The stuck case still runs on its thread: stop here.
            eprintln!(
                "fuzz {name}: stopping after a timeout ({:?})",
                started.elapsed()
            );
            break;
        }
    }
}

fn report(tally: &Tally, elapsed: Duration) -> String {
    let mut out = format!(
        "fuzz: {} cases run in {:.1} s ({:?}), {} passed, {} failed in {} classes; seed {}\n",
        tally.run,
        elapsed.as_secs_f64(),
        tally.by_kind,
        tally.passed,
        tally.failures.values().map(|f| f.0).sum::<usize>(),
        tally.failures.len(),
        seed()
    );
    let times: Vec<String> = tally
        .time_by_kind
        .iter()
        .map(|(k, t)| format!("{k} {t:.1} s"))
        .collect();
    out.push_str(&format!(
        "  time: {}; slowest case {:.2} s: {}\n",
        times.join(", "),
        tally.slowest.0,
        tally.slowest.1
    ));
    let outcomes: Vec<String> = tally
        .outcomes
        .iter()
        .map(|(c, (ok, refused))| format!("{c} {ok}/{refused}"))
        .collect();
    out.push_str(&format!(
        "  accepted/refused by command: {}\n",
        outcomes.join(", ")
    ));
    for (id, n) in &tally.skipped {
        out.push_str(&format!("  skipped (KNOWN_OPEN {id}, would hang): {n}\n"));
    }
    for (id, n) in &tally.tolerated {
        out.push_str(&format!("  tolerated (KNOWN_OPEN {id}): {n}\n"));
    }
    for (class, (n, repro, detail)) in &tally.failures {
        out.push_str(&format!(
            "\nFAIL [{n}×] {class}\n  {repro}\n  {}\n",
            head(detail).replace('\n', "\n  | ")
        ));
    }
    out
}

#[test]
fn fuzz_the_command_line() {
    fixtures();
    // The hook is the whole test binary's: other tests' panics still reach the
    // previous hook (and so their failure output); a case's panic is only recorded.
    let previous = std::panic::take_hook();
    std::panic::set_hook(Box::new(move |info| {
        *panic_message().lock().unwrap() = info.to_string();
        if std::thread::current().name() != Some(CASE_THREAD) {
            previous(info);
        }
    }));
    let n = cases_wanted();
    let started = Instant::now();
    let mut tally = Tally::default();
    fuzz("cli", cli_case(), n * 55 / 100, &mut tally);
    fuzz("preset", preset_case(), n * 15 / 100, &mut tally);
    fuzz("csv", csv_case(), n * 10 / 100, &mut tally);
    fuzz("damaged", damaged_file_case(), n * 5 / 100, &mut tally);
    fuzz("keys", keys_case(), n - n * 85 / 100, &mut tally);
    let text = report(&tally, started.elapsed());
    eprintln!("{text}");
    if let Ok(path) = std::env::var("GROOVELAB_FUZZ_REPORT") {
        std::fs::write(path, &text).unwrap();
    }
    // GROOVELAB_FUZZ_KEEP=1 keeps the fixtures, so a reported case can be rerun by hand.
    if std::env::var_os("GROOVELAB_FUZZ_KEEP").is_none() {
        let _ = std::fs::remove_dir_all(&fixtures().dir);
    }
    assert!(tally.failures.is_empty(), "{text}");
    assert!(tally.run >= n / 2, "most cases were skipped: {text}");
}

#[test]
fn the_harness_sees_a_broken_contract() {
    // The judge itself: a second stderr line, text on stdout with an error, a panic
    // and a null in JSON are failures; a clean error and clean JSON pass.
    fixtures();
    let case = to_case(
        "cli",
        vec!["simulate".into(), "--format".into(), "json".into()],
    );
    let exit = |code, stdout: &str, stderr: &str| {
        Ok(Ok(Exit {
            code,
            stdout: stdout.into(),
            stderr: stderr.into(),
        }))
    };
    let class = |r| judge(&case, &r).class().map(String::from);
    assert_eq!(class(exit(2, "", "error: bad\n")), None);
    assert!(
        class(exit(
            2,
            "",
            "error: bad\n\nFor more information, try '--help'.\n"
        ))
        .is_some()
    );
    assert!(class(exit(2, "x", "error: bad\n")).is_some());
    assert!(class(exit(2, "", "bad\n")).is_some());
    assert!(class(exit(130, "", "error: interrupted\n")).is_some());
    assert_eq!(class(exit(0, "{\"b_star\": null, \"k\": 1.0}", "")), None);
    assert!(class(exit(0, "{\"k\": null}", "")).is_some());
    // A `null` is allowed only where the command documents it: `data` reports a file
    // with one time as having no frame rate; `fit`'s frame rate is always a number.
    let rate = "{\"frame_rate\": null}";
    let of = |command: &str| {
        let case = to_case(
            "cli",
            vec![command.into(), "--format".into(), "json".into()],
        );
        judge(&case, &exit(0, rate, "")).class().map(String::from)
    };
    assert_eq!(of("data"), None);
    assert!(of("fit").is_some());
    assert!(of("simulate").is_some());
    assert!(class(Ok(Err("boom".into()))).is_some());
    assert!(class(Err(Duration::from_secs(1))).is_some());
    let table = to_case("cli", vec!["simulate".into()]);
    assert!(
        judge(&table, &exit(0, "energy inf J", ""))
            .class()
            .is_some()
    );
    assert!(judge(&table, &exit(0, "information", "")).class().is_none());
}

#[test]
fn main_with_runs_in_process() {
    fixtures();
    let out = main_with(&["groovelab", "simulate", "--format", "json"].map(OsString::from));
    assert_eq!(out.code, 0, "{}", out.stderr);
    let v: serde_json::Value = serde_json::from_str(&out.stdout).unwrap();
    assert_eq!(v["scene"]["width"], 0.049);
    let bad = main_with(&["groovelab", "simulate", "--radius", "0"].map(OsString::from));
    assert_eq!(bad.code, 2);
    assert!(bad.stdout.is_empty());
    assert!(bad.stderr.starts_with("error: "), "{}", bad.stderr);
    // Without a terminal the app is refused, as the binary refuses it when piped.
    let app = main_with(&["groovelab"].map(OsString::from));
    assert_eq!(app.code, 2);
    assert!(app.stderr.contains("needs a terminal"), "{}", app.stderr);
}
