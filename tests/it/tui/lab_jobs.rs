//! The app's analyses on its worker pool: a repeated request is not recomputed, a
//! result made for an earlier scene is never shown, a fit is applied whole, and the
//! lab holds no job (the view that shows an analysis owns its request). Work is
//! counted on the app's own pool (`common::counted`), never timed.

use groovelab::lab::jobs::State;
use groovelab::lab::{Lab, analyses};
use groovelab::methods::Method;
use groovelab::settings::params::Key;
use groovelab::tui::app::{App, Library};
use groovelab::tui::keys::parse_script;
use groovelab::tui::replay;

use crate::common::{self, Runs};

fn app(name: &str) -> (App, Runs) {
    common::counted(name, Library::at(None))
}

fn keys(a: &mut App, script: &str) {
    replay(a, &parse_script(script).unwrap());
}

fn set_overlay(a: &mut App, choice: Option<(Method, u8)>) {
    a.set_overlay(choice);
}

#[test]
fn a_repeated_request_is_not_recomputed() {
    let (mut a, runs) = app("paper-b4.9");
    assert_eq!(runs.get(), 0, "nothing is computed that no view wants");
    keys(&mut a, "o");
    a.wait();
    assert_eq!(runs.get(), 1, "the overlay");
    let choice = a.overlay().choice;
    set_overlay(&mut a, choice);
    // The Methods view opened, closed and opened again; the Fit view likewise (a
    // velocity series: one fit, no position fit).
    keys(&mut a, "c");
    a.wait();
    keys(&mut a, "c c f");
    a.wait();
    keys(&mut a, "f f");
    a.wait();
    assert_eq!(runs.get(), 3, "overlay, Methods rows, fit: each once");
    assert!(matches!(a.fit().fits(), State::Ready(Ok(_))));
    // A new scene: what is wanted (the fit and the overlay) runs again, once.
    a.set_value(Key::Width, 0.050);
    a.wait();
    assert_eq!(runs.get(), 5);
}

#[test]
fn a_result_for_an_earlier_scene_is_never_shown() {
    let (mut a, runs) = app("paper-b4.9");
    set_overlay(&mut a, Some((Method::Euler, 4)));
    // Two scene changes before anything finished: the first's run is superseded.
    a.set_value(Key::Width, 0.050);
    a.set_value(Key::Width, 0.047);
    a.wait();
    let (mut fresh, _) = app("paper-b4.9");
    fresh.set_value(Key::Width, 0.047);
    set_overlay(&mut fresh, Some((Method::Euler, 4)));
    fresh.wait();
    let (State::Ready(got), State::Ready(want)) = (a.overlay().state(), fresh.overlay().state())
    else {
        panic!("both overlays ready");
    };
    assert_eq!(got.points, want.points);
    assert_eq!(got.row.err_v, want.row.err_v);
    // Three requests: at most one run each (a superseded one that had not started
    // runs not at all), and none of the superseded ones shown.
    assert!((1..=3).contains(&runs.get()), "{}", runs.get());
}

#[test]
fn a_fit_is_applied_whole_and_solved_once() {
    let (mut a, runs) = app("paper-b4.9");
    keys(&mut a, "f");
    a.wait();
    let State::Ready(Ok(f)) = a.fit().fits() else {
        panic!("fit ready");
    };
    let mu = f.model_fit.mu;
    keys(&mut a, "a");
    assert_eq!(a.lab.scene.mu, mu);
    // One new scene: the fit of it is requested once more, nothing else.
    a.wait();
    assert_eq!(runs.get(), 2);
}

/// The lab's analyses are work any front end can run, with no view and no pool: a
/// fit run in place gives what the Fit view shows.
#[test]
fn the_labs_analyses_are_work_without_a_view() {
    let lab = Lab::of_preset(groovelab::input::preset::load("paper-b4.9").unwrap()).unwrap();
    let work = analyses::fits(&lab, (None, None)).expect("the preset has data");
    let in_place = work(&groovelab::lab::jobs::Ticket::detached()).unwrap();
    let (mut a, _) = app("paper-b4.9");
    keys(&mut a, "f");
    a.wait();
    let State::Ready(Ok(shown)) = a.fit().fits() else {
        panic!("fit ready");
    };
    assert_eq!(in_place.model_fit.mu, shown.model_fit.mu);
}
