//! Fitting the model to measured series of the left ball: the paper's line fits over
//! the sliding phase (table 1), and least-squares fits of the exact model to every
//! point — of the velocities (weighted by their uncertainties when known) or of the
//! tracked positions (weighted by each point's σ when the track states them) — with
//! uncertainties and the regime compared with what was seen.
//! The line fits are in `line`, the model fit in `model` (what it is asked and how it
//! stops in `problem`), the comparison of models in `choice`; here both fits of a
//! series are made together.

#![deny(
    clippy::indexing_slicing,
    clippy::unwrap_used,
    clippy::expect_used,
    clippy::panic
)]

mod approach;
mod choice;
mod least_squares;
mod line;
mod model;
/// A candidate model of given values, for tests of what is made from the models.
#[cfg(test)]
pub(crate) use choice::tests::model as blank_candidate;
/// A fit of nothing, for tests of what is made from fits.
#[cfg(test)]
pub(crate) use model::tests::blank as blank_fit;
mod problem;
mod regime;
mod residuals;
pub mod slips;
mod tracks;
mod uncertainty;

use serde::Serialize;

use crate::physics::scene::Scene;
use crate::study::Progress;
use crate::study::measured::series::Measured;

pub use approach::{APPROACH_FRAMES, Approach, of_velocities};
#[cfg(test)]
pub(crate) use choice::mark;
pub use choice::{
    Candidate, Estimate, compare_candidates, compare_models, rolls_harder_than_it_slides,
};
pub use line::{
    Line, LineFit, PAPER_TABLE, PaperDisagreement, WidthFromLines, line, line_fit,
    paper_disagreements, paper_row, sliding_window,
};
pub use model::{
    Agreement, MAX_MODEL_POINTS, ModelFit, POOR_FIT, model_fit, position_fit, thinned,
};
pub use problem::{DataLooks, FitError, Free, MAX_PLAUSIBLE_MU, MIN_PLAUSIBLE_MU, WORK_BUDGET};
pub use regime::rest_band;
pub use residuals::{NearImpacts, aligned_track};
pub use tracks::{TrackFits, fit_tracks};
pub use uncertainty::{NotIdentified, ScalePart};

/// The fits of one series: the paper's line fits, and one fit per candidate model,
/// the headline among them.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Fits {
    /// The paper's line fits over the sliding phase; `None` where they cannot be made
    /// (`no_line_fit` says why: a window of one frame at 30 frames/s and a high μ_k),
    /// which never stops the model fits, which need none.
    pub line_fit: Option<LineFit>,
    /// Why there is no `line_fit`.
    #[serde(skip)]
    pub no_line_fit: Option<FitError>,
    /// The headline: the fit of the model the data support (or of the one the caller
    /// chose), fitted to a track's positions, else to the velocities: the very fit of
    /// its row in `models`, its numbers the same wherever it is shown.
    pub model_fit: ModelFit,
    /// Why the headline is this model.
    pub chosen: Chosen,
    /// μ_k alone: the `mu` row of `models` (`mu+v0` when v0 was measured in the data),
    /// said beside the headline.
    pub mu_alone: ModelFit,
    /// For a position track: the headline's model fitted to the derived velocities,
    /// a check of it (the positions' fit is the one to quote).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub velocity_fit: Option<ModelFit>,
    /// The candidate models compared by AIC and BIC ([`compare_models`]), one marked
    /// `supported`.
    pub models: Vec<Candidate>,
    /// A track's frames far off the model, left out of these fits ([`slips`]);
    /// `None` where there were none.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub slips: Option<slips::Slips>,
}

/// Why the headline of [`Fits`] is its model.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Chosen {
    /// The simplest model the data support (by BIC, every value determined).
    Supported,
    /// The model the caller asked for (`fit --free`).
    Asked,
    /// No model is supported: μ_k alone, the simplest.
    Simplest,
}

/// What a whole fit of a series is asked ([`fit_all`]).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Ask {
    /// The line fits' window, s from the impact (`None`: the sliding phase's ends).
    pub window: (Option<f64>, Option<f64>),
    /// The model to headline (`fit --free`); `None`: the one the data support.
    pub free: Option<Vec<Free>>,
    /// The scene's v0 was taken from the data's approach ([`Approach`]), not given:
    /// free in every candidate model, so that its error reaches μ_k's ±.
    pub v0_measured: bool,
}

