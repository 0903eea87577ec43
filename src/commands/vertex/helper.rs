//! One helper thread for immediate mode, when more than one thread is in use
//! (`Context::batch_full`): it lights a full batch of glVertex blocks while the application's
//! thread streams the batch before it and fills the next. The application's thread collects
//! each batch in order, one chunk of 16 blocks after another: a chunk the helper has lit is
//! streamed as it is, a chunk it has not begun is lit there and then by the application's
//! thread, a chunk it is lighting is waited for (the helper goes from the first chunk, and the
//! application's thread meanwhile lights the last ones, so the two meet in the middle of a
//! batch that neither could light alone in time).
//! Either way the same function lights the same blocks, so results do not depend on which
//! thread did it, nor on the thread count, and the order of the feedback is the one thread's.
//! A primitive's batches are in flight between its glBegin and glEnd, collected first by
//! glMaterial (the one command between them that changes how vertices are lit) and by glEnd;
//! a primitive of points placed in the application's memory leaves them in flight past its
//! glEnd (its last blocks offered too, a batch that ends early), for the next primitive to
//! stream before its own or any other command to collect first (`Context::collect_carried`),
//! so nothing is in flight when a command that could see their points runs.
//!
//! In feedback mode into the application's memory, the helper also places the points it lays
//! out there, when it knows where: both threads go through a batch from its first chunk, and
//! whoever puts a chunk's values in the buffer publishes where the next chunk's begin (the
//! job's frontier); a chunk whose place is published when the helper has laid it out goes
//! straight there (the application's thread, which would otherwise copy it, only counts it).
//! Immediate 1 light, 2 threads on the Xeon: the copies were a third of the application's
//! thread's time.
//!
//! Nothing waits on the helper for long: the inputs of a batch are shared, not handed over,
//! so a chunk the helper began and did not finish in `LONG_WAIT` (it was descheduled) is lit
//! again by the application's thread; the helper's late result is thrown away. A helper that
//! did not help with a batch, or kept the application's thread waiting, is not offered the
//! next batches, for longer each time it happens again (up to 256 batches), so a machine
//! with more work than cores sees one thread's speed. Between batches the helper watches
//! for the next for `threads::SPIN`, then sleeps until one is offered.

use std::collections::VecDeque;
use std::sync::atomic::{AtomicBool, AtomicU64, AtomicUsize, Ordering};
use std::sync::{Arc, Mutex, MutexGuard, OnceLock};
use std::thread::Thread;
use std::time::{Duration, Instant};

use super::{Filled, HALF_BLOCKS, HalfBlocks, half_blocks};
use crate::capi::ApplicationPlaces;
use crate::lighting::batch::{Reads, process_blocks};
use crate::pipeline::block::{InputBlock, OutputBlock};
use crate::pipeline::points::{LaidOutPoints, PointsSink};
use crate::pipeline::vertex::DerivedState;
use crate::threads::watch;

/// Blocks per chunk, what a thread lights at a time: the batch engine's own group of blocks.
pub(crate) const CHUNK_BLOCKS: usize = 16;

/// Chunks per batch.
const CHUNKS: usize = 2 * HALF_BLOCKS / CHUNK_BLOCKS;

/// How many batches of a context may be offered at once: the one the helper lights while
/// the application's thread streams the one before.
pub(crate) const RING: usize = 2;

/// Where a chunk of a batch stands, in its state's three low bits (the batch's number above).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[repr(u64)]
enum Phase {
    /// Not begun: whoever claims it first lights it.
    Offered,
    /// The helper lights it.
    Helper,
    /// The application's thread lights it (or has).
    Application,
    /// The helper lit it: the chunk's outputs hold it.
    Lit,
    /// The helper laid it out and writes its values in their place in the application's
    /// memory: no one else writes there, nor takes the chunk, until it is `Placed`.
    Placing,
    /// The helper wrote its values in their place (up to the chunk's `placed_end`).
    Placed,
}

/// A chunk's state: batch `seq`, in `phase`.
fn state(seq: u64, phase: Phase) -> u64 {
    seq << 3 | phase as u64
}

/// Chunk `index` of batch `seq` as the frontier counts them (wrapping: the frontier only
/// ever holds one of the last chunks' numbers).
fn chunk_number(seq: u64, index: usize) -> u32 {
    (seq.wrapping_mul(CHUNKS as u64) + index as u64) as u32
}

