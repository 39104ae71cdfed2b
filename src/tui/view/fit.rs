//! The Fit view's panel: the paper's line fits beside its table 1, and the model fit
//! with its uncertainty and the regime it predicts against the one observed.

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::text::{Line, Span};
use ratatui::widgets::Widget;

use super::charts::{ChartPanel, ENERGY_WITHHELD};
use super::models::symbol;
use super::panel::{Ranked, block, by_priority, draw_lines};
use super::withheld::Withheld;
use crate::lab::jobs::State;
use crate::settings::units::{Dimension, show_small, with_uncertainty};
use crate::study::fit::{self, Agreement, ModelFit};
use crate::tui::app::App;
use crate::tui::component::{Component, Ctx, MainView, Place, Prepared};
use crate::tui::theme::Theme;
use crate::tui::view_cache::ViewCache;
use crate::tui::vocabulary::View;

pub fn render(app: &App, area: Rect, buf: &mut Buffer, theme: &Theme) {
    // The long title where it fits on the border whole, else the short one.
    let long = " Fit  ( ) { } move the window, [a] apply, [f] back ";
    let title = if long.chars().count() as u16 + 2 <= area.width {
        long
    } else {
        " Fit  ( ) { } window, [a] apply "
    };
    let blk = block(title, theme);
    let inner = blk.inner(area);
    blk.render(area, buf);
    // Priorities (9 most important): the model's μ_k and whether it predicts what was
    // seen stay on the smallest screen; the paper's forces and table row go first.
    let lines: Ranked = match app.fit().fits() {
        State::Idle if app.lab.unfit().is_some() => {
            unfit_lines(app, usize::from(inner.width), theme)
        }
        State::Idle => vec![(
            9,
            Line::from(Span::styled(
                "no measured data in this preset (try p: paper-b3.5, -b4.4, -b4.9)",
                theme.error,
            )),
        )],
        other @ State::Computing { .. } => {
            return super::panel::computing(&other, "fitting", inner, buf, theme);
        }
        State::Ready(Err(e)) => vec![(9, Line::from(Span::styled(e.to_string(), theme.error)))],
        State::Ready(Ok(f)) => {
            let mut lines = sources_lines(app, theme);
            match (&f.line_fit, &f.no_line_fit) {
                (Some(l), _) => {
                    lines.extend(line_fit_lines(l, app, usize::from(inner.width), theme))
                }
                // Beside the model fits, which need none.
                (None, why) => lines.push((
                    5,
                    Line::from(Span::styled(
                        theme.glyphs.text(&format!(
                            "line fit: not possible ({})",
                            why.as_ref().map_or_else(String::new, ToString::to_string)
                        )),
                        theme.dim,
                    )),
                )),
            }
            paper_row_lines(app, &mut lines, theme);
            model_fits_lines(f, usize::from(inner.width), &mut lines, theme);
            model_choice_lines(&f.models, &mut lines, theme);
            lines
        }
    };
    draw_lines(by_priority(lines, inner), inner, buf);
}

/// The user's data that no fit can use: why, what to give, and what is shown of
/// them instead.
fn unfit_lines(app: &App, width: usize, theme: &Theme) -> Ranked<'static> {
    let Some(u) = app.lab.unfit() else {
        return Vec::new();
    };
    let mut lines: Ranked = vec![(
        9,
        Line::from(Span::styled(format!("no fit of {}:", u.name), theme.error)),
    )];
    let why = Line::from(Span::styled(u.why.clone(), theme.error));
    lines.extend(super::panel::wrap(why, width).into_iter().map(|l| (8, l)));
    let shown = if u.in_file_time.is_some() {
        "shown without a fit: d its rows; the chart its v_cm in the file's own time (×), not aligned with the model's"
    } else {
        "its lengths are not known to be metres: nothing of it is drawn; groovelab data FILE shows what it holds"
    };
    let shown = Line::from(Span::styled(shown, theme.dim));
    lines.extend(super::panel::wrap(shown, width).into_iter().map(|l| (7, l)));
    lines
}

