//! What a view of the main screen is ([`Pane`]) and what it is handed ([`PaneCx`]):
//! apart from the main screen that holds the views, so that each view's file uses
//! this one and the main screen uses both, and no file imports itself through others.

use std::any::Any;

use super::figure::{Figure, FigureCx, NoFigure};
use crate::lab::Lab;
use crate::tui::interact::Input;
use crate::tui::jobs::{Jobs, Notice};
use crate::tui::vocabulary::{Handled, View};

/// What a view needs of the app to handle an input or ask for its work.
#[derive(Debug)]
pub struct PaneCx<'a> {
    pub lab: &'a mut Lab,
    pub jobs: &'a Jobs,
    /// The cursor's time, s, and the span the charts' x axis covers unzoomed.
    pub t: f64,
    pub span: (f64, f64),
    /// True while the outcome is hidden (b hidden, a prediction pending).
    pub derived: bool,
    /// The view shown.
    pub shown: View,
    /// True while the view shown shows the charts ([`Pane::shows_charts`]).
    pub charts_shown: bool,
    /// Where a mouse event points, as the frame on screen laid it out.
    pub pointer: Pointer,
    /// The `--data` video whose data are not in the lab: still being tracked on a
    /// worker, or refused.
    pub video: Option<VideoData>,
}

/// Why the `--data` video's data are not in the lab (its name as the status line
/// says it).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum VideoData {
    /// Still being tracked on a worker: they are to come.
    Tracking(String),
    /// Its tracking was refused; `first_frame`: its first frame is there to click a
    /// ball on (`V`).
    Refused { name: String, first_frame: bool },
}

/// What lies under the mouse: the time under it on the chart's plot, the video's
/// pixel under it on the Scene panel's picture, and the video's frame that picture
/// shows.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Pointer {
    pub time: Option<f64>,
    pub pixel: Option<(f64, f64)>,
    pub frame: Option<usize>,
}

/// A view of the main screen: its keys and mouse, and its jobs.
pub trait Pane: AnyPane + std::fmt::Debug {
    /// The view it is (the one shown is offered an input first); `None` for a part
    /// of every view (the Scene panel's video).
    fn view(&self) -> Option<View>;
    /// True for a view that shows the charts (their keys and mouse work while it is
    /// shown).
    fn shows_charts(&self) -> bool {
        false
    }
    /// Handles `input` (its own keys; [`Handled::Ignored`] lets it go on).
    fn handle(&mut self, input: &Input, cx: &mut PaneCx<'_>) -> Handled;
    /// Asks for the work it wants of this scene (a request already made for it runs
    /// on; one made for an earlier scene is superseded, its result dropped).
    fn sync(&mut self, _cx: &PaneCx<'_>) {}
    /// A job of its finished: what it says.
    fn notice(&mut self, _notice: Notice, _cx: &mut PaneCx<'_>) -> Handled {
        Handled::Ignored
    }
    /// Other data than before (a preset, a drop, an undo): what was chosen for them goes.
    fn data_changed(&mut self) {}
    /// The cursor moved to `t` (playback, a key), the charts' unzoomed span `span`.
    fn moved(&mut self, _t: f64, _span: (f64, f64)) {}
    /// What `W` writes while it is shown: its figure, or why there is none (what it
    /// withholds while the outcome is hidden is not written either); `None` while it
    /// shows the charts, whose figure is written then. Asked of the view shown only.
    fn figure(&self, _cx: &FigureCx) -> Option<Result<Figure, NoFigure>> {
        None
    }
}

/// What every pane is without writing it: found by its type (helix's
/// `Compositor::find`), and cloned with the app.
pub trait AnyPane {
    fn as_any(&self) -> &dyn Any;
    fn as_any_mut(&mut self) -> &mut dyn Any;
    fn boxed(&self) -> Box<dyn Pane>;
}

impl<T: Pane + Clone + 'static> AnyPane for T {
    fn as_any(&self) -> &dyn Any {
        self
    }
    fn as_any_mut(&mut self) -> &mut dyn Any {
        self
    }
    fn boxed(&self) -> Box<dyn Pane> {
        Box::new(self.clone())
    }
}
