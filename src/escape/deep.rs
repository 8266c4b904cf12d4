//! Deep zoom by perturbation for z² + c (the Mandelbrot set and its Julia sets), z³ + c and
//! the Burning Ship.
//!
//! One reference orbit Z at the view centre is computed in big binary fixed point at the
//! precision the zoom needs ([`orbit`]) and stored as f64; every pixel then iterates only its
//! difference δ from the reference,
//!
//! ```text
//! z²: δ(n+1) = 2·Z(n)·δ(n) + δ(n)² + δc,      z³: δ(n+1) = 3Z²δ + 3Zδ² + δ³ + δc,
//! ```
//!
//! (δc the pixel's offset from the centre for the Mandelbrot kind, 0 for Julia sets, which
//! start at δ(0) = the offset instead). The Burning Ship's fold is perturbed with Kalles
//! Fraktaler's diffabs form ([`deep_plain::ship_step`]). δ stays accurate because it is small where Z is not.
//! Where δ is too small for f64 (offsets below about 1e-300) it is kept as an extended-
//! exponent number ([`Cx`]) until it has grown into f64's range.
//!
//! Most iterations are skipped by bilinear approximation ([`super::bla`]; the Burning
//! Ship's, with real 2×2 matrices, [`super::bla_ship`]). Glitches are
//! avoided by rebasing (Zhuoran): when the pixel's orbit comes closer to 0 than its
//! difference (|Z + δ| < |δ|), or the reference ends, the pixel continues from the start of
//! an orbit that begins at 0 (δ := Z + δ, n_ref := 0): the reference itself for the
//! Mandelbrot kind, the critical orbit of 0 for a Julia set.

use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};

use dashu_int::IBig;

use super::bla::Bla;
use super::bla_ship::ShipBla;
use super::centre::{Centre, ibig_to_fx};
use super::complex::C;
use super::deep_plain;
use super::deep_ship;
use super::family::{IterSettings, Sample, ship_fold, smooth_count};
use super::fx::{Cx, Fx, ldexp};

/// Exponent (base 2) above which a difference is kept in f64.
const F64_FROM: i32 = -900;

/// The map a deep view iterates.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Map {
    /// z² + c.
    Square,
    /// z³ + c.
    Cube,
    /// The Burning Ship (|Re z| + i·|Im z|)² + c.
    Ship,
}

impl Map {
    /// The degree (for smooth colouring).
    pub fn degree(self) -> u32 {
        match self {
            Map::Cube => 3,
            Map::Square | Map::Ship => 2,
        }
    }
}

/// What the pixels of a deep view iterate around: an orbit and its bilinear table.
#[derive(Clone, Debug)]
pub struct Orbit {
    /// Z(0), Z(1), … until the orbit escaped or reached the iteration limit.
    pub z: Vec<C>,
    pub bla: Bla,
    /// The Burning Ship's bilinear table (empty for the other maps, whose table is `bla`).
    pub ship: ShipBla,
}

/// The reference of a deep view.
#[derive(Clone, Debug)]
pub struct Reference {
    /// The map iterated.
    pub map: Map,
    /// The orbit of the view centre: for the Mandelbrot kind the orbit of 0 under
    /// the map with C the centre, for a Julia set the orbit of the centre under z^d + c.
    pub main: Orbit,
    /// Julia sets: the orbit of 0 under the same map, where pixels rebase.
    pub critical: Option<Orbit>,
}

/// Progress of a reference orbit (iterations done) and a request to stop it.
#[derive(Default)]
pub struct OrbitProgress {
    /// Iterations of the orbit computed so far.
    pub done: AtomicU64,
    /// Set to stop the orbit (it then returns None).
    pub cancel: AtomicBool,
}

/// A big fixed-point number X / 2^bits as f64.
fn fix_to_f64(v: &IBig, bits: u32) -> f64 {
    let f = ibig_to_fx(v);
    ldexp(f.m, f.e - bits as i32)
}

