//! Every frame of a clip decoded once, whatever its timestamps say: a clip remuxed
//! with all its timestamps zero (as a muxer that writes none leaves it), or one
//! whose frames lie a microsecond apart (a container rate of a million frames/s),
//! gave ffmpeg's raw output 3 of its frames (the rest dropped as sharing a
//! timestamp), which `track` then refused as a truncated file or tracked from
//! three frames.

use crate::common::{paper_scene, scratch_dir};
use crate::film::looks::{self, Size};
use groovelab::input::video::{self, Limits};

/// The lumas of the frames of `path` as `open_every` hands them over, and their
/// numbers.
fn lumas(path: &std::path::Path, every: usize) -> Vec<(u64, Vec<u8>)> {
    let (_, frames) = video::open_every(path, &Limits::default(), every).unwrap();
    frames
        .map(|f| {
            let (k, frame) = f.unwrap();
            (k, frame.luma.data)
        })
        .collect()
}

/// `from` remuxed (no re-encoding) to `to` with ffmpeg's `extra` arguments.
fn remux(from: &std::path::Path, to: &std::path::Path, extra: &[&str]) {
    let out = std::process::Command::new("ffmpeg")
        .args(["-v", "error", "-nostdin", "-y", "-i"])
        .arg(from)
        .args(["-c", "copy"])
        .args(extra)
        .arg(to)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}

#[test]
fn every_frame_is_decoded_whatever_its_timestamps() {
    if !super::tracking::ffmpeg() {
        return;
    }
    let dir = scratch_dir("video_timestamps", "remuxed");
    let clip = looks::random(&paper_scene(), 3, Size::Small);
    let n = 8.min(clip.frames);
    let plain = dir.join("clip.mp4");
    crate::film::h264::write(&plain, &clip.film, n).unwrap();
    let zero = dir.join("zero.mkv");
    remux(&plain, &zero, &["-bsf:v", "setts=ts=0"]);
    let micro = dir.join("micro.mp4");
    remux(
        &plain,
        &micro,
        &["-video_track_timescale", "1000000", "-bsf:v", "setts=ts=N"],
    );
    let truth = lumas(&plain, 1);
    assert_eq!(truth.len(), n, "the clip as written");
    for odd in [&zero, &micro] {
        // Every frame, in order, its picture the clip's own.
        let got = lumas(odd, 1);
        assert_eq!(got.len(), n, "{}", odd.display());
        assert!(
            got == truth,
            "{}: frames differ from the clip's",
            odd.display()
        );
        // Every other frame: the frames kept are the clip's even ones.
        let halves = lumas(odd, 2);
        let even: Vec<_> = truth.iter().step_by(2).cloned().collect();
        assert!(halves == even, "{}: every second frame", odd.display());
    }
}