/// Line fit over the window asked and every candidate model fitted to `m` on
/// `scene` ([`compare_models`], with the model `ask.free` among them when given): the
/// headline is that model when given, else the one the data support. A track's
/// frames far off the headline ([`slips`]) are left out and everything fitted again
/// without them, until the fit finds no others (at most [`slips::SLIP_ROUNDS`]
/// times), said in [`Fits::slips`]. Stops when `progress` says so
/// (`FitError::Cancelled`), or when the fits together spend the work budget
/// ([`WORK_BUDGET`]: `FitError::Budget`).
pub fn fit_all(
    scene: &Scene,
    m: &Measured,
    ask: &Ask,
    progress: &dyn Progress,
) -> Result<Fits, FitError> {
    let mut evals = problem::Evals::new(progress);
    let mut fits = fit_points(scene, (m, m), ask, &mut evals)?;
    // Large slips pull the first fit, and its residuals spread wider than the track's:
    // a smaller slip shows only against the fit made without the large ones.
    let mut left_out: Option<slips::Slips> = None;
    for _ in 0..slips::SLIP_ROUNDS {
        let Some((found, (positions, velocities))) =
            slips::of(scene, m, &fits.model_fit, left_out.as_ref(), &mut evals)
        else {
            break;
        };
        if left_out.as_ref().is_some_and(|s| s.points == found.points) {
            break;
        }
        match fit_points(scene, (&positions, &velocities), ask, &mut evals) {
            Ok(again) => (fits, left_out) = (again, Some(found)),
            Err(FitError::Cancelled) => return Err(FitError::Cancelled),
            // Too few frames left, or the budget spent: the fits before stand.
            Err(_) => break,
        }
    }
    Ok(Fits {
        slips: left_out,
        ..fits
    })
}

/// [`fit_all`]'s fits of the series `m` as `(positions, velocities)`: the candidate
/// models (fitted to a track's positions) on the first, the velocity fit and the
/// line fits on the second (the same series but where slips are left out).
fn fit_points(
    scene: &Scene,
    (m, mv): (&Measured, &Measured),
    ask: &Ask,
    evals: &mut problem::Evals,
) -> Result<Fits, FitError> {
    let (window, free) = (ask.window, ask.free.as_deref());
    let same = |a: &[Free], b: &[Free]| a.len() == b.len() && a.iter().all(|f| b.contains(f));
    let mut sets = choice::candidates(m, ask.v0_measured);
    let simplest = sets.first().cloned().unwrap_or_default();
    let extra = free.filter(|f| !sets.iter().any(|s| same(s, f)));
    if let Some(f) = extra {
        sets.push(f.to_vec());
    }
    let mut models = choice::candidates_within(scene, m, sets, evals)?;
    // A set asked for beside the usual ones witnesses no model's leaving out.
    if let Some(f) = extra {
        choice::mark(&mut models, &|c| !same(&c.free, f));
    }
    choice::by_bic(&mut models);
    let find = |f: &[Free]| models.iter().find(|c| same(&c.free, f));
    let (head, chosen) = match free {
        Some(f) => (find(f), Chosen::Asked),
        None => match models.iter().find(|c| c.supported) {
            Some(c) => (Some(c), Chosen::Supported),
            None => (find(&simplest), Chosen::Simplest),
        },
    };
    let Some(head) = head else {
        return Err(FitError::TooFewPoints {
            usable: m.t().len(),
            needed: free.map_or(1, <[Free]>::len) + 2,
        });
    };
    let fitted = least_squares::with(
        scene,
        &head.free,
        &head.parameters.iter().map(|e| e.value).collect::<Vec<_>>(),
    );
    let mu_alone = find(&simplest).map_or_else(|| (*head.fit).clone(), |c| (*c.fit).clone());
    // A track's headline is fitted to its positions: the same model to its derived
    // velocities as a check.
    let velocity_fit = match head.fit.fitted_to {
        "positions" => {
            Some(model::scored_fit(scene, mv, &head.free, residuals::Target::Velocity, evals)?.fit)
        }
        _ => None,
    };
    let given = [window.0.is_some(), window.1.is_some()];
    // Without v_t the data cannot say when sliding ends, and a track's derived v_t
    // says it poorly: the fitted model does ([`regime::sliding_end`]).
    // (Of a track, by the fit to the velocities it derives.)
    let window = match window {
        (from, None) if !regime::v_t_says_sliding_end(mv) => {
            let by = velocity_fit.as_ref().map_or(fitted, |v| v.scene_of(scene));
            (from, regime::sliding_end(mv, &by))
        }
        w => w,
    };
    let (line_fit, no_line_fit) = line_fits(mv, scene, window, given)?;
    // μ_k,cm against μ_k,t: a verdict of every model fit (the same line fits).
    let lines_disagree = line_fit.as_ref().and_then(LineFit::disagree);
    // A track's two fits of one model measure one μ_k: apart, the tracks are in doubt.
    let fits_disagree = velocity_fit
        .as_ref()
        .and_then(|v| model::fits_disagree(&head.fit, v));
    let head_model = head.fit.model.clone();
    let of_head = |model: &str| fits_disagree.filter(|_| model == head_model);
    let judged = |f: ModelFit| ModelFit {
        lines_disagree,
        fits_disagree: of_head(&f.model),
        ..f
    };
    let model_fit = judged((*head.fit).clone());
    for c in &mut models {
        c.fit.lines_disagree = lines_disagree;
        c.fit.fits_disagree = of_head(&c.fit.model);
    }
    let fits = Fits {
        line_fit,
        no_line_fit,
        model_fit,
        chosen,
        mu_alone: judged(mu_alone),
        velocity_fit: velocity_fit.map(judged),
        models,
        slips: None,
    };
    check_finite(&fits, m, scene)?;
    Ok(fits)
}

