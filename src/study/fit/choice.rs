//! Which model the data support ("model no more than a scene needs", for data too):
//! the candidate models — μ_k alone, with e, with c_rr, with both, and each with v0
//! free where the data hold the approach — fitted to the same series and compared
//! by AIC and BIC for least squares, `n' ln(RSS/n) + 2k` and `n' ln(RSS/n) + k ln n'`
//! over n residuals worth n' independent points (RSS weighted by the points'
//! uncertainties where known; k counts every value estimated; n' from how the
//! residuals of neighbouring frames go together, [`effective_points`]). The simplest model within 2 of the lowest BIC is the one named: a
//! difference below 2 is not evidence for the larger model; and never one with a value
//! the data do not determine (on the edge of its range: the data do not support it as
//! a free value).

use serde::Serialize;

use super::approach::APPROACH_FRAMES;
use super::least_squares::with;
use super::model::{ModelFit, Scored, Search, scored_fit, scored_fit_within, thinned};
use super::problem::{Evals, FitError, Free};
use super::residuals::{Target, labelled_residuals, residuals};
use super::uncertainty::{Label, NotIdentified, effective_points};
use crate::physics::scene::Scene;
use crate::study::Progress;
use crate::study::measured::series::Measured;

/// A fitted value and its standard error; or, where the data do not determine it (on
/// the edge of its physical range, or not identifiable), why: then it is "not
/// determined" (JSON: `value` and `se` null, with `reason`), never a number that reads
/// as fitted.
#[derive(Clone, Debug, PartialEq)]
pub struct Estimate {
    pub parameter: &'static str,
    pub value: f64,
    pub se: Option<f64>,
    pub not_determined: Option<NotIdentified>,
}

impl Serialize for Estimate {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        use serde::ser::SerializeStruct;
        let shown = self.not_determined.is_none();
        let mut st = s.serialize_struct("Estimate", 4)?;
        st.serialize_field("parameter", self.parameter)?;
        st.serialize_field("value", &Some(self.value).filter(|_| shown))?;
        st.serialize_field("se", &self.se.filter(|_| shown))?;
        match &self.not_determined {
            Some(n) => st.serialize_field("reason", &n.reason)?,
            None => st.skip_field("reason")?,
        }
        st.end()
    }
}

/// One candidate model fitted.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Candidate {
    /// The free values joined by `+`: `mu`, `mu+restitution`, …
    pub name: String,
    pub parameters: Vec<Estimate>,
    /// RMS residual in the data's units (m/s for velocities, m for positions).
    pub rms: f64,
    pub points: usize,
    /// How many residuals were scored (over the frames common to all candidates; v_cm
    /// and v_t, or x and the mark's arc, count one each).
    pub residuals: usize,
    /// How many independent points the residuals scored are worth: neighbouring
    /// frames' errors are correlated (derived velocities share frames, a tracker's
    /// errors drift), and a series of N frames does not hold N independent points.
    /// The same for every candidate ([`effective_points`]).
    pub effective_points: f64,
    pub aic: f64,
    pub bic: f64,
    /// True for the model named as the simplest the data support.
    pub supported: bool,
    /// False for a model left out of the choice: its verdict disagrees with the data
    /// (μ_k determined) where a determined model inside it agrees, or its c_rr
    /// exceeds its μ_k where a determined model inside it stands ([`weighed`]).
    pub weighed: bool,
    /// Its free values.
    #[serde(skip)]
    pub free: Vec<Free>,
    /// The whole fit these values, ± and RMS are from: the headline and the app show
    /// this one (one fit per model, the same everywhere).
    #[serde(skip)]
    pub fit: Box<ModelFit>,
}

impl Candidate {
    /// True when the data determine every one of its values: only such a model can
    /// be named (a value on the edge of its range is one the data do not support as
    /// free).
    pub fn determined(&self) -> bool {
        self.parameters.iter().all(|e| e.not_determined.is_none())
    }
}

