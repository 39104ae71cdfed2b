//! Tracking balls in videos against truth: synthetic videos of exactly solved scenes
//! (`tests/support/film`), tracked in memory, from a folder of PNG frames and
//! from an mp4 encoded with ffmpeg; the recovered centres and marks against the exact
//! positions, μ_k fitted from the tracks, and bad inputs refused.

use crate::film::{Film, Look};
use groovelab::vision::{self, Params, Tracker};

/// A tracked point and the true one, px.
type Pair = ((f64, f64), (f64, f64));

/// RMS distance of tracked points from the truth, px.
fn rms(pairs: &[Pair]) -> f64 {
    let s: f64 = pairs
        .iter()
        .map(|(a, b)| (a.0 - b.0).powi(2) + (a.1 - b.1).powi(2))
        .sum();
    (s / pairs.len() as f64).sqrt()
}

/// The frames `frames` of `film` tracked in memory: centre and mark pairs
/// (tracked, true).
fn tracked(film: &Film, frames: impl Iterator<Item = usize>) -> (Vec<Pair>, Vec<Pair>, Tracker) {
    let ks: Vec<usize> = frames.collect();
    let images: Vec<_> = ks.iter().map(|&k| film.frame(k)).collect();
    let tracker = vision::track(&images, Params::default());
    let (mut centres, mut marks) = (Vec::new(), Vec::new());
    for (fixes, &k) in tracker.frames.iter().zip(&ks) {
        for fix in fixes.iter().flatten() {
            let c = fix.outline.circle;
            let t = film.ball_nearest(k, (c.x, c.y));
            centres.push(((c.x, c.y), t.centre));
            if let Some(m) = fix.mark {
                marks.push(((m.x, m.y), t.mark));
            }
        }
    }
    (centres, marks, tracker)
}

#[test]
fn centres_and_marks_of_a_720p_clip_within_the_targets() {
    let s = preset_scene("paper-b4.9");
    let film = Film::new(&s, Look::default(), 0.5);
    let (centres, marks, tracker) = tracked(&film, (0..50).step_by(7));
    // Every frame's two balls found (none touch in these frames), most marks.
    assert_eq!(centres.len(), 2 * tracker.frames.len());
    assert!(marks.len() >= centres.len() / 2, "{} marks", marks.len());
    assert!(rms(&centres) <= 0.2);
    assert!(rms(&marks) <= 0.5);
}

// ---- Files: a folder of PNG frames, an mp4 --------------------------------------------

use std::path::{Path, PathBuf};
use std::sync::OnceLock;

use groovelab::input::video::write::{self, Encoding};
use serde_json::Value;

use crate::common::{preset_scene, run};

/// A small clip: 640×360 at 1000 px/m (R = 27.5 px), 100 frames/s, t = −0.15 … 0.35 s.
fn small_look() -> Look {
    Look {
        width: 640,
        height: 360,
        px_per_m: 1000.0,
        origin: (320.0, 170.0),
        from: -0.15,
        ..Look::default()
    }
}

const FRAMES: usize = 50;

/// The small clip's RGB frames, rendered once for all tests.
fn small_frames() -> &'static [Vec<u8>] {
    static FRAMES_RGB: OnceLock<Vec<Vec<u8>>> = OnceLock::new();
    FRAMES_RGB.get_or_init(|| {
        let film = Film::new(&preset_scene("paper-b4.9"), small_look(), 0.4);
        (0..FRAMES).map(|k| film.rgb(k)).collect()
    })
}

fn dir(test: &str) -> PathBuf {
    crate::common::scratch_dir("video", test)
}

/// Writes `frames` as `frame0001.png` … into `dir`, leaving out the numbers `skip`.
fn write_pngs(dir: &Path, frames: &[Vec<u8>], look: &Look, skip: &[usize]) {
    for (k, f) in frames.iter().enumerate() {
        if !skip.contains(&k) {
            let p = dir.join(format!("frame{:04}.png", k + 1));
            write::png(&p, f, look.width, look.height).unwrap();
        }
    }
}

