//! Layers, of the source and of the settings. The source's layers are folders, each
//! using only those above it (physics → settings → methods → study → lab → the
//! edges): no source file of a layer names a later one. The settings' layers (preset
//! ← command line ← the app's edits) settle into one snapshot (that the same scene
//! reached by flags or by keys draws the same screen is `lab_data`'s test): `u` takes
//! back the last edit, `R` all of them; a preset picked keeps the student's data; data
//! without a scene are one rule for the app, `render` and `fit`; `simulate` prints the
//! snapshot the app shows for the same options.

use std::path::{Path, PathBuf};

use groovelab::cli::{DataArgs, Format, SceneArgs, SimulateArgs};
use groovelab::lab::SpanEnd;
use groovelab::methods::Method;
use groovelab::settings::params::{Key, SceneSpec};
use groovelab::study::preset::Preset;
use groovelab::tui::app::Status;
use serde_json::Value;

use crate::common::{self, press, rendered};

/// The inner layers in order; everything else (`input`, `output`, `signals`, `cli`,
/// `tui`) is an edge and may use them all.
const LAYERS: [&str; 5] = ["physics", "settings", "methods", "study", "lab"];
const EDGES: [&str; 5] = ["input", "output", "signals", "cli", "tui"];

fn sources(dir: &Path, out: &mut Vec<std::path::PathBuf>) {
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            sources(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

#[test]
fn no_layer_uses_a_later_one() {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut bad = Vec::new();
    for (rank, layer) in LAYERS.iter().enumerate() {
        let mut files = Vec::new();
        sources(&src.join(layer), &mut files);
        assert!(!files.is_empty(), "{layer}");
        let later = LAYERS[rank + 1..].iter().chain(&EDGES);
        let later: Vec<String> = later.map(|l| format!("crate::{l}::")).collect();
        for file in files {
            let text = std::fs::read_to_string(&file).unwrap();
            for (n, line) in text.lines().enumerate() {
                let code = line.split("//").next().unwrap_or("");
                if let Some(l) = later.iter().find(|l| code.contains(l.as_str())) {
                    bad.push(format!("{}:{}: {l}", file.display(), n + 1));
                }
            }
        }
    }
    assert!(bad.is_empty(), "upward imports:\n{}", bad.join("\n"));
}

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
        matches!(&a.status, Status::Info(s) if s.starts_with("undone: mu_k = ")),
        "{:?}",
        a.status
    );
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
    assert!(a.lab.measured().unwrap().x.is_some(), "a position track");
    // The picker opens on paper-b4.9; the one above it is paper-b4.4.
    press(&mut a, "p up enter");
    assert_eq!(a.lab.preset().name, "paper-b4.4");
    assert!(a.lab.measured().unwrap().x.is_some(), "still the track");
    assert!(
        matches!(&a.status, Status::Info(s) if s.contains("your data") && s.contains("kept")),
        "{:?}",
        a.status
    );
    press(&mut a, "D");
    let m = a.lab.measured().unwrap();
    assert!(m.x.is_none(), "the preset's own velocities");
    assert_eq!(m.t, a.lab.preset().measured.as_ref().unwrap().t);
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
    let axis = a.work_axis;
    press(&mut a, "X");
    assert_ne!(a.work_axis, axis);
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
        message
            == "paper-b4.9-tracker.txt names no scene: the model uses paper-b4.9's R = 2.75 cm, b = 4.9 cm; set R and b to yours",
        "{message}"
    );
    // `render` prints what the app shows; `fit` refuses.
    let out = common::groovelab(&["render", "--data", TRACK, "--size", "160x40"]);
    let screen = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success() && screen.contains("names no scene"),
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
    let mut a = common::app("paper-b4.9", library());
    press(&mut a, "f");
    a.lab.wait();
    let runs = a.lab.runs();
    assert!(runs > 0, "the Fit view's fits ran");
    // Pinning leaves the scene, its span and its data as they were: nothing again.
    press(&mut a, "P");
    a.lab.wait();
    press(&mut a, "P");
    a.lab.wait();
    assert_eq!(a.lab.runs(), runs);
    // An edit is a new scene: the fits run again (and again for its undo).
    press(&mut a, "right");
    a.lab.wait();
    let edited = a.lab.runs();
    assert!(edited > runs, "{edited} after {runs}");
    press(&mut a, "u");
    a.lab.wait();
    assert!(a.lab.runs() > edited);
}

/// `simulate` on these options, in `format`.
fn simulate(scene: &SceneArgs, format: Format) -> String {
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
fn simulate_prints_the_apps_snapshot_of_the_same_options() {
    let mut cases: Vec<SceneArgs> = Preset::all()
        .0
        .iter()
        .map(|p| common::scene_of(&p.name, SceneSpec::default()))
        .collect();
    cases.push(scene(SceneSpec::default().with(Key::Width, 0.04)));
    cases.push(common::scene_of(
        "paper-b3.5",
        SceneSpec::default().with(Key::Mu, 0.1),
    ));
    cases.push(common::scene_of(
        "critical",
        SceneSpec::default().with(Key::TEnd, 0.5),
    ));
    for args in &cases {
        let app = rendered(args, &data(&[]), None, None, library());
        let now = &app.lab;
        let json: Value = serde_json::from_str(&simulate(args, Format::Json)).unwrap();
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
        let table = simulate(args, Format::Table);
        let verdict = table.lines().find_map(|l| l.strip_prefix("verdict  "));
        assert_eq!(
            verdict.map(str::to_string),
            now.rest_band.map(|_| now.story.verdict.text("±")),
            "{name}"
        );
    }
}
