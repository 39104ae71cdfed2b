//! A video given as `--data` everywhere data are read: `data`, `fit`, `render` and
//! the app, from a folder of frames rendered here (small: no ffmpeg needed) or an mp4
//! (where ffmpeg is installed; CI has it). The app tracks on a worker, shows how far,
//! takes the data in when done and keeps them; `V` draws the frame at the cursor with
//! the tracked points and the model's balls over it.

use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::OnceLock;

use groovelab::cli::{DataArgs, SceneArgs};
use groovelab::input::video::tracked::Options;
use groovelab::input::video::write;
use groovelab::settings::params::Key;
use groovelab::settings::spec::SceneSpec;
use groovelab::tui::app::{Action, Status};
use groovelab::tui::vocabulary::View;
use serde_json::Value;

use crate::common;
use crate::film::{Film, Look};
use groovelab::vision::thumbs::VideoView;

/// A small clip: 320×180 at 500 px/m (R = 13.75 px), 100 frames/s, t = −0.15 … 0.34 s.
pub fn look() -> Look {
    Look {
        width: 320,
        height: 180,
        px_per_m: 500.0,
        origin: (160.0, 85.0),
        from: -0.15,
        ..Look::default()
    }
}

pub const FRAMES: usize = 50;

/// The scratch folder of these tests (`target/tmp/video-app`, reused by each run).
fn scratch() -> PathBuf {
    let d = crate::common::scratch_root("video-app");
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// The small clip as a folder of PNG frames, `…/frames` (made once per test process:
/// its name is in the screens). Never removed and remade: each frame is written
/// beside it and moved in whole, so a test of another process (`cargo nextest` runs
/// one per test) reading the folder meanwhile sees every frame, each complete (the
/// same bytes whoever wrote it last).
pub fn folder() -> &'static Path {
    static DIR: OnceLock<PathBuf> = OnceLock::new();
    DIR.get_or_init(|| {
        let d = scratch().join("frames");
        let beside = scratch().join(format!("frames-being-written-{}", std::process::id()));
        std::fs::create_dir_all(&d).unwrap();
        std::fs::create_dir_all(&beside).unwrap();
        let look = look();
        let film = Film::new(&common::paper_scene(), look, 0.4);
        let name = |k: usize| format!("frame{:04}.png", k + 1);
        for k in 0..FRAMES {
            let p = beside.join(name(k));
            write::png(&p, &film.rgb(k), look.width, look.height).unwrap();
            std::fs::rename(&p, d.join(name(k))).unwrap();
        }
        let _ = std::fs::remove_dir(&beside);
        // A longer clip's frames from an older run are no frames of this one.
        for e in std::fs::read_dir(&d).unwrap().flatten() {
            let file = e.file_name().to_string_lossy().into_owned();
            if !(0..FRAMES).any(|k| name(k) == file) {
                let _ = std::fs::remove_file(e.path());
            }
        }
        d
    })
}

/// `groovelab args` in the scratch folder (where `frames` is the clip's folder),
/// with a cache folder of the test's own (`cache`): exit status, stdout, stderr.
fn run(args: &[&str], cache: &Path) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_groovelab"))
        .args(args)
        .current_dir(scratch())
        .env("XDG_CACHE_HOME", cache)
        .env("GROOVELAB_PRESETS", "/nonexistent-groovelab-presets")
        .output()
        .unwrap();
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

fn cache(test: &str) -> PathBuf {
    let d = scratch().join(format!("cache-{test}"));
    let _ = std::fs::remove_dir_all(&d);
    d
}

/// The folder's options: R = 2.75 cm, b = 4.9 cm, 100 frames/s.
const OPTIONS: [&str; 6] = ["--fps", "100", "--radius", "2.75cm", "--width", "4.9cm"];

