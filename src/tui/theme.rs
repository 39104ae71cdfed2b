//! Looks: colours (a palette for dark and one for light backgrounds, each measured for
//! contrast; monochrome under NO_COLOR), and the glyph set, Unicode or pure ASCII,
//! decided in this one place. Which palette a terminal gets is `tui::look`'s.

use ratatui::buffer::Buffer;
use ratatui::style::{Color, Modifier, Style};
use ratatui::symbols::border;

/// Glyphs and text symbols of one rendering mode.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Glyphs {
    pub ascii: bool,
    pub border: border::Set<'static>,
    pub mu: &'static str,
    pub tau: &'static str,
    pub squared: &'static str,
    pub infinity: &'static str,
    pub arrow_left: &'static str,
    pub arrow_right: &'static str,
    pub vline: &'static str,
    pub hline: &'static str,
    pub dot: &'static str,
    pub flash: &'static str,
    pub selected: &'static str,
}

const ASCII_BORDER: border::Set<'static> = border::Set {
    top_left: "+",
    top_right: "+",
    bottom_left: "+",
    bottom_right: "+",
    vertical_left: "|",
    vertical_right: "|",
    horizontal_top: "-",
    horizontal_bottom: "-",
};

impl Glyphs {
    pub const UNICODE: Glyphs = Glyphs {
        ascii: false,
        border: border::ROUNDED,
        mu: "μ",
        tau: "τ",
        squared: "²",
        infinity: "∞",
        arrow_left: "←",
        arrow_right: "→",
        vline: "│",
        hline: "─",
        dot: "·",
        flash: "✶",
        selected: "▸",
    };
    pub const ASCII: Glyphs = Glyphs {
        ascii: true,
        border: ASCII_BORDER,
        mu: "mu",
        tau: "tau",
        squared: "^2",
        infinity: "inf",
        arrow_left: "<-",
        arrow_right: "->",
        vline: "|",
        hline: "-",
        dot: ".",
        flash: "*",
        selected: ">",
    };

    /// `text` as this mode writes it: in ASCII, the Unicode signs of physics text
    /// spelt out (… → ..., × → x, μ → mu, ≤ → <=, …); in Unicode, unchanged.
    pub fn text(&self, text: &str) -> String {
        if !self.ascii || text.is_ascii() {
            return text.to_string();
        }
        let mut out = String::with_capacity(text.len() + 8);
        for c in text.chars() {
            match c {
                '…' => out.push_str("..."),
                '×' => out.push('x'),
                'μ' => out.push_str("mu"),
                'τ' => out.push_str("tau"),
                'ρ' => out.push_str("rho"),
                'ω' => out.push_str("omega"),
                'α' => out.push_str("alpha"),
                'Δ' => out.push('d'),
                '²' => out.push_str("^2"),
                '³' => out.push_str("^3"),
                '∞' => out.push_str("inf"),
                '≤' => out.push_str("<="),
                '≥' => out.push_str(">="),
                '±' => out.push_str("+-"),
                '≈' => out.push('~'),
                '−' | '–' | '—' => out.push('-'),
                '→' => out.push_str("->"),
                '←' => out.push_str("<-"),
                '↑' => out.push('^'),
                '↓' => out.push('v'),
                '·' | '•' => out.push('.'),
                '′' | '’' => out.push('\''),
                // Anything else stays as it is, and the ASCII tests name it.
                c => out.push(c),
            }
        }
        out
    }

    /// `text` as this mode writes it ([`Glyphs::text`]), cut to `width` columns with an
    /// ellipsis (… or ...) when it does not fit: at the last word boundary if one is
    /// near, never silently mid-word.
    pub fn ellipsize(&self, text: &str, width: usize) -> String {
        let mark = if self.ascii { "..." } else { "…" };
        ellipsize_with(&self.text(text), width, mark)
    }

    pub fn new(ascii: bool) -> Glyphs {
        if ascii {
            Glyphs::ASCII
        } else {
            Glyphs::UNICODE
        }
    }
}

/// `text` cut to `width` characters, ending in `mark` when cut (see
/// [`Glyphs::ellipsize`]); a word boundary within the last third is preferred.
pub fn ellipsize_with(text: &str, width: usize, mark: &str) -> String {
    let n = text.chars().count();
    if n <= width {
        return text.to_string();
    }
    let mark_len = mark.chars().count();
    if width <= mark_len {
        return mark.chars().take(width).collect();
    }
    let room = width - mark_len;
    let head: String = text.chars().take(room).collect();
    // Cut after the last space or punctuation if that keeps two thirds of the room.
    let ends_a_word = text.chars().nth(room) == Some(' ');
    let boundary = head
        .char_indices()
        .rev()
        .filter(|(_, c)| matches!(c, ' ' | ',' | ';' | ':' | '/' | '(' | ')'))
        .map(|(i, c)| {
            if c == ' ' || c == '(' {
                i
            } else {
                i + c.len_utf8()
            }
        })
        .next()
        .filter(|&i| head[..i].chars().count() * 3 >= room * 2);
    let kept = match boundary {
        _ if ends_a_word => head.trim_end(),
        Some(i) => head[..i].trim_end(),
        None => head.as_str(),
    };
    format!("{kept}{mark}")
}

