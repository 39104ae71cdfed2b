//! Fitting against the paper's data and against synthetic data with known μ_k.
//! The fit's tests by theme (`paper`, `files_and_models`, `coverage`), with their shared
//! generators here, then verdicts, nested models and a wrong scene.

mod coverage;
mod files_and_models;
mod nested;
mod paper;
mod profiled;
mod slips;
mod truth;
mod verdicts;
mod wrong_scene;

use groovelab::input::data;
use groovelab::physics::derived::Regime;
use groovelab::physics::engine::solve;
use groovelab::physics::scene::{Scene, Span};
use groovelab::study::fit::{self, Free, PAPER_TABLE};
use groovelab::study::measured::{Measured, Track};

use crate::common::{groovelab, json};

fn paper(width: &str) -> (Scene, Measured) {
    let p = groovelab::input::preset::load(&format!("paper-b{width}")).unwrap();
    let (scene, _) = p.spec.resolve().unwrap();
    (scene, p.measured.unwrap())
}

/// xorshift64* and Box–Muller: seeded noise without a dependency.
struct Noise(u64);

impl Noise {
    fn uniform(&mut self) -> f64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        ((self.0.wrapping_mul(0x2545F4914F6CDD1D) >> 11) as f64 + 0.5) / (1u64 << 53) as f64
    }

    fn gauss(&mut self) -> f64 {
        let (u, v) = (self.uniform(), self.uniform());
        (-2.0 * u.ln()).sqrt() * (std::f64::consts::TAU * v).cos()
    }
}

fn csv(name: &str, text: &str) -> String {
    let dir = crate::common::scratch_root("fit").join("tables");
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(name);
    std::fs::write(&path, text).unwrap();
    path.display().to_string()
}

/// A velocity file of `scene`'s left ball as a student's spreadsheet holds it: frames
/// at `fps` from t ≈ −0.29 s to 0.68 s with the impact at `phase` (0 … 1) of a frame
/// after the frame before it, both speeds with Gaussian noise `sigma`, times on the
/// file's own clock (the reader must find the impact).
fn velocity_file(scene: &Scene, fps: f64, sigma: f64, phase: f64, seed: u64) -> String {
    let sol = solve(
        scene,
        &Span {
            t_start: -0.4,
            t_end: None,
        },
    );
    let mut noise = groovelab::study::video::Noise::new(seed);
    let mut out = String::from("t (s),v_cm (m/s),v_t (m/s)\n");
    let first = -(0.29 * fps).round() - phase;
    for k in 0..=((0.97 * fps) as usize) {
        let t = (first + k as f64) / fps;
        let s = sol.at(t);
        out += &format!(
            "{:.6},{:.5},{:.5}\n",
            t + 1.0,
            s.left.v + sigma * noise.gauss(),
            s.left.u + sigma * noise.gauss()
        );
    }
    out
}

