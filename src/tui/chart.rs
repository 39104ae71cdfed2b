//! A chart laid out for one frame (built by the chart panel before drawing, kept in
//! the frame): what it draws, and the time under a cell for the mouse.

use ratatui::layout::Rect;

use crate::tui::plot::Plot;

/// A chart laid out for one frame: its title's wordings (longest first), the plot
/// with the measured series thinned to its cells, and where its data cells are (a
/// click or drag finds its time there, without building the chart again).
#[derive(Clone, Debug)]
pub struct Chart {
    pub titles: Vec<String>,
    pub plot: Plot,
    pub data: Option<Rect>,
}

impl Chart {
    /// How many points the chart hands to the plot (work counted: a million measured
    /// rows are drawn as the cells they mark).
    pub fn points(&self) -> usize {
        self.plot.series.iter().map(|s| s.points.len()).sum()
    }

    /// The time under screen cell (`column`, `row`), if the cell is inside the plot
    /// (what a click on the chart seeks to).
    pub fn time_at(&self, column: u16, row: u16) -> Option<f64> {
        let plot = self.data?;
        if row < plot.y || row >= plot.bottom() {
            return None;
        }
        crate::tui::plot::time_at_column(self.plot.x_range, plot.x, plot.width, column)
    }
}
