//! What the views draw from a solution, cached per scene and size: curve samples,
//! energies, the pinned run's samples and changes, the run's story, the regime grid, and the measured
//! ball's ghost (from the series derived for the scene), the extent and the data RMS.

use std::cell::RefCell;
use std::rc::Rc;

use crate::physics::derived::{Derived, Regime};
use crate::physics::scene::Span;
use crate::physics::solution::{EnergySplit, Snapshot, Solution};
use crate::physics::story::{self, After, Verdict};
use crate::settings::params::{Key, PARAMS};
use crate::settings::units::show;
use crate::study::measured::Measured;

use super::Lab;

/// A per-scene cache of what the views draw, keyed by size.
pub(super) type Cached<K, T> = RefCell<Option<(K, Rc<[T]>)>>;

impl Lab {
    /// Where the measured left ball's centre is at `t`: the tracked position of a
    /// position file, else its v_cm integrated from the impact place at t = 0; `None`
    /// outside the series.
    pub fn ghost_x(&self, t: f64) -> Option<f64> {
        self.data.as_ref()?.ghost_x(t)
    }

    /// The measured left ball's spin angle at `t` for its spoke, rad, on the model's
    /// scale (the model's angle at the first impact plus the mark's turn since then);
    /// `None` without a tracked rim mark or outside the series.
    pub fn ghost_angle(&self, t: f64) -> Option<f64> {
        let turn = self.data.as_ref()?.ghost_turn(t)?;
        Some(self.solution.angle_at(0.0)[0] + turn)
    }

    /// The exact states at the chart's sample times for a plot `columns` wide: about
    /// four per column plus both sides of every event, computed once per scene and width.
    pub fn samples(&self, columns: usize) -> Rc<[Snapshot]> {
        if let Some((c, s)) = &*self.samples.borrow()
            && *c == columns
        {
            return s.clone();
        }
        let sol = &self.solution;
        let s: Rc<[Snapshot]> = sample_times(sol, (sol.t_start, sol.t_end), columns)
            .into_iter()
            .map(|t| sol.at(t))
            .collect();
        self.samples.replace(Some((columns, s.clone())));
        s
    }

    /// The energy split at the same times as [`Lab::samples`], once per scene and width.
    pub fn energies(&self, columns: usize) -> Rc<[(f64, EnergySplit)]> {
        if let Some((c, s)) = &*self.energies.borrow()
            && *c == columns
        {
            return s.clone();
        }
        let sol = &self.solution;
        let s: Rc<[(f64, EnergySplit)]> = self
            .samples(columns)
            .iter()
            .map(|s| (s.t, sol.energy_at(s.t)))
            .collect();
        self.energies.replace(Some((columns, s.clone())));
        s
    }

    /// The pinned run's states over the current span (its own events kept sharp), once
    /// per scene and width; empty when nothing is pinned.
    pub fn pinned_samples(&self, columns: usize) -> Rc<[Snapshot]> {
        let Some(p) = &self.pinned else {
            return Rc::from(Vec::new());
        };
        if let Some((c, s)) = &*self.pinned_samples.borrow()
            && *c == columns
        {
            return s.clone();
        }
        let span = (self.solution.t_start, self.solution.t_end);
        let s: Rc<[Snapshot]> = sample_times(&p.solution, span, columns)
            .into_iter()
            .map(|t| p.solution.at(t))
            .collect();
        self.pinned_samples.replace(Some((columns, s.clone())));
        s
    }

    /// The pinned run's kinetic energy at [`Lab::pinned_samples`]' times, J, once per
    /// scene and width (the energy chart's A/B curve); empty when nothing is pinned.
    pub fn pinned_kinetic(&self, columns: usize) -> Rc<[(f64, f64)]> {
        let Some(p) = &self.pinned else {
            return Rc::from(Vec::new());
        };
        if let Some((c, k)) = &*self.pinned_kinetic.borrow()
            && *c == columns
        {
            return k.clone();
        }
        let k: Rc<[(f64, f64)]> = self
            .pinned_samples(columns)
            .iter()
            .map(|s| (s.t, p.solution.energy_at(s.t).kinetic()))
            .collect();
        self.pinned_kinetic.replace(Some((columns, k.clone())));
        k
    }

