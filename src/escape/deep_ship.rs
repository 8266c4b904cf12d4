//! The plain-f64 loop of the Burning Ship's deep zoom: as [`super::deep_plain`] (pixels kept
//! in flight side by side, the same escape and rebase tests, the same arithmetic per pixel
//! whatever the interleaving), with the ship's matrix steps ([`super::bla_ship`]).

use super::bla_ship::{ShipBla, apply_plain};
use super::complex::C;
use super::deep_plain::{End, LANES, Lane, land, ship_step};
use super::family::IterSettings;

/// The orbits a pixel iterates around: the one it starts on and the one it rebases onto.
#[derive(Clone, Copy)]
pub struct ShipOrbits<'a> {
    pub main: (&'a [C], &'a ShipBla),
    pub base: (&'a [C], &'a ShipBla),
}

/// One step (bilinear or single) of a lane; Some when the pixel has ended. STRICT: the
/// bailout test of [`IterSettings::escaped`] with `s.strict`.
#[inline(always)]
fn step<const STRICT: bool>(o: &ShipOrbits, l: &mut Lane, s: &IterSettings) -> Option<End> {
    if l.n >= s.max_iter {
        return Some(End::Inside);
    }
    let (z, bla) = if l.on_base { o.base } else { o.main };
    let d = l.d;
    let d1 = d.re.abs() + d.im.abs();
    let skip = if d1 < bla.first_radius(l.m) {
        bla.find_plain(l.m, d1, s.max_iter - l.n)
    } else {
        None
    };
    let (d, m) = match skip {
        Some((k, len)) => {
            l.n += len;
            (apply_plain(k, d, l.dc), l.m + len as usize)
        }
        None => {
            l.n += 1;
            (ship_step(z[l.m], d, l.dc), l.m + 1)
        }
    };
    land::<STRICT>(l, z, d, m, s)
}

/// Iterate the pixels `next()` hands out, LANES at a time, to their ends; `done(id, end)`
/// receives each (in the order they end).
pub fn run<T: Copy>(
    o: &ShipOrbits,
    s: &IterSettings,
    next: impl FnMut() -> Option<(T, Lane)>,
    done: impl FnMut(T, End),
) {
    if s.strict {
        run_isa::<T, true>(o, s, next, done)
    } else {
        run_isa::<T, false>(o, s, next, done)
    }
}

/// [`run_lanes`] compiled for the widest instruction set the processor has (the same
/// arithmetic: Rust fuses no multiply-add by itself).
fn run_isa<T: Copy, const STRICT: bool>(
    o: &ShipOrbits,
    s: &IterSettings,
    next: impl FnMut() -> Option<(T, Lane)>,
    done: impl FnMut(T, End),
) {
    #[cfg(target_arch = "x86_64")]
    {
        if std::is_x86_feature_detected!("avx512vl") {
            // SAFETY: the processor reports AVX-512 F and VL.
            return unsafe { run_avx512::<T, STRICT>(o, s, next, done) };
        }
        if std::is_x86_feature_detected!("avx2") {
            // SAFETY: the processor reports AVX2.
            return unsafe { run_avx2::<T, STRICT>(o, s, next, done) };
        }
    }
    run_lanes::<T, STRICT>(o, s, next, done)
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx512f,avx512vl,avx2")]
fn run_avx512<T: Copy, const STRICT: bool>(
    o: &ShipOrbits,
    s: &IterSettings,
    next: impl FnMut() -> Option<(T, Lane)>,
    done: impl FnMut(T, End),
) {
    run_lanes::<T, STRICT>(o, s, next, done)
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
fn run_avx2<T: Copy, const STRICT: bool>(
    o: &ShipOrbits,
    s: &IterSettings,
    next: impl FnMut() -> Option<(T, Lane)>,
    done: impl FnMut(T, End),
) {
    run_lanes::<T, STRICT>(o, s, next, done)
}

#[inline(always)]
fn run_lanes<T: Copy, const STRICT: bool>(
    o: &ShipOrbits,
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
        if let Some(mut full) = all_some(&lanes) {
            let (k, e) = 'round: loop {
                for (k, lane) in full.iter_mut().enumerate() {
                    if let Some(e) = step::<STRICT>(o, &mut lane.1, s) {
                        break 'round (k, e);
                    }
                }
            };
            lanes = full.map(Some);
            done(full[k].0, e);
            lanes[k] = next();
            continue;
        }
        // The last few pixels.
        for slot in lanes.iter_mut() {
            if let Some((id, lane)) = slot
                && let Some(e) = step::<STRICT>(o, lane, s)
            {
                done(*id, e);
                *slot = next();
            }
        }
    }
}

/// The lanes when every one holds a pixel.
#[inline(always)]
fn all_some<T: Copy>(lanes: &[Option<(T, Lane)>; LANES]) -> Option<[(T, Lane); LANES]> {
    let first = lanes[0]?;
    let mut out = [first; LANES];
    for (o, l) in out.iter_mut().zip(lanes) {
        *o = (*l)?;
    }
    Some(out)
}
