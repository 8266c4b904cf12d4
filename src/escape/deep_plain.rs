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
//! scalar lanes 16 % more. The same scalar code compiled for AVX-512 (its 32 registers hold
//! the lanes' state), with the first level's radius read by index before any search, took
//! 10 % less CPU time than compiled for SSE2 with the search entered at every odd index
//! (320×240, 2.62 s against 2.92 s, three runs each, load 8); six lanes then took 2.91 s and
//! eight 3.04 s.
//!
//! For z² + c the steps are quadratic ([`super::bla_quad`]): on the same view at 640×480 on
//! one thread they took 2.5–2.6 s CPU against the bilinear steps' 10.2–11.1 s (run back to
//! back, load 8–10), since a pixel of its 16×12 grid then takes about 570 single steps and
//! 190 merged ones on average instead of 3,900 and 730.

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

/// One step (bilinear or single) of a lane; Some when the pixel has ended. STRICT: the
/// bailout test of [`IterSettings::escaped`] with `s.strict`.
#[inline(always)]
fn step<const MAP: u8, const STRICT: bool>(
    o: &Orbits,
    l: &mut Lane,
    s: &IterSettings,
) -> Option<End> {
    if l.n >= s.max_iter {
        return Some(End::Inside);
    }
    let (z, bla) = if l.on_base { o.base } else { o.main };
    let d = l.d;
    let d1 = d.re.abs() + d.im.abs();
    // Most iterations that take no step stop at the first level's radius (0 at even m).
    let skip = if d1 < bla.first_radius(l.m) {
        bla.find_plain(l.m, d1, s.max_iter - l.n)
    } else {
        None
    };
    let (d, m) = match skip {
        Some((k, j, len)) => {
            l.n += len;
            let [a, b] = bla.plain_linear(k, j);
            let d = if MAP == SQUARE {
                // A·δ + B·δc + C·δ² + D·δ·δc + E·δc² (each coefficient multiplies first: no
                // square of a tiny difference underflows before a large coefficient).
                let [c, dd, e] = bla.plain_quad(k, j);
                (a + c * d + dd * l.dc) * d + (b + e * l.dc) * l.dc
            } else {
                a * d + b * l.dc
            };
            (d, l.m + len as usize)
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
    land::<STRICT>(l, z, d, m, s)
}

/// The end of a lane's step that brought its difference to `d` at index `m` of its orbit `z`:
/// Some when the pixel escapes (STRICT: the bailout test of [`IterSettings::escaped`] with
/// `s.strict`); a rebase onto the base orbit's start when the full point is smaller than the
/// difference or the orbit ends; else the lane moves on.
#[inline(always)]
pub(super) fn land<const STRICT: bool>(
    l: &mut Lane,
    z: &[C],
    d: C,
    m: usize,
    s: &IterSettings,
) -> Option<End> {
    let full = z[m] + d;
    let r2 = full.norm2();
    let escaped = if STRICT {
        !(r2 <= s.bailout2)
    } else {
        !(r2 < s.bailout2)
    };
    if escaped {
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
    macro_rules! go {
        ($m:expr, $st:expr) => {
            run_isa::<T, $m, $st, LANES>(o, s, next, done)
        };
    }
    match (map, s.strict) {
        (Map::Square, false) => go!(SQUARE, false),
        (Map::Square, true) => go!(SQUARE, true),
        (Map::Cube, false) => go!(CUBE, false),
        (Map::Cube, true) => go!(CUBE, true),
        (Map::Ship, false) => go!(SHIP, false),
        (Map::Ship, true) => go!(SHIP, true),
    }
}

/// [`run_lanes`] compiled for the widest instruction set the processor has: the same
/// arithmetic (Rust fuses no multiply-add by itself, so every bit is kept), but with
/// AVX-512's 32 vector registers the lanes' state stays out of memory, and the three-operand
/// forms of AVX save register copies.
fn run_isa<T: Copy, const MAP: u8, const STRICT: bool, const N: usize>(
    o: &Orbits,
    s: &IterSettings,
    next: impl FnMut() -> Option<(T, Lane)>,
    done: impl FnMut(T, End),
) {
    #[cfg(target_arch = "x86_64")]
    {
        if std::is_x86_feature_detected!("avx512vl") {
            // SAFETY: the processor reports AVX-512 F and VL.
            return unsafe { run_avx512::<T, MAP, STRICT, N>(o, s, next, done) };
        }
        if std::is_x86_feature_detected!("avx2") {
            // SAFETY: the processor reports AVX2.
            return unsafe { run_avx2::<T, MAP, STRICT, N>(o, s, next, done) };
        }
    }
    run_lanes::<T, MAP, STRICT, N>(o, s, next, done)
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx512f,avx512vl,avx2")]
fn run_avx512<T: Copy, const MAP: u8, const STRICT: bool, const N: usize>(
    o: &Orbits,
    s: &IterSettings,
    next: impl FnMut() -> Option<(T, Lane)>,
    done: impl FnMut(T, End),
) {
    run_lanes::<T, MAP, STRICT, N>(o, s, next, done)
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
fn run_avx2<T: Copy, const MAP: u8, const STRICT: bool, const N: usize>(
    o: &Orbits,
    s: &IterSettings,
    next: impl FnMut() -> Option<(T, Lane)>,
    done: impl FnMut(T, End),
) {
    run_lanes::<T, MAP, STRICT, N>(o, s, next, done)
}

#[inline(always)]
fn run_lanes<T: Copy, const MAP: u8, const STRICT: bool, const N: usize>(
    o: &Orbits,
    s: &IterSettings,
    mut next: impl FnMut() -> Option<(T, Lane)>,
    mut done: impl FnMut(T, End),
) {
    let mut lanes: [Option<(T, Lane)>; N] = [None; N];
    for slot in lanes.iter_mut() {
        *slot = next();
    }
    while lanes.iter().any(Option::is_some) {
        // All lanes full: step them in turn until one ends, then refill it.
        if let Some(mut full) = all_some(&lanes) {
            let (k, e) = 'round: loop {
                for (k, lane) in full.iter_mut().enumerate() {
                    if let Some(e) = step::<MAP, STRICT>(o, &mut lane.1, s) {
                        break 'round (k, e);
                    }
                }
            };
            for (slot, lane) in lanes.iter_mut().zip(full) {
                *slot = Some(lane);
            }
            done(full[k].0, e);
            lanes[k] = next();
            continue;
        }
        // The last few pixels.
        for slot in lanes.iter_mut() {
            if let Some((id, lane)) = slot
                && let Some(e) = step::<MAP, STRICT>(o, lane, s)
            {
                done(*id, e);
                *slot = next();
            }
        }
    }
}

/// The lanes when every one holds a pixel.
#[inline(always)]
fn all_some<T: Copy, const N: usize>(lanes: &[Option<(T, Lane)>; N]) -> Option<[(T, Lane); N]> {
    let first = lanes[0]?;
    let mut out = [first; N];
    for (o, l) in out.iter_mut().zip(lanes) {
        *o = (*l)?;
    }
    Some(out)
}
