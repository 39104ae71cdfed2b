//! A ball's own picture, stacked from the frames it was found in: about each fit a
//! patch of the frame is kept (whole pixels, as decoded), the patches registered at
//! their centres and averaged per pixel (a trimmed mean: the wall behind a rolling
//! ball differs in every frame and averages out, the ball's disc, its shading and
//! the rail below it do not; its mark turns and is trimmed away). Each patch's
//! centre is then matched to that picture (a translation by Gauss–Newton on the
//! disc's pixels, robust weights), the picture stacked again at the matched
//! centres, and its outline fitted once: where a wall of the ball's brightness or
//! pattern scatters the single frames' outlines (radii 6–16 % apart on the looks
//! table), the stack shows one clean edge. Used only where the frames' radii
//! disagree (`Tracker::restacked`); as Tracker's autotracker matches an evolving
//! template, and as a median background removes the bench.

use super::circle::{self, Circle, Outline};
use super::frame::Frame;
use super::gray::Gray;
use super::select;
use rayon::prelude::*;

/// A ball's neighbourhood in one frame: the luma rows and the colour planes' rows
/// about the fit's centre at the cut, copied as decoded.
#[derive(Clone, Debug, PartialEq)]
pub struct Patch {
    /// The fit's centre when cut (full-frame px): what offsets are measured from.
    pub centre: (f64, f64),
    /// Full-frame px of the luma block's first pixel.
    x0: i64,
    y0: i64,
    w: usize,
    h: usize,
    y: Vec<u8>,
    /// Colour samples of the block's colour rows (half size).
    cx0: i64,
    cy0: i64,
    cw: usize,
    ch: usize,
    u: Vec<u8>,
    v: Vec<u8>,
}

impl Patch {
    /// The block of `frame` `half` px each way about `centre`, clipped to the frame;
    /// `None` where nothing of it is in the frame.
    pub fn cut(frame: &Frame, centre: (f64, f64), half: usize) -> Option<Patch> {
        let (fw, fh) = (frame.width() as i64, frame.height() as i64);
        let h = half as i64;
        let (cx, cy) = (centre.0.round() as i64, centre.1.round() as i64);
        let (x0, x1) = ((cx - h).max(0), (cx + h + 1).min(fw));
        let (y0, y1) = ((cy - h).max(0), (cy + h + 1).min(fh));
        if x1 <= x0 || y1 <= y0 || !centre.0.is_finite() || !centre.1.is_finite() {
            return None;
        }
        let rows = |plane: &[u8], stride: usize, (a, b): (i64, i64), (c, d): (i64, i64)| {
            let mut out = Vec::with_capacity(((b - a) * (d - c)) as usize);
            for row in c..d {
                let at = row as usize * stride;
                out.extend_from_slice(plane.get(at + a as usize..at + b as usize)?);
            }
            Some(out)
        };
        let y = rows(&frame.luma.data, frame.luma.width, (x0, x1), (y0, y1))?;
        let (cw_all, ch_all) = (frame.chroma_width as i64, frame.chroma_height as i64);
        let (cx0, cx1) = ((x0 / 2).min(cw_all), ((x1 + 1) / 2).min(cw_all));
        let (cy0, cy1) = ((y0 / 2).min(ch_all), ((y1 + 1) / 2).min(ch_all));
        let u = rows(&frame.u, frame.chroma_width, (cx0, cx1), (cy0, cy1))?;
        let v = rows(&frame.v, frame.chroma_width, (cx0, cx1), (cy0, cy1))?;
        Some(Patch {
            centre,
            x0,
            y0,
            w: (x1 - x0) as usize,
            h: (y1 - y0) as usize,
            y,
            cx0,
            cy0,
            cw: (cx1 - cx0).max(0) as usize,
            ch: (cy1 - cy0).max(0) as usize,
            u,
            v,
        })
    }

    /// Bytes held.
    pub fn bytes(&self) -> usize {
        self.y.len() + self.u.len() + self.v.len()
    }

