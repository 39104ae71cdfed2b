//! `render`, the app's headless twin: the same keys give the same bytes on every run
//! (a key waits for the analyses it may act on), and a screen dump writes no files.

use groovelab::settings::params::SceneSpec;

use crate::common::{self, scene_of};

fn render(preset: &str, keys: &str) -> String {
    let scene = scene_of(preset, SceneSpec::default());
    let library = common::no_user_presets("headless");
    common::render_text(&scene, None, (120, 40), false, Some(keys), library).unwrap()
}

#[test]
fn a_key_waits_for_the_analysis_it_acts_on() {
    // `a` applies the fit that `f` started: without waiting it finds the fit running
    // (most runs, not all: the bytes would depend on the machine's load).
    let first = render("paper-b3.5", "f a");
    assert!(first.contains("applied the fit: μ_k = 0.17"), "{first}");
    for run in 0..20 {
        assert_eq!(render("paper-b3.5", "f a"), first, "run {run}");
    }
}
