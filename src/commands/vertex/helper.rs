//! One helper thread for immediate mode, when the application asks for more than one thread
//! (`Context::batch_full` says why not by default): it lights a full batch of glVertex blocks while the
//! application's thread goes on filling the next, which then collects the lit batch and feeds
//! it back (or selects or captures it) before its own, so the order is the one thread's.
//! Only a primitive's batches are in flight, only between its glBegin and glEnd: glEnd and
//! glMaterial (the one command between them that changes how vertices are lit) collect
//! first, so nothing is in flight when any other command runs.
//!
//! A batch is offered, not handed over: if the helper has not started it by the time the
//! application's thread collects it (the helper busy with another context's batch, or not
//! scheduled on a busy machine), the application's thread lights it itself. Either way the
//! same function lights the same blocks, so results do not depend on which thread did it,
//! nor on the thread count. A helper that did not start in time, or made the application's
//! thread wait long, is not offered the next batches, for longer each time it happens again
//! (up to 256 batches), so a machine with more work than cores sees one thread's speed.

use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Condvar, Mutex, MutexGuard, OnceLock};
use std::time::{Duration, Instant};

use super::{HALF_BLOCKS, HalfBlocks, half_blocks};
use crate::lighting::batch::{Faces, process_blocks};
use crate::pipeline::block::OutputBlock;
use crate::pipeline::vertex::DerivedState;

/// Where an offered batch stands.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Phase {
    /// Nothing offered.
    Idle,
    /// Offered, not lit yet: whoever locks the job first lights it.
    Offered,
    /// Lit: `outputs` hold the result.
    Lit,
}

/// A batch and its lit blocks, behind the job's lock. Whoever lights it holds the lock
/// throughout, so the offering thread waits for the helper by taking the lock.
#[derive(Debug)]
pub(crate) struct Batch {
    phase: Phase,
    derived: Option<Arc<DerivedState>>,
    /// The faces whose colors the primitive reads.
    faces: Faces,
    /// The blocks to light (swapped with the pending blocks', so nothing is copied).
    inputs: [HalfBlocks; 2],
    outputs: Vec<OutputBlock>,
}

impl Batch {
    /// The lit blocks.
    pub(crate) fn outputs(&self) -> &[OutputBlock] {
        &self.outputs
    }
}

/// One context's offered batch; kept with its pending blocks and reused for every batch.
#[derive(Debug)]
pub(crate) struct Job {
    batch: Mutex<Batch>,
}

impl Job {
    /// A job with room for a batch.
    pub(crate) fn new() -> Arc<Job> {
        Arc::new(Job {
            batch: Mutex::new(Batch {
                phase: Phase::Idle,
                derived: None,
                faces: Faces::Both,
                inputs: [half_blocks(), half_blocks()],
                outputs: vec![OutputBlock::default(); 2 * HALF_BLOCKS],
            }),
        })
    }

    fn lock(&self) -> MutexGuard<'_, Batch> {
        self.batch.lock().unwrap_or_else(|e| e.into_inner())
    }
}

/// The application thread's side of a context's job: when to offer the helper a batch.
#[derive(Debug, Default)]
pub(crate) struct Offers {
    /// Batches still to light alone, after the helper kept this thread waiting.
    skip: u32,
    /// How many batches the next wait costs the helper (0, then 1, 2, 4, ... 256).
    penalty: u32,
}

impl Offers {
    /// Whether to offer the helper this batch.
    pub(crate) fn offer_now(&mut self) -> bool {
        if self.skip > 0 {
            self.skip -= 1;
            return false;
        }
        true
    }

    /// Whether the helper lit the last batch in time.
    fn helped(&mut self, in_time: bool) {
        if in_time {
            self.penalty /= 2;
        } else {
            self.penalty = (self.penalty * 2).clamp(1, 256);
            self.skip = self.penalty;
        }
    }
}

