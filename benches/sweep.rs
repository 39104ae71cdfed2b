//! Regime-map speed (issue targets: at least a million single-impact scene solutions
//! per second per core; a 400×200 map of the paper scene under 1 s on 2 cores).

use std::hint::black_box;
use std::sync::atomic::AtomicBool;

use criterion::{Criterion, criterion_group, criterion_main};
use groovelab::study::sweep::{self, point};

fn sweeps(c: &mut Criterion) {
    let spec = groovelab::input::preset::load("paper-b3.5").unwrap().spec;
    c.bench_function("one grid point, single-impact scene (paper-b3.5)", |b| {
        b.iter(|| point(black_box(&spec)).unwrap())
    });
    let single = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .unwrap();
    let x = sweep::parse_axis("width=0..4cm", 1000).unwrap();
    let mut g = c.benchmark_group("maps");
    g.sample_size(10);
    g.bench_function("1000 single-impact points (b 0..4 cm), 1 thread", |b| {
        b.iter(|| {
            single.install(|| sweep::run(&spec, &x, None, &AtomicBool::new(false), &|| {}).unwrap())
        })
    });
    let paper = groovelab::input::preset::load("paper-b4.9").unwrap().spec;
    let x = sweep::parse_axis("width=0..5.4cm", 400).unwrap();
    let y = sweep::parse_axis("restitution=0.3..1", 200).unwrap();
    g.bench_function(
        "400x200 map, width x restitution (paper-b4.9), all cores",
        |b| b.iter(|| sweep::run(&paper, &x, Some(&y), &AtomicBool::new(false), &|| {}).unwrap()),
    );
    g.finish();
}

criterion_group!(benches, sweeps);
criterion_main!(benches);
