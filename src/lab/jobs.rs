//! Slow analyses off the key path, as gitui's asyncgit does them: a fixed pool of
//! worker threads takes requests from one queue; a request is keyed by what it was
//! asked for (the scene it belongs to and the job's settings), so a repeat is not
//! recomputed and a superseded result is dropped unseen; a finished job (and each
//! percent of progress) wakes whoever listens through the lab's [`Waker`] (the app's
//! event loop: no polling). `render` waits for every job so headless output is
//! deterministic.

use std::fmt;
use std::panic::{AssertUnwindSafe, catch_unwind};
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::mpsc::{self, Sender};
use std::sync::{Arc, Condvar, Mutex, OnceLock, PoisonError};

/// Worker threads of the pool: the analyses a view can want at once (Methods rows,
/// overlay, two fits) and an export; more would only share the cores.
pub const WORKERS: usize = 4;

type Task = Box<dyn FnOnce() + Send>;

/// The one queue of the pool, its workers started on first use.
fn pool() -> &'static Mutex<Sender<Task>> {
    static POOL: OnceLock<Mutex<Sender<Task>>> = OnceLock::new();
    POOL.get_or_init(|| {
        let (tx, rx) = mpsc::channel::<Task>();
        let rx = Arc::new(Mutex::new(rx));
        for i in 0..WORKERS {
            let rx = Arc::clone(&rx);
            let _ = std::thread::Builder::new()
                .name(format!("groovelab-worker-{i}"))
                .spawn(move || {
                    loop {
                        let task = rx.lock().unwrap_or_else(PoisonError::into_inner).recv();
                        let Ok(task) = task else { break };
                        // A panicking job loses its result, not the worker.
                        let _ = catch_unwind(AssertUnwindSafe(task));
                    }
                });
        }
        Mutex::new(tx)
    })
}

/// Tells a listener that a job finished or moved on (the app: redraw).
#[derive(Clone, Default)]
pub struct Waker(Option<Arc<dyn Fn() + Send + Sync>>);

impl Waker {
    pub fn new(wake: impl Fn() + Send + Sync + 'static) -> Waker {
        Waker(Some(Arc::new(wake)))
    }

    fn wake(&self) {
        if let Some(w) = &self.0 {
            w();
        }
    }
}

impl fmt::Debug for Waker {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(if self.0.is_some() {
            "Waker"
        } else {
            "Waker(none)"
        })
    }
}

/// What the jobs of one lab share: how many are queued or running (to wait for them
/// all), how many bodies ran (work counted, not time), and whom to wake.
#[derive(Debug, Default)]
struct Shared {
    pending: Mutex<usize>,
    idle: Condvar,
    runs: AtomicUsize,
    waker: Mutex<Waker>,
}

/// The jobs of one lab (clones share them).
#[derive(Clone, Debug, Default)]
pub struct Jobs(Arc<Shared>);

impl Jobs {
    /// Whom a finished job wakes from now on.
    pub fn set_waker(&self, waker: Waker) {
        *self.0.waker.lock().unwrap_or_else(PoisonError::into_inner) = waker;
    }

    fn wake(&self) {
        let waker = self
            .0
            .waker
            .lock()
            .unwrap_or_else(PoisonError::into_inner)
            .clone();
        waker.wake();
    }

    /// True while a job is queued or running (a superseded one winding down too).
    pub fn busy(&self) -> bool {
        *self
            .0
            .pending
            .lock()
            .unwrap_or_else(PoisonError::into_inner)
            > 0
    }

    /// Blocks until no job is queued or running.
    pub fn wait(&self) {
        let mut n = self
            .0
            .pending
            .lock()
            .unwrap_or_else(PoisonError::into_inner);
        while *n > 0 {
            n = self.0.idle.wait(n).unwrap_or_else(PoisonError::into_inner);
        }
    }

    /// How many job bodies have run (a job superseded before it started never runs).
    pub fn runs(&self) -> usize {
        self.0.runs.load(Ordering::Relaxed)
    }

    fn add(&self, delta: isize) {
        let mut n = self
            .0
            .pending
            .lock()
            .unwrap_or_else(PoisonError::into_inner);
        *n = n.saturating_add_signed(delta);
        if *n == 0 {
            self.0.idle.notify_all();
        }
    }

    /// Queues `work` on the pool; its result fills `slot` unless superseded first.
    fn submit<T: Send + Sync + 'static>(
        &self,
        ticket: Ticket,
        slot: Arc<OnceLock<T>>,
        work: impl FnOnce(&Ticket) -> T + Send + 'static,
    ) {
        self.add(1);
        let jobs = self.clone();
        let task: Task = Box::new(move || {
            // Counted down however the body ends (a panic too).
            let _done = Done(&jobs);
            if ticket.cancelled() {
                return;
            }
            jobs.0.runs.fetch_add(1, Ordering::Relaxed);
            let result = work(&ticket);
            if !ticket.cancelled() && slot.set(result).is_ok() {
                jobs.wake();
            }
        });
        let sent = pool()
            .lock()
            .unwrap_or_else(PoisonError::into_inner)
            .send(task);
        if sent.is_err() {
            self.add(-1);
        }
    }
}

/// Counts a job down when its task ends.
struct Done<'a>(&'a Jobs);

impl Drop for Done<'_> {
    fn drop(&mut self) {
        self.0.add(-1);
    }
}

/// What a running job may look at: whether it is still wanted, and where to count.
#[derive(Clone, Debug)]
pub struct Ticket {
    cancelled: Arc<AtomicBool>,
    done: Arc<AtomicUsize>,
    total: Arc<AtomicUsize>,
    /// The percent last reported (each new percent wakes the listener once).
    percent: Arc<AtomicUsize>,
    jobs: Jobs,
}