/// Offers `inputs` (every block full) to the helper thread, to light with `derived` for the
/// colors of `faces`; `inputs`
/// gets the job's previous blocks in exchange (to fill again). `false` when there is no helper
/// (it could not be started): nothing is offered and `inputs` is unchanged.
pub(crate) fn offer(
    job: &Arc<Job>,
    derived: &Arc<DerivedState>,
    faces: Faces,
    inputs: &mut [HalfBlocks; 2],
) -> bool {
    let Some(helper) = helper() else {
        return false;
    };
    {
        let mut batch = job.lock();
        std::mem::swap(&mut batch.inputs, inputs);
        batch.derived = Some(derived.clone());
        batch.faces = faces;
        batch.phase = Phase::Offered;
    }
    let mut queue = helper.queue.lock().unwrap_or_else(|e| e.into_inner());
    // One job waits at a time; another context's job there means the helper has work, and
    // this batch will be lit by its own thread when it collects it.
    if queue.is_none() {
        *queue = Some(job.clone());
        helper.queued.store(true, Ordering::Release);
        if helper.sleeping.load(Ordering::Relaxed) {
            helper.wake.notify_one();
        }
    }
    true
}

/// Longer than this waiting for the helper to finish a batch it began, and it is not offered
/// the next (it was descheduled: lighting a batch takes tens of microseconds).
const LONG_WAIT: Duration = Duration::from_micros(200);

/// The offered batch, lit: by the helper (waiting for it to finish if it has begun), or here
/// if it has not begun.
pub(crate) fn collect<'a>(job: &'a Job, offers: &mut Offers) -> MutexGuard<'a, Batch> {
    let mut batch = match job.batch.try_lock() {
        Ok(batch) => batch,
        Err(std::sync::TryLockError::Poisoned(e)) => e.into_inner(),
        Err(std::sync::TryLockError::WouldBlock) => {
            // The helper is lighting it.
            let waiting = Instant::now();
            let batch = job.lock();
            offers.helped(waiting.elapsed() < LONG_WAIT);
            batch
        }
    };
    if batch.phase == Phase::Offered {
        offers.helped(false);
        light(&mut batch);
    } else {
        offers.helped(true);
    }
    batch.phase = Phase::Idle;
    batch.derived = None;
    batch
}

fn light(batch: &mut Batch) {
    let Batch {
        derived,
        faces,
        inputs,
        outputs,
        phase,
    } = batch;
    if let Some(derived) = derived {
        let (first, second) = outputs.split_at_mut(HALF_BLOCKS);
        process_blocks(derived, *faces, &inputs[0][..], first);
        process_blocks(derived, *faces, &inputs[1][..], second);
    }
    *phase = Phase::Lit;
}

/// The helper thread's mailbox.
struct Helper {
    queue: Mutex<Option<Arc<Job>>>,
    /// Whether `queue` holds a job: what the helper watches while it spins.
    queued: AtomicBool,
    /// Whether the helper sleeps on `wake` (set and read under `queue`'s lock).
    sleeping: AtomicBool,
    wake: Condvar,
}

/// How long the helper watches for the next batch before it sleeps: the next batch of a
/// primitive comes within this, and waking a sleeping thread costs the offering thread a
/// system call and the helper tens of microseconds (by then the batch may be collected).
const SPIN: Duration = Duration::from_micros(100);

/// The helper, started on first use and kept for the life of the process; `None` if the
/// thread could not be started.
fn helper() -> Option<&'static Helper> {
    static HELPER: OnceLock<Option<Helper>> = OnceLock::new();
    HELPER
        .get_or_init(|| {
            std::thread::Builder::new()
                .name("fflight-immediate".into())
                .spawn(run)
                .ok()
                .map(|_| Helper {
                    queue: Mutex::new(None),
                    queued: AtomicBool::new(false),
                    sleeping: AtomicBool::new(false),
                    wake: Condvar::new(),
                })
        })
        .as_ref()
}

/// The helper thread: lights each offered batch it finds still offered.
fn run() {
    let Some(helper) = helper() else {
        return;
    };
    loop {
        let spinning = Instant::now();
        while !helper.queued.load(Ordering::Acquire) && spinning.elapsed() < SPIN {
            std::hint::spin_loop();
        }
        let job = {
            let mut queue = helper.queue.lock().unwrap_or_else(|e| e.into_inner());
            loop {
                if let Some(job) = queue.take() {
                    helper.queued.store(false, Ordering::Relaxed);
                    break job;
                }
                helper.sleeping.store(true, Ordering::Relaxed);
                queue = helper.wake.wait(queue).unwrap_or_else(|e| e.into_inner());
                helper.sleeping.store(false, Ordering::Relaxed);
            }
        };
        let mut batch = job.lock();
        if batch.phase == Phase::Offered {
            // A panic leaves the batch offered: the offering thread lights it and meets the
            // panic under its own guard.
            let _ = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| light(&mut batch)));
        }
    }
}
