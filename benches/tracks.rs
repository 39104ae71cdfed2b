//! Track import speed (issue 12 target: reading and differentiating a 10,000-frame
//! track in at most 10 ms).

use std::hint::black_box;

mod common;

use criterion::{Criterion, criterion_group, criterion_main};
use groovelab::input::data;
use groovelab::input::data::Reading;
use groovelab::study::measured::{self, Derive};
use groovelab::study::video::{self, TrackFormat, Video};

fn tracks(c: &mut Criterion) {
    let (scene, _) = common::preset("paper-b4.9");
    // 10,000 frames at 240 frames/s with 0.3 mm noise, centre and rim mark.
    let v = Video {
        fps: 240.0,
        noise: 3e-4,
        from: -0.2,
        to: -0.2 + 9999.0 / 240.0,
        ..Video::default()
    };
    let text = video::write(
        &video::track(&scene, &v).unwrap(),
        TrackFormat::TrackerMulti,
    );
    c.bench_function("read and differentiate a 10,000-frame track", |b| {
        b.iter(|| {
            let series = data::load(
                black_box(&text),
                "bench.txt",
                &Reading::default(),
                &Derive::default(),
            )
            .unwrap();
            measured::for_scene(&series, &scene)
        })
    });
}

criterion_group!(benches, tracks);
criterion_main!(benches);
