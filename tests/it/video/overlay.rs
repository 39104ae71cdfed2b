//! `track --overlay FILE` (issue 34): what was found drawn over the film, checked on
//! the picture itself: the drawn outline sits on the true outline of each ball (not
//! inside it, not beside it); bad FILE names refused in one line before tracking.

use std::path::Path;

use crate::common::{paper_scene, run, scratch_dir};
use crate::film::{Film, Look};
use groovelab::input::video::write;
use groovelab::vision::overlay::COLOURS;

/// A 320×180 clip of 30 frames (R = 13.75 px, 100 frames/s) as a folder of PNGs.
fn film(dir: &Path) -> Film {
    let look = Look {
        width: 320,
        height: 180,
        px_per_m: 500.0,
        origin: (160.0, 85.0),
        from: -0.15,
        ..Look::default()
    };
    let film = Film::new(&paper_scene(), look, 0.3);
    std::fs::create_dir_all(dir).unwrap();
    for k in 0..30 {
        let p = dir.join(format!("frame{:04}.png", k + 1));
        write::png(&p, &film.rgb(k), look.width, look.height).unwrap();
    }
    film
}

/// `track FRAMES` of [`film`]'s folder as the tests run it (its rate and the balls'
/// radius given), then `more`.
fn track_args<'a>(frames: &'a Path, more: &[&'a str]) -> Vec<&'a str> {
    let mut args = vec![
        "track",
        frames.to_str().unwrap(),
        "--fps",
        "100",
        "--radius",
        "2.75cm",
    ];
    args.extend_from_slice(more);
    args
}

/// True when the pixel has the hue of one of the drawing's colours (yellow: red and
/// green well above blue; cyan: green and blue well above red): the anti-aliased edge
/// blends them with the black halo and the frame, which is grey.
fn drawn(p: &image::Rgb<u8>) -> bool {
    let [r, g, b] = p.0.map(i32::from);
    let yellow = r > b + 60 && g > b + 60;
    let cyan = g > r + 60 && b > r + 60;
    yellow || cyan
}

/// The share of 36 directions over the upper half of the circle of radius `r` about
/// `c` in which a drawn pixel lies within `slack` px of the circle.
fn drawn_share(img: &image::RgbImage, c: (f64, f64), r: f64, slack: f64) -> f64 {
    let mut hits = 0;
    for j in 0..36 {
        // From 10° to 170° above the horizontal (the rail hides the lower half).
        let a = (10.0 + 160.0 * j as f64 / 35.0).to_radians();
        let mut hit = false;
        let mut s = -slack;
        while s <= slack {
            let (x, y) = (c.0 + (r + s) * a.cos(), c.1 - (r + s) * a.sin());
            let (xi, yi) = (x.round() as i64, y.round() as i64);
            if xi >= 0 && yi >= 0 && (xi as u32) < img.width() && (yi as u32) < img.height() {
                hit |= drawn(img.get_pixel(xi as u32, yi as u32));
            }
            s += 0.25;
        }
        hits += usize::from(hit);
    }
    hits as f64 / 36.0
}

#[test]
fn the_overlay_sheet_draws_each_outline_on_its_ball() {
    let dir = scratch_dir("video_overlay", "sheet");
    let frames = dir.join("frames");
    let film = film(&frames);
    let sheet = dir.join("check.png");
    let tracks = dir.join("tracks.txt");
    let (code, out, err) = run(&track_args(
        &frames,
        &[
            "--output",
            tracks.to_str().unwrap(),
            "--overlay",
            sheet.to_str().unwrap(),
        ],
    ));
    assert_eq!(code, 0, "{err}");
    assert!(out.contains("wrote the overlay "), "{out}");
    // The hue test knows the drawing's colours.
    assert!(COLOURS.iter().all(|c| drawn(&image::Rgb(*c))));
    let img = image::open(&sheet).unwrap().to_rgb8();
    // 12 tiles of 320×180 (not shrunk: narrower than 480 px), 4 to a row, 4 px apart.
    assert_eq!((img.width(), img.height()), (4 + 4 * 324, 4 + 3 * 184));
    let shown: Vec<usize> = (0..12).map(|i| i * 29 / 11).collect();
    let mut checked = 0;
    for (tile, &k) in shown.iter().enumerate() {
        let (ox, oy) = (
            4.0 + 324.0 * (tile % 4) as f64,
            4.0 + 184.0 * (tile / 4) as f64,
        );
        let truth = film.truth(k);
        // Balls apart by more than a radius (at the impact neither is measured).
        let gap = (truth[0].centre.0 - truth[1].centre.0).abs() - 2.0 * truth[0].radius;
        if gap < 3.0 {
            continue;
        }
        for t in truth {
            let c = (ox + t.centre.0, oy + t.centre.1);
            let r = t.radius;
            // On the ball's outline: drawn nearly all round (within 1.5 px: the fitted
            // radius and centre are within a few tenths of a pixel of the truth).
            let on = drawn_share(&img, c, r, 1.5);
            assert!(
                on >= 0.9,
                "frame {k}: outline drawn in {on:.2} of the directions"
            );
            // Well inside and well outside: not drawn (the mark's ring reaches 0.7 R,
            // its dark halo a pixel beyond: up to ~0.1 of the circle at 0.8 R).
            for f in [0.8, 1.35] {
                let off = drawn_share(&img, c, f * r, 0.0);
                assert!(
                    off <= 0.15,
                    "frame {k}: drawn at {f} R in {off:.2} of the directions"
                );
            }
            checked += 1;
        }
    }
    assert!(checked >= 16, "{checked} balls checked");
    // Each tile names its frame and time (100 frames/s) in its bottom right corner.
    for (tile, &k) in shown.iter().enumerate() {
        let (ox, oy) = (4 + 324 * (tile as u32 % 4), 4 + 184 * (tile as u32 / 4));
        // Counted from 1, as the app's video view counts; the time from the first.
        let text = format!("frame {}  {:.3} s", k + 1, k as f64 / 100.0);
        let wrong = caption_misses(&img, (ox + 320, oy + 180), &text);
        assert_eq!(
            wrong, 0,
            "tile {tile} (frame {k}): {wrong} pixels differ from '{text}'"
        );
    }
}

/// How many pixels of the 8×8 font's `text`, written white on a dark box ending 10 px
/// above the tile's bottom right corner `corner` (exclusive) and 1 px inside it as the
/// overlay writes captions, are not so: a set font pixel not white, or a clear one
/// not dark.
fn caption_misses(img: &image::RgbImage, corner: (u32, u32), text: &str) -> usize {
    let x0 = corner.0 - (8 * text.len() as u32 + 2);
    let y0 = corner.1 - 10 + 1;
    let mut wrong = 0;
    for (i, ch) in text.bytes().enumerate() {
        let rows = font8x8::legacy::BASIC_LEGACY[usize::from(ch)];
        for (row, bits) in rows.iter().enumerate() {
            for col in 0..8u32 {
                let p = img.get_pixel(x0 + 8 * i as u32 + col, y0 + row as u32).0;
                let white = p.iter().all(|&v| v >= 250);
                let dark = p.iter().all(|&v| v <= 90);
                let set = bits & (1 << col) != 0;
                wrong += usize::from(if set { !white } else { !dark });
            }
        }
    }
    wrong
}

#[test]
fn a_bad_overlay_name_is_refused_in_one_line_before_tracking() {
    let dir = scratch_dir("video_overlay", "bad");
    let frames = dir.join("frames");
    film(&frames);
    let missing = dir.join("no-such-folder").join("check.png");
    for (file, says) in [
        (dir.join("check.txt"), "not '.txt'"),
        (dir.join("check"), "a name without an ending"),
        (missing, "no-such-folder"),
    ] {
        let (code, _, err) = run(&track_args(&frames, &["--overlay", file.to_str().unwrap()]));
        assert_eq!(code, 2, "{err}");
        let line = err.trim();
        assert!(
            line.starts_with("error: ") && line.lines().count() == 1,
            "{err}"
        );
        assert!(line.contains(says), "{line}");
        assert!(!file.exists());
    }
}

/// A clip the tracker refuses (the balls in its first 8 frames of 30 only: neither
/// ball in a third of the frames): with `--overlay` what it found is drawn over a
/// pixel grid, and the one error line says where; without, nothing is written.
#[test]
fn a_refused_tracking_draws_what_was_found_over_a_pixel_grid() {
    let dir = scratch_dir("video_overlay", "refused");
    let frames = dir.join("frames");
    let film = film(&frames);
    for k in 8..30 {
        let p = frames.join(format!("frame{:04}.png", k + 1));
        let empty = film.empty(k);
        write::png(&p, empty.as_raw(), 320, 180).unwrap();
    }
    let sheet = dir.join("check.png");
    let tracks = dir.join("tracks.txt");
    let track = |overlay: Option<&Path>| {
        let mut more = vec!["--output", tracks.to_str().unwrap()];
        if let Some(o) = overlay {
            more.extend(["--overlay", o.to_str().unwrap()]);
        }
        run(&track_args(&frames, &more))
    };
    let (code, _, err) = track(None);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("tracking unsure"), "{err}");
    assert!(!err.contains("pixel grid") && !sheet.exists(), "{err}");
    let (code, _, err) = track(Some(&sheet));
    assert_eq!(code, 2, "{err}");
    let line = err.trim();
    assert!(
        line.starts_with("error: ") && line.lines().count() == 1,
        "{err}"
    );
    assert!(line.contains("tracking unsure"), "{line}");
    assert!(
        line.ends_with(&format!("drawn over a pixel grid in {}", sheet.display())),
        "{line}"
    );
    assert!(!dir.join("tracks.txt").exists(), "no tracks are written");
    let img = image::open(&sheet).unwrap().to_rgb8();
    assert_eq!((img.width(), img.height()), (4 + 4 * 324, 4 + 3 * 184));
    // The first tile is frame 0: both balls found there, drawn on their outlines
    // (at their own fitted radius, within 1.5 px of the truth).
    for t in film.truth(0) {
        let c = (4.0 + t.centre.0, 4.0 + t.centre.1);
        let on = drawn_share(&img, c, t.radius, 1.5);
        assert!(on >= 0.9, "outline drawn in {on:.2} of the directions");
    }
    // The grid (every 50 px of the 320 px frame): the column x = 100 is lightened
    // against the frame under it, the columns beside it are not.
    let frame0 = film.image(0);
    let lighter = |x: u32, y: u32| {
        let (a, b) = (img.get_pixel(4 + x, 4 + y).0, frame0.get_pixel(x, y).0);
        (0..3)
            .map(|c| i32::from(a[c]) - i32::from(b[c]))
            .sum::<i32>()
            > 60
    };
    // Rows above the balls, below the labels of x.
    let rows = 15..48;
    assert!(rows.clone().all(|y| lighter(100, y)));
    assert!(rows.clone().all(|y| !lighter(97, y) && !lighter(103, y)));
    // As a video: every frame, at the folder's --fps (a folder says no rate).
    let clip = dir.join("check.mp4");
    let (code, _, err) = track(Some(&clip));
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("pixel grid in"), "{err}");
    let probe = std::process::Command::new("ffprobe")
        .args(["-v", "error", "-select_streams", "v:0", "-count_frames"])
        .args([
            "-show_entries",
            "stream=r_frame_rate,nb_read_frames",
            "-of",
            "csv=p=0",
        ])
        .arg(&clip)
        .output()
        .unwrap();
    assert_eq!(String::from_utf8_lossy(&probe.stdout).trim(), "100/1,30");
}

