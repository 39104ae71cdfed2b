//! Components as helix has them: each view (scene, chart, why, forces, methods, map,
//! fit) and each popup (help, data table, presets, prompts, predict) is a type
//! implementing [`Component`]: it renders from the app's state and the [`Laid`] (one frame, laid out) the
//! screen prepared, into any area it is given, changing nothing. Input is the sibling
//! trait's ([`super::interact::Interactive`]): the popups are layers that own their
//! state ([`super::layer`]), and the views are the bottom layer's panes
//! ([`super::layer::main`]), owning their state, keys and jobs; as drawn, each view
//! is a [`MainView`]: what it prepares for a frame and which components draw it
//! where. The screen (`super::screen`) lays the frame out once and draws the panels,
//! the view shown (the [`MainView`] registered for it asked) and the layers open over
//! them (each drawn by its own component, an exhaustive match on `Layer`).

use std::rc::Rc;

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;

use super::app::App;
use super::chart::Chart;
use super::layout::Panels;
use super::theme::Theme;
use super::view_cache::ViewCache;
use super::vocabulary::View;
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

/// Where a part of the view shown goes: the chart's room, the side panel's, or both.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Place {
    Chart,
    Side,
    Middle,
}

/// What a view computes for a frame before drawing (on the chart's room, at this
/// size): the chart built, the regime grid.
#[derive(Debug, Default)]
pub struct Prepared {
    pub chart: Option<Chart>,
    pub regimes: Option<Rc<[Regime]>>,
    /// True when the measured series were thinned to the chart's cells anew.
    pub marks_thinned: bool,
}

/// A view of the main screen as drawn (its state, keys and jobs are its pane in
/// `layer/main`): what it prepares for a frame, and which components draw it where.
/// The screen asks the view shown, as `view/` registers it.
pub trait MainView {
    /// The view it draws.
    fn view(&self) -> View;
    /// What it computes before drawing, on `chart` (the chart's room); nothing by
    /// default.
    fn prepare(
        &self,
        _app: &App,
        _cache: &mut ViewCache,
        _chart: Rect,
        _theme: &Theme,
    ) -> Prepared {
        Prepared::default()
    }
    /// Its components and where each goes; while the outcome is hidden, the panels
    /// that would tell it are withheld.
    fn parts(&self, app: &App) -> Vec<(&'static dyn Component, Place)>;
}
