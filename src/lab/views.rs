//! What the views draw from a solution, cached per scene and size: curve samples,
//! energies, the pinned run's samples and kinetic energy, the regime grid.

use std::cell::RefCell;
use std::rc::Rc;

use crate::physics::derived::{Derived, Regime};
use crate::physics::solution::{EnergySplit, Snapshot, Solution};

use super::Lab;

/// A per-scene cache of what the views draw, keyed by size.
pub(super) type Cached<K, T> = RefCell<Option<(K, Rc<[T]>)>>;

impl Lab {
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
