//! Measures the f64 round-trip accuracy of the basis-change matrices and the time to build
//! them the first time (the numbers quoted in `cagd_core::basis`'s docs).
//!
//! `cargo run -p cagd-core --example basis_accuracy` (add `--profile test` to reproduce the
//! test-profile build times).

use std::time::Instant;

use cagd_core::{Basis, convert_points, from_bernstein, from_bernstein_exact, to_bernstein};

/// A small deterministic generator (xorshift) of values in [-1, 1].
fn rng(state: &mut u64) -> f64 {
    *state ^= *state << 13;
    *state ^= *state >> 7;
    *state ^= *state << 17;
    (*state >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
}

fn round_trip_error(
    basis: Basis,
    n: usize,
    reverse: bool,
    seed: &mut u64,
) -> Result<f64, cagd_core::Error> {
    let (mut to, mut from) = (to_bernstein(basis, n)?, from_bernstein(basis, n)?);
    if reverse {
        std::mem::swap(&mut to, &mut from);
    }
    let mut worst = 0.0f64;
    for _ in 0..20 {
        let c: Vec<f64> = (0..=n).map(|_| rng(seed)).collect();
        let b = convert_points(&to, &c, 1)?;
        let back = convert_points(&from, &b, 1)?;
        let scale = c.iter().fold(0.0f64, |m, x| m.max(x.abs()));
        let err = c
            .iter()
            .zip(&back)
            .fold(0.0f64, |m, (x, y)| m.max((x - y).abs()));
        worst = worst.max(err / scale);
    }
    Ok(worst)
}

fn main() -> Result<(), cagd_core::Error> {
    let bases = [
        ("Power", Basis::Power),
        ("Chebyshev", Basis::Chebyshev),
        ("Legendre", Basis::Legendre),
        ("SaidBall", Basis::SaidBall),
        ("WangBall", Basis::WangBall),
    ];
    println!("build time of to + from (exact + f64), first call:");
    for n in [16usize, 32, 48, 64] {
        let mut line = format!("n = {n:2}:");
        for (name, b) in bases {
            let t0 = Instant::now();
            to_bernstein(b, n)?;
            from_bernstein(b, n)?;
            line += &format!(" {name} {:.3} s,", t0.elapsed().as_secs_f64());
        }
        let t0 = Instant::now();
        from_bernstein_exact(Basis::Wsgb { l: n / 4 }, n)?;
        line += &format!(" Wsgb(l={}) {:.3} s", n / 4, t0.elapsed().as_secs_f64());
        println!("{line}");
    }
    for reverse in [false, true] {
        if reverse {
            println!("\nf64 round trip to * (from * b), max|err| / max|b|, worst of 20:");
        } else {
            println!("\nf64 round trip from * (to * c), max|err| / max|c|, worst of 20:");
        }
        println!("| n | Power | Chebyshev | Legendre | Said–Ball | Wang–Ball |");
        let mut seed = 0x9e37_79b9_7f4a_7c15u64;
        for n in [1usize, 5, 10, 15, 20, 25, 30, 40, 50, 64] {
            let mut line = format!("| {n} |");
            for (_, b) in bases {
                line += &format!(" {:.1e} |", round_trip_error(b, n, reverse, &mut seed)?);
            }
            println!("{line}");
        }
    }
    println!("\ncondition number |to|_inf |from|_inf:");
    for n in [10usize, 20, 30, 40, 64] {
        let mut line = format!("| {n} |");
        for (_, b) in bases {
            let norm = |m: &nalgebra::DMatrix<f64>| {
                m.row_iter()
                    .map(|r| r.iter().map(|x| x.abs()).sum::<f64>())
                    .fold(0.0f64, f64::max)
            };
            let k = norm(&*to_bernstein(b, n)?) * norm(&*from_bernstein(b, n)?);
            line += &format!(" {k:.1e} |");
        }
        println!("{line}");
    }
    Ok(())
}
