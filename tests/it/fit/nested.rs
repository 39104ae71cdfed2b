//! A model with one more free value never fits worse than the smaller model inside
//! it, and μ_k + v0 finds the truth of a noise-free track (issue 27's trial: a
//! centre-only track of paper-b4.9 gave μ_k 0.1606, RMS 1.7 mm, for a truth that
//! fits to 0.001 mm).

use groovelab::input::data::{self, Reading};
use groovelab::study::fit::{self, Candidate};
use groovelab::study::measured::{self, Derive, Measured};
use groovelab::study::video::{self, TrackFormat, Video};

use crate::common::preset_scene;

/// The track file of a synthetic video of paper-b4.9 (μ_k = 0.17, e = 1).
fn track_text(mark: bool, noise: f64, seed: u64) -> String {
    let s = preset_scene("paper-b4.9");
    let v = Video {
        fps: 120.0,
        noise,
        seed,
        mark,
        ..Video::default()
    };
    video::write(&video::track(&s, &v).unwrap(), TrackFormat::TrackerMulti)
}

fn measured(text: &str) -> Measured {
    let s = preset_scene("paper-b4.9");
    let series = data::load(text, "video.txt", &Reading::default(), &Derive::default()).unwrap();
    (*measured::for_scene(&series, &s).measured).clone()
}

/// The weighted residual sum of squares a candidate reached.
fn cost(c: &Candidate) -> f64 {
    c.rms * c.rms * c.residuals as f64
}

/// Every pair of candidates where one's free values hold the other's.
fn nested(models: &[Candidate]) -> Vec<(&Candidate, &Candidate)> {
    let mut out = Vec::new();
    for small in models {
        for large in models {
            let inside = small.free.iter().all(|f| large.free.contains(f));
            if small.free.len() < large.free.len() && inside {
                out.push((small, large));
            }
        }
    }
    out
}

/// Centre only and with the mark, noise-free and with 0.3 mm noise, fitted from a
/// start away from the truth (μ_k 0.3, v0 2 % fast, as a v0 from the approach
/// frames may be): each model's RMS² is at most each smaller model's inside it, to
/// 1e-9 relative (or 1e-9 mm, a noise-free fit's rounding); and μ_k + v0 of a
/// noise-free track gives μ_k = 0.17 to 1e-4.
#[test]
fn a_larger_model_never_fits_worse_and_mu_v0_finds_the_truth() {
    let truth = preset_scene("paper-b4.9");
    let mut start = truth;
    start.mu = 0.3;
    start.left.v0 *= 1.02;
    start.right.v0 *= 1.02;
    for (mark, noise) in [(false, 0.0), (false, 3e-4), (true, 0.0), (true, 3e-4)] {
        let m = measured(&track_text(mark, noise, 1));
        let models = fit::compare_models(&start, &m, &groovelab::study::Quiet).unwrap();
        assert_eq!(models.len(), 8, "{models:?}");
        for c in &models {
            println!("mark {mark}, noise {noise}: {} RMS {:.4e} m", c.name, c.rms);
        }
        for (small, large) in nested(&models) {
            let (a, b) = (cost(small), cost(large));
            assert!(
                b <= a * (1.0 + 1e-9) + 1e-24 * large.residuals as f64,
                "mark {mark}, noise {noise}: {} RMS {:.6e} m fits worse than {} RMS {:.6e} m",
                large.name,
                large.rms,
                small.name,
                small.rms
            );
        }
        if noise == 0.0 {
            let mu_v0 = models.iter().find(|c| c.name == "mu+v0").unwrap();
            let mu = mu_v0.parameters[0].value;
            assert!((mu - 0.17).abs() < 1e-4, "mark {mark}: μ_k + v0 gives {mu}");
        }
    }
}
