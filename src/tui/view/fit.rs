//! The Fit view's panel: the paper's line fits beside its table 1, and the model fit
//! with its uncertainty and the regime it predicts against the one observed.

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::text::{Line, Span};
use ratatui::widgets::Widget;

use super::{Ranked, block, by_priority, draw_lines};
use crate::lab::jobs::State;
use crate::study::fit;
use crate::tui::app::App;
use crate::tui::theme::Theme;

pub fn render(app: &App, area: Rect, buf: &mut Buffer, theme: &Theme) {
    let title = if inner_width(area) < 40 {
        " Fit  ( ) { } window, [a] apply "
    } else {
        " Fit  ( ) { } move the window, [a] apply, [f] back "
    };
    let blk = block(title, theme);
    let inner = blk.inner(area);
    blk.render(area, buf);
    let g = theme.glyphs;
    let label = |s: &str| Span::styled(g.text(s), theme.dim);
    let value = |s: String| Span::styled(g.text(&s), theme.text);
    // Priorities (9 most important): the model's μ_k and whether it predicts what was
    // seen stay on the smallest screen; the paper's forces and table row go first.
    let lines: Ranked = match app.lab.fits() {
        State::Idle => vec![(
            9,
            Line::from(Span::styled(
                "no measured data in this preset (try p: paper-b3.5, -b4.4, -b4.9)",
                theme.error,
            )),
        )],
        other @ State::Computing { .. } => {
            return super::computing(&other, "fitting", inner, buf, theme);
        }
        State::Ready(Err(e)) => vec![(9, Line::from(Span::styled(e.clone(), theme.error)))],
        State::Ready(Ok(f)) => {
            let l = &f.line_fit;
            let m = &f.model_fit;
            let mut lines: Ranked = vec![
                (
                    5,
                    Line::from(Span::styled(
                        "paper's method: lines over the sliding phase",
                        theme.title,
                    )),
                ),
                (
                    6,
                    Line::from(vec![
                        label("window "),
                        value(format!(
                            "{:.2} … {:.2} s, {} frames",
                            l.from, l.to, l.points
                        )),
                    ]),
                ),
                (
                    7,
                    Line::from(vec![
                        label("|a_cm| "),
                        value(format!("{:.2}±{:.2} m/s{}", l.a_cm, l.a_cm_se, g.squared)),
                        label(&format!("  {}_cm ", g.mu)),
                        value(format!("{:.3}", l.mu_cm)),
                    ]),
                ),
                (
                    7,
                    Line::from(vec![
                        label("|a_t|  "),
                        value(format!("{:.2}±{:.2} m/s{}", l.a_t, l.a_t_se, g.squared)),
                        label(&format!("  {}_t ", g.mu)),
                        value(format!("{:.3}", l.mu_t)),
                    ]),
                ),
                (
                    1,
                    Line::from(vec![
                        label("|F_net| "),
                        value(format!("{:.3} N", l.f_net)),
                        label(&format!("  |{}_net| ", g.tau)),
                        value(format!("{:.4} N m", l.tau_net)),
                    ]),
                ),
            ];
            if let Some(p) = fit::paper_row(app.lab.scene.width) {
                lines.push((
                    3,
                    Line::from(vec![
                        label("paper: "),
                        value(format!(
                            "|a_cm| {:.2}, {}_cm {:.2}, |a_t| {:.2}, {}_t {:.2}",
                            p[0], g.mu, p[1], p[3], g.mu, p[4]
                        )),
                    ]),
                ));
            }
            lines.push((
                5,
                Line::from(Span::styled("model fit to every frame", theme.title)),
            ));
            lines.push((
                9,
                Line::from(vec![
                    label(&format!("{}_k ", g.mu)),
                    value(format!(
                        "{:.4} ± {:.4} (2{})",
                        m.mu,
                        2.0 * m.mu_se,
                        if g.ascii { "sigma" } else { "σ" }
                    )),
                    label("  RMS "),
                    value(format!("{:.4} m/s", m.rms)),
                ]),
            ));
            lines.push((
                8,
                Line::from(vec![
                    label("regime: predicted "),
                    value(m.regime_predicted.name().to_string()),
                    label(", observed "),
                    value(m.regime_observed.name().to_string()),
                ]),
            ));
            lines.push((
                9,
                Line::from(Span::styled(
                    if m.regime_predicted == m.regime_observed {
                        "the model predicts what was seen".to_string()
                    } else {
                        "the model does NOT predict what was seen".to_string()
                    },
                    if m.regime_predicted == m.regime_observed {
                        theme.info
                    } else {
                        theme.error
                    },
                )),
            ));
            lines
        }
    };
    draw_lines(by_priority(lines, inner), inner, buf);
}

fn inner_width(area: Rect) -> u16 {
    area.width.saturating_sub(2)
}
