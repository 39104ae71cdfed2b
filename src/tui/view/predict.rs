//! The predict popup (key `y`): the question before the impact, with its three
//! answers; a click on an answer answers (the Forces view explains the outcome).

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::text::{Line, Span};
use ratatui::widgets::{Clear, Paragraph, Widget, Wrap};

use super::panel::block;
use crate::physics::derived::Regime;
use crate::settings::units::{Dimension, significant};
use crate::tui::app::App;
use crate::tui::component::{Component, Ctx};
use crate::tui::layer::{Question, question_rect};
use crate::tui::theme::Theme;
use crate::tui::vocabulary::ANSWERS;

/// Lengths are shown in their display unit.
const LENGTH: Dimension = Dimension::Length;

pub(super) fn short_answer(r: Regime) -> &'static str {
    match r {
        Regime::Depart => "move apart",
        Regime::Rest => "come to rest",
        Regime::Recollide => "come back",
    }
}

/// How a prediction fared: its mark and its word (✓ right, ✗ not quite); the status
/// line and the Forces view say it alike.
pub(super) fn agreement(right: bool) -> (&'static str, &'static str) {
    if right {
        ("✓", "right")
    } else {
        ("✗", "not quite")
    }
}

fn answer_text(r: Regime) -> &'static str {
    match r {
        Regime::Depart => "they move apart",
        Regime::Rest => "they come to rest",
        Regime::Recollide => "they come back and collide again",
    }
}

/// The question before the impact.
pub fn question(app: &App, area: Rect, buf: &mut Buffer, theme: &Theme) {
    let g = theme.glyphs;
    let mut lines = vec![
        Line::styled("After the impact, what will the balls do?", theme.title),
        Line::from(""),
    ];
    for (key, r) in ANSWERS {
        lines.push(Line::from(vec![
            Span::styled(format!(" {key} "), theme.key),
            Span::styled(answer_text(r), theme.text),
        ]));
    }
    lines.push(Line::from(""));
    let b = if app.hide().b() {
        "b is hidden: look at the front view".to_string()
    } else {
        format!(
            "b = {}{}",
            significant(LENGTH.to_display(app.lab.scene.width), 3),
            LENGTH.suffix()
        )
    };
    lines.push(Line::styled(
        g.text(&format!("{b}; then it plays and explains. Esc cancels.")),
        theme.dim,
    ));
    let forces = if app.hide().forces_givens() {
        "shown as givens (g hides them)"
    } else {
        "hidden (g shows them as givens)"
    };
    lines.push(Line::from(vec![
        Span::styled(" g ", theme.key),
        Span::styled(format!("the forces: {forces}"), theme.dim),
    ]));
    let rect = question_rect(area, lines.len());
    Clear.render(rect, buf);
    Paragraph::new(lines)
        .wrap(Wrap { trim: false })
        .block(block(" Predict ", theme))
        .render(rect, buf);
}

impl Component for Question {
    fn render(&self, area: Rect, buf: &mut Buffer, cx: &Ctx<'_>) {
        question(cx.app, area, buf, cx.theme);
    }
}
