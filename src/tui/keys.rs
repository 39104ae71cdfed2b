//! The one key table: it maps keys to actions, and feeds the hint bar, the help popup
//! and `render --keys` (which names keys exactly as the help shows them).

use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};

use super::app::{Action, Mode};

/// One line of the key table.
#[derive(Clone, Copy, Debug)]
pub struct Binding {
    /// Key names, as `--keys` takes them and the help shows them.
    pub keys: &'static [&'static str],
    pub action: Action,
    pub help: &'static str,
    /// Short label for the hint bar, if it earns a place there.
    pub hint: Option<&'static str>,
}

pub const TABLE: &[Binding] = &[
    Binding {
        keys: &["space"],
        action: Action::PlayPause,
        help: "play / pause",
        hint: Some("play"),
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
        hint: Some("select"),
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
        hint: Some("change"),
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
        help: "type a value with units, e.g. 4.4cm (Esc cancels)",
        hint: Some("type"),
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
        hint: Some("speed"),
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
        help: "jump to the next event (impact, rolling, rest, T-inf); click the chart to seek",
        hint: None,
    },
    Binding {
        keys: &["<"],
        action: Action::PrevEvent,
        help: "jump to the previous event",
        hint: None,
    },
    Binding {
        keys: &["t"],
        action: Action::CycleSpan,
        help: "time span: auto (a little past the last event), x2, x1/2",
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
        help: "chart: left ball, right ball, both",
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
        action: Action::ToggleMethods,
        help: "Methods view: error against work of each solution method",
        hint: Some("methods"),
    },
    Binding {
        keys: &["g"],
        action: Action::ToggleMap,
        help: "Map view: regime over b/R and e with this scene marked, the paper's figure",
        hint: Some("map"),
    },
    Binding {
        keys: &["f"],
        action: Action::ToggleFit,
        help: "Fit view: the paper's line fits and a model fit to the measured data",
        hint: Some("fit"),
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
        help: "overlay a time-stepping method on the exact curves (cycles, then off)",
        hint: Some("overlay"),
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
        keys: &["p"],
        action: Action::Presets,
        help: "choose a preset",
        hint: Some("presets"),
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
        help: "this help",
        hint: Some("help"),
    },
    Binding {
        keys: &["esc"],
        action: Action::Cancel,
        help: "close a popup, cancel typing, or quit",
        hint: None,
    },
    Binding {
        keys: &["q", "C-c"],
        action: Action::Quit,
        help: "quit",
        hint: Some("quit"),
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
    if matches!(
        mode,
        Mode::Edit(_) | Mode::SaveName(_) | Mode::ConfirmOverwrite(_)
    ) {
        return match key.code {
            KeyCode::Enter => Some(Action::Confirm),
            KeyCode::Esc => Some(Action::Cancel),
            KeyCode::Backspace => Some(Action::Backspace),
            KeyCode::Char(c) => Some(Action::Type(c)),
            _ => None,
        };
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
pub fn parse_script(script: &str) -> Result<Vec<KeyEvent>, String> {
    script
        .split_whitespace()
        .map(|name| {
            parse(name).ok_or_else(|| {
                format!(
                    "--keys: unknown key '{name}', allowed: a single character or one of space, up, down, left, right, S-left, S-right, tab, enter, esc, backspace, home, end, pgup, pgdn, C-c"
                )
            })
        })
        .collect()
}

/// The hint bar's entries: `(keys, label)`, arrows spelt out in ASCII.
pub fn hints(ascii: bool) -> Vec<(String, &'static str)> {
    TABLE
        .iter()
        .filter_map(|b| {
            let label = b.hint?;
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
        let edit = Mode::Edit(String::new());
        assert_eq!(action(&edit, parse("q").unwrap()), Some(Action::Type('q')));
        assert_eq!(action(&edit, parse(".").unwrap()), Some(Action::Type('.')));
        assert_eq!(
            action(&edit, parse("enter").unwrap()),
            Some(Action::Confirm)
        );
        assert_eq!(action(&edit, parse("C-c").unwrap()), Some(Action::Quit));
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
        assert!(parse_script("spacebar").unwrap_err().contains("spacebar"));
    }
}
