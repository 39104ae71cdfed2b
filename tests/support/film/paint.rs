//! What the things in a film look like, in colour: the balls' colour and finish
//! (matte, glossy with a highlight, metallic), their marks, the wall's colour and
//! texture (noise, stripes, checker, wood grain, a clutter of other shapes), the near
//! rail board, the light (a gradient, spots, a static shadow) and the shadows the
//! balls cast. Levels are 0–255 per channel, before noise and rounding.

/// An RGB colour, levels 0–255 per channel.
pub type Rgb = [f64; 3];

/// The luma (BT.601) of `c`.
pub fn luma(c: Rgb) -> f64 {
    0.299 * c[0] + 0.587 * c[1] + 0.114 * c[2]
}

/// `c` scaled by `f` per channel.
pub fn scaled(c: Rgb, f: f64) -> Rgb {
    [c[0] * f, c[1] * f, c[2] * f]
}

/// `a` blended toward `b` by `t` (0: `a`, 1: `b`).
pub fn mix(a: Rgb, b: Rgb, t: f64) -> Rgb {
    [
        a[0] + (b[0] - a[0]) * t,
        a[1] + (b[1] - a[1]) * t,
        a[2] + (b[2] - a[2]) * t,
    ]
}

/// How a ball's surface answers the light.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Finish {
    /// Lambert shading over `ambient` (0–1) of its colour.
    Matte { ambient: f64 },
    /// Matte, with a white specular highlight of `strength` (0–1) toward the light.
    Glossy { ambient: f64, strength: f64 },
    /// Polished metal: the room mirrored (bright above, dark below) and a sharp
    /// highlight, tinted by its colour.
    Metallic,
}

/// The wall's pattern (static: it does not move with the balls).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Texture {
    Plain,
    /// Fixed grain of `amp` levels (standard deviation).
    Grain {
        amp: f64,
    },
    /// Stripes of `period` px at `angle` degrees, the colour scaled by 1 ± `amp`.
    Stripes {
        period: f64,
        angle: f64,
        amp: f64,
    },
    /// Squares of `size` px, alternately the wall colour and `other`.
    Checker {
        size: f64,
        other: Rgb,
    },
    /// Wood grain: wavy bands of `period` px, darker by up to `amp` (0–1).
    Wood {
        period: f64,
        amp: f64,
    },
    /// `count` other shapes (discs of about the balls' size and smaller, boxes) in
    /// colours of their own, seeded.
    Clutter {
        count: usize,
    },
}

/// The light over the whole picture (wall, balls and rail alike), a factor per pixel.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Light {
    /// The factor at the left and right edges (a gradient between).
    pub left: f64,
    pub right: f64,
    /// Up to two bright spots: centre as fractions of width and height, radius as a
    /// fraction of the height, and the added factor at the centre (0: none).
    pub spots: [(f64, f64, f64, f64); 2],
    /// A static shadow over the part of the picture beyond a soft line through
    /// (fraction of width, fraction of height) at `angle` degrees: its factor (1: none).
    pub shadow: (f64, f64, f64, f64),
}

impl Light {
    /// Even light.
    pub const EVEN: Light = Light {
        left: 1.0,
        right: 1.0,
        spots: [(0.0, 0.0, 0.0, 0.0); 2],
        shadow: (0.5, 0.5, 0.0, 1.0),
    };

    /// The factor at `(fx, fy)`, fractions of the width and height; `aspect` is
    /// width / height.
    pub fn at(&self, fx: f64, fy: f64, aspect: f64) -> f64 {
        let mut f = self.left + (self.right - self.left) * fx;
        for &(sx, sy, sr, gain) in &self.spots {
            if gain != 0.0 && sr > 0.0 {
                let d2 = ((fx - sx) * aspect).powi(2) + (fy - sy).powi(2);
                f += gain * (-d2 / (2.0 * sr * sr)).exp();
            }
        }
        let (lx, ly, angle, dark) = self.shadow;
        if dark != 1.0 {
            let a = angle.to_radians();
            // Signed distance from the line, in heights; soft over 2 % of the height.
            let s = ((fx - lx) * aspect * a.sin() - (fy - ly) * a.cos()) / 0.02;
            let inside = 0.5 + 0.5 * s.clamp(-1.0, 1.0);
            f *= 1.0 + (dark - 1.0) * inside;
        }
        f
    }
}

