//! A position track in the lab and on the command line (issue 12's wiring): the scene
//! shown derives its velocities, the track flags reach the reader, the ghost replays
//! the tracked centre and mark, the charts and the Fit panel show what was derived.

use groovelab::cli::{self, DataArgs, RenderArgs, SceneArgs, TrackRole, render_with};
use groovelab::settings::params::Key;
use groovelab::settings::spec::SceneSpec;
use groovelab::tui::app::Library;

use crate::common::{self, groovelab, scene_of};

const EXAMPLE: &str = "docs/video/paper-b4.9-tracker.txt";

fn data(extra: impl FnOnce(&mut DataArgs)) -> DataArgs {
    let mut d = DataArgs {
        data: vec![EXAMPLE.into()],
        ..DataArgs::default()
    };
    extra(&mut d);
    d
}

fn scene(values: SceneSpec) -> SceneArgs {
    scene_of("paper-b4.9", values)
}

fn no_user_presets() -> Library {
    common::no_user_presets("labdata")
}

#[test]
fn the_lab_derives_v_t_with_the_scene_shown_overrides_included() {
    let plain = cli::lab(&scene(SceneSpec::default()), &data(|_| {})).unwrap();
    let narrow = cli::lab(
        &scene(SceneSpec::default().with(Key::Width, 0.044)),
        &data(|_| {}),
    )
    .unwrap();
    let (a, b) = (plain.measured().unwrap(), narrow.measured().unwrap());
    assert!(a.x().is_some(), "a position track");
    // v_t = (dθ/dt) r: the same angle track, scaled by the ratio of the contact radii.
    let ratio = narrow.derived.r / plain.derived.r;
    assert!((ratio - 1.0).abs() > 0.05, "the override changes r");
    let mut compared = 0;
    for (x, y) in a.v_t().iter().zip(b.v_t()) {
        if x.is_finite() && x.abs() > 0.01 {
            assert!((y / x - ratio).abs() < 1e-9, "{y} / {x} against {ratio}");
            compared += 1;
        }
    }
    assert!(compared > 50, "{compared}");
    assert_eq!(a.v_cm(), b.v_cm(), "v_cm does not depend on r");
}

#[test]
fn the_ghost_replays_the_tracked_centre_and_mark() {
    let lab = cli::lab(&scene(SceneSpec::default()), &data(|_| {})).unwrap();
    let m = lab.measured().unwrap();
    let (x, angle) = (m.x().unwrap(), m.angle().unwrap());
    let r = lab.scene.radius;
    for i in (0..m.t().len()).step_by(7) {
        let g = lab.ghost_x(m.t()[i]).unwrap();
        assert!(
            (g - (x[i] - r)).abs() < 1e-12,
            "t = {}: {g} against {}",
            m.t()[i],
            x[i] - r
        );
        if angle[i].is_finite() {
            let a = lab.ghost_angle(m.t()[i]).unwrap();
            let want = lab.solution.angle_at(0.0)[0] + angle[i];
            assert!((a - want).abs() < 1e-12, "t = {}", m.t()[i]);
        }
    }
    // Between two frames: linear between them; outside the series: none.
    let mid = 0.5 * (m.t()[10] + m.t()[11]);
    let g = lab.ghost_x(mid).unwrap();
    assert!((g - (0.5 * (x[10] + x[11]) - r)).abs() < 1e-12);
    assert_eq!(lab.ghost_x(m.t()[0] - 0.01), None);
    // The tracked ghost stays within a few mm of the model's ball it was made from.
    let model = lab.solution.at(0.1).left.x;
    assert!((lab.ghost_x(0.1).unwrap() - model).abs() < 0.005);
}

