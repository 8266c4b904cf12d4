//! An escape-time document: the fractal's parameters, the view, the picture size and the name
//! of its gradient — what a view file holds and what the escape-time tab edits.

use super::fx::Fx;
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

    /// World width of the view (0 below f64's range).
    pub fn world_width(&self) -> f64 {
        self.world_width_fx().to_f64()
    }

    /// World width of the view, at any depth.
    pub fn world_width_fx(&self) -> Fx {
        self.view
            .half_height_fx()
            .scale(2.0 * self.width as f64 / self.height.max(1) as f64)
    }

    /// Set the world width of the view (the height follows the picture's aspect).
    pub fn set_world_width_fx(&mut self, width: Fx) {
        self.view
            .set_half_height_fx(width.scale(0.5 * self.height as f64 / self.width.max(1) as f64));
    }

    /// Change the picture size keeping the world width.
    pub fn resize(&mut self, w: u32, h: u32) {
        let width = self.world_width_fx();
        self.width = w;
        self.height = h;
        self.set_world_width_fx(width);
    }
}
