//! Regime maps: the boundary where physics.md puts it, the same bytes whatever the
//! thread count, and agreement with single runs.

use std::process::Command;
use std::sync::atomic::AtomicBool;

use groovelab::physics::closed_form;
use groovelab::physics::derived::Regime;
use groovelab::settings::params::Key;
use groovelab::settings::spec::SceneSpec;
use groovelab::study::sweep::{self, GridPoint, SweepError};

use crate::common::groovelab;

fn base(preset: &str) -> SceneSpec {
    groovelab::input::preset::load(preset).unwrap().spec
}

fn map(spec: &SceneSpec, x: &str, y: Option<&str>, nx: usize, ny: usize) -> Vec<GridPoint> {
    let x = sweep::parse_axis(x, nx).unwrap();
    let y = y.map(|y| sweep::parse_axis(y, ny).unwrap());
    sweep::run(spec, &x, y.as_ref(), &AtomicBool::new(false), &|| {}).unwrap()
}

#[test]
fn the_boundary_is_b_star_of_e_within_one_cell() {
    let spec = base("paper-b4.9");
    let (nx, ny) = (120, 60);
    let points = map(&spec, "width=0..5.4cm", Some("restitution=0.3..1"), nx, ny);
    let dx = 0.054 / (nx - 1) as f64;
    let radius = spec.get(Key::Radius).unwrap();
    for row in points.chunks(nx) {
        let e = row[0].y.unwrap();
        match closed_form::critical_width(radius, e) {
            None => assert!(row.iter().all(|p| p.regime == Regime::Recollide), "e = {e}"),
            Some(b) => {
                for p in row {
                    // Everything more than one cell from b* is on its side of it.
                    if p.x < b - dx {
                        assert_eq!(p.regime, Regime::Depart, "e = {e}, b = {}", p.x);
                    } else if p.x > b + dx {
                        assert_eq!(p.regime, Regime::Recollide, "e = {e}, b = {}", p.x);
                    }
                }
                // And the switch happens there.
                let first = row.iter().position(|p| p.regime != Regime::Depart).unwrap();
                assert!(
                    (row[first].x - b).abs() <= dx,
                    "e = {e}: switch at {} vs b* {b}",
                    row[first].x
                );
            }
        }
    }
}

#[test]
fn one_thread_or_many_give_the_same_map() {
    let spec = base("unequal-speeds");
    let run = |threads| {
        rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap()
            .install(|| map(&spec, "width=1..5.4cm", Some("mu=0.05..0.5"), 60, 30))
    };
    let one = run(1);
    let four = run(4);
    assert_eq!(one.len(), 1800);
    assert_eq!(one, four);
    // Grid order: y outer, x inner.
    assert!(one[0].x < one[1].x && one[0].y == one[1].y);
    assert!(one[60].y > one[0].y);
}

#[test]
fn points_agree_with_single_simulate_runs() {
    let spec = base("unequal-speeds");
    let points = map(&spec, "width=2..5cm", Some("v0_right=0.1..0.8"), 7, 5);
    for p in points.iter().step_by(6) {
        let out = Command::new(env!("CARGO_BIN_EXE_groovelab"))
            .args([
                "simulate",
                "--preset",
                "unequal-speeds",
                "--width",
                &format!("{}", p.x),
                "--v0-right",
                &format!("{}", p.y.unwrap()),
                "--format",
                "json",
            ])
            .output()
            .unwrap();
        assert!(out.status.success());
        let doc: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
        assert_eq!(doc["derived"]["regime"], p.regime.name(), "{p:?}");
        assert_eq!(
            doc["summary"]["impacts"].as_u64().unwrap() as usize,
            p.impacts,
            "{p:?}"
        );
        match p.t_accumulation {
            Some(t) => {
                let s = doc["summary"]["accumulation_time"].as_f64().unwrap();
                assert!((s - t).abs() <= 1e-12 * t.abs().max(1.0), "{p:?}");
            }
            None => assert!(doc["summary"]["accumulation_time"].is_null()),
        }
        let v = doc["derived"]["left_after_impact"]["v_roll"]
            .as_f64()
            .unwrap();
        let v0 = doc["scene"]["left"]["v0"].as_f64().unwrap();
        assert!((v / v0 - p.v_ratio.unwrap()).abs() < 1e-12, "{p:?}");
    }
}