/// The frontier's value: the chunk whose values come next, and where in the application's
/// memory they begin.
fn frontier(chunk: u32, start: u32) -> u64 {
    u64::from(chunk) << 32 | u64::from(start)
}

fn lock<T>(mutex: &Mutex<T>) -> MutexGuard<'_, T> {
    mutex.lock().unwrap_or_else(|e| e.into_inner())
}

/// A full batch, offered: read by both threads, written by neither.
#[derive(Debug)]
pub(crate) struct Offer {
    /// The batch's number in its job, from 1.
    seq: u64,
    derived: Arc<DerivedState>,
    /// What the primitive reads of its vertices.
    reads: Reads,
    /// Where the helper lays out the points it lights, when it does.
    points: Option<Arc<PointsSink>>,
    /// The application's feedback memory, where the helper places those points when it can.
    places: Option<ApplicationPlaces>,
    /// What the blocks hold.
    filled: Option<Filled>,
    inputs: [HalfBlocks; 2],
    /// How many of them, from the first, hold vertices: all but in a primitive's last batch.
    blocks: usize,
}

impl Offer {
    /// The sink that lays out the batch's points, when the helper does.
    pub(crate) fn points_sink(&self) -> Option<&Arc<PointsSink>> {
        self.points.as_ref()
    }

    /// Whether the helper places the batch's points in the application's memory.
    pub(crate) fn places_points(&self) -> bool {
        self.points.is_some() && self.places.is_some()
    }

    /// How many chunks hold vertices.
    fn chunks(&self) -> usize {
        self.blocks.div_ceil(CHUNK_BLOCKS)
    }

    /// How many blocks of chunk `index` hold vertices.
    fn blocks_in(&self, index: usize) -> usize {
        self.blocks
            .saturating_sub(index * CHUNK_BLOCKS)
            .min(CHUNK_BLOCKS)
    }

    /// The number of the chunk whose values come after chunk `index`'s, as the frontier counts
    /// them: the next batch's first after the last that holds vertices.
    fn next_chunk(&self, index: usize) -> u32 {
        if index + 1 < self.chunks() {
            chunk_number(self.seq, index + 1)
        } else {
            chunk_number(self.seq + 1, 0)
        }
    }

    /// Lights chunk `index` into the start of `outputs`; returns how many blocks it has.
    fn light(&self, index: usize, outputs: &mut [OutputBlock]) -> usize {
        let first = blocks_of(index).start;
        let blocks = self.blocks_in(index);
        let inputs: &[InputBlock] =
            &self.inputs[first / HALF_BLOCKS][first % HALF_BLOCKS..][..blocks];
        process_blocks(&self.derived, self.reads, inputs, &mut outputs[..blocks]);
        blocks
    }
}

/// The blocks a batch offers: `blocks` of `halves`, from the first, which hold `filled`
/// (`None` if not all of them do).
pub(crate) struct OfferedBlocks<'a> {
    pub(crate) halves: &'a mut [HalfBlocks; 2],
    pub(crate) blocks: usize,
    pub(crate) filled: Option<Filled>,
}

/// A chunk of a batch: who lights it, and what the helper lit (or laid out).
#[derive(Debug)]
struct Chunk {
    state: AtomicU64,
    outputs: Mutex<Box<[OutputBlock; CHUNK_BLOCKS]>>,
    points: Mutex<LaidOutPoints<'static>>,
    /// Where the values of a `Placed` chunk end in the application's memory.
    placed_end: AtomicUsize,
}

/// Room for one batch in flight.
#[derive(Debug)]
struct Slot {
    /// The batch, while in flight.
    offer: Mutex<Option<Arc<Offer>>>,
    chunks: [Chunk; CHUNKS],
}

/// One context's batches in flight; kept with its pending blocks and reused.
#[derive(Debug)]
pub(crate) struct Job {
    /// Batch `seq` is in slot `seq % RING`.
    slots: [Slot; RING],
    /// The number of the last batch offered (0: none yet).
    offered: AtomicU64,
    /// The number of the last batch the helper has looked at (written by the helper only).
    looked_at: AtomicU64,
    /// Whether the job is in the helper's mailbox.
    queued: AtomicBool,
    /// Where in the application's memory the values of which chunk begin (`frontier`):
    /// published by whoever put the chunk before there, and at an offer with nothing in
    /// flight by the application's thread.
    frontier: AtomicU64,
}

