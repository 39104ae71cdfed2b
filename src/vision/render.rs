//! Synthetic videos of exactly solved scenes, to test the tracker against truth: the
//! two balls of a scene seen from the side, shaded (a light from the upper left), on
//! a near rail that hides their lower part (its top edge at the contact depth kR
//! below the centres), each with a dark mark at a chosen distance from its centre
//! turning with the exact spin angle; motion blur from the shutter time (the exposure
//! centred on the frame's time, sampled finely enough), a lighting gradient on the
//! background, seeded sensor noise; the camera may be tilted. Edges are
//! anti-aliased by the pixel's coverage of the edge.

use crate::physics::engine;
use crate::physics::scene::{Scene, Span};
use crate::physics::solution::Solution;
use crate::study::video::Noise;

use super::gray::Gray;

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
    /// Background luma from the left edge to the right edge (a lighting gradient).
    pub background: (f64, f64),
    /// The mark's distance from the centre and its radius, as fractions of R.
    pub mark_at: f64,
    pub mark_size: f64,
    /// Draw the right ball too.
    pub both: bool,
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
            background: (50.0, 85.0),
            mark_at: 0.55,
            mark_size: 0.12,
            both: true,
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
}

const BALL: f64 = 225.0;
const MARK: f64 = 30.0;
const RAIL: f64 = 38.0;

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
        Film {
            scene: *scene,
            look,
            solution,
            phase: [-a[0], -a[1]],
        }
    }

    /// The picture's axes: along the groove and up, unit vectors in pixels.
    fn axes(&self) -> ((f64, f64), (f64, f64)) {
        let a = self.look.tilt_deg.to_radians();
        ((a.cos(), a.sin()), (a.sin(), -a.cos()))
    }

    /// Both balls at time `t`: their centres and marks, px.
    #[allow(clippy::indexing_slicing)] // the two balls of a fixed pair
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

    /// Frame `k` as RGB bytes, row by row.
    pub fn rgb(&self, k: usize) -> Vec<u8> {
        let luma = self.luma(k);
        let mut out = Vec::with_capacity(luma.len() * 3);
        for v in luma {
            // A slightly cool picture; its luma (BT.601) is `v`.
            let (r, b) = (v * 0.97, v * 1.06);
            let g = (v - 0.299 * r - 0.114 * b) / 0.587;
            for c in [r, g, b] {
                out.push(c.round().clamp(0.0, 255.0) as u8);
            }
        }
        out
    }

    /// Frame `k` as an RGB picture.
    pub fn image(&self, k: usize) -> image::RgbImage {
        let (w, h) = (self.look.width as u32, self.look.height as u32);
        image::RgbImage::from_raw(w, h, self.rgb(k)).unwrap_or_else(|| image::RgbImage::new(w, h))
    }

    /// Frame `k` as the tracker takes it (from [`Film::image`]).
    pub fn frame(&self, k: usize) -> super::frame::Frame {
        super::frame::Frame::from_rgb(&self.image(k))
    }

    /// Frame `k`'s luma (of [`Film::rgb`], full range).
    #[allow(clippy::indexing_slicing)] // test films: pixels inside their own size
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

    /// Frame `k`'s luma before quantization, with noise.
    #[allow(clippy::indexing_slicing)] // test films: pixels inside their own size
    fn luma(&self, k: usize) -> Vec<f64> {
        let l = &self.look;
        let (w, h) = (l.width, l.height);
        let mut img = vec![0.0; w * h];
        let (u, up) = self.axes();
        let rail_top = self.scene.k() * self.scene.radius * l.px_per_m;
        let rail_bottom = rail_top + 0.8 * self.scene.radius * l.px_per_m;
        for y in 0..h {
            for x in 0..w {
                let fx = x as f64 / (w.max(2) - 1) as f64;
                img[y * w + x] = l.background.0 + (l.background.1 - l.background.0) * fx;
            }
        }
        self.draw_balls(&mut img, k);
        // The near rail in front of the balls.
        for y in 0..h {
            for x in 0..w {
                let (dx, dy) = (x as f64 - l.origin.0, y as f64 - l.origin.1);
                let below = -(dx * up.0 + dy * up.1);
                let _ = u;
                let cover = (0.5 + below - rail_top).clamp(0.0, 1.0)
                    * (0.5 + rail_bottom - below).clamp(0.0, 1.0);
                if cover > 0.0 {
                    let v = &mut img[y * w + x];
                    *v = *v * (1.0 - cover) + RAIL * cover;
                }
            }
        }
        let mut noise = Noise::new(l.seed.wrapping_mul(1_000_003).wrapping_add(k as u64));
        if l.noise > 0.0 {
            img.iter_mut().for_each(|v| *v += l.noise * noise.gauss());
        }
        img
    }

    /// The balls, blurred over the exposure, onto `img`.
    #[allow(clippy::indexing_slicing)] // the two balls of a fixed pair
    fn draw_balls(&self, img: &mut [f64], k: usize) {
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
    #[allow(clippy::indexing_slicing)] // test films: the box is clipped to the picture; poses is never empty
    fn draw_ball(&self, img: &mut [f64], poses: &[Truth]) {
        let l = &self.look;
        let (w, h) = (l.width as isize, l.height as isize);
        let r = poses[0].radius;
        let rho = self.look.mark_size * r;
        let light = {
            let v: [f64; 3] = [-0.45, -0.7, 0.55];
            let n = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
            [v[0] / n, v[1] / n, v[2] / n]
        };
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
                let bg = img[i];
                let mut sum = 0.0;
                for p in poses {
                    let (dx, dy) = (x as f64 - p.centre.0, y as f64 - p.centre.1);
                    let d = dx.hypot(dy);
                    let cover = (0.5 - (d - r)).clamp(0.0, 1.0);
                    if cover == 0.0 {
                        sum += bg;
                        continue;
                    }
                    let (qx, qy) = ((dx / r).clamp(-1.0, 1.0), (dy / r).clamp(-1.0, 1.0));
                    let qz = (1.0 - qx * qx - qy * qy).max(0.0).sqrt();
                    let lambert = (qx * light[0] + qy * light[1] + qz * light[2]).max(0.0);
                    let shade = BALL * (0.5 + 0.5 * lambert);
                    let dm = (x as f64 - p.mark.0).hypot(y as f64 - p.mark.1);
                    let m = (0.5 - (dm - rho)).clamp(0.0, 1.0);
                    let ball = shade * (1.0 - m) + MARK * m;
                    sum += bg * (1.0 - cover) + ball * cover;
                }
                img[i] = sum / n;
            }
        }
    }
}
