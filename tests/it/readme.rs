//! The README's console examples are tests: every `$ groovelab …` line of a ```console
//! block in README.md is run, and its output compared with the lines below it (trycmd).
//! A change that alters an example fails here until the README shows the new output.
//! Wildcards: `[..]` matches the rest of a line, `...` on a line of its own any lines;
//! the README uses them only for timings, and says so beside each example.
//!
//! The examples run in a sandbox: a copy of README.md in a fresh folder beside
//! `README.in/`, which holds the files the examples read (`bad.csv`, the video track),
//! and `README.out/`, which makes trycmd copy that folder before running (so
//! `--output map.svg` writes into the copy). User presets come from an empty folder, so
//! `presets` lists exactly the built-in ones. The failure report names the copy; fix
//! the README itself.

use std::fs;
use std::path::{Path, PathBuf};

fn copy(from: &Path, to: &Path) {
    if let Some(parent) = to.parent() {
        fs::create_dir_all(parent).unwrap();
    }
    fs::copy(from, to).unwrap_or_else(|e| panic!("{}: {e}", from.display()));
}

/// A fresh folder for the examples, with README.md and its fixtures.
fn sandbox() -> PathBuf {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("readme-examples");
    let _ = fs::remove_dir_all(&dir);
    copy(&root.join("README.md"), &dir.join("README.md"));
    let input = dir.join("README.in");
    for file in [
        "docs/video/paper-b4.9-tracker.txt",
        "docs/video/ball.txt",
        "docs/video/mark.txt",
        "docs/video/logger-pro.csv",
    ] {
        copy(&root.join(file), &input.join(file));
    }
    // The README's broken file: line 3 holds a v_cm that is not a number.
    fs::write(
        input.join("bad.csv"),
        "t,v_cm,v_t\n0.00,0.61,0.55\n0.01,abc,0.56\n",
    )
    .unwrap();
    fs::create_dir_all(dir.join("README.out")).unwrap();
    fs::write(dir.join("README.out/.keep"), "").unwrap();
    fs::create_dir_all(dir.join("no-presets")).unwrap();
    dir
}

#[test]
fn every_console_example_prints_what_the_readme_shows() {
    let dir = sandbox();
    trycmd::TestCases::new()
        .register_bin("groovelab", Path::new(env!("CARGO_BIN_EXE_groovelab")))
        .env(
            "GROOVELAB_PRESETS",
            dir.join("no-presets").display().to_string(),
        )
        .env("NO_COLOR", "1")
        .case(dir.join("README.md"));
}

/// The README's screens are tests too: each ```text block followed by
/// "(`groovelab render …` prints exactly this.)" is what that command prints now.
#[test]
fn every_screen_in_the_readme_is_what_render_prints() {
    let readme =
        fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("README.md")).unwrap();
    let lines: Vec<&str> = readme.lines().collect();
    let mut checked = 0;
    let mut i = 0;
    while i < lines.len() {
        if lines[i] != "```text" {
            i += 1;
            continue;
        }
        let end = i + 1 + lines[i + 1..].iter().position(|l| *l == "```").unwrap();
        let block = &lines[i + 1..end];
        let said = lines[end + 1..].iter().take(2).find_map(|l| {
            let rest = l.strip_prefix("(`groovelab ")?;
            rest.strip_suffix("` prints exactly this.)")
        });
        if let Some(args) = said {
            let args: Vec<&str> = args.split_whitespace().collect();
            let out = crate::common::groovelab(&args);
            assert!(out.status.success(), "{args:?}");
            let printed = String::from_utf8(out.stdout).unwrap();
            let printed: Vec<&str> = printed.lines().collect();
            assert!(
                printed == block,
                "README.md line {}: `groovelab {}` prints\n{}",
                i + 2,
                args.join(" "),
                printed.join("\n")
            );
            checked += 1;
        }
        i = end + 1;
    }
    assert!(
        checked >= 2,
        "the main screen and the Forces view are checked"
    );
}
