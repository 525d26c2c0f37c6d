//! The thread count of the batch calls: `n_threads <= 1` runs on the calling thread;
//! more runs the blocks of a batch on a rayon pool of exactly that many worker threads,
//! started on first use and kept for the life of the process (starting threads costs tens
//! of microseconds, as much as a batch of thousands of small curves), one pool per count.
//!
//! rayon rather than hand-made `std::thread::scope` workers: work stealing balances
//! blocks of unequal cost, and a C++ kernel that already uses rayon through another
//! library shares its design.

use std::collections::HashMap;
use std::sync::{Arc, Mutex, OnceLock, PoisonError};

use rayon::prelude::*;
use rayon::{ThreadPool, ThreadPoolBuilder};

/// The most worker threads a pool gets; larger counts are clamped (a batch call never
/// needs more threads than a machine has cores, and each pool lives for the process).
pub(super) const MAX_THREADS: usize = 256;

/// The pool of `n` worker threads (`2 <= n <= MAX_THREADS`), started on first use; `None`
/// when the operating system refuses the threads.
fn pool(n: usize) -> Option<Arc<ThreadPool>> {
    static POOLS: OnceLock<Mutex<HashMap<usize, Arc<ThreadPool>>>> = OnceLock::new();
    let pools = POOLS.get_or_init(|| Mutex::new(HashMap::new()));
    // A poisoned lock only means another thread panicked while inserting: the map is still
    // valid.
    let mut map = pools.lock().unwrap_or_else(PoisonError::into_inner);
    if let Some(p) = map.get(&n) {
        return Some(Arc::clone(p));
    }
    let p = Arc::new(
        ThreadPoolBuilder::new()
            .num_threads(n)
            .thread_name(|i| format!("cagd-batch-{i}"))
            .build()
            .ok()?,
    );
    map.insert(n, Arc::clone(&p));
    Some(p)
}

/// The number of blocks to cut a batch of `items` items into for `n_threads` threads:
/// 1 on one thread; otherwise about four blocks per thread (so that work stealing can
/// even out unequal blocks), none smaller than `min_block` items.
pub(super) fn block_count(n_threads: usize, items: usize, min_block: usize) -> usize {
    if n_threads <= 1 {
        return 1;
    }
    let t = n_threads.min(MAX_THREADS);
    (4 * t).min(items / min_block.max(1)).max(1)
}

/// Runs `f` on every block: on the calling thread when `n_threads <= 1`, there is one
/// block, or the pool cannot be started; otherwise on the pool of `n_threads` threads
/// (clamped to [`MAX_THREADS`]). Returns the results in block order.
pub(super) fn run_blocks<B, R, F>(n_threads: usize, blocks: Vec<B>, f: F) -> Vec<R>
where
    B: Send,
    R: Send,
    F: Fn(B) -> R + Sync,
{
    if n_threads > 1 && blocks.len() > 1 {
        if let Some(p) = pool(n_threads.min(MAX_THREADS)) {
            return p.install(|| blocks.into_par_iter().map(&f).collect());
        }
    }
    blocks.into_iter().map(f).collect()
}

/// `[start, end)` of block `b` of `blocks` equal blocks over `items` items (the first
/// `items % blocks` blocks get one more).
pub(super) fn block_range(b: usize, blocks: usize, items: usize) -> (usize, usize) {
    let (q, r) = (items / blocks, items % blocks);
    let start = b * q + b.min(r);
    (start, start + q + usize::from(b < r))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn blocks_cover_the_items_exactly_once() {
        for items in [0usize, 1, 7, 100, 1001] {
            for blocks in 1..=9 {
                let mut next = 0;
                for b in 0..blocks {
                    let (s, e) = block_range(b, blocks, items);
                    assert_eq!(s, next, "{items} {blocks} {b}");
                    assert!(e >= s && e - s <= items / blocks + 1);
                    next = e;
                }
                assert_eq!(next, items);
            }
        }
    }

    #[test]
    fn block_count_respects_threads_and_minimum() {
        assert_eq!(block_count(0, 1_000_000, 64), 1);
        assert_eq!(block_count(1, 1_000_000, 64), 1);
        assert_eq!(block_count(2, 1_000_000, 64), 8);
        assert_eq!(block_count(2, 100, 64), 1);
        assert_eq!(block_count(2, 300, 64), 4);
        assert_eq!(block_count(usize::MAX, 1 << 40, 1), 4 * MAX_THREADS);
    }

    #[test]
    fn blocks_run_on_the_pool_and_keep_their_order() {
        let main = std::thread::current().id();
        let out = run_blocks(2, (0..16).collect(), |b: i32| {
            (b * b, std::thread::current().id() != main)
        });
        assert_eq!(
            out.iter().map(|r| r.0).collect::<Vec<_>>(),
            (0..16).map(|b| b * b).collect::<Vec<_>>()
        );
        assert!(out.iter().all(|r| r.1), "every block ran on a pool thread");
        let seq = run_blocks(1, vec![1, 2], |b: i32| {
            (b, std::thread::current().id() == main)
        });
        assert_eq!(seq, vec![(1, true), (2, true)]);
    }
}
