//! A click on a ball in the app's video view seeds the tracker (issue 34): the clicked
//! terminal cell maps to the video's pixel it shows, at any panel size, video size,
//! groove tilt and offset, and the click asks the video view's tracking again with
//! that pixel as `ball_at`, the other options kept.

use std::sync::Arc;
use std::sync::mpsc;

use groovelab::cli::{DataArgs, SceneArgs};
use groovelab::input::video::tracked::Options;
use groovelab::tui::app::{Action, App, Status};
use groovelab::tui::layer::main::video::{VideoTracker, VideoWork};
use groovelab::tui::screen::Screen;
use groovelab::tui::view::video::{cell_at, pixel_at};
use groovelab::vision::thumbs::{BallPixels, Thumbs, VideoView};
use proptest::prelude::*;
use ratatui::crossterm::event::{KeyModifiers, MouseButton, MouseEvent, MouseEventKind};
use ratatui::layout::Rect;

use crate::common;

/// A video of `w` × `h` px (no pictures: the mapping needs none), its groove through
/// `origin` tilted by `groove` rad, its balls of `radius_px` (NaN: unknown, the band
/// is the whole frame).
fn video(w: usize, h: usize, groove: f64, origin: (f64, f64), radius_px: f64) -> VideoView {
    VideoView {
        thumbs: Thumbs::sized(w, h, 1),
        t: vec![0.0],
        px_per_m: 1000.0,
        groove,
        origin,
        radius_px,
        balls: vec![BallPixels {
            name: "left".into(),
            centre: vec![Some((w as f32 / 3.0, origin.1 as f32))],
            mark: vec![None],
        }],
        levels: [40, 100, 250],
        first_only: None,
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    /// The cell a pixel is drawn in maps back to that pixel within half a cell (the
    /// cell's middle), a cell is twice as tall as wide in video pixels (two half-block
    /// pixels), and the panel's border is never on the picture.
    #[test]
    fn a_clicked_cell_maps_to_the_video_pixel_drawn_there(
        w in 16usize..2000, h in 16usize..1200,
        tilt in -0.3f64..0.3, oy in 0.0f64..1.0, r in prop_oneof![Just(f64::NAN), 2.0f64..80.0],
        ax in 0u16..60, ay in 0u16..20, aw in 10u16..120, ah in 4u16..40,
        px in 0.0f64..1.0, py in 0.0f64..1.0,
    ) {
        let view = video(w, h, tilt, (w as f64 / 2.0, oy * h as f64), r);
        let area = Rect::new(ax, ay, aw, ah);
        let p = (px * w as f64, py * h as f64);
        if let Some((c, row)) = cell_at(&view, area, p) {
            prop_assert!(c > area.x && c < area.right() - 1 && row > area.y && row < area.bottom() - 1);
            let got = pixel_at(&view, area, c, row).expect("a cell of the picture");
            prop_assert!(got.0 >= 0.0 && got.0 < w as f64 && got.1 >= 0.0 && got.1 < h as f64);
            // One cell's size in video pixels, measured from its neighbours when they
            // are on the picture.
            if let (Some(right), Some(below)) =
                (pixel_at(&view, area, c + 1, row), pixel_at(&view, area, c, row + 1))
            {
                let (dx, dy) = (right.0 - got.0, below.1 - got.1);
                prop_assert!(dx > 0.0 && (dy - 2.0 * dx).abs() <= 1e-9 * dy, "{dx} {dy}");
                prop_assert!((p.0 - got.0).abs() <= dx / 2.0 + 1e-9, "{p:?} {got:?} {dx}");
                prop_assert!((p.1 - got.1).abs() <= dy / 2.0 + 1e-9, "{p:?} {got:?} {dy}");
            }
        }
        // The border's cells are the panel's frame, not the picture.
        for (c, row) in [(area.x, area.y + ah / 2), (area.x + aw / 2, area.y)] {
            prop_assert_eq!(pixel_at(&view, area, c, row), None);
        }
    }
}

/// Options as the app opened with them: everything but the seed set.
fn options() -> Options {
    Options {
        radius: 0.0127,
        fps: Some(240.0),
        px_per_m: None,
        radius_from: "--radius".into(),
        cache: None,
        roi: None,
        ball_at: None,
    }
}

/// The app with a video's pictures whose tracker reports every options it is asked
/// with (and tracks nothing).
fn app_with_video(view: VideoView) -> (App, mpsc::Receiver<Options>) {
    let library = common::no_user_presets("video-seed");
    let mut app = groovelab::cli::opened(&SceneArgs::default(), &DataArgs::default(), library)
        .expect("the default scene");
    app.set_video("clips/clip.mp4".into(), Some(Arc::new(view)));
    let (tx, rx) = mpsc::channel();
    let tx = std::sync::Mutex::new(tx);
    app.set_video_tracker(VideoTracker {
        options: options(),
        work: Arc::new(move |o: Options| -> VideoWork {
            tx.lock().unwrap().send(o).unwrap();
            Box::new(|_| None)
        }),
    });
    (app, rx)
}

/// The app as a 120×40 terminal shows it: the area, its theme, the screen laid out
/// (what a click lands on) and the Scene panel's rectangle.
fn laid_out(app: &App) -> (Rect, groovelab::tui::theme::Theme, Screen, Rect) {
    let area = Rect::new(0, 0, 120, 40);
    let theme = groovelab::tui::theme(false);
    let mut screen = Screen::default();
    screen.prepare(app, area, &theme);
    let scene = screen
        .frame()
        .and_then(|f| f.panels)
        .expect("laid out")
        .scene;
    (area, theme, screen, scene)
}

fn click(column: u16, row: u16) -> MouseEvent {
    MouseEvent {
        kind: MouseEventKind::Down(MouseButton::Left),
        column,
        row,
        modifiers: KeyModifiers::NONE,
    }
}

#[test]
fn a_click_on_a_ball_tracks_the_video_again_seeded_there() {
    let (w, h) = (640, 360);
    let view = video(w, h, 0.05, (320.0, 200.0), 25.0);
    let ball = (w as f64 / 3.0, 200.0);
    let (mut app, rx) = app_with_video(view.clone());
    let (area, theme, mut screen, scene) = laid_out(&app);
    let (c, r) = cell_at(&view, scene, ball).expect("the ball is on the picture");

    // The drawn scene shows no video: a click there seeds nothing.
    groovelab::tui::on_mouse(&mut app, area, &theme, click(c, r));
    assert!(
        rx.try_recv().is_err(),
        "no tracking while the scene is drawn"
    );

    app.apply(Action::ToggleVideo);
    assert!(app.video().shown);
    // No frame of the video is shown (its data are not the lab's): a seed is a point
    // in the first frame, so a click shows the first frame alone, beside a note.
    assert!(groovelab::tui::on_mouse(
        &mut app,
        area,
        &theme,
        click(c, r)
    ));
    assert!(
        rx.try_recv().is_err(),
        "no tracking from a click off the first frame"
    );
    let first = app.video().picture().cloned().expect("a picture");
    assert!(first.first_only.is_some(), "the first frame alone");
    assert_eq!(first.balls[0].centre, vec![view.balls[0].centre[0]]);
    let text = common::text(&app, (120, 40), false);
    assert!(text.contains("Click a ball to track"), "{text}");
    assert!(text.contains("first frame"), "{text}");

    // A click on the ball in the first frame seeds the tracking there.
    screen.prepare(&app, area, &theme);
    let (c, r) = cell_at(&first, scene, ball).expect("the ball is on the first frame");
    assert!(groovelab::tui::on_mouse(
        &mut app,
        area,
        &theme,
        click(c, r)
    ));
    let asked = rx.try_recv().expect("the click asked the tracking again");
    let seed = asked.ball_at.expect("with a seed");
    assert_eq!(Some(seed), pixel_at(&first, scene, c, r));
    // Within a cell of the ball: a cell is as many video px across as the next
    // cell's pixel is from this one's, and two half-block pixel rows tall.
    let next = pixel_at(&first, scene, c + 1, r).expect("the next cell on the picture");
    let cell = next.0 - seed.0;
    assert!(cell > 0.0);
    assert!((seed.0 - ball.0).abs() <= cell && (seed.1 - ball.1).abs() <= 2.0 * cell);
    assert_eq!(
        Options {
            ball_at: None,
            ..asked
        },
        options(),
        "the rest kept"
    );
    assert_eq!(app.video().seed, Some(seed));
    let Status::Info(said) = &app.status else {
        panic!("{:?}", app.status)
    };
    assert!(
        said.starts_with("tracking clip.mp4 again from the ball at ("),
        "{said}"
    );
    // The job runs on the pool and reports (nothing: this tracker tracks nothing).
    app.wait();
    assert_eq!(app.video().progress(), None);

    // A click off the picture (the parameters panel) seeds nothing.
    let params = screen.frame().and_then(|f| f.panels).unwrap().params;
    groovelab::tui::on_mouse(&mut app, area, &theme, click(params.x + 2, params.y + 2));
    assert!(rx.try_recv().is_err(), "no tracking from a click elsewhere");
}

#[test]
fn a_video_that_cannot_be_tracked_again_says_so() {
    let view = video(320, 180, 0.0, (160.0, 90.0), f64::NAN);
    let library = common::no_user_presets("video-seed-none");
    let mut app = groovelab::cli::opened(&SceneArgs::default(), &DataArgs::default(), library)
        .expect("the default scene");
    app.set_video("clip.mp4".into(), Some(Arc::new(view.clone())));
    app.apply(Action::ToggleVideo);
    let (area, theme, _, scene) = laid_out(&app);
    let (c, r) = cell_at(&view, scene, (160.0, 90.0)).unwrap();
    groovelab::tui::on_mouse(&mut app, area, &theme, click(c, r));
    assert!(
        matches!(&app.status, Status::Error(e) if e.contains("cannot be tracked again")),
        "{:?}",
        app.status
    );
    assert_eq!(app.video().seed, None);
}

/// The app tracking a folder of 6 ball-less frames (made under `area`, the user's
/// presets under `presets`), its tracking refused and done: the folder and the app.
fn refused_app(area: &str, presets: &str) -> (std::path::PathBuf, App) {
    let dir = super::blank_frames(area, 6);
    let data = DataArgs {
        data: vec![dir.clone()],
        fps: Some(30.0),
        ..DataArgs::default()
    };
    let options = Options {
        radius: 0.0275,
        fps: Some(30.0),
        ..options()
    };
    let library = common::no_user_presets(presets);
    let mut app =
        groovelab::cli::opened_tracking(&SceneArgs::default(), &data, library, options).unwrap();
    app.wait();
    (dir, app)
}

/// A video the tracker refuses shows its first frame in the video view (`V`) beside
/// why (a seed is a point in the first frame, and a refused video has no other
/// picture to click in); a click there tracks it again seeded at the clicked pixel,
/// and a refusal of that says it was seeded. Through the app's own tracking of a
/// folder of ball-less frames.
#[test]
fn a_refused_video_shows_its_first_frame_and_a_click_there_seeds_it() {
    let (dir, mut app) = refused_app("video_refused_first", "video-refused-first");
    let Status::Error(said) = &app.status else {
        panic!("{:?}", app.status)
    };
    // The reason first, the clip named (not its path), the app's seed (a click)
    // offered, not the command line's flags.
    let name = dir.file_name().unwrap().to_string_lossy().into_owned();
    assert!(
        said.starts_with(&format!("{name} not tracked: no ball found"))
            && said.ends_with("(V: its first frame; click a ball there to seed it)")
            && !said.contains("--roi")
            && !said.contains(&*dir.to_string_lossy()),
        "{said}"
    );
    let first = app.video().picture().cloned().expect("the first frame");
    let why = first.first_only.as_deref().expect("shown alone, with why");
    assert!(why.starts_with("no ball found"), "{why}");
    assert_eq!(first.thumbs.pictures.len(), 1);
    assert_eq!(first.thumbs.video, (64, 48));

    app.apply(Action::ToggleVideo);
    for (size, ascii) in [((80, 24), true), ((80, 24), false), ((120, 40), false)] {
        let text = common::text(&app, size, ascii);
        assert!(text.contains("Click a ball to track"), "{text}");
        assert!(text.contains("no ball found"), "{text}");
        let glyphs = if ascii { "ascii" } else { "unicode" };
        insta::assert_snapshot!(
            format!("refused-first-frame-{}x{}-{glyphs}", size.0, size.1),
            text
        );
    }

    let (area, theme, _, scene) = laid_out(&app);
    let (c, r) = cell_at(&first, scene, (20.0, 30.0)).expect("on the picture");
    assert!(groovelab::tui::on_mouse(
        &mut app,
        area,
        &theme,
        click(c, r)
    ));
    let seed = app.video().seed.expect("seeded by the click");
    assert_eq!(Some(seed), pixel_at(&first, scene, c, r));
    assert!(
        matches!(&app.status, Status::Info(s) if s.starts_with("tracking video_refused_first")
            || s.contains(" again from the ball at (")),
        "{:?}",
        app.status
    );
    app.wait();
    let Status::Error(said) = &app.status else {
        panic!("{:?}", app.status)
    };
    let tried = format!(
        "{name} not tracked from the ball clicked at ({:.0}, {:.0}) px: no ball found",
        seed.0, seed.1
    );
    assert!(
        said.starts_with(&tried) && said.ends_with("click another ball there)"),
        "{said}"
    );
    assert!(
        app.video()
            .picture()
            .is_some_and(|v| v.first_only.is_some()),
        "the first frame again, to click elsewhere"
    );
}

/// While the tracking a click asked for runs, the first frame stays, its title counting
/// the frames (the status line is taken by other messages meanwhile).
#[test]
fn the_first_frame_counts_the_frames_of_the_tracking_again() {
    let view = video(640, 360, 0.0, (320.0, 200.0), 25.0);
    let (mut app, _) = app_with_video(view.clone());
    let (go_on, wait) = mpsc::channel::<()>();
    let (reported, told) = mpsc::channel::<()>();
    let wait = std::sync::Mutex::new(Some(wait));
    let reported = std::sync::Mutex::new(reported);
    app.set_video_tracker(VideoTracker {
        options: options(),
        work: Arc::new(move |_| -> VideoWork {
            let wait = wait.lock().unwrap().take().unwrap();
            let reported = reported.lock().unwrap().clone();
            Box::new(move |ticket| {
                ticket.progress(30, 120);
                reported.send(()).unwrap();
                let _ = wait.recv();
                None
            })
        }),
    });
    app.apply(Action::ToggleVideo);
    let (area, theme, mut screen, scene) = laid_out(&app);
    let ball = (640.0 / 3.0, 200.0);
    let (c, r) = cell_at(&view, scene, ball).unwrap();
    groovelab::tui::on_mouse(&mut app, area, &theme, click(c, r));
    let text = common::text(&app, (120, 40), false);
    assert!(text.contains(" Video clip.mp4  first frame "), "{text}");
    screen.prepare(&app, area, &theme);
    let first = app.video().picture().cloned().unwrap();
    let (c, r) = cell_at(&first, scene, ball).unwrap();
    groovelab::tui::on_mouse(&mut app, area, &theme, click(c, r));
    told.recv().unwrap();
    let text = common::text(&app, (120, 40), false);
    assert!(
        text.contains(" Video clip.mp4  tracking again: frame 30 of 120 "),
        "{text}"
    );
    go_on.send(()).unwrap();
    app.wait();
    let text = common::text(&app, (120, 40), false);
    assert!(!text.contains("tracking again"), "{text}");
}

/// A video's refusal is longer than the status line's two rows at 80 columns, which
/// cut it with an ellipsis; the help (`?`) shows the last message whole above the
/// keys, in both glyph sets (its rows read inside the popup's borders, joined).
#[test]
fn the_help_shows_a_refusal_the_status_line_cuts_whole() {
    let (_, mut app) = refused_app("video_refused_help", "video-refused-help");
    let Status::Error(said) = app.status.clone() else {
        panic!("{:?}", app.status)
    };
    let words = |s: &str| s.split_whitespace().collect::<Vec<_>>().join(" ");
    let before = common::text(&app, (80, 24), false);
    assert!(!words(&before).contains(&words(&said)), "{before}");
    common::press(&mut app, "?");
    for ascii in [false, true] {
        let text = common::text(&app, (80, 24), ascii);
        // The popup is 78 columns wide from the second: its text from the third.
        let inside: Vec<String> = text
            .lines()
            .map(|l| l.chars().skip(2).take(75).collect())
            .collect();
        let read = words(&inside.join(" "));
        assert!(
            read.contains(&format!("Last message: {}", words(&said))),
            "ascii {ascii}: {said}\n{text}"
        );
    }
}
