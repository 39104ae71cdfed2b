//! Random looks, drawn from the whole range of benches and cameras users bring: ball
//! colour and finish (white, black, steel, wooden, glossy or matte coloured; lighter
//! or darker than the wall), mark darker or lighter, wall colour and texture (plain,
//! grain, stripes, checker, wood grain, clutter), a backdrop of the balls' brightness
//! in another colour, a near rail board of any brightness, light gradients and spots,
//! a static shadow, moving cast shadows, tilt, 30–240 frames/s, 480p–1080p, H.264 at
//! high compression, small balls in a wide 1080p frame. Each look is framed so both
//! balls stay in the picture over the clip.

use groovelab::physics::engine;
use groovelab::physics::scene::{Scene, Span};

use super::paint::{Cast, Finish, Light, Paint, Rgb, Rng, Shape, Texture, luma, scaled};
use super::{Film, Look};

/// How large the random looks are.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Size {
    /// Small pictures and short clips, for `cargo test` (about 480×270, 30–100
    /// frames/s, 0.35–0.45 s before the impact and 0.3–0.4 s after: 20–85 frames).
    Small,
    /// The cameras' own sizes: 480p, 720p, 1080p, 30–240 frames/s (0.35–0.45 s before
    /// the impact, 0.3–0.6 s after: up to 250 frames).
    Full,
}

/// A random look filmed: the film, how many frames, and the look in words.
pub struct Clip {
    pub film: Film,
    pub frames: usize,
    pub name: String,
}

/// The kinds of ball.
const BALLS: [&str; 6] = ["white", "black", "steel", "wooden", "glossy", "coloured"];

/// The kinds of wall.
const TEXTURES: [&str; 6] = ["plain", "grain", "stripes", "checker", "wood", "clutter"];

/// A colour of hue `h` (0–1), saturation `s` and value `v` (0–255).
fn hsv(h: f64, s: f64, v: f64) -> Rgb {
    let i = (h * 6.0).floor();
    let f = h * 6.0 - i;
    let (p, q, t) = (v * (1.0 - s), v * (1.0 - s * f), v * (1.0 - s * (1.0 - f)));
    match (i as i64).rem_euclid(6) {
        0 => [v, t, p],
        1 => [q, v, p],
        2 => [p, v, t],
        3 => [p, q, v],
        4 => [t, p, v],
        _ => [v, p, q],
    }
}

/// The hue (0–1) and saturation (0–1) of `c`, as [`hsv`] takes them.
pub fn hue_saturation(c: Rgb) -> (f64, f64) {
    let [r, g, b] = c;
    let (max, min) = (r.max(g).max(b), r.min(g).min(b));
    let chroma = max - min;
    if max <= 0.0 || chroma <= 0.0 {
        return (0.0, 0.0);
    }
    let sector = if max == r {
        ((g - b) / chroma).rem_euclid(6.0)
    } else if max == g {
        (b - r) / chroma + 2.0
    } else {
        (r - g) / chroma + 4.0
    };
    (sector / 6.0, chroma / max)
}

/// The hue of a wall "of the balls' brightness in another colour" (issue 34), from
/// the uniform draw `u`: at least a twelfth of the colour circle (30°: red against
/// orange) from the hue of
/// `ball` where the ball has a colour of its own (saturation over 0.15), any hue
/// where it is grey. A wall of the ball's brightness and hue hides the ball from any
/// eye; the looks table's seed 8 drew one (a dark red ball on a dark red wall 12°
/// of hue from it, at crf 39). A draw within 30° is carried, in proportion, onto the
/// hues allowed (uniform there again), so every other draw keeps its hue and every
/// other look is drawn as before.
fn another_hue(ball: Rgb, u: f64) -> f64 {
    let (hue, saturation) = hue_saturation(ball);
    // Where `u` lies in the arc of hues too near the ball's, 0–1 across it.
    let near = (u - hue + 1.0 / 12.0).rem_euclid(1.0) * 6.0;
    if saturation <= 0.15 || near >= 1.0 {
        u
    } else {
        (hue + 1.0 / 12.0 + near * 5.0 / 6.0).rem_euclid(1.0)
    }
}

