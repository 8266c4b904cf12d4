//! The plain-f64 loop of deep zoom: pixels whose offset and difference are in f64's range and
//! that want no derivative iterate here, with the bilinear steps in f64 and nothing else per
//! iteration but the escape and rebase tests.
//!
//! One pixel's iterations form a chain of dependent multiplications; the loop keeps several
//! pixels in flight ([`LANES`] at once, each with its own reference index, count and
//! difference) so that the processor overlaps their chains. The arithmetic of each pixel is
//! exactly that of one pixel alone: the interleaving changes the time, not the bits.
//!
//! The lanes are scalar code (the compiler does not put them in vector registers). Measured on
//! seahorse valley at 1e-25 (30,000 iterations, an AMD Zen 4 under load): eight lanes in
//! AVX-512 registers, with the bilinear search and single steps blended lane by lane, took
//! 10 % more CPU time than these four scalar lanes, since every read of the orbit or the table
//! is a gather (each lane at its own index) and gathers are slow there; the same with the
//! bilinear steps left to scalar code took 3 % less (within the load's noise), and eight
//! scalar lanes 16 % more.

use super::bla::Bla;
use super::complex::C;
use super::deep::Map;
use super::family::IterSettings;

/// Pixels iterated side by side.
pub const LANES: usize = 4;

/// The orbits a pixel iterates around: the one it starts on and the one it rebases onto.
#[derive(Clone, Copy)]
pub struct Orbits<'a> {
    pub main: (&'a [C], &'a Bla),
    pub base: (&'a [C], &'a Bla),
}

/// One pixel in flight.
#[derive(Clone, Copy, Debug)]
pub struct Lane {
    /// Reference index, iterations done, on the rebase orbit.
    pub m: usize,
    pub n: u32,
    pub on_base: bool,
    /// Difference from the reference and the offset added each step.
    pub d: C,
    pub dc: C,
}

/// How a pixel ended: escaped at iteration n with full value z (|z|² = r2), or inside.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum End {
    Escaped { n: u32, z: C, r2: f64 },
    Inside,
}

/// |a + b| − |a| computed without cancellation when b is much smaller than a (Kalles
/// Fraktaler's "diffabs").
#[inline(always)]
pub fn diffabs(a: f64, b: f64) -> f64 {
    if a >= 0.0 {
        if a + b >= 0.0 { b } else { -(2.0 * a + b) }
    } else if a + b > 0.0 {
        2.0 * a + b
    } else {
        -b
    }
}

/// One perturbed step of the Burning Ship around the reference point Z = X + iY: the
/// difference d = x + iy becomes
///
/// ```text
/// Re: (2X + x)·x − (2Y + y)·y + Re δc,
/// Im: 2·diffabs(XY, X·y + x·(Y + y)) + Im δc,
/// ```
///
/// since 2|X + x||Y + y| − 2|X||Y| = 2(|XY + t| − |XY|) with t = (X + x)(Y + y) − XY.
#[inline(always)]
pub fn ship_step(z: C, d: C, dc: C) -> C {
    let (x, y) = (d.re, d.im);
    C::new(
        (2.0 * z.re + x) * x - (2.0 * z.im + y) * y + dc.re,
        2.0 * diffabs(z.re * z.im, z.re * y + x * (z.im + y)) + dc.im,
    )
}

/// The maps as const-generic parameters.
const SQUARE: u8 = 0;
const CUBE: u8 = 1;
const SHIP: u8 = 2;

/// One step (bilinear or single) of a lane; Some when the pixel has ended.
#[inline(always)]
fn step<const MAP: u8>(o: &Orbits, l: &mut Lane, s: &IterSettings) -> Option<End> {
    if l.n >= s.max_iter {
        return Some(End::Inside);
    }
    let (z, bla) = if l.on_base { o.base } else { o.main };
    let d = l.d;
    let skip = if l.m & 1 == 1 {
        bla.find_plain(l.m, d.re.abs() + d.im.abs(), s.max_iter - l.n)
    } else {
        None
    };
    let (d, m) = match skip {
        Some((a, b, len)) => {
            l.n += len;
            (a * d + b * l.dc, l.m + len as usize)
        }
        None => {
            let zm = z[l.m];
            l.n += 1;
            let d = match MAP {
                CUBE => d * (zm * zm * 3.0 + d * (zm * 3.0 + d)) + l.dc,
                SHIP => ship_step(zm, d, l.dc),
                _ => d * (zm * 2.0 + d) + l.dc,
            };
            (d, l.m + 1)
        }
    };
    let full = z[m] + d;
    let r2 = full.norm2();
    if s.escaped(r2) {
        return Some(End::Escaped {
            n: l.n,
            z: full,
            r2,
        });
    }
    if r2 < d.norm2() || m == z.len() - 1 {
        l.d = full;
        l.m = 0;
        l.on_base = true;
    } else {
        l.d = d;
        l.m = m;
    }
    None
}

/// Iterate the pixels `next()` hands out, LANES at a time, to their ends; `done(id, end)`
/// receives each (in the order they end).
pub fn run<T: Copy>(
    o: &Orbits,
    map: Map,
    s: &IterSettings,
    next: impl FnMut() -> Option<(T, Lane)>,
    done: impl FnMut(T, End),
) {
    match map {
        Map::Square => run_lanes::<T, SQUARE>(o, s, next, done),
        Map::Cube => run_lanes::<T, CUBE>(o, s, next, done),
        Map::Ship => run_lanes::<T, SHIP>(o, s, next, done),
    }
}

fn run_lanes<T: Copy, const MAP: u8>(
    o: &Orbits,
    s: &IterSettings,
    mut next: impl FnMut() -> Option<(T, Lane)>,
    mut done: impl FnMut(T, End),
) {
    let mut lanes: [Option<(T, Lane)>; LANES] = [None; LANES];
    for slot in lanes.iter_mut() {
        *slot = next();
    }
    while lanes.iter().any(Option::is_some) {
        // All lanes full: step them in turn until one ends, then refill it.
        if let [Some(a), Some(b), Some(c), Some(d)] = &mut lanes {
            let (k, id, e) = loop {
                if let Some(e) = step::<MAP>(o, &mut a.1, s) {
                    break (0, a.0, e);
                }
                if let Some(e) = step::<MAP>(o, &mut b.1, s) {
                    break (1, b.0, e);
                }
                if let Some(e) = step::<MAP>(o, &mut c.1, s) {
                    break (2, c.0, e);
                }
                if let Some(e) = step::<MAP>(o, &mut d.1, s) {
                    break (3, d.0, e);
                }
            };
            done(id, e);
            lanes[k] = next();
            continue;
        }
        // The last few pixels.
        for slot in lanes.iter_mut() {
            if let Some((id, lane)) = slot
                && let Some(e) = step::<MAP>(o, lane, s)
            {
                done(*id, e);
                *slot = next();
            }
        }
    }
}
