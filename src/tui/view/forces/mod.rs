//! The Forces view (key `v`): the paper's explanatory figures, live at the cursor's
//! time. Front: the groove's cross-section with the weight, normal and friction forces
//! on one ball and their torques, to scale for the current b. Side: both balls' centre
//! and contact-point velocities, friction and spin, with the motion state named.
//! Chain: b → k → |N| → |F| → F_net → a_cm; τ_net → α → a_t; D → the outcome, with ↑/↓
//! against a pinned run; and the predict–observe–explain panel. It only reads the lab
//! (the per-scene values are in `derived.sliding`) and the solution at the cursor.

mod chain;
mod parts;
mod section;

use parts::*;

use crate::tui::component::{Component, Ctx, MainView, Place};
use crate::tui::vocabulary::View;
use chain::chain_view;
use section::front_view;

pub fn render(app: &App, area: Rect, buf: &mut Buffer, theme: &Theme) {
    // The side view needs a state and v_A per ball (4 rows). On a short panel (80×24)
    // it and the chain share a border, which carries the chain's title, and the chain
    // is wider: the row and the columns saved let both chains and D keep their units.
    let joined = area.height < 20;
    let front_w = if area.width >= 110 || joined { 45 } else { 50 };
    let [front, right] =
        Layout::horizontal([Constraint::Percentage(front_w), Constraint::Min(20)]).areas(area);
    let side_h = if joined { 5 } else { right.height * 55 / 100 };
    let [side, chain] =
        Layout::vertical([Constraint::Length(side_h), Constraint::Min(5)]).areas(right);
    front_view(app, front, buf, theme);
    side_view(app, side, joined, buf, theme);
    chain_view(app, chain, joined, buf, theme);
}

/// The side view; `joined`: its bottom border is the chain's top one (drawn there).
fn side_view(app: &App, area: Rect, joined: bool, buf: &mut Buffer, theme: &Theme) {
    let blk = block(
        title_within("Forces: side view, motion states", area, theme),
        theme,
    );
    let blk = if joined {
        blk.borders(Borders::TOP | Borders::LEFT | Borders::RIGHT)
    } else {
        blk.title_bottom(side_footer(area, theme))
    };
    let inner = blk.inner(area);
    blk.render(area, buf);
    if inner.width < 20 || inner.height < 1 {
        return;
    }
    let ranked = (0..2)
        .flat_map(|ball| ball_rows(app, ball, usize::from(inner.width), theme))
        .collect();
    draw_lines(by_priority(ranked, inner), inner, buf);
}

/// The side view's rows of one ball in a panel `width` columns wide: its motion
/// state, then its velocities, friction and spin as bars (ranked).
fn ball_rows(app: &App, ball: usize, width: usize, theme: &Theme) -> Ranked<'static> {
    let g = theme.glyphs;
    let speed = 2.0 * app.lab.scene.speed_scale();
    // A row: 2 + label 5 + bar + " +0.000 m/s" (11) + where it acts, if room is left.
    let half = (width.saturating_sub(20) / 2).clamp(2, 14);
    let room = width.saturating_sub(2 * half + 19);
    let mut ranked: Ranked = Vec::new();
    let i = instant(&app.lab.solution, ball, app.t);
    let s = app.lab.derived.sliding[ball];
    let style = if ball == 0 { theme.left } else { theme.right };
    let mut state = i.state.name().to_string();
    if i.pressed {
        state += ", pressed";
    }
    if i.accumulating {
        state += " (impacts accumulating)";
    }
    ranked.push((
        9,
        Line::styled(format!("{:<6}{state}", ball_name(ball)), style),
    ));
    let row = |label: &str, value: f64, full: f64, unit: &str, what: &str| {
        let what = if what.chars().count() + 2 <= room {
            what
        } else {
            ""
        };
        g.text(&format!(
            "  {label:<5}{} {:+.3} {unit}  {what}",
            bar(value, full, half, theme),
            // No "-0.000".
            value + 0.0
        ))
    };
    ranked.push((
        5,
        Line::styled(row("v_cm", i.v_cm, speed, "m/s", "at the centre"), style),
    ));
    ranked.push((
        3,
        Line::styled(
            row(
                "v'_A",
                i.v_contact_rel,
                speed,
                "m/s",
                "A, B from the centre",
            ),
            theme.dim,
        ),
    ));
    ranked.push((
        6,
        Line::styled(row("v_A", i.v_contact, speed, "m/s", "at A, B"), theme.text),
    ));
    let kind = if i.kinetic || i.friction == 0.0 {
        "at A and at B"
    } else {
        "at A, B (static)"
    };
    // |F| = μ_k m g / (2k) and r = v_t / ω give k, so D: hidden with the forces.
    let hide = app.hidden().forces();
    let friction = row("F", i.friction, s.friction, "N", kind);
    let friction = if hide && i.friction != 0.0 {
        hide_number(&friction, " N")
    } else {
        friction
    };
    ranked.push((4, Line::styled(friction, theme.accent)));
    let spin = match (i.omega > 0.0, g.ascii) {
        _ if i.omega == 0.0 => "",
        (true, false) => "↻ ",
        (false, false) => "↺ ",
        (true, true) => "(cw) ",
        (false, true) => "(ccw) ",
    };
    ranked.push((
        2,
        Line::styled(
            g.text(&if hide {
                format!("  ω     {spin}? rad/s, v_t {:+.3} m/s", i.v_t)
            } else {
                format!("  ω     {spin}{:+.1} rad/s, v_t {:+.3} m/s", i.omega, i.v_t)
            }),
            theme.dim,
        ),
    ));
    ranked
}

/// `line` with the signed number before `unit` replaced by `?` (a hidden value keeps
/// its row and its arrow's direction).
fn hide_number(line: &str, unit: &str) -> String {
    let Some(end) = line.find(unit) else {
        return line.to_string();
    };
    let start = line[..end].rfind(' ').map_or(0, |i| i + 1);
    format!("{}?{}", &line[..start], &line[end..])
}

/// The Forces view (front, side, chain) as a component.
pub struct ForcesView;

impl Component for ForcesView {
    fn render(&self, area: Rect, buf: &mut Buffer, cx: &Ctx<'_>) {
        render(cx.app, area, buf, cx.theme);
    }
}

impl MainView for ForcesView {
    fn view(&self) -> View {
        View::Forces
    }

    /// It takes the chart's and the side panel's room.
    fn parts(&self, _: &App) -> Vec<(&'static dyn Component, Place)> {
        vec![(&ForcesView, Place::Middle)]
    }
}
