//! The least-squares fit of the exact model to a measured series, of its velocities
//! or of its tracked positions, with uncertainties and the regime compared with what
//! was seen; a long series thinned first.

use serde::Serialize;

use crate::physics::closed_form;
use crate::physics::derived::{Derived, Regime};
use crate::physics::engine;
use crate::physics::scene::{Scene, Span};
use crate::physics::story::Verdict;
use crate::study::Progress;
use crate::study::measured::series::Measured;

use super::least_squares::{
    At, Problem, least_squares, normal_matrix, profile_mu, smooth_jacobian, with,
};
use super::problem::{Evals, FitError, Free, MAX_PLAUSIBLE_MU, MIN_PLAUSIBLE_MU};
use super::regime::{data_scatter, observed_after, rest_band, sliding_end};
use super::residuals::{Target, fit_points, labelled_residuals, nuisance};
use super::uncertainty::{
    NotIdentified, ScalePart, effective_points, shared_noise, uncertainties, with_scale,
};

/// Most frames the model fit uses. A longer series is thinned to every k-th frame
/// (the output says so): each model evaluation walks every point used, and a fit
/// takes a few hundred evaluations, so 1 000 000 frames took 10 s where 20 000 take
/// a fifth of a second. Video analysis gives 30–1000 frames a second: a real series
/// stays far below the cap.
pub const MAX_MODEL_POINTS: usize = 20_000;

/// The whole-model least-squares fit.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct ModelFit {
    /// The model: its free values joined by `+` (`mu`, `mu+v0`), as in
    /// [`super::Candidate::name`].
    pub model: String,
    /// What it was fitted to: `velocities` (`rms` in m/s) or `positions` (`rms` in m).
    pub fitted_to: &'static str,
    pub mu: f64,
    pub mu_se: f64,
    /// Fitted v0, e and c_rr (the scene's when not free) and their standard errors.
    pub v0: f64,
    pub v0_se: Option<f64>,
    pub restitution: f64,
    pub restitution_se: Option<f64>,
    pub rolling_resistance: f64,
    pub rolling_resistance_se: Option<f64>,
    /// Root-mean-square residual over all v_cm and v_t points used, m/s (of a fit to
    /// positions: over x and the mark's arc, m).
    pub rms: f64,
    pub points: usize,
    pub regime_predicted: Regime,
    pub regime_observed: Regime,
    /// False where the data end before the model's sliding phase does: no regime was
    /// seen (`regime_observed` then says rest) and the verdict is
    /// [`Agreement::RegimeNotSeen`].
    pub regime_seen: bool,
    /// Speeds within ± this of zero count as "at rest" for both regimes, m/s.
    pub rest_band: f64,
    /// The model's rolling speed after the impact, m/s (positive back toward).
    pub v_roll: f64,
    /// The predicted regime with its margin against the rest band, in words (as the
    /// app and `simulate` say it): "recollide (v' = +0.028 m/s, within …)".
    pub verdict: String,
    /// True when the predicted v' lies inside the rest band.
    pub indistinguishable_from_rest: bool,
    /// True when what was observed agrees with the prediction (the same regime, or
    /// rest where the prediction cannot be told from rest); never where μ_k is not
    /// determined (a regime predicted from it agrees with nothing).
    pub agrees: bool,
    /// Free values the data cannot pin down, and why (their `_se` is null).
    pub not_identified: Vec<NotIdentified>,
    /// The data's own scatter in the units of `rms` (m/s; m for a position fit), where
    /// it can be told: an RMS residual far beyond it means the model does not describe
    /// the data ([`Agreement::PoorFit`]).
    pub scatter: Option<f64>,
    /// Set when the series had more than [`MAX_MODEL_POINTS`] frames: the fit used
    /// every this-many-th frame.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub every: Option<usize>,
    /// Where the data state their scale's ± (a video's): `mu_se` and `v0_se` hold it
    /// added in quadrature to the fit's own, and this says both parts.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub scale: Option<ScalePart>,
    /// The line fits' μ_k,cm and μ_k,t where they disagree ([`LineFit::disagree`]):
    /// the scene's k (b or R) does not fit the data, and there is no verdict. Set by
    /// `fit_all`, which has the line fits.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub lines_disagree: Option<(f64, f64)>,
    /// A track's μ_k fitted to its positions and to the velocities it derives, where
    /// they disagree ([`fits_disagree`]): the tracks carry an error neither fit
    /// models, and there is no verdict. Set by `fit_all` on both fits.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub fits_disagree: Option<(f64, f64)>,
    /// True when the fitted μ_k is beyond [`MAX_PLAUSIBLE_MU`], or below
    /// [`MIN_PLAUSIBLE_MU`] by its ± 2σ: no ball rolls in a groove with that, so the
    /// data's unit is likely wrong (speeds in cm/s read as m/s make every
    /// deceleration, and μ_k, 100× too large; m/s read as cm/s, 100× too small);
    /// there is no verdict.
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub mu_implausible: bool,
}

