//! Speed of the lab's screen (targets: a full 120×40 frame < 1 ms, launch to first
//! frame < 100 ms, re-solve after a parameter change < 1 ms, a key to the next frame
//! ≤ 16 ms in every view, target 1 ms). BENCHMARKS.md.

use std::hint::black_box;

use criterion::{Criterion, criterion_group, criterion_main};
use groovelab::lab::Lab;
use groovelab::settings::params::Key;
use groovelab::tui::app::{App, Library};
use groovelab::tui::keys;
use groovelab::tui::screen::{self, Screen};
use groovelab::tui::theme::{Glyphs, Theme};
use ratatui::buffer::Buffer;
use ratatui::layout::Rect;

fn app(name: &str) -> App {
    let p = groovelab::input::preset::load(name).unwrap();
    App::new(Lab::of_preset(p).unwrap(), Library::at(None))
}

/// A key press as the terminal delivers it: the action, then the next frame laid out
/// and drawn on the terminal's one screen (its caches kept from frame to frame).
fn key_to_frame(a: &mut App, s: &mut Screen, keys: &str, area: Rect, theme: &Theme) -> Buffer {
    groovelab::tui::replay(a, &keys::parse_script(keys).unwrap());
    let mut buf = Buffer::empty(area);
    s.draw(a, area, &mut buf, theme);
    buf
}

fn tui(c: &mut Criterion) {
    let theme = Theme::new(Glyphs::UNICODE, false);
    let area = Rect::new(0, 0, 120, 40);
    let mut a = app("paper-b4.9");
    a.t = 0.3;
    let mut s = Screen::default();
    c.bench_function("draw one 120x40 frame (paper-b4.9)", |b| {
        b.iter(|| {
            let mut buf = Buffer::empty(area);
            s.draw(black_box(&a), area, &mut buf, &theme);
            buf
        })
    });
    c.bench_function("launch: load preset, solve, first 120x40 frame", |b| {
        b.iter(|| {
            let a = app(black_box("paper-b4.9"));
            let mut buf = Buffer::empty(area);
            screen::draw(&a, area, &mut buf, &theme);
            buf
        })
    });
    let mut a = app("paper-b4.9");
    let mut wide = false;
    c.bench_function(
        "re-solve after a parameter change (b 4.9 <-> 5.0 cm)",
        |b| {
            b.iter(|| {
                wide = !wide;
                a.set_value(Key::Width, if wide { 0.050 } else { 0.049 });
            })
        },
    );
    // A key press with the Methods view open, and with the finest overlay: the
    // analyses restart on workers, the key only re-solves and draws.
    for (name, setup) in [
        (
            "key to next frame, Methods view open (b 4.9 <-> 5.0 cm)",
            "c",
        ),
        (
            "key to next frame, finest euler overlay (b 4.9 <-> 5.0 cm)",
            "o ] ] ] ] ] ]",
        ),
        // The Forces view draws the cross-section and reads the cursor's instant.
        ("key to next frame, Forces view (b 4.9 <-> 5.0 cm)", "v"),
    ] {
        let mut a = app("paper-b4.9");
        let mut s = Screen::default();
        key_to_frame(&mut a, &mut s, setup, area, &theme);
        let mut wide = false;
        c.bench_function(name, |b| {
            b.iter(|| {
                wide = !wide;
                let key = if wide { "right" } else { "left" };
                key_to_frame(&mut a, &mut s, key, area, &theme)
            })
        });
        a.wait();
    }
}

criterion_group!(benches, tui);
criterion_main!(benches);
