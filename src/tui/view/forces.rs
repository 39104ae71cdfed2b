//! The Forces view (key `v`): the paper's explanatory figures, live at the cursor's
//! time. Front: the groove's cross-section with the weight, normal and friction forces
//! on one ball and their torques, to scale for the current b. Side: both balls' centre
//! and contact-point velocities, friction and spin, with the motion state named.
//! Chain: b → k → |N| → |F| → F_net → a_cm; τ_net → α → a_t; D → the outcome, with ↑/↓
//! against a pinned run; and the predict–observe–explain panel. It only reads the lab
//! (the per-scene values are in `derived.sliding`) and the solution at the cursor.

use ratatui::buffer::Buffer;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::style::Style;
use ratatui::symbols::border;
use ratatui::text::{Line, Span};
use ratatui::widgets::{Block, Borders, Clear, Paragraph, Widget, Wrap};

use super::panel::{
    Ranked, block, by_priority, draw_lines, fitting, rows_by_priority, title_of, title_within, wrap,
};
use crate::physics::derived::Regime;
use crate::physics::forces::{Instant, Sliding, instant};
use crate::settings::units::{Dimension, show, sig_figs, significant};
use crate::tui::app::{App, Prediction};
use crate::tui::canvas::Canvas;
use crate::tui::theme::Theme;
use crate::tui::vocabulary::ANSWERS;
use crate::tui::vocabulary::Mode;

/// Lengths are shown in their display unit.
const LENGTH: Dimension = Dimension::Length;

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

/// A block's bottom title: the first of `variants` (longest first) that fits on the
/// border of `area`, the last cut with an ellipsis if none does.
fn footer(variants: &[String], area: Rect, theme: &Theme) -> Line<'static> {
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
fn side_footer(area: Rect, theme: &Theme) -> Line<'static> {
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
fn ball_name(ball: usize) -> &'static str {
    if ball == 0 { "left" } else { "right" }
}

/// A number with 3 significant digits, or `?` while b is hidden and it depends on b.
fn num(v: f64, hidden: bool) -> String {
    if hidden { "?".into() } else { sig_figs(v, 3) }
}

/// Out of the picture (+x, toward the viewer) or into it, as the paper's ⊙ / ⊗.
fn along_x(theme: &Theme, positive: bool) -> &'static str {
    match (theme.glyphs.ascii, positive) {
        (false, true) => "⊙",
        (false, false) => "⊗",
        (true, true) => "(.)",
        (true, false) => "(x)",
    }
}

fn front_view(app: &App, area: Rect, buf: &mut Buffer, theme: &Theme) {
    let ball = app.forces_ball;
    let title = format!("Forces: front view, {} ball [b]", ball_name(ball));
    let out = along_x(theme, true);
    let inn = along_x(theme, false);
    let bottom = footer(
        &[
            format!("{out} +x out of the picture, {inn} into it; z right, y down"),
            format!("{out} +x out, {inn} in; z right, y down"),
            format!("{out} out, {inn} in; z right, y down"),
        ],
        area,
        theme,
    );
    let short = format!("Front view, {} ball [b]", ball_name(ball));
    let blk = block(title_of(&[&title, &short], area, theme), theme).title_bottom(bottom);
    let inner = blk.inner(area);
    blk.render(area, buf);
    if inner.width < 20 || inner.height < 3 {
        return;
    }
    let now = instant(&app.lab.solution, ball, app.t);
    let sliding = app.lab.derived.sliding[ball];
    // The picture above the values on a tall panel, else beside them.
    let [picture, values] = if inner.height >= 16 {
        Layout::vertical([Constraint::Min(8), Constraint::Length(8)]).areas(inner)
    } else {
        let values_w = 23.min(inner.width.saturating_sub(14));
        Layout::horizontal([Constraint::Min(10), Constraint::Length(values_w)]).areas(inner)
    };
    cross_section(app, &now, picture, buf, theme);
    let lines = by_priority(
        front_values(app, &now, &sliding, values.width, theme),
        values,
    );
    draw_lines(lines, values, buf);
}

