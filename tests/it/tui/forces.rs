//! The Forces view and predict–observe–explain (issue 20): the keys, what the screen
//! says at the paper's events, b hidden, and `render` snapshots at three sizes, ASCII
//! and Unicode. The numbers themselves are tested against the closed forms in
//! `physics::forces`.

use groovelab::cli::DataArgs;
use groovelab::physics::derived::Regime;
use groovelab::settings::spec::SceneSpec;
use groovelab::tui::app::{App, ChartBall, Library, Mode, View};
use groovelab::tui::keys;
use groovelab::tui::screen;
use groovelab::tui::theme::{Glyphs, Theme};

use crate::common::{self, press, scene_of, text};

fn no_user_presets() -> Library {
    common::no_user_presets("forces")
}

fn app(preset: &str) -> App {
    common::app(preset, no_user_presets())
}

fn render(preset: &str, at: Option<f64>, size: (u16, u16), ascii: bool, keys: &str) -> String {
    let scene = scene_of(preset, SceneSpec::default());
    common::render_text(&scene, at, size, ascii, Some(keys), no_user_presets()).unwrap()
}

const SIZES: [(u16, u16); 3] = [(80, 24), (120, 40), (200, 60)];

#[test]
fn v_shows_the_forces_view_and_b_picks_its_ball() {
    let mut a = app("paper-b3.5");
    press(&mut a, "v");
    assert_eq!(a.view(), View::Forces);
    press(&mut a, "b");
    assert_eq!(a.forces().ball(), 1);
    assert_eq!(
        a.charts().ball(),
        ChartBall::Left,
        "b in the Forces view leaves the chart's ball"
    );
    let s = text(&a, (120, 40), false);
    assert!(s.contains("Forces: front view, right ball"), "{s}");
    press(&mut a, "b v");
    assert_eq!((a.forces().ball(), a.view()), (0, View::Charts));
    // Outside the Forces view b still switches the chart's ball.
    press(&mut a, "b");
    assert_eq!(a.charts().ball(), ChartBall::Right);
}

#[test]
fn the_states_are_named_where_the_event_keys_land() {
    // paper-b3.5: impact, pure gliding at t_r, pure rolling at t' (the paper's figure 6a).
    let mut a = app("paper-b3.5");
    press(&mut a, "v");
    for (keys, state) in [
        ("", "pure rolling"),
        (">", "gliding and slipping"),
        (">", "pure gliding"),
        (">", "pure rolling"),
    ] {
        press(&mut a, keys);
        let s = text(&a, (80, 24), true);
        let left = s
            .lines()
            .find(|l| l.contains("|left  "))
            .unwrap_or_default();
        assert!(left.contains(state), "{keys}: {left}\n{s}");
    }
    // paper-b4.4 and -b4.9: pure slipping at t_t, rolling back at t' (figure 6c).
    for preset in ["paper-b4.4", "paper-b4.9"] {
        let mut a = app(preset);
        press(&mut a, "v > >");
        assert!(
            text(&a, (80, 24), false).contains("left  pure slipping"),
            "{preset}"
        );
        press(&mut a, ">");
        let s = text(&a, (80, 24), false);
        assert!(s.contains("left  pure rolling"), "{preset}: {s}");
    }
}

#[test]
fn eighty_columns_keep_the_states_n_f_and_the_net_torque() {
    for ascii in [false, true] {
        let s = render("paper-b4.4", Some(0.1), (80, 24), ascii, "v");
        let tau = if ascii { "tau_net" } else { "τ_net" };
        for needle in [
            "|N_A|=|N_B| 1.37 N",
            "|F_A|=|F_B| 0.232 N",
            tau,
            "gliding and slipping",
        ] {
            assert!(s.contains(needle), "{needle} (ascii {ascii}):\n{s}");
        }
        // |τ_net| = μ_k m g R = 0.17 · 0.167 · 9.81 · 0.0275 = 0.00766 N m, whatever b.
        assert!(s.contains("0.00766 N m"), "{s}");
    }
}

#[test]
fn friction_points_out_of_the_front_view_after_the_impact() {
    // Right after the impact the left ball's contact points move to −x (v_A = 2 v_cm):
    // friction along +x, toward the viewer: (.) in ASCII.
    let s = render("paper-b3.5", Some(0.05), (120, 40), true, "v");
    assert!(s.contains("F along +x: (.) out"), "{s}");
    assert!(!s.contains("-x: (x) in"), "{s}");
    // The right ball's friction points the other way (into the picture).
    let s = render("paper-b3.5", Some(0.05), (120, 40), true, "v b");
    assert!(s.contains("F along -x: (x) in"), "{s}");
}

#[test]
fn a_pinned_run_gives_arrows_in_the_chain() {
    // A wider groove than the pinned one: k down, |N|, |F|, |a_cm| up, τ_net the same.
    let s = render("paper-b4.4", Some(0.1), (200, 60), false, "P right right v");
    let chain = s.lines().find(|l| l.contains("→ k ")).unwrap();
    for needle in ["cm ↑", "k 0.5", "|N| 1.4", "↑ → |F|", "τ_net"] {
        assert!(s.contains(needle), "{needle}: {chain}\n{s}");
    }
    // τ_net does not depend on b: the same as the pinned run's.
    assert!(s.contains("N m (any b) ="), "{s}");
}