/// True when ffmpeg is installed. Under CI (CI=true) its absence fails the test that
/// asks: CI installs it, so a missing ffmpeg there is a broken setup, not a skip.
pub fn ffmpeg() -> bool {
    // Asked once per test process (several tests ask; each ask ran ffmpeg).
    static INSTALLED: std::sync::OnceLock<bool> = std::sync::OnceLock::new();
    let ok = *INSTALLED.get_or_init(|| {
        std::process::Command::new("ffmpeg")
            .arg("-version")
            .output()
            .is_ok_and(|o| o.status.success())
    });
    if !ok {
        assert!(
            std::env::var("CI").is_err(),
            "ffmpeg is not installed, and CI must have it (.ci/run installs it)"
        );
        eprintln!("SKIPPED: ffmpeg is not installed (apt-get install ffmpeg); this test needs it");
    }
    ok
}

/// The model fit's μ_k and its ± from `fit --format json` of a tracks file.
fn fitted_mu(tracks: &Path) -> (f64, f64, Value) {
    let (code, out, err) = run(&[
        "fit",
        "--data",
        tracks.to_str().unwrap(),
        "--radius",
        "2.75cm",
        "--width",
        "4.9cm",
        "--format",
        "json",
    ]);
    assert_eq!(code, 0, "{err}");
    let j: Value = serde_json::from_str(&out).unwrap();
    // The headline: the position fit. The rim mark is hidden by the rail in half the
    // frames and turns by more than π across such a gap; the fit must not depend on
    // which turn the measured angle was unwrapped to (it did: RMS 18 mm, μ_k not
    // determined).
    let mu = j["model_fit"].clone();
    (
        mu["mu"].as_f64().unwrap_or(f64::NAN),
        mu["mu_se"].as_f64().unwrap_or(f64::NAN),
        j,
    )
}

/// The small clip as a folder of PNG frames (21 and 22 missing: a gap said, the
/// times kept), tracked by `track`: its output, and the fit of its tracks (μ_k, its
/// ±, the JSON); made once for the tests that read them.
fn folder_tracked() -> &'static (String, (f64, f64, Value)) {
    static DONE: OnceLock<(String, (f64, f64, Value))> = OnceLock::new();
    DONE.get_or_init(|| {
        let d = dir("folder");
        let look = small_look();
        write_pngs(&d, small_frames(), &look, &[20, 21]);
        let out = d.join("tracks.txt");
        let (code, stdout, err) = run(&[
            "track",
            d.to_str().unwrap(),
            "--fps",
            "100",
            "--radius",
            "2.75cm",
            "--output",
            out.to_str().unwrap(),
        ]);
        assert_eq!(code, 0, "{err}");
        let fitted = fitted_mu(&out);
        let _ = std::fs::remove_dir_all(&d);
        (stdout, fitted)
    })
}

/// The scale's relative standard error, from `track`'s line `scale S ± σ px/m: …`.
fn scale_rel_se(stdout: &str) -> f64 {
    let scale: Vec<f64> = stdout
        .lines()
        .find_map(|l| l.strip_prefix("scale "))
        .unwrap()
        .split_whitespace()
        .take(3)
        .filter_map(|w| w.parse().ok())
        .collect();
    scale[1] / scale[0]
}

