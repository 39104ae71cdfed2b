//! Each tracked point's σ: written by `track`'s text after the table, read back with
//! the track, and used by the position fit as weights (weighted least squares).

use groovelab::input::data::{self, Reading};
use groovelab::physics::scene::Scene;
use groovelab::study::fit::{self, Free, ModelFit};
use groovelab::study::measured::{
    self, Derive, Measured, MeasuredParts, RawSeries, Track, TrackParts,
};
use groovelab::study::video::{self, Noise, Video};
use groovelab::vision::tracks::{BallTrack, Calibration, Tracks};
use groovelab::vision::write::tracker_text;

use crate::common::paper_scene;

const MU: f64 = 0.17;

/// The exact left ball of `scene` tracked at 120 frames/s with its mark, every
/// coordinate off by a Gaussian of its frame's σ: `small` (m), and `big` on every
/// fourth frame (blurred or half hidden, say); the σ stated with the track.
fn noisy_track(scene: &Scene, seed: u64, small: f64, big: f64) -> Track {
    let exact = video::track(
        scene,
        &Video {
            noise: 0.0,
            ..Video::default()
        },
    )
    .unwrap()
    .into_parts();
    let sigma: Vec<f64> = (0..exact.t.len())
        .map(|k| if k % 4 == 1 { big } else { small })
        .collect();
    let mut g = Noise::new(seed);
    let mut off = |v: &[f64]| -> Vec<f64> {
        v.iter()
            .zip(&sigma)
            .map(|(x, s)| x + s * g.gauss())
            .collect()
    };
    let (mx, my) = exact.mark.clone().unwrap();
    Track::new(TrackParts {
        x: off(&exact.x),
        y: off(&exact.y),
        mark: Some((off(&mx), off(&my))),
        sigma: Some(sigma.clone()),
        mark_sigma: Some(sigma.clone()),
        ..exact
    })
    .unwrap()
}

fn measured_of(scene: &Scene, track: Track) -> Measured {
    let series = measured::prepare(RawSeries::Positions(track), &Derive::default()).unwrap();
    (*measured::for_scene(&series, scene).measured).clone()
}

fn position_fit(scene: &Scene, m: &Measured) -> ModelFit {
    let start = Scene { mu: 0.3, ..*scene };
    fit::position_fit(&start, m, &[Free::Mu], &groovelab::study::Quiet).unwrap()
}

/// Frames with 30 times the σ of the others, perturbed by it: weighted by each
/// point's σ, the fit recovers μ_k within its ±2σ on every seed; weighting all points
/// alike (as without σ) lets those frames pull it off, by far more than the weighted
/// ± on most seeds and several times as far as the weighted fit's on the average.
#[test]
fn the_position_fit_weights_each_point_by_its_sigma() {
    let s = paper_scene();
    let (mut dw2, mut du2, mut pulled) = (0.0, 0.0, 0);
    let seeds = 6;
    for seed in 1..=seeds {
        let m = measured_of(&s, noisy_track(&s, seed, 1e-4, 3e-3));
        assert!(m.x_sigma().is_some() && m.angle_sigma().is_some());
        let plain = Measured::new(MeasuredParts {
            x_sigma: None,
            angle_sigma: None,
            ..m.to_parts()
        })
        .unwrap();
        let (w, u) = (position_fit(&s, &m), position_fit(&s, &plain));
        let (dw, du) = (w.mu - MU, u.mu - MU);
        println!(
            "seed {seed}: weighted μ_k = {:.5} ± {:.5}, unweighted {:.5} ± {:.5}",
            w.mu, w.mu_se, u.mu, u.mu_se
        );
        assert!(
            dw.abs() <= 2.0 * w.mu_se,
            "seed {seed}: {dw} vs ±{}",
            w.mu_se
        );
        // The ± of the weighted fit is its own: about that of the good frames alone.
        assert!(w.mu_se < 0.5 * u.mu_se, "{} vs {}", w.mu_se, u.mu_se);
        pulled += usize::from(du.abs() > 2.0 * w.mu_se);
        (dw2, du2) = (dw2 + dw * dw, du2 + du * du);
    }
    // Unweighted off by about 6 weighted σ on the average (the big frames are a quarter
    // of the points at 30 times the σ): beyond ±2σ_w with probability ~0.75 each.
    assert!(pulled >= 3, "{pulled} of {seeds} pulled beyond ±2σ_w");
    assert!(du2 > 9.0 * dw2, "rms off: unweighted {du2}, weighted {dw2}");
}

