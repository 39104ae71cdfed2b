//! A panel withheld while its content would answer the prediction (issue 28): the
//! Methods runs (each names the outcome and the impacts), the fit (its predicted and
//! observed regimes), the regime map with b shown (b/R on the map is the answer). Its
//! title and a line saying when it shows, nothing else.

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::text::{Line, Span};
use ratatui::widgets::Widget;

use super::panel::{block, draw_lines, title_within, wrap};
use crate::tui::component::{Component, Ctx};

/// A panel titled `title` that says `what` shows once the outcome does.
pub struct Withheld {
    pub title: &'static str,
    pub what: &'static str,
}

impl Component for Withheld {
    fn render(&self, area: Rect, buf: &mut Buffer, cx: &Ctx<'_>) {
        let theme = cx.theme;
        let blk = block(title_within(self.title, area, theme), theme);
        let inner = blk.inner(area);
        blk.render(area, buf);
        let note = if cx.app.hide().b() {
            format!("b hidden: {} shows with b (B)", self.what)
        } else {
            format!("predict first: {} shows once the outcome does", self.what)
        };
        let line = Line::from(Span::styled(theme.glyphs.text(&note), theme.title));
        draw_lines(wrap(line, usize::from(inner.width)), inner, buf);
    }
}