#[test]
fn a_folder_of_frames_tracked_and_fitted_gives_mu_k_within_its_uncertainty() {
    let (stdout, (mu, se, j)) = folder_tracked();
    eprintln!("{stdout}");
    assert!(
        stdout.contains("frame rate 100 frames/s: given (--fps)"),
        "{stdout}"
    );
    assert!(
        stdout.contains("frames missing from the folder: 21–22"),
        "{stdout}"
    );
    // The stated ± holds the fit's own and the scale's (μ_k goes as 1/scale).
    let rel = scale_rel_se(stdout);
    let part = &j["model_fit"]["scale"];
    assert!(
        (part["rel_se"].as_f64().unwrap() - rel).abs() < 0.01 * rel,
        "{part}"
    );
    let sigma = *se;
    assert!(
        (mu - 0.17).abs() <= 2.0 * sigma && sigma < 0.002,
        "μ_k = {mu} ± {sigma}"
    );
    assert_eq!(j["model_fit"]["regime_observed"], "recollide");
    assert_eq!(j["model_fit"]["regime_predicted"], "recollide");
}

/// The position scatter `track` states is the one `fit` then measures on its tracks
/// (the centres' third differences). It stated the outline fits' own ± instead: on a
/// compressed 270p look 0.19 mm, where `fit` measured 0.51 mm on the same tracks.
#[test]
fn the_tracks_position_scatter_is_the_one_the_fit_measures() {
    let (stdout, (_, _, j)) = folder_tracked();
    let stated = stdout
        .split("position scatter ≈ ")
        .nth(1)
        .and_then(|s| s.split(" mm (left)").next())
        .and_then(|s| s.parse::<f64>().ok())
        .unwrap_or_else(|| panic!("no left ball's scatter in mm: {stdout}"))
        * 1e-3;
    let measured = j["track"]["scatter"].as_f64().unwrap();
    // `track` prints four significant digits, its file seven (0.1 µm at x ~ 0.1 m,
    // against a scatter of 7 µm here).
    assert!(
        (stated - measured).abs() <= 0.01 * measured,
        "track {stated} m, fit {measured} m"
    );
}

/// The velocity fit of the same tracks: the rim mark, hidden by the rail in half the
/// frames, turns by 3.8 rad (more than π) across such a gap at 100 frames/s, and its
/// angle was unwrapped a turn off there, so v_t was wrong beside every gap (RMS
/// 0.16 m/s, POOR FIT). Its turn is now taken from the spin beside the gap.
#[test]
fn the_velocity_fit_of_a_video_track_agrees_and_holds_the_truth() {
    let (_, (_, _, j)) = folder_tracked();
    let v = &j["velocity_fit"];
    let (mu, se) = (v["mu"].as_f64().unwrap(), v["mu_se"].as_f64().unwrap());
    // Its stated ± holds its own and the scale's (v_cm, and so μ_k, scale with the
    // lengths: 0.18 % here, twice the fit's own).
    let part = &v["scale"];
    assert!(part["mu_se_scale"].as_f64().unwrap() > part["mu_se_fit"].as_f64().unwrap());
    let sigma = se;
    assert!(
        (mu - 0.17).abs() <= 2.0 * sigma && sigma < 0.002,
        "μ_k = {mu} ± {sigma}"
    );
    assert_eq!(v["agrees"], true, "{v}");
    // RMS of v_cm and v_t against the model: the derived velocities' own scatter
    // here is ~0.2 mm/s on v_cm and a few mm/s on v_t; a turn off gave 0.16 m/s.
    assert!(v["rms"].as_f64().unwrap() < 0.01, "{v}");
    assert_eq!(v["regime_observed"], "recollide");
    assert_eq!(v["regime_predicted"], "recollide");
}

/// The small clip's first `frames` encoded as an mp4 (H.264, crf 18: lossy) in
/// `dir`, its container at `container_fps`, with `metadata`.
fn write_mp4(
    dir: &Path,
    name: &str,
    container_fps: f64,
    metadata: &[(&str, &str)],
    frames: usize,
) -> PathBuf {
    let look = small_look();
    let path = dir.join(name);
    let enc = Encoding {
        width: look.width,
        height: look.height,
        fps: container_fps,
        crf: 18,
        metadata: metadata
            .iter()
            .map(|(k, v)| (k.to_string(), v.to_string()))
            .collect(),
    };
    write::video(&path, &enc, small_frames()[..frames].iter().cloned()).unwrap();
    path
}

