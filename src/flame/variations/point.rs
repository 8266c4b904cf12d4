//! What a formula reads and writes at one point: the input point with the quantities computed
//! once for the xform ([`VarIn`], which ones a formula needs being the bits of [`need`]), the
//! xform's running output ([`Acc`]), and the same for a batch of points as parallel arrays
//! ([`SoaIn`], [`SoaAcc`]).

/// Which per-point quantities a formula reads (bits of [`VarDef::needs`](super::VarDef::needs)).
pub mod need {
    /// `sumsq` = x² + y².
    pub const SUMSQ: u8 = 1;
    /// `sqrt` = r.
    pub const SQRT: u8 = 2;
    /// `ux` = x/r and `uy` = y/r.
    pub const ANGLES: u8 = 4;
    /// `atan_xy` = atan2(x, y).
    pub const ATAN_XY: u8 = 8;
    /// `atan_yx` = atan2(y, x).
    pub const ATAN_YX: u8 = 16;
    /// Every quantity.
    pub const ALL: u8 = 31;
}

/// What a variation reads about its input point.
#[derive(Clone, Copy, Debug, Default)]
pub struct VarIn {
    /// x of the input point.
    pub x: f64,
    /// y of the input point.
    pub y: f64,
    /// z of the input point.
    pub z: f64,
    /// x² + y².
    pub sumsq: f64,
    /// r = √(x² + y²).
    pub sqrt: f64,
    /// x / r (r replaced by `f64::EPSILON` when 0).
    pub ux: f64,
    /// y / r (r replaced by `f64::EPSILON` when 0).
    pub uy: f64,
    /// atan2(x, y).
    pub atan_xy: f64,
    /// atan2(y, x).
    pub atan_yx: f64,
    /// The palette coordinate after the xform's colour blend.
    pub color: f64,
}

impl VarIn {
    /// The input point with the quantities of `needs` computed. With `poison`, quantities not
    /// asked for are NaN (tests use it to catch formulas that read what they did not declare);
    /// otherwise they are 0.
    #[inline(always)]
    pub fn new(x: f64, y: f64, z: f64, color: f64, needs: u8, poison: bool) -> VarIn {
        let fill = if poison { f64::NAN } else { 0.0 };
        let mut t = VarIn {
            x,
            y,
            z,
            sumsq: fill,
            sqrt: fill,
            ux: fill,
            uy: fill,
            atan_xy: fill,
            atan_yx: fill,
            color,
        };
        if needs & (need::SUMSQ | need::SQRT | need::ANGLES) != 0 {
            t.sumsq = x * x + y * y;
        }
        if needs & (need::SQRT | need::ANGLES) != 0 {
            t.sqrt = (x * x + y * y).sqrt();
        }
        if needs & need::ANGLES != 0 {
            let r = (x * x + y * y).sqrt();
            let r = if r == 0.0 { f64::EPSILON } else { r };
            t.ux = x / r;
            t.uy = y / r;
        }
        if needs & need::ATAN_XY != 0 {
            t.atan_xy = x.atan2(y);
        }
        if needs & need::ATAN_YX != 0 {
            t.atan_yx = y.atan2(x);
        }
        t
    }
}

/// The xform's running output: the sum of its regular variations so far (or, for `pre_` and
/// `post_` forms, the point being transformed) and the colour coordinate.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Acc {
    /// x so far.
    pub x: f64,
    /// y so far.
    pub y: f64,
    /// z so far.
    pub z: f64,
    /// The colour coordinate (written by the direct-colour variations).
    pub color: f64,
    /// The sample is not drawn (set by the [`super::flag::HIDES`] variations).
    pub hide: bool,
    /// A colour of its own (red, green, blue, 0–255) instead of the palette's, as JWildfire's
    /// direct-colour variations set it; `None` for the palette's. Channels lowered by
    /// [`Acc::NEAREST_KEY`] ask for the palette colour nearest to them instead (JWildfire's
    /// Gradient = 1), which the renderer looks up where it knows the palette.
    pub rgb: Option<[f64; 3]>,
}

/// A point's own colour as the renderer carries it beside the point: 0 for the palette's
/// colour, else [`own_rgb::OWN`] or [`own_rgb::NEAREST`] with red, green and blue in the
/// low 24 bits, or [`own_rgb::INDEX`] with a palette entry in the low 8 bits.
pub mod own_rgb {
    /// The low 24 bits are the colour to draw.
    pub const OWN: u32 = 1 << 24;
    /// The low 24 bits are a colour whose nearest palette colour is drawn.
    pub const NEAREST: u32 = 1 << 25;
    /// The low 8 bits are the palette entry to draw (as a palette colour is drawn).
    pub const INDEX: u32 = 1 << 26;

