//! The lab's slow analyses and their jobs: the Methods view's rows, the overlay run, the
//! fits of the measured series and the export, started on worker threads when wanted
//! and restarted when the scene changes; the job bodies and their level settings.

use crate::methods::{self, Method, Settings, Y};
use crate::physics::scene::{Scene, Span};
use crate::study::Progress;
use crate::study::compare::{self, Row};
use crate::study::fit::{self, FitError, Fits, Free, ModelFit};

use super::Lab;
use super::jobs::{State, Ticket, Waker};

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
pub fn level_settings(method: Method, level: u8) -> Settings {
    let level = f64::from(level.min(OVERLAY_LEVELS - 1));
    if method.adaptive() {
        Settings {
            tolerance: 10f64.powf(-2.0 - level),
            step: 1e-3,
            max_steps: compare::STEP_BUDGET,
            ..Settings::default()
        }
    } else {
        Settings {
            step: 10f64.powf(-2.0 - level / 2.0),
            max_steps: compare::STEP_BUDGET,
            ..Settings::default()
        }
    }
}

/// The levels the Methods view runs every method at.
pub const METHOD_VIEW_LEVELS: [u8; 4] = [0, 2, 4, 6];

/// A time-stepping run drawn over the exact curves.
#[derive(Clone, Debug)]
pub struct Overlay {
    pub method: Method,
    pub settings: Settings,
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

/// The scene a job belongs to: it counts up with every new solve, so a request made
/// for an earlier scene never matches a newer one.
pub(super) type Generation = u64;

impl Lab {
    /// Requests every analysis that is wanted for this scene (a request already made
    /// for it runs on; one made for an earlier scene is superseded).
    pub(super) fn restart(&mut self) {
        self.request_methods();
        self.request_overlay();
        self.request_fits();
    }

    fn request_methods(&mut self) {
        if !self.want_methods {
            return;
        }
        // Timed rows serve every axis: going back to steps keeps the scene's timed rows.
        let timed = self.want_method_times || self.methods.key() == Some(&(self.generation, true));
        let (scene, span) = (self.scene, self.span);
        self.methods
            .request(&self.jobs, (self.generation, timed), move |ticket| {
                method_rows(&scene, &span, timed, ticket)
            });
    }

    fn request_overlay(&mut self) {
        let Some((method, level)) = self.overlay_choice else {
            self.overlay.cancel();
            return;
        };
        let (scene, span) = (self.scene, self.span);
        let key = (self.generation, method, level);
        self.overlay.request(&self.jobs, key, move |ticket| {
            overlay(method, level, &scene, &span, ticket)
        });
    }

    fn request_fits(&mut self) {
        let Some(m) = self.measured_arc().filter(|_| self.want_fits) else {
            // Leaving the Fit view stops a running fit; a finished one is kept.
            self.fits.stop_running();
            self.position_fit.stop_running();
            return;
        };
        let (scene, window) = (self.scene, self.fit_window);
        if m.x.is_some() {
            let m = m.clone();
            self.position_fit
                .request(&self.jobs, self.generation, move |ticket| {
                    fit::position_fit(&scene, &m, &[Free::Mu], ticket)
                });
        } else {
            self.position_fit.cancel();
        }
        let key = (self.generation, window);
        self.fits.request(&self.jobs, key, move |ticket| {
            fit::fit_all(&scene, &m, window, &[Free::Mu], ticket)
        });
    }

    /// Waits for every queued and running analysis (headless output is then
    /// deterministic).
    pub fn wait(&self) {
        self.jobs.wait();
    }

    /// True while an analysis is queued or runs.
    pub fn busy(&self) -> bool {
        self.jobs.busy()
    }

    /// Whom a finished analysis wakes (the app's event loop).
    pub fn set_waker(&self, waker: Waker) {
        self.jobs.set_waker(waker);
    }

    /// How many analyses have run in this lab (work counted: a repeated request runs
    /// none, a superseded one that had not started none).
    pub fn runs(&self) -> usize {
        self.jobs.runs()
    }

    /// Writes a file off the key press (a chart's SVG takes milliseconds): `work`
    /// returns the file written, or why nothing was written. A newer export
    /// supersedes a running one.
    pub fn start_export<E: std::error::Error + Send + Sync + 'static>(
        &mut self,
        work: impl FnOnce() -> Result<Exported, E> + Send + 'static,
    ) {
        self.exports += 1;
        self.export.request(&self.jobs, self.exports, move |_| {
            work().map_err(|e| std::sync::Arc::new(e) as _)
        });
    }

