//! What a new user's trial of the app found (2026-11-26): the Fit panel's models cut
//! off, the prediction's result shown only in the Forces view, the help covering the
//! status line and swallowing the key that closed it, status messages cut without an
//! ellipsis.

use groovelab::cli::DataArgs;
use groovelab::settings::spec::SceneSpec;
use groovelab::tui::app::{App, Mode};

use crate::common::{self, press, scene_of, text};

fn rendered(keys: &str, at: Option<f64>) -> App {
    let scene = scene_of("paper-b4.9", SceneSpec::default());
    let library = common::no_user_presets("new-user-trial");
    common::rendered(&scene, &DataArgs::default(), at, Some(keys), library)
}

/// The status line: the second-last row of the screen.
fn status_line(screen: &str, rows: usize) -> &str {
    screen.lines().nth(rows - 2).unwrap_or("")
}

#[test]
fn every_model_of_the_fit_is_reachable() {
    let a = rendered("f", None);
    let screen = text(&a, (120, 40), false);
    let groovelab::lab::jobs::State::Ready(Ok(fits)) = a.fit().fits() else {
        panic!("the fit is there");
    };
    let n = fits.models.len();
    assert!(n > 1, "{n}");
    // The panel says where the rest is.
    assert!(
        screen.contains(&format!("models by BIC, lowest first (M lists all {n})")),
        "{screen}"
    );
    assert!(!screen.contains("never named"), "{screen}");
    // M lists every model, the supported one marked, and the marks' meaning.
    let mut a = rendered("f M", None);
    assert_eq!(a.mode(), Mode::Models);
    let popup = text(&a, (120, 40), false);
    let rows = popup
        .lines()
        .skip_while(|l| !l.contains("Models by BIC"))
        .take_while(|l| !l.contains('╰'))
        .filter(|l| l.contains(" AIC "))
        .count();
    assert_eq!(rows, n, "{popup}");
    assert!(popup.contains("* = the model the data support"), "{popup}");
    press(&mut a, "esc");
    assert_eq!(a.mode(), Mode::Normal);
    // Outside the Fit view M says where it works.
    let a = rendered("M", None);
    assert_eq!(a.mode(), Mode::Normal);
    assert!(text(&a, (120, 40), false).contains("M lists the fit's models"));
}

#[test]
fn the_predictions_result_shows_in_every_view_once_the_outcome_shows() {
    // Predicted "move apart"; paper-b4.9 recollides. Before the outcome: no result.
    let before = rendered("y 1 v", Some(0.0));
    let screen = text(&before, (120, 40), false);
    let status = status_line(&screen, 40);
    assert!(status.contains("predicted: move apart"), "{status}");
    assert!(
        !status.contains("observed") && !status.contains("RECOLLIDE"),
        "{status}"
    );
    // After it, in the Charts view (v left the Forces view) and in the Fit view.
    for keys in ["y 1 end v", "y 1 end f"] {
        let after = rendered(keys, None);
        for ascii in [false, true] {
            let screen = text(&after, (120, 40), ascii);
            let status = status_line(&screen, 40);
            let mark = if ascii { "(not quite)" } else { "✗" };
            assert!(
                status.contains(&format!(
                    "predicted: move apart, observed: RECOLLIDE {mark}"
                )),
                "{keys}: {status}"
            );
        }
    }
}

#[test]
fn the_help_leaves_the_status_line_whole_and_other_keys_act() {
    for (w, h) in [(80, 24), (120, 40), (200, 60)] {
        let plain = text(&rendered("", None), (w, h), false);
        let help = text(&rendered("?", None), (w, h), false);
        let rows = usize::from(h);
        assert_eq!(
            status_line(&help, rows),
            status_line(&plain, rows),
            "{w}x{h}"
        );
        assert_eq!(help.lines().last(), plain.lines().last(), "{w}x{h}");
    }
    // The help shows the keys by the hint bar's names.
    let help = text(&rendered("?", None), (120, 40), false);
    assert!(
        help.contains(" ↑  ") && help.contains("Shift-→ PgUp"),
        "{help}"
    );
    // A key that is not the help's closes it and acts: p opens the picker.
    let a = rendered("? p", None);
    assert!(matches!(a.mode(), Mode::Picker(_)), "{:?}", a.mode());
    // Its own key and Esc only close it.
    assert_eq!(rendered("? ?", None).mode(), Mode::Normal);
    assert_eq!(rendered("? esc", None).mode(), Mode::Normal);
}
