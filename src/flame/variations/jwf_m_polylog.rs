//! DarkBeam's `polylogarithm`: Li_n(z^zpow), by its power series for |z|² < 0.07 and by
//! Crandall's expansion in ln z elsewhere (up to |z|² = 250000 and n < 20; beyond, z itself).
//!
//! The formula follows JWildfire's (LGPL-2.1) code, written anew, with DarkBeam's complex
//! arithmetic (its logarithm adds 1e-20 to |z|²) and the values of Riemann's ζ JWildfire
//! tabulates.

use super::jwf_a_complex::DbComplex;
use super::*;

pub(super) static DEFS: &[VarDef] = &[VarDef::new("polylogarithm", polylogarithm)
    .params(&[
        p_int("polylogarithm_n", 2.0, -2147483648.0, 2147483647.0),
        p("polylogarithm_zpow", 1.0),
    ])
    .flags(flag::JWILDFIRE)];

/// ζ(−1), ζ(−3), ζ(−5), … (the negative even values are 0).
#[allow(clippy::excessive_precision)]
const ZETA_NEG_ODD: [f64; 100] = [
    -0.08333333333333333,
    0.008333333333333333,
    -0.003968253968253968,
    0.004166666666666667,
    -0.007575757575757576,
    0.021092796092796094,
    -0.08333333333333333,
    0.4432598039215686,
    -3.0539543302701198,
    26.456212121212122,
    -281.46014492753625,
    3607.5105463980462,
    -54827.583333333336,
    974936.8238505747,
    -20052695.79668808,
    472384867.7216299,
    -12635724795.916668,
    380879311252.4537,
    -12850850499305.082,
    482414483548501.7,
    -2.0040310656516252e+16,
    9.16774360319533e+17,
    -4.5979888343656505e+19,
    2.518047192145109e+21,
    -1.500173349215393e+23,
    9.689957887463594e+24,
    -6.764588237929281e+26,
    5.089065946866229e+28,
    -4.114728879255798e+30,
    3.566658209537556e+32,
    -3.306608987657758e+34,
    3.271563423647871e+36,
    -3.447378255827806e+38,
    3.861427983270526e+40,
    -4.589297443245433e+42,
    5.777538634277042e+44,
    -7.691985875950713e+46,
    1.0813635449971654e+49,
    -1.6029364522008964e+51,
    2.501947904156046e+53,
    -4.106705233581021e+55,
    7.079877440849458e+57,
    -1.280454688793951e+60,
    2.4267340392333523e+62,
    -4.814321887404576e+64,
    9.987557417572751e+66,
    -2.1645634868435182e+69,
    4.896232703962054e+71,
    -1.154902392396352e+74,
    2.83822495706937e+76,
    -7.26120088036067e+78,
    1.932351423341981e+81,
    -5.345016042528861e+83,
    1.535602884642242e+86,
    -4.5789872682265784e+88,
    1.4162025212194806e+91,
    -4.540065229609264e+93,
    1.5076656758807854e+96,
    -5.183094914826456e+98,
    1.843564742725653e+101,
    -6.780555475309095e+103,
    2.57733267027546e+106,
    -1.01191128757046e+109,
    4.101634616154228e+111,
    -1.715524453403202e+114,
    7.400342570526908e+116,
    -3.290922535705444e+119,
    1.507983153416477e+122,
    -7.116987918825454e+124,
    3.458042914157776e+127,
    -1.729090760667674e+130,
    8.893699169503295e+132,
    -4.7038470619636e+135,
    2.55719382310602e+138,
    -1.428406750044352e+141,
    8.195215221831376e+143,
    -4.827648542272736e+146,
    2.918961237477031e+149,
    -1.81089321625689e+152,
    1.152357722002117e+155,
    -7.519231195198174e+157,
    5.029401657641103e+160,
    -3.447342044447767e+163,
    2.420745864586851e+166,
    -1.740946592037767e+169,
    1.281948986348224e+172,
    -9.662412110856088e+174,
    7.452691030430086e+177,
    -5.880839331167436e+180,
    4.74627186549076e+183,
    -3.916913259477282e+186,
    3.304507144322603e+189,
    -2.849289055099457e+192,
    2.510332934507758e+195,
    -2.259390199547524e+198,
    2.07691380042876e+201,
    -1.949473217492725e+204,
    1.868073147126591e+207,
    -1.827075266281457e+210,
    1.823538632259567e+213,
];

