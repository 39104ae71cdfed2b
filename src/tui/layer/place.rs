//! Where a popup goes on the screen: drawing and the mouse's hit-tests both ask here.

use ratatui::layout::Rect;

/// Where a popup of `width` × `height` goes on a screen of `area`: centred, a cell
/// of margin kept on every side (so its corners never sit beside the panels' top and
/// bottom corners, `╭╭`, `╰╰`); a tall one moved up to leave the status line and the
/// hint bar (the screen's last two rows) whole (drawing and the mouse's hit-tests
/// both ask here).
pub fn centered(area: Rect, width: u16, height: u16) -> Rect {
    let w = width.min(area.width.saturating_sub(2));
    let above_status = area.height.saturating_sub(2);
    let h = height.min(above_status.saturating_sub(2));
    Rect {
        x: area.x + (area.width - w) / 2,
        y: area.y
            + ((area.height - h) / 2)
                .min(above_status.saturating_sub(1) - h)
                .max(1),
        width: w,
        height: h,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_tall_popup_leaves_the_last_two_rows_whole() {
        for (w, h) in [(80, 24), (120, 40), (121, 41), (200, 60)] {
            let area = Rect::new(0, 0, w, h);
            for height in [h - 5, h - 4, h - 2, h, 1000] {
                let r = centered(area, w, height);
                assert!(r.bottom() <= h - 3, "{w}x{h} {height}: {r:?}");
                assert!(r.x >= 1 && r.y >= 1, "{r:?}");
            }
            // A small popup stays centred on the whole screen.
            let r = centered(area, 20, 10);
            assert_eq!((r.x, r.y), ((w - 20) / 2, (h - 10) / 2));
        }
    }
}
