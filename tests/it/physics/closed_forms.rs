//! The engine against every closed form of physics.md, over a grid of symmetric scenes.
//!
//! Two families, split by whether the left ball rolls again before it meets the other
//! ball again. It slides back to the impact place at `2 t_t = 2 k e v0 / (μ g)` and rolls
//! at `t'`; `2 t_t ≥ t'` ⇔ `e (1 + 5k²) ≥ 1`.
//! - Rolling first: t', v', x', t_r or t_t, b*, and the accumulation time `T₁/(1 − ρ)`.
//! - Back first (small e): the impacts repeat with ratio e while the ball still slides,
//!   accumulate at `2 t_t / (1 − e)`, and the pair then presses together until the
//!   spin is gone at `t_r = 2 v0 / (5 k μ g)` (our derivation, same model).

use crate::common;

use groovelab::physics::closed_form as cf;
use groovelab::physics::derived::{Derived, Regime};
use groovelab::physics::engine::solve;
use groovelab::physics::solution::{Event, EventKind, Solution, Who};
use groovelab::settings::params::Key;
use groovelab::settings::spec::SceneSpec;

/// Closed forms and the engine agree to this (physics.md: ~1e-12 relative).
const REL: f64 = 1e-12;

fn first(sol: &Solution, kinds: &[EventKind]) -> Option<Event> {
    sol.events
        .iter()
        .find(|e| e.t > 0.0 && e.ball == Who::Left && kinds.contains(&e.kind))
        .copied()
}

fn grid() -> Vec<(f64, f64, f64, f64, f64)> {
    let mut out = Vec::new();
    for radius in [0.005, 0.0275, 0.5] {
        for half in [0.0, 0.1, 0.3, 0.5, 0.7, 0.77, 0.8, 0.9, 0.99, 0.999] {
            for mu in [0.02, 0.17, 0.9] {
                for v0 in [0.01, 0.79, 20.0] {
                    for e in [0.0, 0.3, 0.6, 0.85, 1.0] {
                        out.push((radius, 2.0 * radius * half, mu, v0, e));
                    }
                }
            }
        }
    }
    out
}

#[test]
fn rolling_again_matches_t_prime_v_prime_x_prime() {
    let mut checked = 0;
    for (radius, width, mu, v0, e) in grid() {
        let scene = common::symmetric(radius, width, mu, v0, e);
        let k = scene.k();
        if e * (1.0 + 5.0 * k * k) < 1.0 || e == 0.0 {
            continue;
        }
        let sol = solve(&scene, &common::span());
        let g = scene.g;
        let ev = first(&sol, &[EventKind::Rolling, EventKind::Rest]).expect("rolls again");
        let ctx = format!("R={radius} b={width} mu={mu} v0={v0} e={e}");
        let t_prime = cf::t_roll(k, e, v0, mu, g);
        assert_close!(ev.t, t_prime, REL, 0.0, "t' {ctx}");
        assert_close!(ev.left.v, cf::v_roll(k, e, v0), REL, v0, "v' {ctx}");
        // x' is a difference of two terms of size v0 t', and the engine's x is
        // absolute (a few roundings of ~1e-16 R each), so the scale is the larger of those.
        let x_scale = (v0 * t_prime).max(1e-3 * radius);
        assert_close!(
            ev.left.x + radius,
            cf::x_roll(k, e, v0, mu, g),
            REL,
            x_scale,
            "x' {ctx}"
        );
        if e == 1.0 {
            assert_close!(
                ev.left.x + radius,
                cf::x_roll_elastic(k, v0, mu, g),
                REL,
                x_scale,
                "x' (e = 1) {ctx}"
            );
        }
        let vp = cf::v_roll(k, e, v0);
        let glide = first(&sol, &[EventKind::PureGliding]);
        let slip = first(&sol, &[EventKind::PureSlipping]);
        if vp < -1e-9 * v0 {
            let t_r = cf::t_pure_gliding(k, v0, mu, g);
            assert_close!(glide.expect("pure gliding").t, t_r, REL, 0.0, "t_r {ctx}");
            assert!(slip.is_none_or(|s| s.t > t_prime), "{ctx}");
        } else if vp > 1e-9 * v0 {
            let t_t = cf::t_pure_slipping(k, e, v0, mu, g);
            assert_close!(slip.expect("pure slipping").t, t_t, REL, 0.0, "t_t {ctx}");
            assert!(glide.is_none_or(|s| s.t > t_prime), "{ctx}");
        }
        checked += 1;
    }
    assert!(checked > 500, "only {checked} scenes in the rolling family");
}

