//! The scrolling popups, help, the data table and the fit's models: each owns its scroll, moved by the
//! scroll keys and the wheel; Esc (q) and the key that opened it close it, and any
//! other key closes it and acts as on the main screen (as helix's popups do: `p` in
//! the help opens the picker).

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

impl Interactive<Action> for Scroll {
    /// Scroll keys and the wheel scroll; Ctrl-C falls through (it quits); Esc and
    /// `opened_by` (the popup's own key) close the popup; any other key closes it and
    /// passes on to what lies below.
    fn handle(&mut self, input: &Input, opened_by: Action) -> Handled {
        let action = match (input, wheel(input)) {
            (_, Some(true)) => Action::Up,
            (_, Some(false)) => Action::Down,
            (Input::Key(action), None) => *action,
            (Input::Mouse(..), None) => return Handled::Ignored,
        };
        match action {
            Action::Quit | Action::QuitNow => Handled::Ignored,
            a if self.scroll(a) => Handled::Consumed,
            a if a == Action::Cancel || a == opened_by => Handled::Close(Then::Nothing),
            _ => Handled::Close(Then::Pass),
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

/// The Fit view's models popup: every candidate model by BIC, scrolling.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Models {
    scroll: Scroll,
}

impl Models {
    pub fn scroll(&self) -> Scroll {
        self.scroll
    }

    pub(super) fn scroll_mut(&mut self) -> &mut Scroll {
        &mut self.scroll
    }
}

impl Interactive<()> for Models {
    fn handle(&mut self, input: &Input, (): ()) -> Handled {
        self.scroll.handle(input, Action::ModelsTable)
    }
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
    fn handle(&mut self, input: &Input, (): ()) -> Handled {
        self.scroll.handle(input, Action::Help)
    }
}

impl Interactive<()> for DataTable {
    fn handle(&mut self, input: &Input, (): ()) -> Handled {
        self.scroll.handle(input, Action::DataTable)
    }
}
