//! Layers of the settings (preset ← command line ← the app's edits) settle into one
//! snapshot (that the same scene reached by flags or by keys draws the same screen is
//! `data::lab_data`'s test): `u` takes back the last edit, `R` all of them; a preset
//! picked keeps the student's data; data without a scene are one rule for the app,
//! `render`, `compare` and `fit`; `simulate` prints the snapshot the app shows for the
//! same options, and `compare` compares over its span.

use std::path::{Path, PathBuf};

use groovelab::cli::{DataArgs, SceneArgs, SimulateArgs, SimulateFormat};
use groovelab::lab::SpanEnd;
use groovelab::methods::Method;
use groovelab::settings::params::Key;
use groovelab::settings::spec::SceneSpec;
use groovelab::study::preset::Preset;
use groovelab::tui::app::{App, Status};
use serde_json::Value;

use crate::common::{self, press, rendered, select, text};

const TRACK: &str = "docs/video/paper-b4.9-tracker.txt";

fn library() -> groovelab::tui::app::Library {
    common::no_user_presets("layers")
}

fn scene(values: SceneSpec) -> SceneArgs {
    SceneArgs {
        preset: Some("paper-b4.9".into()),
        values,
    }
}

fn data(files: &[PathBuf]) -> DataArgs {
    DataArgs {
        data: files.to_vec(),
        ..DataArgs::default()
    }
}

#[test]
fn u_undoes_the_last_change_and_r_resets_all_to_the_preset() {
    let mut a = common::app("paper-b4.9", library());
    let fresh = a.lab.scene;
    let (b, end) = (a.lab.value(Key::Width), a.lab.span_end);
    press(&mut a, "u");
    assert_eq!(a.status, Status::Info("nothing to undo".into()));
    press(&mut a, "left");
    press(&mut a, "down down down enter 0 . 3 enter");
    assert_eq!(a.lab.scene.mu, 0.3);
    assert!(a.lab.value(Key::Width) < b);
    press(&mut a, "u");
    assert_eq!(a.lab.scene.mu, fresh.mu, "μ_k back");
    assert!(a.lab.value(Key::Width) < b, "b still changed");
    assert!(
        matches!(&a.status, Status::Info(s) if s.starts_with("undone: μ_k = 0.17 ")),
        "{:?}",
        a.status
    );
    // As the parameter row writes it: μ_k, and mu_k on an ASCII screen.
    assert!(text(&a, (120, 40), true).contains("undone: mu_k = 0.17 "));
    press(&mut a, "u");
    assert_eq!(a.lab.scene, fresh, "exactly the preset's scene again");
    // The span key is an edit too; R drops every edit.
    press(&mut a, "t right right");
    let (changed, spanned) = (a.lab.scene, a.lab.span_end);
    assert_ne!(spanned, end);
    press(&mut a, "R");
    assert_eq!((a.lab.scene, a.lab.span_end), (fresh, end));
    assert_eq!(
        a.status,
        Status::Info("reset to preset paper-b4.9 (u undoes it)".into())
    );
    press(&mut a, "R");
    assert_eq!(
        a.status,
        Status::Info("nothing to reset: the scene is the preset's".into()),
        "a second R adds nothing to undo"
    );
    // A reset pressed by accident loses nothing: u brings every change back.
    press(&mut a, "u");
    assert_eq!((a.lab.scene, a.lab.span_end), (changed, spanned));
    assert!(
        matches!(&a.status, Status::Info(s) if s.starts_with("undone: the reset")),
        "{:?}",
        a.status
    );
    // ... and the changes before it are undone one by one again: two steps of b
    // (the selected row), then the span key.
    press(&mut a, "u u");
    assert_eq!(a.lab.span_end, spanned);
    assert_eq!(a.lab.scene, fresh);
    press(&mut a, "u");
    assert_eq!(a.lab.span_end, end);
    press(&mut a, "u");
    assert_eq!(a.status, Status::Info("nothing to undo".into()));
}