    /// The finished export's result, once; `None` while it runs or when there is none.
    pub fn take_export(&mut self) -> Option<ExportResult> {
        self.export.take()
    }

    /// Asks for (or stops asking for) the Methods view's rows.
    pub fn want_methods(&mut self, on: bool) {
        self.want_methods = on;
        if !on {
            // Leaving the Methods view stops its running job; finished rows are kept.
            self.methods.stop_running();
        }
        self.request_methods();
    }

    /// Asks for the Methods view's rows timed (for its time axis) or not: the timing
    /// runs cost more than the accuracy runs, and only the time axis shows them.
    pub fn want_method_times(&mut self, on: bool) {
        self.want_method_times = on;
        self.request_methods();
    }

    /// The Methods view's rows: every time-stepping method at four levels, timed only
    /// if [`Lab::want_method_times`] asked for it (else their times are 0).
    pub fn method_rows(&self) -> State<'_, Vec<Row>> {
        self.methods.state()
    }

    /// Draws `method` at `level` over the exact curves (or nothing).
    pub fn set_overlay(&mut self, choice: Option<(Method, u8)>) {
        self.overlay_choice = choice;
        self.request_overlay();
    }

    pub fn overlay_choice(&self) -> Option<(Method, u8)> {
        self.overlay_choice
    }

    pub fn overlay(&self) -> State<'_, Overlay> {
        match self.overlay.state() {
            State::Ready(Some(o)) => State::Ready(o),
            State::Ready(None) | State::Idle => State::Idle,
            State::Computing { done, total } => State::Computing { done, total },
        }
    }

    /// Asks for (or stops asking for) the fits of the measured series.
    pub fn want_fits(&mut self, on: bool) {
        self.want_fits = on;
        self.request_fits();
    }

    pub fn fits(&self) -> State<'_, Result<Fits, FitError>> {
        self.fits.state()
    }

    /// The model fitted directly to a position track (Idle for a velocity file).
    pub fn position_fit(&self) -> State<'_, Result<ModelFit, FitError>> {
        self.position_fit.state()
    }

    /// Moves one end of the line-fit window by one measured frame.
    pub fn move_fit_window(&mut self, end: bool, later: bool) -> Result<(), FitWindowError> {
        let Some(m) = self.measured() else {
            return Err(FitWindowError::NoData);
        };
        let current = match self.fits.ready() {
            Some(Ok(f)) => (f.line_fit.from, f.line_fit.to),
            _ => {
                let auto = fit::sliding_window(m).unwrap_or((0.0, 0.0));
                (
                    self.fit_window.0.unwrap_or(auto.0),
                    self.fit_window.1.unwrap_or(auto.1),
                )
            }
        };
        let here = if end { current.1 } else { current.0 };
        let i =
            m.t.iter()
                .position(|&t| (t - here).abs() < 1e-9)
                .unwrap_or(0);
        let j = if later {
            (i + 1).min(m.t.len() - 1)
        } else {
            i.saturating_sub(1)
        };
        let t = m.t[j];
        // The window stays after the impact (the sliding phase starts there) and holds
        // at least three frames (a line needs them); a move past either is refused.
        let (from, to) = if end { (current.0, t) } else { (t, current.1) };
        let frames =
            m.t.iter()
                .filter(|&&x| x >= from - 1e-12 && x <= to + 1e-12)
                .count();
        if from <= 0.0 || frames < 3 {
            return Err(FitWindowError::Refused { from, to });
        }
        self.fit_window = (Some(from), Some(to));
        self.request_fits();
        Ok(())
    }
}

/// Every time-stepping method at the Methods view's levels over the comparison's
/// stretch (the span, cut at [`compare::WINDOW`]: the finest level, 10 µs, takes at
/// most 200,000 steps), timed if `timed` (for the view's time axis; nothing else on
/// the screen depends on the times, so it stays the same for the same input).
fn method_rows(scene: &Scene, span: &Span, timed: bool, ticket: &Ticket) -> Vec<Row> {
    let runs: Vec<(Method, Settings)> = Method::TIME_STEPPING
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
fn overlay(
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
