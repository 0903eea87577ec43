//! Whether immediate mode shares a primitive's batches with the helper thread where neither
//! way is faster on every machine: with one light, lighting a vertex costs about what the
//! application's thread loses to writing blocks the helper has just read. On the Xeon of
//! stops 23-27 sharing wins (immediate 1 light, 2 threads: 59.5 -> 51 ns/vertex, 8 of 8
//! alternating pairs); on an AMD EPYC it lost (20.9 -> 23.3). So each context tries both
//! and keeps the faster: a trial of each way, timed over its big primitives, then the
//! winner for `KEPT_TRIALS` trials, then both again, the winner first. A way that wins again
//! is kept twice as long the next time (up to `MOST_KEPT_TRIALS`): each comparison lights a
//! trial the slower way, and the first primitive of each change is not counted, which cost
//! the 1-light immediate scene (16K-vertex trials of 4096-vertex primitives) about a tenth of
//! its time against always sharing on the Emerald Rapids Xeon (17.5 against 15.6 ns/vertex).
//!
//! Only primitives that follow a big one are timed (two clock readings, at glBegin and
//! glEnd), and only big ones count: a program of small primitives reads no clock, and the
//! time between primitives (the application's own work, other draws, waiting for a frame)
//! is not measured. The first trial shares, so that a short program (or test) sees the
//! helper at work whatever the machine. The first big primitive of a way is not counted: it
//! pays for the change (the batches of the other way still in flight, the helper starting,
//! waking or still watching for batches). Counted, they made the first trial of sharing take
//! 42 ns a vertex against 12-13 after it, and each trial alone 17-25 against 14 on one thread
//! (1 light on the model 167 Xeon): alone was kept first, then tried again every 16 trials.

use std::time::{Duration, Instant};

/// Vertices of a primitive from which its batches can be shared (one batch's).
const BIG_PRIMITIVE: u64 = 1024;

/// Vertices of timed primitives a trial counts: about a millisecond's work.
const TRIAL_VERTICES: u64 = 16 * 1024;

/// Trials of the faster way before both are tried again, after it first wins.
const KEPT_TRIALS: u32 = 15;

/// The most trials a way that keeps winning is kept for (each win again: twice as many and
/// one): some 64 ms of lighting at 15 ns a vertex between two comparisons.
const MOST_KEPT_TRIALS: u32 = 255;

/// The way a primitive's batches are lit.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Way {
    /// On the application's thread, in batches that stay in the first-level cache.
    Alone,
    /// Offered to the helper thread, which lights and lays out what it can.
    Shared,
}

impl Way {
    fn other(self) -> Way {
        match self {
            Way::Alone => Way::Shared,
            Way::Shared => Way::Alone,
        }
    }

    fn index(self) -> usize {
        self as usize
    }
}

/// When a primitive whose way was chosen began, if it is timed.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Timing(Option<Instant>);

/// A context's choice of way, and the trials behind it.
#[derive(Clone, Debug)]
pub(crate) struct SharingChoice {
    /// The way of the trial in progress.
    way: Way,
    /// The timed vertices and their time in the trial in progress.
    vertices: u64,
    elapsed: Duration,
    /// Each way's time per vertex in this round of comparison (seconds), once tried.
    tried: [Option<f64>; 2],
    /// Trials of `way`, the faster, still to go before the next comparison (0: comparing).
    kept: u32,
    /// Trials the last comparison's winner was kept for (0 before the first comparison).
    last_kept: u32,
    /// Whether the last primitive was big: the next one is timed.
    after_big: bool,
    /// Whether the next big timed primitive is the first of `way`, which is not counted.
    settling: bool,
}

impl Default for SharingChoice {
    fn default() -> SharingChoice {
        SharingChoice {
            way: Way::Shared,
            vertices: 0,
            elapsed: Duration::ZERO,
            tried: [None; 2],
            kept: 0,
            last_kept: 0,
            after_big: true,
            settling: true,
        }
    }
}

impl SharingChoice {
    /// glBegin of a primitive whose way is to be chosen: the way, and when it began if it is
    /// timed.
    pub(crate) fn begin(&self) -> (Way, Timing) {
        (self.way, Timing(self.after_big.then(Instant::now)))
    }