#[test]
fn a_repeat_that_changes_nothing_adds_no_undo_step() {
    // Seen: `a` pressed twice made two undo steps for one change. A fit applied is no
    // change when it is in the scene already; the fit of the scene just applied is a
    // new fit (its candidate models are compared on the frames they all keep, which
    // move with the scene), within its ± of the one applied.
    let mut a = rendered(
        &scene(SceneSpec::default()),
        &data(&[]),
        None,
        Some("f a"),
        library(),
    );
    let fitted = a.lab.scene.mu;
    assert_ne!(fitted, 0.17, "the fit moved μ_k");
    assert_eq!(a.lab.settings().edits().len(), 1);
    let groovelab::lab::jobs::State::Ready(Ok(f)) = a.fit().fits() else {
        panic!("the refit")
    };
    let (refit, se) = (f.model_fit.mu, f.model_fit.mu_se);
    assert!(
        (refit - fitted).abs() < se,
        "{refit} ± {se} against {fitted}"
    );
    press(&mut a, "a");
    a.wait();
    let steps = a.lab.settings().edits().len();
    press(&mut a, "a");
    assert_eq!(a.lab.settings().edits().len(), steps, "a repeat is no step");
    assert!(
        matches!(&a.status, Status::Info(s) if s.starts_with("the fit is in the scene already: μ_k = ")),
        "{:?}",
        a.status
    );
    for _ in 0..steps {
        press(&mut a, "u");
    }
    assert_eq!(a.lab.scene.mu, 0.17, "u takes the fits back");
    // The same typed value, and the span key's choice again, are no change either.
    select(&mut a, Key::Width);
    press(&mut a, "enter 4 . 9 enter");
    assert_eq!(a.status, Status::Info("b = 4.9 cm (unchanged)".into()));
    assert!(a.lab.settings().edits().is_empty());
    press(&mut a, "right enter 4 . 9 enter");
    assert_eq!(a.lab.settings().edits().len(), 2, "a real change is a step");
}

#[test]
fn undo_reaches_a_span_set_with_t_end_and_keeps_the_command_lines_values() {
    let values = SceneSpec::default().with(Key::Width, 0.044);
    let mut a = rendered(&scene(values), &data(&[]), None, None, library());
    assert_eq!(a.lab.scene.width, 0.044);
    a.lab.set(Key::TEnd, 0.7).unwrap();
    assert!(matches!(a.lab.span_end, SpanEnd::Fixed { t_end: 0.7, .. }));
    press(&mut a, "right");
    press(&mut a, "R");
    assert_eq!(a.lab.scene.width, 0.044, "the command line's b stays");
    assert_eq!(a.lab.span_end, SpanEnd::Auto);
    assert_eq!(
        a.status,
        Status::Info(
            "reset to preset paper-b4.9 with the command line's values (u undoes it)".into()
        )
    );
}

#[test]
fn a_preset_picked_keeps_the_students_data_until_d_drops_them() {
    let d = data(&[PathBuf::from(TRACK)]);
    let mut a = rendered(&scene(SceneSpec::default()), &d, None, None, library());
    assert!(a.lab.measured().unwrap().x().is_some(), "a position track");
    // The picker opens on paper-b4.9; the one above it is paper-b4.4.
    press(&mut a, "p up enter");
    assert_eq!(a.lab.preset().name, "paper-b4.4");
    assert!(a.lab.measured().unwrap().x().is_some(), "still the track");
    assert!(
        matches!(&a.status, Status::Info(s) if s.contains("your data") && s.contains("kept")),
        "{:?}",
        a.status
    );
    press(&mut a, "D");
    let m = a.lab.measured().unwrap();
    assert!(m.x().is_none(), "the preset's own velocities");
    assert_eq!(m.t(), a.lab.preset().measured.as_ref().unwrap().t());
    assert!(
        matches!(&a.status, Status::Info(s) if s.starts_with("dropped ")),
        "{:?}",
        a.status
    );
    press(&mut a, "D");
    assert!(matches!(&a.status, Status::Info(s) if s.starts_with("no data of your own")));
}

#[test]
fn the_methods_views_work_axis_moved_to_capital_x() {
    let mut a = common::app("paper-b4.9", library());
    let axis = a.methods_state().axis();
    press(&mut a, "X");
    assert_ne!(a.methods_state().axis(), axis);
}