#[test]
fn fit_reads_an_mp4_directly_and_caches_its_tracks() {
    if !ffmpeg() {
        return;
    }
    let d = dir("mp4");
    let clip = write_mp4(&d, "clip.mp4", 100.0, &[], FRAMES);
    let cache = d.join("cache");
    let fit = || {
        std::process::Command::new(env!("CARGO_BIN_EXE_groovelab"))
            .args(["fit", "--data", clip.to_str().unwrap()])
            .args(["--radius", "2.75cm", "--width", "4.9cm", "--format", "json"])
            .env("XDG_CACHE_HOME", &cache)
            .env("GROOVELAB_PRESETS", "/nonexistent-groovelab-presets")
            .output()
            .unwrap()
    };
    let first = fit();
    assert!(
        first.status.success(),
        "{}",
        String::from_utf8_lossy(&first.stderr)
    );
    let j: Value = serde_json::from_slice(&first.stdout).unwrap();
    // The headline (the position fit; see `fitted_mu`).
    let (mu, se) = (
        j["model_fit"]["mu"].as_f64().unwrap(),
        j["model_fit"]["mu_se"].as_f64().unwrap(),
    );
    // Lossy compression: μ_k still within 0.01 of the truth.
    assert!((mu - 0.17).abs() < 0.01 && se < 0.01, "μ_k = {mu} ± {se}");
    assert_eq!(j["model_fit"]["regime_observed"], "recollide");
    // The tracks were cached, as `track` writes them; a second run reads them.
    // The text --data reads (beside it, the app's pictures: `.view`).
    let cached: Vec<PathBuf> = std::fs::read_dir(cache.join("groovelab/tracks"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "txt"))
        .collect();
    assert_eq!(cached.len(), 1, "{cached:?}");
    let text = std::fs::read_to_string(&cached[0]).unwrap();
    assert!(
        text.contains("# frame rate 100 frames/s: the container's"),
        "{text}"
    );
    assert!(
        text.contains("#multi:\n\tleft ball\t\tleft mark\t\tright ball\t\tright mark\t\nt\tx\ty"),
        "{text}"
    );
    let second = fit();
    let again: Value = serde_json::from_slice(&second.stdout).unwrap();
    assert_eq!(again["model_fit"]["mu"], j["model_fit"]["mu"]);
}

#[test]
fn a_slow_motion_file_is_read_at_its_capture_rate_and_fps_overrides_it() {
    if !ffmpeg() {
        return;
    }
    let d = dir("slowmo");
    // A phone's slow motion: 100 frames/s captured, played at 25.
    let clip = write_mp4(
        &d,
        "slow.mp4",
        25.0,
        &[("com.android.capture.fps", "100.000000")],
        12,
    );
    let (code, text, err) = run(&["track", clip.to_str().unwrap(), "--radius", "2.75cm"]);
    assert_eq!(code, 0, "{err}");
    assert!(
        text.contains("# frame rate 100 frames/s: the slow-motion capture rate in the file's metadata (com.android.capture.fps); the container says 25"),
        "{text}"
    );
    // --fps wins; JSON gives the tracks frame by frame and how they were found.
    let (code, json, err) = run(&[
        "track",
        clip.to_str().unwrap(),
        "--fps",
        "50",
        "--radius",
        "2.75cm",
        "--format",
        "json",
    ]);
    assert_eq!(code, 0, "{err}");
    let j: Value = serde_json::from_str(&json).unwrap();
    assert_eq!(j["frame_rate"], 50.0);
    assert_eq!(j["frame_rate_source"], "given");
    assert_eq!(j["container_frame_rate"], 25.0);
    assert_eq!(j["frames"], 12);
    // Every field the docs list, `gaps` too where there are none.
    assert_eq!(j["gaps"], serde_json::json!([]));
    assert_eq!(j["t"][11], 11.0 / 50.0);
    let balls = j["balls"].as_array().unwrap();
    assert_eq!(balls.len(), 2);
    assert_eq!(
        (balls[0]["name"].as_str(), balls[1]["name"].as_str()),
        (Some("left"), Some("right"))
    );
    // Metres do not depend on the rate: the left ball rolls v0 × 1/100 s (the true
    // frame spacing) from one frame to the next.
    let x = &balls[0]["x"];
    let step = x[1].as_f64().unwrap() - x[0].as_f64().unwrap();
    assert!((step - 0.7928 / 100.0).abs() < 2e-4, "{step} m per frame");
    let px = j["calibration"]["px_per_m"].as_f64().unwrap();
    assert!((px - 1000.0).abs() < 5.0, "{px} px/m");
    assert!(j["calibration"]["groove_deg"].as_f64().unwrap().abs() < 0.05);
}

