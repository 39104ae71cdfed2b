//! The Forces view's own state and keys (issue 26): which ball its front view and
//! chain show. The app offers it the keys while the view is shown.

use crate::tui::interact::{Input, Interactive};
use crate::tui::vocabulary::{Action, Handled};

/// Which ball the Forces view shows: 0 left, 1 right.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ForcesState {
    ball: usize,
}

impl ForcesState {
    /// The ball shown: 0 left, 1 right.
    pub fn ball(&self) -> usize {
        self.ball
    }

    /// What `action` does to the view: the ball key switches the ball.
    fn key(&mut self, action: Action) -> Handled {
        match action {
            Action::SwitchBall => {
                self.ball = 1 - self.ball;
                Handled::Consumed
            }
            _ => Handled::Ignored,
        }
    }
}

impl Interactive<()> for ForcesState {
    fn handle(&mut self, input: &Input, (): ()) -> Handled {
        match input {
            Input::Key(action) => self.key(*action),
            Input::Mouse(..) => Handled::Ignored,
        }
    }
}