#[test]
fn a_stop_request_leaves_no_partial_map() {
    let spec = base("paper-b4.9");
    let x = sweep::parse_axis("width=0..5cm", 50).unwrap();
    let stop = AtomicBool::new(true);
    assert_eq!(
        sweep::run(&spec, &x, None, &stop, &|| {}),
        Err(SweepError::Interrupted)
    );
}

#[test]
fn csv_follows_the_interface_and_bad_grids_are_refused() {
    let out = groovelab(&["sweep", "--x", "width=3..5cm", "--grid", "5"]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8(out.stdout).unwrap();
    let mut lines = text.lines();
    assert_eq!(
        lines.next(),
        Some("x,y,regime,v_ratio,t_roll,impacts,t_accumulation")
    );
    let rows: Vec<&str> = lines.collect();
    assert_eq!(rows.len(), 5);
    assert!(rows[0].starts_with("0.03,,depart,"), "{}", rows[0]);
    assert!(rows[4].starts_with("0.05,,recollide,"), "{}", rows[4]);
    for (args, want) in [
        (&["sweep", "--x", "width=0..6cm"][..], "b < 2R"),
        (&["sweep", "--x", "colour=0..1"][..], "unknown parameter"),
        (
            &["sweep", "--x", "width=0..5cm", "--grid", "0x3"][..],
            "--grid",
        ),
        (
            &["sweep", "--x", "width=0..5cm", "--grid", "abc"][..],
            "--grid",
        ),
        (&["sweep", "--x", "width=5..1cm"][..], "backwards"),
        (&["sweep", "--x", "mu=-1..1"][..], "0 ≤ μ_k"),
        (&["sweep"][..], "--x"),
    ] {
        let out = groovelab(args);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
        assert!(out.stdout.is_empty());
        assert!(
            err.starts_with("error: ") && err.contains(want),
            "{args:?}: {err}"
        );
    }
}

/// `--x width … --y width …` printed each row's b = 0 result under the row's x values
/// (the second axis overwrote the first): one line, exit 2, nothing on stdout.
#[test]
fn one_parameter_on_both_axes_is_refused() {
    let out = groovelab(&[
        "sweep",
        "--x",
        "width=0..5cm",
        "--y",
        "width=0..5cm",
        "--grid",
        "3x2",
    ]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(out.stdout.is_empty());
    assert_eq!(
        err,
        "error: --y width is the other axis's parameter already, allowed a parameter other than width\n"
    );
}

/// `--x v0 … --y height …` dropped v0 (a release height replaces the speed, as
/// `simulate` refuses the pair), and `mass` against `mass_left` half of mass: each is
/// one line, exit 2; the library refuses them too.
#[test]
fn axes_that_overwrite_each_other_are_refused() {
    for (x, y, want) in [
        (
            "v0=0.1..1",
            "height=1cm..2cm",
            "error: --y height would overwrite what the other axis, v0, sets (height_left replaces v0_left), allowed a parameter that sets other values\n",
        ),
        (
            "height=1cm..2cm",
            "v0_right=0.1..1",
            "error: --y v0_right would overwrite what the other axis, height, sets (height_right replaces v0_right), allowed a parameter that sets other values\n",
        ),
        (
            "mass=1g..2g",
            "mass-left=1g..2g",
            "error: --y mass_left would overwrite what the other axis, mass, sets (both set mass_left), allowed a parameter that sets other values\n",
        ),
    ] {
        let out = groovelab(&["sweep", "--x", x, "--y", y, "--grid", "3x2"]);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{x} {y}: {err}");
        assert!(out.stdout.is_empty(), "{x} {y}");
        assert_eq!(err, want);
    }
    let spec = base("paper-b4.9");
    let x = sweep::parse_axis("v0=0.1..1", 3).unwrap();
    let y = sweep::parse_axis("height=1cm..2cm", 2).unwrap();
    let refused = sweep::run(&spec, &x, Some(&y), &AtomicBool::new(false), &|| {});
    assert!(matches!(refused, Err(SweepError::Axes(_))), "{refused:?}");
    // Parameters of different values still make a map.
    let y = sweep::parse_axis("mass_left=1g..2g", 2).unwrap();
    let x = sweep::parse_axis("v0_right=0.1..1", 2).unwrap();
    assert!(sweep::check_pair(&x, &y).is_ok());
}
