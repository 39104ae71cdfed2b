//! Regression tests: each test is named after what once broke (or what it guards).
//! Issue 10's reliability items (`reliability_inputs`, `reliability_outputs`, sharing
//! the helpers below), the classroom's items, and a new user's trial.

mod classroom;
mod mark_words;
mod new_user_trial;
mod reliability_inputs;
mod reliability_outputs;
mod small_words;

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
        // As `common::groovelab`: never the user's cache.
        .env(
            "XDG_CACHE_HOME",
            concat!(env!("CARGO_TARGET_TMPDIR"), "/user-cache"),
        )
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
