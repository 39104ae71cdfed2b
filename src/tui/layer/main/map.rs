//! The Map view's pane: it has no state, keys or job of its own (its regime grid is
//! closed forms, cached per scene and size by the screen); it answers what `W`
//! writes from it.

use super::figure::{Figure, FigureCx, NoFigure};
use super::pane::{Pane, PaneCx};
use crate::tui::interact::Input;
use crate::tui::vocabulary::{Handled, View};

/// The Map view.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct MapPane;

impl Pane for MapPane {
    fn view(&self) -> Option<View> {
        Some(View::Map)
    }

    fn handle(&mut self, _: &Input, _: &mut PaneCx<'_>) -> Handled {
        Handled::Ignored
    }

    /// The regime map, withheld while a prediction is pending with b shown (its place
    /// on the map is the answer).
    fn figure(&self, cx: &FigureCx) -> Option<Result<Figure, NoFigure>> {
        Some(if cx.hide.pending() && !cx.hide.b() {
            Err(NoFigure::Hidden("the regime map"))
        } else {
            Ok(Figure::Map)
        })
    }
}
