//! The info panel: the regime and why, the paper's derived quantities, the impact
//! series, and the energy split at the current time (which always adds up).

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::text::{Line, Span};
use ratatui::widgets::Widget;

use super::panel::{NO_BREAK, Ranked, block, by_priority, draw_lines, unbroken};
use crate::physics::derived::{Derived, Summary};
use crate::physics::story::After;
use crate::settings::units::{Dimension, show, sig_figs};
use crate::tui::app::App;
use crate::tui::component::{Component, Ctx};
use crate::tui::theme::Theme;

/// A label (dimmed) and a value (plain): the two kinds of text of the panel.
fn label(s: &str, theme: &Theme) -> Span<'static> {
    Span::styled(s.to_string(), theme.dim)
}

fn value(s: String, theme: &Theme) -> Span<'static> {
    Span::styled(s, theme.text)
}

/// `name value` kept on one row when the panel wraps (`b* 4.26 cm`, never `b*` at a
/// row's end and `4.26 cm` on the next): `name`'s leading spaces still break.
fn pair(name: &str, v: String, theme: &Theme) -> [Span<'static>; 2] {
    [
        label(&format!("{name}{NO_BREAK}"), theme),
        value(unbroken(&v), theme),
    ]
}

pub fn render(app: &App, area: Rect, buf: &mut Buffer, theme: &Theme) {
    let blk = block(" Why ", theme);
    let inner = blk.inner(area);
    blk.render(area, buf);
    // Priorities (9 most important): what a small screen keeps is the regime and why
    // (with the verdict's margin where the data cannot tell it from rest), the impacts
    // and the energy split; then the derived values (k, r, D, b*), what happens after
    // the first impact (t', v', or how the run ends when the closed forms do not hold),
    // before the rest of the story, the state at the cursor and the forces.
    // With b hidden (`B`), nothing here may give it or the outcome away: only the
    // state at the cursor, which the animation shows anyway.
    if app.hidden().derived() {
        let note = theme.glyphs.text(if app.hide().b() {
            "b hidden: predict from the picture; B shows b and why"
        } else {
            "predict first: why shows once the outcome does"
        });
        let mut lines: Ranked = vec![(9, Line::from(Span::styled(note, theme.title)))];
        lines.extend(cursor_lines(app, theme));
        draw_lines(by_priority(lines, inner), inner, buf);
        return;
    }
    let mut lines = regime_lines(app, inner.width, theme);
    // A/B: both runs' key numbers side by side, right under the headline.
    lines.splice(1..1, ab_lines(app, inner.width, theme));
    lines.extend(after_impact_lines(app, theme));
    lines.extend(force_lines(app, theme));
    lines.extend(impact_and_data_lines(app, theme));
    lines.extend(cursor_lines(app, theme));
    lines.extend(energy_lines(app, inner.width, theme));
    draw_lines(by_priority(lines, inner), inner, buf);
}

/// The regime and why, the verdict's margin where the data cannot tell the regime from
/// rest, and the derived values k, r, D, b*.
fn regime_lines(app: &App, width: u16, theme: &Theme) -> Ranked<'static> {
    let g = theme.glyphs;
    let d = &app.lab.derived;
    // The headline and the verdict (its margin against the measured series' rest band)
    // are the lab's, once per scene.
    let regime = app.lab.story.headline.clone();
    let verdict = &app.lab.story.verdict;
    let b_star = d.b_star.map_or("none (e < 2/5)".to_string(), |b| {
        format!("{:.2}", show(b, Dimension::Length))
    });
    let mut lines: Ranked = vec![(9, Line::from(Span::styled(regime, theme.title)))];
    // The margin where it changes the reading: a regime the data cannot tell from rest.
    if verdict.indistinguishable_from_rest() {
        // A narrow panel (80 columns) says it in two rows rather than three, so the
        // numbers after the first impact keep their place.
        let margin = match (verdict.v_roll, verdict.band) {
            (Some(v), Some(band)) if width < 40 => {
                format!("v' = {v:+.3} m/s: indistinguishable from rest (band ±{band:.3} m/s)")
            }
            _ => verdict.margin("±"),
        };
        lines.push((8, Line::from(value(g.text(&margin), theme))));
    }
    // The paper's criterion, where the run does otherwise (the reason is its reason).
    if let Some(note) = &app.lab.story.criterion_note {
        lines.push((8, Line::from(value(note.clone(), theme))));
    }
    lines.extend([
        (8, Line::from(value(d.why(), theme))),
        (
            6,
            Line::from(
                [
                    pair("k", format!("{:.4}", d.k), theme),
                    pair("  r", format!("{:.3}", show(d.r, Dimension::Length)), theme),
                    pair("  D", format!("{:.3}", d.d), theme),
                    pair("  b*", b_star, theme),
                ]
                .concat(),
            ),
        ),
    ]);
    lines
}

