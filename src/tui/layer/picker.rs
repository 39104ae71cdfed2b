//! The preset picker: its highlighted row, moved by the arrows, Home, End, PgUp and
//! PgDn and the wheel; a click on another row highlights it, on the highlighted one
//! (or Enter) loads it.

use ratatui::layout::Rect;

use super::place::centered;
use crate::tui::interact::{Input, Interactive, click, wheel};
use crate::tui::vocabulary::{Action, Handled, Then};

/// Rows moved by PgUp and PgDn.
const PAGE: usize = 10;

/// The preset picker with its highlighted row.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Picker {
    selected: usize,
}

impl Picker {
    /// The picker with preset `selected` highlighted.
    pub fn on(selected: usize) -> Picker {
        Picker { selected }
    }

    /// The highlighted preset.
    pub fn selected(&self) -> usize {
        self.selected
    }

    /// What `action` does among `presets` presets.
    fn key(&mut self, action: Action, presets: usize) -> Handled {
        let (i, n) = (self.selected, presets.max(1));
        self.selected = match action {
            Action::Up => (i + n - 1) % n,
            Action::Down | Action::NextParam => (i + 1) % n,
            Action::Start => 0,
            Action::End => n - 1,
            Action::IncreaseCoarse => i.saturating_sub(PAGE),
            Action::DecreaseCoarse => (i + PAGE).min(n - 1),
            // A click: on another preset selects it, on the selected one loads it (a
            // double click does both).
            Action::Select(j) if j != i && j < presets => j,
            Action::Select(j) if j != i => i,
            Action::Confirm | Action::Edit | Action::Select(_) => {
                return Handled::Close(Then::Load(i));
            }
            Action::Cancel | Action::Presets => return Handled::Close(Then::Nothing),
            // Ctrl-C quits from anywhere.
            Action::Quit => return Handled::Ignored,
            _ => i,
        };
        Handled::Consumed
    }
}

impl Interactive<usize> for Picker {
    /// `presets`: how many the picker offers.
    fn handle(&mut self, input: &Input, presets: usize) -> Handled {
        if let Some(up) = wheel(input) {
            return self.key(if up { Action::Up } else { Action::Down }, presets);
        }
        match input {
            Input::Key(action) => self.key(*action, presets),
            Input::Mouse(..) => match click(input)
                .and_then(|(column, row, area)| row_at(presets, area, column, row))
            {
                Some(j) => self.key(Action::Select(j), presets),
                None => Handled::Ignored,
            },
        }
    }
}

/// Where the picker of `presets` rows is drawn on a screen of `area`, and how many of
/// its rows show.
fn picker_rect(presets: usize, area: Rect) -> (Rect, usize) {
    let rect = centered(area, area.width.saturating_sub(4), presets as u16 + 2);
    (
        rect,
        presets.min(usize::from(rect.height.saturating_sub(2))),
    )
}

/// The preset under screen cell (`column`, `row`) of the picker of `presets` rows on
/// a screen of `area`, if a row of it is there (what a click picks).
pub fn row_at(presets: usize, area: Rect, column: u16, row: u16) -> Option<usize> {
    let (rect, shown) = picker_rect(presets, area);
    let inside = column > rect.x && column + 1 < rect.right() && row > rect.y;
    let i = usize::from(row.checked_sub(rect.y + 1)?);
    (inside && i < shown).then_some(i)
}
