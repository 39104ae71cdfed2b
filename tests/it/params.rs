//! The parameter table round trip: every scene parameter given on the command line
//! survives CLI → scene → preset file → scene unchanged, and every option that the
//! table lists exists on the command line with its range in `--help`.

use clap::{CommandFactory, Parser};
use groovelab::cli::Cli;
use groovelab::input::params::{Key, PARAMS, SceneSpec};
use groovelab::input::preset::{Origin, Preset, to_toml};
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
    #![proptest_config(ProptestConfig::with_cases(200))]

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
        let back = Preset::parse(&text, "round-trip", Origin::BuiltIn).unwrap();
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
    let p = Preset::parse(&text, "x", Origin::BuiltIn).unwrap();
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
        assert_eq!(arg.get_help().map(|h| h.to_string()), Some(p.help.into()));
        assert!(help.contains(p.help), "--help shows {}", p.flag);
    }
}