#[test]
fn a_folder_of_frames_is_data_for_data_and_fit_and_is_kept_in_the_cache() {
    let dir = folder().to_str().unwrap();
    let c = cache("data-fit");
    let (code, out, err) = run(&["data", dir, "--fps", "100", "--radius", "2.75cm"], &c);
    assert_eq!(code, 0, "{err}");
    // Said as what it is: not a Tracker file with no units stated.
    assert!(
        out.contains("video tracked by groovelab, position track")
            && out.contains(
                "length in m: the scale from the ball's radius R = 2.75 cm in the frames ("
            )
            && out.contains("time in s: the video's frames (100 frames/s: given (--fps)")
            && !out.contains("Tracker")
            && !out.contains("none stated"),
        "{out}"
    );
    // 49 found (one frame touching at the impact) of the clip's 50 at its rate.
    assert!(out.contains("49 of 50 frames at 100 frames/s"), "{out}");
    // Tracked once: the text --data reads and the app's pictures, in the cache.
    let kept: Vec<String> = std::fs::read_dir(c.join("groovelab/tracks"))
        .unwrap()
        .map(|e| {
            e.unwrap()
                .path()
                .extension()
                .unwrap()
                .to_string_lossy()
                .into_owned()
        })
        .collect();
    assert_eq!(kept.len(), 2, "{kept:?}");
    assert!(kept.contains(&"txt".into()) && kept.contains(&"view".into()));
    let mut args = vec!["fit", "--data", dir, "--format", "json"];
    args.extend(OPTIONS);
    let (code, out, err) = run(&args, &c);
    assert_eq!(code, 0, "{err}");
    let j: Value = serde_json::from_str(&out).unwrap();
    let (mu, se) = (
        j["model_fit"]["mu"].as_f64().unwrap(),
        j["model_fit"]["mu_se"].as_f64().unwrap(),
    );
    // The scale's ± (0.4 % at R = 13.7 px) adds to the fit's own.
    let sigma = se.hypot(0.004 * mu);
    assert!((mu - 0.17).abs() <= 2.0 * sigma, "μ_k = {mu} ± {sigma}");
    assert_eq!(j["model_fit"]["regime_observed"], "recollide");
}

/// The fit's scene line says where each value came from: a video tracked without
/// `--radius` was scaled with the preset's R, which its tracks state (as a track
/// file's header does), not an option typed (an empty "and )" before).
#[test]
fn the_scene_line_names_the_radius_a_video_was_tracked_with() {
    let dir = folder().to_str().unwrap();
    let c = cache("scene-line");
    let line = |extra: &[&str]| {
        let mut args = vec!["fit", "--data", dir, "--fps", "100"];
        args.extend(extra);
        let (code, out, err) = run(&args, &c);
        assert_eq!(code, 0, "{err}");
        out.lines().next().unwrap_or_default().to_string()
    };
    let untyped = line(&[]);
    assert!(
        untyped.starts_with(&format!(
            "scene (default preset paper-b4.9 with v0 from the data's approach and {dir}'s tracks (radius)): R = 2.75 cm"
        )),
        "{untyped}"
    );
    let typed = line(&["--radius", "2.75cm"]);
    assert!(
        typed.starts_with("scene (default preset paper-b4.9 with v0 from the data's approach and --radius): R = 2.75 cm"),
        "{typed}"
    );
}

/// A folder given as `--data` can only be one of frames: one without them is refused
/// as such by every command, `--fps` with it taken (it was "a directory, allowed a
/// regular file", and `--fps` "not used by fit").
#[test]
fn a_folder_without_frames_is_refused_as_a_folder_of_frames() {
    let empty = crate::common::scratch_dir("video-app", "no-frames");
    let e = empty.to_str().unwrap();
    let c = cache("no-frames");
    for args in [
        vec!["fit", "--data", e, "--radius", "2.75cm"],
        vec!["fit", "--data", e, "--radius", "2.75cm", "--fps", "100"],
        vec!["data", e],
        vec!["render", "--data", e, "--size", "80x24"],
    ] {
        let (code, out, err) = run(&args, &c);
        assert_eq!(code, 2, "{args:?}: {out}{err}");
        assert_eq!(
            err.trim(),
            format!(
                "error: {e}: holds 0 PNG/JPEG frames, expected a folder of numbered frames (at least two)"
            ),
            "{args:?}"
        );
    }
}