/// Where the fitted scene's values came from, by origin ("data: v0 0.448 m/s  flag:
/// R, b  preset: μ_k (start), e, c_rr  assumed: m 167 g"), and a v0 given that the
/// data contradict.
fn sources_lines(app: &App, theme: &Theme) -> Ranked<'static> {
    use crate::lab::Origin;
    use crate::settings::params::Key;
    let g = theme.glyphs;
    let settings = app.lab.settings();
    let scene = &app.lab.scene;
    let value = |v: f64, dim: Dimension| crate::settings::units::show(v, dim).to_string();
    let rows = [
        (Key::Radius, "R".to_string()),
        (Key::Width, "b".to_string()),
        (
            Key::MassLeft,
            format!("m {}", value(scene.left.mass, Dimension::Mass)),
        ),
        (Key::Mu, format!("{}_k (start)", g.mu)),
        (
            Key::V0Left,
            format!("v0 {}", value(scene.left.v0, Dimension::Speed)),
        ),
        (Key::Restitution, "e".to_string()),
        (Key::RollingResistance, "c_rr".to_string()),
    ];
    let mut spans = vec![Span::styled("scene from ", theme.dim)];
    for origin in Origin::ALL {
        let names: Vec<&str> = rows
            .iter()
            .filter(|(k, _)| settings.origin(*k) == origin)
            .map(|(_, n)| n.as_str())
            .collect();
        // Each value whole on one line: its name, number and unit held together.
        let names: Vec<String> = names.iter().map(|n| super::panel::unbroken(n)).collect();
        if names.is_empty() {
            continue;
        }
        spans.push(Span::styled(format!("{}: ", origin.legend()), theme.dim));
        spans.push(Span::styled(
            g.text(&format!("{}  ", names.join(", "))),
            theme.text,
        ));
    }
    let mut lines = vec![(3, Line::from(spans))];
    if let Some(c) = &app.lab.contradiction {
        let by = match c.origin {
            Origin::Edited => "edited",
            Origin::File => "the file's header",
            _ => "an option",
        };
        lines.push((
            8,
            Line::from(Span::styled(
                g.text(&format!("note: {}", c.describe(by))),
                theme.error,
            )),
        ));
    }
    lines
}