#[test]
fn the_track_flags_reach_the_reader() {
    // Swapped roles: the rim mark's track taken for the centre, which the reader
    // notices (it strays from a straight line) and names by the flags' tracks.
    let swapped = cli::lab(
        &scene(SceneSpec::default()),
        &data(|d| {
            d.track = vec![
                (TrackRole::Centre, "mass B".into()),
                (TrackRole::Mark, "mass A".into()),
            ]
        }),
    )
    .err()
    .unwrap()
    .to_string();
    assert!(
        swapped.contains("the ball's centre ('mass B') strays")
            && swapped.contains("give --track \"centre=mass A\" --track \"mark=mass B\""),
        "{swapped}"
    );
    let plain = cli::lab(&scene(SceneSpec::default()), &data(|_| {})).unwrap();
    assert!(plain.measured().is_some());
    let err = cli::lab(
        &scene(SceneSpec::default()),
        &data(|d| d.track = vec![(TrackRole::Centre, "nope".into())]),
    )
    .err()
    .unwrap()
    .to_string();
    assert!(
        err.contains("no track 'nope'") && err.contains("mass A"),
        "{err}"
    );
    // --window sets the derivative's half-width; --length-unit the file's unit.
    let json = |args: &[&str]| -> serde_json::Value {
        let mut all = vec![
            "fit",
            "--preset",
            "paper-b4.9",
            "--data",
            EXAMPLE,
            "--format",
            "json",
        ];
        all.extend_from_slice(args);
        crate::common::json(&all)
    };
    let w = json(&["--window", "50ms"]);
    assert_eq!(w["track"]["half_window_frames"], 6);
    // The example (in metres) read as mm is a ball at 0.8 mm/s: refused as such,
    // which only a reader given the unit can say.
    let mm = groovelab(&[
        "fit",
        "--preset",
        "paper-b4.9",
        "--data",
        EXAMPLE,
        "--length-unit",
        "mm",
    ]);
    let err = String::from_utf8_lossy(&mm.stderr);
    assert!(err.contains("moves at up to 0.000797 m/s"), "{err}");
    let out = groovelab(&[
        "fit",
        "--preset",
        "paper-b4.9",
        "--data",
        EXAMPLE,
        "--window",
        "-5ms",
    ]);
    assert_eq!(out.status.code(), Some(2));
    let help = String::from_utf8(groovelab(&["fit", "--help"]).stdout).unwrap();
    for flag in [
        "--track <ROLE=NAME>",
        "--length-unit <UNIT>",
        "--window <T>",
    ] {
        assert!(help.contains(flag), "{flag}\n{help}");
    }
}

fn render(keys: Option<&str>, at: f64, ascii: bool) -> String {
    render_with(
        &scene(SceneSpec::default()),
        &data(|_| {}),
        &RenderArgs {
            at: Some(at),
            size: (120, 40),
            keys: keys.map(str::to_string),
            output: None,
        },
        ascii,
        no_user_presets(),
    )
    .unwrap()
}

#[test]
fn charts_show_error_bars_and_the_fit_panel_both_fits() {
    let screen = render(Some("f"), 0.1, false);
    assert!(screen.contains('¦'), "error bars\n{screen}");
    for want in ["velocities", "positions", "recollide", "agrees"] {
        assert!(screen.contains(want), "{want}\n{screen}");
    }
    // Each row of the two fits says one thing under its own label: the regime
    // predicted, the one observed, the verdict (once read "observed  agrees  agrees",
    // then "observed rest" below it).
    let rows: Vec<Vec<&str>> = screen
        .lines()
        .filter_map(|l| l.rsplit("││").next())
        .map(|l| l.trim_end_matches('│').split_whitespace().collect())
        .collect();
    let row = |label: &str| rows.iter().find(|r| r.first() == Some(&label)).cloned();
    let observed = row("observed").expect("an observed row");
    assert!(
        observed[1..]
            .iter()
            .all(|w| ["depart", "rest", "recollide"].contains(w)),
        "{observed:?}\n{screen}"
    );
    let verdict = row("verdict").expect("a verdict row");
    assert!(
        verdict[1..]
            .iter()
            .all(|w| w.starts_with("agrees") || *w == "DISAGREES" || *w == "(v'≈0)"),
        "{verdict:?}\n{screen}"
    );
    assert!(row("predicted").is_some(), "{screen}");
    assert!(
        !screen.contains("paper: |a_cm|"),
        "not the paper's data\n{screen}"
    );
    insta::assert_snapshot!("render-tracked-video-fit-120x40", screen);
    let ascii = render(None, 0.1, true);
    assert!(ascii.contains('!'));
    assert!(ascii.is_ascii());
    insta::assert_snapshot!("render-tracked-video-120x40-ascii", ascii);
}

/// The screen `render` draws after `keys`, the status line and the row under it left
/// out (an edit in the app reports itself there, a long report on both rows; flags
/// say nothing).
fn screen(preset: &str, values: SceneSpec, file: Option<&str>, keys: &str) -> String {
    let scene = scene_of(preset, values);
    let data = DataArgs {
        data: file.into_iter().map(Into::into).collect(),
        ..DataArgs::default()
    };
    let args = RenderArgs {
        at: Some(0.1),
        size: (120, 40),
        keys: Some(keys.to_string()),
        output: None,
    };
    let text = render_with(&scene, &data, &args, false, no_user_presets()).unwrap();
    let rows: Vec<&str> = text.lines().collect();
    rows[..rows.len() - 2].join("\n")
}

