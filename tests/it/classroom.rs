//! Issue 28, "the classroom": what a class sees on a projector, each item a regression
//! test through the binary as a user runs it (`render` draws the app's very screen).

use crate::common::groovelab;

/// The screen `render` prints for `args` (which must succeed).
fn screen(args: &[&str]) -> String {
    let out = groovelab(&[&["render"], args].concat());
    assert!(
        out.status.success(),
        "{args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).unwrap()
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