/// The paper's method: straight lines over the sliding phase, their accelerations,
/// μ_k and the net force and torque.
fn line_fit_lines(l: &fit::LineFit, app: &App, width: usize, theme: &Theme) -> Ranked<'static> {
    let g = theme.glyphs;
    let label = |s: &str| Span::styled(g.text(s), theme.dim);
    let value = |s: String| Span::styled(g.text(&s), theme.text);
    let mut lines: Ranked<'static> = vec![
        (
            5,
            Line::from(Span::styled(
                if l.given == [false, false] {
                    "paper's method: lines over the sliding phase"
                } else {
                    "paper's method: lines over the window you set"
                },
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
    ];
    // Each acceleration with its μ_k on one line where the panel holds it, else the
    // μ_k on the line below (not a word wrapped off on its own).
    let mut accelerations = |name: &str, a: String, mu: Option<String>| {
        let a = g.text(&a);
        let mu = mu.map(|m| g.text(&m));
        let len = name.chars().count()
            + a.chars().count()
            + mu.as_ref().map_or(0, |m| m.chars().count() + 2);
        match mu {
            Some(m) if len > width => {
                lines.push((7, Line::from(vec![label(name), value(a)])));
                lines.push((7, Line::from(vec![label("       "), value(m)])));
            }
            Some(m) => lines.push((
                7,
                Line::from(vec![label(name), value(a), label("  "), value(m)]),
            )),
            None => lines.push((7, Line::from(vec![label(name), value(a)]))),
        }
    };
    accelerations(
        "|a_cm| ",
        format!("{} m/s{}", pm_tight(l.a_cm, l.a_cm_se, 2), g.squared),
        Some(format!("{}_cm {:.3}", g.mu, l.mu_cm)),
    );
    if l.a_t.is_finite() {
        // μ_k,t from a slope not told from none says nothing (`a_t_undetermined`).
        let mu_t = if l.a_t_undetermined() {
            format!("{}_t not determined", g.mu)
        } else {
            format!("{}_t {:.3}", g.mu, l.mu_t)
        };
        accelerations(
            "|a_t|  ",
            format!("{} m/s{}", pm_tight(l.a_t, l.a_t_se, 2), g.squared),
            Some(mu_t),
        );
    } else {
        // As `fit` says it: a rim mark tracked but seen in too few frames of the
        // window is not "no rim mark".
        let why = l.why_no_v_t().short();
        accelerations(
            "|a_t|  ",
            format!("and {}_t not measured ({why})", g.mu),
            None,
        );
    }
    lines.push((
        1,
        Line::from(vec![
            label("|F_net| "),
            value(format!("{:.3} N", l.f_net)),
            label(&format!("  |{}_net| ", g.tau)),
            value(format!("{:.4} N m", l.tau_net)),
            label(if app.lab.settings().mass_assumed() {
                "  (m assumed)"
            } else {
                ""
            }),
        ]),
    ));
    lines
}

/// The paper's table-1 row for this width, and where that row contradicts itself
/// (physics.md); beside the paper's own (velocity) series only: a position track is
/// never the paper's data.
fn paper_row_lines(app: &App, lines: &mut Ranked<'static>, theme: &Theme) {
    let g = theme.glyphs;
    let label = |s: &str| Span::styled(g.text(s), theme.dim);
    let value = |s: String| Span::styled(g.text(&s), theme.text);
    let paper_data = app.lab.measured().is_some_and(|m| m.x().is_none());
    let Some(p) = fit::paper_row(app.lab.scene.width).filter(|_| paper_data) else {
        return;
    };
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
    let scene = &app.lab.scene;
    for d in fit::paper_disagreements(scene.width, scene.radius, scene.g) {
        lines.push((
            3,
            Line::from(label(&format!(
                "  its |a_{}| gives {}_{} {:.3}, not {:.2}",
                d.which, g.mu, d.which, d.own, d.printed
            ))),
        ));
    }
}

/// The headline: the fit of the model the data support (of a position track, fitted
/// to the positions, beside the same model fitted to the derived velocities), the
/// numbers `fit` prints; then μ_k alone.
fn model_fits_lines(f: &fit::Fits, width: usize, lines: &mut Ranked<'static>, theme: &Theme) {
    match &f.velocity_fit {
        None => model_fit_lines(&f.model_fit, lines, theme),
        Some(v) => both_fits(v, &f.model_fit, width, lines, theme),
    }
    let g = theme.glyphs;
    if let Some(s) = &f.slips {
        let text = format!(
            "{} of {} frames left out as tracking slips (over {:.2} off the model; `fit` lists them)",
            s.t.len(),
            s.frames,
            show_small(s.beyond, Dimension::Length)
        );
        lines.push((5, Line::from(Span::styled(g.text(&text), theme.dim))));
    }
    // Named as `fit` names it: "μ_k alone" frees v0 too wherever the data measure it.
    let a = &f.mu_alone;
    let alone = match a.model.as_str() {
        "mu" => format!("{}_k alone", g.mu),
        _ => format!("{}_k alone (v0 fitted too)", g.mu),
    };
    let text = if a.model == f.model_fit.model {
        format!("{alone}: the same fit")
    } else {
        format!("{alone}: {}  RMS {}", pm(a, 4, g.ascii), rms(a))
    };
    lines.push((6, Line::from(Span::styled(g.text(&text), theme.dim))));
}

/// A fit's RMS residual in its data's unit.
fn rms(m: &ModelFit) -> String {
    match m.fitted_to {
        "positions" => format!("{:.2}", show_small(m.rms, Dimension::Length)),
        _ => format!("{:.4} m/s", m.rms),
    }
}

/// A model's name: `mu+v0` → `μ_k+v0`.
fn model_name(model: &str, theme: &Theme) -> String {
    let names: Vec<String> = model.split('+').map(|p| symbol(p, theme)).collect();
    names.join("+")
}

/// The candidate models by BIC (lower is better), the one the data support marked;
/// below the fits, the first to go on a small screen. A value the data do not
/// determine is said so (as `fit` says it), and its model is never the one named.
fn model_choice_lines(models: &[fit::Candidate], lines: &mut Ranked<'static>, theme: &Theme) {
    let g = theme.glyphs;
    let symbol = |parameter: &str| symbol(parameter, theme);
    let name = |c: &fit::Candidate| {
        let names: Vec<String> = c.parameters.iter().map(|e| symbol(e.parameter)).collect();
        names.join("+")
    };
    // Only in the room the fits leave: the header before the rows (a small screen
    // keeps the best, listed first).
    match models.iter().find(|c| c.supported) {
        Some(c) => lines.push((
            1,
            Line::from(vec![
                Span::styled("the data support ", theme.dim),
                Span::styled(g.text(&name(c)), theme.info),
                Span::styled(left_out(models), theme.dim),
            ]),
        )),
        None if !models.is_empty() => lines.push((
            1,
            Line::from(Span::styled(
                "no model named: none near the lowest BIC has every value determined",
                theme.dim,
            )),
        )),
        None => {}
    }
    if models.is_empty() {
        return;
    }
    // In the order `fit` lists them (`fit::compare_models`): by BIC, lowest first; the
    // rows the room leaves, all of them in the M popup (the header says so, and stays
    // when no row fits).
    lines.push((
        1,
        Line::from(Span::styled(
            format!("models by BIC, lowest first (M lists all {})", models.len()),
            theme.dim,
        )),
    ));
    for c in models {
        lines.push((0, super::models::row(c, theme)));
    }
    for text in super::models::legend(models) {
        lines.push((0, Line::from(Span::styled(text, theme.dim))));
    }
}

/// After "the data support …": how many models were left out of the choice, and why
/// (a regime the data do not show, or a c_rr over their μ_k).
fn left_out(models: &[fit::Candidate]) -> String {
    let out: Vec<&fit::Candidate> = models.iter().filter(|o| !o.weighed).collect();
    let resisted = out
        .iter()
        .filter(|c| fit::rolls_harder_than_it_slides(c).is_some())
        .count();
    match (out.len(), resisted) {
        (0, _) => " (by BIC)".to_string(),
        (n, 0) => format!(" (by BIC; {n} left out: they predict a regime the data do not show)"),
        (n, r) if r == n => format!(" (by BIC; {n} left out: c_rr over their μ_k)"),
        (n, _) => format!(
            " (by BIC; {n} left out: a regime the data do not show, or c_rr over their μ_k)"
        ),
    }
}

/// `v±e` without spaces, for narrow columns, by the one rule of every ±
/// ([`with_uncertainty`]).
fn pm_tight(v: f64, e: f64, decimals: usize) -> String {
    let (v, e) = with_uncertainty(v, e, decimals);
    format!("{v}±{}", e.replace("< ", "<"))
}

/// The model fit of a velocity series: μ_k ± 2σ, RMS, and the verdict.
fn model_fit_lines(m: &ModelFit, lines: &mut Ranked<'static>, theme: &Theme) {
    let g = theme.glyphs;
    let label = |s: &str| Span::styled(g.text(s), theme.dim);
    let value = |s: String| Span::styled(g.text(&s), theme.text);
    lines.push((
        5,
        Line::from(Span::styled(
            g.text(&format!("model fit: {}", model_name(&m.model, theme))),
            theme.title,
        )),
    ));
    lines.push((
        9,
        Line::from(vec![
            label(&format!("{}_k ", g.mu)),
            value(pm(m, 4, g.ascii)),
            label("  RMS "),
            value(rms(m)),
        ]),
    ));
    verdict_lines(m, lines, theme);
}

/// μ ± 2σ with `decimals`; "not determined" where the data do not determine it (as
/// `fit` says).
fn pm(m: &ModelFit, decimals: usize, ascii: bool) -> String {
    let two_sigma = if ascii { "2sigma" } else { "2σ" };
    if m.undetermined("mu").is_some() {
        "not determined".to_string()
    } else if m.mu_se.is_finite() {
        let (v, e) = with_uncertainty(m.mu, 2.0 * m.mu_se, decimals);
        format!("{v} ± {e} ({two_sigma})")
    } else {
        format!("{:.decimals$}", m.mu)
    }
}

/// The predicted regime with its margin, what was observed, and whether they agree.
fn verdict_lines(m: &ModelFit, lines: &mut Ranked<'static>, theme: &Theme) {
    let g = theme.glyphs;
    lines.push((
        8,
        Line::from(vec![
            Span::styled("predicted ", theme.dim),
            Span::styled(g.text(&m.verdict), theme.text),
        ]),
    ));
    lines.push((
        7,
        Line::from(vec![
            Span::styled("observed ", theme.dim),
            Span::styled(m.observed_name().to_string(), theme.text),
        ]),
    ));
    let verdict = m.agreement();
    lines.push((
        9,
        Line::from(Span::styled(
            g.text(verdict.short_sentence()),
            if verdict.holds() {
                theme.info
            } else {
                theme.error
            },
        )),
    ));
}

/// A model fit's cells in the Fit panel's table, as printed: μ_k ± 2σ (to
/// `decimals`), the RMS, the regime predicted and observed, the verdict.
fn fit_cells(m: &ModelFit, decimals: usize, theme: &Theme) -> [String; 5] {
    let mu = if m.undetermined("mu").is_some() {
        "not determined".to_string()
    } else if m.mu_se.is_finite() {
        pm_tight(m.mu, 2.0 * m.mu_se, decimals)
    } else {
        format!("{:.decimals$}", m.mu)
    };
    let rms = match m.fitted_to {
        "positions" => format!("{:.2}", show_small(m.rms, Dimension::Length)),
        _ => format!("{:.3} m/s", m.rms),
    };
    [
        mu,
        rms,
        m.regime_predicted.name().into(),
        m.observed_name().into(),
        m.agreement().word().into(),
    ]
    .map(|c| theme.glyphs.text(&c))
}

/// The model fit of a position track beside the same model fitted to its derived
/// velocities: a table of two columns where the panel holds both at the widths they
/// print; else the position fit (the one to quote) alone, and a line for the other.
fn both_fits(v: &ModelFit, p: &ModelFit, width: usize, lines: &mut Ranked<'static>, theme: &Theme) {
    let g = theme.glyphs;
    let len = |s: &str| s.chars().count();
    let mu_label = g.text(&format!("{}_k 2{}", g.mu, if g.ascii { "s" } else { "σ" }));
    let labels = [mu_label.as_str(), "RMS", "predicted", "observed", "verdict"];
    let head = labels.iter().map(|l| len(l)).max().unwrap_or(0) + 1;
    let cells = |m: &ModelFit, decimals: usize| fit_cells(m, decimals, theme);
    // Each column one space wider than its widest cell; fewer decimals before fewer
    // columns.
    let col_of =
        |c: &[String], title: &str| c.iter().map(|s| len(s)).max().unwrap_or(0).max(len(title)) + 1;
    let two = [4, 3].into_iter().find_map(|d| {
        let (cv, cp) = (cells(v, d), cells(p, d));
        let (wv, wp) = (col_of(&cv, "velocities"), col_of(&cp, "positions"));
        (head + wv + wp <= width).then_some((cv, cp, wv, wp))
    });
    let model = g.text(&model_name(&p.model, theme));
    // Priorities: μ_k and whether the fit agrees with what was seen stay on the
    // smallest screen; the note on which ± to quote goes first.
    let ranks = [9, 5, 8, 7, 9];
    match two {
        Some((cv, cp, wv, wp)) => {
            let head = width - wv - wp;
            let row = |name: &str, a: &str, b: &str| format!("{name:<head$}{a:>wv$}{b:>wp$}");
            let title = if len(&model) < head {
                row(&model, "velocities", "positions")
            } else {
                lines.push((6, Line::from(Span::styled(model.clone(), theme.title))));
                row("", "velocities", "positions")
            };
            // The columns' heads stay while their cells do.
            lines.push((9, Line::from(Span::styled(title, theme.title))));
            for (i, label) in labels.iter().enumerate() {
                let (a, b) = (cv.get(i), cp.get(i));
                let text = row(label, a.map_or("", |s| s), b.map_or("", |s| s));
                lines.push((ranks[i], Line::from(Span::styled(text, theme.text))));
            }
        }
        None => {
            let cp = cells(p, 4);
            let cp = if head + col_of(&cp, "") <= width {
                cp
            } else {
                cells(p, 3)
            };
            lines.push((
                9,
                Line::from(Span::styled(format!("{model}, positions"), theme.title)),
            ));
            for (i, label) in labels.iter().enumerate() {
                let value = cp.get(i).map_or("", |s| s);
                lines.push((
                    ranks[i],
                    Line::from(vec![
                        Span::styled(format!("{label:<head$}"), theme.dim),
                        Span::styled(value.to_string(), theme.text),
                    ]),
                ));
            }
            // The other fit's μ_k and verdict stay beside the position fit's rows.
            let cv = cells(v, 3);
            lines.push((
                8,
                Line::from(vec![
                    Span::styled("velocities: ", theme.dim),
                    Span::styled(format!("{} {}", cv[0], cv[4]), theme.text),
                ]),
            ));
        }
    }
    lines.push((
        7,
        Line::from(vec![
            Span::styled("positions: ", theme.dim),
            Span::styled(g.text(&p.verdict), theme.text),
        ]),
    ));
    // Apart, neither fit is one to quote: the tracks are in doubt.
    let (quote, style) = match p.agreement() {
        Agreement::FitsDisagree => (Agreement::FitsDisagree.short_sentence(), theme.error),
        _ => ("the position fit's ± is the one to quote", theme.dim),
    };
    lines.push((4, Line::from(Span::styled(g.text(quote), style))));
}

/// The Fit panel (the fits of the measured series) as a component.
pub struct FitPanel;

impl Component for FitPanel {
    fn render(&self, area: Rect, buf: &mut Buffer, cx: &Ctx<'_>) {
        render(cx.app, area, buf, cx.theme);
    }
}

/// The Fit panel while the outcome is hidden: it names the predicted and observed
/// regimes.
const FIT_WITHHELD: Withheld = Withheld {
    title: "Fit",
    what: "the fit",
};

/// The Fit view: the charts with the fit lines, and the Fit panel beside them.
pub struct FitView;

impl MainView for FitView {
    fn view(&self) -> View {
        View::Fit
    }

    fn prepare(&self, app: &App, cache: &mut ViewCache, chart: Rect, theme: &Theme) -> Prepared {
        super::charts::prepared(app, cache, chart, theme, super::charts::Extras::LineFits)
    }

    fn parts(&self, app: &App) -> Vec<(&'static dyn Component, Place)> {
        let hide = app.hidden();
        match (hide.derived(), app.charts().energy()) {
            (true, true) => vec![
                (&ENERGY_WITHHELD, Place::Chart),
                (&FIT_WITHHELD, Place::Side),
            ],
            (true, false) => vec![(&ChartPanel, Place::Chart), (&FIT_WITHHELD, Place::Side)],
            (false, _) => vec![(&ChartPanel, Place::Chart), (&FitPanel, Place::Side)],
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::tui::theme::Glyphs;

    /// The lines of the two fits' table, as text.
    fn both(v: &ModelFit, p: &ModelFit) -> Vec<String> {
        let theme = Theme::new(Glyphs::new(false), true);
        let mut lines: Ranked<'static> = Vec::new();
        both_fits(v, p, 60, &mut lines, &theme);
        lines.iter().map(|(_, l)| l.to_string()).collect()
    }

    #[test]
    fn disagreeing_fits_are_no_fit_to_quote() {
        let v = ModelFit {
            fitted_to: "velocities",
            mu: 0.162,
            ..fit::blank_fit()
        };
        let p = ModelFit {
            fitted_to: "positions",
            mu: 0.131,
            ..fit::blank_fit()
        };
        let agreeing = both(&v, &p).join("\n");
        assert!(
            agreeing.contains("the position fit's ± is the one to quote"),
            "{agreeing}"
        );
        let apart = Some((0.131, 0.162));
        let (v, p) = (
            ModelFit {
                fits_disagree: apart,
                ..v
            },
            ModelFit {
                fits_disagree: apart,
                ..p
            },
        );
        let text = both(&v, &p).join("\n");
        assert!(!text.contains("one to quote"), "{text}");
        assert!(text.contains("no verdict: x and v fits disagree"), "{text}");
        assert!(text.contains("FITS DISAGREE"), "{text}");
    }

    /// The header counts the models left out of the choice by their reason.
    #[test]
    fn the_models_left_out_are_counted_by_their_reason() {
        let model = |values: &[(&'static str, f64)], weighed: bool| {
            let names: Vec<(&'static str, bool)> = values.iter().map(|v| (v.0, true)).collect();
            let mut c = fit::blank_candidate(&names, 0.0);
            for (e, v) in c.parameters.iter_mut().zip(values) {
                e.value = v.1;
            }
            c.weighed = weighed;
            c
        };
        let named = model(&[("mu", 0.17)], true);
        let regime = model(&[("mu", 0.17), ("restitution", 0.9)], false);
        let resisted = model(&[("mu", 0.062), ("rolling_resistance", 0.116)], false);
        assert_eq!(left_out(std::slice::from_ref(&named)), " (by BIC)");
        assert_eq!(
            left_out(&[named.clone(), regime.clone()]),
            " (by BIC; 1 left out: they predict a regime the data do not show)"
        );
        assert_eq!(
            left_out(&[named.clone(), resisted.clone()]),
            " (by BIC; 1 left out: c_rr over their μ_k)"
        );
        assert_eq!(
            left_out(&[named, regime, resisted]),
            " (by BIC; 2 left out: a regime the data do not show, or c_rr over their μ_k)"
        );
    }
}
