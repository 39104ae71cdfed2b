//! Where a popup goes on the screen: drawing and the mouse's hit-tests both ask here.

use ratatui::layout::Rect;

/// Where a popup of `width` × `height` goes on a screen of `area`: centred, a cell
/// of margin kept (drawing and the mouse's hit-tests both ask here).
pub fn centered(area: Rect, width: u16, height: u16) -> Rect {
    let w = width.min(area.width.saturating_sub(2));
    let h = height.min(area.height.saturating_sub(2));
    Rect {
        x: area.x + (area.width - w) / 2,
        y: area.y + (area.height - h) / 2,
        width: w,
        height: h,
    }
}