/// A folder's cache key is its frames': another file in it (notes, a stray video)
/// is no part of the clip and is never read (a folder of other files was hashed whole
/// before it was refused as holding no frames).
#[test]
fn a_folders_other_files_are_no_part_of_its_cache_key() {
    let dir = crate::common::scratch_dir("video-app", "frames-and-notes");
    for e in std::fs::read_dir(folder()).unwrap() {
        let p = e.unwrap().path();
        std::fs::copy(&p, dir.join(p.file_name().unwrap())).unwrap();
    }
    let d = dir.to_str().unwrap();
    let c = cache("other-files");
    let kept = || std::fs::read_dir(c.join("groovelab/tracks")).map_or(0, |r| r.count());
    let args = ["data", d, "--fps", "100", "--radius", "2.75cm"];
    let (code, _, err) = run(&args, &c);
    assert_eq!(code, 0, "{err}");
    assert_eq!(kept(), 2, "the text and the pictures");
    std::fs::write(dir.join("notes.txt"), "filmed on Monday").unwrap();
    let (code, _, err) = run(&args, &c);
    assert_eq!(code, 0, "{err}");
    assert_eq!(kept(), 2, "tracked again for a file that is no frame");
}

/// A `--ball-at` seed that finds no ball is said in the tracks' notes (it was passed
/// over in silence: the user saw the same tracks as without it); one on a ball is
/// used and not noted.
#[test]
fn a_seed_that_finds_no_ball_is_said() {
    let dir = folder().to_str().unwrap();
    let film = Film::new(&common::paper_scene(), look(), 0.4);
    let ball = film.truth(0)[0].centre;
    let on_ball = format!("{:.0},{:.0}", ball.0, ball.1);
    let c = cache("seed-note");
    for (at, noted) in [("5,5", true), (on_ball.as_str(), false)] {
        let (code, out, err) = run(
            &[
                "track",
                dir,
                "--fps",
                "100",
                "--radius",
                "2.75cm",
                "--ball-at",
                at,
            ],
            &c,
        );
        assert_eq!(code, 0, "{at}: {err}");
        let note = format!(
            "# --ball-at {at}: no ball's outline was found about that point, so the seed was not used"
        );
        assert_eq!(out.contains(&note), noted, "{at}: {out}");
        assert!(out.contains("# left ball: centre in"), "{at}: {out}");
    }
}

#[test]
fn video_options_refused_where_they_mean_nothing() {
    let dir = folder().to_str().unwrap();
    let c = cache("refused");
    let csv = scratch().join("v.csv");
    std::fs::write(
        &csv,
        "t,v_cm,v_t\n-0.02,0.8,0.8\n0,0.1,0.8\n0.02,-0.6,0.7\n",
    )
    .unwrap();
    for (args, says) in [
        (vec!["render", "--data", dir], "give it with --fps"),
        (
            vec!["fit", "--preset", "paper-b4.9", "--fps", "100"],
            "--fps describes a --data file and none is given",
        ),
        (
            vec!["fit", "--data", csv.to_str().unwrap(), "--fps", "100"],
            "--fps is not used by fit, allowed only with track, and --data VIDEO",
        ),
    ] {
        let (code, out, err) = run(&args, &c);
        assert_eq!(code, 2, "{args:?}: {out}{err}");
        assert!(
            err.starts_with("error: ") && err.contains(says),
            "{args:?}: {err}"
        );
        assert_eq!(err.lines().count(), 1, "{err}");
    }
}

/// `render` of the folder with `V` (the video) at `--at 0.1`, at `size`.
fn video_screen(size: &str, ascii: bool, c: &Path) -> String {
    folder();
    let mut args = vec!["render", "--data", "frames", "--keys", "V", "--at", "0.1"];
    args.extend(OPTIONS);
    args.extend(["--size", size]);
    if ascii {
        args.push("--ascii");
    }
    let (code, out, err) = run(&args, c);
    assert_eq!(code, 0, "{err}");
    out
}

