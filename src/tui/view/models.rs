//! The Fit view's models popup (key `M`): every candidate model by BIC, lowest first,
//! the one the data support marked, scrolling; the Fit panel shows as many rows as
//! its room leaves, drawn by the same [`row`].

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::text::{Line, Span};

use super::popup::scrolling;
use crate::lab::jobs::State;
use crate::study::fit::{self, Candidate};
use crate::tui::app::App;
use crate::tui::component::{Component, Ctx};
use crate::tui::layer::Models;
use crate::tui::theme::Theme;

/// A fitted value's symbol from the parameter table: its row's label up to the first
/// blank (`mu_k` drawn as μ_k where the screen can, `v0`, `e`, `c_rr`).
pub(super) fn symbol(parameter: &str, theme: &Theme) -> String {
    match crate::settings::params::Key::from_name(parameter) {
        Some(k) => {
            let label = k.param().label;
            let first = label.split(' ').next().unwrap_or(label);
            first.replace("mu", theme.glyphs.mu)
        }
        None => parameter.to_string(),
    }
}

/// The legend of the marks `?` and `-` that some row has.
pub(super) fn legend(models: &[Candidate]) -> Vec<&'static str> {
    let undetermined = models.iter().any(|c| !c.determined());
    let resisted = |c: &Candidate| fit::rolls_harder_than_it_slides(c).is_some();
    let for_regime = models.iter().any(|c| !c.weighed && !resisted(c));
    let for_resistance = models.iter().any(|c| !c.weighed && resisted(c));
    [
        undetermined.then_some("? = a value these data do not determine (never the model named)"),
        for_regime.then_some(
            "- = predicts a regime the data do not show, a smaller one agrees: left out",
        ),
        for_resistance.then_some("- = c_rr over its μ_k (a ball so resisted slides): left out"),
    ]
    .into_iter()
    .flatten()
    .collect()
}

/// One candidate: its mark (`*` the model the data support, `-` not weighed for
/// the regime it predicts, `?` a value not determined), its free values, BIC and
/// AIC.
pub(super) fn row(c: &Candidate, theme: &Theme) -> Line<'static> {
    let g = theme.glyphs;
    let names: Vec<String> = c
        .parameters
        .iter()
        .map(|e| symbol(e.parameter, theme))
        .collect();
    let mark = match (c.supported, c.weighed, c.determined()) {
        (true, _, _) => "* ",
        (false, false, _) => "- ",
        (false, true, true) => "  ",
        (false, true, false) => "? ",
    };
    Line::from(vec![
        Span::styled(mark, theme.info),
        Span::styled(g.text(&format!("{:<14}", names.join("+"))), theme.text),
        Span::styled(format!(" BIC {:>7.1} AIC {:>7.1}", c.bic, c.aic), theme.dim),
    ])
}

/// The popup's lines (the rows, then the legend) and its width.
pub(super) fn lines(app: &App, theme: &Theme) -> (Vec<Line<'static>>, u16) {
    let State::Ready(Ok(f)) = app.fit().fits() else {
        return (Vec::new(), 50);
    };
    let mut lines: Vec<Line> = f.models.iter().map(|c| row(c, theme)).collect();
    lines.push(Line::from(Span::styled(
        "* = the model the data support",
        theme.dim,
    )));
    for text in legend(&f.models) {
        lines.push(Line::from(Span::styled(text, theme.dim)));
    }
    (lines, 92)
}

impl Component for Models {
    fn render(&self, area: Rect, buf: &mut Buffer, cx: &Ctx<'_>) {
        let (lines, width) = lines(cx.app, cx.theme);
        let title = if cx.theme.glyphs.ascii {
            "Models by BIC, lowest first  (Esc closes, up/down scroll)"
        } else {
            "Models by BIC, lowest first  (Esc closes, ↑↓ scroll)"
        };
        let line = |i: usize| lines[i].clone();
        let source: (usize, &dyn Fn(usize) -> Line<'static>) = (lines.len(), &line);
        let first = self.scroll().first();
        scrolling(
            first,
            title,
            Vec::new(),
            source,
            (area, width),
            buf,
            cx.theme,
        );
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::study::fit;
    use crate::tui::theme::Glyphs;

    /// A determined candidate of `free` values, supported and weighed as given.
    fn candidate(free: &[&'static str], supported: bool, weighed: bool) -> Candidate {
        let values: Vec<(&'static str, bool)> = free.iter().map(|&p| (p, true)).collect();
        Candidate {
            supported,
            weighed,
            ..fit::blank_candidate(&values, 1.0)
        }
    }

    #[test]
    fn a_model_not_weighed_is_marked_and_the_mark_explained() {
        let theme = Theme::new(Glyphs::new(true), true);
        let named = candidate(&["mu", "v0"], true, true);
        let left = candidate(&["mu", "v0", "restitution"], false, false);
        assert!(row(&named, &theme).to_string().starts_with("* "));
        assert!(row(&left, &theme).to_string().starts_with("- "));
        let marks = legend(&[left.clone(), named.clone()]);
        assert_eq!(marks.len(), 1, "{marks:?}");
        assert!(
            marks[0].starts_with("- = predicts a regime the data do not show"),
            "{marks:?}"
        );
        // Left out for a c_rr over its μ_k: that reason.
        let mut resisted = candidate(&["mu", "rolling_resistance"], false, false);
        for (e, v) in resisted.parameters.iter_mut().zip([0.062, 0.116]) {
            e.value = v;
        }
        assert!(row(&resisted, &theme).to_string().starts_with("- "));
        let marks = legend(&[resisted.clone(), named.clone()]);
        assert_eq!(marks.len(), 1, "{marks:?}");
        assert!(marks[0].starts_with("- = c_rr over its μ_k"), "{marks:?}");
        assert_eq!(legend(&[resisted, left.clone(), named.clone()]).len(), 2);
        // Every model weighed: no mark, no legend.
        let weighed = candidate(&["mu", "v0", "restitution"], false, true);
        assert!(row(&weighed, &theme).to_string().starts_with("  "));
        assert!(legend(&[weighed, named]).is_empty());
    }
}
