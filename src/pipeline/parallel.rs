//! Large draws on several threads with their primitives in order: chunks of blocks are
//! fetched and lit by helper threads and by the calling thread, whichever gets to them first,
//! and the calling thread streams the lit chunks into assembly and feedback in order, exactly
//! as one thread would. A fixed set of chunk buffers bounds how far lighting runs ahead, so
//! the working set does not grow with the draw; and since the calling thread lights whatever
//! is not claimed yet whenever the next chunk is not ready, a busy machine that leaves the
//! helpers little time slows the draw to one thread's speed, not below.

use std::collections::BTreeMap;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::mpsc::channel;
use std::sync::{Condvar, Mutex, MutexGuard};

use super::block::{InputBlock, OutputBlock};
use super::vertex::DerivedState;
use crate::lighting::batch::{Reads, process_blocks};
use crate::threads::watch;

/// Blocks per chunk: the unit of work (2048 vertices, about 230 KiB of lit blocks; large
/// enough that handing chunks over costs little next to lighting them).
const CHUNK_BLOCKS: usize = 256;

/// Chunk buffers per thread: one being lit while another waits to be streamed.
pub(crate) const BUFFERS_PER_THREAD: usize = 2;

/// A chunk's input blocks (kept between the chunks an output serves: `fill` leaves in them
/// what it does not set) and its lit blocks.
type LitChunk = (Vec<InputBlock>, Vec<OutputBlock>);

/// The chunk buffers not in use. `None` once the draw is over, which sends waiting helpers
/// home.
struct FreeChunks<C> {
    chunks: Mutex<FreeList<C>>,
    returned: Condvar,
}

struct FreeList<C> {
    chunks: Option<Vec<C>>,
    /// Threads asleep waiting for a buffer: `put` wakes one only when there is one, since
    /// `Condvar::notify_one` makes a system call even when nobody waits.
    sleeping: usize,
}

impl<C> FreeList<C> {
    /// A free buffer, `Err` if none is free; `Ok(None)` when the draw is over.
    fn pop(&mut self) -> Result<Option<C>, ()> {
        match self.chunks.as_mut() {
            None => Ok(None),
            Some(free) => free.pop().map(Some).ok_or(()),
        }
    }
}

impl<C> FreeChunks<C> {
    fn new(chunks: Vec<C>) -> FreeChunks<C> {
        FreeChunks {
            chunks: Mutex::new(FreeList {
                chunks: Some(chunks),
                sleeping: 0,
            }),
            returned: Condvar::new(),
        }
    }

    fn lock(&self) -> MutexGuard<'_, FreeList<C>> {
        self.chunks.lock().unwrap_or_else(|e| e.into_inner())
    }

    /// A free buffer, waiting for one if `wait` (watching for `threads::SPIN`, then asleep);
    /// `None` when the draw is over (or, without `wait`, when none is free).
    fn take(&self, wait: bool) -> Option<C> {
        if !wait {
            return self.lock().pop().ok().flatten();
        }
        if let Some(found) = watch(|| self.lock().pop().ok()) {
            return found;
        }
        let mut free = self.lock();
        loop {
            if let Ok(found) = free.pop() {
                return found;
            }
            free.sleeping += 1;
            free = self.returned.wait(free).unwrap_or_else(|e| e.into_inner());
            free.sleeping -= 1;
        }
    }

    fn put(&self, chunk: C) {
        let mut free = self.lock();
        let sleeping = free.sleeping > 0;
        if let Some(chunks) = free.chunks.as_mut() {
            chunks.push(chunk);
            if sleeping {
                self.returned.notify_one();
            }
        }
    }

    /// Ends the draw (also when the calling thread unwinds): helpers stop waiting. Returns
    /// the buffers that were free.
    fn close(&self) -> Vec<C> {
        let free = self.lock().chunks.take();
        self.returned.notify_all();
        free.unwrap_or_default()
    }
}

/// Closes the free list when dropped, so that helpers never wait for a caller that is gone.
struct CloseOnDrop<'a, C>(&'a FreeChunks<C>);

impl<C> Drop for CloseOnDrop<'_, C> {
    fn drop(&mut self) {
        self.0.close();
    }
}

