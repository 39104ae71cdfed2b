//! The fit finds the truth (issue 35): exact tables of a ball's centre and rim mark
//! over μ_k 0.05–0.35, b 3–5.3 cm, v0 0.3–0.9 m/s and 30–240 frames/s, with and
//! without 0.1–0.3 mm of noise, fitted as a student's track is (R and b given, v0 from
//! the data's approach): the headline μ_k within max(0.002, its ± 2σ) of the truth,
//! never "POOR FIT" on noise-free data; and a line fit that cannot be made is said
//! beside the headline, never instead of it.

use groovelab::study::fit::{Agreement, Fits};
use groovelab::study::video::{self, TrackFormat, Video};

use super::*;
use crate::common::{run, symmetric};

/// One exact table: the truth's μ_k, b (m), v0 (m/s), frames/s, noise (m).
#[derive(Clone, Copy, Debug)]
struct Case {
    mu: f64,
    width: f64,
    v0: f64,
    fps: f64,
    noise: f64,
}

impl Case {
    /// The paper's ball (R 2.75 cm, 167 g, e = 1, no rolling resistance) in this
    /// case's groove.
    fn truth(self) -> Scene {
        symmetric(0.0275, self.width, self.mu, self.v0, 1.0)
    }

    /// The track file of the left ball's centre and rim mark, seeded.
    fn file(self, seed: u64) -> String {
        let v = Video {
            fps: self.fps,
            noise: self.noise,
            seed,
            mark: true,
            ..Video::default()
        };
        video::write(
            &video::track(&self.truth(), &v).unwrap(),
            TrackFormat::TrackerMulti,
        )
    }

    /// The fits `fit` makes of the file: R and b given, v0 from the approach (free in
    /// every model), μ_k started from the default preset's 0.17.
    fn fits(self, seed: u64) -> Fits {
        let series = data::load(
            &self.file(seed),
            "truth.txt",
            &data::Reading::default(),
            &Default::default(),
        )
        .unwrap();
        let v0 = groovelab::lab::approach(&series)
            .expect("the approach is in the data")
            .speed;
        let scene = symmetric(0.0275, self.width, 0.17, v0, 1.0);
        let m = groovelab::study::measured::for_scene(&series, &scene).measured;
        let ask = fit::Ask {
            v0_measured: true,
            ..fit::Ask::default()
        };
        fit::fit_all(&scene, &m, &ask, &groovelab::study::Quiet)
            .unwrap_or_else(|e| panic!("{self:?}: {e}"))
    }
}

/// What one case gave: the headline's error against the truth, its ± 2σ, and whether
/// it holds (within max(0.002, ± 2σ); noise-free: not a poor fit either).
struct Outcome {
    error: f64,
    two_sigma: f64,
    holds: bool,
    said: String,
}

fn outcome(case: Case, seed: u64) -> Outcome {
    let f = case.fits(seed);
    let h = &f.model_fit;
    let error = h.mu - case.mu;
    let two_sigma = 2.0 * h.mu_se;
    let poor = h.agreement() == Agreement::PoorFit;
    let close = error.abs() <= two_sigma.max(0.002);
    Outcome {
        error,
        two_sigma,
        holds: close && !(case.noise == 0.0 && poor),
        said: format!(
            "{case:?}: {} μ_k {:.5} ± {:.5}, {} (RMS {:.2e} m)",
            h.model,
            h.mu,
            two_sigma,
            h.agreement().word(),
            h.rms
        ),
    }
}

