//! Issue 37's small words, each where it is made: the SVG exports in the screen's
//! signs with measured v_cm and v_t in two colours, …

use groovelab::lab::Lab;

use crate::common;
use groovelab::study::figures::{Beside, RunChart, run_chart};

/// The stroke colours of the SVG elements of `kind` (`<circle`, `<line`).
fn colours_of_marks(svg: &str, kind: &str) -> std::collections::BTreeSet<String> {
    svg.lines()
        .filter(|l| l.trim_start().starts_with(kind))
        .filter_map(|l| {
            let at = l.find("stroke=\"")? + 8;
            Some(l[at..].split('"').next()?.to_string())
        })
        .collect()
}

#[test]
fn the_run_chart_gives_measured_v_cm_and_v_t_their_own_colours_and_the_screens_signs() {
    let preset = groovelab::input::preset::load("paper-b4.9").unwrap();
    let measured = preset.measured.clone().unwrap();
    let lab = Lab::of_preset(preset).unwrap();
    let which = RunChart::Velocities {
        left: true,
        right: false,
    };
    let svg = run_chart(&lab.solution, which, Some(&measured), Beside::default()).unwrap();
    // Measured v_cm: crosses, each two `<line>`s; measured v_t: `<circle>`s (the
    // model's curves are polylines). Before, both marks were red.
    let circles = colours_of_marks(&svg, "<circle");
    let lines = colours_of_marks(&svg, "<line");
    assert_eq!(circles.len(), 1, "v_t circles in one colour: {circles:?}");
    assert!(
        lines.is_disjoint(&circles),
        "v_t's colour {circles:?} is also the crosses' or another line's: {lines:?}"
    );
    assert!(svg.contains("μ_k = ") && !svg.contains("mu_k") && !svg.contains("mu ="));
}

#[test]
fn microseconds_are_typed_as_us_wherever_a_time_is() {
    use groovelab::settings::units::{Dimension, parse_option};
    for text in ["100us", "100 us", "100µs", "100μs", "0.1ms"] {
        let t = parse_option(text, Dimension::Time).unwrap();
        assert!((t - 1e-4).abs() < 1e-18, "{text}: {t}");
    }
    // `--sample 100us` is accepted: one sample every 0.1 ms over the span.
    let out =
        common::run_in_process(&["simulate", "--sample", "100us", "--format", "json"]).unwrap();
    let j: serde_json::Value = serde_json::from_str(&out).unwrap();
    let samples = j["samples"].as_array().unwrap();
    let dt = samples[1]["t"].as_f64().unwrap() - samples[0]["t"].as_f64().unwrap();
    assert!((dt - 1e-4).abs() < 1e-12, "{dt}");
}

#[test]
fn no_energy_reads_minus_zero() {
    // Every built-in scene: its energy line never writes a sign on a zero.
    let presets = groovelab::study::preset::Preset::built_in();
    assert!(presets.len() > 3);
    for p in presets {
        let name = p.name.as_str();
        let out = common::run_in_process(&["simulate", "--preset", name]).unwrap();
        let energy = out.lines().find(|l| l.starts_with("energy")).unwrap();
        assert!(!energy.contains("-0.00000"), "{name}: {energy}");
    }
}

#[test]
fn the_help_popup_keeps_its_corners_off_the_panels() {
    let library = common::no_user_presets("small_words");
    for size in [(80, 24), (120, 40), (200, 60)] {
        let mut a = common::app("paper-b4.9", library.clone());
        common::press(&mut a, "?");
        let screen = common::text(&a, size, false);
        for pair in ["╭╭", "╮╮", "╰╰", "╯╯"] {
            assert!(!screen.contains(pair), "{size:?} {pair}:\n{screen}");
        }
        assert!(screen.contains("Keys  ("), "{screen}");
    }
}

#[test]
fn fit_on_accelerations_only_says_so_before_asking_for_the_scene() {
    let dir = common::scratch_dir("small_words", "accelerations");
    let file = dir.join("phyphox.csv");
    std::fs::write(
        &file,
        "\"Time (s)\",\"Linear Acceleration x (m/s^2)\",\"Linear Acceleration y (m/s^2)\"\n0,0.1,0.2\n0.01,0.1,0.3\n0.02,0.2,0.1\n",
    )
    .unwrap();
    let path = file.to_str().unwrap();
    for command in ["fit", "compare"] {
        let e = common::run_in_process(&[command, "--data", path]).unwrap_err();
        assert!(
            e.contains("accelerations only") && !e.contains("names no scene"),
            "{e}"
        );
    }
    // A fittable file without its scene is still asked for one.
    let csv = dir.join("velocities.csv");
    std::fs::write(
        &csv,
        "t,v_cm,v_t\n0,0.5,0.5\n0.01,0.49,0.48\n0.02,0.48,0.46\n",
    )
    .unwrap();
    let e = common::run_in_process(&["fit", "--data", csv.to_str().unwrap()]).unwrap_err();
    assert!(e.contains("names no scene"), "{e}");
}
