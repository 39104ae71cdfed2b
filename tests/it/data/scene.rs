//! Issue 19, "Data and scene belong together": measured data are never shown against a
//! groove they were not measured in without saying so, the same for the app, `render`,
//! `simulate` and `fit`, whether the scene was reached by options or by keys.

use std::path::PathBuf;

use groovelab::cli::{DataArgs, SceneArgs};
use groovelab::settings::params::Key;
use groovelab::settings::spec::SceneSpec;
use groovelab::tui::app::{Library, Status};

use crate::common::{self, press, rendered, scene_of, text};

/// The student's scene of the new-user trial: R = 1.5 cm, b = 2.1 cm, m = 110 g,
/// v0 = 0.5 m/s, with no preset named.
fn student_scene() -> SceneArgs {
    SceneArgs {
        preset: None,
        values: SceneSpec::default()
            .with(Key::Radius, 0.015)
            .with(Key::Width, 0.021)
            .with(Key::Mass, 0.110)
            .with(Key::V0, 0.5),
    }
}

fn library() -> Library {
    common::no_user_presets("datascene")
}

/// A velocity file of the student's own, made here: a ball rolling at 0.5 m/s into
/// the impact at t = 0 and sliding back to rest, with `header` lines before the
/// columns. Its path.
fn velocity_file(name: &str, header: &str) -> String {
    let dir = crate::common::scratch_root("data").join("velocity-files");
    std::fs::create_dir_all(&dir).unwrap();
    let mut text = format!("{header}t,v_cm,v_t\n");
    for i in 0..=40 {
        let t = -0.2 + 0.02 * f64::from(i);
        let (v_cm, v_t) = if t < 0.0 {
            (0.5, 0.5)
        } else {
            ((-0.5 + 2.3 * t).min(0.0), (0.5 - 3.0 * t).max(-0.06))
        };
        text += &format!("{t:.2},{v_cm:.4},{v_t:.4}\n");
    }
    let path = dir.join(name);
    std::fs::write(&path, text).unwrap();
    path.display().to_string()
}

fn data(files: &[&str]) -> DataArgs {
    DataArgs {
        data: files.iter().map(PathBuf::from).collect(),
        ..DataArgs::default()
    }
}

/// After `D` in the student's own groove the preset's measured points do not come
/// back against it (they were measured at b = 4.9 cm): no data, said on the status
/// line, and `u` brings the student's back. In the preset's groove they do come back.
#[test]
fn after_d_the_presets_data_come_back_only_in_its_groove() {
    let file = velocity_file("own.csv", "");
    let mut a = rendered(&student_scene(), &data(&[&file]), None, None, library());
    assert!(a.lab.measured().is_some());
    press(&mut a, "D");
    assert!(
        a.lab.measured().is_none(),
        "paper-b4.9's points are not shown"
    );
    assert!(a.lab.data_rms.is_none(), "no RMS against data of no groove");
    let Status::Info(said) = &a.status else {
        panic!("{:?}", a.status)
    };
    assert!(
        said.contains("no data shown")
            && said.contains("paper-b4.9's were measured at R = 2.75 cm, b = 4.9 cm")
            && said.contains("u undoes"),
        "{said}"
    );
    let screen = text(&a, (120, 40), false);
    assert!(!screen.contains("RMS"), "{screen}");
    assert!(!screen.contains("measured v_cm"), "{screen}");
    press(&mut a, "u");
    assert_eq!(
        a.lab.own_data().unwrap().name,
        file,
        "undo brings them back"
    );
    assert!(a.lab.measured().is_some());
    // In the preset's own groove the preset's data are the scene's: they come back.
    let mut b = rendered(
        &scene_of("paper-b4.9", SceneSpec::default()),
        &data(&[&file]),
        None,
        Some("D"),
        library(),
    );
    assert!(b.lab.measured().is_some());
    assert!(matches!(&b.status, Status::Info(s) if s.contains("measured in this groove")));
    assert!(b.lab.other_groove.is_none());
    // … and leave once the groove is another, to come back with it.
    b.lab.set(Key::Width, 0.03).unwrap();
    assert!(b.lab.measured().is_none());
    press(&mut b, "u");
    assert!(b.lab.measured().is_some());
}

/// The same after `D` when the scene came from the file's own `# scene` lines (the
/// app's export read back), through the whole command line.
#[test]
fn after_d_a_file_scene_shows_no_presets_data() {
    let file = velocity_file(
        "with-scene.csv",
        "# scene radius = 1.5 cm\n# scene width = 2.1 cm\n# scene mass = 110 g\n",
    );
    // Wide enough that the status line, naming the file by its path in the checkout,
    // is not wrapped.
    let screen =
        common::run_in_process(&["render", "--data", &file, "--keys", "D", "--size", "160x40"])
            .unwrap();
    assert!(screen.contains("R            1.50 cm"), "{screen}");
    assert!(!screen.contains("RMS"), "{screen}");
    assert!(screen.contains("no data shown"), "{screen}");
}