/// The orbit of z0 under the map with parameter c in binary fixed point with `bits` fraction bits, stored
/// as f64, until it escapes past the bailout or reaches the iteration limit (None when
/// cancelled). Always at least two entries.
pub fn orbit(
    map: Map,
    z0: [IBig; 2],
    c: [IBig; 2],
    bits: u32,
    s: &IterSettings,
    progress: &OrbitProgress,
) -> Option<Vec<C>> {
    let b = bits as usize;
    let [cx, cy] = c;
    let [mut x, mut y] = z0;
    let mut out = Vec::with_capacity(s.max_iter.min(1 << 20) as usize + 1);
    out.push(C::new(fix_to_f64(&x, bits), fix_to_f64(&y, bits)));
    for k in 0..s.max_iter {
        (x, y) = big_step(map, &x, &y, b);
        x += &cx;
        y += &cy;
        let z = C::new(fix_to_f64(&x, bits), fix_to_f64(&y, bits));
        out.push(z);
        if !(z.norm2() <= s.bailout2) {
            break;
        }
        if k % 1024 == 0 {
            progress.done.store(k as u64, Ordering::Relaxed);
            if progress.cancel.load(Ordering::Relaxed) {
                return None;
            }
        }
    }
    progress.done.store(out.len() as u64, Ordering::Relaxed);
    Some(out)
}

/// One step of the map without its parameter, on binary fixed point numbers with `b`
/// fraction bits (truncated): the new x and y.
pub fn big_step(map: Map, x: &IBig, y: &IBig, b: usize) -> (IBig, IBig) {
    let xx = (x * x) >> b;
    let yy = (y * y) >> b;
    match map {
        Map::Cube => (
            (x * (&xx - IBig::from(3u8) * &yy)) >> b,
            (y * (IBig::from(3u8) * &xx - &yy)) >> b,
        ),
        Map::Square => (xx - yy, (x * y) >> (b - 1)),
        Map::Ship => {
            let xy = x * y;
            let xy = if xy < IBig::ZERO { -xy } else { xy };
            (xx - yy, xy >> (b - 1))
        }
    }
}

/// Fraction bits the reference of a view needs: its pixel size, 64 more for the orbit's
/// growth of errors and the sub-pixel offsets.
pub fn bits_for(pixel: Fx) -> u32 {
    let b = -pixel.log2() + 64.0;
    if b.is_finite() {
        b.max(64.0) as u32
    } else {
        64
    }
}

/// The extent of a deep view and the tolerance of its bilinear steps.
#[derive(Clone, Copy, Debug)]
pub struct Extent {
    /// A pixel's size.
    pub pixel: Fx,
    /// The largest offset of a pixel from the centre.
    pub radius: Fx,
    /// The relative size of the non-linear terms the bilinear steps drop ([`super::bla::EPSILON`]
    /// by default).
    pub bla_eps: f64,
}

impl Reference {
    /// The reference for a view centred on `centre` whose pixels lie within `x.radius` of
    /// it: the Mandelbrot kind (`julia` None) or the Julia set of `julia`.
    pub fn new(
        map: Map,
        centre: &Centre,
        julia: Option<C>,
        x: Extent,
        s: &IterSettings,
        progress: &OrbitProgress,
    ) -> Option<Reference> {
        let Extent {
            pixel,
            radius,
            bla_eps,
        } = x;
        // A Julia set's pixels pass by the critical point, where the map squares their offsets:
        // twice the digits.
        let bits = bits_for(pixel) * if julia.is_some() { 2 } else { 1 };
        let c0 = centre.to_binary(bits);
        let zero = || [IBig::ZERO, IBig::ZERO];
        let dc_max = |with_c: bool| if with_c { radius } else { Fx::ZERO };
        let table = |z: Vec<C>, with_c: bool| Orbit {
            ship: match map {
                Map::Ship => ShipBla::new(&z, dc_max(with_c), with_c, bla_eps),
                _ => ShipBla::default(),
            },
            bla: match map {
                Map::Ship => Bla::default(),
                _ => Bla::new(&z, map.degree(), dc_max(with_c), with_c, bla_eps),
            },
            z,
        };
        match julia {
            None => {
                let z = orbit(map, zero(), c0, bits, s, progress)?;
                Some(Reference {
                    map,
                    main: table(z, true),
                    critical: None,
                })
            }
            Some(c) => {
                let cb = Centre::from_f64_exact([c.re, c.im]).to_binary(bits);
                let z = orbit(map, c0, cb.clone(), bits, s, progress)?;
                let k = orbit(map, zero(), cb, bits, s, progress)?;
                Some(Reference {
                    map,
                    main: table(z, false),
                    critical: Some(table(k, false)),
                })
            }
        }
    }