/// `screen` without where each value came from (the parameters panel's marks and
/// their legend: `f` by flags, `e` by keys), and R's mark.
fn without_origins(screen: &str) -> (String, char) {
    let mut r_mark = ' ';
    let rows: Vec<String> = screen
        .lines()
        .enumerate()
        .map(|(i, l)| {
            let mut c: Vec<char> = l.chars().collect();
            match i {
                1..=12 => {
                    if i == 1 {
                        r_mark = c[23];
                    }
                    c[23] = '·';
                }
                13 => {
                    let end = c.iter().position(|&x| x == '╯').unwrap();
                    c[1..end].fill('─');
                }
                _ => {}
            }
            c.into_iter().collect()
        })
        .collect();
    (rows.join("\n"), r_mark)
}

#[test]
fn the_same_scene_by_flags_or_by_keys_draws_the_same_screen() {
    // R = 2.8 cm and b = 4.4 cm typed in the app (a bare number is in the row's unit,
    // cm), then back on b, where the app starts; the same by flags.
    let keys = "up enter 2 . 8 enter down enter 4 . 4 enter";
    let flags = SceneSpec::default()
        .with(Key::Radius, 0.028)
        .with(Key::Width, 0.044);
    for (preset, file) in [
        // No data, a velocity series, a position track with a rim mark (its v_t
        // follows r = kR).
        ("inelastic", None),
        ("paper-b4.9", Some("data/gs-b4.4cm.csv")),
        ("paper-b4.9", Some(EXAMPLE)),
    ] {
        let by_flags = screen(preset, flags.clone(), file, "");
        let by_keys = screen(preset, SceneSpec::default(), file, keys);
        assert!(by_flags.contains("▸b            4.40 cm"), "{by_flags}");
        assert!(by_flags.contains("R            2.80 cm"), "{by_flags}");
        let ((by_keys, typed), (by_flags, given)) =
            (without_origins(&by_keys), without_origins(&by_flags));
        assert_eq!((typed, given), ('e', 'f'), "{by_keys}\n{by_flags}");
        assert_eq!(by_keys, by_flags, "{preset} with {file:?}");
    }
}

#[test]
fn data_follow_the_scene_when_it_changes_in_the_lab() {
    // Once the track's v_t kept the r of start-up after b changed in the app.
    let by_flags = cli::lab(
        &scene(SceneSpec::default().with(Key::Width, 0.044)),
        &data(|_| {}),
    )
    .unwrap();
    let mut by_keys = cli::lab(&scene(SceneSpec::default()), &data(|_| {})).unwrap();
    let before = by_keys.measured().unwrap().v_t().to_vec();
    by_keys.set(Key::Width, 0.044).unwrap();
    let (a, b) = (by_flags.measured().unwrap(), by_keys.measured().unwrap());
    assert_ne!(before, b.v_t(), "v_t follows r");
    // The same numbers, bit for bit: one derivation, scaled by the same r.
    assert_eq!(format!("{:?}", a.v_t()), format!("{:?}", b.v_t()));
    assert_eq!(by_flags.rest_band, by_keys.rest_band);
    assert_eq!(by_flags.data_rms, by_keys.data_rms);
    let t = a.t()[a.t().len() / 2];
    assert_eq!(by_flags.ghost_x(t), by_keys.ghost_x(t));
}

#[test]
fn the_students_file_is_named_once_on_the_status_line_not_in_the_chart_title() {
    // Seen: the chart's title repeated the file name the status line gives.
    let at = |size: (u16, u16)| {
        let args = RenderArgs {
            at: Some(0.1),
            size,
            keys: None,
            output: None,
        };
        let s = scene(SceneSpec::default());
        render_with(&s, &data(|_| {}), &args, false, no_user_presets()).unwrap()
    };
    for size in [(200, 60), (120, 40), (80, 24)] {
        let screen = at(size);
        assert_eq!(
            screen.matches("paper-b4.9-tracker.txt").count(),
            1,
            "{screen}"
        );
        let status = screen.lines().nth(usize::from(size.1) - 2).unwrap();
        assert!(status.ends_with("paper-b4.9-tracker.txt"), "{status}");
    }
    assert!(at((120, 40)).contains("╭ v_cm(t) and v_t(t), left ball  [b] switches ─"));
    // At 80 columns the title is a whole wording, not one cut short.
    assert!(at((80, 24)).contains("╭ v_cm(t) and v_t(t), left ball  [b] ─"));
}

/// Dropping the data forgets their fit: it is neither shown nor applied afterwards
/// (a new-user trial applied μ_k of data it had just dropped).
#[test]
fn a_fit_of_dropped_data_is_not_applied() {
    let out = groovelab(&[
        "render",
        "--preset",
        "steel-and-glass",
        "--data",
        "data/gs-b4.9cm.csv",
        "--keys",
        "f D a",
        "--size",
        "120x40",
    ]);
    assert!(out.status.success());
    let screen = String::from_utf8(out.stdout).unwrap();
    assert!(!screen.contains("applied the fit"), "{screen}");
    assert!(screen.contains("no fit to apply"), "{screen}");
}