impl ModelFit {
    /// Why the data do not determine the free value `parameter` ([`Free::name`]), if
    /// they do not: then it is "not determined" (JSON null), never a number that
    /// reads as fitted.
    pub fn undetermined(&self, parameter: &str) -> Option<&NotIdentified> {
        self.not_identified
            .iter()
            .find(|n| n.parameter == parameter)
    }

    /// `scene` with this fit's values (μ_k, both v0, e, c_rr).
    pub fn scene_of(&self, scene: &Scene) -> Scene {
        let mut s = *scene;
        s.mu = self.mu;
        s.restitution = self.restitution;
        s.rolling_resistance = self.rolling_resistance;
        s.left.v0 = self.v0;
        s.right.v0 = self.v0;
        s
    }

    /// The RMS residual at or below which a fit is perfect whatever the data's
    /// scatter ([`PERFECT_POSITION_RMS`], [`PERFECT_VELOCITY_RMS`]): exact data have a
    /// scatter of about zero, and ten times zero is no yardstick.
    pub fn perfect_rms(&self) -> f64 {
        if self.fitted_to == "positions" {
            PERFECT_POSITION_RMS
        } else {
            PERFECT_VELOCITY_RMS
        }
    }

    /// The regime observed in a word ("recollide"), or "not seen" where the data end
    /// before the model's sliding phase does.
    pub fn observed_name(&self) -> &'static str {
        if self.regime_seen {
            self.regime_observed.name()
        } else {
            "not seen"
        }
    }

    /// The one verdict of the fit against what was observed, for every place that
    /// says it (the `fit` table, the Fit view).
    pub fn agreement(&self) -> Agreement {
        if self.undetermined(Free::Mu.name()).is_some() {
            Agreement::MuNotDetermined
        } else if self.mu_implausible && self.mu > MAX_PLAUSIBLE_MU {
            Agreement::ImplausibleMu
        } else if self.mu_implausible {
            Agreement::TinyMu
        } else if self.lines_disagree.is_some() {
            // Before a poor fit: the cause named (a wrong b or R fits poorly too).
            Agreement::LinesDisagree
        } else if self.fits_disagree.is_some() {
            Agreement::FitsDisagree
        } else if self.scatter.is_some_and(|s| self.rms > POOR_FIT * s)
            && self.rms > self.perfect_rms()
        {
            Agreement::PoorFit
        } else if !self.regime_seen {
            Agreement::RegimeNotSeen
        } else if !self.agrees {
            Agreement::Disagrees
        } else if self.indistinguishable_from_rest {
            Agreement::WithinRestBand
        } else {
            Agreement::Agrees
        }
    }
}