/// Lights `blocks` blocks (for what `reads` says) with `helpers` helper threads besides the
/// calling thread and gives them to `stream` in order on the calling thread. `fill(block, input)` puts block `block`'s
/// vertices into `input` (which starts as `template`, and keeps what `fill` leaves there).
///
/// # Examples
///
/// ```
/// # use fflight::lighting::PreparedLighting;
/// # use fflight::pipeline::vertex::{DerivedState, VertexTransform};
/// # use fflight::state::{light::Light, light_model::LightModel};
/// # use fflight::state::material::{ColorMaterial, Material};
/// # use glam::Mat4;
/// // Identity matrices, lighting off.
/// let derived = DerivedState::new(
///     VertexTransform::new(Mat4::IDENTITY, Mat4::IDENTITY, Mat4::IDENTITY, false, false, None),
///     PreparedLighting::new(
///         false,
///         &std::array::from_fn(Light::initial),
///         &[Material::default(); 2],
///         &LightModel::default(),
///         &ColorMaterial::default(),
///     ),
/// );
/// use fflight::pipeline::{block::InputBlock, parallel::light_in_order};
/// use glam::Vec4;
/// let mut xs = Vec::new();
/// light_in_order(
///     &derived,
///     fflight::lighting::batch::Faces::Both.into(),
///     &InputBlock::default(),
///     100,
///     1,
///     |block, input| {
///         input.len = 1;
///         input.set_position(0, Vec4::new(block as f32, 0.0, 0.0, 1.0));
///     },
///     |output| xs.push(output.vertex(0).clip.x),
/// );
/// // Every block, in order, whichever thread lit it.
/// assert_eq!(xs, (0..100).map(|b| b as f32).collect::<Vec<_>>());
/// ```
pub fn light_in_order(
    derived: &DerivedState,
    reads: Reads,
    template: &InputBlock,
    blocks: usize,
    helpers: usize,
    fill: impl Fn(usize, &mut InputBlock) + Sync,
    mut stream: impl FnMut(&OutputBlock),
) {
    let chunks = blocks.div_ceil(CHUNK_BLOCKS);
    // Chunk `chunk`'s blocks, fetched into `lit.0` and lit into `lit.1`.
    let light = |chunk: usize, lit: &mut LitChunk| {
        let first = chunk * CHUNK_BLOCKS;
        let len = CHUNK_BLOCKS.min(blocks - first);
        let (inputs, outputs) = lit;
        for (k, input) in inputs[..len].iter_mut().enumerate() {
            fill(first + k, input);
        }
        outputs.resize(len, OutputBlock::default());
        process_blocks(derived, reads, &inputs[..len], outputs);
    };
    let new_chunk = || {
        (
            vec![*template; CHUNK_BLOCKS],
            Vec::with_capacity(CHUNK_BLOCKS),
        )
    };
    let mut own = new_chunk();
    in_order(
        chunks,
        helpers.min(chunks.saturating_sub(1)),
        new_chunk,
        light,
        |step| {
            let lit = match step {
                Step::Run(chunk) => {
                    light(chunk, &mut own);
                    &own
                }
                Step::Take(lit) => &*lit,
            };
            lit.1.iter().for_each(&mut stream);
        },
    );
}

/// What `in_order` asks of the calling thread.
pub(crate) enum Step<'a, T> {
    /// Run job `k` itself: every earlier job has been taken, so its results may go straight
    /// where they belong.
    Run(usize),
    /// Take the output of the next job, which another thread ran.
    Take(&'a mut T),
}

/// Runs `jobs` jobs, `helpers` helper threads running them into outputs (`make` makes one,
/// `run(k, output)` runs job `k` into it), and hands them to `main` on the calling thread in
/// order of job: `main(Step::Take(output))` for a job a helper ran, `main(Step::Run(k))` when
/// the next job is still unclaimed (then the calling thread runs it). While the next job is
/// being run elsewhere, the calling thread runs later ones into outputs too. A fixed set of
/// outputs (two per thread) bounds how far the helpers run ahead. Returns the outputs, for a
/// next draw to reuse (but one a helper gives back after the last job's, which is dropped).
pub(crate) fn in_order<T: Send>(
    jobs: usize,
    helpers: usize,
    make: impl Fn() -> T + Sync,
    run: impl Fn(usize, &mut T) + Sync,
    mut main: impl FnMut(Step<T>),
) -> Vec<T> {
    let free = FreeChunks::new(
        (0..BUFFERS_PER_THREAD * (helpers + 1))
            .map(|_| make())
            .collect(),
    );
    let next_job = AtomicUsize::new(0);
    std::thread::scope(|scope| {
        let _close = CloseOnDrop(&free);
        let (done_tx, done_rx) = channel::<(usize, T)>();
        for _ in 0..helpers {
            let (free, next_job, run, done_tx) = (&free, &next_job, &run, done_tx.clone());
            scope.spawn(move || {
                while let Some(mut output) = free.take(true) {
                    let k = next_job.fetch_add(1, Ordering::Relaxed);
                    if k >= jobs {
                        // Given back, for the next draw.
                        free.put(output);
                        return;
                    }
                    run(k, &mut output);
                    if done_tx.send((k, output)).is_err() {
                        return;
                    }
                }
            });
        }
        drop(done_tx);
        // Outputs that arrived before their turn.
        let mut waiting: BTreeMap<usize, T> = BTreeMap::new();
        for job in 0..jobs {
            let mut output = loop {
                if let Some(output) = waiting.remove(&job) {
                    break Some(output);
                }
                if let Ok((k, output)) = done_rx.try_recv() {
                    waiting.insert(k, output);
                    continue;
                }
                let claimed =
                    next_job.compare_exchange(job, job + 1, Ordering::Relaxed, Ordering::Relaxed);
                if claimed.is_ok() {
                    break None;
                }
                // The next job is someone else's: run a later one meanwhile, if an output
                // is free.
                if let Some(mut output) = free.take(false) {
                    let k = next_job.fetch_add(1, Ordering::Relaxed);
                    if k < jobs {
                        run(k, &mut output);
                        waiting.insert(k, output);
                        continue;
                    }
                    free.put(output);
                }
                let (k, output) = watch(|| done_rx.try_recv().ok())
                    .unwrap_or_else(|| done_rx.recv().expect("a helper runs each job it claims"));
                waiting.insert(k, output);
            };
            match &mut output {
                None => main(Step::Run(job)),
                Some(output) => main(Step::Take(output)),
            }
            if let Some(output) = output {
                free.put(output);
            }
        }
        free.close()
    })
}