/// A speed to `decimals` places, or to two significant digits where those places
/// would round a speed that is not zero to `0.000` (a pair that comes back barely,
/// v' = 2e-5 m/s, must not read as one at rest).
pub(crate) fn speed_shown(v: f64, decimals: usize, signed: bool) -> String {
    let half_place = 0.5 * 10f64.powi(-(decimals as i32));
    let text = if v != 0.0 && v.abs() < half_place {
        crate::settings::units::sig_figs(v, 2)
    } else {
        crate::settings::units::fixed(v, decimals)
    };
    if signed && !text.starts_with('-') {
        format!("+{text}")
    } else {
        text
    }
}

/// A run's key numbers for the A/B table: outcome, t' and v' of the left ball (when
/// the closed forms hold), impacts, T∞, the share of the energy lost by the end.
fn key_numbers(derived: &Derived, summary: &Summary, theme: &Theme) -> [String; 6] {
    let after = derived.left_after_impact;
    let none = || "-".to_string();
    let lost = summary.energy_end.lost.total() / summary.energy_end.total();
    [
        summary.outcome.name().to_string(),
        after.map_or_else(none, |a| format!("{:.4} s", a.t_roll)),
        after.map_or_else(none, |a| format!("{} m/s", speed_shown(a.v_roll, 3, true))),
        summary.impacts.to_string(),
        summary
            .accumulation_time
            .map_or_else(none, |t| format!("{t:.4} s")),
        if lost.is_finite() {
            format!("{:.0} %", 100.0 * lost)
        } else {
            none()
        },
    ]
    .map(|s| theme.glyphs.text(&s))
}

/// With a run pinned: its key numbers beside the current run's, one row per quantity.
fn ab_lines(app: &App, width: u16, theme: &Theme) -> Ranked<'static> {
    let Some(pinned) = &app.lab.pinned else {
        return Vec::new();
    };
    let g = theme.glyphs;
    let a = key_numbers(&pinned.derived, &pinned.summary, theme);
    let b = key_numbers(&app.lab.derived, &app.lab.summary, theme);
    let names = [
        "outcome".to_string(),
        "t'".to_string(),
        "v'".to_string(),
        "impacts".to_string(),
        format!("T{}", g.infinity),
        "E lost".to_string(),
    ];
    // Label column, then the two runs in equal columns over the rest of the row.
    let col = usize::from(width).saturating_sub(9) / 2;
    let row = |name: &str, x: &str, y: &str, style| {
        Line::from(vec![
            label(&format!("{name:<9}"), theme),
            Span::styled(format!("{x:<col$}"), style),
            Span::styled(y.to_string(), style),
        ])
    };
    let mut lines: Ranked = vec![(9, row("A/B", "pinned", "now", theme.title))];
    for (i, name) in names.iter().enumerate() {
        // The outcome never goes; the energy lost before the other numbers.
        let priority = match i {
            0 => 9,
            5 => 7,
            _ => 8,
        };
        lines.push((priority, row(name, &a[i], &b[i], theme.text)));
    }
    lines
}

/// What the left ball does after the first impact: the closed forms (t', v', x', the
/// crossing, the accelerations), or the run's own story where they do not hold.
fn after_impact_lines(app: &App, theme: &Theme) -> Ranked<'static> {
    let g = theme.glyphs;
    let d = &app.lab.derived;
    let mut lines: Ranked = Vec::new();
    if let Some(After::Interrupted(i)) = app.lab.story.after.as_ref() {
        // The closed forms do not describe this run: say what it does instead.
        // How the run ends (the last clause) outranks how it gets there.
        let clauses = i.clauses(g.infinity);
        let last = clauses.len().saturating_sub(1);
        for (n, clause) in clauses.into_iter().enumerate() {
            let head = if n == 0 { "left ball: " } else { "" };
            lines.push((
                if n == last { 6 } else { 5 },
                Line::from(vec![label(head, theme), value(g.text(&clause), theme)]),
            ));
        }
    } else if let Some(rec) = d.left_after_impact {
        lines.push((
            6,
            Line::from(
                [
                    pair("t'", format!("{:.4} s", rec.t_roll), theme),
                    pair(
                        "  v'",
                        format!("{} m/s", speed_shown(rec.v_roll, 4, false)),
                        theme,
                    ),
                    pair(
                        "  x'",
                        format!("{:.2}", show(rec.x_roll, Dimension::Length)),
                        theme,
                    ),
                ]
                .concat(),
            ),
        ));
        let crossing = match (rec.t_pure_gliding, rec.t_pure_slipping) {
            (Some(t), _) => format!("pure gliding t_r {t:.4} s"),
            (_, Some(t)) => format!("pure slipping t_t {t:.4} s"),
            _ => "no pure gliding or slipping".to_string(),
        };
        lines.push((
            3,
            Line::from(vec![label("left ball: ", theme), value(crossing, theme)]),
        ));
        let accel = |a: f64| format!("{} m/s{}", sig_figs(a, 4), g.squared);
        lines.push((
            2,
            Line::from(
                [
                    pair("a_cm", accel(rec.a_cm), theme),
                    pair("  a_t", accel(rec.a_t), theme),
                ]
                .concat(),
            ),
        ));
    }
    lines
}

