//! Issue 28, "the classroom": what a class sees on a projector, each item a regression
//! test through the binary as a user runs it (`render` draws the app's very screen).

use crate::common::{groovelab, stdout};

/// The screen `render` prints for `args` (which must succeed).
fn screen(args: &[&str]) -> String {
    stdout(&[&["render"], args].concat())
}

/// Typing the b* the screen shows (4.26 cm, rounded from 4.2603 cm) gives D e =
/// 1.0002: "D e = 1.000 > 1" contradicted itself at the precision shown.
#[test]
fn the_shown_critical_width_says_what_is_true_at_the_shown_precision() {
    let s = screen(&["--width", "4.26cm", "--size", "120x40", "--at", "0.3"]);
    assert!(!s.contains("D e = 1.000"), "{s}");
    assert!(s.contains("D e = 1 + 2e-4 > 1"), "{s}");
    let out = groovelab(&["simulate", "--width", "4.26cm"]);
    let table = String::from_utf8(out.stdout).unwrap();
    assert!(
        table.contains("D e = 1 + 2e-4 > 1: translation reverses first, but barely"),
        "{table}"
    );
}

/// The Methods view's legend counted "1 impacts".
#[test]
fn one_impact_is_singular() {
    let s = screen(&["--preset", "paper-b3.5", "--keys", "c", "--size", "120x40"]);
    assert!(s.contains("outcome right (depart, 1 impact)"), "{s}");
    assert!(!s.contains("1 impacts"), "{s}");
}

/// The error bars' legend said "±1s" (σ replaced by s even in Unicode); ASCII says
/// "+-1 sd".
#[test]
fn the_error_bars_legend_says_sigma() {
    let track = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/docs/video/paper-b4.9-tracker.txt"
    );
    let args = ["--data", track, "--size", "120x40", "--at", "0.1"];
    let s = screen(&args);
    assert!(s.contains("¦ ±1σ × measured v_cm"), "{s}");
    assert!(!s.contains("±1s"), "{s}");
    let s = screen(&[&args[..], &["--ascii"]].concat());
    assert!(s.contains("! +-1 sd x measured v_cm"), "{s}");
}

/// At b = 4.3 cm a_t = −(5/2) μ_k g k = −2.600 m/s²: shown as "-2.6" beside
/// "2.675", one figure short; the Forces view's chain as "2.6" beside "152".
#[test]
fn computed_values_keep_their_significant_figures() {
    let s = screen(&["--width", "4.3cm", "--size", "120x40", "--at", "0.1"]);
    assert!(s.contains("a_cm 2.675 m/s²  a_t -2.600 m/s²"), "{s}");
    let s = screen(&[
        "--width", "4.3cm", "--size", "120x40", "--at", "0.1", "--keys", "v",
    ]);
    assert!(s.contains("|a_t| 2.60 m/s²"), "{s}");
}

/// With μ_k = 1e-8 the Why panel said "F_net 0.000 N" under "a_cm 2.160e-7": the
/// force m a_cm = 0.167 kg × 2.160e-7 m/s² = 3.607e-8 N is shown as such.
#[test]
fn a_tiny_force_is_not_shown_as_zero() {
    let s = screen(&["--mu", "1e-8", "--size", "120x40", "--at", "0.1"]);
    assert!(s.contains("a_cm 2.160e-7 m/s²"), "{s}");
    assert!(s.contains("F_net 3.607e-8 N"), "{s}");
    assert!(!s.contains("0.000 N"), "{s}");
    let out = groovelab(&["simulate", "--mu", "1e-8"]);
    let table = String::from_utf8(out.stdout).unwrap();
    assert!(table.contains("F_net = 3.607e-8 N (x)"), "{table}");
}