#[test]
fn render_prints_the_video_with_the_tracks_and_the_model_over_it() {
    let c = cache("render");
    for size in ["80x24", "120x40", "200x60"] {
        let screen = video_screen(size, false, &c);
        assert!(screen.contains("Video frames"), "{screen}");
        insta::assert_snapshot!(format!("video-{size}"), screen);
    }
    let ascii = video_screen("80x24", true, &c);
    assert!(ascii.is_ascii(), "{ascii}");
    insta::assert_snapshot!("video-80x24-ascii", ascii);
}

/// The scene options R = 2.75 cm, b = 4.9 cm.
fn paper_groove() -> SceneArgs {
    SceneArgs {
        values: SceneSpec::default()
            .with(Key::Radius, 0.0275)
            .with(Key::Width, 0.049),
        ..SceneArgs::default()
    }
}

/// The app opened on `scene` with the folder `dir` (at `fps`) as its `--data`,
/// tracked on a worker for balls of R = 2.75 cm (the cache unused); `area` names
/// its user presets' scratch folder.
fn tracking(dir: &Path, fps: f64, scene: &SceneArgs, area: &str) -> groovelab::tui::app::App {
    let data = DataArgs {
        data: vec![dir.to_path_buf()],
        fps: Some(fps),
        ..DataArgs::default()
    };
    let options = Options {
        radius: 0.0275,
        fps: Some(fps),
        px_per_m: None,
        radius_from: "--radius".into(),
        cache: None,
        roi: None,
        ball_at: None,
    };
    let library = common::no_user_presets(area);
    groovelab::cli::opened_tracking(scene, &data, library, options).unwrap()
}

#[test]
fn the_app_tracks_on_a_worker_and_takes_the_data_in_when_done() {
    let dir = folder().to_path_buf();
    let scene = paper_groove();
    let data = DataArgs {
        data: vec![dir.clone()],
        fps: Some(100.0),
        ..DataArgs::default()
    };
    let mut app = tracking(&dir, 100.0, &scene, "video-app");
    // Open at once, without the data: they join when the job's result is taken.
    assert!(app.lab.own_data().is_none());
    assert!(
        matches!(&app.status, Status::Info(s) if s.starts_with("tracking ")),
        "{:?}",
        app.status
    );
    let before = app.lab.generation();
    // An edit meanwhile is kept.
    app.set_value(Key::Mu, 0.2);
    app.wait();
    let own = app.lab.own_data().expect("the video's data in the lab");
    assert_eq!(own.name, dir.display().to_string());
    assert!(app.lab.generation() > before);
    assert_eq!(app.lab.scene.mu, 0.2);
    assert!(app.video().view.is_some(), "the pictures");
    assert!(
        matches!(&app.status, Status::Info(s) if s.starts_with("tracked ")),
        "{:?}",
        app.status
    );
    // The model's balls where the film has them: at every frame with both tracked,
    // the exact solution's centres mapped into the video by the tracker's scale,
    // groove and origin lie on the tracked ones (the film was made with this scene;
    // 0.1 px of centre noise, 0.4 % of scale: well under a pixel).
    let view = app.video().view.clone().unwrap();
    app.lab.set(Key::Mu, 0.17).unwrap();
    let (mut compared, mut worst) = (0, 0.0f64);
    for k in 0..FRAMES {
        let (Some(Some(l)), Some(Some(r))) = (
            view.balls[0].centre.get(k),
            view.balls.get(1).and_then(|b| b.centre.get(k)),
        ) else {
            continue;
        };
        app.t = groovelab::tui::view::video::frame_time(&app, &view, k).unwrap();
        let model = groovelab::tui::view::video::model_centres(&app, &view).unwrap();
        for (m, t) in model.iter().zip([l, r]) {
            let d = (m.0 - f64::from(t.0)).hypot(m.1 - f64::from(t.1));
            assert!(d < 1.0, "frame {k}: model {m:?}, tracked {t:?}: {d} px");
            worst = worst.max(d);
        }
        compared += 1;
    }
    eprintln!("model against tracked centres: {compared} frames, worst {worst:.2} px");
    assert!(compared >= 40, "{compared} frames");
    app.lab.set(Key::Mu, 0.2).unwrap();
    // Kept in this process: a second open needs no tracking.
    assert!(
        groovelab::cli::pending_video(&scene, &data)
            .unwrap()
            .is_none()
    );
    // V shows the video, V again the drawn scene.
    app.apply(Action::ToggleVideo);
    let text = common::text(&app, (120, 40), false);
    assert!(text.contains("Video frames"), "{text}");
    graphics_once_per_frame(&app, &view);
    app.apply(Action::ToggleVideo);
    assert!(common::text(&app, (120, 40), false).contains(" Scene  t = "));
}