/// The program's own noise-free run of a small groove (μ_k = 0.17, e = 1, c_rr = 0) as
/// a velocity file `name`, the impact between two frames, and the scene options for
/// `fit`.
fn noise_free_run(name: &str) -> (String, [&'static str; 8]) {
    let run = groovelab(&[
        "simulate",
        "--radius",
        "1.5cm",
        "--width",
        "2.1cm",
        "--mass",
        "110g",
        "--mu",
        "0.17",
        "--v0",
        "0.5",
        "--t-start",
        "-0.2043s",
        "--t-end",
        "0.6s",
        "--sample",
        "0.008333",
        "--format",
        "csv",
    ]);
    let path = csv(name, &String::from_utf8(run.stdout).unwrap());
    let scene = [
        "--radius", "1.5cm", "--width", "2.1cm", "--mass", "110g", "--v0", "0.5",
    ];
    (path, scene)
}

/// The models of `fit`'s table (with their BICs) and of the Fit view, in the order
/// each lists them (names without blanks).
type Listed = (Vec<(String, f64)>, Vec<String>);

/// The verdict of each model fit, as the `fit` table's and the Fit view's "verdict"
/// rows print it, for the flat-table scene on the example track's
/// centre (the position fit runs μ_k to the edge of its range).
/// Also how the two list the models ([`Listed`]).
fn flat_table() -> (
    (Vec<String>, Vec<String>, groovelab::study::fit::Agreement),
    Listed,
) {
    use crate::common::{no_user_presets, rendered, scene_of, text};
    use groovelab::cli::DataArgs;
    use groovelab::lab::jobs::State;
    use groovelab::settings::spec::SceneSpec;
    let out = groovelab(&[
        "fit",
        "--preset",
        "flat-table",
        "--data",
        "docs/video/ball.txt",
    ]);
    let table = String::from_utf8_lossy(&out.stdout).to_string();
    // The row's two cells (right-aligned columns apart by two blanks at least), in
    // the table or in a panel of the screen.
    let words = |text: &str, row: &str| -> Vec<String> {
        let line = text
            .lines()
            .flat_map(|l| l.split('│'))
            .map(str::trim)
            .find(|l| l.starts_with(row))
            .unwrap_or_else(|| panic!("no {row} row in {text}"));
        line[row.len()..]
            .split("  ")
            .map(str::trim)
            .filter(|w| !w.is_empty())
            .map(str::to_string)
            .collect()
    };
    let cli = words(&table, "verdict");
    let data = DataArgs {
        data: vec!["docs/video/ball.txt".into()],
        ..DataArgs::default()
    };
    let app = rendered(
        &scene_of("flat-table", SceneSpec::default()),
        &data,
        None,
        Some("f"),
        no_user_presets("fit-verdict"),
    );
    let screen = text(&app, (120, 40), false);
    let view = words(&screen, "verdict");
    let State::Ready(Ok(f)) = app.fit().fits() else {
        panic!("no fits")
    };
    let p = &f.model_fit;
    // The table's model rows: a mark, the name (34 columns), RMS, AIC, BIC.
    let table_models: Vec<(String, f64)> = table
        .lines()
        .skip_while(|l| !l.contains("values (± 2σ)"))
        .skip(1)
        .take_while(|l| l.starts_with("* ") || l.starts_with("  μ_k"))
        .filter_map(|l| {
            let chars: Vec<char> = l.chars().collect();
            let name: String = chars.get(2..36)?.iter().filter(|c| **c != ' ').collect();
            let bic = chars.get(59..69)?.iter().collect::<String>();
            Some((name, bic.trim().parse().ok()?))
        })
        .collect();
    let view_models: Vec<String> = screen
        .lines()
        .filter_map(|l| l.rsplit("││").next())
        .filter_map(|l| {
            let words: Vec<&str> = l
                .trim_start_matches(['*', '?', ' '])
                .split_whitespace()
                .collect();
            (words.get(1) == Some(&"BIC")).then(|| words[0].to_string())
        })
        .collect();
    ((cli, view, p.agreement()), (table_models, view_models))
}

/// Issue 19: `fit` and the Fit view list the candidate models in one order, by BIC,
/// lowest first (the view once put them by BIC, the table by size).
fn models_in_one_order((table, view): Listed) {
    assert!(table.len() >= 4, "{table:?}");
    assert!(
        table.windows(2).all(|w| w[0].1 <= w[1].1),
        "not by BIC: {table:?}"
    );
    let names: Vec<String> = table.iter().map(|(n, _)| n.clone()).collect();
    // The view lists as many as its room allows, in the same order.
    assert!(
        !view.is_empty() && names.starts_with(&view),
        "{names:?} / {view:?}"
    );
}

/// A synthetic video of `scene` at `fps` whose tracked coordinates carry noise of
/// standard deviation `sd` (m) that drifts over `tau` seconds (a first-order
/// autoregression, as a tracker's error does), read as a student's track is.
fn drifting_video(scene: &Scene, fps: f64, seed: u64, sd: f64, tau: f64) -> Measured {
    use groovelab::study::measured::{self, Derive, RawSeries};
    use groovelab::study::video::{self, Noise, Video};
    let v = Video {
        fps,
        noise: 0.0,
        seed,
        from: -0.1,
        to: 0.5,
        ..Video::default()
    };
    let mut track = video::track(scene, &v).unwrap().into_parts();
    let mut noise = Noise::new(seed);
    let phi = (-1.0 / (fps * tau)).exp();
    let mut drift = |values: &mut Vec<f64>| {
        let mut e = sd * noise.gauss();
        for x in values.iter_mut() {
            *x += e;
            e = phi * e + sd * (1.0 - phi * phi).sqrt() * noise.gauss();
        }
    };
    drift(&mut track.x);
    drift(&mut track.y);
    if let Some((mx, my)) = track.mark.as_mut() {
        drift(mx);
        drift(my);
    }
    let series = measured::prepare(
        RawSeries::Positions(Track::new(track).unwrap()),
        &Derive::default(),
    )
    .unwrap();
    (*measured::for_scene(&series, scene).measured).clone()
}

/// The ± that `text` prints as zero ("± 0.0000", "±0.00", "+- 0.000"): a number
/// after a ± made of zeros alone.
fn zero_uncertainties(text: &str) -> Vec<String> {
    text.lines()
        .flat_map(|line| {
            line.split('±')
                .skip(1)
                .chain(line.split("+-").skip(1))
                .filter(|after| {
                    let number: String = after
                        .trim_start()
                        .chars()
                        .take_while(|c| c.is_ascii_digit() || *c == '.')
                        .collect();
                    !number.is_empty() && number.parse::<f64>() == Ok(0.0)
                })
                .map(|_| line.to_string())
                .collect::<Vec<_>>()
        })
        .collect()
}

/// One synthetic measurement of the coverage test: a track (centre only, or with a
/// rim mark) or a velocity series of `truth`, at `fps`, with seeded noise.
fn synthetic(
    truth: &Scene,
    fps: f64,
    kind: usize,
    seed: u64,
) -> groovelab::study::measured::Series {
    use groovelab::study::video::{self, TrackFormat, Video};
    let text = match kind {
        0 | 1 => {
            let v = Video {
                fps,
                seed,
                mark: kind == 1,
                ..Video::default()
            };
            video::write(&video::track(truth, &v).unwrap(), TrackFormat::TrackerMulti)
        }
        _ => velocity_file(truth, fps, 0.01, (seed as f64 * 0.618_034).fract(), seed),
    };
    data::load(
        &text,
        "synthetic.txt",
        &data::Reading::default(),
        &Default::default(),
    )
    .unwrap()
}