#[test]
fn data_without_a_scene_one_rule_for_the_app_render_and_fit() {
    let unnamed = SceneArgs::default();
    let d = data(&[PathBuf::from(TRACK)]);
    let a = rendered(&unnamed, &d, None, None, library());
    let Status::Error(message) = &a.status else {
        panic!("{:?}", a.status)
    };
    assert!(
        message == "the data name no scene: using R = 2.75 cm, b = 4.9 cm; set yours",
        "{message}"
    );
    // `render` prints what the app shows; `fit` refuses.
    let out = common::groovelab(&["render", "--data", TRACK, "--size", "160x40"]);
    let screen = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success()
            && screen.contains("name no scene")
            && screen.contains("data: docs/video/paper-b4.9-tracker.txt"),
        "{screen}"
    );
    let out = common::groovelab(&["fit", "--data", TRACK]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2));
    assert!(err.contains("names no scene"), "{err}");
    // With the scene named, nothing is asked.
    let b = rendered(&scene(SceneSpec::default()), &d, None, None, library());
    assert_eq!(b.status, Status::None);
}

#[test]
fn pinning_keeps_the_snapshots_analyses_and_an_edit_starts_them_over() {
    let (mut a, counted) = common::counted("paper-b4.9", library());
    press(&mut a, "f");
    a.wait();
    let runs = counted.get();
    assert!(runs > 0, "the Fit view's fits ran");
    // Pinning leaves the scene, its span and its data as they were: nothing again.
    press(&mut a, "P");
    a.wait();
    press(&mut a, "P");
    a.wait();
    assert_eq!(counted.get(), runs);
    // An edit is a new scene: the fits run again (and again for its undo).
    press(&mut a, "right");
    a.wait();
    let edited = counted.get();
    assert!(edited > runs, "{edited} after {runs}");
    press(&mut a, "u");
    a.wait();
    assert!(counted.get() > edited);
}

/// `simulate` on these options, in `format`.
fn simulate(scene: &SceneArgs, format: SimulateFormat) -> String {
    let args = SimulateArgs {
        format,
        sample: None,
        method: Method::Exact,
        dt: None,
        tol: None,
        epsilon: None,
        output: None,
    };
    groovelab::cli::simulate(scene, &args).unwrap()
}

#[test]
fn simulate_prints_the_apps_snapshot_of_the_same_scene_by_flags_or_keys() {
    let mut cases: Vec<SceneArgs> = groovelab::input::preset::all()
        .0
        .iter()
        .map(|p| common::scene_of(&p.name, SceneSpec::default()))
        .collect();
    let b_flag = cases.len();
    cases.push(scene(SceneSpec::default().with(Key::Width, 0.04)));
    cases.push(common::scene_of(
        "paper-b3.5",
        SceneSpec::default().with(Key::Mu, 0.1),
    ));
    cases.push(common::scene_of(
        "critical",
        SceneSpec::default().with(Key::TEnd, 0.5),
    ));
    let mut apps: Vec<(&SceneArgs, App)> = cases
        .iter()
        .map(|args| (args, rendered(args, &data(&[]), None, None, library())))
        .collect();
    // The same scene reached by keys in the app: b typed as 4 cm on paper-b4.9.
    let mut keyed = common::app("paper-b4.9", library());
    press(&mut keyed, "enter 4 enter");
    assert_eq!(keyed.lab.scene.width, 0.04);
    apps.push((&cases[b_flag], keyed));
    for (args, app) in &apps {
        let now = &app.lab;
        let json: Value = serde_json::from_str(&simulate(args, SimulateFormat::Json)).unwrap();
        let name = args.preset.as_deref().unwrap();
        // The same span (a preset's data reach past the motion: paper-b3.5's to 0.64 s),
        // hence the same final state and the same events.
        let same = |at: &Value, x: f64| {
            // The printed number read back: within an ulp or two (serde_json's parse
            // need not round-trip the last bit).
            let y = at.as_f64().unwrap();
            assert!(
                (y - x).abs() <= 4.0 * f64::EPSILON * x.abs(),
                "{name}: {y} vs {x}"
            );
        };
        same(&json["span"]["t_start"], now.span.t_start);
        same(&json["span"]["t_end"], now.solution.t_end);
        let last = now.solution.at(now.solution.t_end);
        same(&json["final"]["left"]["x"], last.left.x);
        same(&json["final"]["right"]["v"], last.right.v);
        let events = json["events"].as_array().unwrap().len();
        assert_eq!(events, now.solution.visible_events().count(), "{name}");
        // The table's story is the snapshot's: its verdict against the same rest band.
        let table = simulate(args, SimulateFormat::Table);
        let verdict = table.lines().find_map(|l| l.strip_prefix("verdict  "));
        assert_eq!(
            verdict.map(str::to_string),
            now.rest_band.map(|_| now.story.verdict.text("±")),
            "{name}"
        );
    }
}

