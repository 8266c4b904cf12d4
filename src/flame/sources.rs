//! What a render draws from when one flame is not enough: the sub-frames of a motion-blurred
//! frame, or the layers of a JWildfire flame. Each source is a flame of its own xforms,
//! camera and palette, whose colours (and for sub-frames its hits) are scaled by a factor; the
//! render's sub-batches are dealt out to the sources by their shares of the samples, and all
//! draw into the render's histograms.

use crate::flame::chaos::{Chaos, SUB_BATCH};
use crate::flame::geometry::Geometry;
use crate::flame::histogram::PlotPalette;
use crate::flame::layers::LayerSource;
use crate::flame::model::Flame;
use crate::flame::motion_blur::MotionFrame;

/// The sources of one render, prepared for the renderer.
pub(super) struct Sources {
    /// Each source's flame and the factors on its palette's red, green, blue and alpha.
    pub flames: Vec<(Flame, [f32; 4])>,
    /// The sub-batches of the whole render in order: (source, samples).
    pub batches: Vec<(u32, u32)>,
    /// The mean weight of the hits (the temporal filter's; 1 for layers): the log scale
    /// divides the density by it.
    pub mean_weight: f64,
    /// Layers, whose render state can be saved (the flame rebuilds them); sub-frames cannot.
    pub layers: bool,
}

impl Sources {
    /// The sub-frames of a motion-blurred frame: colours and hits weighted by the temporal
    /// filter.
    pub fn motion(frame: &MotionFrame) -> Sources {
        let flames = frame
            .subframes
            .iter()
            .map(|s| (s.flame.clone(), [s.weight as f32; 4]))
            .collect();
        let samples: Vec<u64> = frame.subframes.iter().map(|s| s.samples).collect();
        Sources {
            flames,
            batches: batches(&samples),
            mean_weight: frame.mean_weight,
            layers: false,
        }
    }

    /// The layers of a JWildfire flame: colours weighted by the layer's weight, hits not.
    /// Without a layer to draw, `flame` stands in and draws nothing.
    pub fn layers(flame: &Flame, layers: Vec<LayerSource>) -> Sources {
        let samples: Vec<u64> = layers.iter().map(|l| l.samples).collect();
        let mut flames: Vec<(Flame, [f32; 4])> = layers
            .into_iter()
            .map(|l| {
                let w = l.weight as f32;
                (l.flame, [w, w, w, 1.0])
            })
            .collect();
        if flames.is_empty() {
            let mut f = flame.clone();
            f.more_layers.clear();
            f.layer = Default::default();
            flames.push((f, [0.0; 4]));
        }
        Sources {
            flames,
            batches: batches(&samples),
            mean_weight: 1.0,
            layers: true,
        }
    }

    /// These sources followed by the sub-batches of `more` (sources of the same flames).
    pub fn extended(&self, more: Sources) -> Sources {
        let mut batches = self.batches.clone();
        batches.extend(more.batches);
        Sources {
            flames: self.flames.clone(),
            batches,
            mean_weight: self.mean_weight,
            layers: self.layers,
        }
    }

    /// Samples of all sources.
    pub fn total(&self) -> u64 {
        self.batches.iter().map(|b| b.1 as u64).sum()
    }
}

/// Sub-batches of at most [`SUB_BATCH`] samples, each source's of equal size (so that threads
/// taking every other one share the work evenly); at least one.
fn batches(samples: &[u64]) -> Vec<(u32, u32)> {
    let mut out = Vec::new();
    for (i, &s) in samples.iter().enumerate() {
        let k = s.div_ceil(SUB_BATCH);
        for j in 0..k {
            let n = s * (j + 1) / k - s * j / k;
            out.push((i as u32, n as u32));
        }
    }
    if out.is_empty() {
        out.push((0, 1));
    }
    out
}

/// What a worker thread draws a source's sub-batch with: the source's xforms, camera and
/// scaled palette.
pub(super) struct SourceTools {
    pub index: u32,
    pub n_xforms: usize,
    pub chaos: Chaos,
    pub geom: Geometry,
    pub palette: PlotPalette,
}

impl SourceTools {
    /// `frame` is the render's own bucket grid: the source draws into it through its own
    /// camera, as flam3 does (the grid, gutter and filters are the render's).
    pub fn new(s: &Sources, index: u32, frame: &Geometry) -> SourceTools {
        let (flame, factors) = &s.flames[index as usize];
        // Checked when the render was prepared.
        let chaos = Chaos::new(flame).expect("source flames were validated");
        let geom = frame.with_camera_of(flame);
        let mut palette = PlotPalette::new(flame);
        for c in &mut palette.colors {
            for (v, f) in c.iter_mut().zip(factors) {
                *v *= f;
            }
        }
        SourceTools {
            index,
            n_xforms: flame.xforms.len(),
            chaos,
            geom,
            palette,
        }
    }
}
