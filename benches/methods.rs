//! Time per simulated second of each method on paper-b4.9 (−0.2 s … 1.0 s, so
//! 1.2 simulated seconds a run) at three points of the default sweep, and the whole
//! comparison of the default scene (target ≤ 3 s) and of the costliest scenes (each
//! within twice the default's). Results: BENCHMARKS.md.

use std::hint::black_box;

mod common;

use criterion::{Criterion, criterion_group, criterion_main};
use groovelab::lab::{Lab, Layers};
use groovelab::methods::{Method, Model, Observer, Run, Stepping, Y, start_state};
use groovelab::settings::params::Key;
use groovelab::settings::spec::SceneSpec;
use groovelab::study::compare::sweep;

struct Finite;
impl Observer for Finite {
    fn step(&mut self, _t: f64, y: &Y) -> bool {
        y.iter().all(|v| v.is_finite())
    }
}

/// One run of 1.2 simulated seconds from the run-up's state `y0`, stepped as `s` says.
fn run<'a>(model: &'a Model, y0: Y, s: &'a Stepping) -> Run<'a> {
    Run {
        model,
        y0: black_box(y0),
        t0: -0.2,
        t1: 1.0,
        stepping: s,
    }
}

fn methods(c: &mut Criterion) {
    let (scene, span) = common::preset("paper-b4.9");
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
            let s = Stepping {
                step: h,
                ..Stepping::default()
            };
            group.bench_function(format!("{} h={h:.0e}", method.name()), |b| {
                b.iter(|| method.integrate(&run(&model, y0, &s), &mut Finite))
            });
        }
    }
    for tol in [1e-3, 1e-6, 1e-9] {
        let s = Stepping {
            tolerance: tol,
            step: 1e-3,
            ..Stepping::default()
        };
        group.bench_function(format!("rk45 tol={tol:.0e}"), |b| {
            b.iter(|| Method::Rk45.integrate(&run(&model, y0, &s), &mut Finite))
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
    // wedging (b = 5.4999 cm, thousands of impacts), μ = 1e-6 (span 147,000 s). Each
    // as `groovelab compare` takes it: the lab's snapshot of the preset under the
    // flags, over the snapshot's span (which reaches the preset's measured series).
    let snapshot = |values: SceneSpec| {
        let preset = groovelab::input::preset::load("paper-b4.9").unwrap();
        let lab = Lab::new(Layers::new(preset, values), None).unwrap();
        (lab.scene, lab.span)
    };
    let scenes = [
        (
            "default comparison, all methods (paper-b4.9)",
            snapshot(SceneSpec::default()),
        ),
        (
            "--mass-right 10kg",
            snapshot(SceneSpec::default().with(Key::MassRight, 10.0)),
        ),
        (
            "--width 5.4999cm",
            snapshot(SceneSpec::default().with(Key::Width, 0.054999)),
        ),
        (
            "--mu 1e-6",
            snapshot(SceneSpec::default().with(Key::Mu, 1e-6)),
        ),
    ];
    for (name, (scene, span)) in scenes {
        whole.bench_function(name, |b| {
            b.iter(|| {
                sweep(
                    &scene,
                    &span,
                    &all,
                    &Stepping::default(),
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