/// ζ(0), ζ(1) (taken as 0), ζ(2), … ζ(33).
#[allow(clippy::excessive_precision)]
const ZETA_POS: [f64; 34] = [
    -0.5,
    0.0,
    1.6449340668482264,
    1.2020569031595942,
    1.0823232337111381,
    1.03692775514337,
    1.0173430619844492,
    1.008349277381923,
    1.0040773561979444,
    1.0020083928260821,
    1.000994575127818,
    1.0004941886041194,
    1.000246086553308,
    1.0001227133475785,
    1.0000612481350588,
    1.000030588236307,
    1.0000152822594086,
    1.0000076371976379,
    1.000003817293265,
    1.0000019082127165,
    1.0000009539620338,
    1.0000004769329869,
    1.0000002384505027,
    1.000000119219926,
    1.000000059608189,
    1.0000000298035034,
    1.0000000149015549,
    1.0000000074507118,
    1.000000003725334,
    1.0000000018626598,
    1.0000000009313275,
    1.0000000004656628,
    1.000000000232831,
    1.0000000001164155,
];

/// ζ(n) as JWildfire's table gives it: 1 above 33, 0 at the negative even integers, a huge
/// stand-in below −200.
fn zeta(n: i64) -> f64 {
    if n > 33 {
        1.0
    } else if n < -200 {
        1e250
    } else if n < 0 {
        if (-n) % 2 == 0 {
            0.0
        } else {
            ZETA_NEG_ODD[((-n - 1) / 2) as usize]
        }
    } else {
        ZETA_POS[n as usize]
    }
}

/// k! as a 64-bit integer (wrapping past 20!, where Java's would throw), as a double; 1 for
/// k < 1.
fn factorial(k: i64) -> f64 {
    (2..=k.min(25)).fold(1i64, |a, i| a.wrapping_mul(i)) as f64
}

/// 1 + 1/2 + … + 1/n (0 for n < 1).
fn harmonic(n: i64) -> f64 {
    (1..=n.min(20)).map(|i| 1.0 / i as f64).sum()
}

fn mul(a: DbComplex, b: DbComplex) -> DbComplex {
    if b.im == 0.0 {
        return a.scale(b.re);
    }
    DbComplex::new(a.re * b.re - a.im * b.im, a.re * b.im + a.im * b.re)
}

/// DarkBeam's z^e: exact forms for e = 0, ±½, ±1, ±2, else through polar form.
fn pow(z: DbComplex, e: f64) -> DbComplex {
    if e == 0.0 {
        return DbComplex::new(1.0, 0.0);
    }
    let ex = e.abs();
    let z = if e < 0.0 { z.recip() } else { z };
    if ex == 0.5 {
        return z.sqrt();
    }
    if ex == 1.0 {
        return z;
    }
    if ex == 2.0 {
        return z.sqr();
    }
    let r = z.re.hypot(z.im).powf(ex);
    let a = z.im.atan2(z.re) * ex;
    DbComplex::new(r * a.cos(), r * a.sin())
}

/// Li_n(z) for n < 20 and |z|² ≤ 250000.
fn polylog(n: i64, z: DbComplex) -> DbComplex {
    let mut li = DbComplex::new(0.0, 0.0);
    if z.re * z.re + z.im * z.im < 0.07 {
        let mut zk = z;
        for i in 1..20 {
            // z^i / i^n as DarkBeam divides: by multiplying with i^n / (i^n)².
            let d = (i as f64).powf(n as f64);
            let m = if d * d < 1e-100 { 1.0 } else { 1.0 / (d * d) };
            li = li.add(DbComplex::new(zk.re * d * m, zk.im * d * m));
            zk = mul(zk, z);
        }
        return li;
    }
    let l = z.ln();
    let mut lk = DbComplex::new(1.0, 0.0);
    let mut l_n1 = z;
    for i in 0..20 {
        let zee = zeta(n - i);
        if zee != 0.0 {
            li = li.add(lk.scale(zee / factorial(i)));
        }
        if i == n - 1 {
            l_n1 = lk;
        }
        lk = mul(lk, l);
    }
    let neg_l = DbComplex::new(-l.re, -l.im).ln();
    let t = DbComplex::new(-neg_l.re + harmonic(n - 1), -neg_l.im);
    li.add(mul(l_n1.scale(1.0 / factorial(n - 1)), t))
}

/// polylogarithm: Li_n(z^zpow) of the input z.
fn polylogarithm(v: &Prepared, t: &VarIn, _acc: &mut Acc, _rng: &mut FastRng) -> V3 {
    let [n, zpow] = v.params();
    let n = n as i64;
    let z = pow(DbComplex::new(t.x, t.y), zpow);
    let o = if z.re * z.re + z.im * z.im > 250000.0 || n >= 20 {
        z
    } else {
        polylog(n, z)
    };
    [v.w * o.re, v.w * o.im, 0.0]
}