#[test]
fn one_ball_in_view_is_tracked_and_named() {
    let d = dir("one");
    let look = Look {
        both: false,
        ..small_look()
    };
    let film = Film::new(&preset_scene("paper-b4.9"), look, 0.4);
    let frames: Vec<Vec<u8>> = (0..12).map(|k| film.rgb(k)).collect();
    write_pngs(&d, &frames, &look, &[]);
    let (code, text, err) = run(&["track", d.to_str().unwrap(), "--fps", "100"]);
    assert_eq!(code, 0, "{err}");
    assert!(
        text.contains("one ball tracked: the left ball (it moves right, coming from the left at first); the other was not found in enough frames"),
        "{text}"
    );
    assert!(
        text.contains("R = 2.75 cm (preset paper-b4.9; give --radius)"),
        "{text}"
    );
    assert!(
        text.contains("#multi:\n\tleft ball\t\tleft mark\t\nt\tx\ty\tx\ty\n"),
        "{text}"
    );
    // The scale given (the length a pixel shows) instead of the one from R.
    let (code, text, err) = run(&[
        "track",
        d.to_str().unwrap(),
        "--fps",
        "100",
        "--scale",
        "0.5mm",
    ]);
    assert_eq!(code, 0, "{err}");
    assert!(text.contains("# scale 2000 px/m: given (--scale"), "{text}");
}

/// `track` refuses `path` with one `error:` line containing `what`, exit 2, and
/// writes nothing to `--output`: that line.
fn refused(path: &Path, extra: &[&str], what: &str) -> String {
    let out = path.with_extension("out.txt");
    // A run before this one may have left it (the folders are reused).
    let _ = std::fs::remove_file(&out);
    let mut args = vec![
        "track",
        path.to_str().unwrap(),
        "--output",
        out.to_str().unwrap(),
    ];
    args.extend_from_slice(extra);
    let (code, stdout, err) = run(&args);
    assert_eq!(code, 2, "{path:?}: {stdout}{err}");
    assert!(stdout.is_empty(), "{stdout}");
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(
        err.starts_with("error: ") && err.contains(what),
        "{path:?}: {err}"
    );
    assert!(!out.exists(), "{out:?} written");
    err
}