/// A model fit's verdict on what was observed ([`ModelFit::agreement`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Agreement {
    /// The predicted regime is what was observed.
    Agrees,
    /// What was observed agrees because the predicted v' lies within the data's rest
    /// band: the data cannot tell the prediction from rest.
    WithinRestBand,
    /// The predicted regime is not what was observed.
    Disagrees,
    /// The data end before the model's sliding phase does: what the balls did after
    /// it was not seen, so nothing to hold the prediction against.
    RegimeNotSeen,
    /// The data do not determine μ_k (on the edge of its range, or not identifiable):
    /// the regime predicted from it says nothing, so there is no verdict.
    MuNotDetermined,
    /// The RMS residual is more than [`POOR_FIT`] times the data's scatter: the model
    /// does not describe the data (wrong units, wrong scene, another experiment), so
    /// its predicted regime says nothing either.
    PoorFit,
    /// μ_k from v_cm and from v_t (the line fits) disagree ([`LineFit::disagree`]):
    /// k = r/R enters them as k and 1/k, so the scene's b or R does not fit the data.
    LinesDisagree,
    /// A track's μ_k fitted to its positions and to its derived velocities disagree
    /// ([`fits_disagree`]): the tracks carry an error neither fit models.
    FitsDisagree,
    /// μ_k is beyond [`MAX_PLAUSIBLE_MU`] ([`ModelFit::mu_implausible`]): the data's
    /// unit is likely wrong.
    ImplausibleMu,
    /// μ_k with its ± 2σ lies below [`MIN_PLAUSIBLE_MU`] ([`ModelFit::mu_implausible`]):
    /// the data's unit is likely wrong the other way.
    TinyMu,
}

/// How many times the data's scatter an RMS residual may be before the fit is poor.
/// A model that describes the data leaves residuals of about the scatter (1×); a few
/// times it where the model misses an impact's detail; never 10×.
pub const POOR_FIT: f64 = 10.0;

/// An RMS position residual no video resolves, m (10 µm: a hundredth of a pixel at
/// 1000 px/m): a fit this close is perfect, never poor (exact tables once read
/// "POOR FIT (RMS 0.000 mm)": ten times a scatter of zero).
pub const PERFECT_POSITION_RMS: f64 = 1e-5;

/// The same for a fit to velocities, m/s (1 mm/s: a tenth of a typical derived
/// velocity's standard error).
pub const PERFECT_VELOCITY_RMS: f64 = 1e-3;

