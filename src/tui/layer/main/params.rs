//! The parameters panel's own state and keys (issue 36): which row is selected (↑↓,
//! Tab, a click) and the keys that step its value (←→, the wheel), asked of the app
//! with the row's key: setting a value is the app's (the hidden b, the limits and
//! the status line are its), choosing the row is the panel's.

use std::sync::LazyLock;

use super::pane::{Pane, PaneCx};
use crate::settings::params::{PARAMS, Param};
use crate::tui::interact::Input;
use crate::tui::vocabulary::{Action, Handled, Then, View};

/// The rows of the parameters panel, top to bottom: the table's rows that have steps.
pub static ROWS: LazyLock<Vec<&'static Param>> =
    LazyLock::new(|| PARAMS.iter().filter(|p| p.steps.is_some()).collect());

/// The parameters panel: the row selected.
#[derive(Clone, Debug)]
pub struct ParamsPanel {
    selected: usize,
}

impl Default for ParamsPanel {
    /// On b, the groove's width: what the experiment varies.
    fn default() -> Self {
        ParamsPanel { selected: 1 }
    }
}

impl ParamsPanel {
    /// The row selected (an index in [`ROWS`]).
    pub fn selected(&self) -> usize {
        self.selected
    }

    /// The parameter of the row selected.
    pub fn param(&self) -> &'static Param {
        ROWS.get(self.selected)
            .or_else(|| ROWS.first())
            .copied()
            .expect("the parameters table has rows with steps")
    }

    /// A step of the selected row's value, asked of the app.
    fn step(&self, up: bool, coarse: bool) -> Handled {
        Handled::Ask(Then::Step {
            key: self.param().key,
            up,
            coarse,
        })
    }
}

impl Pane for ParamsPanel {
    fn view(&self) -> Option<View> {
        None
    }

    fn handle(&mut self, input: &Input, _cx: &mut PaneCx<'_>) -> Handled {
        let Input::Key(action) = *input else {
            return Handled::Ignored;
        };
        let n = ROWS.len();
        match action {
            Action::Up => self.selected = (self.selected + n - 1) % n,
            Action::Down | Action::NextParam => self.selected = (self.selected + 1) % n,
            Action::Select(i) if i < n => self.selected = i,
            Action::ScrollParam(i, up) if i < n => {
                self.selected = i;
                return self.step(up, false);
            }
            Action::Increase => return self.step(true, false),
            Action::Decrease => return self.step(false, false),
            Action::IncreaseCoarse => return self.step(true, true),
            Action::DecreaseCoarse => return self.step(false, true),
            _ => return Handled::Ignored,
        }
        Handled::Consumed
    }
}