#[test]
fn repeated_impacts_accumulate_at_the_geometric_series_time() {
    let mut checked = 0;
    for (radius, width, mu, v0, e) in grid() {
        let scene = common::symmetric(radius, width, mu, v0, e);
        let k = scene.k();
        if e * (1.0 + 5.0 * k * k) < 1.0 || cf::v_roll(k, e, v0) <= 1e-9 * v0 {
            continue;
        }
        let sol = solve(&scene, &common::span());
        let ctx = format!("R={radius} b={width} mu={mu} v0={v0} e={e}");
        let want = cf::accumulation_time(k, e, v0, mu, scene.g).unwrap();
        let got = sol
            .accumulation
            .unwrap_or_else(|| panic!("no accumulation {ctx}"));
        assert_close!(got, want, 1e-9, 0.0, "T∞ {ctx}");
        assert!(!sol.truncated, "{ctx}");
        let last = sol.events.last().unwrap();
        assert_eq!(last.kind, EventKind::ZenoRest, "{ctx}");
        // At rest in contact at the impact place.
        assert_close!(last.left.x, -radius, 1e-9, 0.0, "{ctx}");
        assert_eq!((last.left.v, last.left.u), (0.0, 0.0), "{ctx}");
        checked += 1;
    }
    assert!(checked > 100, "only {checked} recolliding scenes");
}

#[test]
fn weak_rebounds_accumulate_then_press_until_the_spin_is_gone() {
    let mut checked = 0;
    for (radius, width, mu, v0, e) in grid() {
        let scene = common::symmetric(radius, width, mu, v0, e);
        let k = scene.k();
        if e * (1.0 + 5.0 * k * k) >= 1.0 {
            continue;
        }
        let sol = solve(&scene, &common::span());
        let g = scene.g;
        let ctx = format!("R={radius} b={width} mu={mu} v0={v0} e={e}");
        assert!(!sol.truncated, "{ctx}");
        if e > 0.0 {
            // Second impact when the left ball slides back: 2 t_t.
            let second = sol
                .events
                .iter()
                .filter(|ev| ev.kind == EventKind::Collision)
                .nth(1)
                .unwrap();
            assert_close!(
                second.t,
                2.0 * cf::t_pure_slipping(k, e, v0, mu, g),
                REL,
                0.0,
                "{ctx}"
            );
            let t_inf = 2.0 * cf::t_pure_slipping(k, e, v0, mu, g) / (1.0 - e);
            assert_close!(sol.accumulation.unwrap(), t_inf, 1e-9, 0.0, "T∞ {ctx}");
        }
        let contact = sol
            .events
            .iter()
            .find(|ev| ev.kind == EventKind::ContactStart)
            .unwrap_or_else(|| panic!("no pressing contact {ctx}"));
        assert!(contact.left.v.abs() <= 1e-9 * v0, "{ctx}");
        let rest = first(&sol, &[EventKind::Rest]).unwrap();
        assert_close!(
            rest.t,
            cf::t_pure_gliding(k, v0, mu, g),
            1e-9,
            0.0,
            "rest at t_r {ctx}"
        );
        assert_close!(rest.left.x, -radius, 1e-9, 0.0, "{ctx}");
        checked += 1;
    }
    assert!(checked > 100, "only {checked} weak-rebound scenes");
}

#[test]
fn at_the_critical_width_both_balls_stop_at_t_prime() {
    for radius in [0.005, 0.0275, 0.5] {
        for e in [0.4, 0.55, 0.8, 1.0] {
            for v0 in [0.01, 0.6, 20.0] {
                let b = cf::critical_width(radius, e).unwrap();
                let scene = common::symmetric(radius, b, 0.17, v0, e);
                let k = scene.k();
                let ctx = format!("R={radius} e={e} v0={v0}");
                assert_close!(
                    cf::determinant(k) * e,
                    1.0,
                    1e-12,
                    0.0,
                    "D e = 1 at b* {ctx}"
                );
                assert_eq!(Derived::of(&scene).regime, Regime::Rest, "{ctx}");
                let sol = solve(&scene, &common::span());
                let rest = first(&sol, &[EventKind::Rest]).expect("rest");
                assert_close!(
                    rest.t,
                    cf::t_roll(k, e, v0, 0.17, scene.g),
                    REL,
                    0.0,
                    "{ctx}"
                );
                assert_eq!(sol.impacts, 1, "{ctx}");
                // The b = b* rest is also where pure gliding and pure slipping coincide.
                assert_close!(
                    cf::t_pure_gliding(k, v0, 0.17, scene.g),
                    rest.t,
                    1e-9,
                    0.0,
                    "{ctx}"
                );
            }
        }
    }
}