    /// Red, green and blue of a packed colour.
    #[inline]
    pub fn channels(p: u32) -> [u8; 3] {
        [(p >> 16) as u8, (p >> 8) as u8, p as u8]
    }
}

impl Acc {
    /// The colour coordinate the renderer draws the point with where it does not carry own
    /// colours (flames JWildfire's renderer does not draw): its palette index, or, for a point
    /// given a colour of its own, that colour's luminance as the index (as JWildfire's
    /// direct-colour variations index the gradient with Gradient = 2), so their patterns
    /// still show.
    #[inline]
    pub fn drawn_color(&self) -> f64 {
        match self.rgb {
            Some(c) => {
                let bytes = Self::bytes(c).0;
                super::jwf_direct_colour::dc_luma(bytes.map(|v| v as i64))
            }
            None => self.color,
        }
    }

    /// Subtracted from each channel of [`Acc::rgb`] to ask for the palette's nearest colour.
    pub const NEAREST_KEY: f64 = 256.0;

    /// The channels of an own colour as bytes, and whether they ask for the nearest palette
    /// colour.
    #[inline]
    fn bytes(c: [f64; 3]) -> ([u8; 3], bool) {
        let nearest = c.iter().any(|&v| v < 0.0);
        let lift = if nearest { Self::NEAREST_KEY } else { 0.0 };
        (c.map(|v| (v + lift).clamp(0.0, 255.0) as u8), nearest)
    }

    /// The own colour packed as the renderer carries it ([`own_rgb`]); `None` for the
    /// palette's.
    #[inline]
    pub fn packed_rgb(&self) -> Option<u32> {
        let (b, nearest) = Self::bytes(self.rgb?);
        let kind = if nearest {
            own_rgb::NEAREST
        } else {
            own_rgb::OWN
        };
        Some(kind | (b[0] as u32) << 16 | (b[1] as u32) << 8 | b[2] as u32)
    }
}

/// Per-point quantities of a batch of points, as parallel arrays of one length.
pub struct SoaIn<'a> {
    pub x: &'a [f64],
    pub y: &'a [f64],
    pub z: &'a [f64],
    pub sumsq: &'a [f64],
    pub sqrt: &'a [f64],
    pub ux: &'a [f64],
    pub uy: &'a [f64],
    pub atan_xy: &'a [f64],
    pub atan_yx: &'a [f64],
    pub color: &'a [f64],
}

impl<'a> SoaIn<'a> {
    /// The points `r` (every column cut to one length, so that a loop over them indexes
    /// without a bounds test — a test the vectoriser cannot take).
    #[inline(always)]
    pub fn range(&self, r: std::ops::Range<usize>) -> SoaIn<'a> {
        SoaIn {
            x: &self.x[r.clone()],
            y: &self.y[r.clone()],
            z: &self.z[r.clone()],
            sumsq: &self.sumsq[r.clone()],
            sqrt: &self.sqrt[r.clone()],
            ux: &self.ux[r.clone()],
            uy: &self.uy[r.clone()],
            atan_xy: &self.atan_xy[r.clone()],
            atan_yx: &self.atan_yx[r.clone()],
            color: &self.color[r],
        }
    }

    /// The input of point `j`.
    #[inline(always)]
    pub fn at(&self, j: usize) -> VarIn {
        VarIn {
            x: self.x[j],
            y: self.y[j],
            z: self.z[j],
            sumsq: self.sumsq[j],
            sqrt: self.sqrt[j],
            ux: self.ux[j],
            uy: self.uy[j],
            atan_xy: self.atan_xy[j],
            atan_yx: self.atan_yx[j],
            color: self.color[j],
        }
    }
}

/// Running outputs of a batch of points.
pub struct SoaAcc<'a> {
    pub x: &'a mut [f64],
    pub y: &'a mut [f64],
    pub z: &'a mut [f64],
    pub color: &'a mut [f64],
    /// Set where a variation hides the point (only formulas called point by point hide).
    pub hide: &'a mut [bool],
}

impl SoaAcc<'_> {
    /// The running output of point `j`, as a formula called point by point sees it.
    #[inline(always)]
    pub fn at(&self, j: usize) -> Acc {
        Acc {
            x: self.x[j],
            y: self.y[j],
            z: self.z[j],
            color: self.color[j],
            hide: false,
            rgb: None,
        }
    }
}
