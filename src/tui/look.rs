//! Which colours this terminal gets: `--theme` (or `GROOVELAB_THEME`) dark or light, or
//! auto — the terminal's answer to OSC 11 (its background colour, asked once at
//! startup with a short timeout), then `COLORFGBG`, else dark; NO_COLOR keeps the
//! monochrome theme whatever was asked; `COLORTERM=truecolor` (or `24bit`) sends the
//! palette's colours as RGB instead of xterm-256 indices.

use std::time::Duration;

use super::theme::{Backdrop, Colours, ThemeChoice};

/// The environment variable that gives `--theme` a default: `auto`, `dark` or `light`.
pub const SWITCH: &str = "GROOVELAB_THEME";

/// How long startup waits for the terminal's background colour. Terminals that do not
/// answer OSC 11 answer the query that follows it at once, so this is only reached
/// on a slow line.
const QUERY_TIMEOUT: Duration = Duration::from_millis(500);

/// A `GROOVELAB_THEME` value that is none of the allowed ones.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("{SWITCH}={value:?}: expected auto, dark or light")]
pub struct BadTheme {
    value: String,
}

/// The choice of a `GROOVELAB_THEME` value (unset or empty: auto).
pub fn parse_switch(value: Option<&str>) -> Result<ThemeChoice, BadTheme> {
    match value.map(|v| v.trim().to_ascii_lowercase()).as_deref() {
        None | Some("" | "auto") => Ok(ThemeChoice::Auto),
        Some("dark") => Ok(ThemeChoice::Dark),
        Some("light") => Ok(ThemeChoice::Light),
        Some(_) => Err(BadTheme {
            value: value.unwrap_or_default().to_string(),
        }),
    }
}

/// The background `COLORFGBG` names (`fg;bg` or `fg;default;bg`, as rxvt and
/// Konsole set it): ANSI colours 7 and 9–15 are light backgrounds, 0–6 and 8 dark.
pub fn from_colorfgbg(value: &str) -> Option<Backdrop> {
    let bg: u8 = value.rsplit(';').next()?.trim().parse().ok()?;
    match bg {
        7 | 9..=15 => Some(Backdrop::Light),
        0..=6 | 8 => Some(Backdrop::Dark),
        _ => None,
    }
}

/// Whether `COLORTERM` says the terminal takes 24-bit colour.
pub fn truecolor(colorterm: Option<&str>) -> bool {
    colorterm.is_some_and(|v| matches!(v.trim(), "truecolor" | "24bit"))
}

/// The background that an sRGB colour is: light when its relative luminance is above
/// the middle grey's (a contrast of 4.5:1 to black or to white meets there).
pub fn background_of(rgb: [u8; 3]) -> Backdrop {
    if super::theme::luminance(rgb) > 0.18 {
        Backdrop::Light
    } else {
        Backdrop::Dark
    }
}

/// The colours for `choice`: `ask` is the terminal's background when it answers
/// (called only for auto), `colorfgbg` and `colorterm` the environment's.
pub fn resolve(
    choice: ThemeChoice,
    no_color: bool,
    ask: impl FnOnce() -> Option<Backdrop>,
    colorfgbg: Option<&str>,
    colorterm: Option<&str>,
) -> Colours {
    if no_color {
        return Colours::Monochrome;
    }
    let background = match choice {
        ThemeChoice::Dark => Backdrop::Dark,
        ThemeChoice::Light => Backdrop::Light,
        ThemeChoice::Auto => ask()
            .or_else(|| colorfgbg.and_then(from_colorfgbg))
            .unwrap_or(Backdrop::Dark),
    };
    Colours::Palette {
        background,
        truecolor: truecolor(colorterm),
    }
}

