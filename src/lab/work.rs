//! The work of the lab's slow analyses, apart from the lab: every method's rows for
//! the Methods view, one method's run over the exact curves (the overlay) at a level
//! and the levels themselves, and what a fit-window move or an export gives back.

use crate::methods::{self, Method, Stepping, Y};
use crate::physics::scene::{Scene, Span};
use crate::study::Progress;
use crate::study::compare::{self, Row};

use super::jobs::Ticket;

/// Why the line fit's window cannot move.
#[derive(Clone, Copy, Debug, PartialEq, thiserror::Error)]
pub enum FitWindowError {
    #[error("this preset has no measured data to fit")]
    NoData,
    /// The window `from … to` (s) it would become.
    #[error(
        "fit window {from:.2} … {to:.2} s: allowed after the impact (t > 0) and at least 3 frames"
    )]
    Refused { from: f64, to: f64 },
}

/// A file an export wrote: where, and what it holds ("the chart", "800 samples every
/// 10 ms").
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Exported {
    pub path: std::path::PathBuf,
    pub what: String,
}

/// What an export job reports: the file, or why nothing was written (the edge's own
/// error, kept whole; shared, as a finished job's result is read by reference).
pub type ExportResult = Result<Exported, std::sync::Arc<dyn std::error::Error + Send + Sync>>;

/// Steps of the overlay and the Methods view: 10 ms … 10 µs (fixed-step methods),
/// tolerances 1e-2 … 1e-8 (rk45).
pub const OVERLAY_LEVELS: u8 = 7;

/// The settings of `method` at `level`.
pub fn level_settings(method: Method, level: u8) -> Stepping {
    let level = f64::from(level.min(OVERLAY_LEVELS - 1));
    if method.adaptive() {
        Stepping {
            tolerance: 10f64.powf(-2.0 - level),
            step: 1e-3,
            max_steps: compare::STEP_BUDGET,
            ..Stepping::default()
        }
    } else {
        Stepping {
            step: 10f64.powf(-2.0 - level / 2.0),
            max_steps: compare::STEP_BUDGET,
            ..Stepping::default()
        }
    }
}

/// The levels the Methods view runs every method at.
pub const METHOD_VIEW_LEVELS: [u8; 4] = [0, 2, 4, 6];

/// A time-stepping run drawn over the exact curves.
#[derive(Clone, Debug)]
pub struct Overlay {
    pub method: Method,
    pub settings: Stepping,
    /// Its steps, thinned to a few thousand points.
    pub points: Vec<(f64, Y)>,
    pub row: Row,
}

/// Records a run's steps, keeping at most about `limit` of them; stops the run when
/// the job is cancelled.
struct Thinned<'a> {
    points: Vec<(f64, Y)>,
    every: usize,
    seen: usize,
    total: usize,
    ticket: &'a Ticket,
}

impl methods::Observer for Thinned<'_> {
    fn step(&mut self, t: f64, y: &Y) -> bool {
        if self.seen.is_multiple_of(self.every) {
            self.points.push((t, *y));
            self.ticket.progress(self.seen, self.total);
        }
        self.seen += 1;
        y.iter().all(|v| v.is_finite()) && !self.ticket.cancelled()
    }
}

/// Every time-stepping method at the Methods view's levels over the comparison's
/// stretch (the span, cut at [`compare::WINDOW`]: the finest level, 10 µs, takes at
/// most 200,000 steps), timed if `timed` (for the view's time axis; nothing else on
/// the screen depends on the times, so it stays the same for the same input).
pub(super) fn method_rows(scene: &Scene, span: &Span, timed: bool, ticket: &Ticket) -> Vec<Row> {
    let runs: Vec<(Method, Stepping)> = Method::TIME_STEPPING
        .into_iter()
        .flat_map(|m| METHOD_VIEW_LEVELS.map(|l| (m, level_settings(m, l))))
        .collect();
    let reference = compare::Reference::new(scene, span);
    // Superseded: the rows are dropped unseen.
    compare::measure_all(scene, &reference, &runs, timed, &Counted(ticket)).unwrap_or_default()
}

/// The job's progress from a study's ticks.
struct Counted<'a>(&'a Ticket);

impl Progress for Counted<'_> {
    fn tick(&self, done: u64, total: u64) {
        self.0.progress(done as usize, total as usize);
    }
    fn cancelled(&self) -> bool {
        self.0.cancelled()
    }
}

/// One method's run at `level` over the exact curves (the comparison's stretch: the
/// span, cut at [`compare::WINDOW`]), thinned, with its row.
pub(super) fn overlay(
    method: Method,
    level: u8,
    scene: &Scene,
    span: &Span,
    ticket: &Ticket,
) -> Option<Overlay> {
    let settings = level_settings(method, level);
    let reference = compare::Reference::new(scene, span);
    let exact = &reference.exact;
    let steps = if method.adaptive() {
        1
    } else {
        ((exact.t_end - exact.t_start) / settings.step) as usize
    };
    let mut rec = Thinned {
        points: Vec::new(),
        every: (steps / 4000).max(1),
        seen: 0,
        total: steps,
        ticket,
    };
    // The run's points are recorded in the measuring run's first pass: one run.
    let row =
        compare::measure_observed(method, scene, &settings, &reference, ticket, &mut rec).ok()?;
    Some(Overlay {
        method,
        settings,
        points: rec.points,
        row,
    })
}
