//! The parameter table round trip: every scene parameter given on the command line
//! survives CLI → scene → preset file → scene unchanged, every option that the table
//! lists exists on the command line with its range and default in `--help`, and every
//! row's get and set, default and display unit hold.

use clap::{CommandFactory, Parser};
use groovelab::cli::Cli;
use groovelab::physics::scene::{Scene, Span};
use groovelab::settings::params::{Fallback, Key, PARAMS, Param};
use groovelab::settings::spec::SceneSpec;
use groovelab::settings::units::{parse_quantity, parse_typed, show};
use groovelab::study::preset::{self, Preset, PresetOrigin, to_toml};
use proptest::prelude::*;

/// A scene given entirely on the command line (SI numbers, as `{:?}` prints them).
fn cli_scene(values: &[(Key, f64)]) -> (groovelab::physics::scene::Scene, SceneSpec) {
    let mut argv = vec!["groovelab".to_string(), "simulate".to_string()];
    for (k, v) in values {
        argv.push(format!("--{}", k.param().flag));
        argv.push(format!("{v:?}"));
    }
    let cli = Cli::try_parse_from(&argv).unwrap_or_else(|e| panic!("{argv:?}: {e}"));
    let (_, scene, span) = cli
        .scene
        .resolve()
        .unwrap_or_else(|e| panic!("{argv:?}: {e}"));
    (scene, SceneSpec::of(&scene, &span))
}

proptest! {
    #![proptest_config(crate::common::cases(200))]

    #[test]
    fn every_parameter_survives_cli_scene_preset_scene(
        radius in 0.001f64..0.5,
        b_over_2r in 0.0f64..0.999,
        mass_left in 1e-6f64..1000.0,
        mass_right in 1e-6f64..1000.0,
        mu in 0.0f64..10.0,
        v0_left in 0.0f64..100.0,
        v0_right in 0.0f64..100.0,
        restitution in 0.0f64..=1.0,
        rolling_resistance in 0.0f64..1.0,
        g in 0.01f64..1000.0,
        t_start in -1000.0f64..=0.0,
        t_end in 0.001f64..1e6,
    ) {
        let values = [
            (Key::Radius, radius),
            (Key::Width, b_over_2r * 2.0 * radius),
            (Key::MassLeft, mass_left),
            (Key::MassRight, mass_right),
            (Key::Mu, mu),
            (Key::V0Left, v0_left),
            (Key::V0Right, v0_right),
            (Key::Restitution, restitution),
            (Key::RollingResistance, rolling_resistance),
            (Key::G, g),
            (Key::TStart, t_start),
            (Key::TEnd, t_end),
        ];
        let (scene, spec) = cli_scene(&values);
        // Every value arrives as the very double given.
        for (k, v) in values {
            prop_assert_eq!(spec.get(k), Some(v), "{:?}", k);
        }
        let text = to_toml("round-trip", "d", &spec, None).unwrap();
        let back = Preset::parse(&text, "round-trip", PresetOrigin::BuiltIn).unwrap();
        let (again, span) = back.spec.resolve().unwrap();
        prop_assert_eq!(again, scene);
        prop_assert_eq!(span.t_end, Some(t_end));
        prop_assert_eq!(span.t_start, t_start);
    }
}

#[test]
fn a_release_height_survives_as_the_speed_it_gives() {
    let (scene, spec) = cli_scene(&[(Key::Height, 0.05)]);
    assert_eq!(scene.left.v0, scene.right.v0);
    assert_eq!(spec.get(Key::V0Left), Some(scene.left.v0));
}

#[test]
fn names_with_quotes_and_newlines_make_loadable_files() {
    let spec = SceneSpec::default().with(Key::Radius, 0.02);
    let text = to_toml("a \"quoted\"\nname", "it's \"fine\"", &spec, None).unwrap();
    let p = Preset::parse(&text, "x", PresetOrigin::BuiltIn).unwrap();
    assert_eq!(p.name, "a \"quoted\"\nname");
    assert_eq!(p.spec.get(Key::Radius), Some(0.02));
}

#[test]
fn every_table_row_is_an_option_with_its_help() {
    let cmd = Cli::command();
    let help = cmd.clone().render_long_help().to_string();
    for p in &PARAMS {
        let arg = cmd
            .get_arguments()
            .find(|a| a.get_long() == Some(p.flag))
            .unwrap_or_else(|| panic!("--{} is missing", p.flag));
        assert_eq!(arg.get_help().map(|h| h.to_string()), Some(p.help_text()));
        assert!(help.contains(&p.help_text()), "--help shows {}", p.flag);
    }
    // The defaults as `--help` has always written them.
    for (key, text) in [
        (Key::Restitution, "[default: 1]"),
        (Key::RollingResistance, "[default: 0]"),
        (Key::G, "[default: 9.81 m/s²]"),
        (Key::TStart, "[default: -0.2 s]"),
    ] {
        assert!(key.param().help_text().ends_with(text), "{key:?}");
    }
}

/// The default preset's scene and span, with its end fixed (so `t_end` has a value).
fn base() -> (Scene, Span) {
    let p = groovelab::input::preset::load(preset::DEFAULT).unwrap();
    let (scene, span) = p.spec.resolve().unwrap();
    (
        scene,
        Span {
            t_end: Some(span.t_end.unwrap_or(1.5)),
            ..span
        },
    )
}

