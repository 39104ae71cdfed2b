//! The groove seen from the side: both balls to scale along x and round on screen,
//! each with a spoke turning by its integrated spin angle, slip tags, the impact
//! flash, and tick trails of where the centres have been.

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::style::Style;
use ratatui::widgets::Widget;

use super::panel::block;
use crate::physics::model::Phase;
use crate::physics::solution::EventKind;
use crate::tui::app::App;
use crate::tui::canvas::Canvas;
use crate::tui::component::{Component, Ctx};
use crate::tui::theme::Theme;

pub fn render(app: &App, area: Rect, buf: &mut Buffer, theme: &Theme) {
    if app.video().shown {
        return super::video::render(app, area, buf, theme);
    }
    let (title, flashing) = title(app, theme);
    let blk = with_legend(block(title, theme), app, area, theme);
    let inner = blk.inner(area);
    blk.render(area, buf);
    if inner.height < 5 || inner.width < 20 {
        return;
    }
    let geo = Geometry::new(app, inner, theme);
    // Groove line.
    for c in 0..inner.width {
        buf.set_string(inner.x + c, geo.groove_y, theme.glyphs.hline, theme.groove);
    }
    draw_trails(app, &geo, buf, theme);
    let mut canvas = Canvas::new(
        usize::from(inner.width),
        usize::from(geo.ball_rows),
        theme.glyphs.ascii,
    );
    draw_pinned(app, &geo, &mut canvas, theme);
    draw_balls(app, &geo, &mut canvas, theme);
    draw_measured(app, &geo, &mut canvas, theme);
    canvas.write(inner.x, inner.y, buf);
    if flashing {
        let snap = app.lab.solution.at(app.t);
        let c = geo.col(0.5 * (snap.left.x + snap.right.x));
        let y = inner.y + (geo.cy / geo.sy) as u16;
        if c >= 0.0 && c < f64::from(inner.width) {
            buf.set_string(inner.x + c as u16, y, theme.glyphs.flash, theme.flash);
        }
    }
    draw_tags(app, &geo, buf, theme);
}

/// The panel's title: the time, the impacts so far, and the flash of an impact; and
/// whether it flashes.
fn title(app: &App, theme: &Theme) -> (String, bool) {
    let (sol, t) = (&app.lab.solution, app.t);
    let impacts_so_far = sol
        .events
        .iter()
        .filter(|e| e.kind == EventKind::Collision && e.t <= t)
        .count();
    // The flash lasts three frames of playback, so it is seen at any speed.
    let flash_window = 3.0 * app.frame_step();
    let flashing = sol
        .events
        .iter()
        .any(|e| e.kind == EventKind::Collision && (e.t - t).abs() <= flash_window);
    // A video tracked on a worker: how far (its data join the scene when done).
    let tracking = app
        .video()
        .progress()
        .map_or(String::new(), |(done, total)| {
            format!(
                "  tracking video {} %",
                (100 * done.min(total)).checked_div(total).unwrap_or(0)
            )
        });
    let title = format!(
        " Scene  t = {t:.3} s   impacts {impacts_so_far}{}{tracking} ",
        if flashing {
            format!("  {} IMPACT", theme.glyphs.flash)
        } else {
            String::new()
        }
    );
    (title, flashing)
}

/// A legend for the marks that are not balls on the bottom border: the trails, and
/// the measured ball (right); the pinned run's parameters (left) in what room is left.
fn with_legend<'a>(
    blk: ratatui::widgets::Block<'a>,
    app: &App,
    area: Rect,
    theme: &Theme,
) -> ratatui::widgets::Block<'a> {
    let g = theme.glyphs;
    let ghost = app.lab.ghost_x(app.t).is_some();
    let (trail_mark, ghost_mark) = if g.ascii {
        (".", ":")
    } else {
        ("·", "⠂⠄")
    };
    let mut legend = vec![ratatui::text::Span::styled(
        format!(" {trail_mark} trail "),
        theme.dim,
    )];
    if ghost {
        legend.push(ratatui::text::Span::styled(
            format!(" {ghost_mark} measured ball "),
            theme.measured,
        ));
    }
    // A pinned run's changes outrank the legend: on a narrow panel the trail's entry
    // goes first, then the measured ball's, before the pinned line is cut.
    let pinned_w = pinned_line(app, u16::MAX, theme).map_or(0, |l| l.chars().count());
    let legend_width = |l: &[ratatui::text::Span]| l.iter().map(|s| s.width()).sum::<usize>();
    while pinned_w > 0
        && !legend.is_empty()
        && pinned_w + legend_width(&legend) + 1 > usize::from(area.width.saturating_sub(4))
    {
        legend.remove(0);
    }
    let legend = ratatui::text::Line::from(legend);
    let legend_w = legend.width() as u16;
    let mut blk = blk.title_bottom(legend.right_aligned());
    let room = area.width.saturating_sub(4 + legend_w + 1);
    if let Some(line) = pinned_line(app, room, theme) {
        blk = blk.title_bottom(ratatui::text::Line::styled(line, theme.dim));
    }
    blk
}

