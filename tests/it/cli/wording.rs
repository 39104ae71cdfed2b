//! What error lines and notes say to a new user: echoed text cut to a sane length,
//! numbers rounded, the same names and origins in every command.

use crate::common::{groovelab, scratch_dir};

/// The `error:` line of a command that must fail with status 2.
fn refusal(args: &[&str]) -> String {
    let out = groovelab(args);
    assert_eq!(out.status.code(), Some(2), "{args:?} should be refused");
    let err = String::from_utf8(out.stderr).unwrap();
    assert!(err.starts_with("error: "), "{err}");
    err
}

#[test]
fn a_five_megabyte_cell_is_not_echoed_whole() {
    let dir = scratch_dir("wording", "long_cell");
    let file = dir.join("longline.csv");
    let cell = "1".repeat(5_000_000);
    std::fs::write(&file, format!("t,v_cm,v_t\n0,{cell},0\n")).unwrap();
    let err = refusal(&["data", file.to_str().unwrap()]);
    assert!(err.len() < 500, "{} bytes", err.len());
    assert!(err.contains("v_cm = '1111") && err.contains("…'"), "{err}");
}

#[test]
fn a_long_option_value_is_cut_in_the_error_line() {
    let long = format!("{}x", "9".repeat(10_000));
    for args in [
        vec!["simulate", "--v0", &long],
        vec!["simulate", "--preset", &long],
        vec!["fit", "--track", &long],
    ] {
        let err = refusal(&args);
        assert!(err.len() < 600, "{args:?}: {} bytes", err.len());
        assert!(err.contains("…"), "{err}");
    }
}

#[test]
fn a_negative_width_names_the_value_of_2r() {
    let err = refusal(&["simulate", "--radius", "2.75cm", "--width", "-1cm"]);
    assert!(err.contains("allowed 0 ≤ b < 2R = 5.5 cm"), "{err}");
}

#[test]
fn a_computed_width_is_rounded_in_the_scene_line_but_stays_below_2r() {
    use groovelab::settings::units::{Dimension, show_below};
    // b* of the critical preset: many digits, shown as four.
    assert_eq!(
        show_below(0.04260281680828159, 0.055, Dimension::Length),
        "4.26 cm"
    );
    // Four digits would read 5.5 cm = 2R: more are kept.
    assert_eq!(show_below(0.054999, 0.055, Dimension::Length), "5.4999 cm");
}

#[test]
fn a_given_impact_time_without_an_impact_is_called_the_given_time() {
    let dir = scratch_dir("wording", "given_impact");
    let file = dir.join("steady.csv");
    // A ball rolling steadily at 0.25 m/s: no impact anywhere.
    let rows: String = (0..100)
        .map(|i| {
            let t = f64::from(i) * 0.01;
            format!("{t},{},0\n", 0.25 * t)
        })
        .collect();
    std::fs::write(&file, format!("t,x,y\n{rows}")).unwrap();
    let out = groovelab(&["data", file.to_str().unwrap(), "--impact-at", "0.5"]);
    let text =
        String::from_utf8_lossy(&out.stdout).to_string() + &String::from_utf8_lossy(&out.stderr);
    assert!(
        text.contains("no impact at the time --impact-at gives, t = 0.5000 s"),
        "{text}"
    );
    assert!(!text.contains("sharpest change"), "{text}");
}

#[test]
fn a_mass_is_named_as_the_panel_names_it_in_every_error() {
    let range = refusal(&["simulate", "--mass-right", "1e308g"]);
    assert!(range.contains("m right = 1e308 g"), "{range}");
}

/// Every b printed beside a groove just under 2R, typed back as the width, is a
/// groove the program accepts: `simulate`'s changed-preset, scene and data lines, its
/// b/R, and the app's parameter panel. They printed "b = 5.5 cm" of
/// 5.4999999 cm, beside "0 ≤ b < 2R = 5.5 cm" when 5.5 cm is typed.
#[test]
fn a_width_just_under_2r_is_printed_as_a_width_the_program_takes() {
    use crate::common::run_in_process;
    // (R, b) in cm: b under 2R by 1e-7 … 1e-3 relative, at two radii.
    for (r, b) in [
        (2.75, 5.4999999),
        (2.75, 5.49999),
        (2.75, 5.4998),
        (1.0, 1.9999998),
    ] {
        let (radius, width) = (format!("{r}cm"), format!("{b}cm"));
        let scene = [
            "--preset",
            "paper-b4.9",
            "--radius",
            &radius,
            "--width",
            &width,
        ];
        let said = run_in_process(&[&["simulate"][..], &scene].concat()).unwrap();
        let screen =
            run_in_process(&[&["render", "--size", "120x40"][..], &scene].concat()).unwrap();
        let mut widths: Vec<String> = Vec::new();
        // The text after `line`'s first `b = ` (after its start `line` itself for
        // the panel's row).
        for (text, line, b_at) in [
            (&said, "changed by the options:", "b = "),
            (&said, "scene    R = ", "b = "),
            (&said, "the model uses ", "b = "),
            (&screen, "▸b", "▸b"),
        ] {
            let at = text.find(line).unwrap_or_else(|| panic!("{line}: {text}"));
            let rest = &text[at..];
            let rest = &rest[rest.find(b_at).unwrap() + b_at.len()..];
            widths.push(rest.split_whitespace().next().unwrap().to_string());
        }
        for w in &widths {
            let typed = format!("{w}cm");
            let args = [
                "simulate",
                "--preset",
                "paper-b4.9",
                "--radius",
                &radius,
                "--width",
                &typed,
            ];
            assert!(
                run_in_process(&args).is_ok(),
                "R = {r} cm, b = {b} cm printed as {w}: {widths:?}"
            );
        }
        let ratio = said
            .split("b/R = ")
            .nth(1)
            .unwrap()
            .split(',')
            .next()
            .unwrap();
        assert!(ratio.parse::<f64>().unwrap() < 2.0, "b/R = {ratio}");
    }
}
