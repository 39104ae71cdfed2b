//! `render`, the app's headless twin: the same keys give the same bytes on every run
//! (a key waits for the analyses it may act on), and a screen dump writes no files.

use std::path::{Path, PathBuf};
use std::process::Command;

use groovelab::settings::spec::SceneSpec;

use crate::common::{self, scene_of};

fn render(preset: &str, keys: &str) -> String {
    let scene = scene_of(preset, SceneSpec::default());
    let library = common::no_user_presets("headless");
    common::render_text(&scene, None, (120, 40), false, Some(keys), library).unwrap()
}

#[test]
fn a_key_waits_for_the_analysis_it_acts_on() {
    // `a` applies the fit that `f` started: without waiting it finds the fit running
    // (most runs, not all: the bytes would depend on the machine's load). Nine runs in
    // all: were a run without the wait even as likely to finish the fit in time as
    // not, all nine would pass with a chance of 1 in 512 (twenty-one runs cost 0.7 s).
    let first = render("paper-b3.5", "f a");
    assert!(first.contains("applied the fit: μ_k = 0.15"), "{first}");
    for run in 0..8 {
        assert_eq!(render("paper-b3.5", "f a"), first, "run {run}");
    }
}

/// The files under `dir`, relative, sorted (folders too).
fn tree(dir: &Path) -> Vec<PathBuf> {
    let mut found = Vec::new();
    let mut todo = vec![dir.to_path_buf()];
    while let Some(d) = todo.pop() {
        for entry in std::fs::read_dir(&d).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                todo.push(path.clone());
            }
            found.push(path.strip_prefix(dir).unwrap().to_path_buf());
        }
    }
    found.sort();
    found
}

#[test]
fn render_writes_no_files_and_says_what_it_would_write() {
    let dir = crate::common::scratch_dir("tui", "headless-writes-nothing");
    let (home, config) = (dir.join("home"), dir.join("config"));
    std::fs::create_dir_all(&home).unwrap();
    std::fs::create_dir_all(&config).unwrap();
    let before = tree(&dir);
    let cases = [
        ("w enter", "would write ./paper-b4.9-run.csv"),
        ("W enter", "would write ./paper-b4.9-chart.svg"),
        // The Methods diagram is drawn first (the key waits for it), then not written.
        ("c W enter", "would write ./paper-b4.9-methods.svg"),
        ("s enter", "would save preset my-paper-b4.9 as "),
    ];
    for (keys, says) in cases {
        let out = Command::new(env!("CARGO_BIN_EXE_groovelab"))
            .args([
                "render",
                "--preset",
                "paper-b4.9",
                "--size",
                "250x40",
                "--keys",
                keys,
            ])
            .current_dir(&dir)
            .env_remove("GROOVELAB_PRESETS")
            .env("HOME", &home)
            .env("XDG_CONFIG_HOME", &config)
            .output()
            .unwrap();
        let screen = String::from_utf8_lossy(&out.stdout);
        assert!(
            out.status.success(),
            "{keys}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
        assert!(
            screen.contains(&format!("render writes no files: {says}")),
            "{keys}: {screen}"
        );
        assert_eq!(tree(&dir), before, "{keys} wrote a file");
    }
    let _ = std::fs::remove_dir_all(&dir);
}
