//! How many threads large draws and bulk calls may use (and whether immediate mode's helper
//! thread lights its batches: with more than one): `fflSetThreads` / [`set_threads`], else
//! the environment variable `FFLIGHT_THREADS`, else the number of cores. Process-wide, like
//! the pool that runs the work.

use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::{Duration, Instant};

use crate::error::{GlError, GlResult};

/// The count set by `set_threads`; 0 while the default applies.
static REQUESTED: AtomicUsize = AtomicUsize::new(0);

/// At most this many threads, whatever is asked.
pub const MAX_THREADS: usize = 256;

/// Sets how many threads large draws and bulk calls use: 1 runs everything on the calling
/// thread, 0 restores the default (`FFLIGHT_THREADS`, else the number of cores). Counts above
/// [`MAX_THREADS`] are clamped to it; a negative count is GL_INVALID_VALUE.
///
/// # Examples
///
/// ```
/// use fflight::{threads::{set_threads, thread_count}, GlError};
/// set_threads(2)?;
/// assert_eq!(thread_count(), 2);
/// assert_eq!(set_threads(-1), Err(GlError::InvalidValue));
/// set_threads(0)?; // back to the default
/// # Ok::<(), fflight::GlError>(())
/// ```
pub fn set_threads(count: i32) -> GlResult {
    let count = usize::try_from(count).map_err(|_| GlError::InvalidValue)?;
    REQUESTED.store(count.min(MAX_THREADS), Ordering::Relaxed);
    Ok(())
}

/// The number of threads in use: the count set, or the default.
///
/// # Examples
///
/// ```
/// use fflight::threads::thread_count;
/// assert!(thread_count() >= 1);
/// ```
pub fn thread_count() -> usize {
    match REQUESTED.load(Ordering::Relaxed) {
        0 => default_thread_count(),
        n => n,
    }
}

/// Below this many vertices per thread, work runs on fewer threads.
pub const MIN_VERTICES_PER_THREAD: usize = 16 * 1024;

/// How many threads `vertices` vertices of work use: at most the thread count, and no more
/// than give each `MIN_VERTICES_PER_THREAD`; at least 1.
///
/// # Examples
///
/// ```
/// use fflight::threads::threads_for;
/// assert_eq!(threads_for(100), 1); // too little work to share
/// ```
pub fn threads_for(vertices: usize) -> usize {
    thread_count()
        .min(vertices / MIN_VERTICES_PER_THREAD)
        .max(1)
}

/// `FFLIGHT_THREADS` when it holds a positive number, else the number of cores.
fn default_thread_count() -> usize {
    env_thread_count().unwrap_or_else(cores).min(MAX_THREADS)
}

/// The number of cores, read once: immediate mode asks for every batch, and reading it
/// (the affinity mask, the cgroup's quota files) takes microseconds.
fn cores() -> usize {
    static CORES: std::sync::OnceLock<usize> = std::sync::OnceLock::new();
    *CORES.get_or_init(|| std::thread::available_parallelism().map_or(1, |n| n.get()))
}

/// `FFLIGHT_THREADS` when it holds a positive number.
fn env_thread_count() -> Option<usize> {
    std::env::var("FFLIGHT_THREADS")
        .ok()
        .and_then(|v| v.trim().parse::<usize>().ok())
        .filter(|&n| n > 0)
        .map(|n| n.min(MAX_THREADS))
}

/// How long a thread that waits for another watches before it sleeps: the work it waits for
/// (a chunk, a batch) comes within this, and waking a sleeping thread costs the waking thread
/// a system call and the sleeper tens of microseconds (more in a virtual machine, where the
/// wake-up is an interrupt sent through the hypervisor to an idle virtual CPU). It watches
/// yielding: where more threads are runnable than cores, a thread spinning without yielding
/// takes its share of a core from the others, the application's thread among them
/// (immediate 8 spots, 2 cores busy with two other processes: 84-94 ns/vertex spinning,
/// 61-68 yielding, 59-76 with one thread).
pub(crate) const SPIN: Duration = Duration::from_micros(100);

/// `poll`'s first `Some`, polled while yielding for at most `SPIN`; `None` after that, when
/// the caller goes to sleep.
pub(crate) fn watch<T>(mut poll: impl FnMut() -> Option<T>) -> Option<T> {
    let start = Instant::now();
    loop {
        if let Some(found) = poll() {
            return Some(found);
        }
        if start.elapsed() > SPIN {
            return None;
        }
        std::thread::yield_now();
    }
}
