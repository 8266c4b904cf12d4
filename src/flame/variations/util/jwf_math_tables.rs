//! The look-up tables of JWildfire's default maths (`FAST_MATH`), which follows Jafama 1.2
//! (Jeff Hain, `odk.lang.FastMath`; Jafama 2, github.com/jeffhain/jafama, Apache-2.0, keeps the
//! same tables): values of sin, cos, tan, asin, atan, exp, ln and √ at fixed steps, with the
//! Taylor coefficients of the polynomial that interpolates between steps.
//!
//! Jafama fills its tables with `StrictMath`, i.e. fdlibm 5.3. The `libm` crate (a port of
//! musl, itself derived from fdlibm) gives the same bits for all but a few hundred of the
//! 110 000 entries; those are listed here as corrections (found by comparing every entry with
//! the tables JWildfire 9.00 builds under OpenJDK 17), and the unit tests check a checksum of
//! every finished table against the same run.

/// π/2 in two parts (Jafama's `PIO2_HI`, `PIO2_LO`: fdlibm's 33 + 53 bits).
pub(super) const PIO2_HI: f64 = f64::from_bits(0x3ff9_21fb_5440_0000);
pub(super) const PIO2_LO: f64 = f64::from_bits(0x3dd0_b461_1a62_6331);
/// 2/π (fdlibm's `invpio2`).
pub(super) const INVPIO2: f64 = f64::from_bits(0x3fe4_5f30_6dc9_c883);

/// Entries of the sine and cosine tables over [0, 2π] (2¹¹ steps).
pub(super) const SIN_COS_TABS_SIZE: usize = (1 << 11) + 1;
/// Entries of the tangent tables that are stored: the steps of [0, π/2] (2¹² of them) below
/// 77°; above, tan is taken as 1/tan of the complement.
pub(super) const TAN_VIRTUAL_TABS_SIZE: usize = (1 << 12) + 1;
pub(super) const TAN_TABS_SIZE: usize = 3505;
/// Arcsine tables over [0, sin 73°] (2¹³ steps).
pub(super) const ASIN_TABS_SIZE: usize = (1 << 13) + 1;
/// sin 73°, the end of the arcsine tables.
pub(super) const ASIN_MAX_VALUE_FOR_TABS: f64 = f64::from_bits(0x3fee_9a0c_6e7b_db1f);
/// Arctangent tables over [0, tan 74°] (2¹² steps).
pub(super) const ATAN_TABS_SIZE: usize = (1 << 12) + 1;
/// tan 74°, the end of the arctangent tables.
pub(super) const ATAN_MAX_VALUE_FOR_TABS: f64 = f64::from_bits(0x400b_e639_8b3f_2869);
/// e^x for x in [−1, 1] at steps of 2⁻¹⁰.
pub(super) const EXP_LO_TAB_SIZE: usize = (1 << 11) + 1;
/// e^n for the integers n from 0 to 709 (the last below the overflow limit).
pub(super) const EXP_HI_TAB_SIZE: usize = 710;
/// e^−n for n from 0 to 745 (scaled by 2⁵⁴ below −705, to stay normal).
pub(super) const EXP_HI_INV_TAB_SIZE: usize = 746;
/// ln(1 + i/2¹²): the first 12 bits of the mantissa.
pub(super) const LOG_TAB_SIZE: usize = 1 << 12;
/// √ by exponent (−1074 to 1023) and by the first 12 bits of the mantissa.
pub(super) const SQRT_HI_TAB_SIZE: usize = 2098;
pub(super) const SQRT_LO_TAB_SIZE: usize = 1 << 12;

/// A value and its first four derivatives divided by 1!, 2!, 3!, 4!, at every step.
pub(super) struct Taylor {
    pub(super) f: Vec<f64>,
    pub(super) d1: Vec<f64>,
    pub(super) d2: Vec<f64>,
    pub(super) d3: Vec<f64>,
    pub(super) d4: Vec<f64>,
}

impl Taylor {
    fn new(n: usize) -> Self {
        Taylor {
            f: vec![0.0; n],
            d1: vec![0.0; n],
            d2: vec![0.0; n],
            d3: vec![0.0; n],
            d4: vec![0.0; n],
        }
    }
}

