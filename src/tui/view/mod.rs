//! The lab's panels: the one layout ([`layout`]), one file per panel, each reading the
//! app and writing into a buffer, and the hit-tests of their cells. The screen
//! ([`crate::tui::screen`]) lays a frame out once and draws these panels and popups
//! from it; what every panel draws with is in `panel`.

pub mod charts;
pub mod fit;
pub mod forces;
pub mod info;
pub mod map;
pub mod methods;
pub mod models;
mod panel;
pub mod params;

pub use params::param_at;
pub use popups::scroll_max;
pub use table::data_rows;
mod popup;
pub mod popups;
pub mod predict;
pub mod scene;
pub mod status;
pub mod table;
pub mod video;
pub mod video_image;
pub mod withheld;

pub use crate::tui::layout::{MIN_SIZE, Panels, layout};

use crate::tui::app::App;
use crate::tui::component::MainView;

/// The main screen's views as drawn, registered: a new view is its line here.
const VIEWS: [&dyn MainView; 5] = [
    &charts::ChartsView,
    &forces::ForcesView,
    &methods::MethodsView,
    &map::MapView,
    &fit::FitView,
];

/// The view shown, as drawn (the charts for a view not registered).
pub fn shown(app: &App) -> &'static dyn MainView {
    let view = app.view();
    VIEWS
        .iter()
        .copied()
        .find(|v| v.view() == view)
        .unwrap_or(&charts::ChartsView)
}