impl Job {
    /// A job with room for `RING` batches.
    pub(crate) fn new() -> Arc<Job> {
        Arc::new(Job {
            slots: std::array::from_fn(|_| Slot {
                offer: Mutex::new(None),
                chunks: std::array::from_fn(|_| Chunk {
                    state: AtomicU64::new(state(0, Phase::Application)),
                    outputs: Mutex::new(Box::new([OutputBlock::default(); CHUNK_BLOCKS])),
                    points: Mutex::new(LaidOutPoints::default()),
                    placed_end: AtomicUsize::new(0),
                }),
            }),
            offered: AtomicU64::new(0),
            looked_at: AtomicU64::new(0),
            queued: AtomicBool::new(false),
            frontier: AtomicU64::new(0),
        })
    }

    fn slot(&self, seq: u64) -> &Slot {
        &self.slots[(seq % RING as u64) as usize]
    }

    /// The next batch offered has no batch in flight before it: its values begin at `start`
    /// in the application's memory, if it is placed there.
    pub(crate) fn begin_places(&self, start: usize) {
        if let Ok(start) = u32::try_from(start) {
            let next = chunk_number(self.offered.load(Ordering::Relaxed) + 1, 0);
            self.frontier
                .store(frontier(next, start), Ordering::Relaxed);
        }
    }
}

/// The application thread's side of a context's job: when to offer the helper a batch.
#[derive(Debug, Default)]
pub(crate) struct Offers {
    /// Batches still to light alone, after the helper did not help.
    skip: u32,
    /// How many batches the next failure costs the helper (0, then 1, 2, 4, ... 256).
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

    /// Whether the helper helped with the last batch in time.
    fn helped(&mut self, in_time: bool) {
        if in_time {
            self.penalty /= 2;
        } else {
            self.penalty = (self.penalty * 2).clamp(1, 256);
            self.skip = self.penalty;
        }
    }
}

/// Offers `inputs`' blocks (full but for the last) to the helper thread, to light with
/// `derived` for what `reads` says (and lay out into `points`, if given, and place them in
/// the application's memory, if given too, where the frontier says: `Job::begin_places`
/// before the first batch in flight); `inputs.halves` gets the blocks of a batch of `spare`,
/// collected before (or new blocks, if the helper still holds them all) in exchange, to fill
/// again. The job's batches offered before and not collected must be fewer than `RING`.
/// Returns the offer, and what the blocks given in exchange hold (`None`: new blocks).
/// `None` when there is no helper (it could not be started): nothing is offered, the halves
/// are unchanged.
pub(crate) fn offer(
    job: &Arc<Job>,
    derived: &Arc<DerivedState>,
    reads: Reads,
    points: Option<(Arc<PointsSink>, Option<ApplicationPlaces>)>,
    inputs: OfferedBlocks,
    spare: &mut Vec<Arc<Offer>>,
) -> Option<(Arc<Offer>, Option<Filled>)> {
    let helper = helper()?;
    let reused = std::iter::from_fn(|| spare.pop()).find_map(|spare| Arc::try_unwrap(spare).ok());
    let reused_filled = reused.as_ref().and_then(|r| r.filled);
    let fresh = reused.map_or_else(|| [half_blocks(), half_blocks()], |r| r.inputs);
    let (points, places) = points.map_or((None, None), |(sink, places)| (Some(sink), places));
    let offer = Offer {
        seq: job.offered.load(Ordering::Relaxed) + 1,
        derived: derived.clone(),
        reads,
        points,
        places,
        filled: inputs.filled,
        inputs: std::mem::replace(inputs.halves, fresh),
        blocks: inputs.blocks,
    };
    let offer = publish(job, offer);
    if !job.queued.swap(true, Ordering::SeqCst) {
        let mut mailbox = lock(&helper.mailbox);
        mailbox.push_back(job.clone());
        helper.mail.store(true, Ordering::Release);
    }
    // Costs a system call only when the helper sleeps.
    helper.thread.unpark();
    Some((offer, reused_filled))
}

/// Makes `offer` the job's next batch, every chunk that holds vertices offered (the others
/// left to the application's thread, which has nothing to do with them).
fn publish(job: &Job, offer: Offer) -> Arc<Offer> {
    let seq = offer.seq;
    let offer = Arc::new(offer);
    let slot = job.slot(seq);
    for (index, chunk) in slot.chunks.iter().enumerate() {
        let phase = if index < offer.chunks() {
            Phase::Offered
        } else {
            Phase::Application
        };
        chunk.state.store(state(seq, phase), Ordering::Relaxed);
    }
    *lock(&slot.offer) = Some(offer.clone());
    job.offered.store(seq, Ordering::SeqCst);
    offer
}

