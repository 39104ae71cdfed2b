//! The Methods view's own state and keys (issue 26): what its work axis shows. Its
//! key works from every view (the axis is kept for when the view opens).

use crate::tui::interact::{Input, Interactive};
use crate::tui::vocabulary::{Action, Handled, WorkAxis};

/// The Methods view's work axis.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct MethodsState {
    axis: WorkAxis,
}

impl MethodsState {
    /// What the work axis shows: steps, right-hand-side evaluations or time.
    pub fn axis(&self) -> WorkAxis {
        self.axis
    }

    /// What `action` does to the view: `X` cycles the work axis.
    fn key(&mut self, action: Action) -> Handled {
        match action {
            Action::CycleWorkAxis => {
                self.axis = self.axis.next();
                Handled::Say(format!("work axis: {}", self.axis.name()))
            }
            _ => Handled::Ignored,
        }
    }
}

impl Interactive<()> for MethodsState {
    fn handle(&mut self, input: &Input, (): ()) -> Handled {
        match input {
            Input::Key(action) => self.key(*action),
            Input::Mouse(..) => Handled::Ignored,
        }
    }
}
