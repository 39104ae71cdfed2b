//! Components as helix has them: each view (scene, chart, why, forces, methods, map,
//! fit) and each popup (help, data table, presets, prompts, predict) is a type
//! implementing [`Component`]: it renders from the app's state and the [`Laid`] (one frame, laid out) the
//! screen prepared, into any area it is given, changing nothing. Input is the sibling
//! trait's ([`super::interact::Interactive`]): the popups are layers that own their
//! state ([`super::layer`]), and the views are the bottom layer's panes
//! ([`super::layer::main`]), owning their state, keys and jobs. The
//! screen (`super::screen`) lays the frame out once and draws the panels, the view
//! shown (chosen by an exhaustive match on `View`) and the layers open over them
//! (each drawn by its own component, an exhaustive match on `Layer`).

use std::rc::Rc;

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;

use super::app::App;
use super::chart::Chart;
use super::layout::Panels;
use super::theme::Theme;
use crate::physics::derived::Regime;

/// One frame, laid out: what drawing and hit-testing share.
#[derive(Clone, Debug)]
pub struct Laid {
    pub area: Rect,
    /// Where each panel goes (`None`: the terminal is too small).
    pub panels: Option<Panels>,
    /// The chart, in the views that show one.
    pub chart: Option<Chart>,
    /// The Map view's regime grid.
    pub regimes: Option<Rc<[Regime]>>,
    /// How far the open help or data table scrolls at this size.
    pub scroll_max: usize,
}

/// What a component renders with: the app's state, the frame laid out for it, the
/// theme. All shared: rendering changes nothing.
#[derive(Clone, Copy)]
pub struct Ctx<'a> {
    pub app: &'a App,
    pub frame: &'a Laid,
    pub theme: &'a Theme,
}

/// A part of the screen that draws itself.
pub trait Component {
    /// Draws into `area` of `buf` from `cx`, changing nothing.
    fn render(&self, area: Rect, buf: &mut Buffer, cx: &Ctx<'_>);
}
