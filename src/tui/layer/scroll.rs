//! The scrolling popups, help and the data table: each owns its scroll, moved by the
//! scroll keys and the wheel; any other key closes it.

use crate::tui::interact::{Input, Interactive, wheel};
use crate::tui::vocabulary::{Action, Handled, Then};

/// Lines moved by PgUp and PgDn.
const PAGE: usize = 10;

/// A scrolling popup's first line shown, and the largest useful one at the size laid
/// out last (unknown before the first frame).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Scroll {
    first: usize,
    max: usize,
}

impl Default for Scroll {
    fn default() -> Scroll {
        Scroll {
            first: 0,
            max: usize::MAX,
        }
    }
}

impl Scroll {
    /// The first line shown (drawing clamps it to what the frame can show).
    pub fn first(&self) -> usize {
        self.first
    }

    pub(super) fn laid_out(&mut self, max: usize) {
        self.max = max;
    }

    /// Scrolls if `action` is a scroll key; false otherwise.
    fn scroll(&mut self, action: Action) -> bool {
        // Never beyond what the last frame could show (a press after the end is felt).
        let now = self.first.min(self.max);
        self.first = match action {
            Action::Up => now.saturating_sub(1),
            Action::Down | Action::NextParam => now + 1,
            Action::IncreaseCoarse => now.saturating_sub(PAGE),
            Action::DecreaseCoarse => now + PAGE,
            Action::Start => 0,
            Action::End => usize::MAX,
            _ => return false,
        }
        .min(self.max);
        true
    }
}

impl Interactive<()> for Scroll {
    /// Scroll keys and the wheel scroll; Ctrl-C falls through (it quits); any other
    /// key closes the popup.
    fn handle(&mut self, input: &Input, (): ()) -> Handled {
        let action = match (input, wheel(input)) {
            (_, Some(true)) => Action::Up,
            (_, Some(false)) => Action::Down,
            (Input::Key(action), None) => *action,
            (Input::Mouse(..), None) => return Handled::Ignored,
        };
        match action {
            Action::Quit => Handled::Ignored,
            a if self.scroll(a) => Handled::Consumed,
            _ => Handled::Close(Then::Nothing),
        }
    }
}

/// The help popup: the key table, scrolling.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Help {
    scroll: Scroll,
}

/// The data table popup: the measured data beside the model, scrolling.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct DataTable {
    scroll: Scroll,
}

impl Help {
    pub fn scroll(&self) -> Scroll {
        self.scroll
    }

    pub(super) fn scroll_mut(&mut self) -> &mut Scroll {
        &mut self.scroll
    }
}

impl DataTable {
    pub fn scroll(&self) -> Scroll {
        self.scroll
    }

    pub(super) fn scroll_mut(&mut self) -> &mut Scroll {
        &mut self.scroll
    }
}

impl Interactive<()> for Help {
    fn handle(&mut self, input: &Input, cx: ()) -> Handled {
        self.scroll.handle(input, cx)
    }
}

impl Interactive<()> for DataTable {
    fn handle(&mut self, input: &Input, cx: ()) -> Handled {
        self.scroll.handle(input, cx)
    }
}
