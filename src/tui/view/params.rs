//! The parameters panel: every editable value with its unit and a one-letter mark of
//! where it came from ([`Origin::mark`]: d data, f flag, h the data file's header, p
//! preset, e edited, a assumed; the marks in use are the legend on the bottom
//! border), the selected row highlighted, the typing field in place of the value
//! while editing.

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::widgets::Widget;

use super::panel::block;
use crate::lab::Origin;
use crate::settings::params::Key;
use crate::settings::units::{Dimension, fit_number, show_below};
use crate::tui::app::{App, ROWS};
use crate::tui::component::{Component, Ctx};
use crate::tui::line::caret as caret_style;
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

/// Columns of a row: marker, label, value (right-aligned), its origin's mark between
/// spaces, note.
const LABEL_W: usize = 9;
const VALUE_W: usize = 11;

/// A value in the unit a lab uses for it, with fixed decimals so columns line up, in
/// at most [`VALUE_W`] characters: a value too long for its decimals is fitted (fewer
/// digits, never cut).
pub fn value_text(app: &App, key: Key) -> String {
    let v = app.lab.value(key);
    let s = &app.lab.scene;
    if app.hidden().value(key) {
        return "hidden".into();
    }
    if key == Key::V0 && s.left.v0 != s.right.v0 {
        // One control for both balls: it sets both, and says when they differ.
        return "differ".into();
    }
    let dim = key.dimension();
    let (fixed, unit) = (dim.panel_number(v), dim.suffix());
    let room = VALUE_W - unit.chars().count();
    let number = if fixed.chars().count() <= room {
        fixed
    } else {
        fit_number(dim.to_display(v), room)
    };
    if key == Key::Width && !reads_below(&number, dim.to_display(2.0 * s.radius)) {
        // A width just under 2R rounded up would read as 2R, which is refused: its
        // digits cut to the room instead (5.4999999 cm reads 5.499999, not 5.50).
        let below = show_below(v, 2.0 * s.radius, dim);
        let digits = below.strip_suffix(unit.as_str()).unwrap_or(&below);
        return format!("{}{unit}", digits.chars().take(room).collect::<String>());
    }
    format!("{number}{unit}")
}

/// True when `number` (as shown) reads below `limit` (in the same unit).
fn reads_below(number: &str, limit: f64) -> bool {
    number.trim().parse::<f64>().is_ok_and(|n| n < limit)
}

/// What stands right of a value: context that makes it readable, fitted into `room`
/// characters (the less important part goes first; numbers lose digits, never cut).
pub fn note(app: &App, key: Key, room: usize) -> String {
    let d = &app.lab.derived;
    // `label value` with the value fitted into what is left, or nothing if no digit fits.
    // Fixed decimals when they fit (columns line up), else fitted.
    let pair = |label: &str, v: f64, decimals: usize, room: usize| -> Option<String> {
        let room = room.checked_sub(label.chars().count() + 1)?;
        let fixed = format!("{v:.decimals$}");
        let n = if fixed.len() <= room {
            fixed
        } else {
            fit_number(v, room)
        };
        (!n.starts_with('#')).then(|| format!("{label} {n}"))
    };
    let text = match key {
        // b/R and k would give b away; b* does not depend on b, but beside a b
        // that is shown (a pending prediction) it is the answer.
        Key::Width | Key::Radius if app.hidden().derived() => d
            .b_star
            .and_then(|b| pair("b*", Dimension::Length.to_display(b), 2, room))
            .filter(|_| key == Key::Width && app.hide().b()),
        Key::Width => {
            let star = match d.b_star {
                None => Some("no b*".to_string()).filter(|s| s.len() <= room),
                Some(b) => pair("b*", Dimension::Length.to_display(b), 2, room),
            };
            let ratio = app.lab.scene.width / app.lab.scene.radius;
            // b/R beside b* only when both keep 3 digits.
            let both = star
                .as_ref()
                .filter(|s| s.len() <= 7)
                .and_then(|s| pair("b/R", ratio, 2, 8).map(|r| format!("{r} {s}")));
            both.filter(|s| s.chars().count() <= room).or(star)
        }
        Key::Radius => pair("k", d.k, 3, room.min(7)),
        Key::V0 if app.lab.scene.left.v0 != app.lab.scene.right.v0 => Some("sets both".into()),
        Key::V0 => Some("both balls".into()),
        Key::V0Left | Key::V0Right => Some("toward impact".into()),
        Key::HeightLeft | Key::HeightRight => Some("run-up".into()),
        Key::Restitution => d.b_star.is_none().then(|| "e < 2/5".into()),
        _ => None,
    };
    text.filter(|s| s.chars().count() <= room)
        .unwrap_or_default()
}

