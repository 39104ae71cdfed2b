//! The one key table: it maps keys to actions, and feeds the hint bar, the help popup
//! and `render --keys` (which names keys exactly as the help shows them).

use ratatui::crossterm::event::{Event, KeyCode, KeyEvent, KeyModifiers};

use super::vocabulary::{Action, Mode};

mod table;

pub use table::{Binding, TABLE};

/// A key name of the table as the help and the hint bar show it: arrows as arrows
/// (`up` ↑, `S-right` Shift-→; spelt out in ASCII), `pgup` PgUp, `C-c` Ctrl-C; the
/// rest as named. [`parse`] reads both.
pub fn display(name: &str, ascii: bool) -> String {
    let (prefix, base) = match name.split_at_checked(2) {
        Some(("S-", base)) if !base.is_empty() => ("Shift-", base),
        Some(("C-", base)) if !base.is_empty() => ("Ctrl-", base),
        _ => ("", name),
    };
    let base = match (base, ascii) {
        ("up", false) => "↑".to_string(),
        ("down", false) => "↓".to_string(),
        ("left", false) => "←".to_string(),
        ("right", false) => "→".to_string(),
        ("pgup", _) => "PgUp".to_string(),
        ("pgdn", _) => "PgDn".to_string(),
        (c, _) if prefix == "Ctrl-" => c.to_uppercase(),
        (other, _) => other.to_string(),
    };
    format!("{prefix}{base}")
}

/// A binding's keys as the help shows them, blank-separated.
pub fn display_keys(b: &Binding, ascii: bool) -> String {
    let names: Vec<String> = b.keys.iter().map(|k| display(k, ascii)).collect();
    names.join(" ")
}

/// A name as [`display`] shows it, back to the table's (`Shift-→` is `S-right`).
fn from_display(name: &str) -> String {
    let (prefix, base) = if let Some(b) = name.strip_prefix("Shift-").filter(|b| !b.is_empty()) {
        ("S-", b)
    } else if let Some(b) = name.strip_prefix("Ctrl-").filter(|b| !b.is_empty()) {
        ("C-", b)
    } else {
        ("", name)
    };
    let base = match base {
        "↑" => "up",
        "↓" => "down",
        "←" => "left",
        "→" => "right",
        other => other,
    };
    format!("{prefix}{base}")
}

/// Parses a key name of the table (`space`, `S-left`, `C-c`, `pgup`, …), in any case
/// (`End`, `PgUp`, `c-c`), as the help shows it (`↑`, `Shift-→`, `Ctrl-C`), or a
/// single character (typed as itself: `R` is not `r`).
pub fn parse(name: &str) -> Option<KeyEvent> {
    let name = from_display(name);
    let name = name.as_str();
    let prefix = |p: &str| {
        name.get(..2)
            .filter(|head| head.eq_ignore_ascii_case(p) && name.len() > 2)
            .map(|_| &name[2..])
    };
    let (mods, base) = if let Some(rest) = prefix("S-") {
        (KeyModifiers::SHIFT, rest)
    } else if let Some(rest) = prefix("C-") {
        (KeyModifiers::CONTROL, rest)
    } else {
        (KeyModifiers::NONE, name)
    };
    // A name of more than one character is a key's name in any case; Ctrl with a
    // letter is the letter's key (C-U is C-u, as terminals send it).
    let lower = base.to_ascii_lowercase();
    let base = if base.chars().count() > 1 || mods == KeyModifiers::CONTROL {
        lower.as_str()
    } else {
        base
    };
    let code = match base {
        "space" => KeyCode::Char(' '),
        "up" => KeyCode::Up,
        "down" => KeyCode::Down,
        "left" => KeyCode::Left,
        "right" => KeyCode::Right,
        "tab" => KeyCode::Tab,
        "enter" => KeyCode::Enter,
        "esc" => KeyCode::Esc,
        "backspace" => KeyCode::Backspace,
        "delete" => KeyCode::Delete,
        "home" => KeyCode::Home,
        "end" => KeyCode::End,
        "pgup" => KeyCode::PageUp,
        "pgdn" => KeyCode::PageDown,
        other => {
            let mut chars = other.chars();
            let c = chars.next()?;
            if chars.next().is_some() {
                return None;
            }
            KeyCode::Char(c)
        }
    };
    Some(KeyEvent::new(code, mods))
}

