//! Finding balls in a whole frame, coarsely: the frame reduced to about 320 pixels
//! across, its background fitted as a smooth surface (a quadratic in x and y, fitted
//! robustly so that balls and rails do not pull it: a lighting gradient is no ball),
//! the pixels far from it marked, long horizontal runs of them dropped (the rails run
//! across the picture; a ball is far narrower) and thin horizontal lines opened away
//! (a rail's edge broken by noise), and the marked pixels' connected
//! blobs sorted into ball-like ones (as wide as tall, or wider by the part the near
//! rail hides), pairs merged at an impact, and the rest.

use super::background::{Background, Small, differences, threshold};
use super::gray::{Gray, Levels};
use super::params::Params;

/// A blob of the coarse frame, in full-frame pixels.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Blob {
    pub left: f64,
    pub right: f64,
    pub top: f64,
    pub bottom: f64,
    /// Marked pixels, in full-frame pixels².
    pub area: f64,
    /// The ball the blob's solid core would be, where it is not the blob's own
    /// guess: the blob opened (`Params::fringe_share`), its ragged fringe fallen
    /// away. Only for blobs of the difference from the background.
    pub core: Option<super::circle::Circle>,
}

impl Blob {
    pub fn width(&self) -> f64 {
        self.right - self.left
    }
    pub fn height(&self) -> f64 {
        self.bottom - self.top
    }
    /// True when `other` lies within this blob's box.
    pub fn holds(&self, other: &Blob) -> bool {
        other.left >= self.left
            && other.right <= self.right
            && other.top >= self.top
            && other.bottom <= self.bottom
    }
    /// The ball this blob would be if it is one: centre below the top by half the
    /// width.
    pub fn guess(&self) -> super::circle::Circle {
        let r = 0.5 * self.width();
        super::circle::Circle {
            x: 0.5 * (self.left + self.right),
            y: self.top + r,
            r,
        }
    }
}

/// What a coarse look at one frame found.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Coarse {
    /// Ball-shaped blobs, left to right.
    pub balls: Vec<Blob>,
    /// Blobs about twice as wide as a ball: two balls touching.
    pub pairs: Vec<Blob>,
    /// Scatter of the background's luma about its smooth fit (coarse pixels).
    pub noise: f64,
}

/// The reduction factor that brings a frame `width` wide to about 320 pixels.
pub fn factor(width: usize) -> usize {
    (width / 320).max(1)
}

/// Looks at the whole of `img` for balls of radius at least `min_radius` px, with no
/// background learned: the background taken as a smooth surface of luma.
pub fn coarse(img: &Gray, min_radius: f64) -> Coarse {
    let f = factor(img.width);
    coarse_reduced(&img.reduced(f), f, min_radius)
}

/// As [`coarse`], on the frame already reduced `f` times (`small`): a frame
/// reduced once serves this look and the look against the background.
pub fn coarse_reduced(small: &Levels, f: usize, min_radius: f64) -> Coarse {
    let (bg, noise) = background(small);
    let thr = (6.0 * noise).max(12.0);
    let (w, h) = (small.width, small.height);
    let mut mask: Vec<bool> = small
        .data
        .iter()
        .zip(&bg)
        .map(|(v, b)| (v - b).abs() > thr)
        .collect();
    drop_long_runs(&mut mask, w, h, w / 4);
    open_vertically(&mut mask, w, h);
    let mut out = classify(&mut mask, w, h, f, min_radius);
    out.noise = f64::from(noise);
    out
}

/// Looks at the coarse frame `small` for what differs from the background `bg` in
/// brightness or colour (not shadows), inside `params.roi`.
pub fn against(small: &Small, bg: &Background, params: &Params) -> Coarse {
    let d = differences(small, &bg.image, params);
    let thr = threshold(&d, params);
    against_differences(small, &d, thr, params)
}