/// A handful of the grid's corners, cheap in `cargo test`: the example
/// (μ_k 0.18, b 4.9 cm, 100 frames/s, noise-free: once μ_k 0.1966 ± 0.0107, POOR FIT,
/// while μ_k + v0 + c_rr found 0.18 exactly), the 30 frames/s corner whose impact
/// time, linearised, left 0.02 mm residuals (then μ_k + v0 + e + c_rr was named with
/// μ_k 0.3452), noisy tables at both ends of the ranges, and the grid's one noise-free
/// miss (μ_k 0.2, b 3 cm, 30 frames/s).
#[test]
fn exact_and_noisy_tables_give_the_truth() {
    let cases = [
        (0.18, 0.049, 0.5, 100.0, 0.0),
        (0.35, 0.053, 0.3, 30.0, 0.0),
        (0.05, 0.03, 0.9, 240.0, 2e-4),
        (0.28, 0.042, 0.6, 60.0, 3e-4),
        // μ_k + v0 stopped at 0.1979 (0.25 mm RMS) where μ_k alone at the approach's
        // v0 fitted 0.2 exactly: the smaller model is now a start of the larger.
        (0.2, 0.03, 0.6, 30.0, 0.0),
    ];
    for (k, (mu, width, v0, fps, noise)) in cases.into_iter().enumerate() {
        let case = Case {
            mu,
            width,
            v0,
            fps,
            noise,
        };
        let o = outcome(case, 35 + k as u64);
        assert!(o.holds, "{}", o.said);
        if noise == 0.0 {
            // Exact data: the truth itself, not only within a generous ±.
            assert!(o.error.abs() < 1e-4, "{}", o.said);
        }
    }
}

/// The whole grid: 5 μ_k × 3 b × 3 v0 × 4 frame rates × 3 noise levels (540
/// tables), each noise-free one within max(0.002, ± 2σ) and none "POOR FIT", the
/// noisy ones beyond it at most at the 5 % a 95 % interval leaves; and the
/// noisy ones' ± 2σ covers the truth at about its 95 %. Too slow for `cargo test`:
/// `cargo test --release --test it fit::truth::the_whole_grid -- --ignored --nocapture`
/// (result in BENCHMARKS.md).
#[test]
#[ignore = "the whole truth grid, minutes: run in release, result in BENCHMARKS.md"]
fn the_whole_grid() {
    let mut failed = Vec::new();
    let (mut cases, mut worst, mut noisy, mut covered) = (0, 0.0_f64, 0, 0);
    let mut noisy_missed = 0;
    let mut seed = 3500;
    for mu in [0.05, 0.12, 0.2, 0.28, 0.35] {
        for width in [0.03, 0.042, 0.053] {
            for v0 in [0.3, 0.6, 0.9] {
                for fps in [30.0, 60.0, 120.0, 240.0] {
                    for noise in [0.0, 1e-4, 3e-4] {
                        seed += 1;
                        let case = Case {
                            mu,
                            width,
                            v0,
                            fps,
                            noise,
                        };
                        let o = outcome(case, seed);
                        cases += 1;
                        worst = worst.max(o.error.abs());
                        if noise > 0.0 {
                            noisy += 1;
                            covered += usize::from(o.error.abs() <= o.two_sigma);
                        }
                        if !o.holds {
                            println!("MISS {}", o.said);
                            if noise > 0.0 {
                                noisy_missed += 1;
                            } else {
                                failed.push(o.said);
                            }
                        }
                    }
                }
            }
        }
    }
    println!(
        "{cases} tables, worst |μ_k − truth| {worst:.5}, {} noise-free and {noisy_missed} noisy missed; noisy: {covered} of {noisy} within ± 2σ",
        failed.len()
    );
    // Noise-free: every table.
    assert!(failed.is_empty(), "{failed:#?}");
    // Noisy: an honest 95 % interval leaves about 5 % of draws outside it, so "every
    // table" cannot hold there; their rate is what is checked (and a miss's own noise
    // draws, `the_grid_miss_is_the_noise_not_the_fit`). Binomial(360, 0.954): mean
    // 343, sd 4.0; 4 sd below.
    assert!(covered * 100 >= noisy * 90, "{covered} of {noisy}");
    assert!(noisy_missed * 100 <= noisy * 5, "{noisy_missed} of {noisy}");
}