/// The model the data support among `models`: of those weighed (their flag, set by
/// [`mark`]), the simplest
/// whose values are all determined and whose BIC is within [`BIC_MARGIN`] of the
/// lowest (a lower BIC bought with a value on its bound still counts: then no model
/// may be named).
pub(crate) fn supported(models: &[Candidate]) -> Option<usize> {
    let counted = |i: usize| models.get(i).is_none_or(|c| c.weighed);
    let best = models
        .iter()
        .enumerate()
        .filter(|(i, _)| counted(*i))
        .map(|(_, c)| c.bic)
        .fold(f64::INFINITY, f64::min);
    models
        .iter()
        .enumerate()
        .filter(|(i, c)| counted(*i) && c.determined() && c.bic <= best + BIC_MARGIN)
        .min_by(|(_, a), (_, b)| {
            a.parameters
                .len()
                .cmp(&b.parameters.len())
                .then(a.bic.total_cmp(&b.bic))
        })
        .map(|(i, _)| i)
}

/// Which of `models` the choice weighs: all but those whose verdict disagrees with
/// the data (μ_k determined, the regime predicted not the one the data show after the
/// model's own sliding phase) where a determined model inside them (its free values
/// a part of theirs) agrees. Their lower BIC is bought by the values added, which
/// take the model to a motion the data do not show (e freed to 0.85–0.93 where a
/// heavily compressed clip's frames lag the ball near its turn: the small looks 99
/// and 130 then predicted a recollision where the balls had stopped). The simplest
/// model's verdict is never so decided: a model is only ever left out for a smaller
/// one's, and the smaller one agrees by itself. Only the models `witness` passes
/// count as the smaller ones inside (a set `fit --free` asked for beside the usual
/// candidates is none: what a user asks does not change the choice). Left out too: a
/// model whose rolling resistance exceeds its μ_k ([`rolls_harder_than_it_slides`])
/// where a determined model inside it stands, whatever that one's verdict.
fn weighed(models: &[Candidate], witness: &dyn Fn(&Candidate) -> bool) -> Vec<bool> {
    let names = |c: &Candidate| c.parameters.iter().map(|e| e.parameter).collect::<Vec<_>>();
    let inside = |small: &Candidate, large: &Candidate| {
        let large = names(large);
        small.parameters.len() < large.len()
            && small
                .parameters
                .iter()
                .all(|e| large.contains(&e.parameter))
    };
    let disagrees = |c: &Candidate| !c.fit.agrees && c.fit.undetermined(Free::Mu.name()).is_none();
    models
        .iter()
        .map(|c| {
            let regime_left_out = disagrees(c)
                && models
                    .iter()
                    .any(|y| witness(y) && y.fit.agrees && y.determined() && inside(y, c));
            let resistance_left_out = rolls_harder_than_it_slides(c).is_some()
                && models
                    .iter()
                    .any(|y| witness(y) && y.determined() && inside(y, c));
            !(regime_left_out || resistance_left_out)
        })
        .collect()
}

/// The model's fitted rolling resistance and μ_k, `(c_rr, μ_k)`, where the first is the
/// larger: no rolling resistance, since a ball whose rolling is resisted more than
/// friction can hold it rolling slides instead. A fit so buys its BIC with the
/// slowing of frames that are not the ball's (small look 11's first 30 frames:
/// c_rr 0.116 beside μ_k 0.062, where μ_k + v0 alone gave 0.168 for 0.170), and such
/// a model is left out where a determined model inside it stands ([`weighed`]).
pub fn rolls_harder_than_it_slides(c: &Candidate) -> Option<(f64, f64)> {
    let value = |name: &str| {
        c.parameters
            .iter()
            .find(|e| e.parameter == name && e.not_determined.is_none())
            .map(|e| e.value)
    };
    let c_rr = value(Free::RollingResistance.name())?;
    let mu = value(Free::Mu.name())?;
    (c_rr > mu).then_some((c_rr, mu))
}