/// Asks the real terminal for its background colour (OSC 11), at most
/// [`QUERY_TIMEOUT`]; `None` when it does not say.
pub fn ask_terminal() -> Option<Backdrop> {
    let mut options = terminal_colorsaurus::QueryOptions::default();
    options.timeout = QUERY_TIMEOUT;
    let colour = terminal_colorsaurus::background_color(options).ok()?;
    let (r, g, b) = colour.scale_to_8bit();
    Some(background_of([r, g, b]))
}

/// NO_COLOR as <https://no-color.org> has it: set and not empty.
pub fn no_color() -> bool {
    std::env::var_os("NO_COLOR").is_some_and(|v| !v.is_empty())
}

/// The colours of this terminal for `choice`, asking it only for auto.
pub fn detect(choice: ThemeChoice) -> Colours {
    let var = |name: &str| std::env::var(name).ok();
    resolve(
        choice,
        no_color(),
        ask_terminal,
        var("COLORFGBG").as_deref(),
        var("COLORTERM").as_deref(),
    )
}

/// The colours of headless drawing (`render`, the tests): auto is dark, nothing is
/// asked, so the same input gives the same output.
pub fn headless(choice: ThemeChoice) -> Colours {
    resolve(choice, false, || None, None, None)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn colorfgbg_names_the_background_by_its_last_field() {
        assert_eq!(from_colorfgbg("0;15"), Some(Backdrop::Light));
        assert_eq!(from_colorfgbg("15;0"), Some(Backdrop::Dark));
        assert_eq!(from_colorfgbg("0;default;7"), Some(Backdrop::Light));
        assert_eq!(from_colorfgbg("7;8"), Some(Backdrop::Dark));
        assert_eq!(from_colorfgbg("default;default"), None);
        assert_eq!(from_colorfgbg("15;200"), None);
        assert_eq!(from_colorfgbg(""), None);
    }

    #[test]
    fn auto_asks_then_colorfgbg_then_dark_and_no_color_wins() {
        let light = |_| Colours::Palette {
            background: Backdrop::Light,
            truecolor: false,
        };
        let dark = Colours::Palette {
            background: Backdrop::Dark,
            truecolor: false,
        };
        let auto = ThemeChoice::Auto;
        assert_eq!(
            resolve(auto, false, || Some(Backdrop::Light), Some("15;0"), None),
            light(())
        );
        assert_eq!(resolve(auto, false, || None, Some("0;15"), None), light(()));
        assert_eq!(resolve(auto, false, || None, None, None), dark);
        // An explicit choice is not asked about.
        let never = || -> Option<Backdrop> { panic!("asked the terminal") };
        assert_eq!(
            resolve(ThemeChoice::Light, false, never, Some("15;0"), None),
            light(())
        );
        assert_eq!(
            resolve(ThemeChoice::Light, true, never, None, None),
            Colours::Monochrome
        );
        assert_eq!(
            resolve(ThemeChoice::Dark, false, never, None, Some("truecolor")),
            Colours::Palette {
                background: Backdrop::Dark,
                truecolor: true
            }
        );
    }

    #[test]
    fn backgrounds_split_at_middle_grey() {
        assert_eq!(background_of([255, 255, 255]), Backdrop::Light);
        assert_eq!(background_of([253, 246, 227]), Backdrop::Light); // Solarized light
        assert_eq!(background_of([0, 0, 0]), Backdrop::Dark);
        assert_eq!(background_of([0, 43, 54]), Backdrop::Dark); // Solarized dark
        assert_eq!(background_of([40, 44, 52]), Backdrop::Dark); // One Dark
    }

    #[test]
    fn the_switch_takes_three_words() {
        assert_eq!(parse_switch(None), Ok(ThemeChoice::Auto));
        assert_eq!(parse_switch(Some(" Light ")), Ok(ThemeChoice::Light));
        assert_eq!(parse_switch(Some("dark")), Ok(ThemeChoice::Dark));
        let e = parse_switch(Some("solarized")).unwrap_err().to_string();
        assert!(
            e.contains("solarized") && e.contains("auto, dark or light"),
            "{e}"
        );
    }
}