    /// Y, U and V at `q` px from the cut's centre (bilinear; a colour sample's
    /// middle at full-frame px 2 i + 0.5), `None` outside the block.
    fn at(&self, q: (f64, f64)) -> Option<[f32; 3]> {
        let (x, y) = (self.centre.0 + q.0, self.centre.1 + q.1);
        let luma = bilinear(
            &self.y,
            self.w,
            self.h,
            x - self.x0 as f64,
            y - self.y0 as f64,
        )?;
        let (ux, uy) = (
            (x - 0.5) / 2.0 - self.cx0 as f64,
            (y - 0.5) / 2.0 - self.cy0 as f64,
        );
        // Both colour planes at one place: its corners and weights found once.
        let at = Bilinear::at(self.cw, self.ch, ux.max(0.0), uy.max(0.0))?;
        Some([luma, at.of(&self.u)?, at.of(&self.v)?])
    }
}

/// The plane `p` (`w × h`) at (x, y) by bilinear interpolation; `None` outside.
fn bilinear(p: &[u8], w: usize, h: usize, x: f64, y: f64) -> Option<f32> {
    Bilinear::at(w, h, x, y)?.of(p)
}

/// Where a bilinear interpolation at (x, y) reads a plane `w × h`: its four
/// samples' indices and the weights (fractions) across and down.
struct Bilinear {
    corners: [usize; 4],
    fx: f32,
    fy: f32,
}

impl Bilinear {
    /// The interpolation at (x, y), `None` outside the plane.
    fn at(w: usize, h: usize, x: f64, y: f64) -> Option<Bilinear> {
        if !(x >= 0.0 && y >= 0.0) || w == 0 || h == 0 {
            return None;
        }
        // Truncation is the floor of these non-negative values (and no call into
        // libm's `floor`: a twelfth of the stacking's time).
        let (i, j) = (x as usize, y as usize);
        if i >= w || j >= h {
            return None;
        }
        let (fx, fy) = ((x - i as f64) as f32, (y - j as f64) as f32);
        let (i1, j1) = ((i + 1).min(w - 1), (j + 1).min(h - 1));
        Some(Bilinear {
            corners: [j * w + i, j * w + i1, j1 * w + i, j1 * w + i1],
            fx,
            fy,
        })
    }

    /// Plane `p`'s value here (`None` where `p` is short of the plane).
    fn of(&self, p: &[u8]) -> Option<f32> {
        let g = |k: usize| p.get(k).map(|&v| f32::from(v));
        let [a, b, c, d] = self.corners;
        let (a, b, c, d) = (g(a)?, g(b)?, g(c)?, g(d)?);
        let (fx, fy) = (self.fx, self.fy);
        Some(a * (1.0 - fx) * (1.0 - fy) + b * fx * (1.0 - fy) + c * (1.0 - fx) * fy + d * fx * fy)
    }
}

/// A ball's stacked picture: Y, U, V per pixel of a square `2 half + 1` wide,
/// its middle at the registered centres; `None` where too few patches cover it.
#[derive(Clone, Debug, PartialEq)]
pub struct Picture {
    pub half: usize,
    px: Vec<Option<[f32; 3]>>,
}

impl Picture {
    fn side(&self) -> usize {
        2 * self.half + 1
    }

    fn get(&self, i: usize, j: usize) -> Option<[f32; 3]> {
        self.px.get(j * self.side() + i).copied().flatten()
    }

    /// How far each pixel differs from the wall about the disc (radius `radius`
    /// about `mid`, px from the middle): per 30° sector the median colour of a ring
    /// 1.5–1.7 radii out (the wall averaged over the frames, the rail below), and
    /// each pixel's distance from its sector's (colour weighted by `cw`), as whole
    /// levels: the ball bright on a dark surround whatever its shading and the wall's
    /// pattern, where brightness alone loses a limb on a wall of its brightness.
    pub fn difference(&self, mid: (f64, f64), radius: f64, cw: f32) -> Gray {
        let side = self.side();
        let h = self.half as f64;
        let sector = |q: (f64, f64)| {
            let a = (q.1 - mid.1).atan2(q.0 - mid.0).to_degrees() + 180.0;
            ((a / 30.0) as usize).min(11)
        };
        let mut rings: Vec<[Vec<f32>; 3]> = vec![Default::default(); 12];
        for j in 0..side {
            for i in 0..side {
                let q = (i as f64 - h, j as f64 - h);
                let d = (q.0 - mid.0).hypot(q.1 - mid.1) / radius;
                if let (true, Some(v), Some(ring)) = (
                    (1.5..=1.7).contains(&d),
                    self.get(i, j),
                    rings.get_mut(sector(q)),
                ) {
                    for (r, x) in ring.iter_mut().zip(v) {
                        r.push(x);
                    }
                }
            }
        }
        let wall: Vec<Option<[f32; 3]>> = rings
            .iter_mut()
            .map(|ring| {
                let mut out = [0.0f32; 3];
                for (o, r) in out.iter_mut().zip(ring.iter_mut()) {
                    *o = select::median(r)?;
                }
                Some(out)
            })
            .collect();
        let mut data = Vec::with_capacity(side * side);
        for j in 0..side {
            for i in 0..side {
                let q = (i as f64 - h, j as f64 - h);
                let d = match (self.get(i, j), wall.get(sector(q)).copied().flatten()) {
                    (Some(v), Some(w)) => ((v[0] - w[0]).powi(2)
                        + (cw * (v[1] - w[1])).powi(2)
                        + (cw * (v[2] - w[2])).powi(2))
                    .sqrt(),
                    _ => 0.0,
                };
                data.push(super::gray::level(d));
            }
        }
        Gray {
            width: side,
            height: side,
            data,
        }
    }

