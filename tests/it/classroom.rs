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