/// `compare --methods exact --format json` on `scene` and `data`, in-process (the
/// exact engine alone: a few solves, cheap).
fn compare_exact(scene: &SceneArgs, data: &DataArgs) -> Value {
    let mut args: Vec<String> = [
        "groovelab",
        "compare",
        "--methods",
        "exact",
        "--format",
        "json",
    ]
    .map(String::from)
    .to_vec();
    if let Some(p) = &scene.preset {
        args.extend(["--preset".into(), p.clone()]);
    }
    for (key, value) in scene.values.given() {
        // SI values with no unit are read in SI.
        args.extend([format!("--{}", key.param().flag), format!("{value}")]);
    }
    for file in &data.data {
        args.extend(["--data".into(), file.display().to_string()]);
    }
    let out = groovelab::cli::entry::main_with(&args.iter().map(Into::into).collect::<Vec<_>>());
    assert_eq!(out.code, 0, "{args:?}: {}", out.stderr);
    serde_json::from_str(&out.stdout).unwrap()
}

#[test]
fn compare_compares_over_the_span_the_methods_view_does() {
    // Every built-in preset, a scene by flags alone (the default preset under them),
    // and a velocity file whose last point (0.64 s) lies past the critical scene's
    // motion (it ends at about 0.33 s).
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut cases: Vec<(SceneArgs, DataArgs)> = Preset::built_in()
        .iter()
        .map(|p| (common::scene_of(&p.name, SceneSpec::default()), data(&[])))
        .collect();
    cases.push((
        SceneArgs {
            preset: None,
            values: SceneSpec::default().with(Key::Width, 0.035),
        },
        data(&[]),
    ));
    cases.push((
        common::scene_of("critical", SceneSpec::default()),
        data(&[root.join("data/gs-b3.5cm.csv")]),
    ));
    let mut past_the_motion = 0;
    for (scene, files) in &cases {
        // The Methods view's rows are computed over the app's snapshot's span.
        let app = rendered(scene, files, None, None, library());
        let now = &app.lab;
        let json = compare_exact(scene, files);
        let name = format!("{:?} {:?}", scene.preset, files.data);
        let read = |v: &Value| v.as_f64().unwrap();
        let (t0, t1) = (read(&json["span"]["t_start"]), read(&json["span"]["t_end"]));
        // The printed number read back: within an ulp or two.
        assert!(
            (t0 - now.span.t_start).abs() <= 4.0 * f64::EPSILON,
            "{name}: {t0}"
        );
        let end = now.span.t_end.unwrap();
        assert!(
            (t1 - end).abs() <= 4.0 * f64::EPSILON * end,
            "{name}: {t1} vs {end}"
        );
        // The exact row is the reference itself: no error at all.
        let exact = &json["rows"][0];
        assert_eq!(exact["method"], "exact", "{name}");
        for err in ["err_v", "err_u", "err_final"] {
            assert_eq!(read(&exact[err]), 0.0, "{name}: {err}");
        }
        let auto = groovelab::physics::scene::Span {
            t_end: None,
            ..now.span
        };
        let motion = groovelab::physics::engine::solve(&now.scene, &auto).t_end;
        if end > motion + 1e-9 {
            past_the_motion += 1;
        }
    }
    // Measured series that reach past the motion are what this is about: paper-b3.5's
    // own and the file on the critical scene at least.
    assert!(past_the_motion >= 2, "{past_the_motion}");
}