    /// Whether the picture's difference from the wall has fallen to it just
    /// outside the circle `c` (px in the picture), over its upper half (the lower
    /// is the rail's): at 1.1–1.2 radii, risen from the wall's level (1.5–1.7
    /// radii) by at most `STEP_OUTSIDE` of the way to the disc's (0.4–0.6 radii).
    /// A glossy ball's lit part, fading into a limb as dark as the wall, gives an
    /// outline inside the ball with the ball still about it.
    pub fn steps_at(&self, c: Circle, cw: f32) -> bool {
        let h = self.half as f64;
        let diff = self.difference((c.x - h, c.y - h), c.r, cw);
        let band = |lo: f64, hi: f64| {
            let (mut sum, mut n) = (0.0, 0usize);
            for j in 0..diff.height {
                for i in 0..diff.width {
                    let (dx, dy) = (i as f64 - c.x, j as f64 - c.y);
                    let d = dx.hypot(dy) / c.r;
                    if dy < 0.0 && (lo..hi).contains(&d) {
                        sum += f64::from(diff.at(i, j));
                        n += 1;
                    }
                }
            }
            (n > 0).then(|| sum / n as f64)
        };
        let (Some(disc), Some(outer), Some(wall)) =
            (band(0.4, 0.6), band(1.1, 1.2), band(1.5, 1.7))
        else {
            return false;
        };
        let rise = disc - wall;
        rise > 0.0 && outer - wall <= STEP_OUTSIDE * rise
    }

    /// Its luma as a picture of whole levels (for the outline's fit), pixels no
    /// patch covered at the mean level.
    pub fn luma(&self) -> Gray {
        let side = self.side();
        let known: Vec<f32> = self.px.iter().flatten().map(|p| p[0]).collect();
        let fill = known.iter().sum::<f32>() / known.len().max(1) as f32;
        Gray {
            width: side,
            height: side,
            data: self
                .px
                .iter()
                .map(|p| super::gray::level(p.map_or(fill, |p| p[0])))
                .collect(),
        }
    }
}

/// Share of the patches left out at each end of each pixel's sorted values: the
/// mark (a fifth of the frames at most over any pixel as it turns), a highlight's
/// or a wall's extremes.
const TRIM: f64 = 0.2;

/// How far a picture's difference from the wall may have risen toward the
/// disc's at 1.1–1.2 radii (`Picture::steps_at`): 0.07–0.12 on the looks table's
/// balls measured right, 0.18 on small look 18's lit part (12 % small); small looks
/// 13 and 20 (0.19–0.20, measured right) are refused by it too.
const STEP_OUTSIDE: f64 = 0.15;

/// The patches registered at their cut centres moved by `offsets` (px), averaged
/// per pixel and plane (trimmed mean), over a square `half` pixels each way, the
/// pixels `step` px apart.
pub fn stacked(patches: &[&Patch], offsets: &[(f64, f64)], half: usize, step: f64) -> Picture {
    let side = 2 * half + 1;
    let h = half as f64;
    // Each pixel on its own: on the cores at once, in the same order as one by one.
    let px = (0..side * side)
        .into_par_iter()
        .map_init(<[Vec<f32>; 3]>::default, |vals, at| {
            let (i, j) = (at % side, at / side);
            vals.iter_mut().for_each(Vec::clear);
            for (p, o) in patches.iter().zip(offsets) {
                let q = ((i as f64 - h) * step + o.0, (j as f64 - h) * step + o.1);
                if let Some(s) = p.at(q) {
                    for (v, x) in vals.iter_mut().zip(s) {
                        v.push(x);
                    }
                }
            }
            trimmed(vals)
        })
        .collect();
    Picture { half, px }
}

