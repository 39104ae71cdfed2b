//! `--theme` and `GROOVELAB_THEME` at the command line (issue 37): the app and
//! `render` take them; `render`'s text has no colours, so its output is the same
//! whatever the theme; other commands refuse the option; a bad variable is one line
//! naming the allowed words, exit status 2. (The palettes' contrast is measured in
//! the library's `tui::theme` tests.)

use std::process::Command;

fn run(args: &[&str], theme_var: Option<&str>) -> std::process::Output {
    let mut c = Command::new(env!("CARGO_BIN_EXE_groovelab"));
    c.args(args)
        .env("GROOVELAB_PRESETS", "/nonexistent-groovelab-presets")
        .env_remove("GROOVELAB_THEME");
    if let Some(v) = theme_var {
        c.env("GROOVELAB_THEME", v);
    }
    c.output().unwrap()
}

#[test]
fn render_takes_every_theme_and_draws_the_same_text() {
    let base = ["render", "--size", "80x24", "--at", "0.1s"];
    let plain = run(&base, None);
    assert!(plain.status.success());
    for theme in ["auto", "dark", "light"] {
        let out = run(&[&base[..], &["--theme", theme]].concat(), None);
        assert!(out.status.success(), "{theme}");
        assert_eq!(out.stdout, plain.stdout, "{theme}");
        let var = run(&base, Some(theme));
        assert_eq!(var.stdout, plain.stdout, "GROOVELAB_THEME={theme}");
    }
}

#[test]
fn a_bad_theme_is_one_line_naming_the_allowed_words() {
    let out = run(&["render", "--theme", "solarized"], None);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2));
    assert!(err.contains("solarized") && err.contains("light"), "{err}");
    assert_eq!(err.lines().count(), 1, "{err}");
    let out = run(&["render"], Some("sepia"));
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2));
    assert_eq!(
        err.trim(),
        "error: GROOVELAB_THEME=\"sepia\": expected auto, dark or light"
    );
    // A command that draws nothing refuses the option, and ignores the variable.
    let out = run(&["simulate", "--theme", "dark"], None);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("--theme"));
    assert!(run(&["simulate"], Some("sepia")).status.success());
}