/// The values beside the cross-section, most important first at 80×24: |N|, |F|,
/// τ_net; shorter wordings where the column (`width`) is narrow.
fn front_values<'a>(
    app: &App,
    now: &Instant,
    s: &Sliding,
    width: u16,
    theme: &Theme,
) -> Ranked<'a> {
    let g = theme.glyphs;
    let hide = app.hide_b;
    let t = |s: String| g.text(&s);
    let fit = |variants: [String; 2]| fitting(&variants.map(|v| g.text(&v)), width);
    let friction = if now.friction == 0.0 {
        fit(["|F_A|=|F_B| 0, v_A = 0".into(), "|F| 0 (v_A = 0)".into()])
    } else {
        let kind = if now.kinetic { "" } else { " static" };
        let f = num(now.friction.abs(), hide);
        fit([
            format!("|F_A|=|F_B| {f} N{kind}"),
            format!("|F| {f} N{kind}"),
        ])
    };
    let direction = if now.friction == 0.0 {
        String::new()
    } else if now.friction > 0.0 {
        format!("F along +x: {} out", along_x(theme, true))
    } else {
        format!("F along -x: {} in", along_x(theme, false))
    };
    let tau = sig_figs(s.net_torque, 3);
    let (torque, why_torque) = if now.net_torque == 0.0 {
        (
            t("τ_net = 0".into()),
            t(format!("sliding: μ_k m g R = {tau} N m")),
        )
    } else {
        (
            t(format!("τ_net {} N m", sig_figs(now.net_torque.abs(), 3))),
            fit([
                "= μ_k m g R, for any b".into(),
                "= μ_k m g R (any b)".into(),
            ]),
        )
    };
    let tau_ab = num(now.friction.abs() * app.lab.scene.radius, hide);
    let tau_ab = fit([
        format!("|τ_A|=|τ_B| {tau_ab} N m"),
        format!("|τ_A| {tau_ab} N m"),
    ]);
    let mut out: Ranked = vec![
        (
            9,
            Line::styled(
                t(format!("|N_A|=|N_B| {} N", num(s.normal, hide))),
                theme.text,
            ),
        ),
        (9, Line::styled(friction, theme.accent)),
        (7, Line::styled(direction, theme.accent)),
        (8, Line::styled(torque, theme.left)),
        (5, Line::styled(tau_ab, theme.dim)),
        (
            6,
            Line::styled(format!("G {} N", sig_figs(s.weight, 3)), theme.text),
        ),
        (
            4,
            Line::styled(
                format!(
                    "r {}{}  k {}",
                    num(LENGTH.to_display(s.r), hide),
                    LENGTH.suffix(),
                    num(s.k, hide)
                ),
                theme.dim,
            ),
        ),
        (3, Line::styled(why_torque, theme.dim)),
    ];
    if now.other.abs() > 1e-9 * s.weight {
        out.push((
            4,
            Line::styled(t(format!("push {:+.3} N along x", now.other)), theme.dim),
        ));
    }
    out
}

/// Where the cross-section's physical (z, y), from the ball's centre, lands in canvas
/// dots.
#[derive(Clone, Copy)]
struct SectionFrame {
    /// Centre of the ball, dots.
    cx: f64,
    cy: f64,
    /// Cell widths per metre.
    scale: f64,
    /// Dots per cell across and down.
    sx: f64,
    sy: f64,
}

impl SectionFrame {
    /// The frame fitting the picture in `area`: it spans 2.9 R across and, down, room
    /// above the ball for the torques' arrows (up to 1.25 R from the centre) to the
    /// rails' feet (a cell is about twice as tall as wide).
    fn new(area: Rect, radius: f64, r: f64, sub: (usize, usize)) -> SectionFrame {
        let (sx, sy) = (sub.0 as f64, sub.1 as f64);
        let top = 1.3 * radius;
        let tall = top + radius.max(1.35 * r) + 0.1 * radius;
        let scale =
            (f64::from(area.width) / (2.9 * radius)).min(f64::from(area.height) * 2.0 / tall);
        SectionFrame {
            cx: f64::from(area.width) / 2.0 * sx,
            cy: top * scale * sy / 2.0,
            scale,
            sx,
            sy,
        }
    }

    fn dot(&self, z: f64, y: f64) -> (f64, f64) {
        (
            self.cx + z * self.scale * self.sx,
            self.cy + y * self.scale * self.sy / 2.0,
        )
    }
}