    /// glEnd of such a primitive, of `vertices` vertices.
    pub(crate) fn end(&mut self, timing: Timing, vertices: u64) {
        self.after_big = vertices >= BIG_PRIMITIVE;
        if let Timing(Some(began)) = timing {
            self.timed(began.elapsed(), vertices);
        }
    }

    /// A timed primitive of `vertices` vertices took `elapsed`.
    fn timed(&mut self, elapsed: Duration, vertices: u64) {
        if vertices < BIG_PRIMITIVE {
            return;
        }
        if self.settling {
            self.settling = false;
            return;
        }
        self.vertices += vertices;
        self.elapsed += elapsed;
        if self.vertices < TRIAL_VERTICES {
            return;
        }
        let per_vertex = self.elapsed.as_secs_f64() / self.vertices as f64;
        self.vertices = 0;
        self.elapsed = Duration::ZERO;
        if self.kept > 0 {
            self.kept -= 1;
            if self.kept == 0 {
                // The next round begins with the way kept, this trial its measure.
                self.tried = [None; 2];
                self.tried[self.way.index()] = Some(per_vertex);
                self.switch(self.way.other());
            }
            return;
        }
        self.tried[self.way.index()] = Some(per_vertex);
        match self.tried {
            [Some(alone), Some(shared)] => {
                let way = if shared < alone {
                    Way::Shared
                } else {
                    Way::Alone
                };
                // A round after the first begins with the way kept and ends with a trial of
                // the other, this one: the kept way won again unless this one won.
                self.kept = if self.last_kept > 0 && way != self.way {
                    (2 * self.last_kept + 1).min(MOST_KEPT_TRIALS)
                } else {
                    KEPT_TRIALS
                };
                self.last_kept = self.kept;
                self.switch(way);
            }
            _ => self.switch(self.way.other()),
        }
    }

