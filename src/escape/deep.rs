//! Deep zoom by perturbation for z² + c (the Mandelbrot set and its Julia sets) and z³ + c.
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
//! start at δ(0) = the offset instead). δ stays accurate because it is small where Z is not.
//! Where δ is too small for f64 (offsets below about 1e-300) it is kept as an extended-
//! exponent number ([`Cx`]) until it has grown into f64's range.
//!
//! Most iterations are skipped by bilinear approximation ([`super::bla`]). Glitches are
//! avoided by rebasing (Zhuoran): when the pixel's orbit comes closer to 0 than its
//! difference (|Z + δ| < |δ|), or the reference ends, the pixel continues from the start of
//! an orbit that begins at 0 (δ := Z + δ, n_ref := 0): the reference itself for the
//! Mandelbrot kind, the critical orbit of 0 for a Julia set.

use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};

use dashu_int::IBig;

use super::bla::Bla;
use super::centre::{Centre, ibig_to_fx};
use super::complex::C;
use super::deep_plain;
use super::family::{IterSettings, Sample, smooth_count};
use super::fx::{Cx, Fx, ldexp};

/// Exponent (base 2) above which a difference is kept in f64.
const F64_FROM: i32 = -900;

/// What the pixels of a deep view iterate around: an orbit and its bilinear table.
#[derive(Clone, Debug)]
pub struct Orbit {
    /// Z(0), Z(1), … until the orbit escaped or reached the iteration limit.
    pub z: Vec<C>,
    pub bla: Bla,
}

/// The reference of a deep view.
#[derive(Clone, Debug)]
pub struct Reference {
    /// The degree of the map (2 or 3).
    pub degree: u32,
    /// The orbit of the view centre: for the Mandelbrot kind the orbit of 0 under
    /// z^d + C (C the centre), for a Julia set the orbit of the centre under z^d + c.
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

/// The orbit of z0 under z^degree + c in binary fixed point with `bits` fraction bits, stored
/// as f64, until it escapes past the bailout or reaches the iteration limit (None when
/// cancelled). Always at least two entries.
pub fn orbit(
    degree: u32,
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
        if degree == 3 {
            let xx = (&x * &x) >> b;
            let yy = (&y * &y) >> b;
            let nx = ((&x * (&xx - IBig::from(3u8) * &yy)) >> b) + &cx;
            let ny = ((&y * (IBig::from(3u8) * &xx - &yy)) >> b) + &cy;
            (x, y) = (nx, ny);
        } else {
            let xx = (&x * &x) >> b;
            let yy = (&y * &y) >> b;
            let xy = (&x * &y) >> (b - 1);
            x = xx - yy + &cx;
            y = xy + &cy;
        }
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

impl Reference {
    /// The reference for a view centred on `centre` whose pixels lie within `radius` of it:
    /// the Mandelbrot kind (`julia` None) or the Julia set of `julia`.
    pub fn new(
        degree: u32,
        centre: &Centre,
        julia: Option<C>,
        pixel: Fx,
        radius: Fx,
        s: &IterSettings,
        progress: &OrbitProgress,
    ) -> Option<Reference> {
        // A Julia set's pixels pass by the critical point, where the map squares their offsets:
        // twice the digits.
        let bits = bits_for(pixel) * if julia.is_some() { 2 } else { 1 };
        let c0 = centre.to_binary(bits);
        let zero = || [IBig::ZERO, IBig::ZERO];
        let table = |z: Vec<C>, with_c: bool| Orbit {
            bla: Bla::new(&z, degree, if with_c { radius } else { Fx::ZERO }, with_c),
            z,
        };
        match julia {
            None => {
                let z = orbit(degree, zero(), c0, bits, s, progress)?;
                Some(Reference {
                    degree,
                    main: table(z, true),
                    critical: None,
                })
            }
            Some(c) => {
                let cb = Centre::from_f64_exact([c.re, c.im]).to_binary(bits);
                let z = orbit(degree, c0, cb.clone(), bits, s, progress)?;
                let k = orbit(degree, zero(), cb, bits, s, progress)?;
                Some(Reference {
                    degree,
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
    /// dz/dc (Mandelbrot kind) or dz/dz₀ (Julia), only when distance estimates are wanted.
    der: Cx,
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
        if s.want_de {
            let k = if self.r.degree == 3 {
                z * z * 3.0
            } else {
                z * 2.0
            };
            let one = if self.r.is_julia() { 0.0 } else { 1.0 };
            self.der = self.der.mul_c(k).add(Cx::new(one, 0.0, 0));
        }
    }

    /// Rebase onto the orbit that starts at 0.
    fn rebase(&mut self) {
        self.m = 0;
        if let Some(k) = &self.r.critical {
            self.orbit = k;
        }
    }

    fn escaped(&self, n: u32, z: C, r2: f64, s: &IterSettings, pixel: Fx) -> Sample {
        let deg = self.r.degree as f64;
        let mut out = s.escape_sample(n, z, r2, C::ONE, deg);
        out.nu = smooth_count(n, r2, deg);
        out.de = if s.want_de {
            // b = 2|z| ln|z| / |dz|, in pixels.
            let a = r2.sqrt();
            Fx::from_f64(2.0 * a * a.ln())
                .div(self.der.abs().mul(pixel))
                .to_f64() as f32
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
            if let Some(st) = self.orbit.bla.find(self.m, d.abs(), s.max_iter - self.n) {
                d = st.a.mul(d).add(st.b.mul(self.dc));
                if s.want_de {
                    self.der = st.a.mul(self.der).add(st.b);
                }
                self.m += st.len as usize;
                self.n += st.len;
            } else {
                self.der_step(z + d.to_c(), s);
                let lin = if self.r.degree == 3 {
                    d.mul_c(z * z * 3.0)
                        .add(d.mul(d).mul_c(z * 3.0))
                        .add(d.mul(d).mul(d))
                } else {
                    d.mul_c(z * 2.0).add(d.mul(d))
                };
                d = lin.add(self.dc);
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
        let cube = self.r.degree == 3;
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
            if let Some(st) = step {
                d = st.a.mul_c(d).add(st.b.mul(self.dc)).to_c();
                if s.want_de {
                    self.der = st.a.mul(self.der).add(st.b);
                }
                self.m += st.len as usize;
                self.n += st.len;
            } else {
                self.der_step(z + d, s);
                d = if cube {
                    d * (z * z * 3.0 + d * (z * 3.0 + d)) + self.dc64
                } else {
                    d * (z * 2.0 + d) + self.dc64
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
    let deg = r.degree as f64;
    deep_plain::run(&orbits, r.degree == 3, s, next, |k, end| {
        out[k] = match end {
            deep_plain::End::Escaped { n, z, r2 } => s.escape_sample(n, z, r2, C::ONE, deg),
            deep_plain::End::Inside => Sample::inside(s.max_iter),
        }
    });
    out
}

#[cfg(test)]
#[path = "deep_tests.rs"]
mod tests;
