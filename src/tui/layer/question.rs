//! The prediction's question (predict, observe, explain): an answer (1, 2, 3, or a
//! click on one) is the prediction; `g` shows the forces as givens or hides them.

use ratatui::layout::Rect;

use crate::tui::interact::{Input, Interactive, click};
use crate::tui::vocabulary::{ANSWERS, Action, Handled, Then};

/// The question before the impact.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Question;

impl Interactive<()> for Question {
    fn handle(&mut self, input: &Input, (): ()) -> Handled {
        let action = match (input, click(input)) {
            (Input::Key(action), _) => *action,
            (_, Some((column, row, area))) => match answer_at(area, column, row) {
                Some(key) => Action::Type(key),
                None => return Handled::Ignored,
            },
            (Input::Mouse(..), None) => return Handled::Ignored,
        };
        match action {
            Action::Type('g') => Handled::Ask(Then::ToggleGivens),
            Action::Type(c) => match ANSWERS.iter().find(|(k, _)| *k == c) {
                Some((_, guess)) => Handled::Close(Then::Predict(*guess)),
                None => Handled::Consumed,
            },
            Action::Cancel => Handled::Close(Then::Say("no prediction".into())),
            // Ctrl-C quits from anywhere.
            Action::Quit | Action::QuitNow => Handled::Ignored,
            _ => Handled::Consumed,
        }
    }
}

/// Where the question of `lines` lines is drawn on a screen of `area`.
pub fn question_rect(area: Rect, lines: usize) -> Rect {
    let w = 52.min(area.width.saturating_sub(2));
    let h = (lines as u16 + 4).min(area.height);
    Rect {
        x: area.x + (area.width - w) / 2,
        y: area.y + (area.height - h) / 2,
        width: w,
        height: h,
    }
}

/// The answer (its key) on screen cell (`column`, `row`) of the question on a screen
/// of `area`, if one is there (what a click answers): the answers are its 3rd to 5th
/// lines, none of them wrapped.
pub fn answer_at(area: Rect, column: u16, row: u16) -> Option<char> {
    // The title, a blank line, the answers, a blank line, the note.
    let rect = question_rect(area, ANSWERS.len() + 4);
    let inside = column > rect.x && column + 1 < rect.right();
    let i = usize::from(row.checked_sub(rect.y + 3)?);
    ANSWERS.get(i).filter(|_| inside).map(|(key, _)| *key)
}
