//! Stop signals, one mechanism for the whole program: SIGINT, SIGTERM, SIGHUP and
//! SIGQUIT set one process-wide stop flag, which long commands poll (exit 130) and the
//! atomic writer checks before it commits (so a stop leaves no file), and wake the
//! listeners registered with [`on_signal`] (the app restores the terminal; an event
//! loop can forward the signal into its channel).
//!
//! Until [`watch`] or [`on_signal`] is called a signal has its default action: a short
//! command that writes nothing ends at once.

use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Mutex, Once, OnceLock};

/// The signals that end a run from outside: Ctrl-C (outside raw mode), `kill`, a closed
/// terminal (SIGHUP), a service manager, Ctrl-\.
#[cfg(unix)]
pub const ENDING: [i32; 4] = [
    signal_hook::consts::SIGINT,
    signal_hook::consts::SIGTERM,
    signal_hook::consts::SIGHUP,
    signal_hook::consts::SIGQUIT,
];
#[cfg(not(unix))]
pub const ENDING: [i32; 1] = [signal_hook::consts::SIGINT];

/// What a listener is given: the signal's number.
type Listener = Box<dyn Fn(i32) + Send + Sync>;

fn flag() -> &'static Arc<AtomicBool> {
    static STOP: OnceLock<Arc<AtomicBool>> = OnceLock::new();
    STOP.get_or_init(|| Arc::new(AtomicBool::new(false)))
}

fn listeners() -> &'static Mutex<Vec<Listener>> {
    static LISTENERS: OnceLock<Mutex<Vec<Listener>>> = OnceLock::new();
    LISTENERS.get_or_init(Mutex::default)
}

/// The process-wide stop flag: set by any ending signal once [`watch`] has run.
pub fn stop_flag() -> &'static AtomicBool {
    flag()
}

/// Whether an ending signal has arrived since [`watch`] (or the last [`arm`]).
pub fn stopped() -> bool {
    stop_flag().load(Ordering::Relaxed)
}

/// From now on the ending signals set [`stop_flag`] instead of ending the process, so
/// a long run can stop cleanly. Idempotent; the handlers stay for the rest of the
/// process (signal-hook cannot give the default action back).
pub fn watch() {
    static ONCE: Once = Once::new();
    ONCE.call_once(|| {
        for signal in ENDING {
            // Set inside the handler itself: seen by the very next poll.
            let _ = signal_hook::flag::register(signal, Arc::clone(flag()));
        }
    });
}

/// [`watch`], and the flag cleared: the start of one command's run (a process that
/// runs several, as the tests do, starts each unstopped).
pub fn arm() -> &'static AtomicBool {
    watch();
    stop_flag().store(false, Ordering::Relaxed);
    stop_flag()
}

/// Calls `listener` with the signal's number on a thread of its own (blocked, no CPU,
/// until a signal comes) for every ending signal, after setting the stop flag. The
/// app's listener restores the terminal and exits; an event loop's can send the
/// signal into its channel.
pub fn on_signal(listener: impl Fn(i32) + Send + Sync + 'static) -> std::io::Result<()> {
    watch();
    listeners()
        .lock()
        .unwrap_or_else(|e| e.into_inner())
        .push(Box::new(listener));
    // The first start's failure, kept whole for every later caller.
    static THREAD: OnceLock<Result<(), std::sync::Arc<std::io::Error>>> = OnceLock::new();
    THREAD
        .get_or_init(|| start_listening().map_err(std::sync::Arc::new))
        .clone()
        .map_err(|e| std::io::Error::new(e.kind(), e))
}

/// The thread that hands each ending signal to the listeners.
fn start_listening() -> std::io::Result<()> {
    let mut signals = signal_hook::iterator::Signals::new(ENDING)?;
    std::thread::Builder::new()
        .name("groovelab-signals".into())
        .spawn(move || {
            for signal in signals.forever() {
                let listeners = listeners().lock().unwrap_or_else(|e| e.into_inner());
                for listener in listeners.iter() {
                    listener(signal);
                }
            }
        })?;
    Ok(())
}
