//! Slow analyses off the key path, as gitui's asyncgit does them: a [`Pool`] of worker
//! threads (owned by whoever runs the jobs and passed in, never a process-wide static)
//! takes requests from one queue; a [`Job`] is keyed by what it was asked for (the
//! snapshot it belongs to and the job's settings), so a repeat is not recomputed and a
//! superseded result is dropped unseen; a finished job (and each percent of progress)
//! sends its typed notice `N` to whoever listens ([`JobSet::listen`]: the app's event
//! loop, on the one channel it waits on; no polling). `render` waits for every job so
//! headless output is deterministic.

use std::fmt;
use std::panic::{AssertUnwindSafe, catch_unwind};
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::mpsc::{self, Sender};
use std::sync::{Arc, Condvar, Mutex, OnceLock, PoisonError};

/// Worker threads of a pool: the analyses a view can want at once (Methods rows,
/// overlay, two fits) and an export; more would only share the cores.
pub const WORKERS: usize = 4;

type Task = Box<dyn FnOnce() + Send>;

/// Something told each time a job's body starts (a test counts work with it; the app
/// passes none).
pub type OnRun = Arc<dyn Fn() + Send + Sync>;

/// A fixed set of worker threads and their one queue, started on first use; they end
/// when the pool is dropped (clones of a [`JobSet`] share it).
pub struct Pool {
    workers: usize,
    queue: Mutex<Option<Sender<Task>>>,
    on_run: Option<OnRun>,
}

impl Pool {
    /// A pool of `workers` threads.
    pub fn new(workers: usize) -> Pool {
        Pool {
            workers: workers.max(1),
            queue: Mutex::new(None),
            on_run: None,
        }
    }

    /// A pool that tells `on_run` whenever a job's body starts (a superseded job that
    /// had not started never does): work counted, not timed.
    pub fn observed(workers: usize, on_run: OnRun) -> Pool {
        Pool {
            on_run: Some(on_run),
            ..Pool::new(workers)
        }
    }

    /// Queues `task`; false if no worker could take it.
    fn send(&self, task: Task) -> bool {
        let mut queue = self.queue.lock().unwrap_or_else(PoisonError::into_inner);
        let tx = queue.get_or_insert_with(|| self.start());
        tx.send(task).is_ok()
    }

    /// Starts the workers on one queue.
    fn start(&self) -> Sender<Task> {
        let (tx, rx) = mpsc::channel::<Task>();
        let rx = Arc::new(Mutex::new(rx));
        for i in 0..self.workers {
            let rx = Arc::clone(&rx);
            let _ = std::thread::Builder::new()
                .name(format!("groovelab-worker-{i}"))
                .spawn(move || {
                    // Analyses yield the cores to the thread that reads keys and draws:
                    // a key press never waits for them, even on two cores. Lowering a
                    // thread's own priority needs no privilege; where it fails, the
                    // work runs at the usual priority.
                    let _ = thread_priority::set_current_thread_priority(
                        thread_priority::ThreadPriority::Min,
                    );
                    loop {
                        let task = rx.lock().unwrap_or_else(PoisonError::into_inner).recv();
                        let Ok(task) = task else { break };
                        // A panicking job loses its result, not the worker.
                        let _ = catch_unwind(AssertUnwindSafe(task));
                    }
                });
        }
        tx
    }
}

impl Default for Pool {
    fn default() -> Pool {
        Pool::new(WORKERS)
    }
}

impl fmt::Debug for Pool {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "Pool({} workers)", self.workers)
    }
}

/// Whom a job's notice goes to.
type Notify<N> = Arc<dyn Fn(N) + Send + Sync>;

/// What the jobs of one owner share: how many are queued or running (to wait for
/// them all), and whom to notify.
struct Shared<N> {
    pending: Mutex<usize>,
    idle: Condvar,
    listener: Mutex<Option<Notify<N>>>,
}

/// The jobs of one owner on a pool, each finished one notified as an `N` (clones
/// share them).
pub struct JobSet<N> {
    shared: Arc<Shared<N>>,
    pool: Arc<Pool>,
}

impl<N> Clone for JobSet<N> {
    fn clone(&self) -> Self {
        JobSet {
            shared: Arc::clone(&self.shared),
            pool: Arc::clone(&self.pool),
        }
    }
}