/// As [`against`], from the coarse frame's differences `d` from the background
/// and their threshold `thr` (`background::differences`, `background::threshold`).
pub fn against_differences(small: &Small, d: &[f32], thr: f32, params: &Params) -> Coarse {
    let (w, h, f) = (small.width, small.height, small.factor);
    let mut mask: Vec<bool> = d.iter().map(|&v| v > thr).collect();
    if let Some(roi) = params.roi {
        for (i, m) in mask.iter_mut().enumerate() {
            let (x, y) = (((i % w) * f) as f64, ((i / w) * f) as f64);
            let c = 0.5 * f as f64;
            *m &= roi.contains(x + c, y + c);
        }
    }
    // A change of the whole picture's light is no ball: rows marked across most of
    // the frame are dropped.
    drop_long_runs(&mut mask, w, h, (w / 3).max(4));
    let mut opened = mask.clone();
    let mut out = classify(&mut mask, w, h, f, params.min_radius);
    // Not where the difference is at full resolution (frames under 640 px wide):
    // there the blob rule (`Params::outer_agree`) tells a lock inside a larger blob,
    // and the opened blobs' locks came in its place (small looks' seeds 2 and 11,
    // steel and glossy balls on wood grain and stripes: wrong μ_k).
    if params.fringe_share > 0.0 && f > 1 {
        open_each(&mut opened, w, h, params.fringe_share);
        let cores = classify(&mut opened, w, h, f, params.min_radius);
        for b in &mut out.balls {
            b.core = cores
                .balls
                .iter()
                .filter(|c| b.holds(c))
                .max_by(|a, c| a.area.total_cmp(&c.area))
                .map(Blob::guess)
                .filter(|c| *c != b.guess());
        }
    }
    out.noise = f64::from(thr) / params.differ_sigmas.max(1.0);
    out
}

/// The blobs of `mask` (coarse pixels, `f` full pixels each) sorted into balls,
/// pairs and the rest.
fn classify(mask: &mut [bool], w: usize, h: usize, f: usize, min_radius: f64) -> Coarse {
    let ff = f as f64;
    let min_area = (min_radius / ff).powi(2);
    let mut out = Coarse::default();
    for b in blobs(mask, w, h) {
        if (b.area as f64) < min_area {
            continue;
        }
        let blob = Blob {
            left: b.x0 as f64 * ff,
            right: (b.x1 + 1) as f64 * ff,
            top: b.y0 as f64 * ff,
            bottom: (b.y1 + 1) as f64 * ff,
            area: b.area as f64 * ff * ff,
            core: None,
        };
        let (bw, bh) = (blob.width(), blob.height());
        let fill = blob.area / (bw * bh);
        if fill < 0.45 || bw < 2.0 * min_radius {
            continue;
        }
        // A ball: its visible part is at least its upper half (the rails sit below
        // the centre), at most the whole disc.
        if bh <= 1.2 * bw + 2.0 * ff && bh >= 0.4 * bw {
            out.balls.push(blob);
        } else if bh < 0.4 * bw && bh >= 0.18 * bw {
            out.pairs.push(blob);
        }
    }
    // The balls are of one size: a blob far smaller than the largest is something
    // else (a fragment of a rail's edge, a speck).
    let largest = out.balls.iter().map(|b| b.area).fold(0.0, f64::max);
    out.balls.retain(|b| b.area >= 0.3 * largest);
    let largest_pair = out.pairs.iter().map(|b| b.area).fold(0.0, f64::max);
    out.pairs
        .retain(|b| b.area >= 0.3 * largest_pair && b.area >= 0.6 * largest);
    out.balls.sort_by(|a, b| a.left.total_cmp(&b.left));
    out
}

/// Drops horizontal runs of marked pixels longer than `longest` (rails), a run
/// going on across gaps of up to two pixels (noise breaks a rail's edge row).
#[allow(clippy::indexing_slicing)] // rows of a w × h mask, columns checked against w
fn drop_long_runs(mask: &mut [bool], w: usize, h: usize, longest: usize) {
    for y in 0..h {
        let row = &mut mask[y * w..(y + 1) * w];
        let mut x = 0;
        while x < w {
            if !row[x] {
                x += 1;
                continue;
            }
            let start = x;
            while x < w && (row[x] || row[x + 1..w.min(x + 3)].iter().any(|&m| m)) {
                x += 1;
            }
            if x - start > longest {
                row[start..x].iter_mut().for_each(|m| *m = false);
            }
        }
    }
}

/// A vertical opening (erosion then dilation by three pixels in a column): takes
/// away horizontal lines one or two pixels thick (a rail's edge that noise broke
/// into short runs, which would join a ball to the rail), keeps the balls.
#[allow(clippy::indexing_slicing)] // x < w, y < h of a w × h mask (h ≥ 3 checked)
fn open_vertically(mask: &mut [bool], w: usize, h: usize) {
    if h < 3 {
        return;
    }
    let at = |m: &[bool], x: usize, y: usize| m[y * w + x];
    let mut eroded = vec![false; w * h];
    for y in 1..h - 1 {
        for x in 0..w {
            eroded[y * w + x] = at(mask, x, y - 1) && at(mask, x, y) && at(mask, x, y + 1);
        }
    }
    for y in 0..h {
        for x in 0..w {
            mask[y * w + x] = at(&eroded, x, y)
                || (y > 0 && at(&eroded, x, y - 1))
                || (y + 1 < h && at(&eroded, x, y + 1));
        }
    }
}