#[test]
fn frames_without_a_ball_or_with_three_are_refused() {
    let look = small_look();
    let film = Film::new(&preset_scene("paper-b4.9"), look, 0.4);
    // No ball: the empty groove.
    let empty = dir("empty");
    let mut frames: Vec<Vec<u8>> = (0..6).map(|k| film.rgb(k)).collect();
    let bg_only: Vec<Vec<u8>> = frames
        .iter()
        .map(|f| {
            // The background's column at the far left, copied across: no balls.
            let mut g = f.clone();
            for y in 0..look.height {
                for x in 0..look.width {
                    for c in 0..3 {
                        g[(y * look.width + x) * 3 + c] = f[(y * look.width + 2) * 3 + c];
                    }
                }
            }
            g
        })
        .collect();
    write_pngs(&empty, &bg_only, &look, &[]);
    refused(&empty, &["--fps", "100"], "no ball found in 6 frames");
    // Three balls: the left ball's picture copied to the far left.
    let three = dir("three");
    for f in frames.iter_mut() {
        for y in 100..215 {
            for x in 0..70 {
                for c in 0..3 {
                    f[(y * look.width + x) * 3 + c] = f[(y * look.width + x + 140) * 3 + c];
                }
            }
        }
    }
    write_pngs(&three, &frames, &look, &[]);
    // Either refused for the third ball, or the two colliding balls tracked with
    // the right scale (the learned background sees the copy as part of the bench):
    // never a scale from the wrong balls.
    let (code, text, err) = run(&["track", three.to_str().unwrap(), "--fps", "100"]);
    if code == 2 {
        assert!(err.contains("more than two balls in"), "{err}");
    } else {
        assert_eq!(code, 0, "{err}");
        let all = format!("{err}{text}");
        let scale: f64 = all
            .split("scale ")
            .nth(1)
            .and_then(|t| t.split_whitespace().next())
            .and_then(|v| v.parse().ok())
            .unwrap_or(f64::NAN);
        // True 1000 px/m; the radius fit's ± is ~0.2 %, shading ~0.3 %.
        assert!((scale - 1000.0).abs() < 5.0, "scale {scale}: {all}");
    }
    // A folder of frames needs a rate.
    refused(&three, &[], "give it with --fps");
}

#[test]
fn two_frames_are_too_few_not_no_ball() {
    // The balls are in both frames: once "no ball found in 2 frames".
    let look = small_look();
    let two = dir("two");
    write_pngs(&two, &small_frames()[..2], &look, &[]);
    refused(
        &two,
        &["--fps", "100"],
        "only 2 frames, at least 3 needed: a ball is a blob seen in 3 frames or more",
    );
}

#[test]
fn files_that_are_no_video_are_refused_with_one_line() {
    let d = dir("bad");
    let look = small_look();
    let still = d.join("still.png");
    write::png(&still, &small_frames()[0], look.width, look.height).unwrap();
    refused(&still, &[], "is a still image");
    let zero = d.join("zero.mp4");
    std::fs::write(&zero, b"").unwrap();
    refused(&zero, &[], "is empty (0 bytes)");
    refused(&d.join("missing.mp4"), &[], "cannot open");
    let one = dir("bad-one");
    write::png(
        &one.join("f1.png"),
        &small_frames()[0],
        look.width,
        look.height,
    )
    .unwrap();
    refused(
        &one,
        &["--fps", "100"],
        "holds 1 PNG/JPEG frame, expected a folder",
    );
    // Without ffmpeg on the PATH: how to install it.
    let clip = d.join("clip.mp4");
    std::fs::write(&clip, b"not really a video").unwrap();
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_groovelab"))
        .args(["track", clip.to_str().unwrap()])
        .env("PATH", d.join("no-such-bin"))
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2));
    assert!(
        err.contains("apt-get install ffmpeg") && err.lines().count() == 1,
        "{err}"
    );
    if !ffmpeg() {
        return;
    }
    refused(&clip, &[], "is a text file, not a video");
    let junk = d.join("junk.mp4");
    std::fs::write(
        &junk,
        (0..4000u32)
            .map(|i| (i * 7919 % 251) as u8)
            .collect::<Vec<u8>>(),
    )
    .unwrap();
    refused(&junk, &[], "is not a video ffmpeg can read");
    // Text: a tracks file (ffmpeg would draw its characters as a video, its tty
    // demuxer, and find "balls" in them) and tables ffprobe cannot read at all.
    let rows: String = (0..300).map(|i| format!("{}\t{}\n", i, i * 2)).collect();
    for (name, head) in [
        (
            "tracks.txt",
            "# groovelab track clip.mp4: video (h264), 480×270\n",
        ),
        ("table.txt", "t\tx\n"),
        ("table.csv", "t_s,v_cm_m_per_s,v_t_m_per_s\n"),
    ] {
        let file = d.join(name);
        std::fs::write(&file, format!("{head}{rows}")).unwrap();
        refused(&file, &[], "is a text file, not a video");
    }
    // Truncated: the first half of an mp4 (its index is at the end).
    let whole = write_mp4(&d, "whole.mp4", 100.0, &[], 12);
    let bytes = std::fs::read(&whole).unwrap();
    let cut = d.join("cut.mp4");
    std::fs::write(&cut, &bytes[..bytes.len() / 2]).unwrap();
    refused(&cut, &[], "is not a video ffmpeg can read");
    // Audio only.
    let audio = d.join("tone.m4a");
    let made = std::process::Command::new("ffmpeg")
        .args([
            "-v",
            "error",
            "-y",
            "-f",
            "lavfi",
            "-i",
            "sine=frequency=440:duration=0.5",
        ])
        .arg(&audio)
        .status()
        .unwrap();
    assert!(made.success());
    refused(&audio, &[], "has no video, only audio");
}

