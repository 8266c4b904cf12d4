//! Gradients: the 256-colour tables that colour flames and escape-time images.
//!
//! One type serves both views. A gradient always has exactly 256 RGBA entries in `[0, 1]`
//! (straight, not pre-multiplied alpha); `stops` keeps the key colours it was built from when the
//! source had them (a `.ugr` key list, a short Fractint `.map`), so that writers can reproduce
//! the source and the escape-time view can cycle a short map.
//!
//! The table type and its operations are in `table`, the colour spaces (flam3's HSV, Oklab) in
//! `color`, ugnis's own gradients in `builtin` and gradients taken from a picture's colours in
//! `from_image`; everything is used through this module.

mod builtin;
mod color;
mod from_image;
mod table;

pub use builtin::{builtin, builtin_named, default_gradient};
pub use color::{hsv_to_rgb, oklab_to_srgb, rgb_to_hsv, srgb_to_oklab};
pub use from_image::from_pixels;
pub use table::{Gradient, Stop, hue_rotate, resample_colors};