    /// The pinned parameters that differ from the current ones: `(label, was, now)`
    /// with the table's label and unit: every value of the scene and the span's start
    /// (the shown end follows the runs).
    pub fn pinned_changes(&self) -> &[(&'static str, String, String)] {
        &self.pinned_changes
    }

    /// [`Lab::pinned_changes`] computed, once per scene.
    pub(super) fn changes_from_pinned(&self) -> Vec<(&'static str, String, String)> {
        let Some(p) = &self.pinned else {
            return Vec::new();
        };
        let was_span = Span {
            t_start: p.solution.t_start,
            t_end: Some(p.solution.t_end),
        };
        PARAMS
            .iter()
            .filter(|row| row.is_own() && row.replaces.is_none() && row.key != Key::TEnd)
            .filter_map(|row| {
                let x = (row.get)(&p.scene, &was_span)?;
                let y = (row.get)(&self.scene, &self.span)?;
                let differ = (x - y).abs() > 1e-12 * x.abs().max(y.abs());
                let shown = |v| show(v, row.dim).to_string();
                differ.then(|| (row.label, shown(x), shown(y)))
            })
            .collect()
    }

    /// The regime over groove width (0 … 0.99 · 2R, across) and restitution (1 … 0,
    /// down) for these balls, `cols × rows` cells, row by row; once per scene and size.
    pub fn regime_grid(&self, cols: usize, rows: usize) -> Rc<[Regime]> {
        if let Some((size, g)) = &*self.regimes.borrow()
            && *size == (cols, rows)
        {
            return g.clone();
        }
        let b_max = 2.0 * self.scene.radius * 0.99;
        let g: Rc<[Regime]> = (0..rows)
            .flat_map(|rr| (0..cols).map(move |c| (rr, c)))
            .map(|(rr, c)| {
                let mut scene = self.scene;
                scene.width = b_max * c as f64 / (cols - 1).max(1) as f64;
                scene.restitution = 1.0 - rr as f64 / (rows - 1).max(1) as f64;
                Derived::of(&scene).regime
            })
            .collect();
        self.regimes.replace(Some(((cols, rows), g.clone())));
        g
    }
}

/// Sample times: about four per column, plus both sides of every event so jumps and
/// kinks are drawn where they are.
fn sample_times(sol: &Solution, (t0, t1): (f64, f64), columns: usize) -> Vec<f64> {
    let n = 4 * columns.max(1);
    let dt = (t1 - t0) / n as f64;
    let mut ts: Vec<f64> = (0..=n).map(|i| t0 + i as f64 * dt).collect();
    for e in &sol.events {
        ts.push(e.t);
        ts.push(e.t - 1e-12 * (1.0 + e.t.abs()));
    }
    ts.retain(|t| *t >= t0 && *t <= t1);
    ts.sort_by(f64::total_cmp);
    ts.dedup();
    ts
}

/// The x range (m) the balls cover over the span: positions at its ends and at every
/// event (turning points inside a segment, v = 0, are events).
pub(super) fn extent(sol: &Solution, radius: f64) -> (f64, f64) {
    let times = [sol.t_start, sol.t_end]
        .into_iter()
        .chain(sol.visible_events().map(|e| e.t));
    times.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), t| {
        let s = sol.at(t);
        (lo.min(s.left.x - radius), hi.max(s.right.x + radius))
    })
}

/// RMS residuals of the left ball's v_cm and v_t against `m` (the frame that straddles
/// the impact left out; a v_t that was not measured left out, `None` if none was).
pub(super) fn data_rms(sol: &Solution, m: &Measured) -> (f64, Option<f64>) {
    let (mut sc, mut st, mut n, mut nt) = (0.0, 0.0, 0usize, 0usize);
    for i in (0..m.t.len()).filter(|&i| m.t[i].abs() >= 0.005) {
        let s = sol.at(m.t[i]);
        sc += (s.left.v - m.v_cm[i]).powi(2);
        n += 1;
        if m.v_t[i].is_finite() {
            st += (s.left.u - m.v_t[i]).powi(2);
            nt += 1;
        }
    }
    let rms = |sum: f64, n: usize| (sum / n.max(1) as f64).sqrt();
    (rms(sc, n), (nt > 0).then(|| rms(st, nt)))
}

/// The run's story as the panels tell it, once per scene: the headline, what happens
/// after the first impact, and the verdict against the measured series' rest band.
#[derive(Clone, Debug)]
pub struct Story {
    pub headline: String,
    /// The paper's criterion, where the run does otherwise.
    pub criterion_note: Option<String>,
    pub after: Option<After>,
    pub verdict: Verdict,
}

impl Story {
    pub(super) fn of(sol: &Solution, derived: &Derived, band: Option<f64>) -> Story {
        Story {
            headline: story::headline(sol, derived),
            criterion_note: story::criterion_note(sol, derived),
            after: story::after_first_impact(sol, derived),
            verdict: Verdict::of(sol, derived, band),
        }
    }
}
