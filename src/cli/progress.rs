//! Long commands on the terminal: a progress line on stderr (only when stderr is a
//! terminal, so scripts and pipes see nothing) and Ctrl-C as a stop request that the
//! analysis notices within milliseconds, after which nothing is written (exit 130).

use std::io::IsTerminal;
use std::sync::OnceLock;
use std::sync::atomic::{AtomicBool, Ordering};

use indicatif::{ProgressBar, ProgressStyle};

use crate::study::Progress;

/// Set by Ctrl-C (SIGINT) while a long command runs.
static STOP: AtomicBool = AtomicBool::new(false);

/// Arms Ctrl-C for one run: installs the handler once per process and clears the flag.
pub(crate) fn ctrl_c() -> &'static AtomicBool {
    static INSTALLED: OnceLock<()> = OnceLock::new();
    INSTALLED.get_or_init(|| {
        let _ = ctrlc::set_handler(|| STOP.store(true, Ordering::Relaxed));
    });
    STOP.store(false, Ordering::Relaxed);
    &STOP
}

/// A command's progress: a bar (or, with no total known, a counter) on stderr, and
/// the Ctrl-C flag.
pub(crate) struct Bar {
    bar: Option<ProgressBar>,
    stop: &'static AtomicBool,
}

impl Bar {
    /// `what` names the unit counted (e.g. "runs"); `show` is false for work that is
    /// over before a bar would be read.
    pub(crate) fn new(what: &'static str, show: bool) -> Bar {
        let bar = (show && std::io::stderr().is_terminal()).then(|| {
            let bar = ProgressBar::new(0);
            bar.set_style(
                ProgressStyle::with_template(&format!(
                    "{{bar:40}} {{pos}}/{{len}} {what}, {{eta}} left"
                ))
                .expect("a valid template"),
            );
            bar
        });
        Bar {
            bar,
            stop: ctrl_c(),
        }
    }

    /// A counter for work whose total is not known ahead.
    pub(crate) fn counter(what: &'static str, show: bool) -> Bar {
        let mut b = Bar::new(what, false);
        b.bar = (show && std::io::stderr().is_terminal()).then(|| {
            let bar = ProgressBar::new_spinner();
            bar.set_style(
                ProgressStyle::with_template(&format!("{{spinner}} {{pos}} {what}, {{elapsed}}"))
                    .expect("a valid template"),
            );
            bar
        });
        b
    }

    pub(crate) fn finish(&self) {
        if let Some(b) = &self.bar {
            b.finish_and_clear();
        }
    }
}

impl Progress for Bar {
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