/// Values of `p` to try on the base scene: inside its range and this scene's
/// relations (b < 2R, t_end > t_start), away from the current value.
fn trial_values(p: &Param, scene: &Scene, span: &Span) -> Vec<f64> {
    let now = (p.get)(scene, span).unwrap();
    let (lo, hi) = match p.key {
        Key::Width => (0.0, 2.0 * scene.radius),
        Key::TEnd => (span.t_start, 10.0),
        // Speeds toward the impact (the balls must close), heights to a lab's size.
        Key::V0 | Key::V0Left | Key::V0Right => (0.0, 5.0),
        Key::Height | Key::HeightLeft | Key::HeightRight => (0.0, 2.0),
        _ => (p.range.lo, p.range.hi.min(100.0)),
    };
    [0.1, 0.5, 0.9]
        .into_iter()
        .map(|f| lo + f * (hi - lo))
        .chain([now])
        .collect()
}

fn close(a: f64, b: f64) -> bool {
    // The heights go through a square root and back (release speed, release height).
    (a - b).abs() <= 1e-12 * a.abs().max(b.abs()).max(1e-300)
}

#[test]
fn every_row_reads_back_what_it_writes_through_scene_layer_cli_and_preset() {
    let (scene, span) = base();
    for p in &PARAMS {
        for v in trial_values(p, &scene, &span) {
            // set then get, on the scene itself.
            let (mut s, mut t) = (scene, span);
            (p.set)(&mut s, &mut t, v);
            let got = (p.get)(&s, &t).unwrap();
            assert!(close(got, v), "{}: set {v}, got {got}", p.name);
            // The keys it sets say the same (mass sets both masses).
            for k in p.sets {
                let each = k.get(&s, &t).unwrap();
                assert!(close(each, v), "{} via {k:?}: {each} vs {v}", p.name);
            }
            // Through a settings layer and its checks.
            let layer = SceneSpec::of(&scene, &span).with(p.key, v);
            let (a, b) = layer
                .resolve()
                .unwrap_or_else(|e| panic!("{} = {v}: {e}", p.name));
            assert!(close(p.key.get(&a, &b).unwrap(), v), "{} = {v}", p.name);
            // Through the command line: the same scene.
            let mut argv: Vec<String> = vec!["groovelab".into(), "simulate".into()];
            for (k, x) in SceneSpec::of(&scene, &span).given() {
                let contradicts = p.sets.contains(&k) || p.conflicts().any(|q| q.key == k);
                if !contradicts {
                    argv.extend([format!("--{}", k.param().flag), format!("{x:?}")]);
                }
            }
            argv.extend([format!("--{}", p.flag), format!("{v:?}")]);
            let cli = Cli::try_parse_from(&argv).unwrap_or_else(|e| panic!("{argv:?}: {e}"));
            let (_, c, d) = cli.scene.resolve().unwrap();
            assert_eq!((c, d), (a, b), "{argv:?}");
            // Through a preset file and back: the same scene.
            let text = to_toml("x", "d", &SceneSpec::of(&a, &b), None).unwrap();
            let back = Preset::parse(&text, "x", PresetOrigin::BuiltIn).unwrap();
            assert_eq!(back.spec.resolve().unwrap(), (a, b), "{}", p.name);
        }
    }
}

#[test]
fn every_default_is_what_a_layer_without_the_value_gets() {
    let (scene, span) = base();
    let full = SceneSpec::of(&scene, &span);
    for p in PARAMS.iter().filter(|p| p.is_own()) {
        let mut without = SceneSpec::default();
        for (k, v) in full.given().filter(|(k, _)| *k != p.key) {
            without.set(k, v);
        }
        let got = without.resolve();
        match p.default {
            Fallback::Value(d) => {
                let (a, b) = got.unwrap_or_else(|e| panic!("{}: {e}", p.name));
                assert_eq!(p.key.get(&a, &b), Some(d), "{}", p.name);
            }
            Fallback::Required => {
                let e = got.unwrap_err().to_string();
                assert!(e.contains(&format!("--{}", p.flag)), "{}: {e}", p.name);
            }
            // A height is only a way to give a speed; no t_end: the span follows the run.
            Fallback::Optional => {
                let (a, b) = got.unwrap_or_else(|e| panic!("{}: {e}", p.name));
                assert_eq!(a, scene, "{}", p.name);
                if p.key == Key::TEnd {
                    assert_eq!(b.t_end, None);
                }
            }
        }
    }
}

#[test]
fn every_row_is_shown_and_typed_in_its_display_unit() {
    let (scene, span) = base();
    for p in &PARAMS {
        let (unit, shift) = p.dim.display_unit();
        for v in trial_values(p, &scene, &span) {
            let shown = show(v, p.dim).to_string();
            assert!(shown.ends_with(&p.dim.suffix()), "{}: {shown}", p.name);
            // The display unit's number, written with the unit or bare in the app,
            // reads back as the value (to the printed digits).
            let number = p.dim.to_display(v);
            assert!(close(number, v * 10f64.powi(-shift)), "{}", p.name);
            let written = format!("{number:?}{unit}");
            let back = parse_quantity(&written, p.dim).unwrap();
            assert!(close(back, v), "{}: {written} → {back}", p.name);
            let panel = p.dim.panel_number(v);
            let typed = parse_typed(&panel, p.dim).unwrap();
            let half_digit = 0.5 * 10f64.powi(shift) * digit_of(&panel);
            assert!(
                (typed - v).abs() <= half_digit * (1.0 + 1e-9),
                "{}: {panel}",
                p.name
            );
        }
    }
}

/// The value of the last printed digit of `text` (0.01 for "4.90"), or for four
/// significant digits without a point, 1.
fn digit_of(text: &str) -> f64 {
    match text.split_once('.') {
        Some((_, d)) => 10f64.powi(-(d.len() as i32)),
        None => 1.0,
    }
}