impl Agreement {
    /// In a word or two, for a table cell (at most 15 characters: the Fit view's
    /// columns).
    pub fn word(self) -> &'static str {
        match self {
            Agreement::Agrees => "agrees",
            Agreement::WithinRestBand => "agrees (v'≈0)",
            Agreement::Disagrees => "DISAGREES",
            Agreement::RegimeNotSeen => "regime unseen",
            Agreement::MuNotDetermined => "no verdict",
            Agreement::PoorFit => "POOR FIT",
            Agreement::LinesDisagree => "μ_k,cm ≠ μ_k,t",
            Agreement::FitsDisagree => "FITS DISAGREE",
            Agreement::ImplausibleMu => "μ_k > 1: units?",
            Agreement::TinyMu => "μ_k < 0.01: units?",
        }
    }

    /// As a sentence about the model and what was observed.
    pub fn sentence(self) -> &'static str {
        match self {
            Agreement::Agrees => "the model predicts what was observed",
            Agreement::WithinRestBand => {
                "consistent: the predicted v' lies within the rest band, so the data cannot tell it from rest"
            }
            Agreement::Disagrees => "the model does NOT predict what was observed",
            Agreement::RegimeNotSeen => {
                "no verdict on the regime: the data end before the model's sliding phase does, so what the balls did after it was not seen (film or track longer after the impact)"
            }
            Agreement::MuNotDetermined => {
                "no verdict: the data do not determine μ_k, so the regime predicted from it says nothing"
            }
            Agreement::PoorFit => {
                "no verdict: the RMS residual is over 10× the data's scatter, so the model does not describe these data (check the units and the scene)"
            }
            Agreement::LinesDisagree => {
                "no verdict: μ_k,cm and μ_k,t of the line fits disagree beyond their ± and by over a quarter, so the scene's b or R does not fit these data (k = r/R enters μ_k,cm as k, μ_k,t as 1/k): check --width and --radius"
            }
            Agreement::FitsDisagree => {
                "no verdict: μ_k fitted to the positions and to the velocities of the same tracks disagree beyond their ± and by over a tenth, so the tracks carry an error neither fit models (a centre or mark misplaced in many frames) or the scene's b or R is not the groove's: check --width and --radius, then the tracking (track --overlay), or film again"
            }
            Agreement::ImplausibleMu => {
                "no verdict: a μ_k beyond 1 is no ball rolling in a groove, so the data's unit is likely wrong (speeds in cm/s read as m/s make μ_k 100× too large): give --speed-unit cm/s (a track in cm: --length-unit cm), or fix the header"
            }
            Agreement::TinyMu => {
                "no verdict: a μ_k below 0.01 is no ball sliding in a groove (the slipperiest solids slide at 0.04), so the data's unit is likely wrong (speeds in m/s under a cm/s header make μ_k 100× too small): give --speed-unit m/s (a track in m: --length-unit m), or fix the header"
            }
        }
    }

    /// [`Agreement::sentence`] in a narrow panel's words.
    pub fn short_sentence(self) -> &'static str {
        match self {
            Agreement::Agrees => "the model predicts what was seen",
            Agreement::WithinRestBand => "consistent: within the rest band",
            Agreement::Disagrees => "the model does NOT predict what was seen",
            Agreement::RegimeNotSeen => "no verdict: the data end too soon",
            Agreement::MuNotDetermined => "no verdict: μ_k not determined",
            Agreement::PoorFit => "no verdict: RMS ≫ the data's scatter",
            Agreement::LinesDisagree => "no verdict: μ_k,cm ≠ μ_k,t (b, R?)",
            Agreement::FitsDisagree => "no verdict: x and v fits disagree",
            Agreement::ImplausibleMu => "no verdict: μ_k > 1 (units?)",
            Agreement::TinyMu => "no verdict: μ_k < 0.01 (units?)",
        }
    }

    /// True for a verdict that the prediction holds.
    pub fn holds(self) -> bool {
        matches!(self, Agreement::Agrees | Agreement::WithinRestBand)
    }
}

/// Whether a fitted μ_k (with its standard error `se`) is no ball's in a groove:
/// beyond [`MAX_PLAUSIBLE_MU`], or with its ± 2σ wholly below [`MIN_PLAUSIBLE_MU`].
fn implausible_mu(mu: f64, se: Option<f64>) -> bool {
    mu > MAX_PLAUSIBLE_MU || se.is_some_and(|se| mu + 2.0 * se < MIN_PLAUSIBLE_MU)
}

/// How far apart a track's μ_k fitted to its positions and to its derived velocities
/// may lie, relative to their mean, beyond their ±, on tracks that are right: the
/// velocity fit's local derivatives round the impact's corners (a few %), and both
/// ± leave out the errors neighbouring frames share.
pub const FITS_APART: f64 = 0.1;

/// μ_k of the position fit `p` and of the velocity fit `v` (one model, one track)
/// when they disagree: by more than twice their combined ± (their own parts: the
/// scale's is common to both) and more than [`FITS_APART`] of their mean. `None`
/// where either does not determine μ_k.
pub fn fits_disagree(p: &ModelFit, v: &ModelFit) -> Option<(f64, f64)> {
    let mu = Free::Mu.name();
    if p.undetermined(mu).is_some() || v.undetermined(mu).is_some() {
        return None;
    }
    let own = |m: &ModelFit| m.scale.as_ref().map_or(m.mu_se, |s| s.mu_se_fit);
    let apart = (p.mu - v.mu).abs();
    let se = own(p).hypot(own(v));
    (apart.is_finite() && apart > 2.0 * se && apart > FITS_APART * 0.5 * (p.mu + v.mu).abs())
        .then_some((p.mu, v.mu))
}