/// Without σ the fit is the one it was: the same numbers, to the last bit, whether
/// the track never had σ or had them taken away.
#[test]
fn a_track_without_sigma_fits_as_before() {
    let s = paper_scene();
    let track = noisy_track(&s, 3, 2e-4, 2e-4);
    let with = measured_of(&s, track.clone());
    let track = Track::new(TrackParts {
        sigma: None,
        mark_sigma: None,
        ..track.into_parts()
    })
    .unwrap();
    let without = measured_of(&s, track);
    assert!(without.x_sigma().is_none() && without.angle_sigma().is_none());
    let stripped = Measured::new(MeasuredParts {
        x_sigma: None,
        angle_sigma: None,
        ..with.to_parts()
    })
    .unwrap();
    let (a, b) = (position_fit(&s, &without), position_fit(&s, &stripped));
    assert_eq!((a.mu, a.mu_se), (b.mu, b.mu_se));
    // Equal σ everywhere weigh the frames alike, but the mark's angle now by its own
    // σ (√2 σ over the mark's distance from the centre) rather than as an arc of the
    // contact circle: the same μ_k within a small part of its ±, and a ± as large.
    let c = position_fit(&s, &with);
    assert!(
        (c.mu - a.mu).abs() <= 0.25 * a.mu_se,
        "{} vs {}",
        c.mu,
        a.mu
    );
    assert!(
        (c.mu_se / a.mu_se - 1.0).abs() <= 0.3,
        "{} vs {}",
        c.mu_se,
        a.mu_se
    );
}

/// `track`'s text keeps each point's σ through the reader, to its six digits.
#[test]
fn the_tracker_text_keeps_each_points_sigma() {
    let n = 12;
    let t: Vec<f64> = (0..n).map(|k| 0.01 * k as f64).collect();
    let ramp = |a: f64, b: f64| -> Vec<f64> { (0..n).map(|k| a + b * k as f64).collect() };
    let mut sigma = ramp(1e-5, 3.1e-6);
    sigma[4] = f64::NAN; // the ball left out there
    let mut x = ramp(0.01, 0.002);
    x[4] = f64::NAN;
    let ball = BallTrack {
        name: "left",
        x,
        y: vec![0.0; n],
        sigma: sigma.clone(),
        mark_x: ramp(0.011, 0.002),
        mark_y: vec![0.012; n],
        mark_sigma: ramp(2e-5, 1.7e-6),
        unseen: 1,
        ..BallTrack::default()
    };
    let tracks = Tracks {
        t,
        balls: vec![ball.clone()],
        calibration: Calibration {
            px_per_m: 1e4,
            px_per_m_sigma: 5.0,
            scale_given: false,
            radius_px: 127.0,
            radius_px_sigma: 0.05,
            radius_scatter: 0.003,
            radius_m: 0.0127,
            groove_deg: 0.0,
            groove_deg_sigma: 0.0,
            groove_found: false,
            colour_edge_px: None,
            origin_px: (0.0, 0.0),
        },
    };
    let text = tracker_text(&tracks, &["groovelab track clip.mp4".into()]);
    assert!(
        text.contains(
            "# sigma (m)\tt\tleft ball\tleft mark\n# sigma\t0.000000E0\t1.000000E-5\t2.000000E-5\n"
        ),
        "{text}"
    );
    let RawSeries::Positions(read) = data::read(&text, "clip.txt", &Reading::default()).unwrap()
    else {
        panic!("a position track");
    };
    let close = |a: &[f64], b: &[f64]| {
        a.len() == b.len()
            && a.iter()
                .zip(b)
                .all(|(a, b)| (a.is_nan() && b.is_nan()) || (a - b).abs() <= 5e-7 * b.abs())
    };
    let (s, ms) = (read.sigma().unwrap(), read.mark_sigma().unwrap());
    assert!(close(s, &sigma), "{s:?}");
    assert!(close(ms, &ball.mark_sigma), "{ms:?}");
    // The positions read as before the σ lines were there.
    assert!(close(read.x(), &ball.x), "{:?}", read.x());
}