#[test]
fn predict_asks_plays_and_explains() {
    let mut a = app("paper-b4.9");
    press(&mut a, "y");
    assert_eq!(a.mode(), Mode::Predict);
    assert_eq!(a.view(), View::Forces);
    let q = text(&a, (80, 24), false);
    assert!(
        q.contains("what will the balls do?") && q.contains("come back"),
        "{q}"
    );
    // While the question is open, the chain behind it does not give the answer away.
    for size in [(80, 24), (100, 30), (120, 40)] {
        let q = text(&a, size, false);
        assert!(!q.contains("recollide") && !q.contains("D = 0.5"), "{q}");
    }
    press(&mut a, "1");
    let p = a.prediction().cloned().unwrap();
    assert_eq!(p.guess, Regime::Depart);
    assert!(a.playing && a.t == a.lab.solution.t_start && a.mode() == Mode::Normal);
    // Before the outcome shows, nothing gives it away.
    a.t = 0.5 * p.reveal_at;
    let s = text(&a, (120, 40), false);
    assert!(s.contains("predicted: move apart"), "{s}");
    for secret in [
        "observed",
        "recollide",
        "RECOLLIDE",
        "D = 0.5",
        "spin rolls",
    ] {
        assert!(!s.contains(secret), "{secret}:\n{s}");
    }
    // Once the left ball rolls back, the outcome, the verdict and the reason.
    a.t = p.reveal_at;
    let s = text(&a, (120, 40), false);
    assert!(s.contains("observed: RECOLLIDE"), "{s}");
    assert!(s.contains("not quite"), "{s}");
    assert!(s.contains("spin rolls them back"), "{s}");
    // Playing stops where the outcome shows, then plays on.
    press(&mut a, "y 2");
    let reveal = a.prediction().unwrap().reveal_at;
    while a.playing {
        a.tick(0.05);
    }
    assert_eq!(a.t, reveal);
    press(&mut a, "space");
    a.tick(0.05);
    assert!(a.playing && a.t > reveal);
    // A right answer says so; Esc cancels the question.
    press(&mut a, "y 3");
    a.t = a.lab.solution.t_end;
    assert!(text(&a, (120, 40), true).contains("right"), "ascii verdict");
    press(&mut a, "y esc");
    assert_eq!(a.mode(), Mode::Normal);
    assert!(!a.quitting(), "esc in the question does not quit");
    // Asked after the impact, the question rewinds first: the outcome on screen
    // behind it would give the answer away.
    press(&mut a, "end y");
    assert_eq!(a.mode(), Mode::Predict);
    assert_eq!(a.t, a.lab.solution.t_start);
    let s = text(&a, (120, 40), false);
    assert!(!s.contains("RECOLLIDE"), "{s}");
}

#[test]
fn a_changed_scene_makes_the_prediction_stale() {
    let mut a = app("paper-b4.9");
    press(&mut a, "y 2 S-left");
    let s = text(&a, (120, 40), false);
    assert!(s.contains("the scene changed since the prediction"), "{s}");
}

#[test]
fn hiding_b_leaves_the_picture_and_hides_what_gives_b_away() {
    let mut a = app("paper-b4.9");
    press(&mut a, "B v");
    assert!(a.hide().b());
    for ascii in [false, true] {
        let s = text(&a, (120, 40), ascii);
        for secret in ["4.90", "k 0.454", "b/R", "1.80 N", "0.613", "D = 0.516"] {
            assert!(!s.contains(secret), "{secret}:\n{s}");
        }
        assert!(s.contains("hidden") && s.contains("b ?"), "{s}");
        // What does not depend on b stays.
        assert!(s.contains("0.00766 N m"), "{s}");
    }
    // Nor does a pinned run's line in the scene panel.
    press(&mut a, "P right");
    let s = text(&a, (120, 40), false);
    assert!(s.contains("b changed") && !s.contains("4.95"), "{s}");
    press(&mut a, "P left");
    // Changing b while hidden does not tell it in the status line.
    press(&mut a, "right");
    assert!(!text(&a, (120, 40), false).contains("4.95"));
    press(&mut a, "B");
    assert!(text(&a, (120, 40), false).contains("4.95 cm"));
}

/// With b hidden the parameter panel reads the same whatever b is: no row (a release
/// height follows from v0 and k) lets a class work b out.
#[test]
fn with_b_hidden_the_parameter_panel_does_not_depend_on_b() {
    let panel = |width: f64| {
        let mut a = app("paper-b4.9");
        a.set_value(groovelab::settings::params::Key::Width, width);
        press(&mut a, "B v");
        let s = text(&a, (120, 40), false);
        // The panel is the top-left box, up to its closing corner.
        s.lines()
            .take_while(|l| !l.starts_with('╰'))
            .map(|l| {
                l.split('╮')
                    .next()
                    .unwrap_or(l)
                    .split('│')
                    .nth(1)
                    .unwrap_or("")
                    .to_string()
            })
            .collect::<Vec<_>>()
    };
    let (narrow, wide) = (panel(0.045), panel(0.049));
    assert!(narrow.iter().any(|l| l.contains("hidden")), "{narrow:?}");
    assert_eq!(narrow, wide);
}

