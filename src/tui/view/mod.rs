//! The lab's panels: the one layout ([`layout`]), one file per panel, each reading the
//! app and writing into a buffer, and the hit-tests of their cells. The screen
//! ([`crate::tui::screen`]) lays a frame out once and draws these panels and popups
//! from it; what every panel draws with is in `panel`.

pub(crate) mod charts;
pub(crate) mod fit;
pub(crate) mod forces;
pub(crate) mod info;
pub(crate) mod map;
pub(crate) mod methods;
mod panel;
pub(crate) mod params;

pub use params::param_at;
pub use popups::{data_rows, picker_row_at, scroll_max};
pub use predict::answer_at;
pub(crate) mod popups;
pub(crate) mod predict;
pub(crate) mod scene;
pub(crate) mod status;

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
        super::app::ROWS.len() as u16 + 2
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
