//! Helpers of the dimension tests.

use crate::explore::P2;
use crate::flame::rng::FastRng;

pub(super) fn close(a: f64, b: f64, tol: f64) -> bool {
    (a - b).abs() <= tol
}

pub(super) fn random_points(n: usize, seed: u64, f: impl Fn(f64, f64) -> P2) -> Vec<P2> {
    let mut r = FastRng::new(seed);
    (0..n).map(|_| f(r.f01(), r.f01())).collect()
}
