//! The one progress helper of long commands: a bar (or a counter) on stderr, only
//! when stderr is a terminal (scripts and pipes see nothing), and the stop request of
//! a signal (see `signals`) that the analysis notices within milliseconds, after which
//! nothing is written (exit 130).

use std::io::IsTerminal;
use std::sync::atomic::{AtomicBool, Ordering};

use indicatif::{ProgressBar, ProgressStyle};

use crate::study::Progress;

/// A command's progress: a bar (or, with no total known, a counter) on stderr, and
/// the stop flag.
pub(crate) struct Bar<'a> {
    bar: Option<ProgressBar>,
    stop: &'a AtomicBool,
}

impl Bar<'static> {
    /// `what` names the unit counted (e.g. "runs"); `show` is false for work that is
    /// over before a bar would be read. Arms the stop signals for this run.
    pub(crate) fn new(what: &'static str, show: bool) -> Bar<'static> {
        Bar::with_stop(what, show, crate::signals::arm())
    }

    /// A counter for work whose total is not known ahead. Arms the stop signals.
    pub(crate) fn counter(what: &'static str, show: bool) -> Bar<'static> {
        let template = format!("{{spinner}} {{pos}} {what}, {{elapsed}}");
        let stop = crate::signals::arm();
        Bar::styled(show, ProgressBar::new_spinner(), &template, stop)
    }
}

impl<'a> Bar<'a> {
    /// [`Bar::new`] with the caller's stop flag (the signals left as they are).
    pub(crate) fn with_stop(what: &'static str, show: bool, stop: &'a AtomicBool) -> Bar<'a> {
        let template = format!("{{bar:40}} {{pos}}/{{len}} {what}, {{eta}} left");
        Bar::styled(show, ProgressBar::new(0), &template, stop)
    }

    fn styled(show: bool, bar: ProgressBar, template: &str, stop: &'a AtomicBool) -> Bar<'a> {
        let bar = (show && std::io::stderr().is_terminal()).then(|| {
            bar.set_style(ProgressStyle::with_template(template).expect("a valid template"));
            bar
        });
        Bar { bar, stop }
    }

    /// One more unit done (work that counts as it goes, on any thread).
    pub(crate) fn inc(&self) {
        if let Some(b) = &self.bar {
            b.inc(1);
        }
    }

    /// The total, when it is known before the work.
    pub(crate) fn set_total(&self, total: u64) {
        if let Some(b) = &self.bar {
            b.set_length(total);
        }
    }

    pub(crate) fn finish(&self) {
        if let Some(b) = &self.bar {
            b.finish_and_clear();
        }
    }
}

impl Progress for Bar<'_> {
    fn tick(&self, done: u64, total: u64) {
        if let Some(b) = &self.bar {
            if total > 0 && b.length() != Some(total) {
                b.set_length(total);
            }
            b.set_position(done);
        }
    }

    fn cancelled(&self) -> bool {
        self.stop.load(Ordering::Relaxed)
    }
}