/// An opening by a square `2k + 1` coarse pixels wide: erosion, then dilation, each
/// by the square (a row's run, then a column's).
fn open(mask: &mut [bool], w: usize, h: usize, k: usize) {
    if k == 0 || w == 0 || h == 0 {
        return;
    }
    let at = |m: &[bool], x: usize, y: usize| m.get(y * w + x).copied().unwrap_or(false);
    // All (erode) or any (dilate) of the run about each pixel, along rows then columns.
    let pass = |m: &[bool], all: bool, rows: bool| -> Vec<bool> {
        let mut out = vec![false; m.len()];
        for y in 0..h {
            for x in 0..w {
                let (c, n) = if rows { (x, w) } else { (y, h) };
                let (lo, hi) = (c.saturating_sub(k), (c + k).min(n - 1));
                let mut it = (lo..=hi).map(|i| if rows { at(m, i, y) } else { at(m, x, i) });
                // Beyond the frame's edge counts as unmarked for the erosion.
                let whole = c >= k && c + k < n;
                let v = if all {
                    whole && it.all(|b| b)
                } else {
                    it.any(|b| b)
                };
                if let Some(o) = out.get_mut(y * w + x) {
                    *o = v;
                }
            }
        }
        out
    };
    let eroded = pass(&pass(mask, true, true), true, false);
    let opened = pass(&pass(&eroded, false, true), false, false);
    mask.copy_from_slice(&opened);
}

/// Each blob of `mask` opened by a square of `2k + 1` coarse pixels, k its height
/// times `share` (rounded down; blobs under `1 / share` tall are left as they are).
fn open_each(mask: &mut [bool], w: usize, h: usize, share: f64) {
    for pixels in components(&mut mask.to_vec(), w, h) {
        let Region { x0, x1, y0, y1, .. } = Region::of(&pixels, w);
        let k = (share * (y1 - y0 + 1) as f64) as usize;
        if k == 0 {
            continue;
        }
        let (bw, bh) = (x1 - x0 + 1, y1 - y0 + 1);
        let mut sub = vec![false; bw * bh];
        for &i in &pixels {
            if let Some(v) = sub.get_mut((i / w - y0) * bw + (i % w - x0)) {
                *v = true;
            }
        }
        open(&mut sub, bw, bh, k);
        for &i in &pixels {
            let kept = sub
                .get((i / w - y0) * bw + (i % w - x0))
                .copied()
                .unwrap_or(false);
            if let Some(m) = mask.get_mut(i) {
                *m = kept;
            }
        }
    }
}

struct Region {
    x0: usize,
    x1: usize,
    y0: usize,
    y1: usize,
    area: usize,
}

impl Region {
    /// The box and area of the pixels `pixels` (indices into a mask `w` wide).
    fn of(pixels: &[usize], w: usize) -> Region {
        let mut c = Region {
            x0: usize::MAX,
            x1: 0,
            y0: usize::MAX,
            y1: 0,
            area: pixels.len(),
        };
        for &i in pixels {
            let (x, y) = (i % w, i / w);
            c.x0 = c.x0.min(x);
            c.x1 = c.x1.max(x);
            c.y0 = c.y0.min(y);
            c.y1 = c.y1.max(y);
        }
        c
    }
}

/// The 4-connected components of `mask` (cleared as they are taken), each its
/// pixels' indices.
#[allow(clippy::indexing_slicing)] // neighbours pushed only when inside the w × h mask
fn components(mask: &mut [bool], w: usize, h: usize) -> Vec<Vec<usize>> {
    let mut out = Vec::new();
    let mut stack = Vec::new();
    for start in 0..mask.len() {
        if !mask[start] {
            continue;
        }
        mask[start] = false;
        stack.push(start);
        let mut pixels = Vec::new();
        while let Some(i) = stack.pop() {
            pixels.push(i);
            let (x, y) = (i % w, i / w);
            let mut push = |j: usize| {
                if mask[j] {
                    mask[j] = false;
                    stack.push(j);
                }
            };
            if x > 0 {
                push(i - 1);
            }
            if x + 1 < w {
                push(i + 1);
            }
            if y > 0 {
                push(i - w);
            }
            if y + 1 < h {
                push(i + w);
            }
        }
        out.push(pixels);
    }
    out
}

/// The 4-connected components of `mask` (cleared as they are taken): their boxes
/// and areas.
fn blobs(mask: &mut [bool], w: usize, h: usize) -> Vec<Region> {
    components(mask, w, h)
        .iter()
        .map(|pixels| Region::of(pixels, w))
        .collect()
}