impl<N> fmt::Debug for JobSet<N> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "Jobs on {:?}", self.pool)
    }
}

impl<N> JobSet<N> {
    fn add(&self, delta: isize) {
        let mut n = self
            .shared
            .pending
            .lock()
            .unwrap_or_else(PoisonError::into_inner);
        *n = n.saturating_add_signed(delta);
        if *n == 0 {
            self.shared.idle.notify_all();
        }
    }
}

impl<N: Clone + Send + Sync + 'static> JobSet<N> {
    /// Jobs on `pool`, notifying no one until [`JobSet::listen`].
    pub fn new(pool: Arc<Pool>) -> JobSet<N> {
        JobSet {
            shared: Arc::new(Shared {
                pending: Mutex::new(0),
                idle: Condvar::new(),
                listener: Mutex::new(None),
            }),
            pool,
        }
    }

    /// Whom a finished job (or a new percent of progress) notifies from now on.
    pub fn listen(&self, listener: impl Fn(N) + Send + Sync + 'static) {
        *self
            .shared
            .listener
            .lock()
            .unwrap_or_else(PoisonError::into_inner) = Some(Arc::new(listener));
    }

    fn notify(&self, notice: N) {
        let listener = self
            .shared
            .listener
            .lock()
            .unwrap_or_else(PoisonError::into_inner)
            .clone();
        if let Some(l) = listener {
            l(notice);
        }
    }

    /// True while a job is queued or running (a superseded one winding down too).
    pub fn busy(&self) -> bool {
        *self
            .shared
            .pending
            .lock()
            .unwrap_or_else(PoisonError::into_inner)
            > 0
    }

    /// Blocks until no job is queued or running.
    pub fn wait(&self) {
        let mut n = self
            .shared
            .pending
            .lock()
            .unwrap_or_else(PoisonError::into_inner);
        while *n > 0 {
            n = self
                .shared
                .idle
                .wait(n)
                .unwrap_or_else(PoisonError::into_inner);
        }
    }

    /// Queues `work` on the pool; its result fills `slot` unless superseded first.
    fn submit<T: Send + Sync + 'static>(
        &self,
        ticket: Ticket,
        notice: N,
        slot: Arc<OnceLock<T>>,
        work: impl FnOnce(&Ticket) -> T + Send + 'static,
    ) {
        self.add(1);
        let jobs = self.clone();
        let on_run = self.pool.on_run.clone();
        let task: Task = Box::new(move || {
            // Counted down however the body ends (a panic too).
            let _done = Done(&jobs);
            if ticket.cancelled() {
                return;
            }
            if let Some(on_run) = on_run {
                on_run();
            }
            let result = work(&ticket);
            if !ticket.cancelled() && slot.set(result).is_ok() {
                jobs.notify(notice);
            }
        });
        if !self.pool.send(task) {
            self.add(-1);
        }
    }

    /// What a job's progress wakes: its own notice.
    fn progress_notice(&self, notice: N) -> Wake {
        let jobs = self.clone();
        Arc::new(move || jobs.notify(notice.clone()))
    }
}

/// Counts a job down when its task ends.
struct Done<'a, N>(&'a JobSet<N>);

impl<N> Drop for Done<'_, N> {
    fn drop(&mut self) {
        self.0.add(-1);
    }
}

/// A running job's progress notice.
type Wake = Arc<dyn Fn() + Send + Sync>;

/// What a running job may look at: whether it is still wanted, and where to count.
#[derive(Clone)]
pub struct Ticket {
    cancelled: Arc<AtomicBool>,
    done: Arc<AtomicUsize>,
    total: Arc<AtomicUsize>,
    /// The percent last reported (each new percent notifies once).
    percent: Arc<AtomicUsize>,
    wake: Option<Wake>,
}

impl fmt::Debug for Ticket {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("Ticket")
            .field("cancelled", &self.cancelled())
            .finish_non_exhaustive()
    }
}

impl Ticket {
    fn new(wake: Option<Wake>) -> Ticket {
        Ticket {
            cancelled: Arc::default(),
            done: Arc::default(),
            total: Arc::default(),
            percent: Arc::new(AtomicUsize::new(usize::MAX)),
            wake,
        }
    }

    /// A ticket of no job: never cancelled, its progress goes nowhere (for running a
    /// job's work in place).
    pub fn detached() -> Ticket {
        Ticket::new(None)
    }

