//! An escape-time document: the fractal's parameters, the view, the picture size and the name
//! of its gradient — what a view file holds and what the escape-time tab edits.

use crate::escape::{EscapeParams, Family, View};
use crate::gradient;

/// A saved escape-time view.
#[derive(Clone, Debug, PartialEq)]
pub struct EscapeDoc {
    /// The fractal: family, iteration limit, colouring and palette.
    pub params: EscapeParams,
    /// The part of the plane shown.
    pub view: View,
    /// Picture width in pixels.
    pub width: u32,
    /// Picture height in pixels.
    pub height: u32,
    /// How the gradient was named in the file (a built-in name or a file path), for writing
    /// it back.
    pub gradient_source: String,
}

impl EscapeDoc {
    /// A family's default document: its default view at 800×600, 256 iterations.
    pub fn new(family: Family) -> EscapeDoc {
        let (center, half_height) = family.default_view();
        let mut params = EscapeParams::new(family);
        params.palette.gradient = gradient::default_gradient();
        EscapeDoc {
            params,
            view: View::new(center, half_height),
            width: 800,
            height: 600,
            gradient_source: gradient::default_gradient().name,
        }
    }

    /// World width of the view.
    pub fn world_width(&self) -> f64 {
        2.0 * self.view.half_height * self.width as f64 / self.height.max(1) as f64
    }
}
