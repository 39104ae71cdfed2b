//! Speed of the exact engine (issue targets: single impact < 2 µs, paper-b4.9 with
//! its whole impact series < 20 µs, 10,000 samples < 200 µs). Results: BENCHMARKS.md.

use std::hint::black_box;

use criterion::{Criterion, criterion_group, criterion_main};
use groovelab::physics::engine::solve;

mod common;
use common::preset;

fn engine(c: &mut Criterion) {
    let (single, span) = preset("paper-b3.5");
    c.bench_function("solve single impact (paper-b3.5)", |b| {
        b.iter(|| solve(black_box(&single), black_box(&span)))
    });
    let (series, span) = preset("paper-b4.9");
    let sol = solve(&series, &span);
    assert!(sol.accumulation.is_some());
    c.bench_function("solve impact series to T∞ (paper-b4.9)", |b| {
        b.iter(|| solve(black_box(&series), black_box(&span)))
    });
    let dt = (sol.t_end - sol.t_start) / 9_999.0;
    assert_eq!(sol.sample(dt).len(), 10_000);
    c.bench_function("sample 10,000 points (paper-b4.9)", |b| {
        b.iter(|| sol.sample(black_box(dt)))
    });
}

criterion_group!(benches, engine);
criterion_main!(benches);