/// Every `k`-th frame of `m`, with `k` the smallest that leaves at most
/// [`MAX_MODEL_POINTS`] frames; `None` if the series is short enough already.
pub fn thinned(m: &Measured) -> Option<(Measured, usize)> {
    let n = m.t().len();
    if n <= MAX_MODEL_POINTS {
        return None;
    }
    let k = n.div_ceil(MAX_MODEL_POINTS);
    Some((m.retain_points(|i| i % k == 0), k))
}

/// Least squares of the exact model's v_cm and v_t of the left ball to all measured
/// points (Levenberg–Marquardt, numerical derivatives), free `free`. Points with an
/// uncertainty (`v_cm_sigma`, `v_t_sigma`) count by its inverse square; a v_t that
/// was not measured (NaN) is left out. A series longer than [`MAX_MODEL_POINTS`] is
/// [`thinned`] first. Stops when `progress` says so.
pub fn model_fit(
    scene: &Scene,
    m: &Measured,
    free: &[Free],
    progress: &dyn Progress,
) -> Result<ModelFit, FitError> {
    model_fit_of(scene, m, free, Target::Velocity, progress)
}

/// Least squares of the exact model's positions to a tracked series (`m.x`, and
/// `m.angle` when the rim mark was tracked): no differentiation, so its uncertainty
/// comes from independent residuals. Points with a σ (`x_sigma`, `angle_sigma`) count
/// by its inverse square; the ± then still comes from the weighted residuals'
/// scatter. `rms` is in metres (x and r θ), unweighted.
pub fn position_fit(
    scene: &Scene,
    m: &Measured,
    free: &[Free],
    progress: &dyn Progress,
) -> Result<ModelFit, FitError> {
    if m.x().is_none() {
        return Err(FitError::NoPositions);
    }
    model_fit_of(scene, m, free, Target::Position, progress)
}

fn model_fit_of(
    scene: &Scene,
    m: &Measured,
    free: &[Free],
    target: Target,
    progress: &dyn Progress,
) -> Result<ModelFit, FitError> {
    scored_fit(scene, m, free, target, &mut Evals::new(progress)).map(|s| s.fit)
}

/// A model fit with what information criteria need: the weighted residual sum of
/// squares, how many values were estimated (the free ones
/// and a position fit's profiled impact time, place and angle), and its estimates.
pub(super) struct Scored {
    pub fit: ModelFit,
    pub cost: f64,
    pub estimated: usize,
    pub values: Vec<f64>,
    pub ses: Vec<Option<f64>>,
    /// The fitted scene and the frames it was fitted on (of the [`thinned`] series).
    pub scene: Scene,
    pub idx: Vec<usize>,
}

/// How a fit searches ([`best_values`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Search<'a> {
    /// The profile of μ_k over its whole range first ([`profile_mu`]), then every free
    /// value together from its lowest point: a fit from nothing.
    Profile,
    /// Levenberg–Marquardt from the scene's values: a fit carried from another
    /// model's optimum (a smaller one inside it, a larger one projected down).
    From,
    /// [`Search::From`] on these frames only (indices of the [`thinned`] series,
    /// sorted): the refit of a model on the frames every candidate shares.
    Within(&'a [usize]),
}