/// Where things go inside the panel: rows for the balls, the groove, the trail ticks
/// and the tags; the scale along x; the canvas's dot units.
struct Geometry {
    inner: Rect,
    ball_rows: u16,
    groove_y: u16,
    /// Columns per metre, and the x shown in the middle (m).
    scale: f64,
    mid: f64,
    /// Dots per cell across and down (2 × 4 braille, 1 × 1 ASCII).
    sx: f64,
    sy: f64,
    /// The balls' radius in dots, and a dot's height over its width.
    r_dots: f64,
    aspect: f64,
    /// The balls' centre row, in dots.
    cy: f64,
}

impl Geometry {
    fn new(app: &App, inner: Rect, theme: &Theme) -> Geometry {
        // Rows: balls, groove, trail ticks, tags.
        let ball_rows = inner.height - 3;
        let (lo, hi) = app.lab.extent;
        let radius = app.lab.scene.radius;
        let (sx, sy) = if theme.glyphs.ascii {
            (1.0, 1.0)
        } else {
            (2.0, 4.0)
        };
        // Columns per metre: fit the range, and keep the ball inside its rows (a cell
        // is about twice as tall as wide).
        let fit_x = f64::from(inner.width - 1) / (hi - lo);
        let fit_y = f64::from(ball_rows) * 2.0 / (2.0 * radius) * 0.98;
        let scale = fit_x.min(fit_y);
        let r_dots = radius * scale * sx;
        // A dot is `aspect` times taller than wide: 1 for braille, 2 for ASCII cells.
        let aspect = 2.0 * sx / sy;
        Geometry {
            inner,
            ball_rows,
            groove_y: inner.y + ball_rows,
            scale,
            mid: 0.5 * (lo + hi),
            sx,
            sy,
            r_dots,
            aspect,
            cy: f64::from(ball_rows) * sy - r_dots / aspect - 0.5,
        }
    }

    /// The column (from the panel's left, fractional) of position `x` (m).
    fn col(&self, x: f64) -> f64 {
        (x - self.mid) * self.scale + f64::from(self.inner.width) / 2.0
    }
}

/// Trails: where each centre was, a tick per time step so density shows speed.
fn draw_trails(app: &App, geo: &Geometry, buf: &mut Buffer, theme: &Theme) {
    let sol = &app.lab.solution;
    let inner = geo.inner;
    let trail_y = geo.groove_y + 1;
    let steps = usize::from(inner.width);
    let dt = (sol.t_end - sol.t_start) / steps as f64;
    for k in 0..=steps {
        let tk = sol.t_start + k as f64 * dt;
        if tk > app.t {
            break;
        }
        let s = sol.at(tk);
        for (x, style) in [(s.left.x, theme.left), (s.right.x, theme.right)] {
            let c = geo.col(x);
            if c >= 0.0 && c < f64::from(inner.width) {
                buf.set_string(inner.x + c as u16, trail_y, theme.glyphs.dot, style);
            }
        }
    }
}

/// The pinned run's balls (A/B): dashed ghosts, under the current balls' ink.
fn draw_pinned(app: &App, geo: &Geometry, canvas: &mut Canvas, theme: &Theme) {
    let Some(p) = &app.lab.pinned else {
        return;
    };
    let (sx, aspect) = (geo.sx, geo.aspect);
    let ps = p.solution.at(app.t);
    let pr = p.scene.radius * geo.scale * sx;
    let pcy = f64::from(geo.ball_rows) * geo.sy - pr / aspect - 0.5;
    for x in [ps.left.x, ps.right.x] {
        let n = ((std::f64::consts::TAU * pr) * 2.0).ceil().max(12.0) as usize;
        // Dashed: two dots of every four.
        let at = (geo.col(x) * sx, pcy);
        ring(
            canvas,
            (sx, aspect),
            at,
            pr,
            n,
            |k| k % 4 < 2,
            theme.dim,
            ":",
        );
    }
}

/// `n` dots evenly round a circle of radius `r` (dot units) about `centre`, those whose
/// index `keep` accepts; `scale` is (dots per column, aspect).
#[allow(clippy::too_many_arguments)]
fn ring(
    canvas: &mut Canvas,
    (sx, aspect): (f64, f64),
    (cx, cy): (f64, f64),
    r: f64,
    n: usize,
    keep: impl Fn(usize) -> bool,
    style: Style,
    glyph: &'static str,
) {
    for k in (0..n).filter(|&k| keep(k)) {
        let a = k as f64 / n as f64 * std::f64::consts::TAU;
        canvas.dot(
            (cx + r * a.cos()) / sx,
            cy + r * a.sin() / aspect,
            style,
            glyph,
        );
    }
}

