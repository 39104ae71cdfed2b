//! The one key table: it maps keys to actions, and feeds the hint bar, the help popup
//! and `render --keys` (which names keys exactly as the help shows them).

use ratatui::crossterm::event::{Event, KeyCode, KeyEvent, KeyModifiers};

use super::vocabulary::{Action, Export, Mode, View};

/// One line of the key table.
#[derive(Clone, Copy, Debug)]
pub struct Binding {
    /// Key names, as `--keys` takes them and the help shows them.
    pub keys: &'static [&'static str],
    pub action: Action,
    pub help: &'static str,
    /// Short label for the hint bar, if it earns a place there, and its priority: a
    /// narrow hint bar drops the lowest first (`? help` and `q quit` never go).
    pub hint: Option<(&'static str, u8)>,
}

pub const TABLE: &[Binding] = &[
    Binding {
        keys: &["space"],
        action: Action::PlayPause,
        help: "play / pause",
        hint: Some(("play", 8)),
    },
    Binding {
        keys: &["up"],
        action: Action::Up,
        help: "previous parameter",
        hint: None,
    },
    Binding {
        keys: &["down", "tab"],
        action: Action::Down,
        help: "next parameter",
        hint: Some(("select", 7)),
    },
    Binding {
        keys: &["right"],
        action: Action::Increase,
        help: "increase the parameter (fine)",
        hint: None,
    },
    Binding {
        keys: &["left"],
        action: Action::Decrease,
        help: "decrease the parameter (fine)",
        hint: Some(("change", 7)),
    },
    Binding {
        keys: &["S-right", "pgup"],
        action: Action::IncreaseCoarse,
        help: "increase the parameter (coarse)",
        hint: None,
    },
    Binding {
        keys: &["S-left", "pgdn"],
        action: Action::DecreaseCoarse,
        help: "decrease the parameter (coarse)",
        hint: None,
    },
    Binding {
        keys: &["enter"],
        action: Action::Edit,
        help: "type a value: a bare number is in the unit shown (4.4 for b is 4.4 cm), or give a unit (44mm); up/down: earlier values, Ctrl-U clears",
        hint: Some(("type", 6)),
    },
    Binding {
        keys: &["+", "="],
        action: Action::Faster,
        help: "faster playback",
        hint: None,
    },
    Binding {
        keys: &["-"],
        action: Action::Slower,
        help: "slower playback",
        hint: Some(("speed", 2)),
    },
    Binding {
        keys: &["."],
        action: Action::StepForward,
        help: "step one frame forward (the next measured frame when data are shown)",
        hint: None,
    },
    Binding {
        keys: &[","],
        action: Action::StepBack,
        help: "step one frame back (the previous measured frame when data are shown)",
        hint: None,
    },
    Binding {
        keys: &[">"],
        action: Action::NextEvent,
        help: "jump to the next event (impact, rolling, rest, T∞); click the chart to seek",
        hint: None,
    },
    Binding {
        keys: &["<"],
        action: Action::PrevEvent,
        help: "jump to the previous event",
        hint: None,
    },
    Binding {
        keys: &["u"],
        action: Action::Undo,
        help: "undo the last change (again: the one before)",
        hint: None,
    },
    Binding {
        keys: &["R"],
        action: Action::Reset,
        help: "reset all parameters to the preset (and the command line's)",
        hint: None,
    },
    Binding {
        keys: &["t"],
        action: Action::CycleSpan,
        help: "time span: auto (a little past the last event), x2, x1/2",
        hint: None,
    },
    Binding {
        keys: &["z"],
        action: Action::ZoomIn,
        help: "charts: zoom in on time, around the cursor (the mouse wheel over a chart: around the pointer)",
        hint: None,
    },
    Binding {
        keys: &["Z"],
        action: Action::ZoomOut,
        help: "charts: zoom out on time, around the cursor",
        hint: None,
    },
    Binding {
        keys: &["0"],
        action: Action::ZoomWhole,
        help: "charts: the whole run again (no time zoom)",
        hint: None,
    },
    Binding {
        keys: &["home"],
        action: Action::Start,
        help: "go to the start",
        hint: None,
    },
    Binding {
        keys: &["end"],
        action: Action::End,
        help: "go to the end",
        hint: None,
    },
    Binding {
        keys: &["r"],
        action: Action::Restart,
        help: "restart and play",
        hint: None,
    },
    Binding {
        keys: &["b"],
        action: Action::SwitchBall,
        help: "chart: left ball, right ball, both (Forces view: left or right ball)",
        hint: None,
    },
    Binding {
        keys: &["x"],
        action: Action::TogglePositions,
        help: "chart: velocities or positions x(t)",
        hint: None,
    },
    Binding {
        keys: &["e"],
        action: Action::ToggleEnergy,
        help: "chart: energy against time (kinetic parts and what was lost to what)",
        hint: None,
    },
    Binding {
        keys: &["P"],
        action: Action::TogglePin,
        help: "pin this run (A/B): change parameters and compare; P again unpins",
        hint: None,
    },
    Binding {
        keys: &["c"],
        action: Action::ShowView(View::Methods),
        help: "Methods view: error against work of each solution method",
        hint: Some(("methods", 3)),
    },
    Binding {
        keys: &["X"],
        action: Action::CycleWorkAxis,
        help: "Methods view: work axis steps, right-hand-side evaluations, time",
        hint: None,
    },
    Binding {
        keys: &["g"],
        action: Action::ShowView(View::Map),
        help: "Map view: regime over b/R and e, this scene marked, paper's figure",
        hint: Some(("map", 3)),
    },
    Binding {
        keys: &["v"],
        action: Action::ShowView(View::Forces),
        help: "Forces view: the groove's cross-section with forces and torques, motion states, the cause-and-effect chain (b: left or right ball)",
        hint: Some(("forces", 4)),
    },
    Binding {
        keys: &["y"],
        action: Action::Predict,
        help: "predict, observe, explain: predict what the balls do after the impact (1 apart, 2 rest, 3 back), watch, then see why",
        hint: Some(("predict", 3)),
    },
    Binding {
        keys: &["B"],
        action: Action::HideWidth,
        help: "hide or show b's value (a class predicts from the picture alone)",
        hint: None,
    },
    Binding {
        keys: &["f"],
        action: Action::ShowView(View::Fit),
        help: "Fit view: the paper's line fits and a model fit to the measured data",
        hint: Some(("fit", 4)),
    },
    Binding {
        keys: &["("],
        action: Action::FitStartEarlier,
        help: "fit window: start one frame earlier",
        hint: None,
    },
    Binding {
        keys: &[")"],
        action: Action::FitStartLater,
        help: "fit window: start one frame later",
        hint: None,
    },
    Binding {
        keys: &["{"],
        action: Action::FitEndEarlier,
        help: "fit window: end one frame earlier",
        hint: None,
    },
    Binding {
        keys: &["}"],
        action: Action::FitEndLater,
        help: "fit window: end one frame later",
        hint: None,
    },
    Binding {
        keys: &["o"],
        action: Action::CycleOverlay,
        help: "overlay a time-stepping method on the exact curves (cycles, off)",
        hint: Some(("overlay", 1)),
    },
    Binding {
        keys: &["]"],
        action: Action::OverlayFiner,
        help: "overlay: smaller step (tighter tolerance)",
        hint: None,
    },
    Binding {
        keys: &["["],
        action: Action::OverlayCoarser,
        help: "overlay: larger step (looser tolerance)",
        hint: None,
    },
    Binding {
        keys: &["a"],
        action: Action::ApplyFit,
        help: "Fit view: put the fitted μ_k (and v0, e if fitted) into the scene",
        hint: None,
    },
    Binding {
        keys: &["V"],
        action: Action::ToggleVideo,
        help: "Scene panel: the drawn scene or the video (--data VIDEO)",
        hint: None,
    },
    Binding {
        keys: &["d"],
        action: Action::DataTable,
        help: "table of the measured data beside the model (scrolls)",
        hint: None,
    },
    Binding {
        keys: &["D"],
        action: Action::DropData,
        help: "drop your own data (--data); a preset picked keeps them",
        hint: None,
    },
    Binding {
        keys: &["w"],
        action: Action::Export(Export::Csv),
        help: "write the run, its scene first, to a CSV file (loads with --data)",
        hint: None,
    },
    Binding {
        keys: &["W"],
        action: Action::Export(Export::Svg),
        help: "write the figure on screen to an SVG file",
        hint: None,
    },
    Binding {
        keys: &["p"],
        action: Action::Presets,
        help: "choose a preset",
        hint: Some(("presets", 5)),
    },
    Binding {
        keys: &["s"],
        action: Action::Save,
        help: "save the scene as a user preset",
        hint: None,
    },
    Binding {
        keys: &["m"],
        action: Action::ToggleMouse,
        help: "mouse on/off (click selects, scroll changes)",
        hint: None,
    },
    Binding {
        keys: &["?"],
        action: Action::Help,
        help: "this help (up/down, pgup/pgdn scroll)",
        hint: Some(("help", 9)),
    },
    Binding {
        keys: &["esc"],
        action: Action::Cancel,
        help: "close a popup, cancel typing (it never quits: q does)",
        hint: None,
    },
    Binding {
        keys: &["q", "C-c"],
        action: Action::Quit,
        help: "quit (q in a popup closes it; Ctrl-C always quits; Ctrl-Z suspends)",
        hint: Some(("quit", 9)),
    },
];