    /// Lights the next primitives `way`, its first big one not counted if that is a change.
    fn switch(&mut self, way: Way) {
        self.settling = way != self.way;
        self.way = way;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A trial's worth of big primitives of `way`, each taking `micros` per 1024 vertices.
    fn trial(choice: &mut SharingChoice, micros: u64) {
        let settling = u64::from(choice.settling);
        for _ in 0..TRIAL_VERTICES / BIG_PRIMITIVE + settling {
            choice.timed(Duration::from_micros(micros), BIG_PRIMITIVE);
        }
    }

    /// Shared first, then alone; the faster is kept for `KEPT_TRIALS` trials, the last of
    /// which is the next comparison's measure of it; then the other is tried again.
    #[test]
    fn the_faster_way_is_kept_and_compared_again_later() {
        let mut choice = SharingChoice::default();
        assert_eq!(choice.way, Way::Shared);
        trial(&mut choice, 60);
        assert_eq!(choice.way, Way::Alone);
        trial(&mut choice, 50);
        assert_eq!(choice.way, Way::Alone, "alone was faster");
        for _ in 1..KEPT_TRIALS {
            trial(&mut choice, 50);
            assert_eq!(choice.way, Way::Alone);
        }
        trial(&mut choice, 50);
        assert_eq!(choice.way, Way::Shared, "compared again");
        // The machine changed: sharing now wins.
        trial(&mut choice, 40);
        assert_eq!(choice.way, Way::Shared);
        assert_eq!(choice.kept, KEPT_TRIALS);
    }

    /// A way that wins again is kept twice as long (and one trial), up to
    /// `MOST_KEPT_TRIALS`; when the other wins, it is kept `KEPT_TRIALS`.
    #[test]
    fn a_way_that_wins_again_is_kept_longer() {
        let mut choice = SharingChoice::default();
        trial(&mut choice, 40);
        trial(&mut choice, 50);
        assert_eq!((choice.way, choice.kept), (Way::Shared, KEPT_TRIALS));
        let mut kept = Vec::new();
        for _ in 0..6 {
            // The kept trials of sharing, then the comparison's trial alone, slower again.
            while choice.kept > 0 {
                trial(&mut choice, 40);
            }
            assert_eq!(choice.way, Way::Alone, "compared again");
            trial(&mut choice, 50);
            assert_eq!(choice.way, Way::Shared);
            kept.push(choice.kept);
        }
        assert_eq!(kept, [31, 63, 127, 255, 255, 255]);
        // Alone wins: kept for as long as the first time.
        while choice.kept > 0 {
            trial(&mut choice, 40);
        }
        trial(&mut choice, 30);
        assert_eq!((choice.way, choice.kept), (Way::Alone, KEPT_TRIALS));
    }

    /// The first big primitive of each way, however slow, counts for nothing.
    #[test]
    fn the_first_primitive_of_a_way_is_not_counted() {
        let mut choice = SharingChoice::default();
        // Sharing's first primitive starts the helper: ten times slower, not counted.
        choice.timed(Duration::from_micros(600), BIG_PRIMITIVE);
        for _ in 0..TRIAL_VERTICES / BIG_PRIMITIVE {
            choice.timed(Duration::from_micros(40), BIG_PRIMITIVE);
        }
        assert_eq!(choice.way, Way::Alone);
        // Alone's first, slowed by the batches still shared, not counted either.
        choice.timed(Duration::from_micros(600), BIG_PRIMITIVE);
        for _ in 0..TRIAL_VERTICES / BIG_PRIMITIVE {
            choice.timed(Duration::from_micros(50), BIG_PRIMITIVE);
        }
        assert_eq!(choice.way, Way::Shared, "sharing was faster");
        assert_eq!(choice.kept, KEPT_TRIALS);
        // Back to sharing: its first primitive is not counted; then every one is.
        assert!(choice.settling);
        choice.timed(Duration::from_micros(600), BIG_PRIMITIVE);
        assert!(!choice.settling);
        choice.timed(Duration::from_micros(40), BIG_PRIMITIVE);
        assert_eq!(choice.vertices, BIG_PRIMITIVE);
    }

    /// In feedback mode on more than one thread, a primitive is offered to the helper in
    /// batches of 128 blocks with two lights, and with one in a context's first trial (timed
    /// from its start); unlit, it is lit alone, in batches of `LONE_BATCH_BLOCKS`.
    #[test]
    fn one_light_shares_in_the_first_trial() {
        use crate::gl::*;
        let batch_of = |lights: u32| {
            let mut ctx = crate::Context::new();
            ctx.set_capability(GL_LIGHTING, lights > 0).unwrap();
            for light in 0..lights {
                ctx.set_capability(GL_LIGHT0 + light, true).unwrap();
            }
            ctx.feedback_buffer(64, GL_3D_COLOR, 1).unwrap();
            ctx.render_mode(GL_FEEDBACK).unwrap();
            ctx.begin(GL_POINTS).unwrap();
            let primitive = ctx.primitive.as_ref().expect("begun");
            let batch = (
                primitive.batch,
                primitive.timing.is_some_and(|t| t.0.is_some()),
            );
            ctx.end().unwrap();
            batch
        };
        let shared = 2 * super::super::HALF_BLOCKS;
        if crate::threads::thread_count() > 1 {
            assert_eq!(batch_of(1), (shared, true));
        }
        assert_eq!(batch_of(2), (shared, false));
        assert_eq!(batch_of(0), (super::super::LONE_BATCH_BLOCKS, false));
    }

    /// Small primitives count for nothing and are not timed after a small one; a big one
    /// makes the next timed.
    #[test]
    fn only_big_primitives_count_and_only_after_a_big_one_is_the_clock_read() {
        let mut choice = SharingChoice::default();
        for _ in 0..10 * TRIAL_VERTICES {
            choice.timed(Duration::from_secs(1), BIG_PRIMITIVE - 1);
        }
        assert_eq!((choice.way, choice.vertices), (Way::Shared, 0));
        let (_, timing) = choice.begin();
        assert!(timing.0.is_some(), "the first primitive is timed");
        choice.end(timing, 3);
        let (_, timing) = choice.begin();
        assert!(timing.0.is_none(), "not timed after a small one");
        choice.end(timing, 2 * BIG_PRIMITIVE);
        assert_eq!(
            choice.vertices, 0,
            "an untimed primitive counts for nothing"
        );
        assert!(choice.begin().1.0.is_some(), "timed after a big one");
    }
}
