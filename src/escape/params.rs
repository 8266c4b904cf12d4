//! What defines an escape-time picture besides its size and view ([`EscapeParams`], block
//! [`Fill`]), why one cannot be rendered ([`EscapeError`]), and the checks made before
//! anything is allocated: the precision limits of a view (f64, or double-double for deep
//! zoom), the settings, and the memory.

use super::color::{Coloring, Palette};
use super::complex::C;
use super::family::{Family, Sample};
use super::view::View;

/// Relative pixel size below which the Mandelbrot set is drawn by perturbation.
pub const DEEP_BELOW: f64 = 1e-12;
/// Relative pixel size limit of f64 arithmetic.
pub const F64_LIMIT: f64 = 1e-13;
/// Decimal exponent of the smallest half-height of a deep view (1e-10000): the reference
/// orbit's arithmetic grows with the digits, and beyond this one orbit takes hours.
pub const DEEP_LIMIT_EXP10: f64 = -10_000.0;

/// Block filling.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Fill {
    /// Every pixel computed (the default).
    #[default]
    Exact,
    /// Mariani–Silver rectangles: filled when their whole border agrees (not for Newton).
    Guess,
}

/// Everything that defines an escape-time picture except its size and view.
#[derive(Clone, Debug, PartialEq)]
pub struct EscapeParams {
    /// What is iterated.
    pub family: Family,
    /// Iteration limit: a point still bounded after this many iterations counts as inside.
    pub max_iter: u32,
    /// How the samples become colours.
    pub coloring: Coloring,
    /// Escape radius; None: the family's default for the colouring.
    pub bailout: Option<f64>,
    /// Stop orbits found to be cycling (within a thousandth of a pixel) early, as inside; not used
    /// for Newton, warped textures, distance colouring or deep zoom.
    pub periodicity: bool,
    /// Every pixel computed, or Mariani–Silver block filling.
    pub fill: Fill,
    /// Gradient, offset, repeat and inside colour.
    pub palette: Palette,
    /// Deep zoom: the relative size of the non-linear terms a bilinear step may drop (see
    /// [`super::bla::EPSILON`]); larger skips more iterations and is less exact.
    pub bla_eps: f64,
}

impl EscapeParams {
    /// The family's defaults: 256 iterations, basins for Newton, bands for warped textures, smooth
    /// colouring otherwise (four gradient entries per iteration), periodicity checking on.
    pub fn new(family: Family) -> EscapeParams {
        let coloring = if matches!(family, Family::Newton { .. }) {
            Coloring::Basins
        } else if matches!(family, Family::WarpedJulia(_)) {
            Coloring::Bands
        } else {
            Coloring::Smooth
        };
        // Four gradient entries per iteration spread the outside over the whole gradient
        // (with one, the first few dozen iterations use a fifth of it).
        let repeat = if coloring == Coloring::Basins {
            1.0
        } else {
            4.0
        };
        EscapeParams {
            family,
            max_iter: 256,
            coloring,
            bailout: None,
            periodicity: true,
            bla_eps: super::bla::EPSILON,
            fill: Fill::Exact,
            palette: Palette {
                repeat,
                ..Palette::default()
            },
        }
    }

    /// The escape radius used: the one set, or the family's default for the colouring.
    pub fn bailout(&self) -> f64 {
        self.bailout
            .unwrap_or_else(|| self.family.default_bailout(self.coloring.smooth()))
    }
}

/// Why a view cannot be rendered.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum EscapeError {
    /// The pixel is too small for f64 arithmetic at this centre.
    #[error(
        "zoomed in to the limit of 64-bit floating point (pixel {pixel:.3e} at |centre| {scale:.3e}); \
         zoom out (deep zoom is available for z² + c, z³ + c, their Julia sets and the Burning Ship)"
    )]
    PrecisionLimit {
        /// Pixel size in world units.
        pixel: f64,
        /// Scale of the centre the pixel is compared with: the largest of 1, |x| and |y|.
        scale: f64,
    },
    /// The view is narrower than deep zoom goes.
    #[error("view height {height} is below the deep-zoom limit of 1e-10000; zoom out")]
    DeepLimit {
        /// The view's height in world units.
        height: super::fx::Fx,
    },
    /// The picture size (width, height) is outside 1–30000 pixels a side.
    #[error("image size {0}x{1} must be between 1x1 and 30000x30000")]
    BadSize(u32, u32),
    /// A setting is out of range (the message says which).
    #[error("{0}")]
    Settings(String),
    /// The render would not fit in the memory allowed.
    #[error(transparent)]
    OutOfMemory(#[from] crate::memory::MemoryError),
}

