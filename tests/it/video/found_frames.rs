//! Frames found counted against the frames of the clip at its rate (issue 35): a
//! 60 frames/s track whose ball was found in 11 of its 58 frames is "11 of 58 frames
//! at 60 frames/s", never "11 frames at 20 frames/s" (the found frames' own spacing
//! taken for the rate, as `data` once said of a video tracked with gaps).

use crate::common::{run, scratch_dir};

/// A track of `rows` frames at `fps`, the ball found (rolling at 0.5 m/s from 0.1 m)
/// in every `every`-th frame only, the others left empty, as `track` writes a
/// video's frames left out.
fn gappy_track(rows: usize, fps: f64, every: usize) -> String {
    let mut s = String::from("t,x,y\n");
    for k in 0..rows {
        let t = k as f64 / fps;
        if k % every == 0 {
            s += &format!("{t:.9},{:.9},0.0\n", 0.1 + 0.5 * t);
        } else {
            s += &format!("{t:.9},,\n");
        }
    }
    s
}

#[test]
fn found_frames_are_counted_against_the_clips_frames_at_its_rate() {
    let dir = scratch_dir("video_found_frames", "gappy");
    let file = dir.join("track.csv");
    // 58 frames at 60 frames/s, found in frames 0, 3, …, 30 and nowhere after: 11.
    let text: String = gappy_track(58, 60.0, 3)
        .lines()
        .enumerate()
        .map(|(i, l)| {
            // Rows past frame 30 (line 31 on, after the header) lose their position.
            if i > 31 {
                let t = l.split(',').next().unwrap_or("");
                format!("{t},,\n")
            } else {
                format!("{l}\n")
            }
        })
        .collect();
    std::fs::write(&file, text).unwrap();
    let path = file.display().to_string();
    let (code, out, err) = run(&["data", &path]);
    assert_eq!(code, 0, "{err}");
    assert!(out.contains("11 of 58 frames at 60 frames/s"), "{out}");
    assert!(!out.contains("20 frames/s"), "{out}");
    let (code, out, err) = run(&["data", "--format", "json", &path]);
    assert_eq!(code, 0, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(v[0]["frames"], 11, "{out}");
    assert_eq!(v[0]["frames_spanned"], 58, "{out}");
    let rate = v[0]["frame_rate"].as_f64().unwrap();
    // The times are written to a nanosecond: the rate within 1e-3 of 60.
    assert!((rate - 60.0).abs() < 1e-3, "{out}");
}

/// A track found in every frame says its frames alone ("40 frames at 100
/// frames/s"), with no "of".
#[test]
fn a_track_found_in_every_frame_says_no_of() {
    let dir = scratch_dir("video_found_frames", "whole");
    let file = dir.join("track.csv");
    std::fs::write(&file, gappy_track(40, 100.0, 1)).unwrap();
    let (code, out, err) = run(&["data", &file.display().to_string()]);
    assert_eq!(code, 0, "{err}");
    assert!(out.contains("  40 frames at 100 frames/s"), "{out}");
}
