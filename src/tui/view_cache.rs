//! What the charts and the map draw from the lab's snapshot that depends on the
//! terminal's size, cached per snapshot and size, never recomputed per frame: the
//! curve samples (about four per pixel column), the energies at them, the pinned run's
//! samples and kinetic energy, the regime grid, and the measured series thinned to
//! the chart's cells. A new snapshot (any edit) or a new size makes them again; a
//! frame that only moves the time (playback, a drag on the chart) reuses them. The
//! screen (`super::screen`) holds one and fills it while it prepares a frame, before
//! anything is drawn; drawing only reads.

use std::rc::Rc;
use std::sync::Arc;

use crate::lab::{Lab, Resolved};
use crate::physics::derived::{Derived, Regime};
use crate::physics::solution::{EnergySplit, Snapshot, Solution};
use crate::tui::plot::{Cells, PlotPoints};

/// One cached view of a snapshot: the snapshot it belongs to (held, so its address
/// cannot be reused by a newer one), the size, the values.
type Cached<K, T> = Option<(Arc<Resolved>, K, Rc<[T]>)>;

/// The screen's per-size caches (UI state: the lab knows no terminal).
#[derive(Clone, Debug, Default)]
pub struct ViewCache {
    samples: Cached<Window, Snapshot>,
    energies: Cached<Window, (f64, EnergySplit)>,
    pinned_samples: Cached<Window, Snapshot>,
    pinned_kinetic: Cached<Window, (f64, f64)>,
    regimes: Cached<(usize, usize), Regime>,
    /// The measured series a chart draws, thinned to its cells: per grid and which
    /// series (bits in the order of `MeasuredPoints::series`).
    marks: Cached<(Cells, u8), Option<PlotPoints>>,
}

/// What a chart's samples are made for: its width in columns and its time range
/// (the span, or the zoomed window of it), s.
pub type Window = (usize, (f64, f64));

/// `cell`'s values if they were made for `now` at `key`, else `make`'s, kept; and
/// whether they were made now.
fn cached<K: PartialEq + Copy, T>(
    cell: &mut Cached<K, T>,
    now: &Arc<Resolved>,
    key: K,
    make: impl FnOnce() -> Rc<[T]>,
) -> (Rc<[T]>, bool) {
    if let Some((of, k, values)) = &*cell
        && Arc::ptr_eq(of, now)
        && *k == key
    {
        return (values.clone(), false);
    }
    let values = make();
    *cell = Some((Arc::clone(now), key, values.clone()));
    (values, true)
}

impl ViewCache {
    /// The snapshot's measured series marked in `drawn` (bit i: the i-th of
    /// `MeasuredPoints::series`), each thinned to one point per cell of `cells`
    /// ([`Cells::thin`]: the same cells marked), once per snapshot and grid; `None`
    /// for a series not drawn. True if they were thinned now.
    pub fn measured_marks(
        &mut self,
        now: &Arc<Resolved>,
        cells: Cells,
        drawn: u8,
    ) -> (Rc<[Option<PlotPoints>]>, bool) {
        cached(&mut self.marks, now, (cells, drawn), || {
            let Some(m) = &now.points else {
                return Rc::from(Vec::new());
            };
            m.series()
                .enumerate()
                .map(|(i, s)| (drawn & 1 << i != 0).then(|| cells.thin(s).into()))
                .collect()
        })
    }

    /// The exact states at the chart's sample times for a plot `columns` wide over
    /// `range`: about four per column plus both sides of every event, once per scene
    /// and window.
    pub fn samples(&mut self, lab: &Lab, (columns, range): Window) -> Rc<[Snapshot]> {
        let now = lab.resolved();
        cached(&mut self.samples, now, (columns, range), || {
            let sol = &now.solution;
            sample_times(sol, range, columns)
                .into_iter()
                .map(|t| sol.at(t))
                .collect()
        })
        .0
    }

    /// The energy split at the same times as [`ViewCache::samples`], once per scene and window.
    pub fn energies(&mut self, lab: &Lab, window: Window) -> Rc<[(f64, EnergySplit)]> {
        let samples = self.samples(lab, window);
        let now = lab.resolved();
        cached(&mut self.energies, now, window, || {
            samples
                .iter()
                .map(|s| (s.t, now.solution.energy_at(s.t)))
                .collect()
        })
        .0
    }

    /// The pinned run's states over the chart's range (its own events kept sharp),
    /// once per scene and window; empty when nothing is pinned.
    pub fn pinned_samples(&mut self, lab: &Lab, (columns, range): Window) -> Rc<[Snapshot]> {
        let Some(p) = &lab.pinned else {
            return Rc::from(Vec::new());
        };
        let now = lab.resolved();
        cached(&mut self.pinned_samples, now, (columns, range), || {
            sample_times(&p.solution, range, columns)
                .into_iter()
                .map(|t| p.solution.at(t))
                .collect()
        })
        .0
    }

    /// The pinned run's kinetic energy at [`ViewCache::pinned_samples`]' times, J, once per
    /// scene and window (the energy chart's A/B curve); empty when nothing is pinned.
    pub fn pinned_kinetic(&mut self, lab: &Lab, window: Window) -> Rc<[(f64, f64)]> {
        let Some(p) = &lab.pinned else {
            return Rc::from(Vec::new());
        };
        let samples = self.pinned_samples(lab, window);
        let now = lab.resolved();
        cached(&mut self.pinned_kinetic, now, window, || {
            samples
                .iter()
                .map(|s| (s.t, p.solution.energy_at(s.t).kinetic()))
                .collect()
        })
        .0
    }

    /// The regime over groove width (0 … 0.99 · 2R, across) and restitution (1 … 0,
    /// down) for these balls, `cols × rows` cells, row by row; once per scene and size.
    pub fn regime_grid(&mut self, lab: &Lab, cols: usize, rows: usize) -> Rc<[Regime]> {
        let now = lab.resolved();
        cached(&mut self.regimes, now, (cols, rows), || {
            let b_max = 2.0 * now.scene.radius * 0.99;
            (0..rows)
                .flat_map(|rr| (0..cols).map(move |c| (rr, c)))
                .map(|(rr, c)| {
                    let mut scene = now.scene;
                    scene.width = b_max * c as f64 / (cols - 1).max(1) as f64;
                    scene.restitution = 1.0 - rr as f64 / (rows - 1).max(1) as f64;
                    Derived::of(&scene).regime
                })
                .collect()
        })
        .0
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