/// Every table of the JWildfire maths.
pub(super) struct Tables {
    pub(super) sin: Vec<f64>,
    pub(super) cos: Vec<f64>,
    pub(super) tan: Taylor,
    pub(super) asin: Taylor,
    pub(super) atan: Taylor,
    pub(super) exp_hi: Vec<f64>,
    pub(super) exp_hi_inv: Vec<f64>,
    pub(super) exp_lo_pos: Vec<f64>,
    pub(super) exp_lo_neg: Vec<f64>,
    pub(super) log_x_log: Vec<f64>,
    pub(super) log_x_inv: Vec<f64>,
    pub(super) sqrt_x_hi: Vec<f64>,
    pub(super) sqrt_slope_hi: Vec<f64>,
    pub(super) sqrt_x_lo: Vec<f64>,
    pub(super) sqrt_slope_lo: Vec<f64>,
}

const ONE_DIV_F2: f64 = 0.5;
const ONE_DIV_F3: f64 = 1.0 / 6.0;
const ONE_DIV_F4: f64 = 1.0 / 24.0;

impl Tables {
    /// The tables as the `libm` crate computes them, before the corrections.
    #[allow(clippy::needless_range_loop)] // several tables are filled from one step value
    pub(super) fn computed() -> Self {
        let n = SIN_COS_TABS_SIZE;
        let (d_hi, d_lo) = sin_cos_delta();
        let mut sin = vec![0.0; n];
        let mut cos = vec![0.0; n];
        for i in 0..n {
            let a = i as f64 * d_hi + i as f64 * d_lo;
            sin[i] = libm::sin(a);
            cos[i] = libm::cos(a);
        }
        // Exact zeros at π, 2π (sine) and π/2, 3π/2 (cosine).
        let half = (n - 1) / 2;
        sin[half] = 0.0;
        sin[2 * half] = 0.0;
        cos[half / 2] = 0.0;
        cos[3 * half / 2] = 0.0;

        let (t_hi, t_lo) = tan_delta();
        let mut tan = Taylor::new(TAN_TABS_SIZE);
        for i in 0..TAN_TABS_SIZE {
            let a = i as f64 * t_hi + i as f64 * t_lo;
            tan.f[i] = libm::tan(a);
            let c = libm::cos(a);
            let s = libm::sin(a);
            let inv_c = 1.0 / c;
            let inv_c2 = inv_c * inv_c;
            let inv_c3 = inv_c2 * inv_c;
            let inv_c4 = inv_c2 * inv_c2;
            let inv_c5 = inv_c3 * inv_c2;
            tan.d1[i] = inv_c2;
            tan.d2[i] = 2.0 * s * inv_c3 * ONE_DIV_F2;
            tan.d3[i] = 2.0 * (1.0 + 2.0 * s * s) * inv_c4 * ONE_DIV_F3;
            tan.d4[i] = 8.0 * s * (2.0 + s * s) * inv_c5 * ONE_DIV_F4;
        }

        let a_delta = asin_delta();
        let mut asin = Taylor::new(ASIN_TABS_SIZE);
        for i in 0..ASIN_TABS_SIZE {
            let x = i as f64 * a_delta;
            asin.f[i] = libm::asin(x);
            let one_m = 1.0 / (1.0 - x * x);
            let p1 = libm::sqrt(one_m);
            let p3 = p1 * one_m;
            let p5 = p3 * one_m;
            let p7 = p5 * one_m;
            asin.d1[i] = p1;
            asin.d2[i] = x * p3 * ONE_DIV_F2;
            asin.d3[i] = (1.0 + 2.0 * x * x) * p5 * ONE_DIV_F3;
            asin.d4[i] = (5.0 + 2.0 * x * (2.0 + x * (5.0 - 2.0 * x))) * p7 * ONE_DIV_F4;
        }

        let t_delta = atan_delta();
        let mut atan = Taylor::new(ATAN_TABS_SIZE);
        for i in 0..ATAN_TABS_SIZE {
            let x = i as f64 * t_delta;
            let one_p = 1.0 / (1.0 + x * x);
            let p2 = one_p * one_p;
            let p3 = p2 * one_p;
            let p4 = p2 * p2;
            atan.f[i] = libm::atan(x);
            atan.d1[i] = one_p;
            atan.d2[i] = -2.0 * x * p2 * ONE_DIV_F2;
            atan.d3[i] = (-2.0 + 6.0 * x * x) * p3 * ONE_DIV_F3;
            atan.d4[i] = 24.0 * x * (1.0 - x * x) * p4 * ONE_DIV_F4;
        }

        let mid = (EXP_LO_TAB_SIZE - 1) / 2;
        let mut exp_lo_pos = vec![0.0; EXP_LO_TAB_SIZE];
        let mut exp_lo_neg = vec![0.0; EXP_LO_TAB_SIZE];
        for i in 0..EXP_LO_TAB_SIZE {
            let x = -1.0 + i as f64 / mid as f64;
            exp_lo_pos[i] = libm::exp(x);
            exp_lo_neg[i] = -libm::expm1(-x);
        }
        let exp_hi = (0..EXP_HI_TAB_SIZE).map(|i| libm::exp(i as f64)).collect();
        let ln2 = libm::log(2.0);
        let exp_hi_inv = (0..EXP_HI_INV_TAB_SIZE)
            .map(|i| {
                let n = i as f64;
                if -n >= -705.0 {
                    libm::exp(-n)
                } else {
                    libm::exp(54.0 * ln2 - n)
                }
            })
            .collect();

        let step = 1.0 / LOG_TAB_SIZE as f64;
        let log_x: Vec<f64> = (0..LOG_TAB_SIZE).map(|i| 1.0 + i as f64 * step).collect();
        let log_x_log = log_x.iter().map(|&x| libm::log(x)).collect();
        let log_x_inv = log_x.iter().map(|&x| 1.0 / x).collect();

        let mut sqrt_x_hi = vec![0.0; SQRT_HI_TAB_SIZE];
        let mut sqrt_slope_hi = vec![0.0; SQRT_HI_TAB_SIZE];
        for (i, e) in (-1074..=1023).enumerate() {
            let r = libm::pow(2.0, f64::from(e) * 0.5);
            sqrt_x_hi[i] = r * 0.5;
            sqrt_slope_hi[i] = 1.0 / r;
        }
        let mut sqrt_x_lo = vec![1.0; SQRT_LO_TAB_SIZE];
        let mut sqrt_slope_lo = vec![1.0; SQRT_LO_TAB_SIZE];
        // 1 plus the mantissa's low bits set: the middle of each 2⁻¹² interval of [1, 2).
        let base = 1.0f64.to_bits() | (0x000f_ffff_ffff_ffff >> 12);
        for i in 1..SQRT_LO_TAB_SIZE {
            let r = libm::sqrt(f64::from_bits(base | ((i as u64 - 1) << 40)));
            sqrt_x_lo[i] = r;
            sqrt_slope_lo[i] = 1.0 / r;
        }

        Tables {
            sin,
            cos,
            tan,
            asin,
            atan,
            exp_hi,
            exp_hi_inv,
            exp_lo_pos,
            exp_lo_neg,
            log_x_log,
            log_x_inv,
            sqrt_x_hi,
            sqrt_slope_hi,
            sqrt_x_lo,
            sqrt_slope_lo,
        }
    }

