//! The Forces view's own state and keys (issue 26): which ball its front view and
//! chain show. Its ball key is its own while it is shown (the charts' otherwise).

use super::figure::{Figure, FigureCx, NoFigure};
use super::pane::{Pane, PaneCx};
use crate::tui::interact::{Input, Interactive};
use crate::tui::vocabulary::{Action, Handled, View};

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

impl Pane for ForcesState {
    fn view(&self) -> Option<View> {
        Some(View::Forces)
    }

    fn figure(&self, _: &FigureCx) -> Option<Result<Figure, NoFigure>> {
        Some(Err(NoFigure::Forces))
    }

    fn handle(&mut self, input: &Input, cx: &mut PaneCx<'_>) -> Handled {
        if cx.shown != View::Forces {
            return Handled::Ignored;
        }
        Interactive::handle(self, input, ())
    }
}
