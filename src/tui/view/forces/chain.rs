//! The Forces view's chain: b → k → |N| → |F| → F_net → a_cm; τ_net → α → a_t; D →
//! the outcome, with ↑/↓ against a pinned run; and the predict–observe–explain lines.

use super::parts::*;
use crate::tui::view::predict::{agreement, short_answer};

/// The two chains' items for the ball shown: b → k → |N| → |F| → F_net → |a_cm| and
/// τ_net → |α| → |a_t|, each with its unit and, with a run pinned, ↑/↓/= against it
/// (an item and its arrow are never split), `?` where they would give away what b or
/// a `pending` prediction hides. `compact` drops the magnitude bars.
pub(super) fn chains(app: &App, pending: bool, compact: bool, theme: &Theme) -> [Vec<String>; 2] {
    let s = app.lab.derived.sliding[app.forces().ball()];
    let pinned = pinned_sliding(app);
    let hide = app.hidden().forces();
    // While a prediction is pending the two accelerations stay hidden too: their
    // ratio is D, the answer.
    let hide_a = hide || pending;
    let was = |f: fn(&Sliding) -> f64| pinned.map(|(p, _)| f(&p));
    let item = |label: &str, v: f64, unit: &str, hidden: bool, was: Option<f64>| {
        let label = if compact {
            label.trim_matches('|')
        } else {
            label
        };
        let tr = if hidden {
            String::new()
        } else {
            trend(v, was, theme)
        };
        format!("{label} {}{unit}{tr}", num(v, hidden))
    };
    let b = if app.hide().b() {
        "b ?".to_string()
    } else {
        format!(
            "b {:.2}{}",
            show(app.lab.scene.width, LENGTH),
            trend(app.lab.scene.width, pinned.map(|p| p.1), theme)
        )
    };
    let mut translation = vec![b, item("k", s.k, "", hide, was(|p| p.k))];
    if app.lab.settings().mass_assumed() {
        // The forces scale with m, which the user's data do not measure.
        let m = app.lab.scene.left.mass;
        translation.push(format!(
            "m {} assumed",
            crate::settings::units::show(m, Dimension::Mass)
        ));
    }
    translation.extend([
        item("|N|", s.normal, " N", hide, was(|p| p.normal)),
        item("|F|", s.friction, " N", hide, was(|p| p.friction)),
        item("F_net", s.net_force, " N", hide, was(|p| p.net_force)),
        item("|a_cm|", s.a_cm, " m/s²", hide_a, was(|p| p.a_cm)),
    ]);
    let rotation = vec![
        item(
            "τ_net",
            s.net_torque,
            " N m (any b)",
            false,
            was(|p| p.net_torque),
        ),
        item("|α|", s.alpha, " rad/s²", false, was(|p| p.alpha)),
        item("|a_t|", s.a_t, " m/s²", hide_a, was(|p| p.a_t)),
    ];
    [translation, rotation].map(|c| c.iter().map(|i| theme.glyphs.text(i)).collect())
}

/// D and what it decides: `?` while the prediction is pending or b is hidden.
pub(super) fn outcome_items(app: &App, pending: bool, compact: bool, theme: &Theme) -> Vec<String> {
    let s = app.lab.derived.sliding[app.forces().ball()];
    let d = if compact {
        "D = a_t/a_cm"
    } else {
        "D = |a_t|/|a_cm|"
    };
    let regime = app.lab.derived.regime.name().to_string();
    let items = if pending {
        vec![format!("{d} = ?"), "what will the balls do?".to_string()]
    } else if app.hidden().derived() {
        vec![format!("{d} = ?"), regime]
    } else {
        let was = pinned_sliding(app).map(|(p, _)| p.d);
        let tr = trend(s.d, was, theme);
        vec![format!("{d} = {}{tr}", sig_figs(s.d, 3)), regime]
    };
    items.iter().map(|i| theme.glyphs.text(i)).collect()
}

/// `items` joined by `arrow` into rows of at most `width` columns, broken only before
/// an arrow (the next row starts with it), so that a value, its unit and its ↑/↓ stay
/// together.
pub(super) fn chain_rows(items: &[String], arrow: &str, width: usize) -> Vec<String> {
    let len = |s: &str| s.chars().count();
    let lead = arrow.trim_start();
    let mut rows: Vec<String> = Vec::new();
    for item in items {
        match rows.last_mut() {
            None => rows.push(item.clone()),
            Some(row) if len(row) + len(arrow) + len(item) <= width => {
                row.push_str(arrow);
                row.push_str(item);
            }
            Some(_) => rows.push(format!("{lead}{item}")),
        }
    }
    rows
}

