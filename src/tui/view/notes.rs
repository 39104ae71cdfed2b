//! A throwaway view (issue 26's "done when"): the scene's time and the view's name in
//! one panel, to count what a new view touches.

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::text::Line;
use ratatui::widgets::Widget;

use super::panel::{block, draw_lines};
use crate::tui::component::{Component, Ctx};

/// The Notes view: one panel.
pub struct Notes;

impl Component for Notes {
    fn render(&self, area: Rect, buf: &mut Buffer, cx: &Ctx<'_>) {
        let blk = block(" Notes ".to_string(), cx.theme);
        let inner = blk.inner(area);
        blk.render(area, buf);
        let line = Line::from(format!("t = {:.3} s", cx.app.t));
        draw_lines(vec![line], inner, buf);
    }
}
