//! A clip's frames as its timestamps place them: a gap in the timestamps (a phone
//! that skipped frames in low light) is filled with the frame before it, so each
//! frame handed over is the picture at its number over the rate, and the times the
//! tracks give (`number / fps`) stay the clip's. Decoding every frame once instead
//! (`-fps_mode passthrough`, tried in the thirty-fourth session for clips whose
//! timestamps are all zero) closed such a gap up and put every later frame a gap
//! early: a 10 % faster ball, within what the rate check lets by.

use crate::common::{paper_scene, scratch_dir};
use crate::film::looks::{self, Size};
use groovelab::input::video::{self, Limits};

/// The lumas of the frames of `path` as `open` hands them over.
fn lumas(path: &std::path::Path) -> Vec<Vec<u8>> {
    let (_, frames) = video::open(path, &Limits::default()).unwrap();
    frames.map(|f| f.unwrap().1.luma.data).collect()
}

#[test]
fn a_gap_in_the_timestamps_is_filled_with_the_frame_before() {
    if !super::tracking::ffmpeg() {
        return;
    }
    let dir = scratch_dir("video_timestamps", "gap");
    let clip = looks::random(&paper_scene(), 3, Size::Small);
    let n = 12.min(clip.frames);
    let plain = dir.join("clip.mp4");
    crate::film::h264::write(&plain, &clip.film, n).unwrap();
    // Frames 4–6 dropped, the others keeping their timestamps, re-encoded losslessly
    // (the pictures decoded from it are the first clip's, byte for byte).
    let gap = dir.join("gap.mp4");
    let out = std::process::Command::new("ffmpeg")
        .args(["-v", "error", "-nostdin", "-y", "-i"])
        .arg(&plain)
        .args([
            "-vf",
            "select='not(between(n,4,6))'",
            "-fps_mode",
            "passthrough",
        ])
        .args(["-c:v", "libx264", "-qp", "0"])
        .arg(&gap)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let truth = lumas(&plain);
    assert_eq!(truth.len(), n, "the clip as written");
    let got = lumas(&gap);
    assert_eq!(
        got.len(),
        n,
        "a frame for each frame time, the gap's filled"
    );
    for (k, picture) in got.iter().enumerate() {
        if (4..=6).contains(&k) {
            assert!(picture == &truth[3], "frame {k}: the frame before the gap");
        } else {
            assert!(picture == &truth[k], "frame {k}: its own picture");
        }
    }
}

/// A clip whose frames lie a microsecond apart (a container rate of a million
/// frames/s): ffmpeg hands over 3 of its frames and says nothing. The refusal says
/// why and how to retime the clip, in one line (exit 2), not that it is damaged.
#[test]
fn frames_whose_timestamps_collide_are_said_so_with_the_retiming() {
    if !super::tracking::ffmpeg() {
        return;
    }
    let dir = scratch_dir("video_timestamps", "collide");
    let clip = looks::random(&paper_scene(), 3, Size::Small);
    let n = 12.min(clip.frames);
    let plain = dir.join("clip.mp4");
    crate::film::h264::write(&plain, &clip.film, n).unwrap();
    let micro = dir.join("micro.mp4");
    let out = std::process::Command::new("ffmpeg")
        .args(["-v", "error", "-nostdin", "-y", "-i"])
        .arg(&plain)
        .args(["-c", "copy", "-video_track_timescale", "1000000"])
        .args(["-bsf:v", "setts=ts=N"])
        .arg(&micro)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let path = micro.display().to_string();
    let (code, _, err) =
        crate::common::run(&["track", &path, "--fps", "100", "--radius", "2.75cm"]);
    assert_eq!(code, 2, "{err}");
    assert_eq!(err.trim_end().lines().count(), 1, "{err}");
    assert!(err.contains("timestamps collide"), "{err}");
    assert!(err.contains("setpts=N/FPS/TB"), "{err}");
    assert!(!err.contains("damaged"), "{err}");
}