/// Longer than this waiting for the helper to finish a chunk it began, and the application's
/// thread lights it itself (the helper was descheduled: a chunk takes a few microseconds).
const LONG_WAIT: Duration = Duration::from_micros(50);

/// A chunk of a batch, as `collect` streams it.
pub(crate) enum Lit<'a> {
    /// Its blocks, lit.
    Blocks(&'a [OutputBlock]),
    /// Its points, which the helper lit and laid out.
    Points(&'a LaidOutPoints<'static>),
    /// Its points, which the helper lit, laid out and placed in the application's memory,
    /// where they end at `end`.
    Placed { end: usize },
}

/// Streams the chunks of `offer`, a batch of `job`, in order through `stream`: those the
/// helper lit (or laid out, or placed), the others lit here in `scratch` (room for a batch).
/// While the helper lights the chunk to stream next, this thread lights the batch's last
/// chunks it has not begun (the two meet in the middle of a batch the helper has just been
/// offered, as at glEnd). `stream` returns where the feedback values written so far end,
/// which the frontier publishes for the helper. Returns the batch, whose blocks a later
/// offer fills again.
pub(crate) fn collect(
    job: &Job,
    offer: Arc<Offer>,
    offers: &mut Offers,
    scratch: &mut [OutputBlock],
    mut stream: impl FnMut(Lit) -> usize,
) -> Arc<Offer> {
    let seq = offer.seq;
    let slot = job.slot(seq);
    let mut lit_by_helper = 0;
    let mut in_time = true;
    // The chunks from `back` on are this thread's, lit in their place in `scratch`.
    let mut back = offer.chunks();
    for (index, chunk) in slot.chunks.iter().enumerate().take(offer.chunks()) {
        let blocks = offer.blocks_in(index);
        let taken_from_last = |back: &mut usize, scratch: &mut [OutputBlock]| {
            let last = *back - 1;
            let taken = last > index
                && slot.chunks[last]
                    .state
                    .compare_exchange(
                        state(seq, Phase::Offered),
                        state(seq, Phase::Application),
                        Ordering::Acquire,
                        Ordering::Relaxed,
                    )
                    .is_ok();
            if taken {
                *back = last;
                offer.light(last, &mut scratch[blocks_of(last)]);
            }
            taken
        };
        let claimed = if index >= back {
            Claim::Taken
        } else {
            claim(chunk, seq, || taken_from_last(&mut back, scratch))
        };
        let written = match claimed {
            Claim::Placed => {
                lit_by_helper += 1;
                // The helper published the frontier.
                stream(Lit::Placed {
                    end: chunk.placed_end.load(Ordering::Relaxed),
                });
                continue;
            }
            Claim::Lit => {
                lit_by_helper += 1;
                if offer.points.is_some() {
                    stream(Lit::Points(&lock(&chunk.points)))
                } else {
                    stream(Lit::Blocks(&lock(&chunk.outputs)[..blocks]))
                }
            }
            Claim::Here { late } => {
                in_time &= !late;
                let outputs = &mut scratch[blocks_of(index)];
                offer.light(index, outputs);
                stream(Lit::Blocks(&outputs[..blocks]))
            }
            Claim::Taken => stream(Lit::Blocks(&scratch[blocks_of(index)][..blocks])),
        };
        if let (Some(_), Ok(written)) = (offer.places, u32::try_from(written)) {
            job.frontier.store(
                frontier(offer.next_chunk(index), written),
                Ordering::Release,
            );
        }
    }
    offers.helped(in_time && lit_by_helper > 0);
    {
        let mut held = lock(&slot.offer);
        if held.as_ref().is_some_and(|held| held.seq == offer.seq) {
            *held = None;
        }
    }
    offer
}

/// The blocks of chunk `index` in a batch.
fn blocks_of(index: usize) -> std::ops::Range<usize> {
    index * CHUNK_BLOCKS..(index + 1) * CHUNK_BLOCKS
}

/// Who lights a chunk, as the application's thread collects it.
enum Claim {
    /// The helper lit it.
    Lit,
    /// The helper lit it and placed its points.
    Placed,
    /// The application's thread: the helper had not begun it, or was `late` with it.
    Here { late: bool },
    /// The application's thread lit it already, from the last.
    Taken,
}

