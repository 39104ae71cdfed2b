//! The observers a comparison's runs report to besides the metrics: the stop watch,
//! the first pass's impact collector, the timed runs' finiteness check; and the
//! windows around impacts that the error maxima leave out.

use crate::methods::{Observer, Y};
use crate::physics::solution::{Event, EventKind};
use crate::study::Progress;

/// Steps between two looks at the stop flag: often enough to stop within
/// milliseconds, rare enough to cost nothing.
const CHECK_EVERY: u32 = 4096;

/// Counts steps and says when to stop because the caller cancelled.
pub(super) struct Watch<'a> {
    progress: &'a dyn Progress,
    count: u32,
}

impl<'a> Watch<'a> {
    pub(super) fn new(progress: &'a dyn Progress) -> Watch<'a> {
        Watch { progress, count: 0 }
    }

    pub(super) fn stop(&mut self) -> bool {
        self.count = self.count.wrapping_add(1);
        self.count.is_multiple_of(CHECK_EVERY) && self.progress.cancelled()
    }
}

/// The first pass's observer: the impacts the method detects, and whoever else
/// watches that pass (`also`: the overlay records its points there).
pub(super) struct Impacts<'a, 'o>(pub Vec<f64>, pub Watch<'a>, pub &'o mut dyn Observer);

impl Observer for Impacts<'_, '_> {
    fn step(&mut self, t: f64, y: &Y) -> bool {
        let also = self.2.step(t, y);
        also && !self.1.stop() && y.iter().all(|v| v.is_finite())
    }

    fn event(&mut self, event: Event) {
        if event.kind == EventKind::Collision {
            self.0.push(event.t);
        }
        self.2.event(event);
    }
}

/// Watches nothing.
pub(super) struct Unwatched;

impl Observer for Unwatched {
    fn step(&mut self, _t: f64, _y: &Y) -> bool {
        true
    }
}

/// Windows around impacts that the error maxima leave out: from each exact impact to
/// the nearest impact the method detected, widened by `slack` on each side, where that
/// pairing is unambiguous (closer than half-way to the neighbouring exact impacts).
/// An impact a method misses gets no window: its jump counts as an error. Also the
/// largest distance from an exact impact to the nearest detected one.
pub(super) fn impact_windows(
    exact: &[f64],
    method: &[f64],
    slack: f64,
) -> (Vec<(f64, f64)>, Option<f64>) {
    let mut windows = Vec::new();
    let mut worst: Option<f64> = None;
    for (k, &a) in exact.iter().enumerate() {
        let before = k.checked_sub(1).map_or(f64::INFINITY, |j| a - exact[j]);
        let after = exact.get(k + 1).map_or(f64::INFINITY, |&n| n - a);
        let reach = 0.5 * before.min(after);
        let i = method.partition_point(|&b| b < a);
        let nearest = [i.checked_sub(1), Some(i)]
            .into_iter()
            .flatten()
            .filter_map(|j| method.get(j))
            .min_by(|x, y| (*x - a).abs().total_cmp(&(*y - a).abs()));
        if let Some(&b) = nearest {
            worst = Some(worst.unwrap_or(0.0).max((a - b).abs()));
            if (a - b).abs() < reach {
                windows.push((a.min(b) - slack, a.max(b) + slack));
            }
        }
    }
    windows.sort_by(|a, b| a.0.total_cmp(&b.0));
    (windows, worst)
}

/// Only checks that the state stays finite: the observer of timed runs.
pub(super) struct Finite<'a>(pub Watch<'a>);

impl Observer for Finite<'_> {
    fn step(&mut self, _t: f64, y: &Y) -> bool {
        !self.0.stop() && y.iter().all(|v| v.is_finite())
    }
}