/// A preset's data kept while a flag changed the groove: `simulate` describes the
/// scene simulated (not the preset's headline of b = 4.9 cm) and says where the data
/// were measured; the app says the same for the same scene by flags or by keys.
#[test]
fn a_presets_data_in_another_groove_are_said_to_be_so() {
    let out =
        common::run_in_process(&["simulate", "--preset", "paper-b4.9", "--width", "2cm"]).unwrap();
    let head: Vec<&str> = out.lines().take(8).collect();
    let head = head.join("\n");
    assert!(!head.contains("wide groove"), "{head}");
    assert!(
        head.contains("preset   paper-b4.9 changed by the options: b = 2 cm (was 4.9 cm)"),
        "{head}"
    );
    // Each value as the scene line writes it: μ_k, not the option's mu_k.
    let mu = common::run_in_process(&["simulate", "--mu", "0"]).unwrap();
    assert!(
        mu.starts_with("preset   paper-b4.9 changed by the options: μ_k = 0 (was 0.17)\n"),
        "{mu}"
    );
    let note = "paper-b4.9's data were measured at b = 4.9 cm; the model uses b = 2 cm";
    assert!(head.contains(&format!("data     {note}")), "{head}");
    let out =
        common::run_in_process(&["simulate", "--preset", "paper-b4.9", "--radius", "10m"]).unwrap();
    assert!(
        out.contains("measured at R = 2.75 cm; the model uses R = 1000 cm"),
        "{out}"
    );
    // The preset's own scene keeps its headline and has no note.
    let own = common::run_in_process(&["simulate", "--preset", "paper-b4.9"]).unwrap();
    assert!(own.starts_with("preset   paper-b4.9: Paper experiment, b = 4.9 cm"));
    assert!(!own.contains("were measured at"), "{own}");
    // (`fit` says it too, from the same snapshot: `a_files_stated_groove_…` below.)
    // The app: by flags and by keys the same note, in the Why panel.
    let by_flags = rendered(
        &scene_of("paper-b4.9", SceneSpec::default().with(Key::Width, 0.02)),
        &DataArgs::default(),
        None,
        None,
        library(),
    );
    let by_keys = rendered(
        &scene_of("paper-b4.9", SceneSpec::default()),
        &DataArgs::default(),
        None,
        Some("enter 2 enter"),
        library(),
    );
    for a in [&by_flags, &by_keys] {
        assert_eq!(a.lab.scene.width, 0.02);
        assert_eq!(a.lab.other_groove.as_ref().unwrap().describe(), note);
        let why: String = text(a, (200, 60), false)
            .lines()
            .map(|l| l.rsplit('│').nth(1).unwrap_or("").trim().to_string() + " ")
            .collect();
        assert!(why.contains(note), "{why}");
    }
}

/// A file that states its groove (`# scene` lines) keeps it: the model's groove set
/// over it, by an option or a key, is said to be another; a file without them is in
/// the groove the user gives.
#[test]
fn a_files_stated_groove_is_kept_and_compared() {
    let stated = velocity_file(
        "stated.csv",
        "# scene radius = 1.5 cm\n# scene width = 2.1 cm\n",
    );
    let out = common::run_in_process(&["fit", "--data", &stated, "--width", "2.2cm"]).unwrap();
    assert!(
        out.contains("data: the data were measured at b = 2.1 cm; the model uses b = 2.2 cm"),
        "{out}"
    );
    let plain = velocity_file("plain.csv", "");
    let mut a = rendered(&student_scene(), &data(&[&plain]), None, None, library());
    a.lab.set(Key::Width, 0.022).unwrap();
    assert!(
        a.lab.other_groove.is_none(),
        "the user's own claim moves with them"
    );
}

/// A tracked rim mark must stay on the ball: an R edited in the app below the mark's
/// distance from the centre is refused (it would turn the mark's spin into a v_t wrong
/// by their ratio), naming the least R allowed; an R above it is taken.
#[test]
fn an_r_edited_below_the_rim_marks_distance_is_refused() {
    use groovelab::study::video::{self, TrackFormat, Video};
    let truth = crate::common::paper_scene();
    let shot = Video {
        fps: 120.0,
        noise: 3e-4,
        seed: 7,
        from: -0.2,
        to: 0.6,
        mark: true,
        flip_x: false,
        flip_y: false,
        origin: (0.3, 0.03),
        t_impact: 0.2,
    };
    let dir = crate::common::scratch_dir("data", "marked-track");
    let path = dir.join("marked-track.txt");
    let track = video::track(&truth, &shot);
    std::fs::write(
        &path,
        video::write(&track.unwrap(), TrackFormat::TrackerMulti),
    )
    .unwrap();
    let file = path.display().to_string();
    let mut a = rendered(
        &scene_of("paper-b4.9", SceneSpec::default()),
        &data(&[&file]),
        None,
        None,
        library(),
    );
    let least = a
        .lab
        .series()
        .unwrap()
        .found()
        .unwrap()
        .least_radius()
        .unwrap();
    // The mark is drawn on the rim, R = 2.75 cm; the noise lets R go a little lower.
    assert!(least < 0.0275 && least > 0.026, "{least}");
    common::select(&mut a, Key::Radius);
    // (b = 4.9 cm holds R above 2.45 cm.)
    press(&mut a, "enter 2 . 6 enter");
    assert_eq!(a.lab.scene.radius, 0.0275, "refused");
    let Status::Error(said) = &a.status else {
        panic!("{:?}", a.status)
    };
    assert!(
        said.contains("R = 2.6 cm") && said.contains("rim mark"),
        "{said}"
    );
    assert!(
        said.contains(&format!("R ≥ {:.3} cm", least * 100.0)),
        "{said}"
    );
    // Without the data the same R is a valid scene, and with them a larger one too.
    a.lab.set(Key::Radius, 0.03).unwrap();
    press(&mut a, "D");
    a.lab.set(Key::Radius, 0.026).unwrap();
}