/// Bytes an escape-time render of `w`×`h` needs, before anything is allocated: one sample per
/// pixel, the RGB image and the copy made while encoding it, the reference orbit of a deep
/// zoom (up to `max_iter` points, twice with a critical orbit) and the iteration-count table
/// of histogram colouring.
pub fn estimate_memory(params: &EscapeParams, view: &View, w: u32, h: u32) -> u64 {
    let px = w as u64 * h as u64;
    let samples = px * std::mem::size_of::<Sample>() as u64;
    let image = px * 3 * 2;
    let iters = params.max_iter as u64 + 2;
    let orbit = if is_deep(&params.family, view, h) {
        // The reference orbit and its bilinear table (twice for a Julia set: the critical
        // orbit too).
        let copies = if matches!(params.family, Family::Julia { .. }) {
            2
        } else {
            1
        };
        let table = if matches!(params.family, Family::BurningShip) {
            super::bla_ship::table_bytes(iters)
        } else {
            super::bla::table_bytes(iters)
        };
        copies * (iters * std::mem::size_of::<C>() as u64 + table)
    } else {
        0
    };
    let histogram = if params.coloring == Coloring::Histogram {
        iters * 16
    } else {
        0
    };
    samples + image + orbit + histogram
}

/// Refuse an escape-time render that does not fit in memory (see [`crate::memory`]).
pub fn check_memory(
    params: &EscapeParams,
    view: &View,
    w: u32,
    h: u32,
    configured: Option<u64>,
) -> Result<u64, EscapeError> {
    let need = estimate_memory(params, view, w, h);
    crate::memory::check(
        need,
        configured,
        || format!("a {w}×{h} escape-time render"),
        || {
            let mut hint = String::from("reduce the image size");
            if params.coloring == Coloring::Histogram || is_deep(&params.family, view, h) {
                hint.push_str(&format!(" or the maximum iterations ({})", params.max_iter));
            }
            hint
        },
    )?;
    Ok(need)
}

/// An iteration limit for a view of half-height `half`: 256 for the whole set, growing with
/// the decimal digits of the magnification d as 256 + 40·d^1.2 (about 2,000 at 1e-25,
/// 10,000 at 1e-100, 160,000 at 1e-1000), the way deep-zoom programs raise it with the depth.
pub fn auto_max_iter(half: super::fx::Fx) -> u32 {
    let d = -half.log10();
    if !(d > 0.0) {
        return 256;
    }
    (256.0 + 40.0 * d.min(10_000.0).powf(1.2)).min(10_000_000.0) as u32
}

/// Check a view against the f64 precision limit.
pub fn check_view(view: &View, w: u32, h: u32) -> Result<(), EscapeError> {
    if w == 0 || h == 0 || w > 30_000 || h > 30_000 {
        return Err(EscapeError::BadSize(w, h));
    }
    let (pixel, scale) = (view.pixel_size(h), view_scale(view));
    if !(pixel >= F64_LIMIT * scale) || !pixel.is_finite() {
        return Err(EscapeError::PrecisionLimit { pixel, scale });
    }
    Ok(())
}

/// Families that zoom past the f64 limit by perturbation.
pub fn supports_deep_zoom(family: &Family) -> bool {
    matches!(
        family,
        Family::Mandelbrot { power: 2 | 3 }
            | Family::Julia { power: 2 | 3, .. }
            | Family::BurningShip
    )
}

/// Check a view for a family: the f64 limit, or the deep-zoom limit where it applies.
pub fn check_view_for(family: &Family, view: &View, w: u32, h: u32) -> Result<(), EscapeError> {
    if !supports_deep_zoom(family) {
        return check_view(view, w, h);
    }
    if w == 0 || h == 0 || w > 30_000 || h > 30_000 {
        return Err(EscapeError::BadSize(w, h));
    }
    let half = view.half_height_fx();
    if !(half.log10() >= DEEP_LIMIT_EXP10) || !half.is_finite() {
        return Err(EscapeError::DeepLimit {
            height: half.scale(2.0),
        });
    }
    Ok(())
}