/// The rails (their tops at A and B, r below the centre, from ±b/2 outward), the
/// ball, the line AB (dashed) and r from the centre to it.
fn draw_groove_and_ball(
    canvas: &mut Canvas,
    frame: &SectionFrame,
    (radius, half_b, r): (f64, f64, f64),
    theme: &Theme,
) {
    let dot = |z, y| frame.dot(z, y);
    for side in [-1.0, 1.0] {
        let edge = dot(side * half_b, r);
        let outer = dot(side * 1.45 * radius, r);
        canvas.line(edge, outer, theme.groove, "=");
        let foot = dot(side * half_b, r + 0.35 * radius);
        canvas.line(edge, foot, theme.groove, "|");
    }
    let n = (std::f64::consts::TAU * radius * frame.scale * frame.sx * 2.0)
        .ceil()
        .max(16.0) as usize;
    for k in 0..n {
        let a = k as f64 / n as f64 * std::f64::consts::TAU;
        let (x, y) = dot(radius * a.cos(), radius * a.sin());
        canvas.set(x.floor() as i64, y.floor() as i64, theme.dim, "o");
    }
    let (a, b) = (dot(-half_b, r), dot(half_b, r));
    let steps = ((b.0 - a.0) / 2.0).ceil().max(1.0) as usize;
    for k in (0..=steps).step_by(2) {
        let x = a.0 + (b.0 - a.0) * k as f64 / steps as f64;
        canvas.set(x.round() as i64, a.1.round() as i64, theme.dim, ".");
    }
    canvas.line(dot(0.0, 0.0), dot(0.0, r), theme.dim, ":");
}

/// An arrow's head: where (dots), its direction (z, y) and style.
type Head = (f64, f64, (f64, f64), Style);

/// The force arrows to scale, drawn as lines: G = 0.55 R long, the normal forces in
/// proportion (capped), and while friction acts τ_net 1.15 R long (its tip outside
/// the ball) with τ_A and τ_B in proportion (capped). Returns their heads.
fn draw_force_arrows(
    canvas: &mut Canvas,
    frame: &SectionFrame,
    (radius, half_b, r): (f64, f64, f64),
    (k, now): (f64, &Instant),
    theme: &Theme,
) -> Vec<Head> {
    let g_len = 0.55 * radius;
    let n_len = (g_len / (2.0 * k)).min(1.3 * radius);
    let mut heads: Vec<Head> = Vec::new();
    let mut arrow = |canvas: &mut Canvas, from: (f64, f64), to: (f64, f64), style: Style| {
        let (a, b) = (frame.dot(from.0, from.1), frame.dot(to.0, to.1));
        let glyph = line_glyph(b.0 - a.0, (b.1 - a.1) / (frame.sy / 2.0) * frame.sx);
        canvas.line(a, b, style, glyph);
        heads.push((b.0, b.1, (to.0 - from.0, to.1 - from.1), style));
    };
    arrow(canvas, (0.0, 0.0), (0.0, g_len), theme.text);
    for side in [-1.0, 1.0] {
        // From A (or B) toward the centre, along the radius.
        let (z0, y0) = (side * half_b, r);
        let f = n_len / radius;
        arrow(canvas, (z0, y0), (z0 - z0 * f, y0 - y0 * f), theme.text);
    }
    if now.friction != 0.0 {
        let per = 1.15 * radius / (2.0 * r.max(1e-300) * now.friction.abs());
        let cap = |z: f64, y: f64| {
            let len = z.hypot(y);
            let f = if len > 1.25 * radius {
                1.25 * radius / len
            } else {
                1.0
            };
            (z * f, y * f)
        };
        let (ty, tz) = now.torque_a;
        arrow(canvas, (0.0, 0.0), cap(tz * per, ty * per), theme.left);
        arrow(canvas, (0.0, 0.0), cap(tz * per, -ty * per), theme.left);
        arrow(canvas, (0.0, 0.0), (now.net_torque * per, 0.0), theme.left);
    }
    heads
}

/// The groove's cross-section seen from +x: rails at ±b/2, the ball on them, A and B,
/// r, and the forces in the y-z plane (G, N_A, N_B, τ_A, τ_B, τ_net) as arrows to
/// scale; the friction forces along x as ⊙ / ⊗ at A and B.
fn cross_section(app: &App, now: &Instant, area: Rect, buf: &mut Buffer, theme: &Theme) {
    let g = theme.glyphs;
    let scene = &app.lab.scene;
    let k = app.lab.derived.k;
    let (radius, half_b) = (scene.radius, 0.5 * scene.width);
    let r = radius * k;
    let sizes = (radius, half_b, r);
    let mut canvas = Canvas::new(usize::from(area.width), usize::from(area.height), g.ascii);
    let frame = SectionFrame::new(area, radius, r, canvas.sub());
    draw_groove_and_ball(&mut canvas, &frame, sizes, theme);
    let heads = draw_force_arrows(&mut canvas, &frame, sizes, (k, now), theme);
    canvas.write(area.x, area.y, buf);
    let (sx, sy) = (frame.sx, frame.sy);
    for (x, y, d, style) in heads {
        put(buf, area, x / sx, y / sy, head_glyph(d, g.ascii), style);
    }
    // Labels: A, B, the friction marks, G.
    let label = |buf: &mut Buffer, z: f64, y: f64, text: &str, style: Style| {
        let (x, yy) = frame.dot(z, y);
        put(buf, area, x / sx, yy / sy, text, style);
    };
    let below = r + 0.2 * radius;
    label(buf, -half_b - 0.25 * radius, below, "A", theme.text);
    label(buf, half_b + 0.25 * radius, below, "B", theme.text);
    if now.friction != 0.0 {
        let mark = along_x(theme, now.friction > 0.0);
        label(buf, -half_b, r, mark, theme.accent);
        label(buf, half_b, r, mark, theme.accent);
        // τ_net's name above its tip (1.15 R from the centre).
        let tip = now.net_torque.signum() * 1.15 * radius;
        label(buf, tip, -0.25 * radius, &g.text("τ_net"), theme.left);
    }
    label(buf, 0.2 * radius, 0.55 * radius, "G", theme.text);
    label(buf, -0.12 * radius, 0.8 * r, "r", theme.dim);
}

