//! What the Forces view's parts share: its numbers (hidden by the one rule while b
//! is), footers, arrows and bars, and the pinned run's values to compare with.

pub(super) use super::super::panel::{
    NO_BREAK, Ranked, block, by_priority, draw_lines, fitting, rows_by_priority, title_of,
    title_within, unbroken, wrap,
};
pub(super) use crate::physics::derived::Regime;
pub(super) use crate::physics::forces::{Instant, Sliding, instant};
pub(super) use crate::settings::units::{Dimension, show, sig_figs};
pub(super) use crate::tui::app::{App, Prediction};
pub(super) use crate::tui::canvas::Canvas;
pub(super) use crate::tui::theme::Theme;
pub(super) use ratatui::buffer::Buffer;
pub(super) use ratatui::layout::{Constraint, Layout, Rect};
pub(super) use ratatui::style::Style;
pub(super) use ratatui::symbols::border;
pub(super) use ratatui::text::{Line, Span};
pub(super) use ratatui::widgets::{Block, Borders, Widget};

/// Lengths are shown in their display unit.
pub(super) const LENGTH: Dimension = Dimension::Length;

/// A block's bottom title: the first of `variants` (longest first) that fits on the
/// border of `area`, the last cut with an ellipsis if none does.
pub(super) fn footer(variants: &[String], area: Rect, theme: &Theme) -> Line<'static> {
    let g = theme.glyphs;
    let room = usize::from(area.width.saturating_sub(2));
    let texts: Vec<String> = variants
        .iter()
        .map(|t| format!(" {} ", g.text(t)))
        .collect();
    Line::styled(
        g.ellipsize(&fitting(&texts, area.width.saturating_sub(2)), room),
        theme.dim,
    )
}

/// What the side view's signs mean (the bottom of the side view, or of the chain
/// below it when they share a border).
pub(super) fn side_footer(area: Rect, theme: &Theme) -> Line<'static> {
    footer(
        &[
            "+x → toward the right ball; v_t = ω r > 0 rolls toward +x".into(),
            "+x → right ball; ω > 0 rolls to +x".into(),
        ],
        area,
        theme,
    )
}

/// Which ball the front view shows, 0 left or 1 right, and its name.
pub(super) fn ball_name(ball: usize) -> &'static str {
    if ball == 0 { "left" } else { "right" }
}

/// A number with 3 significant digits, or `?` while b is hidden and it depends on b.
pub(super) fn num(v: f64, hidden: bool) -> String {
    if hidden { "?".into() } else { sig_figs(v, 3) }
}

/// Out of the picture (+x, toward the viewer) or into it, as the paper's ⊙ / ⊗.
pub(super) fn along_x(theme: &Theme, positive: bool) -> &'static str {
    match (theme.glyphs.ascii, positive) {
        (false, true) => "⊙",
        (false, false) => "⊗",
        (true, true) => "(.)",
        (true, false) => "(x)",
    }
}

/// A horizontal arrow for `value` against `full` (which fills `half` cells), drawn
/// either side of a zero mark: `←──|` or `|──→`.
pub(super) fn bar(value: f64, full: f64, half: usize, theme: &Theme) -> String {
    let g = theme.glyphs;
    let n = if full > 0.0 && value != 0.0 {
        ((value.abs() / full * half as f64).round() as usize).clamp(1, half)
    } else {
        0
    };
    let shaft = g.hline.repeat(n.saturating_sub(1));
    let (left, right) = if n == 0 {
        (String::new(), String::new())
    } else if value < 0.0 {
        let head = if g.ascii { "<" } else { "←" };
        (format!("{head}{shaft}"), String::new())
    } else {
        let head = if g.ascii { ">" } else { "→" };
        (String::new(), format!("{shaft}{head}"))
    };
    format!("{left:>half$}{}{right:<half$}", g.vline)
}

/// ↑ / ↓ / = of `now` against the pinned run's `was` (empty without a pin).
pub(super) fn trend(now: f64, was: Option<f64>, theme: &Theme) -> String {
    let Some(was) = was else {
        return String::new();
    };
    let up = if theme.glyphs.ascii { "^" } else { "↑" };
    let down = if theme.glyphs.ascii { "v" } else { "↓" };
    if (now - was).abs() <= 1e-9 * now.abs().max(was.abs()) {
        " =".into()
    } else if now > was {
        format!(" {up}")
    } else {
        format!(" {down}")
    }
}

/// The pinned run's sliding values for the ball shown, and its b.
pub(super) fn pinned_sliding(app: &App) -> Option<(Sliding, f64)> {
    app.lab.pinned.as_ref().map(|p| {
        let mass = if app.forces().ball() == 0 {
            p.scene.left.mass
        } else {
            p.scene.right.mass
        };
        (Sliding::of(&p.scene, mass), p.scene.width)
    })
}