/// " (m assumed)" after a number the mass enters while it is assumed (the user's data
/// do not measure it), else nothing.
fn assumed(app: &App) -> &'static str {
    if app.lab.settings().mass_assumed() {
        " (m assumed)"
    } else {
        ""
    }
}

/// The contact force, the net force and the net torque.
fn force_lines(app: &App, theme: &Theme) -> Ranked<'static> {
    let g = theme.glyphs;
    let f = app.lab.derived.forces;
    vec![
        (
            1,
            Line::from(
                [
                    &pair(
                        "|N_A|",
                        format!("{} N", sig_figs(f.normal_a.norm(), 4)),
                        theme,
                    )[..],
                    &pair("  F_net", format!("{} N", sig_figs(f.net.norm(), 4)), theme),
                    &[label(assumed(app), theme)],
                ]
                .concat(),
            ),
        ),
        (
            0,
            Line::from(vec![
                label(&format!("{}_net ", g.tau), theme),
                value(format!("{} N m", sig_figs(f.torque.norm(), 4)), theme),
                label(&format!(" = {}_k m g R", g.mu), theme),
                label(assumed(app), theme),
            ]),
        ),
    ]
}

/// The impacts (and where they accumulate), and how far the model is from the
/// measured points if there are any.
fn impact_and_data_lines(app: &App, theme: &Theme) -> Ranked<'static> {
    let sol = &app.lab.solution;
    let zeno = sol.accumulation.map_or(String::new(), |t| {
        format!(
            "  {}",
            unbroken(&format!("T{} {t:.4} s", theme.glyphs.infinity))
        )
    });
    let mut lines: Ranked = Vec::new();
    // With a run pinned the A/B table gives them, for both runs.
    if app.lab.pinned.is_none() {
        lines.push((
            8,
            Line::from(
                [
                    &pair("impacts", format!("{}", sol.impacts), theme)[..],
                    &[value(zeno, theme)],
                ]
                .concat(),
            ),
        ));
    }
    match app.lab.data_rms {
        Some((rms_cm, Some(rms_t))) => lines.push((
            5,
            Line::from(
                [
                    pair("data: RMS residual v_cm", format!("{rms_cm:.3}"), theme),
                    pair(", v_t", format!("{rms_t:.3} m/s"), theme),
                ]
                .concat(),
            ),
        )),
        // A track without a rim mark: no v_t to compare with, said in words.
        Some((rms_cm, None)) => lines.push((
            5,
            Line::from(
                [
                    &pair("data: RMS v_cm", format!("{rms_cm:.3} m/s"), theme)[..],
                    &[label(", v_t not measured", theme)],
                ]
                .concat(),
            ),
        )),
        None => {}
    }
    // Data of another groove are never shown without saying so.
    if let Some(other) = &app.lab.other_groove {
        lines.push((6, Line::from(Span::styled(other.describe(), theme.error))));
    }
    lines
}

/// The state at the cursor, per ball.
fn cursor_lines(app: &App, theme: &Theme) -> Ranked<'static> {
    let sol = &app.lab.solution;
    let now = sol.at(app.t);
    let seg = sol.segment_at(app.t);
    [
        ("left ", now.left, seg.phase[0]),
        ("right", now.right, seg.phase[1]),
    ]
    .into_iter()
    .map(|(name, st, phase)| {
        (
            5,
            Line::from(vec![
                label(&format!("{name} "), theme),
                value(format!("v {:+.3}  u {:+.3} m/s  ", st.v, st.u), theme),
                label(phase.name(), theme),
            ]),
        )
    })
    .collect()
}

