//! What a component is offered and how it answers (issue 26, helix's
//! `Component::handle_event`): a key's action or a mouse event ([`Input`]), and the
//! [`Interactive`] trait, the sibling of [`super::component::Component`] that handles
//! them. Kept apart from rendering, which reads the whole app: the app holds the
//! components that handle input, so this file knows nothing of the app.

use ratatui::crossterm::event::MouseEvent;
use ratatui::layout::Rect;

use super::vocabulary::{Action, Handled};

/// One event offered to a component: a key (as the key table names its action) or a
/// mouse event on the frame laid out at `Rect` (what a popup hit-tests against).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Input {
    Key(Action),
    Mouse(MouseEvent, Rect),
}

/// A component that handles input: it changes its own state and answers what it did
/// ([`Handled::Ignored`] lets the input fall through to what lies below it). `Cx` is
/// what it needs to know of the app to decide (the charts' moment, the presets'
/// count, the prompts' history), given by value or by reference.
pub trait Interactive<Cx> {
    fn handle(&mut self, input: &Input, cx: Cx) -> Handled;
}

/// The mouse wheel in `input`: `Some(true)` up, `Some(false)` down.
pub fn wheel(input: &Input) -> Option<bool> {
    use ratatui::crossterm::event::MouseEventKind;
    match input {
        Input::Mouse(m, _) => match m.kind {
            MouseEventKind::ScrollUp => Some(true),
            MouseEventKind::ScrollDown => Some(false),
            _ => None,
        },
        Input::Key(_) => None,
    }
}

/// The cell of a left click in `input`, and the frame's area.
pub fn click(input: &Input) -> Option<(u16, u16, Rect)> {
    use ratatui::crossterm::event::{MouseButton, MouseEventKind};
    match input {
        Input::Mouse(m, area) if m.kind == MouseEventKind::Down(MouseButton::Left) => {
            Some((m.column, m.row, *area))
        }
        _ => None,
    }
}