/// At 30 frames/s and μ_k 0.18 in a 5.3 cm groove the sliding phase holds two frames:
/// the line fits cannot be made, and `fit` once exited 2 though the position fit needs
/// none. Now it prints the headline, and "line fit: not possible (why)" on the line
/// fits' line; its JSON has `line_fit` null with the reason in `not_measured`.
#[test]
fn a_line_fit_that_cannot_be_made_is_said_beside_the_headline() {
    let case = Case {
        mu: 0.18,
        width: 0.053,
        v0: 0.3,
        fps: 30.0,
        noise: 0.0,
    };
    let path = csv("short-sliding.txt", &case.file(1));
    let args = [
        "fit", "--radius", "2.75cm", "--width", "5.3cm", "--data", &path,
    ];
    let (code, out, err) = run(&args);
    assert_eq!(code, 0, "{err}");
    let headline = out.lines().nth(1).unwrap_or_default();
    assert!(headline.starts_with("μ_k = 0.18"), "{out}");
    let said = out
        .lines()
        .find(|l| l.starts_with("line fit: not possible ("))
        .unwrap_or_else(|| panic!("{out}"));
    assert!(said.contains("holds 2 points"), "{said}");
    let (code, out, err) = run(&[&args[..], &["--format", "json"]].concat());
    assert_eq!(code, 0, "{err}");
    let j: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert!(j["line_fit"].is_null(), "{}", j["line_fit"]);
    assert!((j["model_fit"]["mu"].as_f64().unwrap() - 0.18).abs() < 1e-4);
    let why = j["not_measured"]
        .as_array()
        .and_then(|a| a.iter().find(|n| n["quantity"] == "line_fit"))
        .unwrap_or_else(|| panic!("{}", j["not_measured"]));
    assert!(
        why["reason"].as_str().unwrap().contains("holds 2 points"),
        "{why}"
    );
    // A window the user gave that holds too few points is still their input to fix.
    let (code, _, err) = run(&[&args[..], &["--from", "0.05", "--to", "0.06"]].concat());
    assert_eq!(code, 2);
    assert!(
        err.starts_with("error: ") && err.contains("the window"),
        "{err}"
    );
}

/// The grid's one miss is a noisy table (μ_k 0.35, b 3 cm, 120 frames/s, 0.3 mm) at
/// 2.8σ: is it the fit or the noise? The same table under many noise draws: the
/// headline's error over its σ has mean near 0 and spread near 1 (the fit is unbiased
/// and its ± honest), and the draws beyond 2σ are about the 4.6 % a 2σ interval
/// leaves. `TRUTH_DRAWS` sets the draws (default 40 a v0).
#[test]
#[ignore = "many fits of one noisy table, minutes in debug: run in release, result in BENCHMARKS.md"]
fn the_grid_miss_is_the_noise_not_the_fit() {
    let draws: u64 = std::env::var("TRUTH_DRAWS")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(40);
    let (mut z, mut beyond, mut beyond_floor) = (Vec::new(), 0, 0);
    for v0 in [0.3, 0.6, 0.9] {
        let case = Case {
            mu: 0.35,
            width: 0.03,
            v0,
            fps: 120.0,
            noise: 3e-4,
        };
        for seed in 0..draws {
            let o = outcome(case, 90_000 + seed);
            let s = o.error / (0.5 * o.two_sigma);
            z.push(s);
            beyond += usize::from(s.abs() > 2.0);
            beyond_floor += usize::from(!o.holds);
        }
    }
    let n = z.len() as f64;
    let mean = z.iter().sum::<f64>() / n;
    let sd = (z.iter().map(|s| (s - mean).powi(2)).sum::<f64>() / (n - 1.0)).sqrt();
    println!(
        "{} draws: error/σ mean {mean:.3}, sd {sd:.3}; beyond 2σ {beyond}; beyond max(0.002, ± 2σ) {beyond_floor}",
        z.len()
    );
    // Unbiased (the mean's own standard error is sd/√n) and honest (sd near 1).
    assert!(mean.abs() < 3.0 * sd / n.sqrt(), "{mean}");
    assert!((0.7..1.3).contains(&sd), "{sd}");
}