#[test]
fn a_video_too_large_is_refused_before_decoding() {
    if !ffmpeg() {
        return;
    }
    let d = dir("large");
    let clip = write_mp4(&d, "clip.mp4", 100.0, &[], 12);
    // The same check that refuses an hour of 4K (5e10 pixels), at a small limit.
    let limits = groovelab::input::video::Limits {
        pixels: 1e6,
        ..Default::default()
    };
    let e = groovelab::input::video::open(&clip, &limits).err().unwrap();
    assert!(
        matches!(
            e.what,
            groovelab::input::video::VideoProblem::TooMuchVideo { max_pixels, .. } if max_pixels == 1e6
        ),
        "{e}"
    );
    assert!(e.to_string().contains("is too much video to track"), "{e}");
}

/// The balls' radius given without its unit (`--radius 2.75`: a number alone is
/// metres) scales the tracks a hundredfold, the balls approaching at tens of m/s:
/// `track` refuses them as `fit` would, in one line that says to check `--radius`,
/// and writes nothing; with its unit the same clip is tracked.
#[test]
fn tracks_of_no_ball_in_a_groove_are_refused_by_track() {
    if !ffmpeg() {
        return;
    }
    let d = dir("radius_in_metres");
    let clip = write_mp4(&d, "clip.mp4", 100.0, &[], 12);
    let err = refused(&clip, &["--radius", "2.75"], "no ball in a groove");
    assert!(
        err.contains("check --radius (a number without a unit is metres: 2.75 is 2.75 m"),
        "{err}"
    );
    let (code, _, err) = run(&["track", clip.to_str().unwrap(), "--radius", "2.75cm"]);
    assert_eq!(code, 0, "{err}");
}

/// A file's probe is remembered by its path, length and time modified: the same
/// clip opened twice gives one answer, and a clip written over it at the same path
/// (another length of frames) is probed anew, not answered from memory.
#[test]
fn a_video_rewritten_at_its_path_is_probed_anew() {
    if !ffmpeg() {
        return;
    }
    let d = dir("probed_anew");
    let limits = groovelab::input::video::Limits::default();
    let frames_of = |p: &Path| groovelab::input::video::open(p, &limits).unwrap().0.frames;
    let clip = write_mp4(&d, "clip.mp4", 100.0, &[], 12);
    assert_eq!(frames_of(&clip), 12);
    assert_eq!(frames_of(&clip), 12);
    let again = write_mp4(&d, "clip.mp4", 100.0, &[], 7);
    assert_eq!(again, clip);
    assert_eq!(frames_of(&clip), 7);
}