    fn is_julia(&self) -> bool {
        self.critical.is_some()
    }
}

/// One pixel's state: its difference from the reference, the derivative of its orbit and
/// where it stands.
struct Pixel<'a> {
    r: &'a Reference,
    orbit: &'a Orbit,
    /// Reference index.
    m: usize,
    /// Iterations done.
    n: u32,
    /// The pixel's offset as the δc added each step (0 for Julia sets).
    dc: Cx,
    dc64: C,
    /// dz/dc (Mandelbrot kind) or dz/dz₀ (Julia), only when distance estimates are wanted;
    /// for the Burning Ship, whose dz/dc is a real 2×2 matrix, its first column ∂z/∂Re c.
    der: Cx,
    /// The Burning Ship: the second column ∂z/∂Im c.
    der_im: Cx,
}

/// How a stretch of iterations ended.
enum Outcome {
    Done(Sample),
    /// Carry on in f64 with this difference.
    ToF64(C),
}

impl Pixel<'_> {
    fn last(&self) -> usize {
        self.orbit.z.len() - 1
    }

    /// The derivative through one exact step at full value z.
    #[inline]
    fn der_step(&mut self, z: C, s: &IterSettings) {
        if !s.want_de {
            return;
        }
        if self.r.map == Map::Ship {
            let (f, sx, sy) = ship_fold(z);
            let step = |v: Cx, e: Cx| Cx::new(v.re * sx, v.im * sy, v.e).mul_c(f * 2.0).add(e);
            self.der = step(self.der, Cx::new(1.0, 0.0, 0));
            self.der_im = step(self.der_im, Cx::new(0.0, 1.0, 0));
            return;
        }
        let k = if self.r.map == Map::Cube {
            z * z * 3.0
        } else {
            z * 2.0
        };
        let one = if self.r.is_julia() { 0.0 } else { 1.0 };
        self.der = self.der.mul_c(k).add(Cx::new(one, 0.0, 0));
    }

    /// The Burning Ship's longest bilinear step admitting difference `d` from here, taken:
    /// the new difference (None for the other maps, and where no step admits `d`).
    fn ship_skip(&mut self, d: Cx, s: &IterSettings) -> Option<Cx> {
        if self.r.map != Map::Ship {
            return None;
        }
        let st = self.orbit.ship.find(self.m, d.abs(), s.max_iter - self.n)?;
        if s.want_de {
            // The Jacobian's columns: J ← A·J + B.
            let col = |v: f64, w: f64| st.b.apply(Cx::new(v, w, 0));
            self.der = st.a.apply(self.der).add(col(1.0, 0.0));
            self.der_im = st.a.apply(self.der_im).add(col(0.0, 1.0));
        }
        self.m += st.len as usize;
        self.n += st.len;
        Some(st.a.apply(d).add(st.b.apply(self.dc)))
    }

    /// Rebase onto the orbit that starts at 0.
    fn rebase(&mut self) {
        self.m = 0;
        if let Some(k) = &self.r.critical {
            self.orbit = k;
        }
    }

    fn escaped(&self, n: u32, z: C, r2: f64, s: &IterSettings, pixel: Fx) -> Sample {
        let deg = self.r.map.degree() as f64;
        let mut out = s.escape_sample(n, z, r2, C::ONE, deg);
        out.nu = smooth_count(n, r2, deg);
        out.de = if s.want_de {
            // b = 2|z| ln|z| / |dz|, in pixels.
            let a = r2.sqrt();
            let size = if self.r.map == Map::Ship {
                // The Jacobian's Frobenius norm over √2 (see `jacobian_size`).
                self.der.norm2().add(self.der_im.norm2()).scale(0.5).sqrt()
            } else {
                self.der.abs()
            };
            Fx::from_f64(2.0 * a * a.ln()).div(size.mul(pixel)).to_f64() as f32
        } else {
            0.0
        };
        out
    }

    /// Iterate while δ is below f64's range.
    fn run_extended(&mut self, mut d: Cx, s: &IterSettings, pixel: Fx) -> Outcome {
        loop {
            if self.n >= s.max_iter {
                return Outcome::Done(Sample::inside(s.max_iter));
            }
            let z = self.orbit.z[self.m];
            if let Some(next) = self.ship_skip(d, s) {
                d = next;
            } else if let Some(st) = self.orbit.bla.find(self.m, d.abs(), s.max_iter - self.n) {
                d = st.a.mul(d).add(st.b.mul(self.dc));
                if s.want_de {
                    self.der = st.a.mul(self.der).add(st.b);
                }
                self.m += st.len as usize;
                self.n += st.len;
            } else {
                self.der_step(z + d.to_c(), s);
                d = match self.r.map {
                    Map::Cube => d
                        .mul_c(z * z * 3.0)
                        .add(d.mul(d).mul_c(z * 3.0))
                        .add(d.mul(d).mul(d))
                        .add(self.dc),
                    Map::Square => d.mul_c(z * 2.0).add(d.mul(d)).add(self.dc),
                    Map::Ship => ship_step_extended(z, d, self.dc),
                };
                self.m += 1;
                self.n += 1;
            }
            let full = self.orbit.z[self.m] + d.to_c();
            let r2 = full.norm2();
            if s.escaped(r2) {
                return Outcome::Done(self.escaped(self.n, full, r2, s, pixel));
            }
            if self.m == self.last() || r2 < d.norm2().to_f64() {
                self.rebase();
                return Outcome::ToF64(full);
            }
            if d.e > F64_FROM {
                return Outcome::ToF64(d.to_c());
            }
        }
    }

    /// Iterate in f64 from difference d to the end.
    fn run_f64(&mut self, mut d: C, s: &IterSettings, pixel: Fx) -> Sample {
        let map = self.r.map;
        loop {
            if self.n >= s.max_iter {
                return Sample::inside(s.max_iter);
            }
            let z = self.orbit.z[self.m];
            let step = if self.m > 0 {
                self.orbit.bla.find_f64(self.m, d, s.max_iter - self.n)
            } else {
                None
            };
            if let Some(next) = self.ship_skip(Cx::from_c(d), s) {
                d = next.to_c();
            } else if let Some(st) = step {
                d = st.a.mul_c(d).add(st.b.mul(self.dc)).to_c();
                if s.want_de {
                    self.der = st.a.mul(self.der).add(st.b);
                }
                self.m += st.len as usize;
                self.n += st.len;
            } else {
                self.der_step(z + d, s);
                d = match map {
                    Map::Cube => d * (z * z * 3.0 + d * (z * 3.0 + d)) + self.dc64,
                    Map::Square => d * (z * 2.0 + d) + self.dc64,
                    Map::Ship => deep_plain::ship_step(z, d, self.dc64),
                };
                self.m += 1;
                self.n += 1;
            }
            let full = self.orbit.z[self.m] + d;
            let r2 = full.norm2();
            if s.escaped(r2) {
                return self.escaped(self.n, full, r2, s, pixel);
            }
            if r2 < d.norm2() || self.m == self.last() {
                d = full;
                self.rebase();
            }
        }
    }
}