#[test]
fn regime_follows_the_critical_width_and_the_determinant() {
    for e in [0.3, 0.5, 0.75, 1.0] {
        for half in [0.0, 0.2, 0.5, 0.7, 0.75, 0.8, 0.95] {
            let radius = 0.0275;
            let width = 2.0 * radius * half;
            let scene = common::symmetric(radius, width, 0.2, 0.6, e);
            let d = Derived::of(&scene);
            let want = match cf::critical_width(radius, e) {
                Some(b) if width < b => Regime::Depart,
                Some(b) if width == b => Regime::Rest,
                _ => Regime::Recollide,
            };
            assert_eq!(d.regime, want, "e={e} b/2R={half}");
            // D e against 1 says the same (v' ∝ 2 − 5ek² = 2(1 − D e)), and so does
            // the sentence every front end shows.
            assert_eq!(d.d * e > 1.0, want == Regime::Depart, "e={e} b/2R={half}");
            let why = d.why();
            match want {
                Regime::Depart => assert!(why.contains("> 1"), "{why}"),
                Regime::Recollide => assert!(why.contains("< 1"), "{why}"),
                Regime::Rest => assert!(why.contains("= 1"), "{why}"),
            }
        }
    }
}

#[test]
fn release_height_gives_the_closed_form_speed() {
    for (width, h) in [(0.0, 0.05), (0.035, 0.1), (0.049, 0.01)] {
        let spec = SceneSpec::default()
            .with(Key::Radius, 0.0275)
            .with(Key::Width, width)
            .with(Key::Mass, 0.167)
            .with(Key::Mu, 0.17)
            .with(Key::Height, h);
        let (scene, _) = spec.resolve().unwrap();
        let k = scene.k();
        let want = (2.0 * 9.81 * h / (1.0 + 2.0 / (5.0 * k * k))).sqrt();
        assert_close!(scene.left.v0, want, 1e-15, 0.0, "b={width} h={h}");
        assert_eq!(scene.left.v0, scene.right.v0);
        assert_close!(
            Derived::of(&scene).release_height,
            h,
            1e-14,
            0.0,
            "round trip"
        );
    }
}

#[test]
fn flat_table_gives_the_billiard_three_sevenths() {
    // b = 0 (k = 1): v' = −3/7 v0, the textbook result for a rolling billiard ball.
    let scene = common::symmetric(0.0275, 0.0, 0.2, 0.6, 1.0);
    let sol = solve(&scene, &common::span());
    let ev = first(&sol, &[EventKind::Rolling]).unwrap();
    assert_close!(ev.left.v, -3.0 / 7.0 * 0.6, REL, 0.0, "v'");
    assert_eq!(Derived::of(&scene).regime, Regime::Depart);
}

#[test]
fn forces_and_torque_of_the_paper() {
    // |N| = m g / (2k), F_net = μ m g / k along x, τ_net = μ m g R along z (paper eqs.).
    let scene = common::symmetric(0.0275, 0.049, 0.17, 0.79, 1.0);
    let d = Derived::of(&scene);
    let (m, g, k, mu, r) = (0.167, 9.81, scene.k(), 0.17, 0.0275);
    let f = d.forces;
    assert_close!(f.normal_a.norm(), m * g / (2.0 * k), 1e-14, 0.0, "|N_A|");
    assert_close!(f.normal_b.norm(), m * g / (2.0 * k), 1e-14, 0.0, "|N_B|");
    // Just after the impact the left ball slips backward (s < 0): F_net points to +x.
    assert_close!(f.net.x, mu * m * g / k, 1e-14, 0.0, "F_net");
    assert!(f.net.y.abs() < 1e-15 && f.net.z.abs() < 1e-15);
    assert_close!(f.torque.z, -mu * m * g * r, 1e-14, 0.0, "τ_net");
    assert!(f.torque.x.abs() < 1e-15 && f.torque.y.abs() < 1e-15);
    // The normal forces lie along the line from the contact to the centre.
    let arm_a = nalgebra::Vector3::new(0.0, k * r, -0.5 * scene.width);
    assert!(f.normal_a.cross(&arm_a).norm() < 1e-12);
}