/// The action a key press means in `mode`, if any.
pub fn action(mode: &Mode, key: KeyEvent) -> Option<Action> {
    if key.code == KeyCode::Char('c') && key.modifiers.contains(KeyModifiers::CONTROL) {
        return Some(Action::QuitNow);
    }
    if mode.is_typing() {
        return match (key.code, mode) {
            (KeyCode::Enter, _) => Some(Action::Confirm),
            (KeyCode::Esc, _) => Some(Action::Cancel),
            (KeyCode::Char(c), Mode::ConfirmOverwrite(_)) => Some(Action::Type(c)),
            (_, Mode::ConfirmOverwrite(_)) => None,
            // ↑/↓: earlier entries of this prompt; the rest edits the line as a
            // terminal does (tui-input's bindings, Ctrl-A/E/U/W/K among them).
            (KeyCode::Up, _) => Some(Action::Up),
            (KeyCode::Down, _) => Some(Action::Down),
            _ => {
                tui_input::backend::crossterm::to_input_request(&Event::Key(key)).map(Action::Line)
            }
        };
    }
    // The prediction's question takes its answers as typed digits, and `g` (the
    // forces shown as givens, or hidden).
    if *mode == Mode::Predict
        && let KeyCode::Char(c) = key.code
        && (c.is_ascii_digit() || c == 'g')
    {
        return Some(Action::Type(c));
    }
    // In a popup (help, picker, data table) `q` closes it like Esc: only the main
    // screen quits on `q`.
    if *mode != Mode::Normal && key.code == KeyCode::Char('q') {
        return Some(Action::Cancel);
    }
    // Terminals report Shift+← as Left with SHIFT; a typed `+` may carry SHIFT too.
    let plain_char = matches!(key.code, KeyCode::Char(_));
    TABLE.iter().find_map(|b| {
        b.keys
            .iter()
            .any(|name| {
                parse(name).is_some_and(|k| {
                    k.code == key.code
                        && (plain_char
                            || k.modifiers
                                == key.modifiers & (KeyModifiers::SHIFT | KeyModifiers::CONTROL))
                })
            })
            .then_some(b.action)
    })
}

/// `render --keys`: whitespace-separated key names.
pub fn parse_script(script: &str) -> Result<Vec<KeyEvent>, UnknownKey> {
    script
        .split_whitespace()
        .map(|name| {
            parse(name).ok_or_else(|| UnknownKey {
                name: name.to_string(),
            })
        })
        .collect()
}

/// A name in a key script that names no key.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error(
    "unknown key '{name}', allowed: a single character or one of space, up, down, left, right, S-left, S-right, tab, enter, esc, backspace, delete, home, end, pgup, pgdn, C-c, C-u (C- with any letter: Ctrl; names in any case)"
)]
pub struct UnknownKey {
    pub name: String,
}

/// Width of one hint in the bar: keys, a space, the label, two spaces.
pub fn hint_width(keys: &str, label: &str) -> usize {
    keys.chars().count() + label.chars().count() + 3
}