/// The chain's block: its own, or (`joined`) one whose top border meets the side
/// view's sides and whose bottom says what the side view's signs mean.
pub(super) fn chain_block(
    title: (&str, &str),
    area: Rect,
    joined: bool,
    theme: &Theme,
) -> Block<'static> {
    let blk = block(title_of(&[title.0, title.1], area, theme), theme);
    if !joined {
        return blk;
    }
    let (left, right) = if theme.glyphs.ascii {
        ("+", "+")
    } else {
        ("├", "┤")
    };
    blk.border_set(border::Set {
        top_left: left,
        top_right: right,
        ..theme.glyphs.border
    })
    .title_bottom(side_footer(area, theme))
}

pub(super) fn chain_view(app: &App, area: Rect, joined: bool, buf: &mut Buffer, theme: &Theme) {
    let g = theme.glyphs;
    let prediction = app.prediction().filter(|p| p.scene == app.lab.scene);
    // While the question is asked, and until the outcome shows, the chain keeps D and
    // the outcome to itself: the answer must not stand beside the question.
    let pending = app.hidden().pending();
    let title = if prediction.is_some() {
        (
            "Forces: predict, observe, explain",
            "predict, observe, explain",
        )
    } else {
        (
            "Forces: cause and effect (while sliding)",
            "cause and effect, while sliding",
        )
    };
    let blk = chain_block(title, area, joined, theme);
    let inner = blk.inner(area);
    blk.render(area, buf);
    if inner.width < 10 || inner.height < 1 {
        return;
    }
    let width = usize::from(inner.width);
    // A narrow panel drops the magnitude bars (|N| → N); every number keeps its unit.
    let compact = inner.width < 60;
    let arrow = g.text(" → ");
    let rows = |items: &[String], style: Style| -> Vec<Line<'static>> {
        chain_rows(items, &arrow, width)
            .into_iter()
            .flat_map(|row| wrap(Line::styled(row, style), width))
            .collect()
    };
    let [translation, rotation] = chains(app, pending, compact, theme);
    let outcome = outcome_items(app, pending, compact, theme);
    let mut groups = vec![
        (7, rows(&translation, theme.text)),
        (7, rows(&rotation, theme.left)),
        (
            if prediction.is_some() { 6 } else { 8 },
            rows(&outcome, theme.accent),
        ),
    ];
    let mut ranked: Ranked = Vec::new();
    if !(pending || app.hidden().derived()) && prediction.is_none() {
        ranked.push((
            5,
            Line::styled(g.text(&app.lab.derived.why()), theme.accent),
        ));
    }
    if let Some(p) = prediction {
        ranked.extend(prediction_lines(app, p, pending, theme));
    } else if app.prediction().is_some() {
        ranked.push((
            9,
            Line::styled(
                "the scene changed since the prediction: y asks again",
                theme.dim,
            ),
        ));
    }
    groups.extend(ranked.into_iter().map(|(p, l)| (p, wrap(l, width))));
    draw_lines(rows_by_priority(groups, inner.height), inner, buf);
}

/// What was predicted and, once seen, what happened and why.
pub(super) fn prediction_lines<'a>(
    app: &App,
    p: &Prediction,
    pending: bool,
    theme: &Theme,
) -> Ranked<'a> {
    let g = theme.glyphs;
    let guess = short_answer(p.guess);
    if pending {
        return vec![(
            9,
            Line::styled(
                format!("predicted: {guess}; watch until the outcome shows"),
                theme.info,
            ),
        )];
    }
    let d = &app.lab.derived;
    let verdict = &app.lab.story.verdict;
    let right = verdict.agrees_with(p.guess);
    let (mark, word) = agreement(right);
    let mark = if g.ascii {
        word.to_string()
    } else {
        format!("{mark} {word}")
    };
    let pm = if g.ascii { "+-" } else { "±" };
    // With b hidden, the reason in words: D's value (or v') would give b away.
    let why = match (app.hidden().derived(), d.symmetric, d.regime) {
        (false, ..) | (true, false, _) => format!("{}; {}", d.why(), verdict.text(pm)),
        (true, true, Regime::Depart) => {
            "|a_t| > |a_cm| (D > 1): the translation reverses first".into()
        }
        (true, true, Regime::Rest) => "|a_t| = |a_cm| (D = 1): both stop together".into(),
        (true, true, Regime::Recollide) => {
            "|a_t| < |a_cm| (D < 1): the spin outlasts the translation and rolls them back".into()
        }
    };
    vec![
        (
            9,
            // Each label with its answer, and the mark with its word, on one row when
            // the line wraps (`observed:` ended a row, `right` stood alone on one).
            Line::from(vec![
                Span::styled(
                    format!("{}   ", unbroken(&format!("predicted: {guess}"))),
                    theme.text,
                ),
                Span::styled(
                    g.text(&format!("observed:{NO_BREAK}{}", app.lab.story.headline)),
                    theme.accent,
                ),
                Span::styled(
                    format!("   {}", unbroken(&mark)),
                    if right { theme.info } else { theme.error },
                ),
            ]),
        ),
        (8, Line::styled(g.text(&format!("why: {why}")), theme.text)),
    ]
}