/// The line fits over `window` (`given`: which ends the user set), or why they
/// cannot be made, said beside the headline. A window the user gave that holds too
/// few points is their input to fix (the error); the automatic one that does (a
/// sliding phase of one frame), or line fits that overflow, only leave them out.
fn line_fits(
    m: &Measured,
    scene: &Scene,
    window: (Option<f64>, Option<f64>),
    given: [bool; 2],
) -> Result<(Option<LineFit>, Option<FitError>), FitError> {
    Ok(match line_fit(m, scene, window) {
        Ok(l) => match line_fit_overflow(&l) {
            bad if bad.is_empty() => (Some(LineFit { given, ..l }), None),
            bad => (
                None,
                Some(FitError::NotFinite {
                    bad,
                    looks: looks(m, scene),
                }),
            ),
        },
        Err(e) if given.iter().any(|g| *g) => return Err(e),
        Err(e) => (None, Some(e)),
    })
}

/// The line fit's numbers that are not finite where they were measured: a_cm and
/// μ_k,cm always; a_t and μ_k,t are NaN by design where v_t was measured in fewer than
/// three frames of the window (no rim mark, or one followed in too few frames), said
/// "not measured", but never ±∞. A line fit with any is left out, said beside the
/// headline: the model fits need none.
fn line_fit_overflow(l: &LineFit) -> Vec<&'static str> {
    [
        ("line fit a_cm", l.a_cm.is_finite()),
        ("line fit μ_k,cm", l.mu_cm.is_finite()),
        ("line fit a_t", !l.a_t.is_infinite()),
        ("line fit μ_k,t", !l.mu_t.is_infinite()),
    ]
    .into_iter()
    .filter(|(_, ok)| !ok)
    .map(|(name, _)| name)
    .collect()
}