/// Values from which D follows at paper-b4.9 (b = 4.9 cm, R = 2.75 cm): k 0.454, r
/// 1.25 cm, b* 4.26 cm, D 0.516, |N| 1.80 N, |F| 0.307 N, F_net 0.613 N, |a_cm| 3.67,
/// |a_t| 1.89 m/s², ω 48.3 rad/s after the impact; the outcome's words and the event
/// labels that come after it; the preset's name and description. (b* gives nothing
/// away while b itself is hidden.)
const GIVE_AWAY: [&str; 19] = [
    "0.454",
    "1.25 cm",
    "1.249",
    "4.26",
    "0.516",
    "1.80 N",
    "1.804",
    "0.307",
    "0.613",
    "3.67",
    "1.89",
    "48.3",
    "RECOLLIDE",
    "DEPART",
    "T∞",
    "│rolling",
    "│slipping",
    "paper-b4.9",
    "collide again and again",
];

fn gives_nothing_away(screen: &str, what: &str) {
    let b_hidden = what.starts_with("B ");
    for word in GIVE_AWAY
        .into_iter()
        .filter(|w| !(b_hidden && *w == "4.26"))
    {
        assert!(
            !screen.contains(word),
            "{what}: '{word}' on screen\n{screen}"
        );
    }
}

/// Predict mode at 80×24, 120×40 and 200×60 shows no outcome, event label, or value
/// from which D follows until the answer shows: asked (`y`), answered and playing (`y
/// 3`, before the left ball turns (0.216 s) and rolls again (0.285 s), in the Forces
/// view and the charts.
#[test]
fn predict_mode_gives_nothing_away_at_any_size() {
    for size in ["80x24", "120x40", "200x60"] {
        let asked = screen(&["--keys", "y", "--size", size]);
        // The question itself lists "they come back and collide again".
        gives_nothing_away(&asked, &format!("asked at {size}"));
        for keys in ["y 3", "y 3 v"] {
            for at in ["0.0", "0.1", "0.2"] {
                let s = screen(&["--keys", keys, "--at", at, "--size", size]);
                gives_nothing_away(&s, &format!("'{keys}' at {at} s, {size}"));
            }
        }
    }
    // Once the outcome shows, everything does.
    let after = screen(&["--keys", "y 3 v", "--at", "0.9", "--size", "120x40"]);
    assert!(
        after.contains("RECOLLIDE") && after.contains("T∞"),
        "{after}"
    );
}

/// A second round asks afresh: the first round's answer is not on screen.
#[test]
fn a_second_prediction_round_does_not_show_the_first_answer() {
    let s = screen(&["--keys", "y 3 y", "--size", "120x40"]);
    assert!(s.contains("what will the balls do?"), "{s}");
    assert!(!s.contains("predicted:"), "{s}");
}

/// With b hidden (`B`), outside predict mode: the chart grows with the run (no curve
/// or event label past the cursor), the status line names no preset, the picker
/// states no outcome.
#[test]
fn hiding_b_hides_the_chart_ahead_the_preset_and_its_outcomes() {
    for size in ["80x24", "120x40", "200x60"] {
        let s = screen(&["--keys", "B", "--at", "0.1", "--size", size]);
        gives_nothing_away(&s, &format!("B at {size}"));
    }
    let picker = screen(&["--keys", "B p", "--size", "120x40"]);
    for outcome in ["roll apart", "come back", "both balls stop", "recollide"] {
        assert!(!picker.contains(outcome), "{picker}");
    }
    assert!(picker.contains("description hidden"), "{picker}");
}

/// The teacher's choice: `g` in the question shows the forces as the exercise's
/// givens (|F| 0.307 N, F_net 0.613 N), still without D or the outcome.
#[test]
fn predict_mode_can_show_the_forces_as_givens() {
    let s = screen(&["--keys", "y g 3", "--at", "0.1", "--size", "120x40"]);
    assert!(s.contains("0.307 N") && s.contains("F_net 0.613 N"), "{s}");
    assert!(s.contains("D = |a_t|/|a_cm| = ?"), "{s}");
    assert!(!s.contains("RECOLLIDE"), "{s}");
    let asked = screen(&["--keys", "y g", "--size", "120x40"]);
    assert!(asked.contains("the forces: shown as givens"), "{asked}");
}

/// The rows of `screen` below the parameter and scene panels (the view and the
/// status and hint lines): what the keys of a view put on screen.
fn below_the_scene(screen: &str) -> String {
    let lines: Vec<&str> = screen.lines().collect();
    let top = 1 + lines[1..].iter().position(|l| l.starts_with('╭')).unwrap();
    lines[top..].join("\n")
}