/// Who lights `chunk` of batch `seq`: while the helper lights it, this thread does what
/// `meanwhile` does (true if it did something) and waits.
fn claim(chunk: &Chunk, seq: u64, mut meanwhile: impl FnMut() -> bool) -> Claim {
    let mut waiting: Option<Instant> = None;
    let mut late = false;
    loop {
        let now = chunk.state.load(Ordering::Acquire);
        if now == state(seq, Phase::Lit) {
            return Claim::Lit;
        }
        if now == state(seq, Phase::Placed) {
            return Claim::Placed;
        }
        if now == state(seq, Phase::Placing) {
            // Writing the application's memory: waited for however long it takes (a copy of a
            // chunk's values takes a microsecond or so).
            std::thread::yield_now();
            continue;
        }
        if now != state(seq, Phase::Helper) || late {
            let mine = state(seq, Phase::Application);
            if chunk
                .state
                .compare_exchange(now, mine, Ordering::Acquire, Ordering::Acquire)
                .is_ok()
            {
                return Claim::Here { late };
            }
            continue;
        }
        // The helper is lighting it: light another meanwhile, or wait, yielding (the helper
        // may be waiting for this core).
        if meanwhile() {
            continue;
        }
        std::thread::yield_now();
        late = waiting.get_or_insert_with(Instant::now).elapsed() > LONG_WAIT;
    }
}

/// Takes back every chunk of `offer` (a batch of `job` in flight) that the helper has not
/// finished, waiting for one it is placing: after this, the helper writes nothing of it in
/// the application's memory.
pub(crate) fn withdraw(job: &Job, offer: &Offer) {
    let seq = offer.seq;
    for chunk in &job.slot(seq).chunks {
        loop {
            let now = chunk.state.load(Ordering::Acquire);
            if now == state(seq, Phase::Placing) {
                std::thread::yield_now();
                continue;
            }
            let unfinished = now == state(seq, Phase::Offered) || now == state(seq, Phase::Helper);
            let mine = state(seq, Phase::Application);
            if !unfinished
                || chunk
                    .state
                    .compare_exchange(now, mine, Ordering::Acquire, Ordering::Acquire)
                    .is_ok()
            {
                break;
            }
        }
    }
}

/// The helper thread's mailbox.
struct Helper {
    /// Jobs with batches offered.
    mailbox: Mutex<VecDeque<Arc<Job>>>,
    /// Whether `mailbox` holds a job: what the helper watches while it spins.
    mail: AtomicBool,
    thread: Thread,
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
                .map(|handle| Helper {
                    mailbox: Mutex::new(VecDeque::new()),
                    mail: AtomicBool::new(false),
                    thread: handle.thread().clone(),
                })
        })
        .as_ref()
}

/// The helper thread: lights the chunks of each offered batch that the application's thread
/// has not claimed, from the first.
fn run() {
    let Some(helper) = helper() else {
        return;
    };
    let mut scratch = Box::new([OutputBlock::default(); CHUNK_BLOCKS]);
    loop {
        let job = next_job(helper);
        job.queued.store(false, Ordering::SeqCst);
        loop {
            let offered = job.offered.load(Ordering::SeqCst);
            // Batches older than the ring's are collected already.
            let seq = (job.looked_at.load(Ordering::Relaxed) + 1)
                .max(offered.saturating_sub(RING as u64 - 1));
            if seq > offered {
                break;
            }
            job.looked_at.store(seq, Ordering::Relaxed);
            let offer = lock(&job.slot(seq).offer).clone();
            if let Some(offer) = offer.filter(|offer| offer.seq == seq) {
                // A panic leaves the chunk to the application's thread, which lights it (late)
                // and meets the panic under its own guard.
                let _ = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
                    light_chunks(&job, &offer, &mut scratch)
                }));
            }
        }
    }
}

/// Lights the chunks of `offer` the application's thread has not claimed, in order (placing
/// their points where it can).
fn light_chunks(job: &Job, offer: &Offer, scratch: &mut Box<[OutputBlock; CHUNK_BLOCKS]>) {
    let seq = offer.seq;
    for (index, chunk) in job.slot(seq).chunks.iter().enumerate().take(offer.chunks()) {
        let claimed = chunk.state.compare_exchange(
            state(seq, Phase::Offered),
            state(seq, Phase::Helper),
            Ordering::Acquire,
            Ordering::Relaxed,
        );
        if claimed.is_err() {
            // The application's thread took it.
            continue;
        }
        let blocks = offer.light(index, &mut scratch[..]);
        match &offer.points {
            Some(sink) => {
                let mut points = lock(&chunk.points);
                sink.lay_out_blocks(&scratch[..blocks], &mut points);
                if let Some(places) = &offer.places
                    && place(job, offer, index, places, points.values())
                {
                    continue;
                }
            }
            None => std::mem::swap(&mut *lock(&chunk.outputs), scratch),
        }
        // Fails if the application's thread tired of waiting and lit it too: it streams its
        // own, and the chunk's outputs (now ours) are not read.
        let _ = chunk.state.compare_exchange(
            state(seq, Phase::Helper),
            state(seq, Phase::Lit),
            Ordering::Release,
            Ordering::Relaxed,
        );
    }
}

