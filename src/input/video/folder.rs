//! A folder of numbered frames (`frame0001.png`, `img_12.jpg`, …): the PNG and JPEG
//! files in it, ordered by the last number in their names, read one at a time with
//! the `image` crate (no ffmpeg). Missing numbers are gaps: said, and the frames'
//! times keep them (a frame's time is its number over the rate).

// Tracker rewrites this file (src/input/video is being reworked beside issue 35);
// its indexing, unwrap and expect are converted to `get` and errors after that.
use std::path::{Path, PathBuf};

use super::info::{Frames, Info, Limits};
use super::problem::{VideoError, VideoProblem};
use crate::vision::Frame;

/// True for a file named as a PNG or JPEG image.
pub fn is_image(path: &Path) -> bool {
    path.extension()
        .and_then(|e| e.to_str())
        .is_some_and(|e| matches!(e.to_ascii_lowercase().as_str(), "png" | "jpg" | "jpeg"))
}

/// The last run of digits in `name`'s stem.
fn number(path: &Path) -> Option<u64> {
    let stem = path.file_stem()?.to_str()?;
    let end = stem.rfind(|c: char| c.is_ascii_digit())? + 1;
    let start = stem[..end]
        .rfind(|c: char| !c.is_ascii_digit())
        .map_or(0, |i| i + 1);
    stem[start..end].parse().ok()
}

/// Opens the folder `dir`.
pub(super) fn open(dir: &Path, limits: &Limits) -> Result<(Info, Frames), VideoError> {
    let err = |what: VideoProblem| VideoError::new(dir, what);
    let entries = std::fs::read_dir(dir).map_err(|e| err(VideoProblem::Folder(e)))?;
    let mut frames: Vec<(u64, PathBuf)> = Vec::new();
    for e in entries.flatten() {
        let p = e.path();
        if p.is_file() && is_image(&p) {
            let Some(n) = number(&p) else {
                return Err(err(VideoProblem::NoFrameNumber { frame: p }));
            };
            frames.push((n, p));
        }
    }
    frames.sort();
    let same = frames.windows(2).find_map(|w| match w {
        [a, b] if a.0 == b.0 => Some((a, b)),
        _ => None,
    });
    if let Some((a, b)) = same {
        return Err(err(VideoProblem::SameFrameNumber {
            first: a.1.clone(),
            second: b.1.clone(),
            number: a.0,
        }));
    }
    let first = match frames.as_slice() {
        [first, _, ..] => read(&first.1)?,
        _ => {
            return Err(err(VideoProblem::TooFewImages {
                frames: frames.len(),
            }));
        }
    };
    let (w, h) = (first.width(), first.height());
    let pixels = (w * h) as f64 * frames.len() as f64;
    if pixels > limits.pixels || w > limits.side || h > limits.side {
        return Err(err(VideoProblem::FolderTooLarge {
            frames: frames.len(),
            width: w,
            height: h,
            max_pixels: limits.pixels,
            max_side: limits.side,
        }));
    }
    let gaps = frames
        .windows(2)
        .filter_map(|p| match p {
            [a, b] if b.0 > a.0 + 1 => Some([a.0 + 1, b.0 - 1]),
            _ => None,
        })
        .collect();
    let info = Info {
        kind: "folder of PNG/JPEG frames".into(),
        width: w,
        height: h,
        frames: frames.len() as u64,
        container_fps: None,
        capture_fps: None,
        gaps,
        duration: None,
    };
    let iter = frames.into_iter().map(move |(n, p)| {
        let g = read(&p)?;
        if (g.width(), g.height()) != (w, h) {
            return Err(VideoError::new(
                &p,
                VideoProblem::FrameSize {
                    size: (g.width(), g.height()),
                    first: (w, h),
                },
            ));
        }
        Ok((n, g))
    });
    Ok((info, Box::new(iter)))
}

/// One frame, in colour.
fn read(path: &Path) -> Result<Frame, VideoError> {
    let img = image::open(path).map_err(|e| VideoError::new(path, VideoProblem::ReadImage(e)))?;
    Ok(Frame::from_rgb(&img.to_rgb8()))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn frame_numbers_are_the_last_digits() {
        assert_eq!(number(Path::new("clip2_frame0012.png")), Some(12));
        assert_eq!(number(Path::new("7.jpg")), Some(7));
        assert_eq!(number(Path::new("frame.png")), None);
    }
}
