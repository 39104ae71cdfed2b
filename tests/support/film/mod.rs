//! Synthetic films of exactly solved scenes, to test the tracker against truth (test
//! support: used by the integration tests and the video benchmark, not by the
//! program): the two balls of a scene seen from the side, in colour (`paint`: the
//! balls' colour and finish, their marks, the wall's colour and texture, the near
//! rail board, the light, cast shadows), the rail hiding their lower part (its top
//! edge at the contact depth kR below the centres), each with a mark at a chosen
//! distance from its centre turning with the exact spin angle; motion blur from the
//! shutter time (the exposure centred on the frame's time, sampled finely enough),
//! seeded sensor noise; the camera may be tilted. Edges are anti-aliased by the
//! pixel's coverage of the edge. `looks` draws random looks from the whole range users
//! bring; `h264` passes frames through the encoder the way a phone's clip is.

#![allow(dead_code)]

pub mod h264;
pub mod looks;
pub mod paint;

use groovelab::physics::engine;
use groovelab::physics::scene::{Scene, Span};
use groovelab::physics::solution::Solution;
use groovelab::study::video::Noise;
use groovelab::vision::Gray;
use image::RgbImage;

use paint::{Paint, Rgb};

/// The camera and the look of the picture.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Look {
    pub width: usize,
    pub height: usize,
    /// Pixels per metre.
    pub px_per_m: f64,
    /// The groove's angle in the picture, degrees (positive: right end lower).
    pub tilt_deg: f64,
    /// Where the first impact point is in the picture, px.
    pub origin: (f64, f64),
    /// Frames per second; frame k shows time `from + k / fps`.
    pub fps: f64,
    /// The first frame's time, s (the first impact at 0).
    pub from: f64,
    /// Exposure time, s (0: sharp).
    pub shutter: f64,
    /// Sensor noise, luma levels (standard deviation).
    pub noise: f64,
    pub seed: u64,
    /// The colours, finishes, wall, rail and light.
    pub paint: Paint,
    /// The mark's distance from the centre and its radius, as fractions of R.
    pub mark_at: f64,
    pub mark_size: f64,
    /// Draw the right ball too.
    pub both: bool,
    /// The x264 constant rate factor the clip is to be encoded with (`None`: frames
    /// kept lossless); see `h264`.
    pub crf: Option<u32>,
}

impl Default for Look {
    fn default() -> Self {
        Look {
            width: 1280,
            height: 720,
            px_per_m: 2000.0,
            tilt_deg: 0.0,
            origin: (640.0, 330.0),
            fps: 100.0,
            from: -0.2,
            shutter: 1.0 / 1000.0,
            noise: 2.0,
            seed: 1,
            paint: Paint::default(),
            mark_at: 0.55,
            mark_size: 0.12,
            both: true,
            crf: None,
        }
    }
}

/// Where a ball and its mark are in a frame, px (the exposure's middle).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Truth {
    pub centre: (f64, f64),
    pub mark: (f64, f64),
    /// The ball's radius, px.
    pub radius: f64,
}

/// A scene filmed: its exact solution and the look.
pub struct Film {
    pub scene: Scene,
    pub look: Look,
    solution: Solution,
    /// Each ball's mark angle at the first frame (on top).
    phase: [f64; 2],
    /// What does not move, computed once: the lit wall, the light's factor, and the
    /// rail's cover of each pixel it touches (index, cover), row by row.
    wall: Vec<[f32; 3]>,
    light: Vec<f32>,
    rail: Vec<(u32, f32)>,
}

impl Film {
    /// Films `scene` with `look` from `look.from` to `to` (s).
    pub fn new(scene: &Scene, look: Look, to: f64) -> Film {
        let solution = engine::solve(
            scene,
            &Span {
                t_start: look.from.min(-1e-3) - 0.05,
                t_end: Some(to + 0.05),
            },
        );
        let a = solution.angle_at(look.from);
        let mut film = Film {
            scene: *scene,
            look,
            solution,
            phase: [-a[0], -a[1]],
            wall: Vec::new(),
            light: Vec::new(),
            rail: Vec::new(),
        };
        film.still();
        film
    }

    /// The scale, px/m.
    pub fn px_per_m(&self) -> f64 {
        self.look.px_per_m
    }

    /// The scene's true μ_k.
    pub fn mu(&self) -> f64 {
        self.scene.mu
    }

