//! Golden JSON of every built-in preset: the output is recorded (insta), and its
//! numbers are checked against the closed forms and conservation laws, so a recorded
//! value is never trusted just because the program printed it.

use groovelab::cli::{SimulateArgs, SimulateFormat, simulate};
use groovelab::physics::closed_form as cf;
use groovelab::physics::model;
use groovelab::settings::spec::SceneSpec;
use groovelab::study::preset::Preset;
use groovelab::tui::app::Library;
use serde_json::Value;

use crate::common::scene_of;

fn run_json(preset: &str) -> Value {
    let args = scene_of(preset, SceneSpec::default());
    let out = simulate(
        &args,
        &SimulateArgs {
            format: SimulateFormat::Json,
            sample: None,
            method: groovelab::methods::Method::Exact,
            dt: None,
            tol: None,
            epsilon: None,
            output: None,
        },
    )
    .unwrap();
    serde_json::from_str(&out).unwrap()
}

/// Floats rounded to 9 significant digits, so the snapshot pins the physics, not the
/// last bits of rounding.
fn rounded(v: &Value) -> Value {
    match v {
        Value::Number(n) if n.is_f64() => {
            let f = n.as_f64().unwrap();
            let r: f64 = format!("{f:.8e}").parse().unwrap();
            serde_json::json!(r)
        }
        Value::Array(a) => Value::Array(a.iter().map(rounded).collect()),
        Value::Object(o) => Value::Object(o.iter().map(|(k, v)| (k.clone(), rounded(v))).collect()),
        other => other.clone(),
    }
}

fn f(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

fn events<'a>(doc: &'a Value, kind: &str) -> Vec<&'a Value> {
    doc["events"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|e| e["kind"] == kind)
        .collect()
}

#[test]
fn golden_json_of_every_preset() {
    for preset in Preset::built_in() {
        let doc = run_json(&preset.name);
        insta::assert_snapshot!(
            format!("simulate-json-{}", preset.name),
            serde_json::to_string_pretty(&rounded(&doc)).unwrap()
        );
    }
}

/// The symmetric presets against the paper's closed forms.
#[test]
fn symmetric_presets_match_the_closed_forms() {
    for name in [
        "paper-b3.5",
        "paper-b4.4",
        "paper-b4.9",
        "flat-table",
        "critical",
        "inelastic",
    ] {
        let doc = run_json(name);
        let sc = &doc["scene"];
        let (radius, width, mu, g, e) = (
            f(&sc["radius"]),
            f(&sc["width"]),
            f(&sc["mu"]),
            f(&sc["g"]),
            f(&sc["restitution"]),
        );
        let v0 = f(&sc["left"]["v0"]);
        assert_eq!(sc["left"], sc["right"], "{name} is symmetric");
        let k = cf::contact_ratio(radius, width);
        let d = &doc["derived"];
        assert_close!(f(&d["k"]), k, 1e-15, 0.0, "{name} k");
        assert_close!(f(&d["D"]), cf::determinant(k), 1e-15, 0.0, "{name} D");
        assert_close!(
            f(&d["b_star"]),
            cf::critical_width(radius, e).unwrap(),
            1e-15,
            0.0,
            "{name} b*"
        );
        let vp = cf::v_roll(k, e, v0);
        let regime = if vp.abs() < 1e-12 * v0 {
            "rest"
        } else if vp > 0.0 {
            "recollide"
        } else {
            "depart"
        };
        assert_eq!(d["regime"], regime, "{name}");
        // First impact: velocities reverse times e, spins unchanged.
        let first = &doc["events"][0];
        assert_eq!(first["kind"], "collision");
        assert_close!(f(&first["left"]["v"]), -e * v0, 1e-15, 0.0, "{name}");
        assert_close!(f(&first["left"]["u"]), v0, 1e-15, 0.0, "{name}");
        // Rolling again (or rest, at b*) at t' with v'.
        let again = doc["events"]
            .as_array()
            .unwrap()
            .iter()
            .find(|e| (e["kind"] == "rolling" || e["kind"] == "rest") && e["ball"] == "left")
            .unwrap();
        assert_close!(
            f(&again["t"]),
            cf::t_roll(k, e, v0, mu, g),
            1e-12,
            0.0,
            "{name} t'"
        );
        assert_close!(f(&again["left"]["v"]), vp, 1e-12, v0, "{name} v'");
        match cf::accumulation_time(k, e, v0, mu, g) {
            Some(t) => assert_close!(
                f(&doc["summary"]["accumulation_time"]),
                t,
                1e-9,
                0.0,
                "{name} T∞"
            ),
            None => assert!(doc["summary"]["accumulation_time"].is_null(), "{name}"),
        }
        // Energy books: nothing grows, everything lost is accounted for.
        let (e0, e1) = (
            &doc["summary"]["energy_start"],
            &doc["summary"]["energy_end"],
        );
        let total = |s: &Value| {
            f(&s["translational"])
                + f(&s["rotational"])
                + f(&s["lost"]["friction"])
                + f(&s["lost"]["impacts"])
                + f(&s["lost"]["rolling_resistance"])
        };
        assert_close!(total(e1), total(e0), 1e-12, 0.0, "{name} energy");
        if e == 1.0 {
            assert_eq!(
                f(&e1["lost"]["impacts"]),
                0.0,
                "{name}: elastic impacts lose nothing"
            );
        }
    }
}