/// The energy at the cursor and where it is: two lines, or three short ones in a
/// narrow panel rather than two that wrap mid-sum.
fn energy_lines(app: &App, width: u16, theme: &Theme) -> Ranked<'static> {
    // Whole percentages by largest remainder, so the five shares add up to 100.
    let e = app.lab.solution.energy_at(app.t);
    let shares = percentages(&[
        e.translational,
        e.rotational,
        e.lost.friction,
        e.lost.impacts,
        e.lost.rolling_resistance,
    ]);
    let pct = |i: usize| value(format!("{}%", shares[i]), theme);
    let total = || {
        value(
            format!(
                "{} J{}",
                crate::settings::units::fixed(e.total(), 4),
                assumed(app)
            ),
            theme,
        )
    };
    let first = vec![
        label("energy ", theme),
        total(),
        label(" = trans ", theme),
        pct(0),
        label(" + rot ", theme),
        pct(1),
    ];
    // Two rows where the first fits (with "(m assumed)" it may not at 40 columns).
    let fits = Line::from(first.clone()).width() <= usize::from(width);
    let rows: Vec<Vec<Span>> = if fits {
        vec![
            first,
            vec![
                label("  + friction ", theme),
                pct(2),
                label(" + impacts ", theme),
                pct(3),
                label(" + c_rr ", theme),
                pct(4),
            ],
        ]
    } else {
        vec![
            vec![
                label("energy ", theme),
                total(),
                label(" = trans ", theme),
                pct(0),
            ],
            vec![
                label("  + rot ", theme),
                pct(1),
                label(" + friction ", theme),
                pct(2),
            ],
            vec![
                label("  + impacts ", theme),
                pct(3),
                label(" + c_rr ", theme),
                pct(4),
            ],
        ]
    };
    rows.into_iter().map(|r| (7, Line::from(r))).collect()
}

/// Whole-number percentages of `parts` that sum to exactly 100 (largest remainder).
pub fn percentages(parts: &[f64]) -> Vec<u32> {
    // Shares of the non-negative finite parts only: a negative or overflowing part
    // once made shares beyond u32 whose sum overflowed.
    let part = |p: f64| if p.is_finite() { p.max(0.0) } else { 0.0 };
    let total: f64 = parts.iter().map(|&p| part(p)).sum();
    if !(total > 0.0 && total.is_finite()) {
        return vec![0; parts.len()];
    }
    let exact: Vec<f64> = parts
        .iter()
        .map(|&p| (100.0 * (part(p) / total)).min(100.0))
        .collect();
    let mut out: Vec<u32> = exact.iter().map(|x| x.floor() as u32).collect();
    let missing = 100u32.saturating_sub(out.iter().sum());
    let mut order: Vec<usize> = (0..parts.len()).collect();
    order.sort_by(|&a, &b| (exact[b] - exact[b].floor()).total_cmp(&(exact[a] - exact[a].floor())));
    for &i in order.iter().take(missing as usize) {
        out[i] += 1;
    }
    out
}

/// The why panel (what happens and why) as a component.
pub struct Why;

impl Component for Why {
    fn render(&self, area: Rect, buf: &mut Buffer, cx: &Ctx<'_>) {
        render(cx.app, area, buf, cx.theme);
    }
}

#[cfg(test)]
mod tests {
    #[test]
    fn a_slow_speed_that_is_not_zero_never_reads_zero() {
        use super::speed_shown;
        assert_eq!(speed_shown(2e-5, 3, true), "+2.0e-5");
        assert_eq!(speed_shown(-0.00031, 4, false), "-0.0003");
        assert_eq!(speed_shown(-0.00003, 4, false), "-3.0e-5");
        assert_eq!(speed_shown(0.0, 3, true), "+0.000");
        assert!(speed_shown(-1e-19, 4, false).parse::<f64>().unwrap() < 0.0);
        assert_eq!(speed_shown(0.1234, 3, true), "+0.123");
    }

    use super::percentages;

    #[test]
    fn shares_always_add_up_to_100() {
        for parts in [
            [1.0, 1.0, 1.0, 0.0, 0.0],
            [0.333, 0.333, 0.334, 1e-9, 0.0],
            [5.0, 0.0, 0.0, 0.0, 0.0],
        ] {
            assert_eq!(percentages(&parts).iter().sum::<u32>(), 100, "{parts:?}");
        }
        assert_eq!(percentages(&[0.0; 5]), vec![0; 5]);
    }

    #[test]
    fn overflowing_or_negative_energies_do_not_overflow_the_shares() {
        // A 1e308 kg ball once gave shares past u32 whose sum overflowed.
        for parts in [
            [1e308, 1e308, 1.0, 0.0, 0.0],
            [f64::INFINITY, 1.0, f64::NAN, 0.0, 0.0],
            [1e300, -1e300 + 1e285, 1e-300, 0.0, 0.0],
            [f64::MAX, f64::MAX, f64::MAX, f64::MAX, f64::MAX],
        ] {
            let shares = percentages(&parts);
            let sum: u32 = shares.iter().sum();
            assert!(sum == 100 || sum == 0, "{parts:?}: {shares:?}");
        }
    }
}