/// True when the view is drawn by perturbation (deep zoom).
pub fn is_deep(family: &Family, view: &View, h: u32) -> bool {
    supports_deep_zoom(family)
        && view
            .pixel_size_fx(h)
            .lt(super::fx::Fx::from_f64(DEEP_BELOW * view_scale(view)))
}

fn view_scale(view: &View) -> f64 {
    let [x, y] = view.center();
    x.abs().max(y.abs()).max(1.0)
}

pub(super) fn check_params(p: &EscapeParams) -> Result<(), EscapeError> {
    if !super::bla::EPSILON_RANGE.contains(&p.bla_eps) {
        return Err(EscapeError::Settings(format!(
            "bilinear tolerance {} must be between 2^-53 (1.1e-16) and 0.001",
            p.bla_eps
        )));
    }
    if p.max_iter == 0 || p.max_iter > 100_000_000 {
        return Err(EscapeError::Settings(format!(
            "max iterations {} must be between 1 and 100000000",
            p.max_iter
        )));
    }
    match &p.family {
        Family::Mandelbrot { power } | Family::Julia { power, .. } if !(2..=9).contains(power) => {
            return Err(EscapeError::Settings(format!(
                "power {power} must be between 2 and 9"
            )));
        }
        Family::Newton { coeffs }
            if coeffs.iter().filter(|c| c.norm2() > 0.0).count() < 2 || coeffs.len() < 2 =>
        {
            return Err(EscapeError::Settings(
                "Newton needs a polynomial of degree 1 or more with a non-zero constant or linear term"
                    .into(),
            ));
        }
        _ => {}
    }
    let b = p.bailout();
    if !(b > 0.0 && b.is_finite()) {
        return Err(EscapeError::Settings(format!(
            "escape radius {b} must be positive"
        )));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn automatic_iterations_grow_with_the_depth() {
        use super::super::fx::Fx;
        assert_eq!(auto_max_iter(Fx::from_f64(1.5)), 256);
        let at = |e: &str| auto_max_iter(Fx::parse(e).unwrap());
        let (a, b, c) = (at("1e-25"), at("1e-100"), at("1e-1000"));
        assert!(a > 1000 && a < 5000, "{a}");
        assert!(b > a && b < 20_000, "{b}");
        assert!(c > b && c <= 200_000, "{c}");
        assert!(at("1e-10000") <= 10_000_000);
    }

    #[test]
    fn view_maps_pixels_both_ways_with_y_up() {
        let v = View::new([-0.7, 0.2], 1.5);
        let p = v.world_from_pixel(0.0, 0.0, 400, 300);
        assert!(p.re < -0.7 && p.im > 0.2, "top-left is up and left");
        let q = v.pixel_from_world(p, 400, 300);
        assert!((q[0] - 0.5).abs() < 1e-9 && (q[1] - 0.5).abs() < 1e-9);
        let z = v.zoomed_at(100.0, 50.0, 400, 300, 2.0);
        let before = v.world_from_pixel(99.5, 49.5, 400, 300);
        let after = z.world_from_pixel(99.5, 49.5, 400, 300);
        assert!(
            (before - after).abs() < 1e-12,
            "the point under the cursor stays"
        );
        assert!(check_view(&v, 400, 300).is_ok());
        let deep = View::new([-0.7, 0.2], 1e-12);
        assert!(matches!(
            check_view(&deep, 400, 300),
            Err(EscapeError::PrecisionLimit { .. })
        ));
        // The Mandelbrot set z² + c zooms on by perturbation, to the deep-zoom limit.
        let m2 = Family::Mandelbrot { power: 2 };
        assert!(check_view_for(&m2, &deep, 400, 300).is_ok());
        assert!(is_deep(&m2, &deep, 300));
        assert!(!is_deep(&m2, &v, 300));
        let m4 = Family::Mandelbrot { power: 4 };
        assert!(check_view_for(&m4, &deep, 400, 300).is_err());
        let mut too_deep = View::new([-0.7, 0.2], 1.0);
        too_deep.set_half_height_fx(super::super::fx::Fx::parse("1e-10001").unwrap());
        assert!(matches!(
            check_view_for(&m2, &too_deep, 400, 300),
            Err(EscapeError::DeepLimit { .. })
        ));
    }
}