/// The ASCII glyph of a line with direction (`dx`, `dy`) in cell widths.
fn line_glyph(dx: f64, dy: f64) -> &'static str {
    let a = dy.atan2(dx).to_degrees().rem_euclid(180.0);
    if !(22.5..157.5).contains(&a) {
        "-"
    } else if a < 67.5 {
        "\\"
    } else if a < 112.5 {
        "|"
    } else {
        "/"
    }
}

/// An arrow head for direction `d` = (z right, y down).
fn head_glyph(d: (f64, f64), ascii: bool) -> &'static str {
    let a = (-d.1).atan2(d.0).to_degrees().rem_euclid(360.0);
    let i = ((a + 22.5) / 45.0).floor() as usize % 8;
    if ascii {
        ["->", "/", "^", "\\", "<-", "/", "v", "\\"][i]
    } else {
        ["→", "↗", "↑", "↖", "←", "↙", "↓", "↘"][i]
    }
}

/// Writes `text` centred at (`x`, `y`) cell coordinates of `area`, clipped to it.
fn put(buf: &mut Buffer, area: Rect, x: f64, y: f64, text: &str, style: Style) {
    let w = text.chars().count() as f64;
    let col = (x - w / 2.0 + 0.5).floor();
    let row = y.floor();
    if row < 0.0 || row >= f64::from(area.height) || col < 0.0 || col + w > f64::from(area.width) {
        return;
    }
    buf.set_string(area.x + col as u16, area.y + row as u16, text, style);
}

/// A horizontal arrow for `value` against `full` (which fills `half` cells), drawn
/// either side of a zero mark: `←──|` or `|──→`.
fn bar(value: f64, full: f64, half: usize, theme: &Theme) -> String {
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
    ranked.push((
        4,
        Line::styled(row("F", i.friction, s.friction, "N", kind), theme.accent),
    ));
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
            g.text(&format!(
                "  ω     {spin}{:+.1} rad/s, v_t {:+.3} m/s",
                i.omega, i.v_t
            )),
            theme.dim,
        ),
    ));
    ranked
}

