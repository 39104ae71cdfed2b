//! Which model the data support ("model no more than a scene needs", for data too):
//! the candidate models — μ_k alone, with e, with c_rr, with both, and each with v0
//! free where the data hold the approach — fitted to the same series and compared
//! by AIC and BIC for least squares, `n ln(RSS/n) + 2k` and `n ln(RSS/n) + k ln n`
//! (RSS weighted by the points' uncertainties where known; k counts every value
//! estimated). The simplest model within 2 of the lowest BIC is the one named: a
//! difference below 2 is not evidence for the larger model.

use serde::Serialize;

use super::least_squares::{Target, residuals, with};
use super::model::{Scored, scored_fit, thinned};
use super::problem::{FitError, Free};
use crate::physics::scene::Scene;
use crate::study::Progress;
use crate::study::measured::series::Measured;

/// A fitted value and its standard error (`None`: the data do not pin it down).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Estimate {
    pub parameter: &'static str,
    pub value: f64,
    pub se: Option<f64>,
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
    pub aic: f64,
    pub bic: f64,
    /// True for the model named as the simplest the data support.
    pub supported: bool,
}

/// Fewest frames before the impact for v0 to be a candidate: the approach must be
/// seen to be measured.
const APPROACH_FRAMES: usize = 3;

/// BIC difference below which a larger model is not preferred.
const BIC_MARGIN: f64 = 2.0;

/// The candidate models' free values for the series `m`.
fn candidates(m: &Measured) -> Vec<Vec<Free>> {
    let base = [
        vec![Free::Mu],
        vec![Free::Mu, Free::Restitution],
        vec![Free::Mu, Free::RollingResistance],
        vec![Free::Mu, Free::Restitution, Free::RollingResistance],
    ];
    let approach = m.t.iter().filter(|&&t| t < 0.0).count() >= APPROACH_FRAMES;
    let with_v0 = base.iter().filter(|_| approach).map(|f| {
        let mut f = f.clone();
        f.insert(1, Free::V0);
        f
    });
    base.iter().cloned().chain(with_v0).collect()
}

/// Fits every candidate model to `m` (positions when it has them, else velocities)
/// and scores it; marks the simplest model the data support. A candidate the data
/// cannot fit (more values than points) is left out.
pub fn compare_models(
    scene: &Scene,
    m: &Measured,
    progress: &dyn Progress,
) -> Result<Vec<Candidate>, FitError> {
    let target = if m.x.is_some() {
        Target::Position
    } else {
        Target::Velocity
    };
    let mut out = Vec::new();
    let mut fitted: Vec<(Vec<Free>, Scored)> = Vec::new();
    for free in candidates(m) {
        // From the best fit of a smaller model inside this one: a larger model
        // should fit at least as well, and a cold start may end in a worse minimum.
        let start = fitted
            .iter()
            .filter(|(f, _)| f.iter().all(|x| free.contains(x)))
            .min_by(|a, b| a.1.cost.total_cmp(&b.1.cost))
            .map_or(*scene, |(f, s)| with(scene, f, &s.values));
        // A model with more values than the data have points is not a candidate.
        match scored_fit(&start, m, &free, target, progress) {
            Ok(s) => fitted.push((free, s)),
            Err(FitError::Data(_)) => continue,
            Err(e) => return Err(e),
        }
    }
    if fitted.is_empty() {
        return Ok(out);
    }
    // Scored on the same frames: each fit leaves out the frames its own impacts
    // straddle, and criteria over different frames are not comparable.
    let thin = thinned(m);
    let data = thin.as_ref().map_or(m, |(t, _)| t);
    let common: Vec<usize> = fitted[0]
        .1
        .idx
        .iter()
        .copied()
        .filter(|i| fitted.iter().all(|(_, s)| s.idx.binary_search(i).is_ok()))
        .collect();
    for (free, s) in &fitted {
        let r = residuals(&s.scene, data, &common, target);
        let cost: f64 = r.iter().map(|x| x * x).sum();
        out.push(candidate(free, s, cost, r.len()));
    }
    let best = out.iter().map(|c| c.bic).fold(f64::INFINITY, f64::min);
    let pick = out
        .iter()
        .enumerate()
        .filter(|(_, c)| c.bic <= best + BIC_MARGIN)
        .min_by(|(_, a), (_, b)| {
            a.parameters
                .len()
                .cmp(&b.parameters.len())
                .then(a.bic.total_cmp(&b.bic))
        })
        .map(|(i, _)| i);
    if let Some(i) = pick {
        out[i].supported = true;
    }
    Ok(out)
}

/// The scores of one fitted candidate with weighted residual sum of squares `cost`
/// over `n` residuals.
fn candidate(free: &[Free], s: &Scored, cost: f64, n: usize) -> Candidate {
    let n = n.max(1) as f64;
    let k = s.estimated as f64;
    // A perfect fit (RSS = 0) would give −∞: the floor keeps every score finite.
    let fit_term = n * (cost / n).max(1e-300).ln();
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
            })
            .collect(),
        rms: s.fit.rms,
        points: s.fit.points,
        aic: fit_term + 2.0 * k,
        bic: fit_term + k * n.ln(),
        supported: false,
    }
}