    /// The frames the film has from its start to `to` (s).
    pub fn frames_to(&self, to: f64) -> usize {
        ((to - self.look.from) * self.look.fps).floor() as usize + 1
    }

    /// Computes what does not move: the lit wall, the light and the rail's cover.
    fn still(&mut self) {
        let l = &self.look;
        let (w, h) = (l.width, l.height);
        let p = &l.paint;
        let clutter = looks::clutter(l);
        let aspect = w as f64 / h.max(1) as f64;
        self.light = Vec::with_capacity(w * h);
        self.wall = Vec::with_capacity(w * h);
        for y in 0..h {
            for x in 0..w {
                let f = p.light.at(
                    x as f64 / (w.max(2) - 1) as f64,
                    y as f64 / (h.max(2) - 1) as f64,
                    aspect,
                );
                let c = p.wall_at(x as f64, y as f64, w as f64, &clutter);
                self.light.push(f as f32);
                self.wall
                    .push([(c[0] * f) as f32, (c[1] * f) as f32, (c[2] * f) as f32]);
            }
        }
        let (_, up) = self.axes();
        let r = self.scene.radius * l.px_per_m;
        let rail_top = self.scene.k() * r;
        let rail_bottom = rail_top + p.rail_height * r;
        self.rail.clear();
        for y in 0..h {
            for x in 0..w {
                let (dx, dy) = (x as f64 - l.origin.0, y as f64 - l.origin.1);
                let below = -(dx * up.0 + dy * up.1);
                let cover = (0.5 + below - rail_top).clamp(0.0, 1.0)
                    * (0.5 + rail_bottom - below).clamp(0.0, 1.0);
                if cover > 0.0 {
                    self.rail.push(((y * w + x) as u32, cover as f32));
                }
            }
        }
    }

    /// The picture's axes: along the groove and up, unit vectors in pixels.
    fn axes(&self) -> ((f64, f64), (f64, f64)) {
        let a = self.look.tilt_deg.to_radians();
        ((a.cos(), a.sin()), (a.sin(), -a.cos()))
    }

    /// Both balls at time `t`: their centres and marks, px.
    pub fn at(&self, t: f64) -> [Truth; 2] {
        let (u, up) = self.axes();
        let s = self.look.px_per_m;
        let r = self.scene.radius;
        let snap = self.solution.at(t);
        let angle = self.solution.angle_at(t);
        let o = self.look.origin;
        let xs = [snap.left.x, snap.right.x];
        std::array::from_fn(|i| {
            let c = (o.0 + s * xs[i] * u.0, o.1 + s * xs[i] * u.1);
            let th = angle[i] + self.phase[i];
            let d = s * r * self.look.mark_at;
            let (a, b) = (d * th.sin(), d * th.cos());
            Truth {
                centre: c,
                mark: (c.0 + a * u.0 + b * up.0, c.1 + a * u.1 + b * up.1),
                radius: s * r,
            }
        })
    }

    /// The time of frame `k`, s.
    pub fn time(&self, k: usize) -> f64 {
        self.look.from + k as f64 / self.look.fps
    }

    /// The truth at frame `k`.
    pub fn truth(&self, k: usize) -> [Truth; 2] {
        self.at(self.time(k))
    }

    /// The true ball at frame `k` whose centre is nearest `(x, y)` (px): the ball a
    /// tracked centre is of.
    pub fn ball_nearest(&self, k: usize, (x, y): (f64, f64)) -> Truth {
        let [a, b] = self.truth(k);
        let d = |t: &Truth| (t.centre.0 - x).hypot(t.centre.1 - y);
        if d(&a) <= d(&b) { a } else { b }
    }

    /// Frame `k` as RGB bytes, row by row.
    pub fn rgb(&self, k: usize) -> Vec<u8> {
        self.image(k).into_raw()
    }

    /// Frame `k` as an RGB picture (what the camera gives, before any encoding).
    pub fn image(&self, k: usize) -> RgbImage {
        self.picture(k, true)
    }

    /// Frame `k` without the balls and their shadows (the same noise): the bench alone.
    pub fn empty(&self, k: usize) -> RgbImage {
        self.picture(k, false)
    }

