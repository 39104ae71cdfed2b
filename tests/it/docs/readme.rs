//! The documents' console examples are tests: every `$ groovelab …` line of a ```console
//! block in README.md and docs/guide.md is run, and its output compared with the lines
//! below it (trycmd). A change that alters an example fails here until the document
//! shows the new output. Wildcards: `[..]` matches the rest of a line, `...` on a line
//! of its own any lines; the documents use them only for timings and for long outputs
//! they cut, and say so beside each example.
//!
//! The examples run in a sandbox: a copy of each document (`README.md`, `guide.md`) in
//! a fresh folder of its own (the two run side by side) beside `NAME.in/`, which holds the files the examples read (`bad.csv`,
//! the video tracks), and `NAME.out/`, which makes trycmd copy that folder before
//! running (so `--output map.svg` writes into the copy). User presets come from an empty
//! folder, so `presets` lists exactly the built-in ones, and a video's tracks are kept
//! in a cache folder of the sandbox's. The guide's film (`frames/`) is rendered here
//! from the exact solution (`video_app::folder`). The failure report names the copy;
//! fix the document itself.

use std::fs;
use std::path::{Path, PathBuf};

fn copy(from: &Path, to: &Path) {
    if let Some(parent) = to.parent() {
        fs::create_dir_all(parent).unwrap();
    }
    fs::copy(from, to).unwrap_or_else(|e| panic!("{}: {e}", from.display()));
}

/// The documents whose examples are tests, by path in the repository.
const DOCUMENTS: [&str; 2] = ["README.md", "docs/guide.md"];

/// A fresh folder for the examples of the document `doc`, with its fixtures: one
/// folder a document, so the documents' examples run side by side.
fn sandbox(doc: &str) -> PathBuf {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let name = Path::new(doc).file_stem().unwrap().to_str().unwrap();
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("{name}-examples"));
    let _ = fs::remove_dir_all(&dir);
    copy(&root.join(doc), &dir.join(format!("{name}.md")));
    let input = dir.join(format!("{name}.in"));
    for file in [
        "docs/video/paper-b4.9-tracker.txt",
        "docs/video/ball.txt",
        "docs/video/mark.txt",
        "docs/video/logger-pro.csv",
    ] {
        copy(&root.join(file), &input.join(file));
    }
    // The guide's broken file: line 3 holds a v_cm that is not a number.
    fs::write(
        input.join("bad.csv"),
        "t,v_cm,v_t\n0.00,0.61,0.55\n0.01,abc,0.56\n",
    )
    .unwrap();
    // The guide's film: a folder of frames rendered from the exact solution.
    for e in fs::read_dir(crate::video::app::folder()).unwrap() {
        let p = e.unwrap().path();
        copy(&p, &input.join("frames").join(p.file_name().unwrap()));
    }
    let out = dir.join(format!("{name}.out"));
    fs::create_dir_all(&out).unwrap();
    fs::write(out.join(".keep"), "").unwrap();
    fs::create_dir_all(dir.join("no-presets")).unwrap();
    dir
}

fn examples_run(dir: &Path) -> trycmd::TestCases {
    let cases = trycmd::TestCases::new();
    cases
        .register_bin("groovelab", Path::new(env!("CARGO_BIN_EXE_groovelab")))
        .env(
            "GROOVELAB_PRESETS",
            dir.join("no-presets").display().to_string(),
        )
        .env("NO_COLOR", "1")
        .env("XDG_CACHE_HOME", dir.join("cache").display().to_string());
    cases
}

/// Runs the console examples of the document `doc` in its own sandbox.
fn examples_of(doc: &str) {
    let dir = sandbox(doc);
    let name = Path::new(doc).file_stem().unwrap().to_str().unwrap();
    examples_run(&dir).case(dir.join(format!("{name}.md")));
}

#[test]
fn every_readme_example_prints_what_the_readme_shows() {
    examples_of(DOCUMENTS[0]);
}

#[test]
fn every_guide_example_prints_what_the_guide_shows() {
    examples_of(DOCUMENTS[1]);
}

/// Each document holds examples: a document whose blocks stopped being ```console
/// (and so stopped being run) fails here.
#[test]
fn each_document_has_examples_that_run() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    for (doc, least) in [("README.md", 6), ("docs/guide.md", 15)] {
        let text = fs::read_to_string(root.join(doc)).unwrap();
        let mut in_console = false;
        let mut commands = 0;
        for line in text.lines() {
            if line.starts_with("```") {
                in_console = line == "```console";
            } else if in_console && line.starts_with("$ groovelab ") {
                commands += 1;
            }
        }
        assert!(commands >= least, "{doc}: {commands} examples run");
    }
}

/// The documents' screens are tests too: each ```text block followed by
/// "(`groovelab render …` prints exactly this.)" is what that command prints now.
#[test]
fn every_screen_in_the_documents_is_what_render_prints() {
    for (doc, least) in [("README.md", 1), ("docs/guide.md", 2)] {
        let text = fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join(doc)).unwrap();
        let checked = screens_are_what_render_prints(doc, &text);
        assert!(checked >= least, "{doc}: {checked} screens checked");
    }
}

/// Checks each screen of one document; returns how many it checked.
fn screens_are_what_render_prints(doc: &str, text: &str) -> usize {
    let lines: Vec<&str> = text.lines().collect();
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
                "{doc} line {}: `groovelab {}` prints\n{}",
                i + 2,
                args.join(" "),
                printed.join("\n")
            );
            checked += 1;
        }
        i = end + 1;
    }
    checked
}
