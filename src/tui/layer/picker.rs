//! The preset picker: its highlighted row, moved by the arrows, Home, End, PgUp and
//! PgDn and the wheel; a click on another row highlights it, on the highlighted one
//! (or Enter) loads it.

use ratatui::layout::Rect;

use super::place::centered;
use crate::tui::interact::{Input, Interactive, click, wheel};
use crate::tui::vocabulary::{Action, Handled, Then};

/// Rows moved by PgUp and PgDn.
const PAGE: usize = 10;

/// The preset picker with its highlighted row, or none yet (while b is hidden or a
/// prediction pends, the loaded preset's name would give the outcome away).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Picker {
    selected: usize,
    /// Whether a row is highlighted at all.
    marked: bool,
}

impl Picker {
    /// The picker with preset `selected` highlighted.
    pub fn on(selected: usize) -> Picker {
        Picker {
            selected,
            marked: true,
        }
    }

    /// The picker with no row highlighted until a key or a click picks one.
    pub fn unmarked() -> Picker {
        Picker {
            selected: 0,
            marked: false,
        }
    }

    /// The highlighted preset (the first while none is).
    pub fn selected(&self) -> usize {
        self.selected
    }

    /// The highlighted preset, if one is.
    pub fn marked(&self) -> Option<usize> {
        self.marked.then_some(self.selected)
    }

    /// What `action` does among `presets` presets.
    fn key(&mut self, action: Action, presets: usize) -> Handled {
        let (i, n) = (self.selected, presets.max(1));
        if !self.marked {
            // The first move highlights the first row (Up and End the last); Enter
            // has nothing to load yet.
            self.selected = match action {
                Action::Up | Action::End => n - 1,
                Action::Down
                | Action::NextParam
                | Action::Start
                | Action::IncreaseCoarse
                | Action::DecreaseCoarse => 0,
                Action::Select(j) if j < presets => j,
                Action::Cancel | Action::Presets => return Handled::Close(Then::Nothing),
                Action::Quit | Action::QuitNow => return Handled::Ignored,
                _ => return Handled::Consumed,
            };
            self.marked = true;
            return Handled::Consumed;
        }
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
            Action::Quit | Action::QuitNow => return Handled::Ignored,
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
