//! The comparison solves the exact scene once, whatever the methods and levels.

use super::*;
use crate::methods::solves;
use crate::physics::scene::Ball;
use crate::study::Quiet;

/// A scene no other test solves (its count is its own): the paper's balls in a
/// 4.31 cm groove, so the impacts recollide and accumulate.
fn own_scene() -> Scene {
    let ball = Ball {
        mass: 0.167,
        v0: 0.8,
    };
    Scene {
        width: 0.0431,
        restitution: 0.93,
        left: ball,
        right: Ball { v0: 0.0, ..ball },
        ..Scene::default()
    }
}

#[test]
fn every_method_and_level_starts_from_the_one_reference_solution() {
    let scene = own_scene();
    let span = Span {
        t_start: -0.05,
        t_end: Some(0.3),
    };
    let reference = Reference::new(&scene, &span);
    assert_eq!(reference.cut, None);
    // One solve: the span is within the window, so the reference is not solved again.
    assert_eq!(solves::of(&scene), 1);
    let runs: Vec<(Method, Settings)> = std::iter::once(Method::Exact)
        .chain(Method::TIME_STEPPING)
        .flat_map(|m| {
            [1e-3, 3e-4].map(|v| {
                let settings = if m.adaptive() {
                    Settings {
                        tolerance: v,
                        ..Settings::default()
                    }
                } else {
                    Settings {
                        step: v,
                        ..Settings::default()
                    }
                };
                (m, settings)
            })
        })
        .collect();
    let rows = measure_all(&scene, &reference, &runs, false, &Quiet).unwrap();
    assert_eq!(rows.len(), 12);
    // Each of the 10 time-stepping runs (two passes each) started from the reference's
    // state: no further solve (each used to solve the scene's run-up again).
    assert_eq!(solves::of(&scene), 1, "{rows:#?}");
    // Timing a time-stepping run solves nothing either; timing exact is solving it.
    let euler = &runs[2];
    timing(euler.0, &scene, &euler.1, &reference, &rows[2], &Quiet).unwrap();
    assert_eq!(solves::of(&scene), 1);
    timing(
        Method::Exact,
        &scene,
        &runs[0].1,
        &reference,
        &rows[0],
        &Quiet,
    )
    .unwrap();
    assert!(solves::of(&scene) >= 4, "at least three timed solves");
}

#[test]
fn the_reference_start_is_the_run_up_state() {
    let scene = Scene {
        width: 0.0432,
        ..own_scene()
    };
    let span = Span {
        t_start: -0.05,
        t_end: Some(0.3),
    };
    let reference = Reference::new(&scene, &span);
    // Bit for bit the state `start_state` solves the scene again for.
    assert_eq!(
        reference.start(),
        crate::methods::start_state(&scene, span.t_start)
    );
}
