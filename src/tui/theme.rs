//! Looks: colours (readable on dark and light terminals, monochrome under NO_COLOR),
//! and the glyph set, Unicode or pure ASCII, decided in this one place.

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
    /// Second series of a ball (v_t) and the like.
    pub accent: Style,
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

    /// Colours that read on dark and light backgrounds (no white or black text), or
    /// modifiers only when `monochrome` (NO_COLOR).
    pub fn new(glyphs: Glyphs, monochrome: bool) -> Theme {
        let plain = Style::default();
        if monochrome {
            return Theme {
                glyphs,
                monochrome,
                text: plain,
                dim: plain.add_modifier(Modifier::DIM),
                title: plain.add_modifier(Modifier::BOLD),
                selected: plain.add_modifier(Modifier::REVERSED),
                error: plain.add_modifier(Modifier::BOLD | Modifier::UNDERLINED),
                info: plain,
                left: plain.add_modifier(Modifier::BOLD),
                right: plain,
                accent: plain.add_modifier(Modifier::DIM),
                measured: plain.add_modifier(Modifier::BOLD),
                overlay: plain.add_modifier(Modifier::ITALIC),
                overlay_t: plain.add_modifier(Modifier::ITALIC | Modifier::DIM),
                event: plain.add_modifier(Modifier::DIM),
                cursor: plain.add_modifier(Modifier::BOLD),
                flash: plain.add_modifier(Modifier::BOLD | Modifier::REVERSED),
                groove: plain.add_modifier(Modifier::DIM),
                key: plain.add_modifier(Modifier::BOLD),
            };
        }
        Theme {
            glyphs,
            monochrome,
            text: plain,
            dim: plain.fg(Color::Gray),
            title: plain.fg(Color::Cyan).add_modifier(Modifier::BOLD),
            selected: plain.add_modifier(Modifier::REVERSED),
            error: plain.fg(Color::Red).add_modifier(Modifier::BOLD),
            info: plain.fg(Color::Green),
            left: plain.fg(Color::Blue).add_modifier(Modifier::BOLD),
            right: plain.fg(Color::Magenta).add_modifier(Modifier::BOLD),
            accent: plain.fg(Color::Yellow),
            measured: plain.fg(Color::Red),
            overlay: plain.fg(Color::LightCyan),
            overlay_t: plain.fg(Color::LightGreen),
            event: plain.fg(Color::DarkGray),
            cursor: plain.fg(Color::Green).add_modifier(Modifier::BOLD),
            flash: plain.fg(Color::Red).add_modifier(Modifier::BOLD),
            groove: plain.fg(Color::DarkGray),
            key: plain.fg(Color::Cyan).add_modifier(Modifier::BOLD),
        }
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