/// Marks which of `models` are weighed ([`weighed`] by `witness`) and the one the
/// data support ([`supported`]).
pub(crate) fn mark(models: &mut [Candidate], witness: &dyn Fn(&Candidate) -> bool) {
    let counted = weighed(models, witness);
    for (c, w) in models.iter_mut().zip(counted) {
        c.weighed = w;
        c.supported = false;
    }
    if let Some(c) = supported(models).and_then(|i| models.get_mut(i)) {
        c.supported = true;
    }
}

/// BIC difference below which a larger model is not preferred.
const BIC_MARGIN: f64 = 2.0;

/// The candidate models' free values for the series `m`.
/// With `v0_measured` (the scene's v0 was taken from the data, not given) v0 is free
/// in every one: a measured value carries its error into μ_k, a given one does not.
pub(super) fn candidates(m: &Measured, v0_measured: bool) -> Vec<Vec<Free>> {
    let base = [
        vec![Free::Mu],
        vec![Free::Mu, Free::Restitution],
        vec![Free::Mu, Free::RollingResistance],
        vec![Free::Mu, Free::Restitution, Free::RollingResistance],
    ];
    let approach = m.t().iter().filter(|&&t| t < 0.0).count() >= APPROACH_FRAMES;
    let with_v0 = base.iter().filter(|_| approach).map(|f| {
        let mut f = f.clone();
        f.insert(1, Free::V0);
        f
    });
    if v0_measured && approach {
        return with_v0.collect();
    }
    base.iter().cloned().chain(with_v0).collect()
}

/// Fits every candidate model to `m` (positions when it has them, else velocities)
/// and scores it; marks the simplest model the data support. A candidate the data
/// cannot fit (more values than points) is left out. Listed in [`by_bic`]'s order:
/// the one order `fit`, its JSON and the app show them in.
pub fn compare_models(
    scene: &Scene,
    m: &Measured,
    progress: &dyn Progress,
) -> Result<Vec<Candidate>, FitError> {
    compare_within(scene, m, &mut Evals::new(progress))
}

/// [`compare_models`], counting its work in `evals` (the budget of a whole fit).
pub(super) fn compare_within(
    scene: &Scene,
    m: &Measured,
    evals: &mut Evals,
) -> Result<Vec<Candidate>, FitError> {
    let mut models = candidates_within(scene, m, candidates(m, false), evals)?;
    by_bic(&mut models);
    Ok(models)
}

/// Orders `models` by BIC, lowest (best) first; equal BICs the model with fewer
/// values first.
pub fn by_bic(models: &mut [Candidate]) {
    models.sort_by(|a, b| {
        a.bic
            .total_cmp(&b.bic)
            .then(a.parameters.len().cmp(&b.parameters.len()))
    });
}

/// [`compare_models`] over the candidate models `candidates` (each a list of free
/// values; a smaller one inside a larger one first).
pub fn compare_candidates(
    scene: &Scene,
    m: &Measured,
    candidates: Vec<Vec<Free>>,
    progress: &dyn Progress,
) -> Result<Vec<Candidate>, FitError> {
    candidates_within(scene, m, candidates, &mut Evals::new(progress))
}