/// The trimmed mean of each plane's values, `None` with fewer than 5.
fn trimmed(vals: &mut [Vec<f32>; 3]) -> Option<[f32; 3]> {
    let n = vals[0].len();
    if n < 5 {
        return None;
    }
    let cut = (n as f64 * TRIM).floor() as usize;
    let mut out = [0.0f32; 3];
    for (o, v) in out.iter_mut().zip(vals.iter_mut()) {
        // The middle values found by two selections, then only they sorted: the
        // same values summed in the same (rising) order as a whole sort gives, at
        // under half its cost (the stacking's largest part).
        if cut > 0 {
            v.select_nth_unstable_by(cut - 1, f32::total_cmp);
            let upper = v.get_mut(cut..)?;
            upper.select_nth_unstable_by(n - 2 * cut, f32::total_cmp);
        }
        let kept = v.get_mut(cut..n - cut)?;
        kept.sort_by(f32::total_cmp);
        *o = kept.iter().sum::<f32>() / kept.len().max(1) as f32;
    }
    Some(out)
}

/// Where a patch's ball lies against a picture: its offset from the cut's centre
/// (px; the picture's middle maps to the cut centre plus it), that offset's
/// standard error, and the residual's robust scale (levels).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Match {
    pub offset: (f64, f64),
    pub sigma: f64,
    pub residual: f64,
}

/// The pixels of the picture's disc the match compares: within `radius` of the
/// disc's middle `mid` (px from the picture's middle), every `stride`-th.
fn disc(pic: &Picture, mid: (f64, f64), radius: f64, stride: usize) -> Vec<((f64, f64), [f32; 3])> {
    let side = pic.side();
    let h = pic.half as f64;
    let mut out = Vec::new();
    for j in (0..side).step_by(stride.max(1)) {
        for i in (0..side).step_by(stride.max(1)) {
            let q = (i as f64 - h, j as f64 - h);
            if (q.0 - mid.0).hypot(q.1 - mid.1) <= radius
                && let Some(t) = pic.get(i, j)
            {
                out.push((q, t));
            }
        }
    }
    out
}

/// The patch's values against the picture's at the offset `o`: per pixel and plane
/// the difference (colour weighted by `cw`), `None` where the patch ends.
fn residuals(
    patch: &Patch,
    pixels: &[((f64, f64), [f32; 3])],
    o: (f64, f64),
    cw: f32,
) -> Option<Vec<f32>> {
    let mut r = Vec::with_capacity(3 * pixels.len());
    for (q, t) in pixels {
        let s = patch.at((q.0 + o.0, q.1 + o.1))?;
        r.push(s[0] - t[0]);
        r.push(cw * (s[1] - t[1]));
        r.push(cw * (s[2] - t[2]));
    }
    Some(r)
}