/// |a + b| − |a| where b is an extended number (see [`deep_plain::diffabs`]).
fn diffabs_extended(a: f64, b: Fx) -> Fx {
    let sum = Fx::from_f64(a).add(b);
    let twice = Fx::from_f64(2.0 * a).add(b);
    if a >= 0.0 {
        if sum.m >= 0.0 { b } else { Fx::ZERO.sub(twice) }
    } else if sum.m > 0.0 {
        twice
    } else {
        Fx::ZERO.sub(b)
    }
}

/// [`deep_plain::ship_step`] for an extended difference.
fn ship_step_extended(z: C, d: Cx, dc: Cx) -> Cx {
    let (x, y) = (Fx::new(d.re, d.e), Fx::new(d.im, d.e));
    let re = x
        .scale(2.0 * z.re)
        .add(x.mul(x))
        .sub(y.scale(2.0 * z.im).add(y.mul(y)));
    let t = y.scale(z.re).add(x.mul(Fx::from_f64(z.im).add(y)));
    let im = diffabs_extended(z.re * z.im, t).scale(2.0);
    Cx::from_parts(re, im).add(dc)
}

/// One pixel at offset `dc` from the reference point (the parameter offset for the
/// Mandelbrot kind, the starting-point offset for a Julia set). Distance estimates come out
/// in units of `pixel`.
pub fn iterate(r: &Reference, dc: Cx, s: &IterSettings, pixel: Fx) -> Sample {
    let julia = r.is_julia();
    let mut p = Pixel {
        r,
        orbit: &r.main,
        m: 0,
        n: 0,
        dc: if julia { Cx::ZERO } else { dc },
        dc64: if julia { C::ZERO } else { dc.to_c() },
        der: if julia {
            Cx::new(1.0, 0.0, 0)
        } else {
            Cx::ZERO
        },
        der_im: Cx::ZERO,
    };
    let d0 = if julia { dc } else { Cx::ZERO };
    let d = if d0.e <= F64_FROM && !d0.is_zero() || dc.e <= F64_FROM {
        match p.run_extended(d0, s, pixel) {
            Outcome::Done(sample) => return sample,
            Outcome::ToF64(d) => d,
        }
    } else {
        d0.to_c()
    };
    p.run_f64(d, s, pixel)
}

