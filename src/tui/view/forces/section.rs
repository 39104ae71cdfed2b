//! The Forces view's front view: the groove's cross-section with the weight, normal
//! and friction forces on one ball and their torques, to scale for the current b.

use super::parts::*;

pub(super) fn front_view(app: &App, area: Rect, buf: &mut Buffer, theme: &Theme) {
    let ball = app.forces().ball();
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
        let values_w = 23.min(inner.width.saturating_sub(15));
        // A column between: the drawing fills its area to the edge, and its rail
        // (`=(.)`) ran into the values (`(.)=|tau_A|`).
        Layout::horizontal([Constraint::Min(10), Constraint::Length(values_w)])
            .spacing(1)
            .areas(inner)
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
pub(super) fn front_values<'a>(
    app: &App,
    now: &Instant,
    s: &Sliding,
    width: u16,
    theme: &Theme,
) -> Ranked<'a> {
    let g = theme.glyphs;
    let hide = app.hidden().forces();
    let t = |s: String| g.text(&s);
    let fit = |variants: [String; 2]| fitting(&variants.map(|v| g.text(&v)), width);
    let friction = if now.friction == 0.0 {
        // Zeros keep their units: "0" alone read as a missing unit (a new user's trial).
        fit([
            "|F_A|=|F_B| 0 N, v_A = 0 m/s".into(),
            "|F| 0 N (v_A = 0)".into(),
        ])
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
            t("τ_net = 0 N m".into()),
            t(format!("sliding: μ_k m g R = {tau} N m")),
        )
    } else {
        (
            t(format!("τ_net {} N m", sig_figs(now.net_torque.abs(), 3))),
            fit([
                format!("= μ_k m g R, {}", unbroken("for any b")),
                format!("= μ_k m g R {}", unbroken("(any b)")),
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
pub(super) struct SectionFrame {
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
pub(super) fn draw_groove_and_ball(
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
pub(super) type Head = (f64, f64, (f64, f64), Style);

/// The force arrows to scale, drawn as lines: G = 0.55 R long, the normal forces in
/// proportion (capped), and while friction acts τ_net 1.15 R long (its tip outside
/// the ball) with τ_A and τ_B in proportion (capped). Returns their heads.
pub(super) fn draw_force_arrows(
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
pub(super) fn cross_section(app: &App, now: &Instant, area: Rect, buf: &mut Buffer, theme: &Theme) {
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
pub(super) fn line_glyph(dx: f64, dy: f64) -> &'static str {
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
pub(super) fn head_glyph(d: (f64, f64), ascii: bool) -> &'static str {
    let a = (-d.1).atan2(d.0).to_degrees().rem_euclid(360.0);
    let i = ((a + 22.5) / 45.0).floor() as usize % 8;
    if ascii {
        ["->", "/", "^", "\\", "<-", "/", "v", "\\"][i]
    } else {
        ["→", "↗", "↑", "↖", "←", "↙", "↓", "↘"][i]
    }
}

/// Writes `text` centred at (`x`, `y`) cell coordinates of `area`, clipped to it.
pub(super) fn put(buf: &mut Buffer, area: Rect, x: f64, y: f64, text: &str, style: Style) {
    let w = text.chars().count() as f64;
    let col = (x - w / 2.0 + 0.5).floor();
    let row = y.floor();
    if row < 0.0 || row >= f64::from(area.height) || col < 0.0 || col + w > f64::from(area.width) {
        return;
    }
    buf.set_string(area.x + col as u16, area.y + row as u16, text, style);
}