/// Predict mode at 80×24, 120×40 and 200×60, answered and watched up to just before
/// the impact, shows the same view whatever the outcome: a pair that departs (b = 3.5
/// cm), one that comes back within a second (4.9 cm) and one that comes back over 13
/// s (4.3 cm). The span's end (the chart's x axis, the status line), the y range of
/// the whole run (a velocity that turns negative), the Methods runs, the map with b
/// on it and the fit each told the outcome. (One app per scene and keys, drawn at
/// each size, as `render` draws it: its analyses run once.)
#[test]
fn predict_mode_shows_the_same_view_whatever_the_outcome() {
    use groovelab::cli::DataArgs;
    use groovelab::settings::params::Key;
    use groovelab::settings::spec::SceneSpec;

    use crate::common::{no_user_presets, rendered, scene_of, text};
    let sizes = [(80, 24), (120, 40), (200, 60)];
    for size in sizes {
        // Asked: the status line names no span (it said "of -0.200 … 1.077 s").
        let asked = screen(&["--keys", "y", "--size", &format!("{}x{}", size.0, size.1)]);
        assert!(
            !asked.contains("1.077") && !asked.contains(" of -0.200"),
            "{asked}"
        );
    }
    // (The energy chart differs: a rolling ball's energy depends on b through k.)
    for keys in ["y 3 v", "y 3 c", "y 3 g", "y 3 f", "y 3 v x"] {
        let apps: Vec<_> = [0.035, 0.043, 0.049]
            .iter()
            .map(|&b| {
                let scene = scene_of("paper-b4.9", SceneSpec::default().with(Key::Width, b));
                let library = no_user_presets("classroom");
                rendered(
                    &scene,
                    &DataArgs::default(),
                    Some(-0.1),
                    Some(keys),
                    library,
                )
            })
            .collect();
        for size in sizes {
            let views: Vec<String> = apps
                .iter()
                .map(|a| below_the_scene(&text(a, size, false)))
                .collect();
            assert_eq!(views[0], views[1], "'{keys}' {size:?}: 3.5 cm and 4.3 cm");
            assert_eq!(views[1], views[2], "'{keys}' {size:?}: 4.3 cm and 4.9 cm");
        }
    }
}

/// The energy chart before the impact shows rotational over translational energy,
/// 2/(5k²) = 1/D: the answer. While the outcome is hidden (b hidden, or a prediction
/// pending) it is withheld, and shows again once the outcome does.
#[test]
fn the_energy_chart_waits_for_the_outcome() {
    for keys in ["B e", "y 3 v e"] {
        let s = screen(&["--keys", keys, "--at", "-0.1", "--size", "120x40"]);
        assert!(!s.contains("Energy of both balls"), "'{keys}':\n{s}");
        assert!(s.contains("the energy chart shows"), "'{keys}':\n{s}");
    }
    let after = screen(&["--keys", "y 3 v e", "--at", "0.9", "--size", "120x40"]);
    assert!(after.contains("Energy of both balls"), "{after}");
}

/// The data table's rows after the cursor hold the speeds after the impact (the
/// paper's b = 3.5 cm data end at -0.119 m/s: they depart). While the outcome is
/// hidden the table ends at the cursor, as the charts do.
#[test]
fn the_data_table_ends_at_the_cursor_while_the_outcome_is_hidden() {
    let rows = |s: &str| {
        s.lines()
            .filter(|l| l.contains("+0.") || l.contains("-0."))
            .filter(|l| l.matches('.').count() >= 7)
            .count()
    };
    for keys in ["B d", "y 1 d"] {
        let s = screen(&["--preset", "paper-b3.5", "--keys", keys, "--at", "-0.1"]);
        assert!(s.contains("rows up to the cursor"), "'{keys}':\n{s}");
        // Frames at -0.18, -0.16, -0.14, -0.12, -0.10 s: five rows, none after.
        assert_eq!(rows(&s), 5, "'{keys}':\n{s}");
    }
    let open = screen(&["--preset", "paper-b3.5", "--keys", "d", "--at", "-0.1"]);
    assert!(rows(&open) > 5, "{open}");
}
