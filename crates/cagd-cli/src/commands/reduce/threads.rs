//! `cagd reduce --threads N`: the input objects reduced on `N` threads (rayon), each
//! object on its own, the outputs and the first failure (in input order) exactly those of
//! the one-thread run.

use rayon::prelude::*;

use crate::commands::args::ReduceArgs;
use crate::commands::reduce::{Failure, Output};
use crate::input::shape::Shape;

/// The signature of a whole `reduce` run (`run` or `polynomial::run`): one output per
/// input object.
pub(crate) type Run = fn(&[(String, Shape)], &ReduceArgs) -> Result<Vec<Output>, Failure>;

/// Runs `run` on `shapes` with `args.threads` threads: on the calling thread when it is 0
/// or 1, when there is at most one object, or when the threads cannot be started;
/// otherwise every object separately on a pool of that many threads. A run of one object
/// is what the whole run does to it (the runs keep no state across objects), so the
/// outputs are the same, and the failure reported is that of the first failing object.
pub(crate) fn run_on_threads(
    run: Run,
    shapes: &[(String, Shape)],
    args: &ReduceArgs,
) -> Result<Vec<Output>, Failure> {
    if args.threads <= 1 || shapes.len() <= 1 {
        return run(shapes, args);
    }
    let Ok(pool) = rayon::ThreadPoolBuilder::new()
        .num_threads(args.threads)
        .build()
    else {
        return run(shapes, args);
    };
    let each: Vec<Result<Vec<Output>, Failure>> =
        pool.install(|| shapes.par_chunks(1).map(|one| run(one, args)).collect());
    let mut out = Vec::with_capacity(shapes.len());
    for r in each {
        out.extend(r?);
    }
    Ok(out)
}