#[test]
fn u_after_picking_a_preset_brings_back_the_preset_its_edits_and_data() {
    // The command line's b and two edits on paper-b4.9 with its own data.
    let flags = SceneSpec::default().with(Key::Width, 0.046);
    let mut a = rendered(&scene(flags), &data(&[]), None, None, library());
    let fresh = a.lab.scene;
    press(&mut a, "left");
    press(&mut a, "down down down enter 0 . 3 enter");
    let edited = (a.lab.scene, a.lab.span_end);
    let b49_data = a.lab.measured().unwrap().t().to_vec();
    // The picker opens on paper-b4.9; the one above it is paper-b4.4.
    press(&mut a, "p up enter");
    let b44 = groovelab::input::preset::load("paper-b4.4").unwrap();
    assert_eq!(a.lab.preset().name, "paper-b4.4");
    assert_eq!(a.lab.value(Key::Width), 0.044, "the preset alone: no flag");
    assert_eq!(
        a.lab.measured().unwrap().t(),
        b44.measured.as_ref().unwrap().t()
    );
    // An edit on the picked preset, and a reset to it, are undone first.
    press(&mut a, "right R");
    assert_eq!(
        a.status,
        Status::Info("reset to preset paper-b4.4 (u undoes it)".into()),
        "the command line's values are not in force after a pick"
    );
    press(&mut a, "u u");
    assert_eq!(a.lab.preset().name, "paper-b4.4");
    assert_eq!(a.lab.value(Key::Width), 0.044);
    // Then the pick: the preset before, its edits and its data.
    press(&mut a, "u");
    assert!(
        matches!(&a.status, Status::Info(s) if s.starts_with("undone: preset paper-b4.4: back to paper-b4.9")),
        "{:?}",
        a.status
    );
    assert_eq!(a.lab.preset().name, "paper-b4.9");
    assert_eq!((a.lab.scene, a.lab.span_end), edited);
    assert_eq!(a.lab.measured().unwrap().t(), b49_data);
    // The older steps survive: μ_k, then b, then nothing.
    press(&mut a, "u u");
    assert_eq!(a.lab.scene, fresh);
    assert_eq!(a.lab.value(Key::Width), 0.046, "the command line's b again");
    press(&mut a, "u");
    assert_eq!(a.status, Status::Info("nothing to undo".into()));
}

#[test]
fn u_after_picking_a_preset_keeps_the_students_data() {
    let d = data(&[PathBuf::from(TRACK)]);
    let mut a = rendered(&scene(SceneSpec::default()), &d, None, None, library());
    let before = a.lab.scene;
    press(&mut a, "p up enter u");
    assert_eq!(a.lab.preset().name, "paper-b4.9");
    assert_eq!(a.lab.scene, before);
    assert!(a.lab.measured().unwrap().x().is_some(), "still the track");
    assert_eq!(a.lab.own_data().unwrap().name, TRACK);
}

/// A fit applied (`a` in the Fit view) keeps the values the data measure as the
/// data's: v0 stays `d`, and the next fit still frees it, so it gives the same
/// models and μ_k's ± still carries v0's. (It was marked edited: the next fit held
/// v0 at the value applied, listed other models and headlined μ_k alone with a
/// smaller ±; a new user's report.) A value typed over it is the user's again.
#[test]
fn a_fit_applied_keeps_the_datas_values_the_datas() {
    use groovelab::lab::Origin;
    use groovelab::lab::jobs::State;
    let d = data(&[PathBuf::from(TRACK)]);
    let mut a = rendered(&scene(SceneSpec::default()), &d, None, None, library());
    assert_eq!(a.lab.settings().origin(Key::V0), Origin::Data);
    press(&mut a, "f");
    a.wait();
    let State::Ready(Ok(before)) = a.fit().fits() else {
        panic!("fit ready");
    };
    let (models, head, mu_se) = (
        before.models.len(),
        before.model_fit.model.clone(),
        before.model_fit.mu_se,
    );
    assert!(before.model_fit.v0_se.is_some(), "v0 fitted");
    press(&mut a, "a");
    assert_eq!(a.lab.settings().origin(Key::V0), Origin::Data);
    assert_eq!(a.lab.settings().origin(Key::Mu), Origin::Edited);
    a.wait();
    let State::Ready(Ok(after)) = a.fit().fits() else {
        panic!("fit ready");
    };
    assert_eq!(after.models.len(), models);
    assert_eq!(after.model_fit.model, head);
    assert!(
        (after.model_fit.mu_se - mu_se).abs() < 0.05 * mu_se,
        "μ_k ± {} before, {} after",
        mu_se,
        after.model_fit.mu_se
    );
    // v0 typed by hand: the user's.
    a.lab.set(Key::V0, 0.8).unwrap();
    assert_eq!(a.lab.settings().origin(Key::V0), Origin::Edited);
}
