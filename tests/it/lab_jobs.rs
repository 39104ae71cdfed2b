//! The lab's analyses on the worker pool: a repeated request is not recomputed, a
//! result made for an earlier scene is never shown, a fit is applied whole. Work is
//! counted (`Lab::runs`), never timed.

use groovelab::lab::Lab;
use groovelab::lab::jobs::State;
use groovelab::methods::Method;
use groovelab::settings::params::Key;
use groovelab::study::preset::Preset;
use groovelab::tui::app::{App, Library};
use groovelab::tui::keys::parse_script;
use groovelab::tui::replay;

fn app(name: &str) -> App {
    let p = Preset::load(name).unwrap();
    App::new(Lab::of_preset(p).unwrap(), Library::at(None))
}

fn keys(a: &mut App, script: &str) {
    replay(a, &parse_script(script).unwrap());
}

#[test]
fn a_repeated_request_is_not_recomputed() {
    let mut a = app("paper-b4.9");
    assert_eq!(a.lab.runs(), 0, "nothing is computed that no view wants");
    keys(&mut a, "o");
    a.lab.wait();
    assert_eq!(a.lab.runs(), 1, "the overlay");
    let choice = a.lab.overlay_choice();
    a.lab.set_overlay(choice);
    // The Methods view opened, closed and opened again; the Fit view likewise (a
    // velocity series: one fit, no position fit).
    keys(&mut a, "c");
    a.lab.wait();
    keys(&mut a, "c c f");
    a.lab.wait();
    keys(&mut a, "f f");
    a.lab.wait();
    assert_eq!(a.lab.runs(), 3, "overlay, Methods rows, fit: each once");
    assert!(matches!(a.lab.fits(), State::Ready(Ok(_))));
    // A new scene: what is wanted (the fit and the overlay) runs again, once.
    a.set_value(Key::Width, 0.050);
    a.lab.wait();
    assert_eq!(a.lab.runs(), 5);
}

#[test]
fn a_result_for_an_earlier_scene_is_never_shown() {
    let mut a = app("paper-b4.9");
    a.lab.set_overlay(Some((Method::Euler, 4)));
    // Two scene changes before anything finished: the first's run is superseded.
    a.set_value(Key::Width, 0.050);
    a.set_value(Key::Width, 0.047);
    a.lab.wait();
    let mut fresh = app("paper-b4.9");
    fresh.set_value(Key::Width, 0.047);
    fresh.lab.set_overlay(Some((Method::Euler, 4)));
    fresh.lab.wait();
    let (State::Ready(got), State::Ready(want)) = (a.lab.overlay(), fresh.lab.overlay()) else {
        panic!("both overlays ready");
    };
    assert_eq!(got.points, want.points);
    assert_eq!(got.row.err_v, want.row.err_v);
    // Three requests: at most one run each (a superseded one that had not started
    // runs not at all), and none of the superseded ones shown.
    assert!((1..=3).contains(&a.lab.runs()), "{}", a.lab.runs());
}

#[test]
fn a_fit_is_applied_whole_and_solved_once() {
    let mut a = app("paper-b4.9");
    keys(&mut a, "f");
    a.lab.wait();
    let State::Ready(Ok(f)) = a.lab.fits() else {
        panic!("fit ready");
    };
    let mu = f.model_fit.mu;
    keys(&mut a, "a");
    assert_eq!(a.lab.scene.mu, mu);
    // One new scene: the fit of it is requested once more, nothing else.
    a.lab.wait();
    assert_eq!(a.lab.runs(), 2);
}