/// Which background a palette is made for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Backdrop {
    Dark,
    Light,
}

/// `--theme`: a palette for a dark or a light background, or `auto` (ask the terminal).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, clap::ValueEnum)]
pub enum ThemeChoice {
    /// Ask the terminal for its background (OSC 11), then `COLORFGBG`, else dark.
    #[default]
    Auto,
    /// Colours for a dark background.
    Dark,
    /// Colours for a light background (xterm's default: black on white).
    Light,
}

/// How the app colours: not at all (NO_COLOR), or with the palette for a background,
/// as xterm-256 indices or, where the terminal says it takes 24-bit colour, the same
/// colours as RGB.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Colours {
    Monochrome,
    Palette {
        background: Backdrop,
        truecolor: bool,
    },
}

/// The colours of one palette, as xterm-256 indices (16–255: the 6×6×6 cube and the
/// grey ramp, whose RGB every xterm-like terminal shares, unlike the 16 ANSI colours
/// that terminal themes redefine). Text roles read at 4.5:1 or better on the palette's
/// background, lines at 3:1 (`theme_tests` measures them).
struct Palette {
    dim: u8,
    title: u8,
    error: u8,
    info: u8,
    left: u8,
    left_t: u8,
    right: u8,
    right_t: u8,
    measured: u8,
    overlay: u8,
    overlay_t: u8,
    event: u8,
    cursor: u8,
    groove: u8,
    key: u8,
}

/// Light colours for a dark background.
const DARK: Palette = Palette {
    dim: 247,      // #9e9e9e
    title: 117,    // #87d7ff
    error: 203,    // #ff5f5f
    info: 114,     // #87d787
    left: 75,      // #5fafff, blue
    left_t: 153,   // #afd7ff, paler blue
    right: 207,    // #ff5fff, magenta
    right_t: 219,  // #ffafff, paler magenta
    measured: 203, // #ff5f5f, red
    overlay: 221,  // #ffd75f, gold
    overlay_t: 78, // #5fd787, green
    event: 246,    // #949494
    cursor: 120,   // #87ff87
    groove: 244,   // #808080
    key: 81,       // #5fd7ff
};

/// Dark colours for a light background.
const LIGHT: Palette = Palette {
    dim: 241,      // #626262
    title: 24,     // #005f87
    error: 124,    // #af0000
    info: 22,      // #005f00
    left: 19,      // #0000af, blue
    left_t: 25,    // #005faf, lighter blue
    right: 127,    // #af00af, magenta
    right_t: 90,   // #870087, darker magenta
    measured: 160, // #d70000, red
    overlay: 94,   // #875f00, brown
    overlay_t: 22, // #005f00, green
    event: 242,    // #6c6c6c
    cursor: 22,    // #005f00
    groove: 244,   // #808080
    key: 25,       // #005faf
};

/// RGB of an xterm-256 colour index (xterm's defaults: the 16 ANSI colours of its
/// resources, the 6×6×6 cube with levels 0, 95, 135, …, 255, and the grey ramp 8, 18,
/// …, 238).
pub const fn xterm_256(i: u8) -> [u8; 3] {
    const ANSI: [[u8; 3]; 16] = [
        [0, 0, 0],
        [205, 0, 0],
        [0, 205, 0],
        [205, 205, 0],
        [0, 0, 238],
        [205, 0, 205],
        [0, 205, 205],
        [229, 229, 229],
        [127, 127, 127],
        [255, 0, 0],
        [0, 255, 0],
        [255, 255, 0],
        [92, 92, 255],
        [255, 0, 255],
        [0, 255, 255],
        [255, 255, 255],
    ];
    const LEVEL: [u8; 6] = [0, 95, 135, 175, 215, 255];
    match i {
        0..=15 => ANSI[i as usize],
        16..=231 => {
            let n = (i - 16) as usize;
            [LEVEL[n / 36], LEVEL[(n / 6) % 6], LEVEL[n % 6]]
        }
        _ => {
            let v = 8 + 10 * (i - 232);
            [v, v, v]
        }
    }
}