/// The real source is named: the status line says `scene of FILE` when the file's
/// `# scene` lines give the scene (not the default preset under them), the export
/// prompt suggests the data file's name for the student's own scene, and `fit` lists
/// the options as typed (`--mass`, not `--mass-left --mass-right`) over the default
/// preset, named as such.
#[test]
fn the_source_of_the_scene_is_named_as_it_came() {
    let file = velocity_file(
        "lab-run.csv",
        "# scene radius = 1.5 cm\n# scene width = 2.1 cm\n# scene mass = 110 g\n",
    );
    let screen =
        common::run_in_process(&["render", "--data", &file, "--keys", "w", "--size", "120x40"])
            .unwrap();
    let rows: Vec<&str> = screen.lines().collect();
    let status = rows[rows.len() - 2..].join("\n");
    assert!(status.contains("scene of lab-run.csv"), "{status}");
    assert!(!status.contains("preset paper-b4.9"), "{status}");
    assert!(
        screen.contains("lab-run-run.csv"),
        "the export's name: {screen}"
    );
    // The preset's own scene keeps its name.
    let a = rendered(
        &scene_of("paper-b4.9", SceneSpec::default()),
        &data(&[&file]),
        None,
        None,
        library(),
    );
    assert_eq!(a.lab.settings().source(), "preset paper-b4.9");
    assert_eq!(a.lab.scene_name(), "paper-b4.9");
    let plain = velocity_file("typed.csv", "");
    let fit = common::run_in_process(&[
        "fit", "--data", &plain, "--radius", "1.5cm", "--width", "2.1cm", "--mass", "110g", "--v0",
        "0.5",
    ])
    .unwrap();
    assert!(
        fit.starts_with(
            "scene (default preset paper-b4.9 with --radius --width --mass --v0): R = 1.5 cm"
        ),
        "{fit}"
    );
}

/// `data` says what a file's `# scene` lines give, as `fit` takes them: the header's
/// values named, the masses no longer "assumed" when it states them; a file without
/// them keeps the preset-or-options line.
#[test]
fn data_names_what_a_files_header_gives() {
    let stated = velocity_file(
        "data-stated.csv",
        "# scene radius = 1.5 cm\n# scene width = 2.1 cm\n# scene mass = 110 g\n",
    );
    let out = common::run_in_process(&["data", &stated]).unwrap();
    assert!(
        out.contains("its header gives R = 1.5 cm, b = 2.1 cm, m left = 110 g, m right = 110 g"),
        "{out}"
    );
    assert!(
        out.contains("μ_k, e from the preset or the options"),
        "{out}"
    );
    assert!(!out.contains("m assumed"), "{out}");
    let json: serde_json::Value = serde_json::from_str(
        &common::run_in_process(&["data", &stated, "--format", "json"]).unwrap(),
    )
    .unwrap();
    let width = json[0]["header_values"]["width"].as_f64().unwrap();
    assert!((width - 0.021).abs() < 1e-15, "{width}");
    assert_eq!(json[0]["assumed"], serde_json::json!([]));
    let plain = velocity_file("data-plain.csv", "");
    let out = common::run_in_process(&["data", &plain]).unwrap();
    assert!(
        out.contains("R, b, μ_k, e from the preset or the options; m assumed"),
        "{out}"
    );
    let json: serde_json::Value = serde_json::from_str(
        &common::run_in_process(&["data", &plain, "--format", "json"]).unwrap(),
    )
    .unwrap();
    assert!(json[0].get("header_values").is_none());
    assert_eq!(
        json[0]["assumed"],
        serde_json::json!(["mass_left", "mass_right"])
    );
}

/// A header that gives both balls' v0 leaves v0 out of "from the preset", also where
/// the data have no approach of their own to give it.
#[test]
fn data_counts_a_headers_v0_as_given() {
    let dir = common::scratch_dir("datascene", "header_v0");
    let file = dir.join("no-impact.csv");
    std::fs::write(
        &file,
        "# scene v0 = 0.5 m/s\nt,v_cm,v_t\n0,0.5,0.5\n0.01,0.49,0.48\n0.02,0.48,0.46\n0.03,0.47,0.44\n",
    )
    .unwrap();
    let out = common::run_in_process(&["data", file.to_str().unwrap()]).unwrap();
    assert!(
        out.contains(
            "its header gives v0 left = 0.5 m/s, v0 right = 0.5 m/s; R, b, μ_k, e from the preset"
        ),
        "{out}"
    );
}
