//! flam3's variations as `pre_`/`post_` forms over a batch of points (flam3's `pre_blur`, the
//! most used, among them): the formula inlined into a loop compiled for the baseline CPU, for
//! AVX2 and FMA and for AVX-512F, chosen at run time, with the random numbers of a variation
//! that draws a fixed number per point drawn for the whole batch first (the same stream in
//! the same order: the same bits as the forms applied point by point).

use super::{
    Direct, MAX_DRAWS, Predrawn, SpanFormula, draws, reads_compat, wider_is_faster, z_out,
};
#[cfg(target_arch = "x86_64")]
use crate::flame::fastmath::Simd;
use crate::flame::rng::FastRng;
use crate::flame::variations::{Assign, Prepared, VarIn, flag, need};

/// flam3's variation `ID` as a `pre_`/`post_` form over the points `x`, `y`, `z` (in place):
/// a [`crate::flame::variations::FormBatchFn`].
pub(super) fn form_batch<const ID: u16>(
    v: &Prepared,
    x: &mut [f64],
    y: &mut [f64],
    z: &mut [f64],
    rng: &mut FastRng,
) {
    #[cfg(target_arch = "x86_64")]
    match crate::flame::fastmath::simd() {
        // SAFETY: the CPU has reported AVX-512F (and AVX2 and FMA).
        Simd::Avx512 if wider_is_faster(ID) => {
            return unsafe { form_avx512::<ID>(v, x, y, z, rng) };
        }
        // SAFETY: the CPU has reported AVX2 and FMA (AVX-512F implies them here).
        Simd::Avx512 | Simd::Avx2Fma => return unsafe { form_avx2::<ID>(v, x, y, z, rng) },
        Simd::Baseline => {}
    }
    form_loop::<ID>(v, x, y, z, rng)
}

/// [`form_batch`] for CPUs with AVX2 and FMA.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
fn form_avx2<const ID: u16>(
    v: &Prepared,
    x: &mut [f64],
    y: &mut [f64],
    z: &mut [f64],
    rng: &mut FastRng,
) {
    form_loop::<ID>(v, x, y, z, rng)
}

/// [`form_batch`] for CPUs with AVX-512F.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx512f,avx2,fma")]
fn form_avx512<const ID: u16>(
    v: &Prepared,
    x: &mut [f64],
    y: &mut [f64],
    z: &mut [f64],
    rng: &mut FastRng,
) {
    form_loop::<ID>(v, x, y, z, rng)
}

/// The loop, with Fractorium's compatibility switch fixed (one copy per setting for the
/// variations that read it).
#[inline(always)]
fn form_loop<const ID: u16>(
    v: &Prepared,
    x: &mut [f64],
    y: &mut [f64],
    z: &mut [f64],
    rng: &mut FastRng,
) {
    if reads_compat(ID) && !v.compat {
        form_loop_as::<ID, false>(v, x, y, z, rng)
    } else {
        form_loop_as::<ID, true>(v, x, y, z, rng)
    }
}

/// The form over spans of up to 256 points: the span's draws first (for a variation with a
/// fixed count), then the formula point by point as [`Prepared::apply_pre`] computes it (the
/// input's derived quantities as [`VarIn::new`] gives them, the framework's z where the
/// formula writes none, the output replacing or added to the point). One loop per case, each
/// without a call the vectoriser cannot take: the generator's draws and the standard
/// library's atan2 (the angles are computed only for the variations that read them).
#[inline(always)]
fn form_loop_as<const ID: u16, const C: bool>(
    v: &Prepared,
    x: &mut [f64],
    y: &mut [f64],
    z: &mut [f64],
    rng: &mut FastRng,
) {
    let n = x.len().min(y.len()).min(z.len());
    let (x, y, z) = (&mut x[..n], &mut y[..n], &mut z[..n]);
    let d = draws(ID);
    let angles = v.def.needs & (need::ATAN_XY | need::ATAN_YX) != 0;
    // Every quantity but the angles: those the formula does not read are left unused (the
    // ones it reads are those `VarIn::new` computes, with its bits); a constant, so that the
    // loop has no test on it.
    const NO_ANGLES: u8 = need::SUMSQ | need::SQRT | need::ANGLES;
    if d == 0 {
        // The formula draws from the generator itself (if at all).
        let f = &mut Direct::<C> { v, rng };
        return if angles {
            span::<ID, _>(v, x, y, z, v.def.needs, f)
        } else {
            span::<ID, _>(v, x, y, z, NO_ANGLES, f)
        };
    }
    if angles {
        predrawn::<ID, C>(v, x, y, z, v.def.needs, rng)
    } else {
        predrawn::<ID, C>(v, x, y, z, NO_ANGLES, rng)
    }
}