/// The free values that fit `m` best, from the scene's, and the frames they were
/// fitted on: those away from the model's impacts (and among those `search` names).
fn best_values(
    pb: &Problem,
    evals: &mut Evals,
    search: Search,
) -> Result<(Vec<f64>, Vec<usize>), FitError> {
    let Problem {
        scene,
        m,
        free,
        target,
    } = *pb;
    let p: Vec<f64> = free
        .iter()
        .map(|f| match f {
            Free::Mu if search == Search::Profile => scene.mu.max(0.01),
            other => other.value_in(scene),
        })
        .collect();
    let within = match search {
        Search::Within(w) => Some(w),
        _ => None,
    };
    let frames = |p: &[f64], evals: &mut Evals| {
        let mut idx = fit_points(m, &with(scene, free, p), target, evals);
        if let Some(w) = within {
            idx.retain(|i| w.binary_search(i).is_ok());
        }
        idx
    };
    let Some(i) = free
        .iter()
        .position(|f| *f == Free::Mu)
        .filter(|_| search == Search::Profile)
    else {
        return refined(pb, evals, p, &frames);
    };
    // The profile over every frame, and where the ball comes back to hit again also
    // over the frames before that: after many recollisions (b near 2R) the cost
    // over every frame has a valley too narrow for any grid, while up to the first
    // return it is smooth in μ_k. Each then fitted on every frame; the better kept.
    let mut best: Option<(f64, Fitted)> = None;
    for within in [None, before_return(m)] {
        if best.is_some() && within.is_none() {
            continue;
        }
        let start = profile_mu(pb, evals, &p, i, within.as_deref())?;
        let (q, idx) = refined(pb, evals, start, &frames)?;
        let r = pb.residuals(&q, &idx, evals);
        let cost = r.iter().map(|x| x * x).sum::<f64>() / r.len().max(1) as f64;
        if best.as_ref().is_none_or(|b| cost < b.0) {
            best = Some((cost, (q, idx)));
        }
    }
    best.map(|b| b.1).ok_or(FitError::TooFewPoints {
        usable: 0,
        needed: free.len() + 2,
    })
}

/// Fitted free values and the frames they were fitted on.
type Fitted = (Vec<f64>, Vec<usize>);

/// The frames of a track before its ball first comes back to where it hit: from the
/// first frame after the impact, the ball moves away (x below 0 by more than five
/// scatters and 1 mm) and a frame back over half the way from its farthest point
/// ends them (at 30 frames/s a ball that hits again at once is never seen nearer). `None` without positions, without such a return, or with fewer than
/// six frames after the impact before it.
fn before_return(m: &Measured) -> Option<Vec<usize>> {
    let x = m.x()?;
    let away = (5.0 * m.stencils().as_ref().map_or(0.0, |s| s.scatter)).max(1e-3);
    let mut farthest = 0.0_f64;
    let mut after = 0;
    let back = m.t().iter().zip(x).position(|(&t, &x)| {
        if t <= 0.0 || !x.is_finite() {
            return false;
        }
        after += 1;
        farthest = farthest.min(x);
        farthest < -away && x > 0.5 * farthest
    })?;
    (after > 6).then(|| (0..back).collect())
}

/// Every free value together by Levenberg–Marquardt from `p`, on the frames `frames`
/// picks (away from the model's impacts: chosen again once the fit has moved them).
fn refined(
    pb: &Problem,
    evals: &mut Evals,
    mut p: Vec<f64>,
    frames: &dyn Fn(&[f64], &mut Evals) -> Vec<usize>,
) -> Result<(Vec<f64>, Vec<usize>), FitError> {
    let mut idx = frames(&p, evals);
    for _ in 0..3 {
        p = least_squares(pb, evals, &idx, p)?;
        let next = frames(&p, evals);
        if next == idx {
            break;
        }
        idx = next;
    }
    Ok((p, idx))
}

pub(super) fn scored_fit(
    scene: &Scene,
    m: &Measured,
    free: &[Free],
    target: Target,
    evals: &mut Evals,
) -> Result<Scored, FitError> {
    scored_fit_within(scene, m, free, target, Search::Profile, evals)
}

