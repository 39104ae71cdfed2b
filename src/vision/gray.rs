//! One video frame as 8-bit luma (what `input::video` decodes and the renderer
//! draws), with the few reads the tracker needs: a pixel, a box-averaged reduction.

/// A frame's luma, row by row, `width × height` bytes (0 black, 255 white).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Gray {
    pub width: usize,
    pub height: usize,
    pub data: Vec<u8>,
}

/// `v` as a whole level: rounded half away from zero and held to 0–255, as
/// `v.round().clamp(0.0, 255.0) as u8` (NaN 0), without a call into libm's
/// `roundf` per pixel (the build assumes no SSE4.1, so `round` is not one
/// instruction): the tracker's pictures of differences make one per pixel.
#[inline]
pub fn level(v: f32) -> u8 {
    let c = v.clamp(0.0, 255.0);
    // Truncation is the floor here (c is 0–255 or NaN, which gives 0).
    let t = c as u8;
    if c - f32::from(t) >= 0.5 { t + 1 } else { t }
}

/// The Sobel sums (across, down) of whole levels at the middle of three pixels of
/// the rows above, at and below (`u`, `m`, `d`: three levels each; (0, 0) for
/// other lengths): at most 4 × 255 a side, so exact in any type that holds them.
#[inline]
pub fn sobel_sums(u: &[u8], m: &[u8], d: &[u8]) -> (i32, i32) {
    let (&[u0, u1, u2], &[m0, _, m2], &[d0, d1, d2]) = (u, m, d) else {
        return (0, 0);
    };
    let l = i32::from;
    (
        (l(u2) + 2 * l(m2) + l(d2)) - (l(u0) + 2 * l(m0) + l(d0)),
        (l(d0) + 2 * l(d1) + l(d2)) - (l(u0) + 2 * l(u1) + l(u2)),
    )
}

impl Gray {
    /// A frame of one level.
    pub fn filled(width: usize, height: usize, level: u8) -> Gray {
        Gray {
            width,
            height,
            data: vec![level; width * height],
        }
    }

    /// The level at column `x`, row `y` (both inside the frame).
    #[inline]
    #[allow(clippy::indexing_slicing)] // the hot read of the outline fit, callers keep x, y inside the frame (the fit's box is clipped to it)
    pub fn at(&self, x: usize, y: usize) -> f32 {
        f32::from(self.data[y * self.width + x])
    }

    /// The level at column `x`, row `y`; 0 outside the frame.
    #[inline]
    pub fn get(&self, x: usize, y: usize) -> f32 {
        if x >= self.width {
            return 0.0;
        }
        self.data
            .get(y * self.width + x)
            .map_or(0.0, |&v| f32::from(v))
    }

    /// The frame reduced `factor` times in each direction, each pixel the mean of its
    /// block (the last partial blocks dropped), as f32 levels.
    #[allow(clippy::indexing_slicing)] // whole blocks only: rows below h·f ≤ height, columns below w·f ≤ width
    pub fn reduced(&self, factor: usize) -> Levels {
        let f = factor.max(1);
        let (w, h) = (self.width / f, self.height / f);
        let mut out = vec![0.0f32; w * h];
        // Each block row's lines summed per column first (a plain add the compiler
        // vectorises), then each block's columns: a pass over the frame's bytes
        // costs one add each, not a short sum per block per line.
        // The column sums in 16 bits while f lines of 255 fit (twice the adds per
        // instruction of 32 bits): the same whole sums.
        if f * 255 <= usize::from(u16::MAX) {
            self.reduce_into::<u16>(f, w, h, &mut out);
        } else {
            self.reduce_into::<u32>(f, w, h, &mut out);
        }
        Levels {
            width: w,
            height: h,
            data: out,
        }
    }
}

impl Gray {
    /// [`Gray::reduced`]'s block means into `out` (`w × h`), the columns summed in
    /// `C` (wide enough for `f` lines of 255).
    #[allow(clippy::indexing_slicing)] // as in `reduced`: whole blocks inside the frame
    fn reduce_into<C>(&self, f: usize, w: usize, h: usize, out: &mut [f32])
    where
        C: Copy + Default + std::ops::AddAssign + From<u8> + Into<u32>,
    {
        let mut columns = vec![C::default(); w * f];
        let norm = 1.0 / (f * f) as f32;
        for by in 0..h {
            columns.iter_mut().for_each(|v| *v = C::default());
            for y in by * f..(by + 1) * f {
                let line = &self.data[y * self.width..y * self.width + w * f];
                for (c, &v) in columns.iter_mut().zip(line) {
                    *c += C::from(v);
                }
            }
            let row = &mut out[by * w..(by + 1) * w];
            // The usual factors with their block width known to the compiler (its
            // sums unrolled, not a loop of f per block): the same whole sums.
            match f {
                2 => block_sums::<C, 2>(&columns, row, norm),
                3 => block_sums::<C, 3>(&columns, row, norm),
                4 => block_sums::<C, 4>(&columns, row, norm),
                5 => block_sums::<C, 5>(&columns, row, norm),
                6 => block_sums::<C, 6>(&columns, row, norm),
                8 => block_sums::<C, 8>(&columns, row, norm),
                _ => {
                    for (o, block) in row.iter_mut().zip(columns.chunks_exact(f)) {
                        *o = block.iter().map(|&c| c.into()).sum::<u32>() as f32 * norm;
                    }
                }
            }
        }
    }
}

/// Each block's `F` column sums of `columns` added, times `norm`, into `row`.
#[inline]
fn block_sums<C, const F: usize>(columns: &[C], row: &mut [f32], norm: f32)
where
    C: Copy + Into<u32>,
{
    for (o, block) in row.iter_mut().zip(columns.chunks_exact(F)) {
        let mut s = 0u32;
        for &c in block.iter().take(F) {
            s += c.into();
        }
        *o = s as f32 * norm;
    }
}

/// A reduced frame in f32 levels (see [`Gray::reduced`]).
#[derive(Clone, Debug, PartialEq)]
pub struct Levels {
    pub width: usize,
    pub height: usize,
    pub data: Vec<f32>,
}

#[cfg(test)]
mod tests {

    #[test]
    fn a_level_is_rounded_as_round_and_clamp_round() {
        let slow = |v: f32| v.round().clamp(0.0, 255.0) as u8;
        let mut values = vec![
            f32::NAN,
            f32::INFINITY,
            f32::NEG_INFINITY,
            -0.0,
            0.0,
            1e30,
            -1e30,
        ];
        // Every half level from −2 to 258 and the floats beside it, where rounding turns.
        for k in -4..=516 {
            let h = k as f32 * 0.5;
            values.extend([h, h.next_up(), h.next_down(), h.next_up().next_up()]);
        }
        // And a spread of others (a fixed LCG: the test reads no clock).
        let mut x: u64 = 12345;
        for _ in 0..200_000 {
            x = x
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            values.push((x >> 40) as f32 / (1u64 << 24) as f32 * 270.0 - 7.0);
        }
        for v in values {
            assert_eq!(level(v), slow(v), "{v:?}");
        }
    }

    use super::*;

    #[test]
    fn reduction_averages_blocks() {
        let mut g = Gray::filled(5, 4, 10);
        g.data[0] = 50; // block (0, 0) of 2×2: (50 + 10 + 10 + 10) / 4 = 20
        let r = g.reduced(2);
        assert_eq!((r.width, r.height), (2, 2));
        assert_eq!(r.data, vec![20.0, 10.0, 10.0, 10.0]);
    }
}
