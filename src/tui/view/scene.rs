//! The groove seen from the side: both balls to scale along x and round on screen,
//! each with a spoke turning by its integrated spin angle, slip tags, the impact
//! flash, and tick trails of where the centres have been.

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::widgets::Widget;

use super::block;
use crate::physics::model::Phase;
use crate::physics::solution::EventKind;
use crate::tui::app::App;
use crate::tui::canvas::Canvas;
use crate::tui::theme::Theme;

pub fn render(app: &App, area: Rect, buf: &mut Buffer, theme: &Theme) {
    let g = theme.glyphs;
    let sol = &app.lab.solution;
    let t = app.t;
    let snap = sol.at(t);
    let seg = sol.segment_at(t);
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
    let title = format!(
        " Scene  t = {t:.3} s   impacts {impacts_so_far}{} ",
        if flashing {
            format!("  {} IMPACT", g.flash)
        } else {
            String::new()
        }
    );
    let mut blk = block(title, theme);
    // A legend for the marks that are not balls: the trails, and the measured ball
    // (right); the pinned run's parameters (left) in what room is left.
    let ghost = app.lab.ghost_x(t).is_some();
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
    blk = blk.title_bottom(legend.right_aligned());
    let room = area.width.saturating_sub(4 + legend_w + 1);
    if let Some(line) = pinned_line(app, room, theme) {
        blk = blk.title_bottom(ratatui::text::Line::styled(line, theme.dim));
    }
    let inner = blk.inner(area);
    blk.render(area, buf);
    if inner.height < 5 || inner.width < 20 {
        return;
    }
    // Rows: balls, groove, trail ticks, tags.
    let ball_rows = inner.height - 3;
    let groove_y = inner.y + ball_rows;
    let (lo, hi) = app.lab.extent;
    let radius = app.lab.scene.radius;
    let (sx, sy) = if g.ascii { (1.0, 1.0) } else { (2.0, 4.0) };
    // Columns per metre: fit the range, and keep the ball inside its rows (a cell is
    // about twice as tall as wide).
    let fit_x = f64::from(inner.width - 1) / (hi - lo);
    let fit_y = f64::from(ball_rows) * 2.0 / (2.0 * radius) * 0.98;
    let scale = fit_x.min(fit_y);
    let mid = 0.5 * (lo + hi);
    let col = |x: f64| (x - mid) * scale + f64::from(inner.width) / 2.0;

    // Groove line.
    for c in 0..inner.width {
        buf.set_string(inner.x + c, groove_y, g.hline, theme.groove);
    }

    // Trails: where each centre was, a tick per time step so density shows speed.
    let trail_y = groove_y + 1;
    let steps = usize::from(inner.width);
    let dt = (sol.t_end - sol.t_start) / steps as f64;
    for k in 0..=steps {
        let tk = sol.t_start + k as f64 * dt;
        if tk > t {
            break;
        }
        let s = sol.at(tk);
        for (x, style) in [(s.left.x, theme.left), (s.right.x, theme.right)] {
            let c = col(x);
            if c >= 0.0 && c < f64::from(inner.width) {
                buf.set_string(inner.x + c as u16, trail_y, g.dot, style);
            }
        }
    }

    // Balls: outline and a spoke at the spin angle, in dot units (square dots).
    let mut canvas = Canvas::new(usize::from(inner.width), usize::from(ball_rows), g.ascii);
    let angles = sol.angle_at(t);
    let r_dots = radius * scale * sx;
    // A dot is `aspect` times taller than wide: 1 for braille, 2 for ASCII cells.
    let aspect = 2.0 * sx / sy;
    let cy = f64::from(ball_rows) * sy - r_dots / aspect - 0.5;
    // The pinned run's balls (A/B): dashed ghosts, under the current balls' ink.
    if let Some(p) = &app.lab.pinned {
        let ps = p.solution.at(t);
        let pr = p.scene.radius * scale * sx;
        let pcy = f64::from(ball_rows) * sy - pr / aspect - 0.5;
        for x in [ps.left.x, ps.right.x] {
            let cx = col(x) * sx;
            let n = ((std::f64::consts::TAU * pr) * 2.0).ceil().max(12.0) as usize;
            for k in (0..n).filter(|k| k % 4 < 2) {
                let a = k as f64 / n as f64 * std::f64::consts::TAU;
                canvas.dot(
                    (cx + pr * a.cos()) / sx,
                    pcy + pr * a.sin() / aspect,
                    theme.dim,
                    ":",
                );
            }
        }
    }
    let balls = [
        (snap.left.x, angles[0], theme.left),
        (snap.right.x, angles[1], theme.right),
    ];
    for (x, angle, style) in balls {
        let cx = col(x) * sx;
        let n = ((2.0 * std::f64::consts::PI * r_dots) * 2.0)
            .ceil()
            .max(12.0) as usize;
        for k in 0..n {
            let a = k as f64 / n as f64 * std::f64::consts::TAU;
            canvas.dot(
                (cx + r_dots * a.cos()) / sx,
                cy + r_dots * a.sin() / aspect,
                style,
                "o",
            );
        }
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
    // The measured left ball where the track (or its v_cm) puts it: a dotted ghost
    // beside the model, with the tracked mark's angle as its spoke.
    if let Some(xg) = app.lab.ghost_x(t) {
        let cx = col(xg) * sx;
        if let Some(angle) = app.lab.ghost_angle(t) {
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
        for k in 0..n {
            let a = k as f64 / n as f64 * std::f64::consts::TAU;
            canvas.dot(
                (cx + r_dots * a.cos()) / sx,
                cy + r_dots * a.sin() / aspect,
                theme.measured,
                ":",
            );
        }
    }
    canvas.write(inner.x, inner.y, buf);
    if flashing {
        let c = col(0.5 * (snap.left.x + snap.right.x));
        let y = inner.y + (cy / sy) as u16;
        if c >= 0.0 && c < f64::from(inner.width) {
            buf.set_string(inner.x + c as u16, y, g.flash, theme.flash);
        }
    }

    // Tags under each ball: what its contact points do.
    let tag_y = groove_y + 2;
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
        let c = (col(x) - w / 2.0).min(f64::from(inner.width) - w).max(0.0);
        let c = if i == 1 {
            // Keep the right tag clear of the left one when the balls touch.
            c.max(col(snap.left.x) + w / 2.0 + 1.0)
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
    let changes = app.lab.pinned_changes();
    let body = if changes.is_empty() {
        "same parameters".to_string()
    } else {
        changes
            .iter()
            .map(|(label, was, now)| {
                let name = label.replace("mu", theme.glyphs.mu);
                // b hidden (a prediction from the picture): changed, but not to what.
                if app.hide_b && name == "b" {
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