/// [`scored_fit`] searching as `search` says: from `scene`'s values (a model's
/// optimum carried from another), on the frames every candidate shares
/// ([`super::choice`]).
pub(super) fn scored_fit_within(
    scene: &Scene,
    m: &Measured,
    free: &[Free],
    target: Target,
    search: Search,
    evals: &mut Evals,
) -> Result<Scored, FitError> {
    let thin = thinned(m);
    let (m, every) = match &thin {
        Some((t, k)) => (t, Some(*k)),
        None => (m, None),
    };
    let pb = Problem {
        scene,
        m,
        free,
        target,
    };
    let (p, idx) = best_values(&pb, evals, search)?;
    let fitted = with(scene, free, &p);
    let (r, labels) = labelled_residuals(&fitted, m, &idx, target, true, evals);
    let n = p.len();
    let cost: f64 = r.iter().map(|x| x * x).sum();
    let (mut ses, not_identified) = standard_errors(&pb, evals, (&p, &idx), (&r, &labels));
    let scale = m
        .scale_rel_se()
        .and_then(|rel| with_scale(rel, free, &p, &mut ses));
    let se = |f: Free| {
        free.iter()
            .position(|x| *x == f)
            .and_then(|i| ses.get(i).copied().flatten())
    };
    let scored = |fit: ModelFit| Scored {
        fit,
        cost,
        estimated: n + nuisance(m, target),
        values: free.iter().map(|f| f.value_in(&fitted)).collect(),
        ses: ses.clone(),
        scene: fitted,
        idx: idx.clone(),
    };
    let rest_band = rest_band(m);
    let v_roll = closed_form::v_roll(fitted.k(), fitted.restitution, fitted.left.v0);
    let derived = Derived::of(&fitted);
    let sol = engine::solve(&fitted, &Span::default());
    let verdict = Verdict::of(&sol, &derived, Some(rest_band));
    let observed = observed_after(m, rest_band, sliding_end(m, &fitted));
    let (regime_observed, regime_seen) = (observed.unwrap_or(Regime::Rest), observed.is_some());
    Ok(scored(ModelFit {
        model: free.iter().map(|f| f.name()).collect::<Vec<_>>().join("+"),
        fitted_to: match target {
            Target::Velocity => "velocities",
            Target::Position => "positions",
        },
        mu: fitted.mu,
        mu_se: se(Free::Mu).unwrap_or(f64::NAN),
        v0: fitted.left.v0,
        v0_se: se(Free::V0),
        restitution: fitted.restitution,
        restitution_se: se(Free::Restitution),
        rolling_resistance: fitted.rolling_resistance,
        rolling_resistance_se: se(Free::RollingResistance),
        rms: raw_rms(&fitted, m, &idx, target, evals),
        points: idx.len(),
        regime_predicted: derived.regime,
        regime_observed,
        regime_seen,
        rest_band,
        v_roll,
        verdict: verdict.text("±"),
        indistinguishable_from_rest: verdict.indistinguishable_from_rest(),
        agrees: regime_seen
            && verdict.agrees_with(regime_observed)
            && !not_identified
                .iter()
                .any(|n| n.parameter == Free::Mu.name()),
        not_identified,
        scatter: data_scatter(m, target == Target::Position),
        every,
        scale,
        lines_disagree: None,
        fits_disagree: None,
        mu_implausible: implausible_mu(fitted.mu, se(Free::Mu)),
    }))
}

/// The free values' standard errors at the optimum `p` (fitted on the frames `idx`,
/// with residuals `r` labelled `labels`), and the values the data do not determine.
fn standard_errors(
    pb: &Problem,
    evals: &mut Evals,
    (p, idx): (&[f64], &[usize]),
    (r, labels): (&[f64], &[super::uncertainty::Label]),
) -> (Vec<Option<f64>>, Vec<NotIdentified>) {
    let (m, target) = (pb.m, pb.target);
    let cost: f64 = r.iter().map(|x| x * x).sum();
    let mut s2 = cost / r.len().saturating_sub(p.len() + nuisance(m, target)).max(1) as f64;
    let j = smooth_jacobian(pb, evals, &At { idx, p, r0: r });
    // Velocities derived from a track share frames: their errors are correlated, by
    // the stencils. Other residuals that go together from frame to frame (a tracker's
    // drift, a velocity some tool smoothed, a model that misses the data's shape) are
    // worth fewer independent points: their variance counts for that many.
    let shared = match (&m.stencils(), target) {
        (Some(st), Target::Velocity) => Some(shared_noise(&j, labels, st)),
        _ => {
            s2 *= r.len() as f64 / effective_points(r, labels).max(1.0);
            None
        }
    };
    uncertainties(&normal_matrix(&j), shared.as_deref(), s2, pb.free, p)
}

