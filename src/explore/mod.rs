//! Explore: the teaching material beside the three main views — classic constructions
//! (Cantor set, Koch curve and snowflake, Sierpinski triangle and carpet), the chaos game and
//! textbook IFS tables, L-systems, fractal interpolation functions, Julia sets by inverse
//! iteration, the Lorenz attractor, and fractal dimension (similarity dimension, box counting,
//! the divider method, Voss lacunarity).
//!
//! Everything here is engine code: no GUI and no file formats (Fractint `.l` files and SVG
//! output live in `io`). Live views are served by incremental sources a window can pull a few
//! thousand items from per frame: [`ifs::ChaosGame`] and `julia::InverseJulia` yield points,
//! [`lsystem::Segments`] yields turtle segments, [`lorenz::Orbit`] yields integration steps,
//! and every construction reports the numbers of its current step.

pub mod classic;
pub mod dimension;
pub mod fif;
pub mod ifs;
pub mod julia;
pub mod lorenz;
pub mod lsystem;
pub mod raster;

/// Why an Explore computation was refused.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ExploreError {
    /// A number outside its allowed range.
    #[error("{what} is {value}; it must be between {min} and {max}")]
    OutOfRange {
        /// What the number is.
        what: &'static str,
        /// The number given.
        value: f64,
        /// Smallest allowed value.
        min: f64,
        /// Largest allowed value.
        max: f64,
    },
    /// A computation that would produce more than its limit allows.
    #[error("{what}: {} would be produced; the limit is {limit:.0}{hint}", big(*count))]
    TooLarge {
        /// What would be produced.
        what: String,
        /// How many would be produced.
        count: f64,
        /// How many are allowed.
        limit: f64,
        /// Advice appended to the message (may be empty).
        hint: String,
    },
    /// Any other invalid input, with a message saying what was expected.
    #[error("{0}")]
    Invalid(String),
}

/// A count for a message: whole numbers up to 10¹², scientific notation beyond.
fn big(count: f64) -> String {
    if count.abs() < 1e12 {
        format!("{count:.0}")
    } else {
        format!("{count:.2e}")
    }
}

/// Refuse `value` outside `[min, max]` (and non-finite values) with a message naming `what`.
pub fn check_range(what: &'static str, value: f64, min: f64, max: f64) -> Result<(), ExploreError> {
    if value.is_finite() && (min..=max).contains(&value) {
        Ok(())
    } else {
        Err(ExploreError::OutOfRange {
            what,
            value,
            min,
            max,
        })
    }
}

/// A point of the plane.
pub type P2 = [f64; 2];

/// Axis-aligned bounds of a point set.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Bounds {
    /// The lower-left corner (xmin, ymin).
    pub min: P2,
    /// The upper-right corner (xmax, ymax).
    pub max: P2,
}

impl Bounds {
    /// Empty bounds (any point extends them).
    pub const EMPTY: Bounds = Bounds {
        min: [f64::INFINITY, f64::INFINITY],
        max: [f64::NEG_INFINITY, f64::NEG_INFINITY],
    };

    /// Extend the bounds to hold `p` (non-finite points are ignored).
    pub fn add(&mut self, p: P2) {
        if p[0].is_finite() && p[1].is_finite() {
            self.min[0] = self.min[0].min(p[0]);
            self.min[1] = self.min[1].min(p[1]);
            self.max[0] = self.max[0].max(p[0]);
            self.max[1] = self.max[1].max(p[1]);
        }
    }

    /// The bounds of the finite points among `points`.
    pub fn of(points: impl IntoIterator<Item = P2>) -> Bounds {
        let mut b = Bounds::EMPTY;
        for p in points {
            b.add(p);
        }
        b
    }

    /// Whether no point was added.
    pub fn is_empty(&self) -> bool {
        !(self.min[0] <= self.max[0] && self.min[1] <= self.max[1])
    }

    /// xmax − xmin.
    pub fn width(&self) -> f64 {
        self.max[0] - self.min[0]
    }

    /// ymax − ymin.
    pub fn height(&self) -> f64 {
        self.max[1] - self.min[1]
    }
}