    fn picture(&self, k: usize, balls: bool) -> RgbImage {
        let l = &self.look;
        let img = self.linear(k, balls);
        let mut noise = Noise::new(l.seed.wrapping_mul(1_000_003).wrapping_add(k as u64));
        let tint = l.paint.tint;
        let mut out = vec![0; img.len() * 3];
        // Sensor noise, the same on the three channels (as in luma), a row at a time.
        let mut row = vec![0.0; l.width];
        let rows = img.chunks(l.width).zip(out.chunks_mut(l.width * 3));
        for (pixels, outs) in rows {
            if l.noise > 0.0 {
                noise.fill_gauss(&mut row[..pixels.len()]);
            }
            for ((px, o), &g) in pixels.iter().zip(outs.chunks_exact_mut(3)).zip(&row) {
                let n = l.noise * g;
                for (c, o) in o.iter_mut().enumerate() {
                    let v = (f64::from(px[c]) + n) * tint[c];
                    // `v.round().clamp(0.0, 255.0) as u8` without libm's `round` (a call per
                    // channel, 8 % of a clip's rendering): adding a half is exact for every
                    // level from 0.5 up, and the cast saturates as the clamp did.
                    *o = (v + 0.5) as u8;
                }
            }
        }
        RgbImage::from_raw(l.width as u32, l.height as u32, out).expect("sized")
    }

    /// Frame `k` as the tracker takes it (from [`Film::image`]).
    pub fn frame(&self, k: usize) -> groovelab::vision::Frame {
        groovelab::vision::Frame::from_rgb(&self.image(k))
    }

    /// Frame `k`'s luma (BT.601 of [`Film::rgb`], full range).
    pub fn gray(&self, k: usize) -> Gray {
        let rgb = self.rgb(k);
        let data = rgb
            .chunks_exact(3)
            .map(|p| {
                (0.299 * f64::from(p[0]) + 0.587 * f64::from(p[1]) + 0.114 * f64::from(p[2]))
                    .round()
                    .clamp(0.0, 255.0) as u8
            })
            .collect();
        Gray {
            width: self.look.width,
            height: self.look.height,
            data,
        }
    }

    /// Frame `k`'s levels before noise, tint and rounding.
    fn linear(&self, k: usize, balls: bool) -> Vec<[f32; 3]> {
        let mut img = self.wall.clone();
        if balls {
            if let Some(cast) = self.look.paint.cast {
                self.draw_shadows(&mut img, k, cast);
            }
            self.draw_balls(&mut img, k);
        }
        // The near rail in front of the balls.
        let rail = self.look.paint.rail;
        for &(i, cover) in &self.rail {
            let i = i as usize;
            let f = self.light[i];
            for c in 0..3 {
                let v = &mut img[i][c];
                *v = *v * (1.0 - cover) + rail[c] as f32 * f * cover;
            }
        }
        img
    }

    /// The shadows the balls cast on the wall at frame `k`'s time.
    fn draw_shadows(&self, img: &mut [[f32; 3]], k: usize, cast: paint::Cast) {
        let l = &self.look;
        let (w, h) = (l.width as isize, l.height as isize);
        let balls = if l.both { 2 } else { 1 };
        for t in self.truth(k).iter().take(balls) {
            let r = t.radius;
            let (cx, cy) = (
                t.centre.0 + cast.offset.0 * r,
                t.centre.1 + cast.offset.1 * r,
            );
            let (rx, ry) = (1.1 * r, 0.9 * r);
            let soft = (cast.blur * r).max(0.5);
            let reach = rx + 2.0 * soft;
            for y in
                ((cy - reach).floor() as isize).max(0)..=((cy + reach).ceil() as isize).min(h - 1)
            {
                for x in ((cx - reach).floor() as isize).max(0)
                    ..=((cx + reach).ceil() as isize).min(w - 1)
                {
                    let (dx, dy) = ((x as f64 - cx) / rx, (y as f64 - cy) / ry);
                    // Beyond the soft edge nothing is shaded, whatever `hypot` rounds to.
                    let edge = 1.0 + soft / r;
                    if dx * dx + dy * dy > edge * edge * (1.0 + 1e-9) {
                        continue;
                    }
                    // Distance outside the ellipse, px (approximately).
                    let d = (dx.hypot(dy) - 1.0) * r;
                    let inside = (0.5 - d / (2.0 * soft)).clamp(0.0, 1.0);
                    if inside > 0.0 {
                        let f = (1.0 + (cast.factor - 1.0) * inside) as f32;
                        let v = &mut img[(y * w + x) as usize];
                        v.iter_mut().for_each(|c| *c *= f);
                    }
                }
            }
        }
    }