    /// The tables as JWildfire has them: computed, then corrected.
    pub(super) fn build() -> Self {
        let mut t = Tables::computed();
        for &(table, fixes) in FIXES {
            let v = t.table_mut(table);
            for &(i, bits) in fixes {
                if let Some(e) = v.get_mut(usize::from(i)) {
                    *e = f64::from_bits(bits);
                }
            }
        }
        t
    }

    /// Every table by name (the names of Jafama's fields), in a fixed order.
    #[cfg(test)]
    pub(super) fn all(&self) -> [(&'static str, &Vec<f64>); 27] {
        [
            ("sinTab", &self.sin),
            ("cosTab", &self.cos),
            ("tanTab", &self.tan.f),
            ("tanDer1DivF1Tab", &self.tan.d1),
            ("tanDer2DivF2Tab", &self.tan.d2),
            ("tanDer3DivF3Tab", &self.tan.d3),
            ("tanDer4DivF4Tab", &self.tan.d4),
            ("asinTab", &self.asin.f),
            ("asinDer1DivF1Tab", &self.asin.d1),
            ("asinDer2DivF2Tab", &self.asin.d2),
            ("asinDer3DivF3Tab", &self.asin.d3),
            ("asinDer4DivF4Tab", &self.asin.d4),
            ("atanTab", &self.atan.f),
            ("atanDer1DivF1Tab", &self.atan.d1),
            ("atanDer2DivF2Tab", &self.atan.d2),
            ("atanDer3DivF3Tab", &self.atan.d3),
            ("atanDer4DivF4Tab", &self.atan.d4),
            ("expHiTab", &self.exp_hi),
            ("expHiInvTab", &self.exp_hi_inv),
            ("expLoPosTab", &self.exp_lo_pos),
            ("expLoNegTab", &self.exp_lo_neg),
            ("logXLogTab", &self.log_x_log),
            ("logXInvTab", &self.log_x_inv),
            ("sqrtXSqrtHiTab", &self.sqrt_x_hi),
            ("sqrtSlopeHiTab", &self.sqrt_slope_hi),
            ("sqrtXSqrtLoTab", &self.sqrt_x_lo),
            ("sqrtSlopeLoTab", &self.sqrt_slope_lo),
        ]
    }

    fn table_mut(&mut self, name: Table) -> &mut Vec<f64> {
        match name {
            Table::Sin => &mut self.sin,
            Table::Cos => &mut self.cos,
            Table::TanD1 => &mut self.tan.d1,
            Table::TanD2 => &mut self.tan.d2,
            Table::TanD3 => &mut self.tan.d3,
            Table::TanD4 => &mut self.tan.d4,
            Table::LogXLog => &mut self.log_x_log,
        }
    }
}

/// The step of the sine and cosine tables, 2π/2¹¹, in two parts.
pub(super) fn sin_cos_delta() -> (f64, f64) {
    let steps = (SIN_COS_TABS_SIZE - 1) as f64;
    (4.0 * PIO2_HI / steps, 4.0 * PIO2_LO / steps)
}

/// The step of the tangent tables, (π/2)/2¹², in two parts.
pub(super) fn tan_delta() -> (f64, f64) {
    let steps = (TAN_VIRTUAL_TABS_SIZE - 1) as f64;
    (PIO2_HI / steps, PIO2_LO / steps)
}

pub(super) fn asin_delta() -> f64 {
    ASIN_MAX_VALUE_FOR_TABS / (ASIN_TABS_SIZE - 1) as f64
}

pub(super) fn atan_delta() -> f64 {
    ATAN_MAX_VALUE_FOR_TABS / (ATAN_TABS_SIZE - 1) as f64
}

/// The tables that need corrections.
#[derive(Clone, Copy)]
enum Table {
    Sin,
    Cos,
    TanD1,
    TanD2,
    TanD3,
    TanD4,
    LogXLog,
}

/// The entries where fdlibm (as OpenJDK 17's `StrictMath`) and the `libm` crate differ: index
/// and the bits of fdlibm's value.
type Fixes = &'static [(u16, u64)];

const FIXES: &[(Table, Fixes)] = &[
    (
        Table::Sin,
        &[
            (300, 0x3fe9_777e_f4c7_d742),
            (305, 0x3fe9_c2d1_10f0_75c2),
            (386, 0x3fed_a383_a966_8988),
            (560, 0x3fef_a755_7f08_a516),
            (594, 0x3fee_fe22_0c0b_95ec),
            (699, 0x3fea_e068_f345_ecf0),
            (715, 0x3fe9_fdf4_f131_49de),
            (743, 0x3fe8_4b71_11af_83fa),
            (765, 0x3fe6_d5af_ef4a_afce),
            (1405, 0xbfed_733f_508c_0e00),
            (1589, 0xbfef_93f1_4f85_ac08),
            (1602, 0xbfef_58a2_b178_9e84),
            (1611, 0xbfef_2817_fc46_09ce),
            (1636, 0xbfee_817b_ab4c_d10c),
            (1682, 0xbfec_d7d9_898b_32f6),
            (1767, 0xbfe8_4b71_11af_83fc),
            (1777, 0xbfe7_a4f7_07bf_97d0),
            (1778, 0xbfe7_9400_574f_55e6),
        ],
    ),
    (
        Table::Cos,
        &[
            (237, 0x3fe7_e83f_87b0_3686),
            (242, 0x3fe7_9400_574f_55e4),
            (688, 0xbfe0_7387_9922_ffec),
            (775, 0xbfe7_1bac_960e_41be),
            (797, 0xbfe8_8c66_e748_1ba0),
            (934, 0xbfee_c9b2_d3c3_bf84),
            (943, 0xbfef_045a_14cf_738c),
            (954, 0xbfef_43d0_85ff_92dc),
            (964, 0xbfef_7599_a3a1_2078),
            (972, 0xbfef_97f9_24c9_099a),
            (1149, 0xbfed_acf4_2ce6_8aba),
            (1204, 0xbfeb_3e4d_3ef5_5710),
            (1228, 0xbfe9_ef43_ef29_af94),
            (1824, 0x3fe8_bc80_6b15_1742),
            (1826, 0x3fe8_dc45_3316_98cc),
            (1910, 0x3fed_2cb2_20e0_ef9e),
            (1911, 0x3fed_36fc_7bcb_fbdc),
            (1951, 0x3fee_97ec_3601_6b32),
        ],
    ),
    (
        Table::TanD1,
        &[
            (645, 0x3ff1_0532_e5d5_359e),
            (789, 0x3ff1_8f23_2ee7_6448),
            (842, 0x3ff1_ca9d_9b22_1715),
            (1037, 0x3ff2_d2c3_629c_cd01),
            (1555, 0x3ff7_5f24_f0da_f76d),
            (1650, 0x3ff8_9ae8_026e_52a1),
            (1657, 0x3ff8_b3d3_92fa_9197),
            (1790, 0x3ffa_be18_41eb_8974),
            (1846, 0x3ffb_b8dc_b32b_6874),
            (1867, 0x3ffc_1c31_4853_8dce),
            (1896, 0x3ffc_aa68_166b_f78c),
            (1898, 0x3ffc_b46f_ce69_e399),
            (1929, 0x3ffd_53b5_6139_4738),
            (1933, 0x3ffd_68ca_bd98_5675),
            (1936, 0x3ffd_78af_aae5_b098),
            (1966, 0x3ffe_1b90_e114_f43a),
            (1977, 0x3ffe_5921_7d33_5827),
            (1990, 0x3ffe_a334_e084_7b75),
            (2029, 0x3fff_8a56_9b3c_ba91),
        ],
    ),
    (
        Table::TanD2,
        &[
            (645, 0x3fd1_3138_1dea_baa6),
            (789, 0x3fd5_ecdc_33a3_d7e4),
            (842, 0x3fd7_d028_5856_4d91),
            (1037, 0x3fdf_a0cd_d463_14b3),
            (1555, 0x3fef_ba5b_4b77_6667),
            (1650, 0x3ff2_0b5f_e767_2e64),
            (1657, 0x3ff2_37ce_cee3_073e),
            (1790, 0x3ff5_e9a9_b10c_66dc),
            (1846, 0x3ff7_ba7b_fa32_ad37),
            (1867, 0x3ff8_749d_ee22_c1da),
            (1896, 0x3ff9_8122_1e23_3873),
            (1898, 0x3ff9_9429_7909_3ff1),
            (1929, 0x3ffa_c3ef_fb8d_0a62),
            (1933, 0x3ffa_ec60_ac6d_90a4),
            (1936, 0x3ffb_0ae6_5a8f_24db),
            (1966, 0x3ffc_4570_f2bb_3084),
            (1977, 0x3ffc_bd2a_f13d_5bf6),
            (1990, 0x3ffd_4dd5_b3ae_cbf9),
            (2029, 0x3fff_1585_84a1_88d0),
            (2091, 0x4001_19b8_40b5_8045),
            (2095, 0x4001_3525_7aaf_c09b),
            (2105, 0x4001_7aaa_628e_3a76),
            (2118, 0x4001_d71f_18fc_d306),
            (2150, 0x4002_c534_f9b3_ddb2),
            (2183, 0x4003_cb75_9a9b_e495),
            (2191, 0x4004_0dc2_5aa4_2119),
            (2195, 0x4004_2f52_d1bc_3b27),
            (2211, 0x4004_b869_9cd8_1f6e),
            (2255, 0x4006_4a25_dfde_0666),
            (2350, 0x400a_3c54_9eb0_f63f),
            (2400, 0x400c_ad8d_1517_daca),
            (2405, 0x400c_f028_5526_7807),
            (2415, 0x400d_77be_4c45_c4c1),
            (2440, 0x400e_d91d_0cc1_0804),
            (2458, 0x400f_e4fa_94d5_a7c3),
            (2706, 0x401a_4092_e711_1a0b),
            (2753, 0x401d_210f_786e_3699),
            (2983, 0x4029_a8c7_bc7f_6f59),
            (3023, 0x402c_a58a_ab83_370e),
            (3030, 0x402d_375c_f22d_863a),
            (3052, 0x402f_1b84_26c9_8c77),
            (3118, 0x4032_ed8f_39ca_f4e8),
            (3139, 0x4034_3434_34ef_932d),
            (3257, 0x403d_ffdc_d81c_e30e),
            (3274, 0x403f_e6c1_333e_d70a),
            (3351, 0x4045_6e18_5045_790b),
            (3397, 0x4049_f2b7_3837_5d67),
            (3412, 0x404b_b199_a3a1_8b2c),
            (3436, 0x404e_d3d1_840b_8768),
            (3438, 0x404f_1c06_bf41_42bf),
            (3478, 0x4052_c6a4_4c53_4376),
        ],
    ),
    (
        Table::TanD3,
        &[
            (645, 0x3fdb_0904_fe77_488c),
            (789, 0x3fde_41a4_a66a_35c9),
            (842, 0x3fdf_b0ae_a4bd_388d),
            (1037, 0x3fe3_311b_5ca2_f2a7),
            (1555, 0x3ff2_8efc_b03a_54a2),
            (1650, 0x3ff5_6f4e_6fa9_d304),
            (1657, 0x3ff5_ab7d_6fd9_b405),
            (1790, 0x3ffa_de91_2a8d_83e8),
            (1846, 0x3ffd_8d02_efe8_12f1),
            (1867, 0x3ffe_a567_fa01_ad28),
            (1896, 0x4000_1f9e_e859_c0fa),
            (1898, 0x4000_2e42_7a6e_cee0),
            (1929, 0x4001_1a01_ee11_2779),
            (1933, 0x4001_39ad_b89b_86c4),
            (1936, 0x4001_51a0_560f_28a2),
            (1966, 0x4002_4a97_1a0c_1121),
            (1977, 0x4002_aa61_38c5_4c4f),
            (1990, 0x4003_1edc_927d_8e7e),
            (2029, 0x4004_92eb_a4ec_11c0),
            (2074, 0x4006_6e84_6490_c5d4),
            (2091, 0x4007_306c_7572_56f8),
            (2105, 0x4007_d66d_5314_10dc),
            (2124, 0x4008_c14f_3f2b_23d5),
            (2191, 0x400c_5f48_649d_1361),
            (2211, 0x400d_949a_cfc6_b682),
            (2255, 0x4010_3d19_2299_feee),
            (2400, 0x4016_7b8d_1d01_dd6d),
            (2415, 0x4017_4a52_f899_4d2e),
            (2440, 0x4018_b832_679b_7c9c),
            (2458, 0x4019_d142_6b86_0ff5),
            (2476, 0x401a_fa37_78e5_67e5),
            (2706, 0x4028_d3fa_bdb5_f1ad),
            (2753, 0x402c_7b19_327e_e78d),
            (2886, 0x4035_9878_3fc9_dc06),
            (3030, 0x4041_ea3c_632b_02ca),
            (3052, 0x4043_78e5_af94_8269),
            (3118, 0x4049_47e9_9b2d_d176),
            (3139, 0x404b_92a4_1f2e_0060),
            (3351, 0x4062_c376_fe2f_0f12),
            (3397, 0x4068_360c_1c78_1ce2),
            (3412, 0x406a_67cf_d8dd_06a1),
            (3436, 0x406e_75e1_82d5_5ce1),
        ],
    ),
    (
        Table::TanD4,
        &[
            (645, 0x3fc9_1d9d_fae8_2b41),
            (789, 0x3fd0_c0db_0c1c_bf91),
            (842, 0x3fd2_8aab_f9de_ab24),
            (1037, 0x3fda_aa99_1062_c868),
            (1555, 0x3ff1_e28d_9bd2_1cd3),
            (1650, 0x3ff5_bbf8_5b62_bf4c),
            (1657, 0x3ff6_0ddd_325a_9435),
            (1790, 0x3ffd_5228_7c8c_d740),
            (1846, 0x4000_9a02_8be0_a0fc),
            (1867, 0x4001_6826_3cb6_6539),
            (1896, 0x4002_989e_7ad1_6eea),
            (1898, 0x4002_ae82_d348_56e6),
            (1929, 0x4004_1198_136c_045e),
            (1933, 0x4004_41a7_a2b2_9e06),
            (1936, 0x4004_660d_06d5_38f4),
            (1966, 0x4005_e336_fc69_77a2),
            (1977, 0x4006_7732_a23e_3eb6),
            (1990, 0x4007_2c1e_f477_6d9e),
            (2029, 0x4009_74f9_5d7a_4471),
            (2074, 0x400c_6f5d_5835_508e),
            (2091, 0x400d_aac0_5a5e_ec06),
            (2105, 0x400e_bac7_06ce_a954),
            (2118, 0x400f_c1d7_53ff_d622),
            (2150, 0x4011_3bb8_4005_f05e),
            (2183, 0x4012_c706_8961_62c3),
            (2195, 0x4013_612c_8647_70b0),
            (2211, 0x4014_37ff_71dc_f629),
            (2255, 0x4016_c2af_55ef_6175),
            (2286, 0x4018_c850_a6fa_5a8c),
            (2350, 0x401d_ae32_b369_cb0c),
            (2400, 0x4021_2a1f_2980_a48a),
            (2440, 0x4023_57da_de69_17fb),
            (2458, 0x4024_6e50_a8d8_4ba0),
            (2476, 0x4025_97bf_cbed_3f82),
            (2706, 0x4037_3a2c_4fb7_f3b1),
            (2753, 0x403b_9679_75a0_25a4),
            (2886, 0x4047_3ccf_5df4_5682),
            (3023, 0x4055_3076_056c_8a4f),
            (3030, 0x4055_e4ee_0cf0_3bed),
            (3052, 0x4058_4cf2_fd2b_3500),
            (3088, 0x405c_f623_35c0_a9ac),
            (3118, 0x4060_d7a2_6fc1_0e81),
            (3139, 0x4062_c5f0_8473_8acf),
            (3257, 0x4072_1fdc_a298_94c6),
            (3324, 0x407b_7a74_d980_51c4),
            (3346, 0x407f_c084_1682_a50c),
            (3397, 0x4086_93aa_4019_1710),
            (3412, 0x4089_29d0_b12b_556c),
            (3436, 0x408e_1565_207e_b006),
            (3438, 0x408e_8b26_ceb6_75ae),
            (3478, 0x4094_e58c_65d2_370d),
        ],
    ),
    (
        Table::LogXLog,
        &[
            (227, 0x3fab_9ddb_0b26_f20d),
            (236, 0x3fac_ae72_fb95_c20b),
            (400, 0x3fb7_da76_6d7b_12cd),
            (411, 0x3fb8_7a9b_c136_57f2),
            (443, 0x3fba_4a46_37ed_23be),
            (494, 0x3fbd_2687_1895_6a32),
            (495, 0x3fbd_34cd_dd63_eba3),
            (500, 0x3fbd_7c23_c69c_b340),
            (504, 0x3fbd_b527_0187_d928),
            (549, 0x3fc0_1993_2dc3_3ead),
            (555, 0x3fc0_43df_d91b_a862),
            (557, 0x3fc0_51f6_4ce7_d3f1),
            (563, 0x3fc0_7c30_5d1f_a421),
            (567, 0x3fc0_984f_575c_1f78),
            (585, 0x3fc1_168e_8127_e327),
            (627, 0x3fc2_3b41_2580_b40c),
            (629, 0x3fc2_4920_a1b9_1215),
            (709, 0x3fc4_6f49_02a6_f800),
            (750, 0x3fc5_85b3_7d34_c876),
            (789, 0x3fc6_8c5b_bea4_66f1),
            (874, 0x3fc8_c19f_e298_2057),
            (903, 0x3fc9_8045_3ed2_2499),
            (907, 0x3fc9_9a7a_ca4d_5a9f),
            (932, 0x3fca_3dd0_4b93_8660),
            (953, 0x3fca_c663_48e8_d87c),
            (980, 0x3fcb_7526_a22e_4703),
            (1019, 0x3fcc_6ff3_c6ef_cf70),
            (1055, 0x3fcd_55c5_099c_7930),
            (1083, 0x3fce_0768_a96b_17ef),
            (1097, 0x3fce_5fde_5bc9_03a6),
            (1109, 0x3fce_ab80_6ab0_93b2),
            (1111, 0x3fce_b817_1605_b043),
            (1125, 0x3fcf_1013_2bf2_977e),
            (1149, 0x3fcf_a65b_bd2f_d023),
            (1156, 0x3fcf_d20f_bf76_fdc8),
            (1172, 0x3fd0_1ade_3913_9ef7),
            (1182, 0x3fd0_39f0_8744_c24c),
            (1226, 0x3fd0_c1f5_5d88_a8a0),
            (1235, 0x3fd0_dda4_55d1_ab93),
            (1255, 0x3fd1_1afe_6a86_bd15),
            (1263, 0x3fd1_3378_6aeb_970a),
            (1296, 0x3fd1_980d_2dd4_2370),
            (1331, 0x3fd2_020e_d5db_d513),
            (1356, 0x3fd2_4d5b_ef6a_eff9),
            (1359, 0x3fd2_565f_3ea5_d665),
            (1375, 0x3fd2_865b_8130_49cf),
            (1376, 0x3fd2_895a_13de_86a4),
            (1378, 0x3fd2_8f56_cdaa_0a1d),
            (1393, 0x3fd2_bc2c_6d90_027f),
            (1395, 0x3fd2_c224_6858_2293),
            (1404, 0x3fd2_dcf9_6f8f_d216),
            (1414, 0x3fd2_fabc_84ca_c498),
            (1420, 0x3fd3_0c91_557f_1ebd),
            (1431, 0x3fd3_2d35_47d4_c69e),
            (1491, 0x3fd3_de1c_6de0_d4ad),
            (1511, 0x3fd4_18a8_21a4_c2a9),
            (1521, 0x3fd4_35d9_f257_fdcd),
            (1550, 0x3fd4_8a39_00b8_e0c3),
            (1744, 0x3fd6_b3bb_2235_943d),
            (1754, 0x3fd6_cfc3_04df_e9ea),
            (1760, 0x3fd6_e08e_aa2b_a1e3),
            (1792, 0x3fd7_39d7_f6bb_d006),
            (1810, 0x3fd7_6bda_aa4f_e7a9),
            (1820, 0x3fd7_8792_6d6b_723f),
            (1829, 0x3fd7_a07a_5da6_1e88),
            (1846, 0x3fd7_cf6b_6ca1_cf13),
            (1856, 0x3fd7_eaf8_3b82_afc4),
            (1862, 0x3fd7_fb7a_3b58_15c7),
            (1876, 0x3fd8_21ee_5ea9_b160),
            (1898, 0x3fd8_5e2d_3325_7404),
            (1926, 0x3fd8_aa88_9737_e6cf),
            (1940, 0x3fd8_d094_3ac0_f569),
            (1949, 0x3fd8_e8fd_810a_8fe3),
            (1974, 0x3fd9_2c9b_e77a_066d),
            (1976, 0x3fd9_3201_a7a3_5336),
            (2005, 0x3fd9_8012_0dd9_6609),
            (2041, 0x3fd9_e076_88a9_c028),
            (2062, 0x3fda_186e_62c0_e7f9),
            (2071, 0x3fda_305b_f13f_f789),
            (2072, 0x3fda_3304_0204_fa63),
            (2094, 0x3fda_6d59_9e90_75ad),
            (2138, 0x3fda_e166_4588_2a0c),
            (2141, 0x3fda_e948_381d_e5f7),
            (2148, 0x3fda_fba8_fdce_860b),
            (2188, 0x3fdb_6448_a205_482e),
            (2227, 0x3fdb_c9a7_09b2_3b8a),
            (2289, 0x3fdc_6985_d777_c1b0),
            (2382, 0x3fdd_5670_ddef_7f0f),
            (2402, 0x3fdd_88f2_4c32_508e),
            (2406, 0x3fdd_9307_686a_b204),
            (2420, 0x3fdd_b644_ce44_844f),
            (2457, 0x3fde_130a_15a7_14ce),
            (2574, 0x3fdf_34fc_4332_cab6),
            (2607, 0x3fdf_85d8_86b1_dc50),
            (2711, 0x3fe0_410c_a8c6_b66b),
            (2793, 0x3fe0_a324_e273_90e3),
            (2827, 0x3fe0_cb79_b844_7d7c),
            (2972, 0x3fe1_7548_39eb_3cd6),
            (3170, 0x3fe2_579d_2322_11b2),
            (3177, 0x3fe2_5f80_8ad4_89b1),
            (3341, 0x3fe3_162c_43ca_f73f),
        ],
    ),
];