/// ↑ / ↓ / = of `now` against the pinned run's `was` (empty without a pin).
fn trend(now: f64, was: Option<f64>, theme: &Theme) -> String {
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
fn pinned_sliding(app: &App) -> Option<(Sliding, f64)> {
    app.lab.pinned.as_ref().map(|p| {
        let mass = if app.forces_ball == 0 {
            p.scene.left.mass
        } else {
            p.scene.right.mass
        };
        (Sliding::of(&p.scene, mass), p.scene.width)
    })
}

/// The two chains' items for the ball shown: b → k → |N| → |F| → F_net → |a_cm| and
/// τ_net → |α| → |a_t|, each with its unit and, with a run pinned, ↑/↓/= against it
/// (an item and its arrow are never split), `?` where they would give away what b or
/// a `pending` prediction hides. `compact` drops the magnitude bars.
fn chains(app: &App, pending: bool, compact: bool, theme: &Theme) -> [Vec<String>; 2] {
    let s = app.lab.derived.sliding[app.forces_ball];
    let pinned = pinned_sliding(app);
    let hide = app.hide_b;
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
    let b = if hide {
        "b ?".to_string()
    } else {
        format!(
            "b {:.2}{}",
            show(app.lab.scene.width, LENGTH),
            trend(app.lab.scene.width, pinned.map(|p| p.1), theme)
        )
    };
    let translation = vec![
        b,
        item("k", s.k, "", hide, was(|p| p.k)),
        item("|N|", s.normal, " N", hide, was(|p| p.normal)),
        item("|F|", s.friction, " N", hide, was(|p| p.friction)),
        item("F_net", s.net_force, " N", hide, was(|p| p.net_force)),
        item("|a_cm|", s.a_cm, " m/s²", hide_a, was(|p| p.a_cm)),
    ];
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
fn outcome_items(app: &App, pending: bool, compact: bool, theme: &Theme) -> Vec<String> {
    let s = app.lab.derived.sliding[app.forces_ball];
    let d = if compact {
        "D = a_t/a_cm"
    } else {
        "D = |a_t|/|a_cm|"
    };
    let regime = app.lab.derived.regime.name().to_string();
    let items = if pending {
        vec![format!("{d} = ?"), "what will the balls do?".to_string()]
    } else if app.hide_b {
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
fn chain_rows(items: &[String], arrow: &str, width: usize) -> Vec<String> {
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
fn chain_block(title: (&str, &str), area: Rect, joined: bool, theme: &Theme) -> Block<'static> {
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

fn chain_view(app: &App, area: Rect, joined: bool, buf: &mut Buffer, theme: &Theme) {
    let g = theme.glyphs;
    let prediction = app.prediction.as_ref().filter(|p| p.scene == app.lab.scene);
    // While the question is asked, and until the outcome shows, the chain keeps D and
    // the outcome to itself: the answer must not stand beside the question.
    let pending = app.mode == Mode::Predict || prediction.is_some_and(|p| app.t < p.reveal_at);
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
    if !(pending || app.hide_b) && prediction.is_none() {
        ranked.push((
            5,
            Line::styled(g.text(&app.lab.derived.why()), theme.accent),
        ));
    }
    if let Some(p) = prediction {
        ranked.extend(prediction_lines(app, p, pending, theme));
    } else if app.prediction.is_some() {
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
fn prediction_lines<'a>(app: &App, p: &Prediction, pending: bool, theme: &Theme) -> Ranked<'a> {
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
    let mark = match (right, g.ascii) {
        (true, false) => "✓ right",
        (false, false) => "✗ not quite",
        (true, true) => "right",
        (false, true) => "not quite",
    };
    let pm = if g.ascii { "+-" } else { "±" };
    // With b hidden, the reason in words: D's value (or v') would give b away.
    let why = match (app.hide_b, d.symmetric, d.regime) {
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
            Line::from(vec![
                Span::styled(format!("predicted: {guess}   "), theme.text),
                Span::styled(
                    g.text(&format!("observed: {}", app.lab.story.headline)),
                    theme.accent,
                ),
                Span::styled(
                    format!("   {mark}"),
                    if right { theme.info } else { theme.error },
                ),
            ]),
        ),
        (8, Line::styled(g.text(&format!("why: {why}")), theme.text)),
    ]
}

fn short_answer(r: Regime) -> &'static str {
    match r {
        Regime::Depart => "move apart",
        Regime::Rest => "come to rest",
        Regime::Recollide => "come back",
    }
}

fn answer_text(r: Regime) -> &'static str {
    match r {
        Regime::Depart => "they move apart",
        Regime::Rest => "they come to rest",
        Regime::Recollide => "they come back and collide again",
    }
}

/// Where the question of `lines` lines is drawn on a screen of `area`.
fn question_rect(area: Rect, lines: usize) -> Rect {
    let w = 52.min(area.width.saturating_sub(2));
    let h = (lines as u16 + 4).min(area.height);
    Rect {
        x: area.x + (area.width - w) / 2,
        y: area.y + (area.height - h) / 2,
        width: w,
        height: h,
    }
}

/// The answer (its key) on screen cell (`column`, `row`) of the question on a screen
/// of `area`, if one is there (what a click answers): the answers are its 3rd to 5th
/// lines, none of them wrapped.
pub fn answer_at(area: Rect, column: u16, row: u16) -> Option<char> {
    // The title, a blank line, the answers, a blank line, the note.
    let rect = question_rect(area, ANSWERS.len() + 4);
    let inside = column > rect.x && column + 1 < rect.right();
    let i = usize::from(row.checked_sub(rect.y + 3)?);
    ANSWERS.get(i).filter(|_| inside).map(|(key, _)| *key)
}

/// The question before the impact (Mode::Predict).
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
    let b = if app.hide_b {
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
    let rect = question_rect(area, lines.len());
    Clear.render(rect, buf);
    Paragraph::new(lines)
        .wrap(Wrap { trim: false })
        .block(block(" Predict ", theme))
        .render(rect, buf);
}
