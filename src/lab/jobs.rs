//! Slow analyses off the key path: each runs on a thread of its own, reports progress,
//! can be cancelled, and is superseded by a newer request (gitui's asyncgit, in small).
//! A key press only starts a job; the screen shows "computing…" until the result is
//! there, and `render` waits for it so headless output stays deterministic.

use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::{Arc, Condvar, Mutex};

/// What a running job may look at: whether it is still wanted, and where to count.
#[derive(Clone, Debug, Default)]
pub struct Ticket {
    cancelled: Arc<AtomicBool>,
    done: Arc<AtomicUsize>,
    total: Arc<AtomicUsize>,
}

impl Ticket {
    /// True once a newer request (or a scene change) has made this job useless.
    pub fn cancelled(&self) -> bool {
        self.cancelled.load(Ordering::Relaxed)
    }

    /// The flag itself, for code that takes an `&AtomicBool`.
    pub fn flag(&self) -> &AtomicBool {
        &self.cancelled
    }

    /// Progress: `done` of `total` units.
    pub fn progress(&self, done: usize, total: usize) {
        self.total.store(total, Ordering::Relaxed);
        self.done.store(done, Ordering::Relaxed);
    }
}

/// A study's cancellation hook: a superseded job stops inside long runs. Its progress
/// is the job's own ([`Ticket::progress`]), not the study's inner steps.
impl crate::study::Progress for Ticket {
    fn cancelled(&self) -> bool {
        Ticket::cancelled(self)
    }
}

/// The result slot a job fills and the UI reads.
type Slot<T> = Arc<(Mutex<Option<T>>, Condvar)>;

/// One analysis: not asked for, running, or done. Cloning shares a running job.
#[derive(Clone, Debug, Default)]
pub enum Job<T> {
    #[default]
    Idle,
    Running {
        ticket: Ticket,
        slot: Slot<T>,
    },
    Ready(T),
}

/// What a view can show of a job.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum State<'a, T> {
    Idle,
    /// Running, with progress `done` of `total` (total 0: unknown).
    Computing {
        done: usize,
        total: usize,
    },
    Ready(&'a T),
}

impl<T: Send + 'static> Job<T> {
    /// Starts `work` on a thread, cancelling whatever this job was running.
    pub fn start(&mut self, work: impl FnOnce(&Ticket) -> T + Send + 'static) {
        self.cancel();
        let ticket = Ticket::default();
        let slot: Slot<T> = Arc::new((Mutex::new(None), Condvar::new()));
        let (t, s) = (ticket.clone(), slot.clone());
        std::thread::spawn(move || {
            let result = work(&t);
            let (lock, ready) = &*s;
            if let Ok(mut guard) = lock.lock() {
                *guard = Some(result);
            }
            ready.notify_all();
        });
        *self = Job::Running { ticket, slot };
    }

    /// Forgets the job; a running one is told to stop.
    pub fn cancel(&mut self) {
        if let Job::Running { ticket, .. } = self {
            ticket.cancelled.store(true, Ordering::Relaxed);
        }
        *self = Job::Idle;
    }

    /// Takes a finished result in; true if the job just became ready.
    pub fn poll(&mut self) -> bool {
        let Job::Running { slot, .. } = self else {
            return false;
        };
        let taken = slot.0.lock().ok().and_then(|mut g| g.take());
        match taken {
            Some(result) => {
                *self = Job::Ready(result);
                true
            }
            None => false,
        }
    }

    /// Blocks until a running job is done.
    pub fn wait(&mut self) {
        if let Job::Running { slot, .. } = self {
            let (lock, ready) = &**slot;
            let Ok(mut guard) = lock.lock() else {
                return;
            };
            while guard.is_none() {
                guard = match ready.wait(guard) {
                    Ok(g) => g,
                    Err(_) => return,
                };
            }
            let result = guard.take();
            drop(guard);
            if let Some(r) = result {
                *self = Job::Ready(r);
            }
        }
    }

    pub fn is_running(&self) -> bool {
        matches!(self, Job::Running { .. })
    }

    pub fn state(&self) -> State<'_, T> {
        match self {
            Job::Idle => State::Idle,
            Job::Running { ticket, .. } => State::Computing {
                done: ticket.done.load(Ordering::Relaxed),
                total: ticket.total.load(Ordering::Relaxed),
            },
            Job::Ready(r) => State::Ready(r),
        }
    }

    pub fn ready(&self) -> Option<&T> {
        match self {
            Job::Ready(r) => Some(r),
            _ => None,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_job_runs_off_thread_and_a_newer_one_supersedes_it() {
        let mut job: Job<u32> = Job::default();
        job.start(|t| {
            // Runs until cancelled: the superseding start must stop it.
            while !t.cancelled() {
                std::thread::yield_now();
            }
            1
        });
        assert!(matches!(job.state(), State::Computing { .. }));
        job.start(|t| {
            t.progress(1, 1);
            2
        });
        job.wait();
        assert_eq!(job.ready(), Some(&2));
        job.cancel();
        assert!(matches!(job.state(), State::Idle));
    }
}
