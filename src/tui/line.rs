//! The prompts' line editor: a text field with a cursor, edited as in a terminal
//! (`tui-input` does the editing: ←/→, Home/End, Backspace/Delete, Ctrl-A/E/U/W/K),
//! and ↑/↓ through the entries confirmed earlier in this session.

use ratatui::style::{Modifier, Style};
use tui_input::{Input, InputRequest};

/// The cell under the cursor in a field drawn with `base`: the reverse of it, so it
/// shows in a highlighted row and under NO_COLOR alike.
pub fn caret(base: Style) -> Style {
    if base.add_modifier.contains(Modifier::REVERSED) {
        base.remove_modifier(Modifier::REVERSED)
    } else {
        base.add_modifier(Modifier::REVERSED)
    }
}

/// The text of an open prompt, its cursor, and where ↑/↓ has gone in the history.
#[derive(Clone, Debug, Default)]
pub struct Field {
    input: Input,
    /// How many entries back ↑ has gone (0: the line being typed).
    back: usize,
    /// The line being typed, kept while ↑ shows earlier entries.
    draft: String,
    /// The text is a suggestion, selected as a whole: a typed character replaces it, a
    /// deletion clears it, a cursor move keeps it for editing.
    suggestion: bool,
}

impl Field {
    /// A field holding `text`, the cursor at its end.
    pub fn new(text: impl Into<String>) -> Field {
        Field {
            input: Input::new(text.into()),
            ..Field::default()
        }
    }

    /// A field offering `text` (a default name), selected: typing replaces it.
    pub fn suggested(text: impl Into<String>) -> Field {
        Field {
            suggestion: true,
            ..Field::new(text)
        }
    }

    /// True while the text is the untouched suggestion (typing replaces it).
    pub fn is_suggestion(&self) -> bool {
        self.suggestion
    }

    pub fn value(&self) -> &str {
        self.input.value()
    }

    /// The cursor, in characters from the start.
    pub fn cursor(&self) -> usize {
        self.input.cursor()
    }

    /// One editing request (a typed character, a cursor move, a deletion).
    pub fn edit(&mut self, request: InputRequest) {
        if std::mem::take(&mut self.suggestion) {
            match request {
                InputRequest::InsertChar(_) => self.input = Input::default(),
                InputRequest::DeletePrevChar
                | InputRequest::DeleteNextChar
                | InputRequest::DeletePrevWord
                | InputRequest::DeleteNextWord
                | InputRequest::DeleteLine
                | InputRequest::DeleteTillEnd
                | InputRequest::DeleteFromStart => {
                    self.input = Input::default();
                    return;
                }
                _ => {}
            }
        }
        self.input.handle(request);
    }

    /// ↑: the entry before the one shown (`history` oldest first); the line being
    /// typed is kept for ↓.
    pub fn earlier(&mut self, history: &[String]) {
        if self.back == history.len() {
            return;
        }
        self.suggestion = false;
        if self.back == 0 {
            self.draft = self.value().to_string();
        }
        self.back += 1;
        self.input = Input::new(history[history.len() - self.back].clone());
    }

    /// ↓: the entry after the one shown, and after the last the line being typed.
    pub fn later(&mut self, history: &[String]) {
        if self.back == 0 {
            return;
        }
        self.back -= 1;
        self.input = Input::new(match self.back {
            0 => std::mem::take(&mut self.draft),
            back => history[history.len() - back].clone(),
        });
    }

    /// What a field `room` characters wide shows: the part of the text around the
    /// cursor, with `_` at the end when the cursor is there, and the cursor's column.
    pub fn shown(&self, room: usize) -> (String, usize) {
        let mut chars: Vec<char> = self.value().chars().collect();
        let cursor = self.cursor();
        if cursor == chars.len() {
            chars.push('_');
        }
        let room = room.max(1);
        // The window ends one past the cursor, or at the text's end if that fits.
        let first = (cursor + 1).saturating_sub(room);
        let first = first.min(chars.len().saturating_sub(room)).min(cursor);
        let text = chars.iter().skip(first).take(room).collect();
        (text, cursor - first)
    }
}