/// `c` scaled to luma `y` (clamped to the 0–255 levels).
fn with_luma(c: Rgb, y: f64) -> Rgb {
    let l = luma(c).max(1.0);
    scaled(c, y / l).map(|v| v.clamp(0.0, 255.0))
}

/// A random look of `scene`, seeded, framed so both balls stay in view.
pub fn random(scene: &Scene, seed: u64, size: Size) -> Clip {
    let drawn = draw(scene, seed, size);
    let film = Film::new(scene, drawn.look, drawn.to);
    let frames = film.frames_to(drawn.to);
    Clip {
        film,
        frames,
        name: drawn.name,
    }
}

/// A look drawn, not yet filmed: the look, the clip's end (s from the impact) and
/// the look in words.
pub struct Drawn {
    pub look: Look,
    pub to: f64,
    pub name: String,
}

/// The look [`random`] films, drawn only (no picture made).
pub fn draw(scene: &Scene, seed: u64, size: Size) -> Drawn {
    let mut g = Rng::new(seed.wrapping_mul(0x2545_F491_4F6C_DD1D));
    let mut words: Vec<String> = Vec::new();

    // The camera.
    // Small clips keep to ≤ 100 frames/s: at 240 frames/s the ≥ 0.35 s before the
    // impact alone would be 84 frames (the full-size looks have every rate).
    let fps = match size {
        Size::Small => g.pick(&[30.0, 50.0, 60.0, 100.0]),
        Size::Full => g.pick(&[30.0, 50.0, 60.0, 100.0, 120.0, 240.0]),
    };
    let (width, height) = match size {
        Size::Small => g.pick(&[(480, 270), (400, 300)]),
        Size::Full => g.pick(&[(854, 480), (1280, 720), (1920, 1080)]),
    };
    let small_balls = size == Size::Full && width == 1920 && g.chance(0.4);
    let radius_px = match size {
        Size::Small => g.range(11.0, 22.0),
        Size::Full if small_balls => g.range(9.0, 14.0),
        Size::Full => g.range(height as f64 / 22.0, height as f64 / 9.0),
    };
    // What `fit` needs: a steady approach before the impact (at least 0.35 s and 12
    // frames, so the first impact is found and the approach speed has a ±), and the
    // sliding after it (about 0.26 s in paper-b4.9) with some rolling beyond.
    let from = -(0.35f64.max(12.0 / fps) + g.range(0.0, 0.1));
    let after = match size {
        Size::Small => g.range(0.3, 0.4),
        Size::Full => g.range(0.3, 0.6),
    };
    let to = after.max(12.0 / fps);
    let tilt_deg = if g.chance(0.4) {
        g.range(-4.0, 4.0)
    } else {
        0.0
    };

    // Frame the balls' travel: the scale no larger than fits it.
    let (lo, hi) = extent(scene, from, to);
    let r = scene.radius;
    let fit = 0.9 * width as f64 / (hi - lo + 2.0 * r + 0.02);
    let px_per_m = (radius_px / r).min(fit);
    let rpx = px_per_m * r;
    let mid = 0.5 * (lo + hi);
    let y_line = g.range(0.35, 0.55) * height as f64;
    let origin = (
        0.5 * width as f64 - px_per_m * mid * tilt_deg.to_radians().cos(),
        y_line - px_per_m * mid * tilt_deg.to_radians().sin(),
    );
    let shutter = (g.range(0.1, 0.5) / fps).min(0.004);
    let crf = match size {
        Size::Small => g.chance(0.3).then(|| g.range(30.0, 40.0).round() as u32),
        Size::Full => g.chance(0.5).then(|| g.range(30.0, 40.0).round() as u32),
    };

    // The balls and their marks.
    let kind = g.pick(&BALLS);
    let (ball, finish) = match kind {
        "white" => (
            [242.0, 240.0, 234.0],
            if g.chance(0.5) {
                Finish::Matte { ambient: 0.55 }
            } else {
                Finish::Glossy {
                    ambient: 0.55,
                    strength: 0.5,
                }
            },
        ),
        "black" => (
            [30.0, 30.0, 33.0],
            Finish::Glossy {
                ambient: 0.5,
                strength: g.range(0.4, 0.9),
            },
        ),
        "steel" => ([190.0, 194.0, 200.0], Finish::Metallic),
        "wooden" => (
            hsv(g.range(0.06, 0.1), g.range(0.4, 0.6), g.range(140.0, 210.0)),
            Finish::Matte { ambient: 0.45 },
        ),
        "glossy" => (
            hsv(g.unit(), g.range(0.6, 0.95), g.range(120.0, 240.0)),
            Finish::Glossy {
                ambient: 0.4,
                strength: g.range(0.5, 0.9),
            },
        ),
        _ => (
            hsv(g.unit(), g.range(0.2, 0.9), g.range(50.0, 240.0)),
            Finish::Matte {
                ambient: g.range(0.35, 0.6),
            },
        ),
    };
    words.push(kind.to_string());
    let ball_luma = luma(ball);
    let dark_mark = if ball_luma > 150.0 {
        true
    } else if ball_luma < 70.0 {
        false
    } else {
        g.chance(0.5)
    };
    let mark = if dark_mark {
        g.pick(&[[20.0, 20.0, 22.0], [90.0, 10.0, 10.0], [10.0, 20.0, 80.0]])
    } else {
        g.pick(&[
            [250.0, 250.0, 245.0],
            [250.0, 230.0, 60.0],
            [120.0, 240.0, 255.0],
        ])
    };
    words.push(format!("{} mark", if dark_mark { "dark" } else { "light" }));

    // The wall.
    let wall_kind = g.pick(&["dark", "light", "same-brightness", "any"]);
    let lit = ball_luma * 0.75;
    let wall: Rgb = match wall_kind {
        "dark" => hsv(g.unit(), g.range(0.0, 0.6), g.range(20.0, 90.0)),
        "light" => hsv(g.unit(), g.range(0.0, 0.5), g.range(170.0, 245.0)),
        "same-brightness" => with_luma(
            hsv(another_hue(ball, g.unit()), g.range(0.5, 0.9), 200.0),
            lit,
        ),
        _ => hsv(g.unit(), g.range(0.0, 1.0), g.range(20.0, 245.0)),
    };
    let texture = match g.pick(&TEXTURES) {
        "grain" => Texture::Grain {
            amp: g.range(4.0, 14.0),
        },
        "stripes" => Texture::Stripes {
            period: g.range(6.0, 2.0 * rpx.max(8.0)),
            angle: g.range(0.0, 180.0),
            amp: g.range(0.08, 0.3),
        },
        "checker" => Texture::Checker {
            size: g.range(0.4, 2.0) * rpx,
            other: with_luma(
                hsv(g.unit(), g.range(0.0, 0.8), 200.0),
                (luma(wall) + g.range(-80.0, 80.0)).clamp(10.0, 245.0),
            ),
        },
        "wood" => Texture::Wood {
            period: g.range(5.0, 25.0),
            amp: g.range(0.15, 0.4),
        },
        "clutter" => Texture::Clutter {
            count: g.range(6.0, 16.0) as usize,
        },
        _ => Texture::Plain,
    };
    let wall = if matches!(texture, Texture::Wood { .. }) && wall_kind == "any" {
        hsv(g.range(0.05, 0.1), g.range(0.4, 0.7), g.range(110.0, 200.0))
    } else {
        wall
    };
    words.push(format!(
        "{wall_kind} {} wall",
        match texture {
            Texture::Plain => "plain",
            Texture::Grain { .. } => "grainy",
            Texture::Stripes { .. } => "striped",
            Texture::Checker { .. } => "checkered",
            Texture::Wood { .. } => "wood-grain",
            Texture::Clutter { .. } => "cluttered",
        }
    ));
    let rail = hsv(g.unit(), g.range(0.0, 0.7), g.range(10.0, 250.0));
    words.push(format!(
        "rail {}",
        if luma(rail) > luma(wall) + 30.0 {
            "lighter"
        } else if luma(rail) < luma(wall) - 30.0 {
            "darker"
        } else {
            "alike"
        }
    ));

    // The light.
    let mut light = Light::EVEN;
    if g.chance(0.5) {
        light.left = g.range(0.6, 1.2);
        light.right = g.range(0.6, 1.2);
        words.push("uneven light".into());
    }
    if g.chance(0.3) {
        for s in &mut light.spots {
            *s = (
                g.unit(),
                g.range(0.1, 0.9),
                g.range(0.1, 0.4),
                g.range(0.2, 0.5),
            );
        }
        words.push("spots".into());
    }
    if g.chance(0.25) {
        light.shadow = (g.unit(), g.unit(), g.range(0.0, 360.0), g.range(0.55, 0.8));
        words.push("static shadow".into());
    }
    let cast = g.chance(0.35).then(|| Cast {
        offset: (g.range(-0.5, 0.5), g.range(0.1, 0.4)),
        factor: g.range(0.45, 0.8),
        blur: g.range(0.1, 0.4),
    });
    if cast.is_some() {
        words.push("moving shadows".into());
    }
    if tilt_deg != 0.0 {
        words.push(format!("tilt {tilt_deg:.1}°"));
    }
    words.push(format!("{fps} fps"));
    words.push(format!("{height}p"));
    if small_balls {
        words.push(format!("small balls (R {rpx:.0} px)"));
    }
    if let Some(c) = crf {
        words.push(format!("crf {c}"));
    }
    let paint = Paint {
        ball,
        finish,
        mark,
        wall: (wall, wall),
        texture,
        rail,
        rail_height: g.range(0.8, 4.0),
        light,
        cast,
        tint: [g.range(0.92, 1.08), 1.0, g.range(0.92, 1.08)],
    };
    let look = Look {
        width,
        height,
        px_per_m,
        tilt_deg,
        origin,
        fps,
        from,
        shutter,
        noise: g.range(1.0, 5.0),
        seed,
        paint,
        mark_at: g.range(0.4, 0.7),
        mark_size: g.range(0.1, 0.2),
        both: true,
        crf,
    };
    Drawn {
        look,
        to,
        name: words.join(", "),
    }
}

