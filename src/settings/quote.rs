//! Echoing what the user typed or a file holds in a message, cut to a sane length:
//! a 5 MB cell must not make a 5 MB error line.

use std::fmt;

/// The most characters of an echoed text a message shows; longer ones end in "…".
pub const CLIP_CHARS: usize = 40;

/// `text` for a message: whole when at most [`CLIP_CHARS`] characters, else its first
/// [`CLIP_CHARS`] characters and "…".
pub fn clip(text: &str) -> Clipped<'_> {
    Clipped(text)
}

/// An echoed text, shown cut (see [`clip`]).
#[derive(Clone, Copy, Debug)]
pub struct Clipped<'a>(&'a str);

impl fmt::Display for Clipped<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.0.char_indices().nth(CLIP_CHARS) {
            Some((cut, _)) => write!(f, "{}…", &self.0[..cut]),
            None => f.write_str(self.0),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn short_texts_are_whole_and_long_ones_cut_at_a_character() {
        assert_eq!(clip("2.75cm").to_string(), "2.75cm");
        let exact = "a".repeat(CLIP_CHARS);
        assert_eq!(clip(&exact).to_string(), exact);
        let long = "μ".repeat(5_000);
        let shown = clip(&long).to_string();
        assert_eq!(shown.chars().count(), CLIP_CHARS + 1);
        assert!(shown.ends_with('…'));
        assert!(shown.starts_with("μμ"));
    }
}