/// Writes `values`, the points of chunk `index` of `offer` (claimed by the helper), in their
/// place in `places` if the frontier reaches the chunk and they fit; whether it did.
#[allow(unsafe_code)]
fn place(
    job: &Job,
    offer: &Offer,
    index: usize,
    places: &ApplicationPlaces,
    values: &[f32],
) -> bool {
    let seq = offer.seq;
    let number = chunk_number(seq, index);
    let Some(now) = frontier_at(job, number) else {
        return false;
    };
    let start = now as u32 as usize;
    let end = start + values.len();
    let (Ok(end_value), true) = (u32::try_from(end), end <= places.len()) else {
        return false;
    };
    let chunk = &job.slot(seq).chunks[index];
    let placing = chunk.state.compare_exchange(
        state(seq, Phase::Helper),
        state(seq, Phase::Placing),
        Ordering::Acquire,
        Ordering::Relaxed,
    );
    if placing.is_err() {
        // The application's thread tired of waiting and took it.
        return false;
    }
    // SAFETY: the application's thread writes feedback values only in order, a chunk after
    // the one before has published the frontier, and never where a chunk it has not
    // collected goes (from `start` on, once the frontier is this chunk's); it collects (or
    // withdraws) every chunk in flight, and waits for a `Placing` one, before any command
    // could change the feedback memory.
    unsafe { places.write(start, values) };
    chunk.placed_end.store(end, Ordering::Relaxed);
    job.frontier.store(
        frontier(offer.next_chunk(index), end_value),
        Ordering::Release,
    );
    chunk
        .state
        .store(state(seq, Phase::Placed), Ordering::Release);
    true
}

/// The frontier once it reaches chunk `number`, waited for while the application's thread
/// streams the chunks before (`None` if it does not come within `LONG_WAIT`). Not waited
/// for, a chunk the helper laid out before the application's thread finished the batch
/// before was not placed, nor then any after it in its batch and the next (their frontier
/// comes only as that thread copies them): 14% of the chunks with one light, against none.
fn frontier_at(job: &Job, number: u32) -> Option<u64> {
    let mut waiting: Option<Instant> = None;
    loop {
        let now = job.frontier.load(Ordering::Acquire);
        let behind = number.wrapping_sub((now >> 32) as u32);
        if behind == 0 {
            return Some(now);
        }
        // Beyond the batches in flight: not a frontier this chunk follows.
        if behind > (RING * CHUNKS) as u32
            || waiting.get_or_insert_with(Instant::now).elapsed() > LONG_WAIT
        {
            return None;
        }
        std::hint::spin_loop();
    }
}