/// Parses a key name of the table (`space`, `S-left`, `C-c`, `pgup`, …) or a single
/// character (typed as itself).
pub fn parse(name: &str) -> Option<KeyEvent> {
    let (mods, base) = if let Some(rest) = name.strip_prefix("S-") {
        (KeyModifiers::SHIFT, rest)
    } else if let Some(rest) = name.strip_prefix("C-") {
        (KeyModifiers::CONTROL, rest)
    } else {
        (KeyModifiers::NONE, name)
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
        return Some(Action::Quit);
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
    "unknown key '{name}', allowed: a single character or one of space, up, down, left, right, S-left, S-right, tab, enter, esc, backspace, delete, home, end, pgup, pgdn, C-c, C-u (C- with any letter: Ctrl)"
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
                _ => b.keys[0],
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
        assert_eq!(action(&edit, parse("C-c").unwrap()), Some(Action::Quit));
    }

    #[test]
    fn q_closes_popups_types_in_prompts_and_quits_only_the_main_screen() {
        let q = parse("q").unwrap();
        assert_eq!(action(&Mode::Normal, q), Some(Action::Quit));
        for popup in [Mode::Help, Mode::Picker(0), Mode::Table] {
            assert_eq!(action(&popup, q), Some(Action::Cancel), "{popup:?}");
            assert_eq!(action(&popup, parse("C-c").unwrap()), Some(Action::Quit));
        }
        for prompt in [
            Mode::SaveName(Default::default()),
            Mode::Export(Export::Csv, Default::default()),
        ] {
            let typed = Some(Action::Line(tui_input::InputRequest::InsertChar('q')));
            assert_eq!(action(&prompt, q), typed, "{prompt:?}");
        }
        let confirm = Mode::ConfirmOverwrite("x".into());
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
    fn scripts_reject_unknown_names() {
        assert!(parse_script("space right enter").is_ok());
        assert_eq!(parse_script("spacebar").unwrap_err().name, "spacebar");
    }
}