impl Ticket {
    fn new(jobs: &Jobs) -> Ticket {
        Ticket {
            cancelled: Arc::default(),
            done: Arc::default(),
            total: Arc::default(),
            percent: Arc::new(AtomicUsize::new(usize::MAX)),
            jobs: jobs.clone(),
        }
    }

    /// True once a newer request (or a scene change) has made this job useless.
    pub fn cancelled(&self) -> bool {
        self.cancelled.load(Ordering::Relaxed)
    }

    /// The flag itself, for code that takes an `&AtomicBool`.
    pub fn flag(&self) -> &AtomicBool {
        &self.cancelled
    }

    /// Progress: `done` of `total` units; a new percent wakes the listener.
    pub fn progress(&self, done: usize, total: usize) {
        self.total.store(total, Ordering::Relaxed);
        self.done.store(done, Ordering::Relaxed);
        let percent = done.saturating_mul(100) / total.max(1);
        if self.percent.swap(percent, Ordering::Relaxed) != percent {
            self.jobs.wake();
        }
    }
}

/// A study's cancellation hook: a superseded job stops inside long runs. Its progress
/// is the job's own ([`Ticket::progress`]), not the study's inner steps.
impl crate::study::Progress for Ticket {
    fn cancelled(&self) -> bool {
        Ticket::cancelled(self)
    }
}

/// One analysis, keyed by what it was asked for: not asked for, or requested (then
/// running until its result is there). Cloning shares a running job.
#[derive(Clone, Debug)]
pub struct Job<K, T> {
    request: Option<(K, Ticket, Arc<OnceLock<T>>)>,
}

impl<K, T> Default for Job<K, T> {
    fn default() -> Self {
        Job { request: None }
    }
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

impl<K: PartialEq, T: Send + Sync + 'static> Job<K, T> {
    /// Asks for `work` under `key` on the pool of `jobs`: nothing happens if this key
    /// is already running or done (a repeat is not recomputed); else whatever ran is
    /// told to stop and its result will be dropped. True if `work` was queued.
    pub fn request(
        &mut self,
        jobs: &Jobs,
        key: K,
        work: impl FnOnce(&Ticket) -> T + Send + 'static,
    ) -> bool {
        if matches!(&self.request, Some((k, ..)) if *k == key) {
            return false;
        }
        self.cancel();
        let ticket = Ticket::new(jobs);
        let slot = Arc::new(OnceLock::new());
        jobs.submit(ticket.clone(), Arc::clone(&slot), work);
        self.request = Some((key, ticket, slot));
        true
    }

    /// The key of the job asked for last, if one is.
    pub fn key(&self) -> Option<&K> {
        self.request.as_ref().map(|(k, ..)| k)
    }

    /// Forgets the job; a running one is told to stop.
    pub fn cancel(&mut self) {
        if let Some((_, ticket, _)) = self.request.take() {
            ticket.cancelled.store(true, Ordering::Relaxed);
        }
    }

    /// Stops a job that is still running; a finished one is kept.
    pub fn stop_running(&mut self) {
        if self.is_running() {
            self.cancel();
        }
    }

    pub fn is_running(&self) -> bool {
        matches!(self.state(), State::Computing { .. })
    }

    pub fn state(&self) -> State<'_, T> {
        match &self.request {
            None => State::Idle,
            Some((_, ticket, slot)) => match slot.get() {
                Some(r) => State::Ready(r),
                None => State::Computing {
                    done: ticket.done.load(Ordering::Relaxed),
                    total: ticket.total.load(Ordering::Relaxed),
                },
            },
        }
    }

    pub fn ready(&self) -> Option<&T> {
        match self.state() {
            State::Ready(r) => Some(r),
            _ => None,
        }
    }

    /// The finished result, once: the job is idle afterwards.
    pub fn take(&mut self) -> Option<T>
    where
        T: Clone,
    {
        let r = self.ready().cloned()?;
        self.request = None;
        Some(r)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::sync::atomic::AtomicU32;

    #[test]
    fn a_superseded_result_is_dropped_and_a_repeat_is_not_recomputed() {
        let jobs = Jobs::default();
        let mut job: Job<u32, u32> = Job::default();
        let started = Arc::new(AtomicU32::new(0));
        let s = Arc::clone(&started);
        assert!(job.request(&jobs, 1, move |t| {
            s.fetch_add(1, Ordering::SeqCst);
            // Runs until superseded: the newer request must stop it.
            while !t.cancelled() {
                std::thread::yield_now();
            }
            1
        }));
        while started.load(Ordering::SeqCst) == 0 {
            std::thread::yield_now();
        }
        assert!(matches!(job.state(), State::Computing { .. }));
        assert!(job.request(&jobs, 2, |t| {
            t.progress(1, 1);
            2
        }));
        jobs.wait();
        assert_eq!(job.ready(), Some(&2), "the newer result, not the stale one");
        assert_eq!(jobs.runs(), 2);
        // The same request again: already done, nothing runs.
        assert!(!job.request(&jobs, 2, |_| 3));
        jobs.wait();
        assert_eq!((jobs.runs(), job.ready()), (2, Some(&2)));
        job.cancel();
        assert!(matches!(job.state(), State::Idle));
    }

    #[test]
    fn a_finished_job_wakes_the_listener() {
        let jobs = Jobs::default();
        let (tx, rx) = mpsc::channel();
        let tx = Mutex::new(tx);
        jobs.set_waker(Waker::new(move || {
            let _ = tx.lock().unwrap().send(());
        }));
        let mut job: Job<(), u8> = Job::default();
        job.request(&jobs, (), |_| 7);
        rx.recv().unwrap();
        jobs.wait();
        assert_eq!(job.take(), Some(7));
        assert!(matches!(job.state(), State::Idle));
    }
}