/// Every number a fit reports is finite, or the fit is an error: an overflowing
/// scene (v0 = 1e308) must not print "RMS residual inf" or "± NaN". The line fit is
/// checked where it is made ([`line_fit_overflow`]).
fn check_finite(f: &Fits, data: &Measured, scene: &Scene) -> Result<(), FitError> {
    let m = &f.model_fit;
    let named = [
        ("model fit v0 error", m.v0_se.unwrap_or(0.0)),
        ("model fit e error", m.restitution_se.unwrap_or(0.0)),
        (
            "model fit c_rr error",
            m.rolling_resistance_se.unwrap_or(0.0),
        ),
        ("model fit μ_k", m.mu),
        // An undetermined μ_k has no error, by design (said in words).
        (
            "model fit μ_k error",
            if m.undetermined(Free::Mu.name()).is_some() {
                0.0
            } else {
                m.mu_se
            },
        ),
        ("model fit v0", m.v0),
        ("model fit e", m.restitution),
        ("model fit c_rr", m.rolling_resistance),
        ("model fit RMS residual", m.rms),
        ("model fit rolling speed v'", m.v_roll),
    ];
    let bad: Vec<&'static str> = named
        .iter()
        .filter(|(_, v)| !v.is_finite())
        .map(|(n, _)| *n)
        .collect();
    if bad.is_empty() {
        return Ok(());
    }
    Err(FitError::NotFinite {
        bad,
        looks: looks(data, scene),
    })
}

