//! The lab's slow analyses and their jobs: the Methods view's rows, the overlay run, the
//! fits of the measured series and the export, started on worker threads when wanted
//! and restarted when the scene changes; the job bodies and their level settings.

use crate::methods::{self, Method, Settings, Y};
use crate::physics::scene::{Scene, Span};
use crate::physics::solution::Solution;
use crate::study::compare::{self, Row};
use crate::study::fit::{self, Fits, Free, ModelFit};

use super::Lab;
use super::jobs::{Job, State, Ticket};

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
            ..Settings::default()
        }
    } else {
        Settings {
            step: 10f64.powf(-2.0 - level / 2.0),
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

impl Lab {
    /// (Re)starts every analysis that is wanted and not ready for this scene.
    pub(super) fn restart(&mut self) {
        if self.want_methods && matches!(self.methods, Job::Idle) {
            let (scene, span, sol) = (self.scene, self.span, self.solution.clone());
            self.methods
                .start(move |ticket| method_rows(&scene, &span, &sol, ticket));
        }
        match self.overlay_choice {
            Some((method, level)) => {
                let (scene, span, sol) = (self.scene, self.span, self.solution.clone());
                self.overlay
                    .start(move |ticket| overlay(method, level, &scene, &span, &sol, ticket));
            }
            None => self.overlay.cancel(),
        }
        self.restart_fits();
    }

    fn restart_fits(&mut self) {
        match self.measured().filter(|_| self.want_fits) {
            Some(m) => {
                let (scene, m, window) = (self.scene, m.clone(), self.fit_window);
                if m.x.is_some() {
                    let m = m.clone();
                    self.position_fit.start(move |ticket| {
                        fit::position_fit(&scene, &m, &[Free::Mu], ticket)
                            .map_err(|e| e.to_string())
                    });
                } else {
                    self.position_fit.cancel();
                }
                self.fits.start(move |ticket| {
                    fit::fit_all(&scene, &m, window, &[Free::Mu], ticket).map_err(|e| e.to_string())
                });
            }
            None => {
                self.fits.cancel();
                self.position_fit.cancel();
            }
        }
    }

    /// Takes in finished analyses; true if any arrived (the screen needs a redraw).
    pub fn poll(&mut self) -> bool {
        let a = self.methods.poll();
        let b = self.overlay.poll();
        let c = self.fits.poll();
        let d = self.position_fit.poll();
        let e = self.export.poll();
        a || b || c || d || e
    }

    /// Waits for every running analysis (headless output is then deterministic).
    pub fn wait(&mut self) {
        self.methods.wait();
        self.overlay.wait();
        self.fits.wait();
        self.position_fit.wait();
        self.export.wait();
    }

    /// Writes a file off the key press (a chart's SVG takes milliseconds): `work`
    /// returns the status message, or why nothing was written. A newer export
    /// supersedes a running one.
    pub fn start_export(&mut self, work: impl FnOnce() -> Result<String, String> + Send + 'static) {
        self.export.start(move |_| work());
    }

    /// The finished export's message, once; `None` while it runs or when there is none.
    pub fn take_export(&mut self) -> Option<Result<String, String>> {
        self.export.poll();
        match std::mem::take(&mut self.export) {
            Job::Ready(r) => Some(r),
            other => {
                self.export = other;
                None
            }
        }
    }

    /// True while an analysis runs.
    pub fn busy(&self) -> bool {
        self.methods.is_running()
            || self.overlay.is_running()
            || self.fits.is_running()
            || self.position_fit.is_running()
            || self.export.is_running()
    }

    /// Asks for (or stops asking for) the Methods view's rows.
    pub fn want_methods(&mut self, on: bool) {
        self.want_methods = on;
        if on {
            self.restart_if_idle();
        }
    }

    fn restart_if_idle(&mut self) {
        if self.want_methods && matches!(self.methods, Job::Idle) {
            let (scene, span, sol) = (self.scene, self.span, self.solution.clone());
            self.methods
                .start(move |ticket| method_rows(&scene, &span, &sol, ticket));
        }
    }

    /// The Methods view's rows: every time-stepping method at four levels, untimed.
    pub fn method_rows(&self) -> State<'_, Vec<Row>> {
        self.methods.state()
    }

    /// Draws `method` at `level` over the exact curves (or nothing).
    pub fn set_overlay(&mut self, choice: Option<(Method, u8)>) {
        self.overlay_choice = choice;
        match choice {
            Some((method, level)) => {
                let (scene, span, sol) = (self.scene, self.span, self.solution.clone());
                self.overlay
                    .start(move |ticket| overlay(method, level, &scene, &span, &sol, ticket));
            }
            None => self.overlay.cancel(),
        }
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
        self.restart_fits();
    }

    pub fn fits(&self) -> State<'_, Result<Fits, String>> {
        self.fits.state()
    }

    /// The model fitted directly to a position track (Idle for a velocity file).
    pub fn position_fit(&self) -> State<'_, Result<ModelFit, String>> {
        self.position_fit.state()
    }

    /// Moves one end of the line-fit window by one measured frame.
    pub fn move_fit_window(&mut self, end: bool, later: bool) -> Result<(), String> {
        let Some(m) = self.measured() else {
            return Err("this preset has no measured data to fit".into());
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
            return Err(format!(
                "fit window {from:.2} … {to:.2} s: allowed after the impact (t > 0) and at least 3 frames"
            ));
        }
        self.fit_window = (Some(from), Some(to));
        self.restart_fits();
        Ok(())
    }
}

/// Every time-stepping method at the Methods view's levels, timed for the view's time
/// axis (the screen on the steps and evaluations axes stays the same for the same
/// input: nothing else on it depends on the times).
fn method_rows(scene: &Scene, span: &Span, sol: &Solution, ticket: &Ticket) -> Vec<Row> {
    let runs: Vec<(Method, u8)> = Method::TIME_STEPPING
        .into_iter()
        .flat_map(|m| METHOD_VIEW_LEVELS.map(|l| (m, l)))
        .collect();
    let mut rows = Vec::with_capacity(runs.len());
    for (i, &(method, level)) in runs.iter().enumerate() {
        if ticket.cancelled() {
            break;
        }
        ticket.progress(i, runs.len());
        let settings = level_settings(method, level);
        match compare::measure(method, scene, span, &settings, sol, true, ticket) {
            Ok(row) => rows.push(row),
            // Superseded: the rows are dropped unseen.
            Err(_) => break,
        }
    }
    rows
}

/// One method's run at `level` over the exact curves, thinned, with its row.
fn overlay(
    method: Method,
    level: u8,
    scene: &Scene,
    span: &Span,
    sol: &Solution,
    ticket: &Ticket,
) -> Option<Overlay> {
    let settings = level_settings(method, level);
    let steps = if method.adaptive() {
        1
    } else {
        ((sol.t_end - sol.t_start) / settings.step) as usize
    };
    let mut rec = Thinned {
        points: Vec::new(),
        every: (steps / 4000).max(1),
        seen: 0,
        total: steps,
        ticket,
    };
    let model = methods::Model::of(scene);
    let y0 = methods::start_state(scene, sol.t_start);
    methods::integrate(
        method,
        &model,
        y0,
        sol.t_start,
        sol.t_end,
        &settings,
        &mut rec,
    );
    // A superseded run stops here; its (absent) result is never shown.
    let row = compare::measure(method, scene, span, &settings, sol, false, ticket).ok()?;
    Some(Overlay {
        method,
        settings,
        points: rec.points,
        row,
    })
}