pub fn render(app: &App, area: Rect, buf: &mut Buffer, theme: &Theme) {
    let shown = usize::from(area.height.saturating_sub(2));
    let title = if shown < ROWS.len() {
        format!(" Parameters ({}/{}) ", app.selected() + 1, ROWS.len())
    } else {
        " Parameters ".to_string()
    };
    // A hidden value hides whether it was changed too: `?`, and not in the legend.
    let origins: Vec<Option<Origin>> = ROWS
        .iter()
        .map(|p| (!app.hide().value(p.key)).then(|| app.lab.settings().origin(p.key)))
        .collect();
    let used: Vec<Origin> = origins.iter().flatten().copied().collect();
    // Between the corners.
    let room = usize::from(area.width.saturating_sub(2));
    let blk = block(title, theme).title_bottom(legend(&used, room));
    let inner = blk.inner(area);
    blk.render(area, buf);
    let g = theme.glyphs;
    let first = first_shown(area, app.selected());
    for (i, p) in ROWS.iter().enumerate().skip(first) {
        let y = inner.y + (i - first) as u16;
        if y >= inner.bottom() {
            break;
        }
        let selected = i == app.selected();
        let label = p.label.replace("mu", g.mu);
        // The typing field: the part of the line around its cursor, in brackets.
        let (value, caret) = match (app.editing(), selected) {
            (Some(field), true) => {
                let (shown, at) = field.shown(VALUE_W - 2);
                let x = 1 + LABEL_W + VALUE_W - shown.chars().count() - 1 + at;
                (format!("[{shown}]"), Some(x))
            }
            _ => (value_text(app, p.key), None),
        };
        let marker = if selected { g.selected } else { " " };
        let room = usize::from(inner.width).saturating_sub(1 + LABEL_W + VALUE_W + 3);
        let mark = origins[i].map_or('?', Origin::mark);
        let line = format!(
            "{marker}{label:<LABEL_W$}{value:>VALUE_W$} {mark} {}",
            note(app, p.key, room)
        );
        let style = if selected { theme.selected } else { theme.text };
        buf.set_stringn(inner.x, y, &line, inner.width as usize, style);
        if let Some(x) = caret.and_then(|x| u16::try_from(x).ok())
            && x < inner.width
        {
            buf[(inner.x + x, y)].set_style(caret_style(style));
        }
    }
}

/// The bottom border's legend: each mark in use and its word, in [`Origin::ALL`]'s
/// order (" d data  f flag  p preset "), as many whole entries as fit in `room`
/// columns (a border cuts a legend mid-word: "a a" for "a assumed").
pub fn legend(origins: &[Origin], room: usize) -> String {
    let mut shown: Vec<String> = Vec::new();
    for o in Origin::ALL.into_iter().filter(|o| origins.contains(o)) {
        shown.push(format!("{} {}", o.mark(), o.legend()));
        if format!(" {} ", shown.join("  ")).chars().count() > room {
            shown.pop();
            break;
        }
    }
    if shown.is_empty() {
        return String::new();
    }
    format!(" {} ", shown.join("  "))
}

/// The parameters panel as a component.
pub struct ParamsPanel;

impl Component for ParamsPanel {
    fn render(&self, area: Rect, buf: &mut Buffer, cx: &Ctx<'_>) {
        render(cx.app, area, buf, cx.theme);
    }
}