/// Waits for a job in the mailbox: watching it for `threads::SPIN`, then asleep until
/// `offer` wakes the thread.
fn next_job(helper: &Helper) -> Arc<Job> {
    let take = || {
        if !helper.mail.load(Ordering::Acquire) {
            return None;
        }
        let mut mailbox = lock(&helper.mailbox);
        let job = mailbox.pop_front();
        helper.mail.store(!mailbox.is_empty(), Ordering::Relaxed);
        job
    };
    loop {
        if let Some(job) = watch(take) {
            return job;
        }
        std::thread::park();
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::lighting::batch::Faces;

    /// A batch of blocks with a vertex in every lane, all different.
    fn inputs() -> [HalfBlocks; 2] {
        let mut inputs = [half_blocks(), half_blocks()];
        for (b, block) in inputs
            .iter_mut()
            .flat_map(|half| half.iter_mut())
            .enumerate()
        {
            for lane in 0..crate::lighting::lanes::LANES {
                let t = (b * crate::lighting::lanes::LANES + lane) as f32 / 1024.0;
                block.set_position(lane, glam::Vec4::new(t - 0.5, 0.5 - t, 0.25 * t, 1.0));
                block.set_normal(lane, glam::Vec3::new(t, 1.0 - t, 0.5));
            }
            block.len = crate::lighting::lanes::LANES;
        }
        inputs
    }

    /// Batch 1 of `job`, `inputs()` to light with `derived`, published (the job not queued: the
    /// helper thread, if any, never sees it).
    fn offered(job: &Job, derived: &Arc<DerivedState>) -> Arc<Offer> {
        let offer = Offer {
            seq: 1,
            derived: derived.clone(),
            reads: Faces::Front.into(),
            points: None,
            places: None,
            filled: None,
            inputs: inputs(),
            blocks: 2 * HALF_BLOCKS,
        };
        publish(job, offer)
    }

    /// What collecting a batch streams, and what one thread streams lighting it all, when the
    /// "helper" lit the chunks `lit` in time and began chunk `stalled` and stalled (it was
    /// descheduled); and the offers after.
    fn collect_with_helper(lit: &[usize], stalled: usize) -> Collected {
        let mut ctx = crate::Context::new();
        ctx.set_capability(crate::gl::GL_LIGHTING, true).unwrap();
        ctx.set_capability(crate::gl::GL_LIGHT0, true).unwrap();
        ctx.set_capability(crate::gl::GL_LIGHT1, true).unwrap();
        let derived = ctx.shared_derived();
        let job = Job::new();
        let offer = offered(&job, &derived);
        let chunks = &job.slot(offer.seq).chunks;
        let helper_claims = |index: usize| {
            chunks[index].state.compare_exchange(
                state(offer.seq, Phase::Offered),
                state(offer.seq, Phase::Helper),
                Ordering::Acquire,
                Ordering::Relaxed,
            )
        };
        for &index in lit {
            assert!(helper_claims(index).is_ok());
            offer.light(index, &mut lock(&chunks[index].outputs)[..]);
            chunks[index]
                .state
                .store(state(offer.seq, Phase::Lit), Ordering::Release);
        }
        assert!(helper_claims(stalled).is_ok());
        let mut expected = vec![OutputBlock::default(); 2 * HALF_BLOCKS];
        for (half, inputs) in offer.inputs.iter().enumerate() {
            let outputs = &mut expected[half * HALF_BLOCKS..][..HALF_BLOCKS];
            process_blocks(&derived, offer.reads, &inputs[..], outputs);
        }
        let mut offers = Offers::default();
        let mut scratch = vec![OutputBlock::default(); 2 * HALF_BLOCKS];
        let mut streamed = Vec::new();
        let waiting = Instant::now();
        let returned = collect(&job, offer, &mut offers, &mut scratch, |lit| {
            match lit {
                Lit::Blocks(blocks) => streamed.extend_from_slice(blocks),
                _ => unreachable!("no points were offered to lay out"),
            }
            0
        });
        assert!(waiting.elapsed() >= LONG_WAIT);
        assert!(
            Arc::try_unwrap(returned).is_ok(),
            "the inputs come back to fill again"
        );
        Collected {
            streamed,
            expected,
            offers,
        }
    }

    struct Collected {
        streamed: Vec<OutputBlock>,
        expected: Vec<OutputBlock>,
        offers: Offers,
    }

    /// A chunk the helper began and did not finish is lit by the collecting thread after
    /// `LONG_WAIT`; the helper's chunks lit in time are streamed as they are; the stream is
    /// the whole batch in order, as one thread lights it; and the helper is not offered the
    /// next batch.
    #[test]
    fn a_chunk_the_helper_leaves_unfinished_is_lit_by_the_collecting_thread() {
        let mut collected = collect_with_helper(&[CHUNKS - 1], CHUNKS - 2);
        assert!(
            collected.streamed == collected.expected,
            "the stream differs from one thread's"
        );
        assert!(
            !collected.offers.offer_now(),
            "the late helper is offered the next batch"
        );
        assert!(collected.offers.offer_now());
    }

    /// While it waits for the helper's first chunk, the collecting thread lights the others
    /// from the last, and streams them after it, in order.
    #[test]
    fn the_collecting_thread_lights_from_the_last_while_the_helper_lights_the_first() {
        let collected = collect_with_helper(&[], 0);
        assert!(
            collected.streamed == collected.expected,
            "the stream differs from one thread's"
        );
    }

    /// Withdrawing a batch waits for the chunk the helper is placing, and leaves the helper
    /// none of the others: it can neither begin one nor place one it began.
    #[test]
    fn a_withdrawn_batch_leaves_the_helper_nothing_to_write() {
        let job = Job::new();
        let offer = offered(&job, &crate::Context::new().shared_derived());
        let chunks = &job.slot(offer.seq).chunks;
        let set = |index: usize, phase: Phase| {
            chunks[index]
                .state
                .store(state(offer.seq, phase), Ordering::Release)
        };
        set(0, Phase::Placing);
        set(1, Phase::Helper);
        let began = Instant::now();
        std::thread::scope(|s| {
            s.spawn(|| {
                std::thread::sleep(Duration::from_millis(5));
                set(0, Phase::Placed);
            });
            withdraw(&job, &offer);
        });
        assert!(
            began.elapsed() >= Duration::from_millis(5),
            "not waited for"
        );
        let phase = |index: usize| chunks[index].state.load(Ordering::Acquire);
        assert_eq!(phase(0), state(offer.seq, Phase::Placed));
        for index in 1..CHUNKS {
            assert_eq!(phase(index), state(offer.seq, Phase::Application));
        }
    }

    /// Points the helper placed in the application's memory, each chunk where the one before
    /// ended from where the frontier began, are the values one thread lays out, and the
    /// collecting thread only counts them.
    #[test]
    fn placed_points_are_where_one_thread_lays_them_out() {
        placed_points_with_blocks(2 * HALF_BLOCKS, crate::lighting::lanes::LANES);
    }

    /// The same for a primitive's last batch, whose blocks end before the batch's (in the
    /// middle of a chunk, the last block partly filled).
    #[test]
    fn placed_points_of_a_last_batch_are_where_one_thread_lays_them_out() {
        placed_points_with_blocks(2 * CHUNK_BLOCKS + 5, 3);
    }

    fn placed_points_with_blocks(blocks: usize, last_len: usize) {
        use crate::gl::*;
        const UNWRITTEN: f32 = -7.0;
        const START: usize = 5;
        let mut ctx = crate::Context::new();
        ctx.set_capability(GL_LIGHTING, true).unwrap();
        ctx.set_capability(GL_LIGHT0, true).unwrap();
        ctx.feedback_buffer(1 << 16, GL_3D_COLOR, 1).unwrap();
        ctx.render_mode(GL_FEEDBACK).unwrap();
        let sink = ctx
            .points_sink(ctx.raster.viewport_map(), ctx.clip_planes())
            .expect("feedback mode");
        let derived = ctx.shared_derived();
        let places = ApplicationPlaces::kept_for_tests(vec![UNWRITTEN; 1 << 16]);
        let job = Job::new();
        job.begin_places(START);
        let offer = publish(
            &job,
            Offer {
                seq: 1,
                derived: derived.clone(),
                reads: Faces::Front.into(),
                points: Some(Arc::new(sink.clone())),
                places: Some(places),
                filled: None,
                inputs: {
                    let mut inputs = inputs();
                    inputs[(blocks - 1) / HALF_BLOCKS][(blocks - 1) % HALF_BLOCKS].len = last_len;
                    inputs
                },
                blocks,
            },
        );
        // One thread's values, the whole batch laid out at once.
        let mut expected = LaidOutPoints::default();
        sink.clear(&mut expected, blocks);
        for (half, inputs) in offer.inputs.iter().enumerate() {
            let used = blocks.saturating_sub(half * HALF_BLOCKS).min(HALF_BLOCKS);
            let mut outputs = vec![OutputBlock::default(); used];
            process_blocks(&derived, offer.reads, &inputs[..used], &mut outputs);
            outputs
                .iter()
                .for_each(|block| sink.lay_out(block, &mut expected));
        }
        let expected = expected.values().to_vec();
        // The helper's work, done here: every chunk in order, each placed.
        light_chunks(
            &job,
            &offer,
            &mut Box::new([OutputBlock::default(); CHUNK_BLOCKS]),
        );
        let mut end = START;
        let mut scratch = vec![OutputBlock::default(); 2 * HALF_BLOCKS];
        collect(&job, offer, &mut Offers::default(), &mut scratch, |lit| {
            match lit {
                Lit::Placed { end: placed } => end = placed,
                _ => panic!("a chunk not placed"),
            }
            end
        });
        let values = places.read();
        assert_eq!(end, START + expected.len(), "where the values end");
        assert!(values[START..end] == expected[..], "the values placed");
        assert!(
            values[..START]
                .iter()
                .chain(&values[end..])
                .all(|&v| v == UNWRITTEN),
            "nothing written elsewhere"
        );
    }
}