/// [`form_loop_as`] for a variation with a fixed number of draws per point: the spans' draws
/// first, then the formula reading them.
#[inline(always)]
fn predrawn<const ID: u16, const C: bool>(
    v: &Prepared,
    x: &mut [f64],
    y: &mut [f64],
    z: &mut [f64],
    needs: u8,
    rng: &mut FastRng,
) {
    let (n, d) = (x.len().min(y.len()).min(z.len()), draws(ID));
    let mut drawn = [[0u64; MAX_DRAWS]; 256];
    for start in (0..n).step_by(drawn.len()) {
        let m = (n - start).min(drawn.len());
        for p in drawn[..m].iter_mut() {
            for u in p[..d].iter_mut() {
                *u = rng.u64();
            }
        }
        // Slices of one length m, so that the loop reads the draws without a bounds test.
        let r = start..start + m;
        let (xs, ys, zs) = (&mut x[r.clone()], &mut y[r.clone()], &mut z[r]);
        let drawn = &drawn[..m];
        span::<ID, _>(v, xs, ys, zs, needs, &mut Predrawn::<C> { v, drawn });
    }
}

/// The form over the points `x`, `y`, `z` (of one length) with the formula `f`.
#[inline(always)]
fn span<const ID: u16, F: SpanFormula<ID>>(
    v: &Prepared,
    x: &mut [f64],
    y: &mut [f64],
    z: &mut [f64],
    needs: u8,
    f: &mut F,
) {
    let writes_z = v.def.has(flag::WRITES_Z);
    // The framework's z and the way the output joins the point, decided once: a `match` in
    // the loop (a switch on a value the compiler does not see as fixed) keeps it scalar.
    let default_z = v.default_z_rule();
    let adds = v.assign == Assign::Sum;
    let n = x.len().min(y.len()).min(z.len());
    let (x, y, z) = (&mut x[..n], &mut y[..n], &mut z[..n]);
    for i in 0..n {
        let t = VarIn::new(x[i], y[i], z[i], 0.0, needs, false);
        let (fx, fy) = f.at(i, &t);
        let fz = if writes_z {
            z_out(ID, v, &t)
        } else {
            default_z.of(t.z)
        };
        if adds {
            x[i] += fx;
            y[i] += fy;
            z[i] += fz;
        } else {
            [x[i], y[i], z[i]] = [fx, fy, fz];
        }
    }
}

#[cfg(test)]
mod tests {
    use crate::flame::affine::Affine;
    use crate::flame::fastmath::{self, Simd};
    use crate::flame::rng::FastRng;
    use crate::flame::variations::{Acc, Form, Prepared, V3, VarId, all, flag};

    /// Every copy of every flam3 form loop (baseline, AVX2 and FMA, AVX-512 as far as the CPU
    /// has them), as `pre_` and as `post_` form, with Fractorium's compatibility switch on and
    /// off, gives the bits of the form applied point by point with the same generator.
    #[test]
    fn form_loops_match_the_forms_point_by_point() {
        let mut gen_rng = FastRng::new(5);
        let n = 300; // more than one span of draws
        let mut pts: Vec<V3> = (0..n)
            .map(|_| {
                let s = 10f64.powf(gen_rng.f01() * 6.0 - 3.0);
                let (a, b) = (gen_rng.f01() - 0.5, gen_rng.f01() - 0.5);
                [a * s, b * s, gen_rng.f01() - 0.5]
            })
            .collect();
        pts[0] = [0.0, 0.0, 0.0];
        pts[1] = [1e-300, -1e-300, 0.25];
        let aff = Affine::new(0.9, -0.3, 0.2, 0.4, 1.1, -0.6);
        let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<u64>>();
        let mut checked = 0;
        for (id, def) in all().iter().enumerate() {
            let Some(batch) = def.form_batch else {
                continue;
            };
            assert!(def.has(flag::FLAM3), "{}", def.name);
            let params: Vec<f64> = def.params.iter().map(|p| p.default + 0.37).collect();
            for (form, compat) in [(Form::Pre, true), (Form::Post, true), (Form::Pre, false)] {
                let v = Prepared::new(id as VarId, form, 0.7, &params, aff, compat);
                let mut rng = FastRng::new(9);
                let mut want = pts.clone();
                for p in want.iter_mut() {
                    let mut acc = Acc {
                        x: p[0],
                        y: p[1],
                        z: p[2],
                        color: 0.25,
                        ..Acc::default()
                    };
                    if form == Form::Pre {
                        v.apply_pre(p, &mut Acc::default(), 0.25, &mut rng);
                    } else {
                        v.apply_post(&mut acc, 0.25, &mut rng);
                        *p = [acc.x, acc.y, acc.z];
                    }
                }
                let next = rng.u64();
                let col = |k: usize, of: &[V3]| of.iter().map(|p| p[k]).collect::<Vec<f64>>();
                for simd in [Simd::Baseline, Simd::Avx2Fma, Simd::Avx512] {
                    let (mut x, mut y, mut z) = (col(0, &pts), col(1, &pts), col(2, &pts));
                    let mut rng = FastRng::new(9);
                    fastmath::limit_simd(simd);
                    batch(&v, &mut x, &mut y, &mut z, &mut rng);
                    fastmath::limit_simd(Simd::Avx512);
                    let name = format!("{} {form:?} (compat {compat}) {simd:?}", def.name);
                    assert_eq!(bits(&x), bits(&col(0, &want)), "{name} x");
                    assert_eq!(bits(&y), bits(&col(1, &want)), "{name} y");
                    assert_eq!(bits(&z), bits(&col(2, &want)), "{name} z");
                    // The generator is left where the point-by-point forms leave it.
                    assert_eq!(rng.u64(), next, "{name} stream");
                }
            }
            checked += 1;
        }
        assert_eq!(checked, 99);
    }
}
