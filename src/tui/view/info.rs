//! The info panel: the regime and why, the paper's derived quantities, the impact
//! series, and the energy split at the current time (which always adds up).

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::text::{Line, Span};
use ratatui::widgets::Widget;

use super::{Ranked, block, by_priority, draw_lines};
use crate::input::units::{Dimension, show, significant};
use crate::physics::story::After;
use crate::tui::app::App;
use crate::tui::theme::Theme;

pub fn render(app: &App, area: Rect, buf: &mut Buffer, theme: &Theme) {
    let g = theme.glyphs;
    let d = &app.lab.derived;
    let sol = &app.lab.solution;
    let blk = block(" Why ", theme);
    let inner = blk.inner(area);
    blk.render(area, buf);

    // The headline, the story after the first impact and the verdict (its margin
    // against the measured series' rest band) are the lab's, once per scene.
    let regime = app.lab.story.headline;
    let why = d.why();
    let verdict = &app.lab.story.verdict;
    let story = app.lab.story.after.as_ref();
    let b_star = d.b_star.map_or("none (e < 2/5)".to_string(), |b| {
        format!("{:.2}", show(b, Dimension::Length))
    });
    let label = |s: &str| Span::styled(s.to_string(), theme.dim);
    let value = |s: String| Span::styled(s, theme.text);
    // Priorities (9 most important): what a small screen keeps is the regime and why
    // (with the verdict's margin where the data cannot tell it from rest), the impacts
    // and the energy split; then the derived values (k, r, D, b*), what happens after
    // the first impact (t', v', or how the run ends when the closed forms do not hold),
    // before the rest of the story, the state at the cursor and the forces.
    let mut lines: Ranked = vec![(9, Line::from(Span::styled(regime, theme.title)))];
    // The margin where it changes the reading: a regime the data cannot tell from rest.
    if verdict.indistinguishable_from_rest() {
        // A narrow panel (80 columns) says it in two rows rather than three, so the
        // numbers after the first impact keep their place.
        let margin = match (verdict.v_roll, verdict.band) {
            (Some(v), Some(band)) if inner.width < 40 => {
                format!("v' = {v:+.3} m/s: indistinguishable from rest (band ±{band:.3} m/s)")
            }
            _ => verdict.margin("±"),
        };
        lines.push((8, Line::from(value(g.text(&margin)))));
    }
    // The paper's criterion, where the run does otherwise (the reason is its reason).
    if let Some(note) = story::criterion_note(sol, d) {
        lines.push((8, Line::from(value(note))));
    }
    lines.extend([
        (8, Line::from(value(why))),
        (
            6,
            Line::from(vec![
                label("k "),
                value(format!("{:.4}", d.k)),
                label("  r "),
                value(format!("{:.3}", show(d.r, Dimension::Length))),
                label("  D "),
                value(format!("{:.3}", d.d)),
                label("  b* "),
                value(b_star),
            ]),
        ),
    ]);
    if let Some(After::Interrupted(i)) = &story {
        // The closed forms do not describe this run: say what it does instead.
        // How the run ends (the last clause) outranks how it gets there.
        let clauses = i.clauses(g.infinity);
        let last = clauses.len().saturating_sub(1);
        for (n, clause) in clauses.into_iter().enumerate() {
            let head = if n == 0 { "left ball: " } else { "" };
            lines.push((
                if n == last { 6 } else { 5 },
                Line::from(vec![label(head), value(g.text(&clause))]),
            ));
        }
    } else if let Some(rec) = d.left_after_impact {
        lines.push((
            6,
            Line::from(vec![
                label("t' "),
                value(format!("{:.4} s", rec.t_roll)),
                label("  v' "),
                value(format!("{:.4} m/s", rec.v_roll)),
                label("  x' "),
                value(format!("{:.2}", show(rec.x_roll, Dimension::Length))),
            ]),
        ));
        let crossing = match (rec.t_pure_gliding, rec.t_pure_slipping) {
            (Some(t), _) => format!("pure gliding t_r {t:.4} s"),
            (_, Some(t)) => format!("pure slipping t_t {t:.4} s"),
            _ => "no pure gliding or slipping".to_string(),
        };
        lines.push((3, Line::from(vec![label("left ball: "), value(crossing)])));
        lines.push((
            2,
            Line::from(vec![
                label("a_cm "),
                value(format!("{} m/s{}", significant(rec.a_cm, 4), g.squared)),
                label("  a_t "),
                value(format!("{} m/s{}", significant(rec.a_t, 4), g.squared)),
            ]),
        ));
    }
    let f = d.forces;
    lines.push((
        1,
        Line::from(vec![
            label("|N_A| "),
            value(format!("{:.3} N", f.normal_a.norm())),
            label("  F_net "),
            value(format!("{:.3} N", f.net.norm())),
        ]),
    ));
    lines.push((
        0,
        Line::from(vec![
            label(&format!("{}_net ", g.tau)),
            value(format!("{:.5} N m", f.torque.norm())),
            label(&format!(" = {}_k m g R", g.mu)),
        ]),
    ));
    let zeno = sol
        .accumulation
        .map_or(String::new(), |t| format!("  T{} {t:.4} s", g.infinity));
    lines.push((
        8,
        Line::from(vec![
            label("impacts "),
            value(format!("{}", sol.impacts)),
            value(zeno),
        ]),
    ));
    // How far the model is from the measured points, if there are any.
    match app.lab.data_rms {
        Some((rms_cm, Some(rms_t))) => lines.push((
            5,
            Line::from(vec![
                label("data: RMS residual v_cm "),
                value(format!("{rms_cm:.3}")),
                label(", v_t "),
                value(format!("{rms_t:.3} m/s")),
            ]),
        )),
        // A track without a rim mark: no v_t to compare with, said in words.
        Some((rms_cm, None)) => lines.push((
            5,
            Line::from(vec![
                label("data: RMS v_cm "),
                value(format!("{rms_cm:.3} m/s")),
                label(", v_t not measured"),
            ]),
        )),
        None => {}
    }
    // The state at the cursor, per ball.
    let now = sol.at(app.t);
    let seg = sol.segment_at(app.t);
    for (name, st, phase) in [
        ("left ", now.left, seg.phase[0]),
        ("right", now.right, seg.phase[1]),
    ] {
        lines.push((
            5,
            Line::from(vec![
                label(&format!("{name} ")),
                value(format!("v {:+.3}  u {:+.3} m/s  ", st.v, st.u)),
                label(phase.name()),
            ]),
        ));
    }
    // Whole percentages by largest remainder, so the five shares add up to 100.
    let e = sol.energy_at(app.t);
    let shares = percentages(&[
        e.translational,
        e.rotational,
        e.lost.friction,
        e.lost.impacts,
        e.lost.rolling_resistance,
    ]);
    let pct = |i: usize| value(format!("{}%", shares[i]));
    if inner.width >= 40 {
        lines.push((
            7,
            Line::from(vec![
                label("energy "),
                value(format!("{:.4} J", e.total())),
                label(" = trans "),
                pct(0),
                label(" + rot "),
                pct(1),
            ]),
        ));
        lines.push((
            7,
            Line::from(vec![
                label("  + friction "),
                pct(2),
                label(" + impacts "),
                pct(3),
                label(" + c_rr "),
                pct(4),
            ]),
        ));
    } else {
        // Narrow: three short lines rather than two that wrap mid-sum.
        lines.push((
            7,
            Line::from(vec![
                label("energy "),
                value(format!("{:.4} J", e.total())),
                label(" = trans "),
                pct(0),
            ]),
        ));
        lines.push((
            7,
            Line::from(vec![
                label("  + rot "),
                pct(1),
                label(" + friction "),
                pct(2),
            ]),
        ));
        lines.push((
            7,
            Line::from(vec![
                label("  + impacts "),
                pct(3),
                label(" + c_rr "),
                pct(4),
            ]),
        ));
    }
    draw_lines(by_priority(lines, inner), inner, buf);
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

#[cfg(test)]
mod tests {
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
