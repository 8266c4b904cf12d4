//! C conversions of doubles to integers as x86-64 performs them.
//!
//! C leaves the conversion of an out-of-range double to an integer undefined; x86-64's
//! `cvttsd2si` answers with the "integer indefinite" value, the most negative integer, for NaN
//! and for every value outside the target range. Fractorium's formulas convert freely (cell
//! indices of huge coordinates, parities of NaN), so the helpers below return that value where
//! Rust's saturating `as` would not.

/// 2⁶³, the first double above the i64 range.
const TWO_63: f64 = 9_223_372_036_854_775_808.0;

/// C's `(int)x` on x86-64: truncation toward zero; NaN and values outside the i32 range give
/// `i32::MIN`.
#[inline(always)]
pub fn trunc_i32(x: f64) -> i32 {
    if x > -2_147_483_649.0 && x < 2_147_483_648.0 {
        x as i32
    } else {
        i32::MIN
    }
}

/// C's `(int64_t)x` on x86-64: truncation toward zero; NaN and values outside the i64 range
/// give `i64::MIN`.
#[inline(always)]
pub fn trunc_i64(x: f64) -> i64 {
    if (-TWO_63..TWO_63).contains(&x) {
        x as i64
    } else {
        i64::MIN
    }
}

/// ⌊x⌋ as a 64-bit integer the way Fractorium's integer `Floor` computes it: truncate (as
/// [`trunc_i64`]), then step down by one for a negative non-integer. It equals ⌊x⌋ in the
/// i64 range; NaN and x ≥ 2⁶³ give `i64::MIN`, and x < −2⁶³ gives `i64::MAX` (the step down
/// wraps around from `i64::MIN`, as the C code's signed overflow does on x86-64).
#[inline(always)]
pub fn floor_i64(x: f64) -> i64 {
    let i = trunc_i64(x);
    if x >= 0.0 {
        i
    } else {
        i.wrapping_sub(((i as f64) > x) as i64)
    }
}

/// [`floor_i64`] as a double, computed in floating point: ⌊x⌋ in the i64 range, −2⁶³ for NaN
/// and x ≥ 2⁶³, 2⁶³ − 1 (as a double, 2⁶³) for x < −2⁶³.
#[inline(always)]
pub fn floor_f(x: f64) -> f64 {
    if (-TWO_63..TWO_63).contains(&x) {
        x.floor()
    } else if x < -TWO_63 {
        i64::MAX as f64
    } else {
        i64::MIN as f64
    }
}

/// Apophysis' `LRint` as Fractorium has it: round half away from zero by converting x ± ½ to a
/// 64-bit integer (x86-64 semantics of [`trunc_i64`]: NaN and huge values give −2⁶³).
#[inline(always)]
pub fn lrint(x: f64) -> f64 {
    let shifted = if x >= 0.0 { x + 0.5 } else { x - 0.5 };
    trunc_i64(shifted) as f64
}