/// Balls: outline and a spoke at the spin angle, in dot units (square dots).
fn draw_balls(app: &App, geo: &Geometry, canvas: &mut Canvas, theme: &Theme) {
    let (sx, aspect, cy, r_dots) = (geo.sx, geo.aspect, geo.cy, geo.r_dots);
    let snap = app.lab.solution.at(app.t);
    let angles = app.lab.solution.angle_at(app.t);
    let balls = [
        (snap.left.x, angles[0], theme.left),
        (snap.right.x, angles[1], theme.right),
    ];
    for (x, angle, style) in balls {
        let cx = geo.col(x) * sx;
        let n = ((2.0 * std::f64::consts::PI * r_dots) * 2.0)
            .ceil()
            .max(12.0) as usize;
        ring(
            canvas,
            (sx, aspect),
            (cx, cy),
            r_dots,
            n,
            |_| true,
            style,
            "o",
        );
        // Positive spin turns clockwise on screen (x right, rows down).
        let m = (r_dots * 2.0).ceil().max(2.0) as usize;
        for k in 0..=m {
            let f = k as f64 / m as f64 * r_dots;
            canvas.dot(
                (cx + f * angle.cos()) / sx,
                cy + f * angle.sin() / aspect,
                style,
                "*",
            );
        }
    }
}

/// The measured left ball where the track (or its v_cm) puts it: a dotted ghost
/// beside the model, with the tracked mark's angle as its spoke.
fn draw_measured(app: &App, geo: &Geometry, canvas: &mut Canvas, theme: &Theme) {
    let Some(xg) = app.lab.ghost_x(app.t) else {
        return;
    };
    let (sx, aspect, cy, r_dots) = (geo.sx, geo.aspect, geo.cy, geo.r_dots);
    let cx = geo.col(xg) * sx;
    if let Some(angle) = app.lab.ghost_angle(app.t) {
        let m = (r_dots * 2.0).ceil().max(2.0) as usize;
        for k in (0..=m).step_by(2) {
            let f = k as f64 / m as f64 * r_dots;
            canvas.dot(
                (cx + f * angle.cos()) / sx,
                cy + f * angle.sin() / aspect,
                theme.measured,
                ".",
            );
        }
    }
    let n = ((std::f64::consts::TAU * r_dots) / 3.0).ceil().max(8.0) as usize;
    let dots = (sx, aspect);
    ring(
        canvas,
        dots,
        (cx, cy),
        r_dots,
        n,
        |_| true,
        theme.measured,
        ":",
    );
}

/// Tags under each ball: what its contact points do.
fn draw_tags(app: &App, geo: &Geometry, buf: &mut Buffer, theme: &Theme) {
    let g = theme.glyphs;
    let inner = geo.inner;
    let snap = app.lab.solution.at(app.t);
    let seg = app.lab.solution.segment_at(app.t);
    let tag_y = geo.groove_y + 2;
    let pressed = seg.contact_force > 0.0;
    for (i, x, style) in [(0, snap.left.x, theme.left), (1, snap.right.x, theme.right)] {
        let tag = match seg.phase[i] {
            Phase::Sliding { sign } => {
                format!(
                    "sliding {}",
                    if sign < 0 {
                        g.arrow_left
                    } else {
                        g.arrow_right
                    }
                )
            }
            Phase::Rolling => "rolling".to_string(),
            Phase::Resting => "at rest".to_string(),
        };
        let tag = if pressed {
            format!("{tag}, pressed")
        } else {
            tag
        };
        let w = tag.chars().count() as f64;
        // Not `clamp`: a tag wider than the panel would make min > max and panic.
        let c = (geo.col(x) - w / 2.0)
            .min(f64::from(inner.width) - w)
            .max(0.0);
        let c = if i == 1 {
            // Keep the right tag clear of the left one when the balls touch.
            c.max(geo.col(snap.left.x) + w / 2.0 + 1.0)
                .min(f64::from(inner.width) - w)
        } else {
            c
        };
        if c >= 0.0 {
            buf.set_stringn(
                inner.x + c as u16,
                tag_y,
                &tag,
                (inner.width as f64 - c) as usize,
                style,
            );
        }
    }
}

/// The scene panel's bottom line while a run is pinned: which parameters it had that
/// differ now, cut with "…" to `width` characters.
fn pinned_line(app: &App, width: u16, theme: &Theme) -> Option<String> {
    let p = app.lab.pinned.as_ref()?;
    let changes = &app.lab.pinned_changes;
    let body = if changes.is_empty() {
        "same parameters".to_string()
    } else {
        changes
            .iter()
            .map(|(label, was, now)| {
                let name = label.replace("mu", theme.glyphs.mu);
                // b hidden (a prediction from the picture): changed, but not to what.
                if app.hide().change(label) {
                    "b changed".to_string()
                } else {
                    format!("{name} {was} → {now}")
                }
            })
            .collect::<Vec<_>>()
            .join(", ")
    };
    let g = theme.glyphs;
    let text = g.text(&format!(" pinned {} (dashed): {body} ", p.label));
    let width = usize::from(width);
    if text.chars().count() <= width {
        return Some(text);
    }
    let cut: String = text.chars().take(width.saturating_sub(4)).collect();
    Some(g.text(&format!("{}… ", cut.trim_end())))
}

/// The scene panel (the balls in the groove) as a component.
pub struct ScenePanel;

impl Component for ScenePanel {
    fn render(&self, area: Rect, buf: &mut Buffer, cx: &Ctx<'_>) {
        render(cx.app, area, buf, cx.theme);
    }
}