/// The offset of `patch`'s ball against `pic` whose disc (radius `radius` about
/// `mid`) it is matched on: the whole offsets within `reach` of `start` tried
/// (every second, then about the best), then Gauss–Newton steps with Huber weights
/// (the mark, a highlight, a shadow's edge weigh less). `cw`: the colour planes'
/// weight against luma.
pub fn matched(
    patch: &Patch,
    pic: &Picture,
    (mid, radius): ((f64, f64), f64),
    start: (f64, f64),
    reach: f64,
    cw: f32,
) -> Option<Match> {
    let stride = ((radius / 16.0).floor() as usize).max(1);
    let coarse = disc(pic, mid, radius, 2 * stride);
    let sad = |o: (f64, f64)| {
        residuals(patch, &coarse, o, cw).map(|r| r.iter().map(|v| v.abs()).sum::<f32>())
    };
    let consider = |best: &mut Option<((f64, f64), f32)>, o: (f64, f64)| {
        if let Some(s) = sad(o)
            && best.is_none_or(|(_, b)| s < b)
        {
            *best = Some((o, s));
        }
    };
    let mut best = None;
    let n = reach.ceil() as i64;
    for dj in (-n..=n).step_by(2) {
        for di in (-n..=n).step_by(2) {
            consider(&mut best, (start.0 + di as f64, start.1 + dj as f64));
        }
    }
    let (b0, _) = best?;
    for dj in -1..=1 {
        for di in -1..=1 {
            consider(&mut best, (b0.0 + di as f64, b0.1 + dj as f64));
        }
    }
    let (mut o, _) = best?;
    let fine = disc(pic, mid, radius, stride);
    let mut sigma = f64::NAN;
    let mut scale = f32::NAN;
    for _ in 0..10 {
        let r = residuals(patch, &fine, o, cw)?;
        let rx = residuals(patch, &fine, (o.0 + 0.5, o.1), cw)?;
        let lx = residuals(patch, &fine, (o.0 - 0.5, o.1), cw)?;
        let ry = residuals(patch, &fine, (o.0, o.1 + 0.5), cw)?;
        let ly = residuals(patch, &fine, (o.0, o.1 - 0.5), cw)?;
        let mut magnitudes: Vec<f32> = r.iter().map(|v| v.abs()).collect();
        scale = 1.4826 * select::median(&mut magnitudes).unwrap_or(0.0) + 0.5;
        let (mut a, mut b, mut c, mut gx, mut gy, mut wsum, mut rss) =
            (0.0f64, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
        let rows = r.iter().zip(rx.iter().zip(&lx)).zip(ry.iter().zip(&ly));
        for ((&res, (&xr, &xl)), (&yr, &yl)) in rows {
            let (res, jx, jy) = (f64::from(res), f64::from(xr - xl), f64::from(yr - yl));
            let w = (1.5 * scale as f64 / res.abs().max(1e-9)).min(1.0);
            a += w * jx * jx;
            b += w * jx * jy;
            c += w * jy * jy;
            gx += w * jx * res;
            gy += w * jy * res;
            wsum += w;
            rss += w * res * res;
        }
        let det = a * c - b * b;
        if det.is_nan() || det <= 1e-9 {
            return None;
        }
        let (sx, sy) = ((-c * gx + b * gy) / det, (b * gx - a * gy) / det);
        let (sx, sy) = (sx.clamp(-1.0, 1.0), sy.clamp(-1.0, 1.0));
        o = (o.0 + sx, o.1 + sy);
        let var = rss / (wsum - 2.0).max(1.0);
        sigma = (var * a.max(c) / det).sqrt() * (stride as f64);
        if (o.0 - start.0).abs() > reach + 1.0 || (o.1 - start.1).abs() > reach + 1.0 {
            return None;
        }
        if sx.hypot(sy) < 0.005 {
            break;
        }
    }
    Some(Match {
        offset: o,
        sigma,
        residual: scale as f64,
    })
}

/// A ball's picture and where its patches lie on it.
#[derive(Clone, Debug, PartialEq)]
pub struct Stacked {
    /// The outline fitted to the picture (px in the picture: its middle at `half`).
    pub outline: Outline,
    pub picture: Picture,
    /// Each patch's match (`None`: not matched), in the patches' order.
    pub matches: Vec<Option<Match>>,
}

impl Stacked {
    /// The ball's centre in full-frame px in the frame of patch `k`, with its
    /// standard error.
    pub fn centre(&self, patch: &Patch, k: usize) -> Option<((f64, f64), f64)> {
        let m = self.matches.get(k).copied().flatten()?;
        let h = self.picture.half as f64;
        let c = self.outline.circle;
        Some((
            (
                patch.centre.0 + m.offset.0 + c.x - h,
                patch.centre.1 + m.offset.1 + c.y - h,
            ),
            m.sigma,
        ))
    }
}

/// The outline of a picture about `guess`: fitted to its difference from the
/// wall about it (`Picture::difference`, the ball the brighter), or to its luma
/// (of the ball's `polarity`) where the difference gives none.
fn outline_of(
    picture: &Picture,
    guess: Circle,
    (polarity, rail_moves, cw): (f64, f64, f32),
) -> Option<Outline> {
    let h = picture.half as f64;
    let fit = |img: &Gray, polarity: f64| {
        circle::fit(img, guess, 0.3 * guess.r, polarity, rail_moves, &[])
            .and_then(|f| circle::fit(img, f.circle, 2.5, f.polarity, rail_moves, &[]))
    };
    let diff = picture.difference((guess.x - h, guess.y - h), guess.r, cw);
    fit(&diff, 1.0).or_else(|| fit(&picture.luma(), polarity))
}

/// Each of `patches` [`matched`] to `picture` from its offset in `offsets`: on the
/// cores at once (the stacking's largest part, each match on its own), in order.
fn matched_all(
    patches: &[&Patch],
    offsets: &[(f64, f64)],
    picture: &Picture,
    disc: ((f64, f64), f64),
    reach: f64,
    cw: f32,
) -> Vec<Option<Match>> {
    patches
        .par_iter()
        .zip(offsets)
        .map(|(p, &o)| matched(p, picture, disc, o, reach, cw))
        .collect()
}

/// Rounds of stacking and matching: the first picture blurred by the fits' own
/// scatter, the second sharp, the third settles.
const ROUNDS: usize = 3;

/// One ball's picture from its patches: stacked at their cut centres, each
/// matched to it and stacked again, `ROUNDS` times; its outline fitted (about
/// `radius`, the frames' median, of polarity `polarity`), then every patch matched
/// to the last picture on its disc. `None` where the picture gives no outline,
/// its outline does not step from the wall (`Picture::steps_at`) or fewer than
/// half the patches match.
pub fn stack(
    patches: &[&Patch],
    radius: f64,
    polarity: f64,
    rail_moves: f64,
    cw: f32,
) -> Option<Stacked> {
    if patches.len() < 8 || radius.is_nan() || radius <= 0.0 {
        return None;
    }
    let reach = (0.25 * radius).max(3.0);
    let half = (1.75 * radius).ceil() as usize + 2;
    let mut offsets = vec![(0.0, 0.0); patches.len()];
    let mut disc = ((0.0, 0.0), 0.85 * radius);
    let mut last = None;
    for round in 0..=ROUNDS {
        let picture = stacked(patches, &offsets, half, 1.0);
        let h = half as f64;
        let guess = Circle {
            x: h + disc.0.0,
            y: h + disc.0.1,
            r: radius,
        };
        let fitted = outline_of(&picture, guess, (polarity, rail_moves, cw));
        // A first picture blurred by the fits' scatter may show no outline yet:
        // matched on the disc guessed, it sharpens.
        let outline = match fitted {
            Some(o) => o,
            None if round == ROUNDS => return None,
            None => {
                let matches = matched_all(patches, &offsets, &picture, disc, reach, cw);
                for (o, m) in offsets.iter_mut().zip(&matches) {
                    if let Some(m) = m {
                        *o = m.offset;
                    }
                }
                continue;
            }
        };
        let c = outline.circle;
        disc = ((c.x - h, c.y - h), 0.92 * c.r);
        let matches = matched_all(patches, &offsets, &picture, disc, reach, cw);
        if round == ROUNDS {
            last = Some(Stacked {
                outline,
                picture,
                matches,
            });
            break;
        }
        for (o, m) in offsets.iter_mut().zip(&matches) {
            if let Some(m) = m {
                *o = m.offset;
            }
        }
    }
    let s = last?;
    if !s.picture.steps_at(s.outline.circle, cw) {
        return None;
    }
    let matched = s.matches.iter().flatten().count();
    (2 * matched >= patches.len()).then_some(s)
}

/// The radius (px) of the outline of one ball's picture stacked at its patches'
/// cut centres (the fits'), no patch matched, its pixels `step` px apart: the
/// fits' scatter blurs the edge without moving it, and a coarse picture of a
/// large ball costs what a small ball's does. Fitted about `radius` px, of
/// `polarity`; `None` with fewer than 8 patches or where the outline is not clear
/// (under `min_coverage` of the circle, points scattering over `max_rms` of the
/// picture's pixels).
pub fn radius_at_fits(
    patches: &[&Patch],
    (radius, step): (f64, f64),
    (polarity, rail_moves, cw): (f64, f64, f32),
    (min_coverage, max_rms): (f64, f64),
) -> Option<f64> {
    if patches.len() < 8 || !(radius > 0.0 && radius.is_finite() && step >= 1.0) {
        return None;
    }
    let r = radius / step;
    let half = (1.75 * r).ceil() as usize + 2;
    let picture = stacked(patches, &vec![(0.0, 0.0); patches.len()], half, step);
    let h = half as f64;
    let guess = Circle { x: h, y: h, r };
    let o = outline_of(&picture, guess, (polarity, rail_moves, cw))?;
    (o.coverage() >= min_coverage && o.rms <= max_rms).then_some(o.circle.r * step)
}
