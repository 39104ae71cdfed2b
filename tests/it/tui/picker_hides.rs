//! Issue 37, "no leak": while b is hidden or a prediction pends, the status line hides
//! the preset's name, so the preset picker (`p`) must not mark the loaded preset.

use groovelab::tui::app::Mode;

use crate::common::{self, press, text};

/// The picker's row that carries the selection mark, if any.
/// The picker's marked row: a line with the marker and a preset's name (the
/// parameters panel marks its selected parameter with the same glyph).
fn marked_row(screen: &str, names: &[String]) -> Option<String> {
    screen
        .lines()
        .find(|l| {
            l.split('▸').nth(1).is_some_and(|after| {
                names
                    .iter()
                    .any(|n| after.trim_start().starts_with(n.as_str()))
            })
        })
        .map(|l| l.trim().to_string())
}

#[test]
fn the_picker_marks_no_preset_while_b_is_hidden_or_a_prediction_pends() {
    let library = common::no_user_presets("picker_hides");
    let names: Vec<String> = common::app("paper-b4.9", library.clone())
        .library()
        .presets
        .iter()
        .map(|p| p.name.clone())
        .collect();
    // Every built-in preset, the first and the last in the list among them.
    for name in &names {
        for hide in ["B", "y 1"] {
            let mut a = common::app(name, library.clone());
            press(&mut a, &format!("{hide} p"));
            assert!(matches!(a.mode(), Mode::Picker(_)), "{name} {hide}");
            let screen = text(&a, (120, 40), false);
            assert_eq!(
                marked_row(&screen, &names),
                None,
                "{name} after {hide:?}:\n{screen}"
            );
            // Enter has nothing to load yet; a first arrow marks the first row.
            press(&mut a, "enter");
            assert_eq!(a.lab.preset().name, *name);
            press(&mut a, "down");
            let row = marked_row(&text(&a, (120, 40), false), &names).unwrap_or_default();
            assert!(row.contains(&format!("▸{}", names[0])), "{row}");
        }
    }
    // Without either, it opens on the loaded preset as before.
    let last = names.last().unwrap();
    let mut a = common::app(last, library);
    press(&mut a, "p");
    let row = marked_row(&text(&a, (120, 40), false), &names).unwrap_or_default();
    assert!(row.contains(&format!("▸{last}")), "{row}");
}