/// What the series `data` looks like in `scene`, for a fit that gives no finite
/// number ([`FitError::NotFinite`]).
fn looks(data: &Measured, scene: &Scene) -> DataLooks {
    let mut steps: Vec<f64> = data
        .t()
        .windows(2)
        .filter_map(|w| w.last().zip(w.first()).map(|(b, a)| b - a))
        .collect();
    steps.sort_by(f64::total_cmp);
    let span = |v: &[f64]| {
        v.iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &x| {
                (lo.min(x), hi.max(x))
            })
    };
    DataLooks {
        t: span(data.t()),
        frame: steps.get(steps.len() / 2).copied().unwrap_or(f64::NAN),
        fastest: data
            .v_cm()
            .iter()
            .chain(data.v_t())
            .filter(|v| v.is_finite())
            .fold(0.0_f64, |a, v| a.max(v.abs())),
        positions: data.x().map(span),
        v0: scene.left.v0.abs().max(scene.right.v0.abs()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::physics::scene::Ball;
    use std::sync::atomic::{AtomicU64, Ordering};

    /// A [`Progress`] that keeps the last count of model evaluations the fit reported.
    #[derive(Default)]
    struct Ticks(AtomicU64);

    impl Progress for Ticks {
        fn tick(&self, done: u64, _total: u64) {
            self.0.store(done, Ordering::Relaxed);
        }
    }

    /// The default scene with the paper's balls (167 g at 0.79 m/s), and its exact
    /// motion from `t_start`.
    fn paper_balls_from(t_start: f64) -> (Scene, crate::physics::solution::Solution) {
        let ball = Ball {
            mass: 0.167,
            v0: 0.79,
        };
        let scene = Scene {
            left: ball,
            right: ball,
            ..Scene::default()
        };
        let span = crate::physics::scene::Span {
            t_start,
            t_end: None,
        };
        (scene, crate::physics::engine::solve(&scene, &span))
    }

    /// Looks table seeds 5, 17, 31: a track whose rim mark was followed before the
    /// impact but in fewer than three frames of the sliding phase made the whole fit
    /// refuse ("no finite line fit a_t"), although the model fits need no line fit.
    /// The headline stands; the line fit keeps a_cm and says a_t is not measured.
    #[test]
    fn a_rim_mark_lost_in_the_sliding_phase_leaves_the_headline_and_a_cm() {
        let (scene, sol) = paper_balls_from(-0.1);
        let t: Vec<f64> = (0..40).map(|i| -0.1 + f64::from(i) / 100.0).collect();
        let v_cm = t.iter().map(|&t| sol.at(t).left.v).collect();
        // The mark followed until the impact and in one frame after it.
        let v_t = t
            .iter()
            .map(|&t| {
                if t <= 0.011 {
                    sol.at(t).left.u
                } else {
                    f64::NAN
                }
            })
            .collect();
        let m = Measured::velocities(t, v_cm, v_t).unwrap();
        let fits = fit_all(&scene, &m, &Ask::default(), &crate::study::Quiet).unwrap();
        assert!(
            (fits.model_fit.mu - scene.mu).abs() < 1e-6,
            "{}",
            fits.model_fit.mu
        );
        let line = fits.line_fit.ok_or(fits.no_line_fit).unwrap();
        assert!(line.a_cm.is_finite() && line.mu_cm.is_finite());
        assert!((line.mu_cm - scene.mu).abs() < 0.02, "{}", line.mu_cm);
        assert!(line.a_t.is_nan() && line.mu_t.is_nan());
        // A line fit that overflows is left out, beside the headline.
        let inf = LineFit {
            a_t: f64::INFINITY,
            ..line
        };
        assert_eq!(line_fit_overflow(&inf), vec!["line fit a_t"]);
    }

    /// Trial item 19: near b = 2R each run of the model has thousands of segments, and
    /// `fit --width 5.4999cm` took 88 s to say "μ_k not determined". The fit counts its
    /// model evaluations and their segments, and stops at its budget with a sentence;
    /// the same data in their own scene fit far within the real budget.
    #[test]
    fn a_fit_near_b_2r_stops_at_its_work_budget_and_says_so() {
        let (scene, sol) = paper_balls_from(-0.1);
        let t: Vec<f64> = (0..30).map(|i| -0.1 + f64::from(i) / 50.0).collect();
        let v_cm = t.iter().map(|&t| sol.at(t).left.v).collect();
        let v_t = t.iter().map(|&t| sol.at(t).left.u).collect();
        let m = Measured::velocities(t, v_cm, v_t).unwrap();
        let free = &[Free::Mu];
        let velocity = residuals::Target::Velocity;
        let near = Scene {
            width: 0.054999,
            ..scene
        };
        let budget = 40_000;
        let ticks = Ticks::default();
        let mut evals = problem::Evals::with_budget(&ticks, budget);
        let err = model::scored_fit(&near, &m, free, velocity, &mut evals).err();
        let Some(FitError::Budget {
            evaluations,
            segments,
            longest,
        }) = err.clone()
        else {
            panic!("{err:?}")
        };
        // Runs of thousands of segments: stopped after the few the budget holds.
        assert!(longest > 5_000, "{longest}");
        // The count the error gives is the one the fit reported as it went.
        assert_eq!(evaluations, ticks.0.load(Ordering::Relaxed));
        assert!(segments > budget && segments <= budget + 2 * longest as u64);
        assert!(evaluations <= budget / 5_000 + 2, "{evaluations}");
        let text = err.unwrap().to_string();
        assert!(
            text.contains("work budget") && text.contains("μ_k is not determined"),
            "{text}"
        );
        // The data's own scene: a fit of tens of segments a run, within a hundredth of
        // the real budget.
        let mut evals = problem::Evals::with_budget(&crate::study::Quiet, WORK_BUDGET / 100);
        let fitted = model::scored_fit(&scene, &m, free, velocity, &mut evals).unwrap();
        assert!((fitted.fit.mu - 0.17).abs() < 1e-3, "{}", fitted.fit.mu);
    }

    #[test]
    fn a_fit_without_finite_numbers_says_what_the_numbers_look_like_and_which_options_read_them() {
        // ms and cm/s read as s and m/s: frames 8.33 "s" apart, speeds of 50 "m/s".
        let t: Vec<f64> = (-3..=3).map(|i| f64::from(i) * 8.333).collect();
        let data = Measured::velocities(t, vec![50.0; 7], vec![50.0; 7]).unwrap();
        let ball = Ball {
            mass: 0.11,
            v0: 0.5,
        };
        let scene = Scene {
            radius: 0.015,
            width: 0.021,
            left: ball,
            right: ball,
            ..Scene::default()
        };
        let e = FitError::NotFinite {
            bad: vec!["model fit μ_k"],
            looks: looks(&data, &scene),
        }
        .to_string();
        for want in [
            "no finite model fit μ_k",
            "t = -25 … 25 s with frames 8.33 s apart and speeds up to 50 m/s",
            "the scene's v0 is 0.5 m/s",
            "--time-unit",
            "--speed-unit",
            "--length-unit",
        ] {
            assert!(e.contains(want), "{want}: {e}");
        }
        assert!(!e.contains("overflow"), "{e}");
    }
}