/// The progress a tracking reports counts the frames tracked as well as the frames
/// read: most clips are read whole before their first frame is tracked, and the
/// app's "tracking video 100 %" once showed for the longer half of the work.
#[test]
fn progress_reaches_the_whole_only_when_every_frame_is_tracked() {
    use groovelab::input::video::tracked::{self, Options};
    use std::sync::Mutex;
    struct Ticks(Mutex<Vec<(u64, u64)>>);
    impl groovelab::study::Progress for Ticks {
        fn tick(&self, done: u64, total: u64) {
            self.0.lock().unwrap().push((done, total));
        }
    }
    let d = dir("progress");
    let n = 12;
    write_pngs(&d, &small_frames()[..n], &small_look(), &[]);
    let options = Options {
        radius: 0.0275,
        fps: Some(100.0),
        px_per_m: None,
        radius_from: "--radius".into(),
        cache: None,
        roi: None,
        ball_at: None,
    };
    let ticks = Ticks(Mutex::new(Vec::new()));
    // Tracked or refused (12 frames may be too few to fit): the ticks are the same.
    let _ = tracked::track(&d, &options, &ticks);
    let ticks = ticks.0.into_inner().unwrap();
    let total = 2 * n as u64;
    assert!(ticks.iter().all(|&(_, t)| t == total), "{ticks:?}");
    assert!(ticks.windows(2).all(|w| w[0].0 < w[1].0), "{ticks:?}");
    assert_eq!(ticks.last(), Some(&(total, total)));
    // Once every frame is read, the frames tracked are still ahead.
    let read_all = ticks
        .iter()
        .position(|&(done, _)| done >= n as u64)
        .unwrap();
    assert!(ticks[read_all].0 < total, "{ticks:?}");
    assert_eq!(ticks.iter().filter(|&&(done, _)| done == total).count(), 1);
}

/// A clip tracked again is decoded by ffmpeg once: its further trackings read the
/// frames the first kept in memory. An empty groove (no ball at the usual floor, nor
/// at the lower one, nor without the shadow test: three trackings, then refused) is
/// tracked with an `ffmpeg` of the test's own first on the PATH, which notes each
/// call and runs the system's.
#[cfg(unix)]
#[test]
fn a_clip_tracked_again_is_decoded_once() {
    use std::os::unix::fs::PermissionsExt;
    if !ffmpeg() {
        return;
    }
    let d = dir("decoded_once");
    let (w, h) = (160, 120);
    let clip = d.join("empty.mp4");
    let enc = Encoding {
        width: w,
        height: h,
        fps: 30.0,
        crf: 18,
        metadata: Vec::new(),
    };
    write::video(&clip, &enc, (0..12).map(|_| vec![90u8; w * h * 3])).unwrap();
    let path = std::env::var_os("PATH").unwrap_or_default();
    let real = std::env::split_paths(&path)
        .map(|p| p.join("ffmpeg"))
        .find(|p| p.is_file())
        .unwrap();
    let bin = d.join("bin");
    std::fs::create_dir_all(&bin).unwrap();
    let calls = d.join("calls");
    let wrapper = bin.join("ffmpeg");
    std::fs::write(
        &wrapper,
        format!(
            "#!/bin/sh\necho \"$*\" >> '{}'\nexec '{}' \"$@\"\n",
            calls.display(),
            real.display()
        ),
    )
    .unwrap();
    std::fs::set_permissions(&wrapper, std::fs::Permissions::from_mode(0o755)).unwrap();
    let mut paths = vec![bin];
    paths.extend(std::env::split_paths(&path));
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_groovelab"))
        .args(["track", clip.to_str().unwrap(), "--radius", "2.75cm"])
        .env("PATH", std::env::join_paths(paths).unwrap())
        .env("XDG_CACHE_HOME", d.join("cache"))
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(err.contains("no ball found in 12 frames"), "{err}");
    let calls = std::fs::read_to_string(&calls).unwrap_or_default();
    let decodes = calls.lines().filter(|l| l.contains("-f rawvideo")).count();
    assert_eq!(decodes, 1, "ffmpeg's calls:\n{calls}");
}
