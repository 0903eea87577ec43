//! Large draws on several threads with their primitives in order: helper threads fetch and
//! light chunks of blocks while the calling thread streams the lit chunks into assembly and
//! feedback, chunk after chunk, exactly as one thread would. Each helper works through every
//! `helpers`-th chunk with two chunk buffers that the calling thread hands back once
//! streamed, so the working set is fixed whatever the draw's size.

use std::sync::mpsc::{Receiver, SyncSender, sync_channel};

use super::block::{InputBlock, OutputBlock};
use super::vertex::DerivedState;
use crate::lighting::batch::process_blocks;

/// Blocks per chunk: a helper's unit of work (2048 vertices, about 230 KiB of lit blocks;
/// large enough that handing chunks over costs little next to lighting them).
const CHUNK_BLOCKS: usize = 256;

/// Chunk buffers per helper: one being lit while the other is streamed.
const BUFFERS_PER_HELPER: usize = 2;

/// A helper's channels, seen from the calling thread: lit chunks in, streamed chunks back.
type HelperLane = (Receiver<Vec<OutputBlock>>, SyncSender<Vec<OutputBlock>>);

/// Lights `blocks` blocks on `helpers` threads and gives them to `stream` in order on the
/// calling thread. `fill(block, input)` puts block `block`'s vertices into `input` (which
/// starts as `template`, and keeps what `fill` leaves there).
pub fn light_in_order(
    derived: &DerivedState,
    template: &InputBlock,
    blocks: usize,
    helpers: usize,
    fill: impl Fn(usize, &mut InputBlock) + Sync,
    mut stream: impl FnMut(&OutputBlock),
) {
    let chunks = blocks.div_ceil(CHUNK_BLOCKS);
    let helpers = helpers.clamp(1, chunks.max(1));
    std::thread::scope(|scope| {
        let mut lanes: Vec<HelperLane> = Vec::with_capacity(helpers);
        for helper in 0..helpers {
            let (lit_tx, lit_rx) = sync_channel(BUFFERS_PER_HELPER);
            let (free_tx, free_rx) = sync_channel(BUFFERS_PER_HELPER);
            for _ in 0..BUFFERS_PER_HELPER {
                free_tx
                    .send(vec![OutputBlock::default(); CHUNK_BLOCKS])
                    .expect("the receiver is here");
            }
            let fill = &fill;
            scope.spawn(move || {
                let mut inputs = [*template; CHUNK_BLOCKS];
                for chunk in (helper..chunks).step_by(helpers) {
                    // The calling thread stopped taking chunks: it is unwinding.
                    let Ok(mut outputs) = free_rx.recv() else {
                        return;
                    };
                    let first = chunk * CHUNK_BLOCKS;
                    let len = CHUNK_BLOCKS.min(blocks - first);
                    for (k, input) in inputs[..len].iter_mut().enumerate() {
                        fill(first + k, input);
                    }
                    outputs.truncate(len);
                    process_blocks(derived, &inputs[..len], &mut outputs);
                    if lit_tx.send(outputs).is_err() {
                        return;
                    }
                }
            });
            lanes.push((lit_rx, free_tx));
        }
        for chunk in 0..chunks {
            let (lit, free) = &lanes[chunk % helpers];
            let mut outputs = lit.recv().expect("a helper lights every chunk it is given");
            outputs.iter().for_each(&mut stream);
            outputs.resize(CHUNK_BLOCKS, OutputBlock::default());
            // The helper may have finished its last chunk and gone.
            let _ = free.send(outputs);
        }
    });
}