/// While the user's video is tracked, and after its tracking is refused, the app
/// shows no measured series: the preset's points beside "measured v_cm" (and v0
/// named the data's, a data line in Why) read as the user's own (a new user's
/// report: a refused clip showed the paper's data as if they were the clip's).
#[test]
fn a_refused_video_leaves_no_preset_data_standing_in_for_it() {
    let dir = super::blank_frames("video_app_refused", 6);
    let mut app = tracking(&dir, 30.0, &paper_groove(), "video-app-refused");
    let shown = |app: &groovelab::tui::app::App| {
        let text = common::text(app, (120, 40), false);
        assert!(!text.contains("measured v_cm"), "{text}");
        assert!(!text.contains("data: RMS"), "{text}");
        assert!(!text.contains(" d both balls"), "{text}");
    };
    assert!(app.lab.series().is_none());
    shown(&app);
    app.wait();
    assert!(
        matches!(&app.status, Status::Error(s) if s.contains("no ball found")),
        "{:?}",
        app.status
    );
    assert!(app.lab.series().is_none());
    shown(&app);
    // The Fit view asked for says the clip was not tracked (not that the preset has
    // no data, which a new user read as a contradiction).
    app.apply(Action::ShowView(View::Fit));
    assert!(
        matches!(&app.status, Status::Error(s) if s.starts_with("frames was not tracked, so there are no data to fit")),
        "{:?}",
        app.status
    );
    app.apply(Action::ShowView(View::Charts));
    // D gives the preset's data their place back (it said "no data of your own").
    app.apply(Action::DropData);
    assert!(
        matches!(&app.status, Status::Info(s) if s.starts_with(&format!("dropped {}", dir.display()))),
        "{:?}",
        app.status
    );
    assert!(app.lab.series().is_some());
    assert!(common::text(&app, (120, 40), false).contains("measured v_cm"));
}

/// A preset file whose v0 only its measured series gives (no `v0` line) opens on a
/// video tracked on a worker without a panic (the lab named no value the data's and
/// then had no v0): its series' values stay, the series itself is not shown.
#[test]
fn a_preset_whose_v0_is_its_series_opens_on_a_video_tracked_on_a_worker() {
    let dir = super::blank_frames("video_app_nov0", 6);
    let text = std::fs::read_to_string("presets/paper-b4.9.toml").unwrap();
    let nov0: String = text
        .lines()
        .filter(|l| !l.trim_start().starts_with("v0"))
        .map(|l| format!("{l}\n"))
        .collect();
    let preset = dir.with_file_name("nov0.toml");
    std::fs::write(&preset, nov0).unwrap();
    let scene = SceneArgs {
        preset: Some(preset.display().to_string()),
        ..SceneArgs::default()
    };
    let mut app = tracking(&dir, 30.0, &scene, "video-app-nov0");
    assert!(app.lab.series().is_none());
    assert!(
        (app.lab.scene.left.v0 - 0.7928).abs() < 0.01,
        "{}",
        app.lab.scene.left.v0
    );
    app.wait();
    assert!(app.lab.series().is_none());
}

