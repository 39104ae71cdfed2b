//! The Fit view's panel: the paper's line fits beside its table 1, and the model fit
//! with its uncertainty and the regime it predicts against the one observed.

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::text::{Line, Span};
use ratatui::widgets::{Paragraph, Widget, Wrap};

use super::block;
use crate::lab::jobs::State;
use crate::study::fit;
use crate::tui::app::App;
use crate::tui::theme::Theme;

pub fn render(app: &App, area: Rect, buf: &mut Buffer, theme: &Theme) {
    let blk = block(" Fit  ( ) { } move the window, [f] back ", theme);
    let inner = blk.inner(area);
    blk.render(area, buf);
    let g = theme.glyphs;
    let label = |s: &str| Span::styled(g.text(s), theme.dim);
    let value = |s: String| Span::styled(g.text(&s), theme.text);
    let lines: Vec<Line> = match app.lab.fits() {
        State::Idle => vec![Line::from(Span::styled(
            "no measured data in this preset (try p: paper-b3.5, -b4.4, -b4.9)",
            theme.error,
        ))],
        other @ State::Computing { .. } => {
            return super::computing(&other, "fitting", inner, buf, theme);
        }
        State::Ready(Err(e)) => vec![Line::from(Span::styled(e.clone(), theme.error))],
        State::Ready(Ok(f)) => {
            let l = &f.line_fit;
            let m = &f.model_fit;
            let mut lines = vec![
                Line::from(Span::styled(
                    "paper's method: lines over the sliding phase",
                    theme.title,
                )),
                Line::from(vec![
                    label("window "),
                    value(format!(
                        "{:.2} … {:.2} s, {} frames",
                        l.from, l.to, l.points
                    )),
                ]),
                Line::from(vec![
                    label("|a_cm| "),
                    value(format!("{:.2}±{:.2} m/s{}", l.a_cm, l.a_cm_se, g.squared)),
                    label(&format!("  {}_cm ", g.mu)),
                    value(format!("{:.3}", l.mu_cm)),
                ]),
                Line::from(vec![
                    label("|a_t|  "),
                    value(format!("{:.2}±{:.2} m/s{}", l.a_t, l.a_t_se, g.squared)),
                    label(&format!("  {}_t ", g.mu)),
                    value(format!("{:.3}", l.mu_t)),
                ]),
                Line::from(vec![
                    label("|F_net| "),
                    value(format!("{:.3} N", l.f_net)),
                    label(&format!("  |{}_net| ", g.tau)),
                    value(format!("{:.4} N m", l.tau_net)),
                ]),
            ];
            if let Some(p) = fit::paper_row(app.lab.scene.width) {
                lines.push(Line::from(vec![
                    label("paper: "),
                    value(format!(
                        "|a_cm| {:.2}, {}_cm {:.2}, |a_t| {:.2}, {}_t {:.2}",
                        p[0], g.mu, p[1], p[3], g.mu, p[4]
                    )),
                ]));
            }
            lines.push(Line::from(Span::styled(
                "model fit to every frame",
                theme.title,
            )));
            lines.push(Line::from(vec![
                label(&format!("{}_k ", g.mu)),
                value(format!(
                    "{:.4} ± {:.4} (2{})",
                    m.mu,
                    2.0 * m.mu_se,
                    if g.ascii { "sigma" } else { "σ" }
                )),
                label("  RMS "),
                value(format!("{:.4} m/s", m.rms)),
            ]));
            lines.push(Line::from(vec![
                label("regime: predicted "),
                value(m.regime_predicted.name().to_string()),
                label(", observed "),
                value(m.regime_observed.name().to_string()),
            ]));
            lines.push(Line::from(Span::styled(
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
            )));
            lines
        }
    };
    Paragraph::new(lines)
        .wrap(Wrap { trim: true })
        .render(inner, buf);
}
