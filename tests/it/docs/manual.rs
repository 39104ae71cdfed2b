//! `groovelab completions SHELL` and `groovelab manpage`: generated from the same clap
//! definitions as the parser, so they name every command and option; the bash script
//! parses (`bash -n`) and the man page renders (`man -l`, where man is installed; the
//! roff structure is checked everywhere).

use std::io::Write;
use std::process::{Command, Stdio};

use clap::CommandFactory;
use groovelab::cli::{Cli, entry::main_with};

/// stdout of a successful `groovelab ARGS`.
fn output(args: &[&str]) -> String {
    let argv: Vec<std::ffi::OsString> = std::iter::once("groovelab")
        .chain(args.iter().copied())
        .map(Into::into)
        .collect();
    let exit = main_with(&argv);
    assert_eq!(exit.code, 0, "groovelab {args:?}: {}", exit.stderr);
    assert!(exit.stderr.is_empty(), "{}", exit.stderr);
    exit.stdout
}

/// Every command's name and its own long options (globals with the top level).
fn commands_and_flags() -> Vec<(String, Vec<String>)> {
    let cmd = Cli::command();
    let flags = |c: &clap::Command| -> Vec<String> {
        c.get_arguments()
            .filter_map(|a| a.get_long())
            .map(|l| format!("--{l}"))
            .collect()
    };
    std::iter::once(("groovelab".to_string(), flags(&cmd)))
        .chain(
            cmd.get_subcommands()
                .map(|s| (s.get_name().to_string(), flags(s))),
        )
        .collect()
}

/// Runs `program args` with `input` on stdin; its status, stdout and stderr, or `None`
/// if the program is not installed.
fn pipe(program: &str, args: &[&str], input: &str) -> Option<(bool, String, String)> {
    let mut child = Command::new(program)
        .args(args)
        .env("MANPAGER", "cat")
        .env("PAGER", "cat")
        .env("MANWIDTH", "100")
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .ok()?;
    child
        .stdin
        .take()
        .expect("piped")
        .write_all(input.as_bytes())
        .expect("the program reads its input");
    let out = child.wait_with_output().expect("the program ends");
    Some((
        out.status.success(),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    ))
}

#[test]
fn the_bash_completion_parses_and_knows_every_command_and_option() {
    let script = output(&["completions", "bash"]);
    for (command, flags) in commands_and_flags() {
        assert!(script.contains(&command), "{command} missing");
        for flag in flags {
            assert!(script.contains(&flag), "{flag} of {command} missing");
        }
    }
    let (ok, _, err) = pipe("bash", &["-n"], &script).expect("bash is installed");
    assert!(ok, "bash -n rejects the completion script: {err}");
}

/// The completion scripts offer each command the options its `--help` lists, not the
/// global ones it refuses (clap_complete offers hidden options: `presets --<TAB>`
/// offered all 31 scene and data options).
#[test]
fn completions_offer_each_command_only_the_options_it_takes() {
    let script = output(&["completions", "bash"]);
    // bash: `opts="…"` on the line after each command's case label.
    let opts = |command: &str| -> Vec<String> {
        let label = format!("        groovelab__subcmd__{command})\n");
        let at = script
            .find(&label)
            .unwrap_or_else(|| panic!("no case for {command}"));
        let line = script[at + label.len()..].lines().next().unwrap();
        line.trim()
            .trim_start_matches("opts=\"")
            .trim_end_matches('"')
            .split_whitespace()
            .map(str::to_string)
            .collect()
    };
    let has = |command: &str, flag: &str| opts(command).iter().any(|o| o == flag);
    assert_eq!(opts("presets"), ["-h", "--help"], "presets");
    assert!(has("simulate", "--mass") && has("simulate", "--method"));
    assert!(!has("simulate", "--data") && !has("simulate", "--ascii"));
    assert!(has("track", "--radius") && has("track", "--scale") && !has("track", "--mass"));
    assert!(has("render", "--data") && has("render", "--ascii"));
    let fish = output(&["completions", "fish"]);
    assert!(
        !fish
            .lines()
            .any(|l| l.contains("using_subcommand presets") && l.contains("-l mass")),
        "fish offers presets --mass"
    );
}

#[test]
fn every_shell_gets_a_script_and_an_unknown_shell_is_refused() {
    for shell in ["bash", "zsh", "fish", "powershell", "elvish"] {
        let script = output(&["completions", shell]);
        assert!(
            script.contains("groovelab") && script.contains("rolling-resistance"),
            "{shell}: {}",
            &script[..script.len().min(200)]
        );
    }
    // zsh and fish check syntax too, where they are installed.
    for (shell, check) in [("zsh", ["-n"]), ("fish", ["-n"])] {
        if let Some((ok, _, err)) = pipe(shell, &check, &output(&["completions", shell])) {
            assert!(ok, "{shell} -n: {err}");
        }
    }
    let argv: Vec<std::ffi::OsString> = ["groovelab", "completions", "tcsh"]
        .into_iter()
        .map(Into::into)
        .collect();
    let exit = main_with(&argv);
    assert_eq!(exit.code, 2);
    assert!(exit.stdout.is_empty());
    assert!(
        exit.stderr.starts_with("error: ")
            && exit.stderr.contains("bash, elvish, fish, powershell, zsh"),
        "{}",
        exit.stderr
    );
    assert_eq!(exit.stderr.lines().count(), 1, "{}", exit.stderr);
}

#[test]
fn the_man_page_has_every_command_and_option_and_renders() {
    let page = output(&["manpage"]);
    assert!(
        page.starts_with(".ie ") || page.starts_with(".TH "),
        "{}",
        &page[..80]
    );
    assert!(page.contains("\n.TH groovelab 1 "), "no title line");
    for heading in [
        ".SH NAME",
        ".SH SYNOPSIS",
        ".SH DESCRIPTION",
        ".SH OPTIONS",
        ".SH VERSION",
    ] {
        assert!(
            page.contains(&format!("\n{heading}\n")),
            "{heading} missing"
        );
    }
    // Roff requests only where a line starts with one: no text line begins with a dot.
    for line in page.lines().filter(|l| l.starts_with('.')) {
        let request = line[1..].split_whitespace().next().unwrap_or("");
        assert!(
            [
                "ie", "el", "TH", "SH", "SS", "PP", "TP", "RS", "RE", "IP", "br", "sp", "B", "I"
            ]
            .contains(&request)
                || request.starts_with('\\'),
            "unexpected roff request in {line:?}"
        );
    }
    for (command, flags) in commands_and_flags() {
        if command != "groovelab" && command != "help" {
            let heading = format!(".SH \"COMMAND: GROOVELAB {}\"", command.to_uppercase());
            assert!(page.contains(&heading), "{heading} missing");
        }
        for flag in flags {
            // roff escapes the dashes of an option as \-.
            let escaped = flag.replace('-', "\\-");
            assert!(page.contains(&escaped), "{flag} of {command} missing");
        }
    }
    // `man -l -` renders it where man is installed (CI installs it).
    if let Some((ok, text, err)) = pipe("man", &["-l", "-"], &page) {
        assert!(ok, "man -l failed: {err}");
        assert!(err.trim().is_empty(), "man -l warns: {err}");
        for expected in [
            "NAME",
            "COMMAND: GROOVELAB SIMULATE",
            "--rolling-resistance",
        ] {
            assert!(
                text.contains(expected),
                "{expected} not in the rendered page"
            );
        }
    }
}