/// [`compare_candidates`], counting its work in `evals`.
// Indices `k` and `j` run over `0..fitted.len()`, whose length the loops never
// change: each model is refitted in place while the others are read.
#[allow(clippy::indexing_slicing)]
pub(super) fn candidates_within(
    scene: &Scene,
    m: &Measured,
    candidates: Vec<Vec<Free>>,
    evals: &mut Evals,
) -> Result<Vec<Candidate>, FitError> {
    let target = if m.x().is_some() {
        Target::Position
    } else {
        Target::Velocity
    };
    let mut out = Vec::new();
    let mut fitted = first_fits(scene, m, candidates, target, evals)?;
    if fitted.is_empty() {
        return Ok(out);
    }
    // Fitted and scored on the same frames: each fit leaves out the frames its own
    // impacts straddle, and fits or criteria over different frames are not
    // comparable (a model with a value on its edge must give the smaller model's
    // numbers). So every candidate is fitted again on the frames all of them kept,
    // until that set holds still.
    let thin = thinned(m);
    let data = thin.as_ref().map_or(m, |(t, _)| t);
    let mut common = shared_frames(&fitted);
    for _ in 0..3 {
        let all_on_common = fitted.iter().all(|(_, s)| s.idx == common);
        if all_on_common {
            break;
        }
        for k in 0..fitted.len() {
            if fitted[k].1.idx == common {
                continue;
            }
            // From its own fit, a smaller model's refit, or its own values as another
            // model fitted them, whichever fits the common frames best: a larger model
            // must fit them at least as well, and one model fitted from two starts
            // must not land in two minima (one fit per model).
            let free = fitted[k].0.clone();
            let own = fitted[k].1.scene;
            let theirs = fitted.iter().map(|(_, s)| {
                let values: Vec<f64> = free.iter().map(|f| f.value_in(&s.scene)).collect();
                with(&own, &free, &values)
            });
            let start = fitted[..k]
                .iter()
                .filter(|(f, _)| f.iter().all(|x| free.contains(x)))
                .map(|(f, s)| with(&own, f, &s.values))
                .chain(theirs)
                .chain([own])
                .map(|start| (cost_on(&start, data, &common, target, evals), start))
                .min_by(|a, b| a.0.total_cmp(&b.0))
                .map_or(fitted[k].1.scene, |(_, start)| start);
            fitted[k].1 =
                scored_fit_within(&start, m, &free, target, Search::Within(&common), evals)?;
        }
        common = shared_frames(&fitted);
    }
    // Optima carried both ways between nested models until none moves: a larger
    // model from a smaller one's optimum, a smaller one from a larger one's projected
    // down (an exact track at μ_k = 0.18 once gave μ_k + v0 = 0.1966 with 1.6 mm RMS
    // where μ_k + v0 + c_rr found 0.18 with c_rr = 0 and no residual: issue 35).
    for _ in 0..3 {
        let up = nested_no_worse(m, target, &common, &mut fitted, evals)?;
        let down = projected_down(m, target, &common, &mut fitted, evals)?;
        if !(up || down) {
            break;
        }
    }
    let scored: Vec<(Vec<f64>, Vec<Label>)> = fitted
        .iter()
        .map(|(_, s)| labelled_residuals(&s.scene, data, &common, target, true, evals))
        .collect();
    let cost = |r: &[f64]| r.iter().map(|x| x * x).sum::<f64>();
    // The noise's correlation from the best fit's residuals (the least structure a
    // misfit leaves): the same number of independent points for every candidate.
    let n_eff = scored
        .iter()
        .min_by(|a, b| cost(&a.0).total_cmp(&cost(&b.0)))
        .map_or(1.0, |(r, l)| effective_points(r, l));
    for ((free, s), (r, _)) in fitted.iter().zip(&scored) {
        out.push(candidate(free, s, cost(r), r.len(), n_eff));
    }
    mark(&mut out, &|_| true);
    Ok(out)
}

/// Each candidate fitted on its own frames, from its usual start and from the best
/// fit of a smaller model inside it ([`candidates_within`]); one with more values than
/// the data have points is left out.
fn first_fits(
    scene: &Scene,
    m: &Measured,
    candidates: Vec<Vec<Free>>,
    target: Target,
    evals: &mut Evals,
) -> Result<Vec<(Vec<Free>, Scored)>, FitError> {
    // With v0 measured the models without it are no candidates, but μ_k alone at the
    // measured v0 is still a start for every model with v0, which must fit at least
    // as well (an exact 30 frames/s track: μ_k + v0 stopped at 0.1979 with 0.25 mm
    // RMS where μ_k alone at the approach's v0 fitted 0.2000 to 2e-11 m).
    let alone = vec![Free::Mu];
    let held = if !candidates.contains(&alone) && candidates.iter().any(|f| f.contains(&Free::V0)) {
        scored_fit(scene, m, &alone, target, evals)
            .ok()
            .map(|s| (alone, s))
    } else {
        None
    };
    let mut fitted: Vec<(Vec<Free>, Scored)> = Vec::new();
    for free in candidates {
        // From its usual start and from the best fit of a smaller model inside this
        // one, the better of the two: a larger model must fit at least as well, and
        // either start alone may end in a worse minimum (issue 27's trial: from the
        // smaller model's optimum μ_k + v0 + e stopped at e = 1 with 2 mm RMS).
        let nested = fitted
            .iter()
            .chain(&held)
            .filter(|(f, _)| f.iter().all(|x| free.contains(x)))
            .min_by(|a, b| mean(&a.1).total_cmp(&mean(&b.1)))
            .map(|(f, s)| with(scene, f, &s.values));
        // A model with more values than the data have points is not a candidate.
        let s = match scored_fit(scene, m, &free, target, evals) {
            Ok(s) => s,
            Err(FitError::TooFewPoints { .. }) => continue,
            Err(e) => return Err(e),
        };
        let s = match nested {
            Some(start) => {
                let other = scored_fit_within(&start, m, &free, target, Search::From, evals)?;
                if mean(&other) < mean(&s) { other } else { s }
            }
            None => s,
        };
        fitted.push((free, s));
    }
    Ok(fitted)
}