/// The smooth background of a reduced frame (a quadratic surface fitted to every
/// third pixel, three rounds leaving out those more than three scatters off), per
/// pixel, and the scatter of the pixels kept.
#[allow(clippy::indexing_slicing)] // fixed 6 × 6 sums, samples inside the w × h image
fn background(img: &Levels) -> (Vec<f32>, f32) {
    let (w, h) = (img.width, img.height);
    // u of each column and v of each row once (the same numbers, not two
    // divisions per pixel and round).
    let us: Vec<f64> = (0..w)
        .map(|x| 2.0 * x as f64 / w.max(2) as f64 - 1.0)
        .collect();
    let vs: Vec<f64> = (0..h)
        .map(|y| 2.0 * y as f64 / h.max(2) as f64 - 1.0)
        .collect();
    let basis = |x: usize, y: usize| {
        let (u, v) = (us[x], vs[y]);
        [1.0, u, v, u * u, u * v, v * v]
    };
    let samples: Vec<(usize, usize)> = (0..h)
        .step_by(3)
        .flat_map(|y| (0..w).step_by(3).map(move |x| (x, y)))
        .collect();
    let mut coef = [0.0f64; 6];
    let mut cut = f64::INFINITY;
    let mut scatter = 0.0;
    for _ in 0..4 {
        // The normal equations summed by hand (plain arrays stay fast unoptimized).
        let mut ata = [[0.0f64; 6]; 6];
        let mut atb = [0.0f64; 6];
        let mut res = Vec::with_capacity(samples.len());
        for &(x, y) in &samples {
            let b = basis(x, y);
            let v = f64::from(img.data[y * w + x]);
            let fit: f64 = b.iter().zip(&coef).map(|(a, c)| a * c).sum();
            if (v - fit).abs() > cut {
                continue;
            }
            res.push((v - fit).abs());
            for i in 0..6 {
                for j in i..6 {
                    ata[i][j] += b[i] * b[j];
                }
                atb[i] += b[i] * v;
            }
        }
        let m: [[f64; 6]; 6] =
            std::array::from_fn(|i| std::array::from_fn(|j| ata[i.min(j)][i.max(j)]));
        if let Some(c) = solve(m, atb) {
            coef = c;
        }
        // The median by selection: the same value a sort puts there, without
        // sorting the thousands of residuals four times a frame.
        let mid = res.len() / 2;
        let median = if res.is_empty() {
            0.0
        } else {
            *res.select_nth_unstable_by(mid, f64::total_cmp).1
        };
        scatter = median * 1.4826;
        cut = (3.0 * scatter).max(3.0);
    }
    // The surface at each pixel, the sum of its basis values times their
    // coefficients: the terms of a column (u's) and of a row (v's) made once, the
    // same products summed in the same order as `basis` and a dot product would
    // (the constant's, 1 × c0, is c0).
    let [c0, c1, c2, c3, c4, c5] = coef;
    let columns: Vec<[f64; 3]> = us.iter().map(|&u| [u, u * c1, (u * u) * c3]).collect();
    let mut bg = Vec::with_capacity(w * h);
    for &v in &vs {
        let (vc2, vvc5) = (v * c2, (v * v) * c5);
        bg.extend(columns.iter().map(|&[u, uc1, uuc3]| {
            [c0, uc1, vc2, uuc3, (u * v) * c4, vvc5]
                .into_iter()
                .sum::<f64>() as f32
        }));
    }
    (bg, scatter.max(0.5) as f32)
}

/// Solves `a x = b` by Gaussian elimination with partial pivoting; `None` when `a` is
/// singular.
#[allow(clippy::indexing_slicing)] // indices below N of N × N arrays
fn solve<const N: usize>(mut a: [[f64; N]; N], mut b: [f64; N]) -> Option<[f64; N]> {
    for col in 0..N {
        let pivot = (col..N).max_by(|&i, &j| a[i][col].abs().total_cmp(&a[j][col].abs()))?;
        if a[pivot][col].abs() < 1e-300 {
            return None;
        }
        a.swap(col, pivot);
        b.swap(col, pivot);
        let top = a[col];
        for row in col + 1..N {
            let f = a[row][col] / top[col];
            for (v, t) in a[row][col..].iter_mut().zip(&top[col..]) {
                *v -= f * t;
            }
            b[row] -= f * b[col];
        }
    }
    let mut x = [0.0; N];
    for row in (0..N).rev() {
        let s: f64 = (row + 1..N).map(|k| a[row][k] * x[k]).sum();
        x[row] = (b[row] - s) / a[row][row];
    }
    x.iter().all(|v| v.is_finite()).then_some(x)
}