/// The hint bar's entries that fit in `width` columns, in table order: the lowest
/// priority goes first, so `? help` and `q quit` stay at every width.
pub fn hints_within(width: usize, ascii: bool) -> Vec<(String, &'static str)> {
    let mut all: Vec<(String, &'static str, u8)> = hints(ascii)
        .into_iter()
        .zip(TABLE.iter().filter_map(|b| b.hint))
        .map(|((keys, label), (_, priority))| (keys, label, priority))
        .collect();
    let total = |v: &[(String, &str, u8)]| v.iter().map(|h| hint_width(&h.0, h.1)).sum::<usize>();
    while total(&all) > width && all.len() > 2 {
        // The last of the lowest priority goes first.
        let lowest = all.iter().map(|h| h.2).min().unwrap_or(0);
        let i = all.iter().rposition(|h| h.2 == lowest).unwrap_or(0);
        all.remove(i);
    }
    all.into_iter().map(|(k, l, _)| (k, l)).collect()
}

/// The hint bar's entries: `(keys, label)`, arrows spelt out in ASCII.
pub fn hints(ascii: bool) -> Vec<(String, &'static str)> {
    TABLE
        .iter()
        .filter_map(|b| {
            let (label, _) = b.hint?;
            let keys = match (b.action, ascii) {
                (Action::Decrease, false) => "←→",
                (Action::Decrease, true) => "left/right",
                (Action::Down, false) => "↑↓",
                (Action::Down, true) => "up/down",
                (Action::Slower, _) => "+-",
                _ => return Some((display(b.keys[0], ascii), label)),
            };
            Some((keys.to_string(), label))
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn no_key_is_bound_twice() {
        // e is the energy chart (issue 11a), w / W write the run / the chart.
        let mut seen = std::collections::HashSet::new();
        for b in TABLE {
            for k in b.keys {
                assert!(seen.insert(*k), "{k} is bound twice");
            }
        }
        for k in [
            "e", "w", "W", "a", "d", "t", "P", ">", "<", "x", "b", "c", "g", "f", "o", "z", "Z",
            "0",
        ] {
            assert!(seen.contains(k), "{k} is not bound");
        }
    }

    #[test]
    fn every_name_in_the_table_parses() {
        for b in TABLE {
            for name in b.keys {
                assert!(parse(name).is_some(), "{name}");
                assert_eq!(
                    action(&Mode::Normal, parse(name).unwrap()),
                    Some(b.action),
                    "{name}"
                );
            }
        }
    }

    #[test]
    fn typing_mode_types_characters() {
        use tui_input::InputRequest::*;
        let edit = Mode::Edit(Default::default());
        let line = |name: &str| action(&edit, parse(name).unwrap());
        assert_eq!(line("q"), Some(Action::Line(InsertChar('q'))));
        assert_eq!(line("."), Some(Action::Line(InsertChar('.'))));
        assert_eq!(line("C-u"), Some(Action::Line(DeleteLine)));
        assert_eq!(line("C-w"), Some(Action::Line(DeletePrevWord)));
        assert_eq!(line("C-a"), Some(Action::Line(GoToStart)));
        assert_eq!(line("C-e"), Some(Action::Line(GoToEnd)));
        assert_eq!(line("C-k"), Some(Action::Line(DeleteTillEnd)));
        assert_eq!(line("left"), Some(Action::Line(GoToPrevChar)));
        assert_eq!(line("home"), Some(Action::Line(GoToStart)));
        assert_eq!(line("delete"), Some(Action::Line(DeleteNextChar)));
        assert_eq!(line("up"), Some(Action::Up));
        assert_eq!(
            action(&edit, parse("enter").unwrap()),
            Some(Action::Confirm)
        );
        assert_eq!(action(&edit, parse("C-c").unwrap()), Some(Action::QuitNow));
    }

    #[test]
    fn q_closes_popups_types_in_prompts_and_quits_only_the_main_screen() {
        let q = parse("q").unwrap();
        assert_eq!(action(&Mode::Normal, q), Some(Action::Quit));
        for popup in [Mode::Help, Mode::Picker(0), Mode::Table] {
            assert_eq!(action(&popup, q), Some(Action::Cancel), "{popup:?}");
            assert_eq!(action(&popup, parse("C-c").unwrap()), Some(Action::QuitNow));
        }
        for prompt in [
            Mode::SaveName(Default::default()),
            Mode::Export(Export::Csv, Default::default()),
        ] {
            let typed = Some(Action::Line(tui_input::InputRequest::InsertChar('q')));
            assert_eq!(action(&prompt, q), typed, "{prompt:?}");
        }
        let confirm = Mode::ConfirmOverwrite("x".into());
        use crate::tui::vocabulary::Export;
        assert_eq!(action(&confirm, q), Some(Action::Type('q')));
    }

    #[test]
    fn the_hint_bar_keeps_help_and_quit_at_every_width() {
        for width in [20, 60, 78, 80, 118, 198] {
            let h = hints_within(width, false);
            let labels: Vec<&str> = h.iter().map(|x| x.1).collect();
            assert!(labels.ends_with(&["help", "quit"]), "{width}: {labels:?}");
            let used: usize = h.iter().map(|(k, l)| hint_width(k, l)).sum();
            assert!(used <= width.max(hint_width("?", "help") + hint_width("q", "quit")));
        }
        // At 80 columns the most important keys stay, in table order.
        let labels: Vec<&str> = hints_within(78, true).iter().map(|x| x.1).collect();
        assert!(
            labels.starts_with(&["play", "select", "change"]),
            "{labels:?}"
        );
        assert_eq!(hints_within(400, false).len(), hints(false).len());
        // The Forces view and the prediction are named at 120 columns (a new user
        // did not find them).
        let labels: Vec<&str> = hints_within(120, false).iter().map(|x| x.1).collect();
        assert!(
            labels.contains(&"forces") && labels.contains(&"predict"),
            "{labels:?}"
        );
    }

    #[test]
    fn shift_arrows_are_coarse() {
        let k = KeyEvent::new(KeyCode::Right, KeyModifiers::SHIFT);
        assert_eq!(action(&Mode::Normal, k), Some(Action::IncreaseCoarse));
        let k = KeyEvent::new(KeyCode::Right, KeyModifiers::NONE);
        assert_eq!(action(&Mode::Normal, k), Some(Action::Increase));
    }

    #[test]
    fn key_names_are_read_in_any_case_and_single_characters_as_typed() {
        for (name, same) in [
            ("End", "end"),
            ("PGUP", "pgup"),
            ("PgDn", "pgdn"),
            ("Space", "space"),
            ("s-LEFT", "S-left"),
            ("c-c", "C-c"),
            ("C-U", "C-u"),
        ] {
            assert_eq!(parse(name), parse(same), "{name}");
            assert!(parse(name).is_some(), "{name}");
        }
        // A single character is typed as itself: R resets, r restarts.
        assert_ne!(parse("R"), parse("r"));
        assert_eq!(
            action(&Mode::Normal, parse("R").unwrap()),
            Some(Action::Reset)
        );
        // `S-` and `C-` alone are characters' names, not prefixes.
        assert_eq!(parse("S-"), None);
    }

    #[test]
    fn the_help_shows_the_hint_bars_names_and_they_parse() {
        assert_eq!(display("up", false), "↑");
        assert_eq!(display("up", true), "up");
        assert_eq!(display("S-right", false), "Shift-→");
        assert_eq!(display("S-right", true), "Shift-right");
        assert_eq!(display("pgup", false), "PgUp");
        assert_eq!(display("C-c", false), "Ctrl-C");
        assert_eq!(display("space", false), "space");
        assert_eq!(display("S", false), "S");
        for b in TABLE {
            for name in b.keys {
                for ascii in [false, true] {
                    let shown = display(name, ascii);
                    assert_eq!(parse(&shown), parse(name), "{name} shown as {shown}");
                }
            }
        }
        // The names `--keys` took before stay.
        assert_eq!(parse("S-right"), parse("Shift-→"));
        assert_eq!(parse("c-c"), parse("Ctrl-C"));
    }

    #[test]
    fn scripts_reject_unknown_names() {
        assert!(parse_script("space right enter").is_ok());
        assert_eq!(parse_script("spacebar").unwrap_err().name, "spacebar");
    }
}
