//! Reduction of huge arguments of sine and cosine by π/2 (Payne and Hanek's method), without
//! branches so that loops over arrays still vectorise: the reduction of [`super::sin_cos_any`]
//! for |x| ≥ 2²⁰, where the two-constant reduction runs out of bits of π/2.
//!
//! x = M·2ᴱ with M a 53-bit integer; since M is an integer, x·2/π mod 4 = M·F_E mod 4 with
//! F_E = 2ᴱ·2/π mod 4. A table holds F_E for every exponent a finite |x| ≥ 2²⁰ can have, to
//! 2⁻¹²⁸, in five pieces of 26 bits; M splits into a 27-bit and a 26-bit half, so that every
//! product of a half and a piece is exact, and the large products are reduced mod 4 exactly.
//! The residue's error is about 2⁻⁷⁵ absolute (plus one rounding relative), so the reduced
//! argument keeps nearly full precision even next to a multiple of π/2.

use super::MAGIC;

/// 2/π in binary, bits 2⁻¹ … 2⁻¹¹⁵² (most significant first): enough for F_E down to 2⁻¹²⁸
/// up to the largest exponent of a double.
const TWO_OVER_PI: [u64; 18] = [
    0xa2f9_836e_4e44_1529,
    0xfc27_57d1_f534_ddc0,
    0xdb62_9599_3c43_9041,
    0xfe51_63ab_debb_c561,
    0xb724_6e3a_424d_d2e0,
    0x0649_2eea_09d1_921c,
    0xfe1d_eb1c_b129_a73e,
    0xe882_35f5_2ebb_4484,
    0xe99c_7026_b45f_7e41,
    0x3991_d639_8353_39f4,
    0x9c84_5f8b_bdf9_283b,
    0x1ff8_97ff_de05_980f,
    0xef2f_118b_5a0a_6d1f,
    0x6d36_7ecf_27cb_09b7,
    0x4f46_3f66_9e5f_ea2d,
    0x7527_bac7_ebe5_f17b,
    0x3d07_39f7_8a52_92ea,
    0x6bfb_5fb1_1f8d_5d08,
];

/// The biased exponent of 2²⁰, the smallest argument reduced here.
const FIRST_BIASED_EXP: u64 = 1043;
/// Exponents E = −32 (x = 2²⁰ as M·2⁻³²) … 971 (the largest finite doubles).
const ROWS: usize = 1004;

/// Bit 2⁻ʲ of 2/π (0 outside the stored bits; 2/π < 1 has no bit 2⁰).
const fn bit(j: i64) -> u64 {
    if j < 1 || j > 1152 {
        return 0;
    }
    let p = (j - 1) as usize;
    (TWO_OVER_PI[p / 64] >> (63 - p % 64)) & 1
}

/// 2ᵖ for a normal exponent p.
const fn pow2(p: i64) -> f64 {
    f64::from_bits(((p + 1023) as u64) << 52)
}

/// F_E = 2ᴱ·2/π mod 4 for E = row − 32, in five pieces: piece k holds the bits of weight
/// 2^(1−26k) … 2^(−24−26k).
const fn table() -> [[f64; 5]; ROWS] {
    let mut t = [[0.0; 5]; ROWS];
    let mut row = 0;
    while row < ROWS {
        let e = row as i64 - 32;
        let mut k = 0;
        while k < 5 {
            // Bit 2⁻ʲ of 2/π has weight 2^(E−j) in 2ᴱ·2/π.
            let first = e - 1 + 26 * k;
            let mut n: u64 = 0;
            let mut j = first;
            while j < first + 26 {
                n = (n << 1) | bit(j);
                j += 1;
            }
            t[row][k as usize] = n as f64 * pow2(-24 - 26 * k);
            k += 1;
        }
        row += 1;
    }
    t
}

static F: [[f64; 5]; ROWS] = table();

/// v − 4·round(v/4): exact for v a multiple of 2⁻⁵⁰ below 2⁵³ in magnitude (the result lies
/// in [−2, 2]).
#[inline(always)]
fn mod4(v: f64) -> f64 {
    v - 4.0 * ((v * 0.25 + MAGIC) - MAGIC)
}

/// (r, q) with x = (q + r/(π/2))·π/2 mod 2π, |r| ≤ π/4, for finite |x| ≥ 2²⁰; q's low two bits
/// are those of `(q + MAGIC).to_bits()` (the quadrant, as the fast reduction gives it). Other
/// input gives unspecified values (no fault: the table row is clamped).
#[inline(always)]
pub(super) fn reduce(x: f64) -> (f64, u64) {
    let bits = x.to_bits();
    let row = (((bits >> 52) & 0x7ff).saturating_sub(FIRST_BIASED_EXP) as usize).min(ROWS - 1);
    let f = &F[row];
    // M in [2⁵², 2⁵³) and its halves: mh, a multiple of 2²⁶ (27 bits), and ml < 2²⁶.
    let m = f64::from_bits((bits & 0x000f_ffff_ffff_ffff) | (1075 << 52));
    let mh = f64::from_bits(m.to_bits() & !0x3ff_ffff);
    let ml = m - mh;
    // mh·f0 is a multiple of 4. The others, largest first, are multiples of 2⁻²⁴ or 2⁻⁵⁰ below
    // 2²⁹: reduced mod 4 and added exactly.
    let s = mod4(mod4(ml * f[0]) + mod4(mh * f[1]) + ml * f[1]);
    let h = mod4(s + mod4(mh * f[2]));
    // The small products (below 2⁻²²): rounded as they are added.
    let l = (((ml * f[4] + mh * f[4]) + ml * f[3]) + mh * f[3]) + ml * f[2];
    // x < 0: the residue of |x| negated.
    let sign = bits & (1 << 63);
    let h = f64::from_bits(h.to_bits() ^ sign);
    let l = f64::from_bits(l.to_bits() ^ sign);
    let t = (h + l) + MAGIC;
    let q = t - MAGIC;
    let r = ((h - q) + l) * std::f64::consts::FRAC_PI_2;
    (r, t.to_bits())
}
