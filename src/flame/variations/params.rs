//! A variation's parameters: their kinds (how a stored value is normalised before a formula
//! sees it), the text parameters some JWildfire variations take, and the constructors the
//! registry's tables use.

/// How a parameter's value is normalised before use (Fractorium's parameter types).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ParamKind {
    /// Clamped to [min, max].
    Real,
    /// Wrapped into [min, max).
    Cyclic,
    /// Clamped; a value within 1e-6 of 0 becomes ±`f64::EPSILON`.
    NonZero,
    /// Rounded (half up) and clamped.
    Int,
    /// Rounded and clamped; 0 becomes ±1.
    IntNonZero,
}

/// A text parameter (JWildfire's "resources": a string, stored in files as the hex digits of
/// its UTF-8 bytes).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TextParam {
    /// Full attribute name.
    pub name: &'static str,
    /// Value of a new variation.
    pub default: &'static str,
    /// Most bytes a value may have (longer ones are cut at a character boundary).
    pub max_len: usize,
}

impl TextParam {
    /// `v` cut to at most [`TextParam::max_len`] bytes at a character boundary.
    pub fn normalise(&self, v: &str) -> String {
        let mut end = v.len().min(self.max_len);
        while !v.is_char_boundary(end) {
            end -= 1;
        }
        v[..end].to_string()
    }
}

/// One parameter of a variation: full attribute name (e.g. `julian_power`), default and range.
#[derive(Clone, Copy, Debug)]
pub struct Param {
    /// Full attribute name, as written in files.
    pub name: &'static str,
    /// Value of a new variation.
    pub default: f64,
    /// How a stored value is normalised.
    pub kind: ParamKind,
    /// Lower end of the range (may be `-inf`).
    pub min: f64,
    /// Upper end of the range (may be `inf`).
    pub max: f64,
    /// The parameter sets a count, a loop bound, a recursion depth or a table size, and the
    /// range is what the variation can use: a stored value outside it is reported when a file
    /// is read (see [`Param::limited`]).
    pub limited: bool,
}

impl Param {
    /// The same parameter marked as a count, loop bound, recursion depth or table size whose
    /// range is what the variation can use, chosen so that no stored value makes one
    /// evaluation (or the preparation of the variation) take more than a moment.
    pub const fn limited(self) -> Param {
        Param {
            limited: true,
            ..self
        }
    }

    /// Is the stored value `v` outside the range of a [limited](Param::limited) parameter (the
    /// variation will use the nearest bound)?
    pub fn beyond_limit(&self, v: f64) -> bool {
        self.limited && (v > self.max + 0.5 || v < self.min - 0.5)
    }

    /// The value a formula sees for the stored value `v` (a value that is not a number takes
    /// the default).
    pub fn normalise(&self, v: f64) -> f64 {
        let v = if v.is_nan() { self.default } else { v };
        let (lo, hi) = (self.min, self.max);
        match self.kind {
            ParamKind::Real => v.clamp(lo, hi),
            ParamKind::Cyclic => {
                if v > hi {
                    lo + (v - lo) % (hi - lo)
                } else if v < lo {
                    hi - (hi - v) % (hi - lo)
                } else {
                    v
                }
            }
            ParamKind::NonZero => {
                let c = v.clamp(lo, hi);
                if c.abs() < 1e-6 {
                    if c < 0.0 { -f64::EPSILON } else { f64::EPSILON }
                } else {
                    c
                }
            }
            ParamKind::Int => (v + 0.5)
                .floor()
                .clamp(lo, hi)
                .clamp(-2147483648.0, 2147483647.0),
            ParamKind::IntNonZero => {
                let i = (v + 0.5)
                    .floor()
                    .clamp(lo, hi)
                    .clamp(-2147483648.0, 2147483647.0);
                if i == 0.0 {
                    if v < 0.0 { -1.0 } else { 1.0 }
                } else {
                    i
                }
            }
        }
    }
}

/// The bound of a parameter range that is open upwards.
pub(super) const INF: f64 = f64::INFINITY;
/// The bound of a parameter range that is open downwards.
pub(super) const NEG_INF: f64 = f64::NEG_INFINITY;

/// A real parameter without bounds.
pub const fn p(name: &'static str, default: f64) -> Param {
    Param {
        name,
        default,
        kind: ParamKind::Real,
        min: f64::MIN,
        max: f64::MAX,
        limited: false,
    }
}

/// A real parameter clamped to [min, max].
pub const fn p_range(name: &'static str, default: f64, min: f64, max: f64) -> Param {
    Param {
        name,
        default,
        kind: ParamKind::Real,
        min,
        max,
        limited: false,
    }
}

/// A real parameter wrapped into [min, max).
pub const fn p_cyclic(name: &'static str, default: f64, min: f64, max: f64) -> Param {
    Param {
        name,
        default,
        kind: ParamKind::Cyclic,
        min,
        max,
        limited: false,
    }
}

/// A real parameter that must not be 0.
pub const fn p_nonzero(name: &'static str, default: f64, min: f64, max: f64) -> Param {
    Param {
        name,
        default,
        kind: ParamKind::NonZero,
        min,
        max,
        limited: false,
    }
}

/// An integer parameter.
pub const fn p_int(name: &'static str, default: f64, min: f64, max: f64) -> Param {
    Param {
        name,
        default,
        kind: ParamKind::Int,
        min,
        max,
        limited: false,
    }
}

/// An integer parameter that must not be 0.
pub const fn p_int_nonzero(name: &'static str, default: f64, min: f64, max: f64) -> Param {
    Param {
        name,
        default,
        kind: ParamKind::IntNonZero,
        min,
        max,
        limited: false,
    }
}

/// The first `N` parameter values of `values`, to bind by name: `let [size, seed] =
/// params_of(q);`. [`Prepared::params`](super::Prepared::params) for the functions that are
/// given the parameters as a slice (the builders of shared data).
#[inline(always)]
pub fn params_of<const N: usize>(values: &[f64]) -> [f64; N] {
    match values.first_chunk() {
        Some(a) => *a,
        None => panic!("{N} parameters read from {} values", values.len()),
    }
}