/// The RGB an xterm with its default colours shows for `colour`; `None` for the
/// terminal's own foreground or background (`Reset`).
pub fn xterm_rgb(colour: Color) -> Option<[u8; 3]> {
    let index = match colour {
        Color::Reset => return None,
        Color::Rgb(r, g, b) => return Some([r, g, b]),
        Color::Indexed(i) => i,
        Color::Black => 0,
        Color::Red => 1,
        Color::Green => 2,
        Color::Yellow => 3,
        Color::Blue => 4,
        Color::Magenta => 5,
        Color::Cyan => 6,
        Color::Gray => 7,
        Color::DarkGray => 8,
        Color::LightRed => 9,
        Color::LightGreen => 10,
        Color::LightYellow => 11,
        Color::LightBlue => 12,
        Color::LightMagenta => 13,
        Color::LightCyan => 14,
        Color::White => 15,
    };
    Some(xterm_256(index))
}

/// WCAG 2 relative luminance of an sRGB colour, 0 (black) to 1 (white).
pub fn luminance([r, g, b]: [u8; 3]) -> f64 {
    let linear = |c: u8| {
        let c = f64::from(c) / 255.0;
        if c <= 0.04045 {
            c / 12.92
        } else {
            ((c + 0.055) / 1.055).powf(2.4)
        }
    };
    0.2126 * linear(r) + 0.7152 * linear(g) + 0.0722 * linear(b)
}

/// WCAG 2 contrast ratio of two colours, 1 (equal) to 21 (black on white).
pub fn contrast(a: [u8; 3], b: [u8; 3]) -> f64 {
    let (la, lb) = (luminance(a), luminance(b));
    (la.max(lb) + 0.05) / (la.min(lb) + 0.05)
}

/// What a role's colour draws: text (WCAG asks 4.5:1) or only lines and marks (3:1).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Use {
    Text,
    Line,
}

/// Styles of the app.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Theme {
    pub glyphs: Glyphs,
    /// NO_COLOR: styles are modifiers only, so marks must differ by glyph.
    pub monochrome: bool,
    pub text: Style,
    pub dim: Style,
    pub title: Style,
    pub selected: Style,
    pub error: Style,
    pub info: Style,
    pub left: Style,
    pub right: Style,
    /// Second series of the left ball (v_t) and the like.
    pub accent: Style,
    /// Second series of the right ball (v_t).
    pub right_accent: Style,
    pub measured: Style,
    /// A time-stepping overlay's v_cm and v_t: never the measured data's colour.
    pub overlay: Style,
    pub overlay_t: Style,
    pub event: Style,
    pub cursor: Style,
    pub flash: Style,
    pub groove: Style,
    pub key: Style,
}

impl Theme {
    /// No colours for the curves: those that colour alone would tell apart get letters
    /// (or glyphs) instead.
    pub fn uncoloured_curves(&self) -> bool {
        self.left.fg.is_none() && self.right.fg.is_none()
    }

    /// The dark palette in xterm-256 colours, or modifiers only when `monochrome`
    /// (NO_COLOR).
    pub fn new(glyphs: Glyphs, monochrome: bool) -> Theme {
        let colours = if monochrome {
            Colours::Monochrome
        } else {
            Colours::Palette {
                background: Backdrop::Dark,
                truecolor: false,
            }
        };
        Theme::with(glyphs, colours)
    }

    /// The theme of `colours`.
    pub fn with(glyphs: Glyphs, colours: Colours) -> Theme {
        let plain = Style::default();
        let (background, truecolor) = match colours {
            Colours::Monochrome => return Theme::monochrome(glyphs),
            Colours::Palette {
                background,
                truecolor,
            } => (background, truecolor),
        };
        let p = match background {
            Backdrop::Dark => &DARK,
            Backdrop::Light => &LIGHT,
        };
        let colour = |i: u8| {
            if truecolor {
                let [r, g, b] = xterm_256(i);
                Color::Rgb(r, g, b)
            } else {
                Color::Indexed(i)
            }
        };
        let fg = |i: u8| plain.fg(colour(i));
        let bold = |i: u8| fg(i).add_modifier(Modifier::BOLD);
        Theme {
            glyphs,
            monochrome: false,
            // The terminal's own foreground: made for its background.
            text: plain,
            dim: fg(p.dim),
            title: bold(p.title),
            selected: plain.add_modifier(Modifier::REVERSED),
            error: bold(p.error),
            info: fg(p.info),
            left: bold(p.left),
            right: bold(p.right),
            accent: fg(p.left_t),
            right_accent: fg(p.right_t),
            measured: fg(p.measured),
            overlay: fg(p.overlay),
            overlay_t: fg(p.overlay_t),
            event: fg(p.event),
            cursor: bold(p.cursor),
            flash: bold(p.error),
            groove: fg(p.groove),
            key: bold(p.key),
        }
    }