/// Refits, on the frames `common`, every model that fits them worse than a smaller
/// model inside it, from that model's values (its own extra values where the smaller
/// model's scene has them), and keeps the refit where it is better: a model with one
/// more free value must never fit worse than the one without it. True when any
/// model moved.
// Indices `k` and `j` run over `0..fitted.len()`, whose length the loops never
// change: each model is refitted in place while the others are read.
#[allow(clippy::indexing_slicing)]
fn nested_no_worse(
    m: &Measured,
    target: Target,
    common: &[usize],
    fitted: &mut [(Vec<Free>, Scored)],
    evals: &mut Evals,
) -> Result<bool, FitError> {
    let mut moved = false;
    let thin = thinned(m);
    let data = thin.as_ref().map_or(m, |(t, _)| t);
    let mut costs: Vec<f64> = fitted
        .iter()
        .map(|(_, s)| cost_on(&s.scene, data, common, target, evals))
        .collect();
    for k in 0..fitted.len() {
        for j in 0..fitted.len() {
            let (small, large) = (&fitted[j].0, &fitted[k].0);
            if j == k || small.len() >= large.len() || !small.iter().all(|x| large.contains(x)) {
                continue;
            }
            if costs[k] <= costs[j] * (1.0 + 1e-12) {
                continue;
            }
            // From the smaller model's optimum: its scene holds the larger model's
            // extra values where the smaller one keeps them fixed, so the start fits
            // exactly as well as the smaller model, and the refit only improves on it.
            let free = large.clone();
            let start = fitted[j].1.scene;
            let refit = scored_fit_within(&start, m, &free, target, Search::Within(common), evals)?;
            let refit_cost = cost_on(&refit.scene, data, common, target, evals);
            if refit.idx == common && refit_cost < costs[k] {
                fitted[k].1 = refit;
                costs[k] = refit_cost;
                moved = true;
            }
        }
    }
    Ok(moved)
}

/// Refits, on the frames `common`, every model whose optimum fits them worse than a
/// larger model's optimum projected down onto it (the larger model's values of the
/// smaller one's free values, its other values the smaller one's fixed ones: where
/// the larger model found its extra values at their "off" values, e = 1 or
/// c_rr = 0, that is the smaller model's own better optimum), from that projection;
/// keeps the refit where it is better. True when any model moved.
// Indices `k` and `j` run over `0..fitted.len()`, whose length the loops never
// change: each model is refitted in place while the others are read.
#[allow(clippy::indexing_slicing)]
fn projected_down(
    m: &Measured,
    target: Target,
    common: &[usize],
    fitted: &mut [(Vec<Free>, Scored)],
    evals: &mut Evals,
) -> Result<bool, FitError> {
    let thin = thinned(m);
    let data = thin.as_ref().map_or(m, |(t, _)| t);
    let mut moved = false;
    for j in 0..fitted.len() {
        let Some((small, own)) = fitted.get(j).map(|(f, s)| (f.clone(), s.scene)) else {
            continue;
        };
        let mut cost = cost_on(&own, data, common, target, evals);
        let larger: Vec<Scene> = fitted
            .iter()
            .filter(|(f, _)| f.len() > small.len() && small.iter().all(|x| f.contains(x)))
            .map(|(_, s)| {
                let values: Vec<f64> = small.iter().map(|f| f.value_in(&s.scene)).collect();
                with(&own, &small, &values)
            })
            .collect();
        for start in larger {
            evals.next()?;
            if cost_on(&start, data, common, target, evals) >= cost {
                continue;
            }
            let refit =
                scored_fit_within(&start, m, &small, target, Search::Within(common), evals)?;
            let refit_cost = cost_on(&refit.scene, data, common, target, evals);
            if let Some(slot) = fitted
                .get_mut(j)
                .filter(|_| refit.idx == common && refit_cost < cost)
            {
                slot.1 = refit;
                cost = refit_cost;
                moved = true;
            }
        }
    }
    Ok(moved)
}