/// The shadow each ball casts on the wall, which moves with it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Cast {
    /// Offset from the ball's centre, in radii (x right, y down).
    pub offset: (f64, f64),
    /// The wall's factor inside the shadow (1: no shadow).
    pub factor: f64,
    /// Its soft edge, in radii.
    pub blur: f64,
}

/// The colours and finishes of a film.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Paint {
    /// Each ball's colour (the lit side's level is about this) and finish.
    pub ball: Rgb,
    pub finish: Finish,
    /// The mark's colour (darker or lighter than the ball).
    pub mark: Rgb,
    /// The wall's colour at the left and right edges (a painted gradient), and its
    /// pattern.
    pub wall: (Rgb, Rgb),
    pub texture: Texture,
    /// The near rail board's colour and its height, in radii (from the contact line
    /// down).
    pub rail: Rgb,
    pub rail_height: f64,
    pub light: Light,
    /// The balls' cast shadows (`None`: none).
    pub cast: Option<Cast>,
    /// A colour cast of the whole picture, a factor per channel (white balance).
    pub tint: Rgb,
}

/// The cool grey tint of the project's first films: luma kept, red down, blue up.
const COOL: Rgb = [0.97, (1.0 - 0.299 * 0.97 - 0.114 * 1.06) / 0.587, 1.06];

impl Default for Paint {
    /// The project's first look: light grey matte balls with dark marks on a dark
    /// grey wall lit more on the right, a thin dark rail, a slightly cool picture.
    fn default() -> Self {
        Paint {
            ball: [225.0; 3],
            finish: Finish::Matte { ambient: 0.5 },
            mark: [30.0; 3],
            wall: ([50.0; 3], [85.0; 3]),
            texture: Texture::Plain,
            rail: [38.0; 3],
            rail_height: 0.8,
            light: Light::EVEN,
            cast: None,
            tint: COOL,
        }
    }
}

/// The unit vector toward the light (from the upper left, toward the camera).
const LIGHT: [f64; 3] = [-0.45, -0.7, 0.55];

impl Paint {
    /// The ball's colour at the point of its disc `(qx, qy)` (unit radius, y down)
    /// before the light's factor.
    pub fn shade(&self, qx: f64, qy: f64) -> Rgb {
        let n = (LIGHT[0] * LIGHT[0] + LIGHT[1] * LIGHT[1] + LIGHT[2] * LIGHT[2]).sqrt();
        let l = [LIGHT[0] / n, LIGHT[1] / n, LIGHT[2] / n];
        let qz = (1.0 - qx * qx - qy * qy).max(0.0).sqrt();
        let lambert = (qx * l[0] + qy * l[1] + qz * l[2]).max(0.0);
        // The highlight: the normal's alignment with the half-vector of the light
        // and the view (0, 0, 1).
        let h = {
            let v = [l[0], l[1], l[2] + 1.0];
            let m = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
            [v[0] / m, v[1] / m, v[2] / m]
        };
        let spec = (qx * h[0] + qy * h[1] + qz * h[2]).max(0.0);
        match self.finish {
            Finish::Matte { ambient } => scaled(self.ball, ambient + (1.0 - ambient) * lambert),
            Finish::Glossy { ambient, strength } => {
                let base = scaled(self.ball, ambient + (1.0 - ambient) * lambert);
                mix(base, [255.0; 3], strength * spec.powi(40))
            }
            Finish::Metallic => {
                // The room mirrored: the reflected ray's upward part (bright ceiling,
                // dark floor), with a band of horizon.
                let up = -qy;
                let room = 0.25 + 0.6 * (0.5 + 0.5 * up).powf(1.5);
                let base = scaled(self.ball, room);
                mix(base, [255.0; 3], 0.8 * spec.powi(80))
            }
        }
    }

