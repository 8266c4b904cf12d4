//! Fractal dimension: the similarity dimension of a set of contractions, box counting of point
//! sets, images and flame attractors (with the log-log points and the fitted line), the divider
//! (coastline) method and Voss's mass distribution with its lacunarity.
//!
//! Box counting estimates D = lim ln N(ε)/ln(1/ε), N(ε) being the number of grid cells of side ε
//! that meet the set; this limit is the box-counting (capacity) dimension, which can differ from
//! the Hausdorff dimension (Falconer, *Fractal Geometry*, ch. 3).

mod box_count;
mod divider;
mod fit;
mod similarity;
#[cfg(test)]
mod testing;
mod voss;

pub use box_count::{
    BoxCount, BoxLevel, Ink, MAX_FILL, MAX_LEVEL, MAX_SAMPLES, MIN_SAMPLES, Mask, SKIP_COARSE,
    box_count_flame, box_count_mask, box_count_peak_bytes, box_count_points, box_count_stream,
    check_samples,
};
pub use divider::{COASTLINE_DATA, divider_dimension, divider_length};
pub use fit::{LineFit, fit_line};
pub use similarity::{MAX_RATIOS, SOLVER_MAX, equal_ratio_dimension, similarity_dimension};
pub use voss::{
    VOSS_MAX_CENTRES, VOSS_MAX_POINTS, VossLevel, lacunarity_of_masses, voss, voss_dimension,
};
