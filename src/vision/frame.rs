//! One video frame in colour as the tracker takes it: ffmpeg's native layout for
//! h264 (yuv420p: the luma plane at full size, the two colour planes at half size
//! each way), so a decoded frame needs no conversion; an in-memory RGB picture (the
//! `image` crate's `RgbImage`, as the renderer and PNG/JPEG folders give) is turned
//! into it with the same BT.601 video-range formulas ffmpeg uses to encode one.

use image::RgbImage;

use super::gray::{Gray, level};

/// A frame: luma (Y, 16 black … 235 white) and colour difference (U blue−luma, V
/// red−luma, 128 grey) at half resolution, rounded up.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Frame {
    pub luma: Gray,
    /// The colour planes' size, px: `(width + 1) / 2 × (height + 1) / 2`.
    pub chroma_width: usize,
    pub chroma_height: usize,
    pub u: Vec<u8>,
    pub v: Vec<u8>,
}

impl Frame {
    /// A frame from yuv420p bytes (Y, then U, then V), as ffmpeg writes them;
    /// `None` when `bytes` is not `Frame::bytes(width, height)` long.
    pub fn from_yuv420p(width: usize, height: usize, mut bytes: Vec<u8>) -> Option<Frame> {
        let (cw, ch) = chroma_size(width, height);
        if bytes.len() != Frame::bytes(width, height) {
            return None;
        }
        let v = bytes.split_off(width * height + cw * ch);
        let u = bytes.split_off(width * height);
        Some(Frame {
            luma: Gray {
                width,
                height,
                data: bytes,
            },
            chroma_width: cw,
            chroma_height: ch,
            u,
            v,
        })
    }

    /// Bytes of one yuv420p frame of `width × height`.
    pub fn bytes(width: usize, height: usize) -> usize {
        let (cw, ch) = chroma_size(width, height);
        width * height + 2 * cw * ch
    }

    /// A frame from an RGB picture (BT.601, video range: what ffmpeg's h264 encode
    /// of the same picture decodes to, before compression).
    pub fn from_rgb(img: &RgbImage) -> Frame {
        let (w, h) = (img.width() as usize, img.height() as usize);
        let (cw, ch) = chroma_size(w, h);
        let px = img.as_raw();
        let rgb = |x: usize, y: usize| {
            let i = 3 * (y * w + x);
            match px.get(i..i + 3) {
                Some([r, g, b]) => [f32::from(*r), f32::from(*g), f32::from(*b)],
                _ => [0.0; 3],
            }
        };
        // Each pixel's luma straight from its three bytes (the same formula per
        // pixel, without a bounds-checked look-up per read).
        let mut luma: Vec<u8> = px
            .chunks_exact(3)
            .take(w * h)
            .map(|p| {
                let [r, g, b] = match *p {
                    [r, g, b] => [r, g, b].map(f32::from),
                    _ => [0.0; 3],
                };
                level(16.0 + (65.481 * r + 128.553 * g + 24.966 * b) / 255.0)
            })
            .collect();
        // A short picture buffer (never from `image`): its missing pixels black.
        if luma.len() < w * h {
            luma.extend((luma.len()..w * h).map(|i| {
                let [r, g, b] = rgb(i % w, i / w);
                level(16.0 + (65.481 * r + 128.553 * g + 24.966 * b) / 255.0)
            }));
        }
        let (mut u, mut v) = (Vec::with_capacity(cw * ch), Vec::with_capacity(cw * ch));
        for cy in 0..ch {
            let rows = 2 * cy..(2 * cy + 2).min(h);
            for cx in 0..cw {
                // The mean colour of the 2×2 block (fewer at a ragged edge).
                let mut s = [0.0f32; 3];
                let mut n = 0.0f32;
                for y in rows.clone() {
                    for x in 2 * cx..(2 * cx + 2).min(w) {
                        let p = rgb(x, y);
                        s.iter_mut().zip(p).for_each(|(a, b)| *a += b);
                        n += 1.0;
                    }
                }
                let [r, g, b] = s.map(|c| c / n.max(1.0));
                u.push(level(
                    128.0 + (-37.797 * r - 74.203 * g + 112.0 * b) / 255.0,
                ));
                v.push(level(128.0 + (112.0 * r - 93.786 * g - 18.214 * b) / 255.0));
            }
        }
        Frame {
            luma: Gray {
                width: w,
                height: h,
                data: luma,
            },
            chroma_width: cw,
            chroma_height: ch,
            u,
            v,
        }
    }

    /// A grey frame (no colour) from luma alone.
    pub fn from_gray(luma: Gray) -> Frame {
        let (cw, ch) = chroma_size(luma.width, luma.height);
        Frame {
            luma,
            chroma_width: cw,
            chroma_height: ch,
            u: vec![128; cw * ch],
            v: vec![128; cw * ch],
        }
    }

    pub fn width(&self) -> usize {
        self.luma.width
    }

    pub fn height(&self) -> usize {
        self.luma.height
    }
}

/// The colour planes' size for a `width × height` frame.
pub fn chroma_size(width: usize, height: usize) -> (usize, usize) {
    (width.div_ceil(2), height.div_ceil(2))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rgb_becomes_video_range_yuv() {
        // White, black and pure red (BT.601: Y 235, 16, 81; red's V 240, U 90).
        let mut img = RgbImage::new(3, 1);
        img.put_pixel(0, 0, image::Rgb([255, 255, 255]));
        img.put_pixel(2, 0, image::Rgb([255, 0, 0]));
        let f = Frame::from_rgb(&img);
        assert_eq!(f.luma.data, vec![235, 16, 81]);
        assert_eq!((f.chroma_width, f.chroma_height), (2, 1));
        // The first chroma sample is the white/black pair's mean: grey, no colour.
        assert_eq!((f.u[0], f.v[0]), (128, 128));
        assert_eq!((f.u[1], f.v[1]), (90, 240));
    }

    #[test]
    fn yuv420p_bytes_split_into_planes() {
        let (w, h) = (5, 3);
        let n = Frame::bytes(w, h);
        assert_eq!(n, 15 + 2 * 3 * 2);
        let bytes: Vec<u8> = (0..n).map(|i| i as u8).collect();
        let f = Frame::from_yuv420p(w, h, bytes).unwrap();
        assert_eq!(f.luma.data.len(), 15);
        assert_eq!(f.u, vec![15, 16, 17, 18, 19, 20]);
        assert_eq!(f.v, vec![21, 22, 23, 24, 25, 26]);
        assert!(Frame::from_yuv420p(w, h, vec![0; n - 1]).is_none());
    }
}
