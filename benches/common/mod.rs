//! What the benches share: a preset's checked scene and span.

use groovelab::physics::scene::{Scene, Span};

/// The scene and span of the preset `name` (built in or a file), checked.
pub fn preset(name: &str) -> (Scene, Span) {
    groovelab::input::preset::load(name)
        .unwrap()
        .spec
        .resolve()
        .unwrap()
}
