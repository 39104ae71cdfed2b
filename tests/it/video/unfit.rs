//! A video whose tracks no fit can use (one ball pushed along, no impact in the clip)
//! opens all the same (issue 35): its frames in the video view at the clip's own
//! time, and the Fit view saying why there is no fit.

use super::tracking::ffmpeg;
use crate::common::{run, scratch_dir};

#[test]
fn a_clip_with_no_impact_opens_with_its_frames_and_says_why_there_is_no_fit() {
    if !ffmpeg() {
        return;
    }
    let dir = scratch_dir("video-unfit", "pushed");
    let clip = dir.join("pushed.mp4");
    // A light disc of radius 20 px on a dark ground, pushed to the right and
    // speeding up: 1.5 s at 30 frames/s, 320×180.
    let made = std::process::Command::new("ffmpeg")
        .args(["-loglevel", "error", "-y", "-f", "lavfi", "-i"])
        .arg("color=c=black:s=320x180:r=30:d=1.5,format=gray")
        .arg("-vf")
        .arg("geq=lum='if(lt(hypot(X-(50+80*T+30*T*T)\\,Y-90)\\,20)\\,220\\,30)',format=yuv420p")
        .args(["-c:v", "libx264", "-crf", "18"])
        .arg(&clip)
        .status()
        .unwrap();
    assert!(made.success());
    let c = clip.to_str().unwrap();
    let base = [
        "render", "--data", c, "--radius", "2.75cm", "--size", "100x30",
    ];
    let (code, screen, err) = run(&base);
    assert_eq!(code, 0, "{err}");
    assert!(
        screen.contains("pushed.mp4: no fit (f says why; d shows its rows)"),
        "{screen}"
    );
    let with = |keys: &str| {
        let mut args = base.to_vec();
        args.extend(["--keys", keys]);
        let (code, out, err) = run(&args);
        assert_eq!(code, 0, "{err}");
        out
    };
    let fit = with("f");
    assert!(
        fit.contains("no fit of") && fit.contains("no impact found"),
        "{fit}"
    );
    // The video view shows a frame of the clip (45 frames) at the cursor's time, not
    // "no time to show".
    let video = with("V");
    assert!(video.contains("frame 1 of 45"), "{video}");
    assert!(!video.contains("no time to show"), "{video}");
}
