//! The parameters panel: every editable value with its unit, the selected row
//! highlighted, the typing field in place of the value while editing.

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::widgets::Widget;

use super::block;
use crate::input::params::Key;
use crate::input::units::{Dimension, show, significant};
use crate::tui::app::{App, Mode, ROWS};
use crate::tui::theme::Theme;

/// The first parameter shown when the panel at `area` holds fewer rows than there
/// are parameters: the list scrolls to keep the selected one in view.
fn first_shown(area: Rect, selected: usize) -> usize {
    let rows = usize::from(area.height.saturating_sub(2)).max(1);
    (selected + 1)
        .saturating_sub(rows)
        .min(ROWS.len().saturating_sub(rows))
}

/// Which parameter a click at (`x`, `y`) hits.
pub fn param_at(area: Rect, selected: usize, x: u16, y: u16) -> Option<usize> {
    let inside = x > area.x && x + 1 < area.right() && y > area.y && y + 1 < area.bottom();
    let i = first_shown(area, selected) + y.checked_sub(area.y + 1)? as usize;
    (inside && i < ROWS.len()).then_some(i)
}

/// A value in the unit a lab uses for it, with fixed decimals so columns line up.
fn value_text(app: &App, key: Key) -> String {
    let v = app.lab.value(key);
    let s = &app.lab.scene;
    if key == Key::V0 && s.left.v0 != s.right.v0 {
        // One control for both balls: it sets both, and says when they differ.
        return "differ".into();
    }
    match key.dimension() {
        Dimension::Ratio => significant(v, 4),
        Dimension::Length => format!("{:.2} cm", v * 100.0),
        Dimension::Mass => format!("{:.1} g", v * 1000.0),
        Dimension::Speed => format!("{v:.3} m/s"),
        dim => show(v, dim).to_string(),
    }
}

/// What stands right of a value: context that makes it readable (less when narrow).
fn note(app: &App, key: Key, narrow: bool) -> String {
    let d = &app.lab.derived;
    match key {
        Key::Width => {
            let star = d
                .b_star
                .map_or("no b*".to_string(), |b| format!("b* {:.2}", b * 100.0));
            if narrow {
                star
            } else {
                format!(
                    "b/R {:.2} {star}",
                    app.lab.scene.width / app.lab.scene.radius
                )
            }
        }
        Key::Radius => format!("k {:.3}", d.k),
        Key::V0 if narrow => String::new(),
        Key::V0 if app.lab.scene.left.v0 != app.lab.scene.right.v0 => "sets both".into(),
        Key::V0 if !narrow => "both balls".into(),
        Key::V0Left | Key::V0Right if !narrow => "toward impact".into(),
        Key::Height if !narrow => "run-up".into(),
        Key::Restitution => match d.b_star {
            None => "e < 2/5".into(),
            Some(_) => String::new(),
        },
        _ => String::new(),
    }
}

pub fn render(app: &App, area: Rect, buf: &mut Buffer, theme: &Theme) {
    let shown = usize::from(area.height.saturating_sub(2));
    let title = if shown < ROWS.len() {
        format!(" Parameters ({}/{}) ", app.selected + 1, ROWS.len())
    } else {
        " Parameters ".to_string()
    };
    let blk = block(title, theme);
    let inner = blk.inner(area);
    blk.render(area, buf);
    let g = theme.glyphs;
    let first = first_shown(area, app.selected);
    for (i, p) in ROWS.iter().enumerate().skip(first) {
        let y = inner.y + (i - first) as u16;
        if y >= inner.bottom() {
            break;
        }
        let selected = i == app.selected;
        let label = p.label.replace("mu", g.mu);
        let value = match (&app.mode, selected) {
            (Mode::Edit(text), true) => format!("[{text}_]"),
            _ => value_text(app, p.key),
        };
        let marker = if selected { g.selected } else { " " };
        let narrow = inner.width < 34;
        let line = format!(
            "{marker}{label:<9}{value:>11}  {}",
            note(app, p.key, narrow)
        );
        let style = if selected { theme.selected } else { theme.text };
        buf.set_stringn(inner.x, y, &line, inner.width as usize, style);
    }
}
