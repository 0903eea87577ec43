//! One helper thread for immediate mode: while the application's thread lights the second
//! half of a full batch of glVertex blocks, the helper lights the first half. The batch is
//! processed within one call (the glVertex that fills it, or the glEnd or glMaterial that
//! flushes it), so nothing is in flight when the call returns and no other command has to
//! wait for the helper.
//!
//! The first half is offered, not handed over: if the helper has not started it by the time
//! the application's thread is done with its own half (the helper busy with another context's
//! half, or not scheduled on a busy machine), the application's thread lights it too. Either
//! way the same function lights the same blocks, so results do not depend on which thread
//! did it, nor on the thread count.

use std::sync::{Arc, Condvar, Mutex, MutexGuard, OnceLock};

use super::{HALF_BLOCKS, HalfBlocks, half_blocks};
use crate::lighting::batch::process_blocks;
use crate::pipeline::block::OutputBlock;
use crate::pipeline::vertex::DerivedState;

/// Where an offered half stands.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Phase {
    /// Nothing offered.
    Idle,
    /// Offered, not lit yet: whoever locks the job first lights it.
    Offered,
    /// Lit: `outputs` hold the result.
    Lit,
}

/// A half batch and its lit blocks, behind the job's lock. Whoever lights it holds the lock
/// throughout, so the offering thread waits for the helper by taking the lock.
#[derive(Debug)]
pub(crate) struct HalfBatch {
    phase: Phase,
    derived: Option<Arc<DerivedState>>,
    /// The blocks to light (swapped with the pending blocks', so nothing is copied).
    pub(crate) inputs: HalfBlocks,
    pub(crate) outputs: Vec<OutputBlock>,
}

/// One context's offered half; kept with its pending blocks and reused for every batch.
#[derive(Debug)]
pub(crate) struct Job {
    half: Mutex<HalfBatch>,
}

impl Job {
    /// A job with room for half a batch.
    pub(crate) fn new() -> Arc<Job> {
        Arc::new(Job {
            half: Mutex::new(HalfBatch {
                phase: Phase::Idle,
                derived: None,
                inputs: half_blocks(),
                outputs: vec![OutputBlock::default(); HALF_BLOCKS],
            }),
        })
    }

    fn lock(&self) -> MutexGuard<'_, HalfBatch> {
        self.half.lock().unwrap_or_else(|e| e.into_inner())
    }
}

/// Offers `inputs` (every block full) to the helper thread, to light with `derived`; `inputs`
/// gets the job's previous blocks in exchange (to fill again). `false` when there is no helper
/// (it could not be started): nothing is offered and `inputs` is unchanged.
pub(crate) fn offer(
    job: &Arc<Job>,
    derived: &Arc<DerivedState>,
    inputs: &mut HalfBlocks,
) -> bool {
    let Some(helper) = helper() else {
        return false;
    };
    {
        let mut half = job.lock();
        std::mem::swap(&mut half.inputs, inputs);
        half.derived = Some(derived.clone());
        half.phase = Phase::Offered;
    }
    let mut queue = helper.queue.lock().unwrap_or_else(|e| e.into_inner());
    // One job waits at a time; another context's job there means the helper has work, and
    // this half will be lit by its own thread when it collects it.
    if queue.is_none() {
        *queue = Some(job.clone());
        helper.wake.notify_one();
    }
    true
}

/// The offered half, lit: by the helper (waiting for it to finish if it has begun), or here
/// if it has not begun.
pub(crate) fn collect(job: &Job) -> MutexGuard<'_, HalfBatch> {
    let mut half = job.lock();
    if half.phase == Phase::Offered {
        light(&mut half);
    }
    half.phase = Phase::Idle;
    half.derived = None;
    half
}

fn light(half: &mut HalfBatch) {
    let HalfBatch {
        derived,
        inputs,
        outputs,
        phase,
    } = half;
    if let Some(derived) = derived {
        process_blocks(derived, &inputs[..], outputs);
    }
    *phase = Phase::Lit;
}

/// The helper thread's mailbox.
struct Helper {
    queue: Mutex<Option<Arc<Job>>>,
    wake: Condvar,
}

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
                    wake: Condvar::new(),
                })
        })
        .as_ref()
}

/// The helper thread: lights each offered half it finds still offered.
fn run() {
    let Some(helper) = helper() else {
        return;
    };
    loop {
        let job = {
            let mut queue = helper.queue.lock().unwrap_or_else(|e| e.into_inner());
            loop {
                if let Some(job) = queue.take() {
                    break job;
                }
                queue = helper.wake.wait(queue).unwrap_or_else(|e| e.into_inner());
            }
        };
        let mut half = job.lock();
        if half.phase == Phase::Offered {
            // A panic leaves the half offered (the lock poisoned, which `lock` ignores):
            // the offering thread lights it and meets the panic under its own guard.
            let lit = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| light(&mut half)));
            if lit.is_err() {
                half.phase = Phase::Offered;
            }
        }
    }
}