    /// The balls, blurred over the exposure, onto `img`.
    fn draw_balls(&self, img: &mut [[f32; 3]], k: usize) {
        let l = &self.look;
        let t = self.time(k);
        let ends = [self.at(t - 0.5 * l.shutter), self.at(t + 0.5 * l.shutter)];
        let travel = (0..2)
            .map(|i| {
                let (a, b) = (ends[0][i], ends[1][i]);
                (a.centre.0 - b.centre.0)
                    .hypot(a.centre.1 - b.centre.1)
                    .max((a.mark.0 - b.mark.0).hypot(a.mark.1 - b.mark.1))
            })
            .fold(0.0, f64::max);
        let subs = ((travel / 0.25).ceil() as usize).clamp(1, 64);
        let times: Vec<f64> = (0..subs)
            .map(|j| t + l.shutter * ((j as f64 + 0.5) / subs as f64 - 0.5))
            .collect();
        let balls = if l.both { 2 } else { 1 };
        for i in 0..balls {
            let poses: Vec<Truth> = times.iter().map(|&ts| self.at(ts)[i]).collect();
            self.draw_ball(img, &poses);
        }
    }

    /// One ball at each of its `poses` over the exposure, averaged.
    fn draw_ball(&self, img: &mut [[f32; 3]], poses: &[Truth]) {
        let l = &self.look;
        let paint = &l.paint;
        let (w, h) = (l.width as isize, l.height as isize);
        let r = poses[0].radius;
        let rho = self.look.mark_size * r;
        let xs = poses.iter().map(|p| p.centre.0);
        let ys = poses.iter().map(|p| p.centre.1);
        let x0 = (xs.clone().fold(f64::INFINITY, f64::min) - r - 2.0).floor() as isize;
        let x1 = (xs.fold(f64::NEG_INFINITY, f64::max) + r + 2.0).ceil() as isize;
        let y0 = (ys.clone().fold(f64::INFINITY, f64::min) - r - 2.0).floor() as isize;
        let y1 = (ys.fold(f64::NEG_INFINITY, f64::max) + r + 2.0).ceil() as isize;
        let n = poses.len() as f64;
        for y in y0.max(0)..=y1.min(h - 1) {
            for x in x0.max(0)..=x1.min(w - 1) {
                let i = (y * w + x) as usize;
                let bg = img[i].map(f64::from);
                let light = f64::from(self.light[i]);
                let mut sum = [0.0; 3];
                for p in poses {
                    let (dx, dy) = (x as f64 - p.centre.0, y as f64 - p.centre.1);
                    let cover = edge_cover(dx, dy, r);
                    if cover == 0.0 {
                        (0..3).for_each(|c| sum[c] += bg[c]);
                        continue;
                    }
                    let (qx, qy) = ((dx / r).clamp(-1.0, 1.0), (dy / r).clamp(-1.0, 1.0));
                    let shade = paint.shade(qx, qy);
                    let m = edge_cover(x as f64 - p.mark.0, y as f64 - p.mark.1, rho);
                    let ball: Rgb = paint::mix(shade, paint.mark, m);
                    (0..3).for_each(|c| sum[c] += bg[c] * (1.0 - cover) + ball[c] * light * cover);
                }
                img[i] = sum.map(|v| (v / n) as f32);
            }
        }
    }
}

/// How much of the pixel `(dx, dy)` from the centre of a disc of radius `r` the disc
/// covers (0 … 1), anti-aliased over a pixel of its edge: `0.5 − (d − r)` clamped.
/// Far outside it and well inside it the clamp decides whatever `hypot` rounds to:
/// those pixels (most of a ball's box, and of a mark's) skip the call.
fn edge_cover(dx: f64, dy: f64, r: f64) -> f64 {
    let d2 = dx * dx + dy * dy;
    if d2 > (r + 0.5) * (r + 0.5) * (1.0 + 1e-9) {
        0.0
    } else if r > 0.5 && d2 < (r - 0.5) * (r - 0.5) * (1.0 - 1e-9) {
        1.0
    } else {
        (0.5 - (dx.hypot(dy) - r)).clamp(0.0, 1.0)
    }
}

/// The frames `0..n` of `film` as RGB pictures.
pub fn images(film: &Film, n: usize) -> Vec<RgbImage> {
    (0..n).map(|k| film.image(k)).collect()
}