impl PartialEq for Field {
    /// Two fields are the same when they show the same text and cursor.
    fn eq(&self, other: &Field) -> bool {
        self.value() == other.value() && self.cursor() == other.cursor()
    }
}

impl From<&str> for Field {
    fn from(text: &str) -> Field {
        Field::new(text)
    }
}

/// Entries confirmed in one kind of prompt this session, oldest first.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct History(pub Vec<String>);

impl History {
    /// Keeps `entry` unless it is blank or repeats the last one.
    pub fn push(&mut self, entry: &str) {
        let entry = entry.trim();
        if !entry.is_empty() && self.0.last().is_none_or(|last| last != entry) {
            self.0.push(entry.to_string());
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn typed(text: &str) -> Field {
        let mut f = Field::default();
        for c in text.chars() {
            f.edit(InputRequest::InsertChar(c));
        }
        f
    }

    #[test]
    fn typing_replaces_a_suggestion_and_a_move_keeps_it() {
        let mut f = Field::suggested("my-paper-b4.9");
        assert!(f.is_suggestion());
        f.edit(InputRequest::InsertChar('x'));
        assert_eq!((f.value(), f.is_suggestion()), ("x", false));
        f.edit(InputRequest::InsertChar('y'));
        assert_eq!(f.value(), "xy", "only the first key replaces");
        let mut f = Field::suggested("run.csv");
        f.edit(InputRequest::DeletePrevChar);
        assert_eq!(f.value(), "", "a deletion clears the whole suggestion");
        let mut f = Field::suggested("run.csv");
        f.edit(InputRequest::GoToPrevChar);
        f.edit(InputRequest::InsertChar('2'));
        assert_eq!(f.value(), "run.cs2v", "after a move the text is edited");
    }

    #[test]
    fn the_cursor_moves_and_deletes_inside_the_line() {
        let mut f = typed("44cm");
        f.edit(InputRequest::GoToPrevChar);
        f.edit(InputRequest::GoToPrevChar);
        f.edit(InputRequest::InsertChar('.'));
        f.edit(InputRequest::InsertChar('5'));
        assert_eq!(f.value(), "44.5cm");
        f.edit(InputRequest::GoToStart);
        f.edit(InputRequest::DeleteNextChar);
        assert_eq!((f.value(), f.cursor()), ("4.5cm", 0));
        f.edit(InputRequest::GoToEnd);
        f.edit(InputRequest::InsertChar(' '));
        f.edit(InputRequest::InsertChar('x'));
        f.edit(InputRequest::DeletePrevWord);
        assert_eq!(f.value(), "4.5cm ");
        f.edit(InputRequest::DeleteLine);
        assert_eq!(f.value(), "");
    }

    #[test]
    fn history_goes_back_and_returns_to_the_draft() {
        let mut h = History::default();
        for e in ["4.4", "4.4", " ", "44mm"] {
            h.push(e);
        }
        assert_eq!(h.0, ["4.4", "44mm"], "blanks and repeats are not kept");
        let mut f = typed("3");
        f.earlier(&h.0);
        assert_eq!(f.value(), "44mm");
        f.earlier(&h.0);
        f.earlier(&h.0);
        assert_eq!(f.value(), "4.4", "stops at the oldest");
        f.later(&h.0);
        assert_eq!(f.value(), "44mm");
        f.later(&h.0);
        assert_eq!(f.value(), "3", "the line being typed comes back");
        f.later(&h.0);
        assert_eq!(f.value(), "3");
    }

    #[test]
    fn a_long_line_shows_the_part_around_the_cursor() {
        let mut f = typed("0123456789");
        assert_eq!(f.shown(20), ("0123456789_".to_string(), 10));
        assert_eq!(f.shown(5), ("6789_".to_string(), 4));
        f.edit(InputRequest::GoToStart);
        assert_eq!(f.shown(5), ("01234".to_string(), 0));
        f.edit(InputRequest::GoToNextChar);
        f.edit(InputRequest::GoToNextChar);
        assert_eq!(f.shown(20), ("0123456789".to_string(), 2));
    }
}