/// The overlay clip is the same bytes on one core as on all of them: x264's output
/// depends on its thread count, by default 1.5 a core, so the video writer fixes it
/// (the video tests' clips, written by it, were other clips on other machines). Run
/// under `taskset -c 0`, a process sees one core.
#[test]
fn an_encoded_clip_is_the_same_on_one_core_as_on_all() {
    if !super::tracking::ffmpeg() {
        return;
    }
    let cpus = std::thread::available_parallelism().map_or(1, usize::from);
    let taskset = std::process::Command::new("taskset")
        .arg("--version")
        .output();
    if cpus < 2 || !taskset.is_ok_and(|o| o.status.success()) {
        // One core: every run is on one. No taskset (util-linux): nothing to pin with.
        eprintln!("SKIPPED: {cpus} core(s), or no taskset");
        return;
    }
    let dir = scratch_dir("video_overlay", "cores");
    let frames = dir.join("frames");
    film(&frames);
    let encode = |clip: &Path, one_core: bool| {
        let args = track_args(&frames, &["--overlay", clip.to_str().unwrap()]);
        let mut cmd = if one_core {
            let mut c = std::process::Command::new("taskset");
            c.args(["-c", "0", env!("CARGO_BIN_EXE_groovelab")]);
            c
        } else {
            std::process::Command::new(env!("CARGO_BIN_EXE_groovelab"))
        };
        let out = cmd.args(args).output().unwrap();
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        std::fs::read(clip).unwrap()
    };
    let all = encode(&dir.join("all.mp4"), false);
    let one = encode(&dir.join("one.mp4"), true);
    assert!(all.len() > 1000, "{} bytes", all.len());
    assert!(
        all == one,
        "{} bytes on all cores, {} on one",
        all.len(),
        one.len()
    );
}