    fn monochrome(glyphs: Glyphs) -> Theme {
        let plain = Style::default();
        Theme {
            glyphs,
            monochrome: true,
            text: plain,
            dim: plain.add_modifier(Modifier::DIM),
            title: plain.add_modifier(Modifier::BOLD),
            selected: plain.add_modifier(Modifier::REVERSED),
            error: plain.add_modifier(Modifier::BOLD | Modifier::UNDERLINED),
            info: plain,
            left: plain.add_modifier(Modifier::BOLD),
            right: plain,
            accent: plain.add_modifier(Modifier::DIM),
            right_accent: plain.add_modifier(Modifier::DIM),
            measured: plain.add_modifier(Modifier::BOLD),
            overlay: plain.add_modifier(Modifier::ITALIC),
            overlay_t: plain.add_modifier(Modifier::ITALIC | Modifier::DIM),
            event: plain.add_modifier(Modifier::DIM),
            cursor: plain.add_modifier(Modifier::BOLD),
            flash: plain.add_modifier(Modifier::BOLD | Modifier::REVERSED),
            groove: plain.add_modifier(Modifier::DIM),
            key: plain.add_modifier(Modifier::BOLD),
        }
    }

    /// Every style of the theme with its name and what it draws: the contrast test
    /// reads them all (a new field must be added here, or this does not compile).
    pub fn roles(&self) -> Vec<(&'static str, Style, Use)> {
        let Theme {
            glyphs: _,
            monochrome: _,
            text,
            dim,
            title,
            selected,
            error,
            info,
            left,
            right,
            accent,
            right_accent,
            measured,
            overlay,
            overlay_t,
            event,
            cursor,
            flash,
            groove,
            key,
        } = *self;
        use Use::{Line, Text};
        vec![
            ("text", text, Text),
            ("dim", dim, Text),
            ("title", title, Text),
            ("selected", selected, Text),
            ("error", error, Text),
            ("info", info, Text),
            ("left", left, Text),
            ("right", right, Text),
            ("accent", accent, Text),
            ("right_accent", right_accent, Text),
            ("measured", measured, Text),
            // Legends and progress name the overlay in its colours: text.
            ("overlay", overlay, Text),
            ("overlay_t", overlay_t, Text),
            // Events are lines with a label in their colour: text.
            ("event", event, Text),
            ("cursor", cursor, Text),
            ("flash", flash, Text),
            ("groove", groove, Line),
            ("key", key, Text),
        ]
    }
}

/// Last line of defence for `--ascii`: any cell still holding a non-ASCII symbol gets
/// a close ASCII stand-in, so ASCII output is 7-bit whatever a widget drew.
pub fn force_ascii(buf: &mut Buffer) {
    for cell in buf.content.iter_mut() {
        let sym = cell.symbol();
        if sym.is_ascii() {
            continue;
        }
        let c = sym.chars().next().unwrap_or(' ');
        let stand_in = match c {
            '\u{2800}' => " ",
            '\u{2801}'..='\u{28ff}' => ".",
            '─' | '━' | '╌' => "-",
            '│' | '┃' | '╎' => "|",
            '╭' | '╮' | '╰' | '╯' | '┌' | '┐' | '└' | '┘' | '┼' | '├' | '┤' | '┬' | '┴' => {
                "+"
            }
            '•' | '●' | '✶' => "*",
            '·' => ".",
            '×' => "x",
            '…' => ".",
            _ => "?",
        };
        cell.set_symbol(stand_in);
    }
}

#[cfg(test)]
#[path = "theme_tests.rs"]
mod contrast_tests;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ellipsize_cuts_at_words_and_says_so() {
        let g = Glyphs::UNICODE;
        assert_eq!(g.ellipsize("short", 10), "short");
        assert_eq!(g.ellipsize("exactly ten", 11), "exactly ten");
        let cut = g.ellipsize("saved /home/user/presets/my-paper.toml", 20);
        assert_eq!(cut.chars().count(), 20.min(cut.chars().count()));
        assert!(cut.ends_with('…') && cut.chars().count() <= 20, "{cut}");
        assert_eq!(g.ellipsize("the balls roll apart", 15), "the balls roll…");
        // A long word is cut mid-word, but with the mark.
        assert_eq!(g.ellipsize("abcdefghijklmnop", 6), "abcde…");
        let a = Glyphs::ASCII.ellipsize("μ_k = 0.17 applied from the fit", 12);
        assert!(a.is_ascii() && a.ends_with("...") && a.len() <= 12, "{a}");
        assert_eq!(Glyphs::ASCII.ellipsize("abc", 2), "..");
    }
}
