//! What every popup draws with: a box centred on the screen, and one whose lines
//! scroll with "more" marks on its borders.

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::text::{Line, Span};
use ratatui::widgets::{Block, Clear, Paragraph, Widget, Wrap};

use super::panel::block;
use crate::tui::layer::centered;
use crate::tui::theme::Theme;

pub(super) fn popup(
    title: &str,
    lines: Vec<Line<'_>>,
    area: Rect,
    width: u16,
    buf: &mut Buffer,
    theme: &Theme,
) {
    let rect = centered(area, width, lines.len() as u16 + 2);
    Clear.render(rect, buf);
    let blk = block(theme.glyphs.text(&format!(" {title} ")), theme);
    Paragraph::new(lines)
        .wrap(Wrap { trim: false })
        .block(blk)
        .render(rect, buf);
}

/// Where a scrolling popup of `width` with `head` fixed lines over `count` scrolling
/// ones goes on a screen of `area`, how many scrolling lines show, and how far it
/// scrolls.
pub(super) fn scroll_frame(
    area: Rect,
    width: u16,
    head: usize,
    count: usize,
) -> (Rect, usize, usize) {
    let rect = centered(
        area,
        width,
        (head + count).min(usize::from(u16::MAX - 2)) as u16 + 2,
    );
    let visible = usize::from(rect.height.saturating_sub(2)).saturating_sub(head);
    (rect, visible, count.saturating_sub(visible))
}

/// A popup of `width` whose `lines` scroll: as many as fit from line `first`, "more ↓"
/// on the bottom border while lines are below, "↑ more" on the top one while lines
/// are above.
pub(super) fn scrolling<'a>(
    first: usize,
    title: &str,
    head: Vec<Line<'a>>,
    (count, line): (usize, &dyn Fn(usize) -> Line<'a>),
    (area, width): (Rect, u16),
    buf: &mut Buffer,
    theme: &Theme,
) {
    let g = theme.glyphs;
    let (rect, visible, max) = scroll_frame(area, width, head.len(), count);
    Clear.render(rect, buf);
    let first = first.min(max);
    let mut blk: Block = block(g.text(&format!(" {title} ")), theme);
    if first + visible < count {
        let more = g.text(&format!(" more ↓ ({} of {count}) ", first + visible));
        blk = blk.title_bottom(Line::from(Span::styled(more, theme.key)).right_aligned());
    }
    if first > 0 {
        blk =
            blk.title_top(Line::from(Span::styled(g.text(" ↑ more "), theme.key)).right_aligned());
    }
    let inner = blk.inner(rect);
    blk.render(rect, buf);
    // Only the rows on screen are made (a data table can have a million).
    let shown: Vec<Line> = head
        .into_iter()
        .chain((first..count.min(first + visible)).map(line))
        .collect();
    super::panel::draw_lines(shown, inner, buf);
}