/// The RMS of the unweighted residuals: in the data's own units, whatever the weights.
fn raw_rms(fitted: &Scene, m: &Measured, idx: &[usize], target: Target, evals: &mut Evals) -> f64 {
    let raw = labelled_residuals(fitted, m, idx, target, false, evals).0;
    (raw.iter().map(|x| x * x).sum::<f64>() / raw.len().max(1) as f64).sqrt()
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;

    /// A fit of nothing, for tests of what is made from fits.
    pub(crate) fn blank() -> ModelFit {
        ModelFit {
            model: "mu".into(),
            fitted_to: "velocities",
            mu: 0.2,
            mu_se: 0.01,
            v0: 0.5,
            v0_se: None,
            restitution: 1.0,
            restitution_se: None,
            rolling_resistance: 0.0,
            rolling_resistance_se: None,
            rms: 0.01,
            points: 10,
            regime_predicted: Regime::Recollide,
            regime_observed: Regime::Recollide,
            regime_seen: true,
            rest_band: 0.03,
            v_roll: 0.1,
            verdict: String::new(),
            indistinguishable_from_rest: false,
            agrees: true,
            not_identified: Vec::new(),
            scatter: None,
            every: None,
            scale: None,
            lines_disagree: None,
            fits_disagree: None,
            mu_implausible: false,
        }
    }

    /// A position fit and a velocity fit of one track, μ_k and its own ± (1σ), the
    /// scale's part beside it.
    fn pair(p: (f64, f64), v: (f64, f64)) -> (ModelFit, ModelFit) {
        let with = |(mu, se): (f64, f64), to: &'static str| ModelFit {
            mu,
            mu_se: se.hypot(0.025 * mu),
            fitted_to: to,
            scale: Some(ScalePart {
                rel_se: 0.025,
                mu_se_fit: se,
                mu_se_scale: 0.025 * mu,
                v0_se_fit: None,
                v0_se_scale: None,
            }),
            ..blank()
        };
        (with(p, "positions"), with(v, "velocities"))
    }

    #[test]
    fn position_and_velocity_fits_disagree_only_beyond_their_own_pm_and_a_tenth() {
        // Seed 22 of the looks table: 0.131 ± 0.0048 from the positions, 0.162 ±
        // 0.005 from the velocities: 4.5 of their combined own ± and 21 % apart.
        let (p, v) = pair((0.1306, 0.0048), (0.1624, 0.0050));
        assert_eq!(fits_disagree(&p, &v), Some((0.1306, 0.1624)));
        let judged = ModelFit {
            fits_disagree: fits_disagree(&p, &v),
            ..p.clone()
        };
        assert_eq!(judged.agreement(), Agreement::FitsDisagree);
        assert!(!judged.agreement().holds());
        // Apart by 21 % but within twice their ±: no disagreement.
        let (p, v) = pair((0.1306, 0.012), (0.1624, 0.012));
        assert_eq!(fits_disagree(&p, &v), None);
        // The scale's part is common to both fits: a large one does not hide it.
        let (mut p, v) = pair((0.1306, 0.0048), (0.1624, 0.0050));
        p.mu_se = 0.05;
        assert!(fits_disagree(&p, &v).is_some());
        // Exact tracks: far beyond their tiny ± but under a tenth apart (the velocity
        // fit's derivatives round the impact's corners): no disagreement.
        let (p, v) = pair((0.1700, 0.0002), (0.1640, 0.0002));
        assert_eq!(fits_disagree(&p, &v), None);
        // A μ_k not determined by either fit: nothing to compare.
        let (mut p, v) = pair((0.1306, 0.0048), (0.1624, 0.0050));
        p.not_identified.push(NotIdentified {
            parameter: Free::Mu.name(),
            reason: String::new(),
            on_edge_of: None,
        });
        assert_eq!(fits_disagree(&p, &v), None);
    }
}