/// The smallest and largest centre x (m) either ball reaches from `from` to `to`.
fn extent(scene: &Scene, from: f64, to: f64) -> (f64, f64) {
    let s = engine::solve(
        scene,
        &Span {
            t_start: from - 0.01,
            t_end: Some(to + 0.01),
        },
    );
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for j in 0..=200 {
        let t = from + (to - from) * j as f64 / 200.0;
        let snap = s.at(t);
        for x in [snap.left.x, snap.right.x] {
            lo = lo.min(x);
            hi = hi.max(x);
        }
    }
    (lo, hi)
}

/// The clutter's shapes of a look (empty unless its wall is cluttered), seeded by it.
pub fn clutter(look: &Look) -> Vec<Shape> {
    let Texture::Clutter { count } = look.paint.texture else {
        return Vec::new();
    };
    let mut g = Rng::new(look.seed ^ 0xC1u64);
    let (w, h) = (look.width as f64, look.height as f64);
    let r = (look.height as f64 / 20.0).max(8.0);
    (0..count)
        .map(|_| {
            let disc = g.chance(0.5);
            let a = g.range(0.3, 1.4) * r;
            Shape {
                centre: (g.range(0.0, w), g.range(0.0, h)),
                size: if disc {
                    (a, a)
                } else {
                    (a, g.range(0.3, 1.4) * r)
                },
                disc,
                colour: hsv(g.unit(), g.range(0.0, 0.9), g.range(20.0, 245.0)),
            }
        })
        .collect()
}
