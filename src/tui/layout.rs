//! The one layout of the screen: where each panel goes at a size (the screen lays a
//! frame out with it once; drawing and the mouse's hit-tests share the result).

use ratatui::layout::{Constraint, Layout, Rect};

/// Smallest terminal the layout is made for.
pub const MIN_SIZE: (u16, u16) = (80, 24);

/// Where each panel goes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Panels {
    pub params: Rect,
    pub scene: Rect,
    pub chart: Rect,
    pub info: Rect,
    pub status: Rect,
    pub hints: Rect,
}

/// The layout for a screen of `area`; `None` if it is too small.
pub fn layout(area: Rect) -> Option<Panels> {
    if area.width < MIN_SIZE.0 || area.height < MIN_SIZE.1 {
        return None;
    }
    // Tall screens show every parameter; short ones scroll the list (7 rows) so the
    // charts keep room.
    let top_height = if area.height >= 32 {
        crate::tui::app::ROWS.len() as u16 + 2
    } else {
        9
    };
    let [top, middle, status, hints] = Layout::vertical([
        Constraint::Length(top_height),
        Constraint::Min(8),
        Constraint::Length(1),
        Constraint::Length(1),
    ])
    .areas(area);
    let params_width = if area.width >= 110 { 41 } else { 32 };
    let [params, scene] =
        Layout::horizontal([Constraint::Length(params_width), Constraint::Min(30)]).areas(top);
    // Wide screens give the side panel more room (the runs list, the fit's two columns).
    let info_width = if area.width >= 180 {
        60
    } else if area.width >= 110 {
        46
    } else {
        36
    };
    let [chart, info] =
        Layout::horizontal([Constraint::Min(30), Constraint::Length(info_width)]).areas(middle);
    Some(Panels {
        params,
        scene,
        chart,
        info,
        status,
        hints,
    })
}