/// With a graphics protocol (kitty, forced: no terminal here), the video panel's
/// picture is made on a worker once per picture shown, not per redraw, and drawn
/// into the panel's cells.
fn graphics_once_per_frame(app: &groovelab::tui::app::App, view: &VideoView) {
    use groovelab::tui::screen::Screen;
    use ratatui::buffer::Buffer;
    use ratatui::layout::Rect;
    use ratatui_image::picker::{Picker, ProtocolType};
    let mut app = app.clone();
    let (tx, rx) = std::sync::mpsc::channel();
    let mut picker = Picker::halfblocks();
    picker.set_protocol_type(ProtocolType::Kitty);
    let wake = Box::new(move || {
        let _ = tx.send(());
    });
    let mut screen = Screen::with_graphics(Some(picker), wake);
    let (area, theme) = (Rect::new(0, 0, 120, 40), groovelab::tui::theme(false));
    let mut buf = Buffer::empty(area);
    app.t = groovelab::tui::view::video::frame_time(&app, view, 20).unwrap();
    screen.draw(&app, area, &mut buf, &theme);
    // A hang guard, not a measurement.
    rx.recv_timeout(std::time::Duration::from_secs(60))
        .expect("the picture made");
    let symbols = |buf: &Buffer| -> String { buf.content().iter().map(|c| c.symbol()).collect() };
    // Sent once (kitty keeps it), then placed by its placeholder characters.
    screen.draw(&app, area, &mut buf, &theme);
    assert!(symbols(&buf).contains("\x1b_G"), "kitty's escape sends it");
    for _ in 0..3 {
        screen.draw(&app, area, &mut buf, &theme);
    }
    assert!(symbols(&buf).contains('\u{10EEEE}'), "kitty's placeholders");
    assert_eq!(screen.video_pictures(), 1, "one picture for five redraws");
    app.t = groovelab::tui::view::video::frame_time(&app, view, 21).unwrap();
    screen.draw(&app, area, &mut buf, &theme);
    assert_eq!(screen.video_pictures(), 2, "the next frame: a new picture");
}

#[test]
fn the_tracking_shows_its_progress_and_a_key_never_waits_for_it() {
    let library = common::no_user_presets("video-progress");
    let scene = SceneArgs {
        preset: Some("inelastic".into()),
        ..SceneArgs::default()
    };
    let mut app = groovelab::cli::opened(&scene, &DataArgs::default(), library).unwrap();
    let (tx, rx) = std::sync::mpsc::channel::<()>();
    app.track_video("clip.mp4".into(), move |ticket| {
        ticket.progress(3, 10);
        // Held until the test lets it go: the app runs on meanwhile.
        let _ = rx.recv();
        None
    });
    let mut spins = 0u64;
    while app.video().progress() != Some((3, 10)) {
        std::thread::yield_now();
        spins += 1;
        assert!(spins < 1 << 32, "the job never started");
    }
    // Keys act while it runs.
    app.apply(Action::PlayPause);
    assert!(app.playing);
    let text = common::text(&app, (120, 40), false);
    assert!(text.contains("tracking video 30 %"), "{text}");
    app.apply(Action::ToggleVideo);
    let text = common::text(&app, (120, 40), false);
    assert!(text.contains("tracking clip.mp4: frame 3 of 10"), "{text}");
    // The Fit view asked for before the data came (a preset without any): they are
    // still to come, not "no measured data" (true only until then).
    app.apply(Action::ShowView(View::Fit));
    assert!(
        matches!(&app.status, Status::Error(s) if s.starts_with("clip.mp4 is still being tracked")),
        "{:?}",
        app.status
    );
    tx.send(()).unwrap();
    app.wait();
    assert_eq!(app.video().progress(), None);
}

#[test]
fn an_mp4_is_data_for_the_app_and_render() {
    if !crate::video::tracking::ffmpeg() {
        return;
    }
    let look = look();
    let film = Film::new(&common::paper_scene(), look, 0.4);
    let clip = scratch().join("clip.mp4");
    let enc = write::Encoding {
        width: look.width,
        height: look.height,
        fps: 100.0,
        crf: 18,
        metadata: Vec::new(),
    };
    write::video(&clip, &enc, (0..FRAMES).map(|k| film.rgb(k))).unwrap();
    let c = cache("mp4");
    let mut args = vec!["render", "--data", clip.to_str().unwrap(), "--keys", "V"];
    args.extend(&OPTIONS[2..]);
    let (code, out, err) = run(&args, &c);
    assert_eq!(code, 0, "{err}");
    assert!(
        out.contains("Video clip.mp4") && out.contains("of 50"),
        "{out}"
    );
}