/// The weighted residual sum of squares of `scene` on `frames` of `data`: what the
/// fits of different models are compared by on the frames they share.
fn cost_on(
    scene: &Scene,
    data: &Measured,
    frames: &[usize],
    target: Target,
    evals: &mut Evals,
) -> f64 {
    let r = residuals(scene, data, frames, target, evals);
    r.iter().map(|x| x * x).sum()
}

/// A fit's weighted residual sum of squares per residual: fits of one model from two
/// starts may keep different frames.
fn mean(s: &Scored) -> f64 {
    s.cost / s.idx.len().max(1) as f64
}

/// The frames (of the thinned series) every fitted candidate used, in order.
fn shared_frames(fitted: &[(Vec<Free>, Scored)]) -> Vec<usize> {
    fitted.first().map_or_else(Vec::new, |(_, first)| {
        first
            .idx
            .iter()
            .copied()
            .filter(|i| fitted.iter().all(|(_, s)| s.idx.binary_search(i).is_ok()))
            .collect()
    })
}

/// The scores of one fitted candidate with weighted residual sum of squares `cost`
/// over `n` residuals worth `n_eff` independent points ([`effective_points`]): the
/// Gaussian log-likelihood of correlated residuals is, for the smooth changes a
/// model's values make, that of `n_eff` independent ones with the same variance,
/// `−2 ln L = n_eff ln(RSS/n)` (+ a constant).
fn candidate(free: &[Free], s: &Scored, cost: f64, n: usize, n_eff: f64) -> Candidate {
    let n = n.max(1) as f64;
    let n_eff = n_eff.clamp(1.0, n);
    let k = s.estimated as f64;
    // A perfect fit (RSS = 0) would give −∞: the floor keeps every score finite.
    let fit_term = n_eff * (cost / n).max(1e-300).ln();
    Candidate {
        name: free.iter().map(|f| f.name()).collect::<Vec<_>>().join("+"),
        parameters: free
            .iter()
            .zip(&s.values)
            .zip(&s.ses)
            .map(|((f, &value), &se)| Estimate {
                parameter: f.name(),
                value,
                se,
                not_determined: s.fit.undetermined(f.name()).cloned(),
            })
            .collect(),
        rms: s.fit.rms,
        points: s.fit.points,
        residuals: n as usize,
        effective_points: n_eff,
        aic: fit_term + 2.0 * k,
        bic: fit_term + k * n_eff.ln(),
        supported: false,
        weighed: true,
        free: free.to_vec(),
        fit: Box::new(s.fit.clone()),
    }
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;

    /// A candidate of `parameters` (each determined or on the edge of its range) at
    /// `bic`, weighed, not supported, its fit a fit of nothing (it agrees); named by
    /// its values joined by `+`.
    pub(crate) fn model(parameters: &[(&'static str, bool)], bic: f64) -> Candidate {
        Candidate {
            name: parameters.iter().map(|p| p.0).collect::<Vec<_>>().join("+"),
            parameters: parameters
                .iter()
                .map(|&(parameter, determined)| Estimate {
                    parameter,
                    value: 1.0,
                    se: determined.then_some(0.1),
                    not_determined: (!determined).then(|| NotIdentified {
                        parameter,
                        reason: "on the edge".into(),
                        on_edge_of: Some("0 ≤ e ≤ 1"),
                    }),
                })
                .collect(),
            rms: 0.0,
            points: 10,
            residuals: 10,
            effective_points: 10.0,
            aic: bic,
            bic,
            supported: false,
            weighed: true,
            free: Vec::new(),
            fit: Box::new(crate::study::fit::model::tests::blank()),
        }
    }

    #[test]
    fn a_model_with_a_value_not_determined_is_never_named() {
        let mu = model(&[("mu", true)], 0.0);
        // e on its edge, 1 lower in BIC: the simplest determined model within 2 is μ.
        let models = [
            mu.clone(),
            model(&[("mu", true), ("restitution", false)], -1.0),
        ];
        assert_eq!(supported(&models), Some(0));
        // The simplest overall has its μ on the edge: the next one is named.
        let models = [
            model(&[("mu", false)], 0.0),
            model(&[("mu", true), ("restitution", true)], 1.0),
        ];
        assert_eq!(supported(&models), Some(1));
        // The lowest BIC, by far, is bought with a value on its edge: none is named
        // (naming μ alone, 10 worse, would be no more honest).
        let models = [mu, model(&[("mu", true), ("restitution", false)], -10.0)];
        assert_eq!(supported(&models), None);
    }

    /// The index of the model named among `models`, each weighed as `fit` weighs it.
    fn chosen(models: &[Candidate]) -> Option<usize> {
        let mut models = models.to_vec();
        mark(&mut models, &|_| true);
        models.iter().position(|c| c.supported)
    }

    /// With `agrees` (its predicted regime the observed one) set as given.
    fn agreeing(mut c: Candidate, agrees: bool) -> Candidate {
        c.fit.agrees = agrees;
        c
    }

    #[test]
    fn a_model_predicting_another_regime_than_a_smaller_one_inside_it_is_not_weighed() {
        let mu = |agrees| agreeing(model(&[("mu", true)], 0.0), agrees);
        let mu_e =
            |bic, agrees| agreeing(model(&[("mu", true), ("restitution", true)], bic), agrees);
        // μ + e 10 lower in BIC but predicting a regime not seen, μ alone inside it
        // predicting that one: μ alone is named (small looks 99, 130: e 0.85–0.92
        // where the balls were seen to stop).
        let models = [mu(true), mu_e(-10.0, false)];
        assert_eq!(weighed(&models, &|_| true), [true, false]);
        assert_eq!(chosen(&models), Some(0));
        // Both agree, or neither: the BIC decides as before.
        assert_eq!(chosen(&[mu(true), mu_e(-10.0, true)]), Some(1));
        assert_eq!(chosen(&[mu(true), mu_e(-1.0, true)]), Some(0));
        assert_eq!(chosen(&[mu(false), mu_e(-10.0, false)]), Some(1));
        // Only the larger agrees: the smaller is weighed still (nothing inside it
        // agrees), and named where the BIC says so: its DISAGREES stands.
        let models = [mu(false), mu_e(-1.0, true)];
        assert_eq!(weighed(&models, &|_| true), [true, true]);
        assert_eq!(chosen(&models), Some(0));
        assert_eq!(chosen(&[mu(false), mu_e(5.0, true)]), Some(0));
        // A model beside, not inside: μ + c_rr agreeing leaves μ + e weighed.
        let mu_c = agreeing(
            model(&[("mu", true), ("rolling_resistance", true)], 0.0),
            true,
        );
        let models = [mu(false), mu_c, mu_e(-10.0, false)];
        assert_eq!(weighed(&models, &|_| true), [true, true, true]);
        // The smaller one inside has a value not determined: it leaves nothing out.
        let undetermined = agreeing(model(&[("mu", false)], 0.0), true);
        assert_eq!(
            weighed(&[undetermined, mu_e(-10.0, false)], &|_| true),
            [true, true]
        );
        // A model whose μ_k is not determined has no verdict: never left out for one.
        let mut no_mu = mu_e(-10.0, false);
        if let Some(e) = no_mu.parameters.first_mut() {
            e.not_determined = Some(NotIdentified {
                parameter: "mu",
                reason: "on the edge".into(),
                on_edge_of: None,
            });
        }
        no_mu.fit.not_identified = no_mu.parameters[0].not_determined.iter().cloned().collect();
        assert_eq!(weighed(&[mu(true), no_mu], &|_| true), [true, true]);
        // A smaller model that is no witness (a set `fit --free` asked for) leaves
        // nothing out.
        let models = [mu(true), mu_e(-10.0, false)];
        assert_eq!(weighed(&models, &|c| c.parameters.len() > 1), [true, true]);
    }

    /// μ_k + c_rr at `bic` with those values (both determined), its verdict as given.
    fn resisted(mu: f64, c_rr: f64, bic: f64, agrees: bool) -> Candidate {
        let mut c = agreeing(
            model(&[("mu", true), ("rolling_resistance", true)], bic),
            agrees,
        );
        for (e, v) in c.parameters.iter_mut().zip([mu, c_rr]) {
            e.value = v;
        }
        c
    }

    #[test]
    fn a_model_rolling_harder_than_it_slides_is_not_weighed() {
        // Small look 11's first 30 frames: c_rr 0.116 beside μ_k 0.062, 10 lower in
        // BIC than μ_k alone, neither seeing the regime: μ_k alone is named.
        let mu = |agrees| agreeing(model(&[("mu", true)], 0.0), agrees);
        let models = [mu(false), resisted(0.062, 0.116, -10.0, false)];
        assert_eq!(weighed(&models, &|_| true), [true, false]);
        assert_eq!(chosen(&models), Some(0));
        assert_eq!(
            rolls_harder_than_it_slides(&models[1]),
            Some((0.116, 0.062))
        );
        // Whatever the verdicts: it agreeing changes nothing.
        let models = [mu(true), resisted(0.062, 0.116, -10.0, true)];
        assert_eq!(weighed(&models, &|_| true), [true, false]);
        // A rolling resistance under μ_k is weighed as the BIC says (0.014 beside
        // 0.44: small look 130's), and so is one equal to it.
        let models = [mu(false), resisted(0.44, 0.014, -10.0, false)];
        assert_eq!(weighed(&models, &|_| true), [true, true]);
        assert_eq!(chosen(&models), Some(1));
        assert!(rolls_harder_than_it_slides(&resisted(0.1, 0.1, 0.0, true)).is_none());
        // c_rr not determined: no value to judge (the model is never named anyway).
        let mut edge = resisted(0.062, 0.116, -10.0, false);
        edge.parameters[1].not_determined = Some(NotIdentified {
            parameter: "rolling_resistance",
            reason: "on the edge".into(),
            on_edge_of: None,
        });
        assert!(rolls_harder_than_it_slides(&edge).is_none());
        // No determined model inside it, or none that is a witness: it stays.
        let undetermined = agreeing(model(&[("mu", false)], 0.0), true);
        let models = [undetermined, resisted(0.062, 0.116, -10.0, false)];
        assert_eq!(weighed(&models, &|_| true), [true, true]);
        let models = [mu(true), resisted(0.062, 0.116, -10.0, false)];
        assert_eq!(weighed(&models, &|c| c.parameters.len() > 1), [true, true]);
    }

    #[test]
    fn a_value_not_determined_is_null_in_json_with_its_reason() {
        let c = model(&[("mu", true), ("restitution", false)], 0.0);
        let j = serde_json::to_value(&c).unwrap();
        let e = &j["parameters"][1];
        assert!(e["value"].is_null() && e["se"].is_null(), "{e}");
        assert_eq!(e["reason"], "on the edge");
        let mu = &j["parameters"][0];
        assert_eq!(mu["value"], 1.0);
        assert!(mu.get("reason").is_none(), "{mu}");
    }
}