#[test]
fn the_help_lists_the_keys_with_predict() {
    let predict = keys::TABLE
        .iter()
        .find(|b| b.keys == ["y"])
        .expect("y is bound");
    assert!(predict.help.contains("predict"));
    assert!(
        keys::TABLE
            .iter()
            .any(|b| b.keys == ["v"] && b.help.contains("Forces view"))
    );
}

#[test]
fn ascii_forces_screens_need_no_stand_ins() {
    let theme = Theme::new(Glyphs::ASCII, true);
    for preset in [
        "paper-b3.5",
        "paper-b4.9",
        "inelastic",
        "unequal-speeds",
        "critical",
    ] {
        for keys in ["v", "v > >", "v b > > >", "P S-right v", "B y 2", "y"] {
            let mut a = app(preset);
            press(&mut a, keys);
            for (w, h) in SIZES {
                let cells = screen::non_ascii_cells(&a, w, h, &theme);
                assert!(cells.is_empty(), "{preset} {keys:?} {w}x{h}: {cells:?}");
            }
        }
    }
}

#[test]
fn snapshots_of_the_forces_view() {
    let cases: [(&str, &str, f64, &str); 3] = [
        ("b3.5-sliding", "paper-b3.5", 0.05, "v"),
        ("b4.4-pinned-wider", "paper-b4.4", 0.1, "P right right v"),
        ("b4.9-predicted-hidden-b", "paper-b4.9", 0.35, "B y 3"),
    ];
    for (name, preset, at, keys) in cases {
        // One app per case, drawn at every size and glyph set.
        let scene = scene_of(preset, SceneSpec::default());
        let data = DataArgs::default();
        let a = common::rendered(&scene, &data, Some(at), Some(keys), no_user_presets());
        for (w, h) in SIZES {
            for ascii in [false, true] {
                let mode = if ascii { "ascii" } else { "unicode" };
                insta::assert_snapshot!(
                    format!("forces-{name}-{w}x{h}-{mode}"),
                    text(&a, (w, h), ascii)
                );
            }
        }
    }
}

/// `B` hides b in every view, not only the Forces view: the Why panel (regime, D e,
/// k, r, D), the regime map's marker and the paper figure's b line would give it away.
/// And while a prediction is pending the chain hides |a_cm| and |a_t| (their ratio
/// is D, the answer), showing them once the outcome has shown.
#[test]
fn hidden_b_and_a_pending_prediction_give_nothing_away() {
    for size in SIZES {
        for ascii in [false, true] {
            let main = render("paper-b4.9", Some(0.1), size, ascii, "B");
            for away in ["RECOLLIDE", "D e = 0.516", "k 0.4542", "r 1.249"] {
                assert!(!main.contains(away), "{size:?} {away}: {main}");
            }
            assert!(main.contains("b hidden"), "{size:?}: {main}");
            let map = render("paper-b4.9", None, size, ascii, "B g");
            let marker = if ascii { "@" } else { "◆" };
            let shown = render("paper-b4.9", None, size, ascii, "g");
            // The marker appears in the legend too: one more on the shown map.
            assert!(
                map.matches(marker).count() < shown.matches(marker).count(),
                "{size:?}"
            );
        }
    }
    let asked = render("paper-b4.9", None, (120, 40), false, "y");
    assert!(
        asked.contains("|a_cm| ? m/s²") && asked.contains("|a_t| ? m/s²"),
        "{asked}"
    );
    assert!(
        !asked.contains("3.67") && !asked.contains("1.89"),
        "{asked}"
    );
    // The run-up heights give D away with v0 (D = v0²/(2gh − v0²)): hidden as k is
    // (they were shown, 9.42 cm, beside v0 0.793 m/s).
    for size in SIZES {
        for ascii in [false, true] {
            let asked = render("paper-b4.9", None, size, ascii, "y");
            assert!(!asked.contains("9.42"), "{size:?}: {asked}");
        }
    }
    // With the forces as givens (`g`), k is shown, and so are the heights (on a screen
    // tall enough for their rows).
    let givens = render("paper-b4.9", None, (120, 40), false, "y g");
    assert!(givens.contains("h left       9.42 cm"), "{givens}");
    // Answered and played past the outcome: the chain shows them.
    let answered = render("paper-b4.9", Some(1.0), (120, 40), false, "y 3");
    assert!(
        answered.contains("|a_cm| 3.67 m/s²") && answered.contains("|a_t| 1.89 m/s²"),
        "{answered}"
    );
    assert!(answered.contains("h left       9.42 cm"), "{answered}");
}
