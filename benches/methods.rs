//! Time per simulated second of each method on paper-b4.9 (−0.2 s … 1.0 s, so
//! 1.2 simulated seconds a run) at three points of the default sweep, and the whole
//! comparison of the default scene (target ≤ 3 s) and of the costliest scenes (each
//! within twice the default's). Results: BENCHMARKS.md.

use std::hint::black_box;

use criterion::{Criterion, criterion_group, criterion_main};
use groovelab::methods::{Method, Model, Observer, Settings, Y, integrate, start_state};
use groovelab::physics::scene::{Ball, Scene};
use groovelab::study::compare::sweep;
use groovelab::study::preset::Preset;

struct Finite;
impl Observer for Finite {
    fn step(&mut self, _t: f64, y: &Y) -> bool {
        y.iter().all(|v| v.is_finite())
    }
}

fn methods(c: &mut Criterion) {
    let (scene, span) = Preset::load("paper-b4.9").unwrap().spec.resolve().unwrap();
    let model = Model::of(&scene);
    let y0 = start_state(&scene, span.t_start);
    let mut group = c.benchmark_group("paper-b4.9, 1.2 simulated s");
    group.sample_size(10);
    for method in [
        Method::Euler,
        Method::SymplecticEuler,
        Method::Rk4,
        Method::Moreau,
    ] {
        for h in [1e-3, 1e-4, 1e-5] {
            let s = Settings {
                step: h,
                ..Settings::default()
            };
            group.bench_function(format!("{} h={h:.0e}", method.name()), |b| {
                b.iter(|| integrate(method, &model, black_box(y0), -0.2, 1.0, &s, &mut Finite))
            });
        }
    }
    for tol in [1e-3, 1e-6, 1e-9] {
        let s = Settings {
            tolerance: tol,
            step: 1e-3,
            ..Settings::default()
        };
        group.bench_function(format!("rk45 tol={tol:.0e}"), |b| {
            b.iter(|| {
                integrate(
                    Method::Rk45,
                    &model,
                    black_box(y0),
                    -0.2,
                    1.0,
                    &s,
                    &mut Finite,
                )
            })
        });
    }
    group.finish();
    let mut whole = c.benchmark_group("compare");
    whole.sample_size(10);
    let all: Vec<Method> = std::iter::once(Method::Exact)
        .chain(Method::TIME_STEPPING)
        .collect();
    // The default scene and the costliest ones (issue: each within twice the
    // default's): a 10 kg right ball (span 2.25 s, cut at 2 s), a groove all but
    // wedging (b = 5.4999 cm, thousands of impacts), μ = 1e-6 (span 147,000 s).
    let heavy = Scene {
        right: Ball {
            mass: 10.0,
            ..scene.right
        },
        ..scene
    };
    let scenes = [
        ("default comparison, all methods (paper-b4.9)", scene),
        ("--mass-right 10kg", heavy),
        (
            "--width 5.4999cm",
            Scene {
                width: 0.054999,
                ..scene
            },
        ),
        ("--mu 1e-6", Scene { mu: 1e-6, ..scene }),
    ];
    for (name, scene) in scenes {
        whole.bench_function(name, |b| {
            b.iter(|| {
                sweep(
                    &scene,
                    &span,
                    &all,
                    &Settings::default(),
                    &groovelab::study::Quiet,
                )
                .unwrap()
            })
        });
    }
    whole.finish();
}

criterion_group!(benches, methods);
criterion_main!(benches);