/// The pixels at offsets `dcs` (as for [`iterate`]): those that need neither derivatives nor
/// extended exponents in the interleaved plain-f64 loop ([`deep_plain`]), the others one by
/// one.
pub fn iterate_many(r: &Reference, dcs: &[Cx], s: &IterSettings, pixel: Fx) -> Vec<Sample> {
    let mut out = vec![Sample::default(); dcs.len()];
    let julia = r.is_julia();
    let plain = |dc: &Cx| !s.want_de && (dc.is_zero() || dc.e > F64_FROM);
    for (k, dc) in dcs.iter().enumerate() {
        if !plain(dc) {
            out[k] = iterate(r, *dc, s, pixel);
        }
    }
    let base = r.critical.as_ref().unwrap_or(&r.main);
    let orbits = deep_plain::Orbits {
        main: (&r.main.z, &r.main.bla),
        base: (&base.z, &base.bla),
    };
    let mut todo = dcs.iter().enumerate().filter(|(_, dc)| plain(dc));
    let next = || {
        todo.next().map(|(k, dc)| {
            let dc = dc.to_c();
            let lane = deep_plain::Lane {
                m: 0,
                n: 0,
                on_base: false,
                d: if julia { dc } else { C::ZERO },
                dc: if julia { C::ZERO } else { dc },
            };
            (k, lane)
        })
    };
    let deg = r.map.degree() as f64;
    let done = |k: usize, end| {
        out[k] = match end {
            deep_plain::End::Escaped { n, z, r2 } => s.escape_sample(n, z, r2, C::ONE, deg),
            deep_plain::End::Inside => Sample::inside(s.max_iter),
        }
    };
    if r.map == Map::Ship {
        let orbits = deep_ship::ShipOrbits {
            main: (&r.main.z, &r.main.ship),
            base: (&base.z, &base.ship),
        };
        deep_ship::run(&orbits, s, next, done);
    } else {
        deep_plain::run(&orbits, r.map, s, next, done);
    }
    out
}

#[cfg(test)]
#[path = "deep_tests.rs"]
mod tests;
