//! How long a run takes: the minimum and median of repeated runs.

use std::time::Instant;

use crate::methods::{self, Method, Model, Settings};
use crate::physics::scene::{Scene, Span};
use crate::study::{Cancelled, Progress};

use super::observers::{Finite, Watch};
use super::reference::Reference;
use super::row::{Row, RunStatus};

/// A run at least this long (s) is its own warm-up: its first timing counts.
const NO_WARM_UP: f64 = 0.01;

/// Minimum and median of at least three timings of `f`, more for quick runs (up to
/// 15 within 50 ms). A quick run's first call is an untimed warm-up (caches, the
/// allocator); a run of [`NO_WARM_UP`] or more is timed from its first call, where
/// such start-up costs are lost in the run.
pub fn time<T>(mut f: impl FnMut() -> T) -> (f64, f64) {
    let mut times = Vec::new();
    let first = Instant::now();
    std::hint::black_box(f());
    let first = first.elapsed().as_secs_f64();
    if first >= NO_WARM_UP {
        times.push(first);
    }
    let budget = Instant::now();
    while times.len() < 3 || (times.len() < 15 && budget.elapsed().as_secs_f64() < 0.05) {
        let start = Instant::now();
        std::hint::black_box(f());
        times.push(start.elapsed().as_secs_f64());
    }
    times.sort_by(f64::total_cmp);
    (times[0], times[times.len() / 2])
}

/// The minimum and median time of the run `row` measured (see [`time`]); zero for a
/// run refused before its first step.
pub fn timing(
    method: Method,
    scene: &Scene,
    settings: &Settings,
    reference: &Reference,
    row: &Row,
    progress: &dyn Progress,
) -> Result<(f64, f64), Cancelled> {
    let exact = &reference.exact;
    let times = if method == Method::Exact {
        let span = Span {
            t_start: exact.t_start,
            t_end: Some(exact.t_end),
        };
        time(|| methods::exact_solution(scene, &span))
    } else if row.status == RunStatus::Stalled && row.steps == 0 {
        (0.0, 0.0)
    } else {
        let model = Model::of(scene);
        let run = reference.run(&model, settings);
        time(|| method.integrate(&run, &mut Finite(Watch::new(progress))))
    };
    if progress.cancelled() {
        return Err(Cancelled);
    }
    Ok(times)
}