#[test]
fn unequal_presets_conserve_momentum_and_end_as_physics_says() {
    // Equal masses, e = 1: the balls swap velocities; later impacts accumulate and the
    // pair rolls on together at one speed.
    let doc = run_json("unequal-speeds");
    let first = &doc["events"][0];
    let (vl, vr) = (
        f(&doc["scene"]["left"]["v0"]),
        f(&doc["scene"]["right"]["v0"]),
    );
    assert_close!(f(&first["left"]["v"]), -vr, 1e-15, 0.0, "swap");
    assert_close!(f(&first["right"]["v"]), vl, 1e-15, 0.0, "swap");
    let last = doc["events"].as_array().unwrap().last().unwrap();
    assert_eq!(last["kind"], "zeno_contact");
    assert_eq!(last["left"]["v"], last["right"]["v"]);
    assert_eq!(last["left"]["v"], last["left"]["u"], "rolling");
    assert!(
        f(&last["left"]["v"]) > 0.0,
        "drifting right, as the faster left ball pushed"
    );
    // The pair cannot end faster than its mean speed after the first impact: friction
    // only ever brakes the centre of mass of two sliding balls or leaves it alone.
    assert!(f(&last["left"]["v"]) <= 0.5 * (vl - vr) + 1e-12);
    assert!(events(&doc, "collision").len() > 3, "repeated impacts");

    // Unequal masses: the first impact follows Newton's law with e.
    let doc = run_json("steel-and-glass");
    let sc = &doc["scene"];
    let (ml, mr, e) = (
        f(&sc["left"]["mass"]),
        f(&sc["right"]["mass"]),
        f(&sc["restitution"]),
    );
    let (vl, vr) = (f(&sc["left"]["v0"]), -f(&sc["right"]["v0"]));
    let (wl, wr) = model::impact(ml, mr, vl, vr, e);
    let first = &doc["events"][0];
    assert_close!(f(&first["left"]["v"]), wl, 1e-15, 0.0, "left after");
    assert_close!(f(&first["right"]["v"]), wr, 1e-15, 0.0, "right after");
    assert_close!(ml * wl + mr * wr, ml * vl + mr * vr, 1e-14, 0.0, "momentum");
    let lost = f(&doc["summary"]["energy_end"]["lost"]["impacts"]);
    assert_close!(
        lost,
        model::impact_loss(ml, mr, vl, vr, e),
        1e-12,
        0.0,
        "impact loss"
    );
}

#[test]
fn paper_presets_carry_the_measured_series() {
    let data = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("data");
    for width in ["3.5", "4.4", "4.9"] {
        let preset = groovelab::input::preset::load(&format!("paper-b{width}")).unwrap();
        let measured = preset.measured.expect("measured data");
        assert!(preset.source.unwrap().contains("Gröber"));
        // v0 is the mean measured v_cm before the impact.
        let before: Vec<f64> = measured
            .t()
            .iter()
            .zip(measured.v_cm())
            .filter(|(t, _)| **t < 0.0)
            .map(|(_, v)| *v)
            .collect();
        let mean = before.iter().sum::<f64>() / before.len() as f64;
        let (scene, _) = preset.spec.resolve().unwrap();
        assert!(
            (scene.left.v0 - mean).abs() <= 5.1e-5,
            "b = {width}: v0 is the mean to 4 decimals"
        );
        // Same numbers as the paper's data files in data/; a missing file is a
        // failure, never a silent skip.
        let csv = data.join(format!("gs-b{width}cm.csv"));
        let text = std::fs::read_to_string(&csv).unwrap_or_else(|e| {
            panic!("{}: {e}; the paper's data must be in data/", csv.display())
        });
        let rows: Vec<Vec<f64>> = text
            .lines()
            .skip(1)
            .map(|l| l.split(',').map(|x| x.parse().unwrap()).collect())
            .collect();
        assert_eq!(rows.len(), measured.t().len());
        for (i, row) in rows.iter().enumerate() {
            assert_eq!(
                [row[0], row[1], row[2]],
                [measured.t()[i], measured.v_cm()[i], measured.v_t()[i]]
            );
        }
    }
}

#[test]
fn presets_marks_a_user_preset_that_a_built_in_one_hides() {
    let dir = crate::common::scratch_dir("physics", "hidden-preset");
    let text = std::fs::read_to_string("presets/paper-b4.9.toml").unwrap();
    std::fs::write(dir.join("paper-b4.9.toml"), text).unwrap();
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_groovelab"))
        .arg("presets")
        .env("GROOVELAB_PRESETS", &dir)
        .output()
        .unwrap();
    let list = String::from_utf8_lossy(&out.stdout);
    let lines: Vec<&str> = list
        .lines()
        .filter(|l| l.starts_with("paper-b4.9 "))
        .collect();
    assert_eq!(lines.len(), 2, "{list}");
    // `--preset paper-b4.9` loads the built-in one: the file's line says so.
    assert!(!lines[0].contains("hidden"), "{}", lines[0]);
    assert!(
        lines[1].contains("hidden: --preset paper-b4.9 is the built-in one"),
        "{}",
        lines[1]
    );
    // The app's picker lists both too, and tells the file's row from the built-in's.
    let mut app = crate::common::app("paper-b4.9", Library::at(Some(dir.clone())));
    crate::common::press(&mut app, "p");
    for ascii in [false, true] {
        let screen = crate::common::text(&app, (120, 40), ascii);
        let rows: Vec<&str> = screen
            .lines()
            .filter(|l| l.contains("paper-b4.9  "))
            .collect();
        assert_eq!(rows.len(), 2, "{screen}");
        assert!(!rows[0].contains("[your file"), "{}", rows[0]);
        assert!(
            rows[1].contains("  [your file, named like a built-in] Paper"),
            "{}",
            rows[1]
        );
    }
    let _ = std::fs::remove_dir_all(&dir);
}