    /// The wall's colour at pixel `(x, y)` of a `w × h` picture, before the light;
    /// `clutter` holds the clutter's shapes.
    pub fn wall_at(&self, x: f64, y: f64, w: f64, clutter: &[Shape]) -> Rgb {
        let fx = x / (w - 1.0).max(1.0);
        let base = mix(self.wall.0, self.wall.1, fx);
        match self.texture {
            Texture::Plain => base,
            Texture::Grain { amp } => {
                let g = amp * hash_gauss(x as u64, y as u64);
                [base[0] + g, base[1] + g, base[2] + g]
            }
            Texture::Stripes { period, angle, amp } => {
                let a = angle.to_radians();
                let s = (x * a.cos() + y * a.sin()) / period;
                scaled(base, 1.0 + amp * (std::f64::consts::TAU * s).sin())
            }
            Texture::Checker { size, other } => {
                // Anti-aliased: the blend over the pixel's edge.
                let along = |v: f64| {
                    let t = v / size;
                    let d = (t - t.round()).abs() * size; // px to the nearest edge
                    let side = (t.floor() as i64).rem_euclid(2) as f64;
                    (side, (d + 0.5).min(1.0))
                };
                let (sx, cx) = along(x);
                let (sy, cy) = along(y);
                let parity = (sx + sy) % 2.0;
                let t = parity * cx * cy + (1.0 - parity) * (1.0 - cx * cy);
                mix(other, base, t.clamp(0.0, 1.0))
            }
            Texture::Wood { period, amp } => {
                let warp = 6.0 * (x / 90.0).sin() + 3.0 * (x / 23.0 + y / 40.0).sin();
                let ring = ((y + warp) / period * std::f64::consts::TAU).sin();
                scaled(base, 1.0 - amp * (0.5 + 0.5 * ring).powi(3))
            }
            Texture::Clutter { .. } => clutter
                .iter()
                .rev()
                .find_map(|s| s.cover(x, y).map(|c| mix(base, s.colour, c)))
                .unwrap_or(base),
        }
    }
}

/// One shape of a clutter: a disc or a box.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Shape {
    pub centre: (f64, f64),
    /// A disc's radius, or a box's half width and half height.
    pub size: (f64, f64),
    pub disc: bool,
    pub colour: Rgb,
}

impl Shape {
    /// How much of pixel `(x, y)` the shape covers (None: none).
    fn cover(&self, x: f64, y: f64) -> Option<f64> {
        let (dx, dy) = (x - self.centre.0, y - self.centre.1);
        let c = if self.disc {
            (0.5 - (dx.hypot(dy) - self.size.0)).clamp(0.0, 1.0)
        } else {
            (0.5 - (dx.abs() - self.size.0)).clamp(0.0, 1.0)
                * (0.5 - (dy.abs() - self.size.1)).clamp(0.0, 1.0)
        };
        (c > 0.0).then_some(c)
    }
}

/// A fixed standard normal number for pixel `(x, y)` (a static grain).
fn hash_gauss(x: u64, y: u64) -> f64 {
    let mut r = Rng::new(x.wrapping_mul(0x9E37_79B9) ^ y.wrapping_mul(0x85EB_CA6B) ^ 0x5bd1);
    r.gauss()
}

/// A small seeded generator (SplitMix64): the same looks on every platform.
#[derive(Clone, Debug)]
pub struct Rng(u64);

impl Rng {
    pub fn new(seed: u64) -> Rng {
        Rng(seed ^ 0x9E37_79B9_7F4A_7C15)
    }

    /// Uniform in [0, 1).
    pub fn unit(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^= z >> 31;
        (z >> 11) as f64 / (1u64 << 53) as f64
    }

    /// Uniform in [a, b).
    pub fn range(&mut self, a: f64, b: f64) -> f64 {
        a + (b - a) * self.unit()
    }

    /// One of `items`.
    pub fn pick<T: Copy>(&mut self, items: &[T]) -> T {
        items[((self.unit() * items.len() as f64) as usize).min(items.len() - 1)]
    }

    /// True with probability `p`.
    pub fn chance(&mut self, p: f64) -> bool {
        self.unit() < p
    }

    /// A standard normal number (Box–Muller).
    pub fn gauss(&mut self) -> f64 {
        let (u, v) = (self.unit().max(1e-300), self.unit());
        (-2.0 * u.ln()).sqrt() * (std::f64::consts::TAU * v).cos()
    }
}
