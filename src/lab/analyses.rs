//! The lab's slow analyses of a snapshot, as work a job runs (the Methods rows, the
//! overlay run, the fits of the measured series), and the fit window's rule. The lab
//! holds no job and knows no view: whoever shows an analysis asks for it on its own
//! [`super::jobs::JobSet`], keyed by [`super::Lab::generation`], and drops a result made
//! for an earlier one (their work is in `work`).

use std::sync::Arc;

use crate::methods::Method;
use crate::study::compare::Row;
use crate::study::fit::{self, FitError, Fits};
use crate::study::measured::Measured;

use super::jobs::Ticket;
use super::work::{self, FitWindowError, Overlay};
use super::{FitWindow, Resolved};

/// The work of one analysis: what a job runs on a worker.
pub trait JobFn<T>: FnOnce(&Ticket) -> T + Send + 'static {}
impl<T, F: FnOnce(&Ticket) -> T + Send + 'static> JobFn<T> for F {}

/// Every time-stepping method at the Methods view's levels, timed if `timed` (else
/// their times are 0).
pub fn method_rows(now: &Resolved, timed: bool) -> impl JobFn<Vec<Row>> {
    let (scene, span) = (now.scene, now.span);
    move |ticket: &Ticket| work::method_rows(&scene, &span, timed, ticket)
}

/// `method` at `level` over the exact curves (`None`: stopped before it finished).
pub fn overlay(now: &Resolved, method: Method, level: u8) -> impl JobFn<Option<Overlay>> {
    let (scene, span) = (now.scene, now.span);
    move |ticket: &Ticket| work::overlay(method, level, &scene, &span, ticket)
}

/// The measured series shown, shared (a job takes it without copying the series).
fn measured(now: &Resolved) -> Option<Arc<Measured>> {
    now.data.as_ref().map(|d| Arc::clone(&d.measured))
}

/// The fits of the measured series in `window` (the model the data support as the
/// headline; v0 free in every model when the data gave it); `None` without data.
pub fn fits(now: &Resolved, window: FitWindow) -> Option<impl JobFn<Result<Fits, FitError>>> {
    let (scene, m) = (now.scene, measured(now)?);
    let ask = fit::Ask {
        window,
        free: None,
        v0_measured: now.v0_measured,
    };
    Some(move |ticket: &Ticket| fit::fit_all(&scene, &m, &ask, ticket))
}

/// The line-fit window after moving one end (`end`, else the start) by one measured
/// frame (`later`, else earlier), from the window the fit used (`fitted`, once it is
/// there) or else the one asked for (`window`, the sliding phase where unset).
pub fn moved_fit_window(
    now: &Resolved,
    window: FitWindow,
    fitted: Option<(f64, f64)>,
    end: bool,
    later: bool,
) -> Result<FitWindow, FitWindowError> {
    let Some(m) = now.measured() else {
        return Err(FitWindowError::NoData);
    };
    let current = fitted.unwrap_or_else(|| {
        let auto = fit::sliding_window(m).unwrap_or((0.0, 0.0));
        (window.0.unwrap_or(auto.0), window.1.unwrap_or(auto.1))
    });
    let here = if end { current.1 } else { current.0 };
    let i = m
        .t()
        .iter()
        .position(|&t| (t - here).abs() < 1e-9)
        .unwrap_or(0);
    let j = if later {
        (i + 1).min(m.t().len() - 1)
    } else {
        i.saturating_sub(1)
    };
    let t = m.t()[j];
    // The window stays after the impact (the sliding phase starts there) and holds
    // at least three frames (a line needs them); a move past either is refused.
    let (from, to) = if end { (current.0, t) } else { (t, current.1) };
    let frames = m
        .t()
        .iter()
        .filter(|&&x| x >= from - 1e-12 && x <= to + 1e-12)
        .count();
    if from <= 0.0 || frames < 3 {
        return Err(FitWindowError::Refused { from, to });
    }
    Ok((Some(from), Some(to)))
}
