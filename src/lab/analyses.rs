//! The lab's slow analyses as jobs: the Methods view's rows, the overlay run, the fits
//! of the measured series and the export, started on worker threads when wanted and
//! restarted when the scene changes (their work is in `work`).

use crate::methods::Method;
use crate::study::compare::Row;
use crate::study::fit::{self, FitError, Fits, Free, ModelFit};

use super::Lab;
use super::jobs::{State, Waker};
use super::work::{ExportResult, Exported, FitWindowError, Overlay, method_rows, overlay};

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
        let Some(m) = self.measured_arc() else {
            // No data (dropped, or a preset without any): a fit of data no longer
            // shown is forgotten, so it is neither drawn nor applied.
            self.fits.cancel();
            self.position_fit.cancel();
            return;
        };
        if !self.want_fits {
            // Leaving the Fit view stops a running fit; a finished one is kept.
            self.fits.stop_running();
            self.position_fit.stop_running();
            return;
        }
        let (scene, window) = (self.scene, self.fit_window);
        let ask = fit::Ask {
            window,
            free: None,
            v0_measured: self
                .settings()
                .from_the_data(crate::settings::params::Key::V0),
        };
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
            fit::fit_all(&scene, &m, &ask, ticket)
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