    /// True once a newer request (or a scene change) has made this job useless.
    pub fn cancelled(&self) -> bool {
        self.cancelled.load(Ordering::Relaxed)
    }

    /// The flag itself, for code that takes an `&AtomicBool`.
    pub fn flag(&self) -> &AtomicBool {
        &self.cancelled
    }

    /// Progress: `done` of `total` units; a new percent notifies the listener.
    pub fn progress(&self, done: usize, total: usize) {
        self.total.store(total, Ordering::Relaxed);
        self.done.store(done, Ordering::Relaxed);
        let percent = done.saturating_mul(100) / total.max(1);
        if self.percent.swap(percent, Ordering::Relaxed) != percent
            && let Some(wake) = &self.wake
        {
            wake();
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
    /// Asks for `work` under `key` on the pool of `jobs`, to send `notice` when done:
    /// nothing happens if this key is already running or done (a repeat is not
    /// recomputed); else whatever ran is told to stop and its result will be dropped.
    /// True if `work` was queued.
    pub fn request<N: Clone + Send + Sync + 'static>(
        &mut self,
        jobs: &JobSet<N>,
        key: K,
        notice: N,
        work: impl FnOnce(&Ticket) -> T + Send + 'static,
    ) -> bool {
        if matches!(&self.request, Some((k, ..)) if *k == key) {
            return false;
        }
        self.cancel();
        let ticket = Ticket::new(Some(jobs.progress_notice(notice.clone())));
        let slot = Arc::new(OnceLock::new());
        jobs.submit(ticket.clone(), notice, Arc::clone(&slot), work);
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

    /// Jobs on a pool of their own, and how many bodies ran.
    fn counted() -> (JobSet<u8>, Arc<AtomicUsize>) {
        let runs = Arc::new(AtomicUsize::new(0));
        let r = Arc::clone(&runs);
        let pool = Pool::observed(
            WORKERS,
            Arc::new(move || {
                r.fetch_add(1, Ordering::SeqCst);
            }),
        );
        (JobSet::new(Arc::new(pool)), runs)
    }

    #[test]
    fn a_superseded_result_is_dropped_and_a_repeat_is_not_recomputed() {
        let (jobs, runs) = counted();
        let mut job: Job<u32, u32> = Job::default();
        let started = Arc::new(AtomicU32::new(0));
        let s = Arc::clone(&started);
        assert!(job.request(&jobs, 1, 0, move |t| {
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
        assert!(job.request(&jobs, 2, 0, |t| {
            t.progress(1, 1);
            2
        }));
        jobs.wait();
        assert_eq!(job.ready(), Some(&2), "the newer result, not the stale one");
        assert_eq!(runs.load(Ordering::SeqCst), 2);
        // The same request again: already done, nothing runs.
        assert!(!job.request(&jobs, 2, 0, |_| 3));
        jobs.wait();
        assert_eq!((runs.load(Ordering::SeqCst), job.ready()), (2, Some(&2)));
        job.cancel();
        assert!(matches!(job.state(), State::Idle));
    }

    #[test]
    fn a_finished_job_sends_its_notice() {
        let (jobs, _) = counted();
        let (tx, rx) = mpsc::channel();
        let tx = Mutex::new(tx);
        jobs.listen(move |n| {
            let _ = tx.lock().unwrap().send(n);
        });
        let mut job: Job<(), u8> = Job::default();
        job.request(&jobs, (), 9, |_| 7);
        assert_eq!(rx.recv().unwrap(), 9, "the job's own notice");
        jobs.wait();
        assert_eq!(job.take(), Some(7));
        assert!(matches!(job.state(), State::Idle));
    }

    #[test]
    fn the_workers_end_with_their_pool() {
        let (jobs, runs) = counted();
        let mut job: Job<(), u8> = Job::default();
        job.request(&jobs, (), 0, |_| 1);
        jobs.wait();
        let pool = Arc::downgrade(&jobs.pool);
        drop((job, jobs));
        // The worker drops its handle just after the job is counted done.
        let mut tries = 0;
        while pool.upgrade().is_some() && tries < 10_000_000 {
            std::thread::yield_now();
            tries += 1;
        }
        assert!(pool.upgrade().is_none(), "no static keeps the pool");
        assert_eq!(runs.load(Ordering::SeqCst), 1);
    }
}
