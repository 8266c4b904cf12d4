//! JWildfire's layers: a flame of several layers, each with its own xforms, final xforms and
//! gradient, drawn into one picture. A flame's own xforms, final xforms and gradient are its
//! first layer ([`Flame::layer`] holds that layer's settings); [`Flame::more_layers`] holds the
//! others. A flame of one plain layer is an ordinary flame.
//!
//! How JWildfire draws them (its `DefaultRenderThread` and `DefaultRenderIterationState`):
//! every visible layer with xforms gets the same share of the iterations; a layer of density
//! d < 1 skips each of its iterations with probability 1 − d²; a layer's weight multiplies the
//! colours it plots but not its hits; all layers plot into one raster, tone-mapped once.

use crate::flame::model::{Flame, Xform};
use crate::gradient::Gradient;

/// A layer's own settings (JWildfire's `<layer>` attributes).
#[derive(Clone, Debug, PartialEq)]
pub struct LayerSettings {
    /// The layer's name (may be empty).
    pub name: String,
    /// Factor on the colours the layer plots (its hits count fully).
    pub weight: f64,
    /// Share of the layer's iterations that are drawn, squared (1: all).
    pub density: f64,
    /// Whether the layer is drawn at all.
    pub visible: bool,
    /// Other attributes of the `<layer>` element, kept in file order for round trip.
    pub extra_attrs: Vec<(String, String)>,
}

impl Default for LayerSettings {
    fn default() -> Self {
        LayerSettings {
            name: String::new(),
            weight: 1.0,
            density: 1.0,
            visible: true,
            extra_attrs: Vec::new(),
        }
    }
}

impl LayerSettings {
    /// True for the settings of a layer drawn as a plain flame is drawn.
    pub fn is_plain(&self) -> bool {
        self.weight == 1.0 && self.density >= 1.0 && self.visible
    }
}

/// A layer after the first.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct Layer {
    /// The layer's settings.
    pub settings: LayerSettings,
    /// Its xforms.
    pub xforms: Vec<Xform>,
    /// Its final xforms, applied in order.
    pub finals: Vec<Xform>,
    /// Its gradient.
    pub palette: Gradient,
}

/// One layer to draw: a flame of the layer's xforms, final xforms and gradient (with the whole
/// flame's camera and settings), the factor on its colours, and its share of the samples.
#[derive(Clone, Debug)]
pub(crate) struct LayerSource {
    pub flame: Flame,
    pub weight: f64,
    pub samples: u64,
}

impl Flame {
    /// True when the flame has layers to draw beyond one plain layer.
    pub fn has_layers(&self) -> bool {
        !self.more_layers.is_empty() || !self.layer.is_plain()
    }

    /// True when the render draws from several flames: layers, or JWildfire's motion blur.
    pub(crate) fn has_sources(&self) -> bool {
        self.has_layers() || self.jwildfire_motion_blur().len() > 1
    }

    /// What the render draws: every layer of the flame at each time of JWildfire's motion
    /// blur (the flame at that time, its colours faded), the samples shared evenly among the
    /// times.
    pub(crate) fn sources(&self) -> Vec<LayerSource> {
        let times = self.jwildfire_motion_blur();
        if times.len() == 1 {
            return self.layer_sources();
        }
        let n = times.len() as f64;
        let mut out = Vec::new();
        for (time, fade) in times {
            let f = if self.keys.is_empty() {
                self.clone()
            } else {
                self.at_jwildfire_time(time)
            };
            for mut s in f.layer_sources() {
                s.weight *= fade;
                s.samples = (s.samples as f64 / n).round() as u64;
                out.push(s);
            }
        }
        out
    }

    /// The layers JWildfire draws (visible, with xforms), each with its share of the flame's
    /// samples. Empty when no layer is drawn.
    pub(crate) fn layer_sources(&self) -> Vec<LayerSource> {
        let mut out = Vec::new();
        if self.layer.visible && !self.xforms.is_empty() {
            let mut f = self.clone();
            f.more_layers.clear();
            f.layer = LayerSettings::default();
            out.push((f, &self.layer));
        }
        for l in &self.more_layers {
            if !l.settings.visible || l.xforms.is_empty() {
                continue;
            }
            let mut f = self.clone();
            f.more_layers.clear();
            f.layer = LayerSettings::default();
            f.xforms = l.xforms.clone();
            let mut finals = l.finals.iter().cloned();
            f.final_xform = finals.next();
            f.more_finals = finals.collect();
            f.palette = l.palette.clone();
            f.palette_hires = None;
            f.solo_xform = None;
            out.push((f, &l.settings));
        }
        let n = out.len().max(1) as f64;
        let total = self.total_samples() as f64;
        out.into_iter()
            .map(|(flame, s)| {
                let drawn = if s.density < 1.0 {
                    s.density.max(0.0).powi(2)
                } else {
                    1.0
                };
                LayerSource {
                    flame,
                    weight: s.weight,
                    samples: (total / n * drawn).round() as u64,
                }
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::flame::model::Affine;

    #[test]
    fn layers_share_the_samples_and_density_thins_them() {
        let mut f = crate::flame::model::test_sierpinski(100, 100, 10.0);
        assert!(!f.has_layers());
        let total = f.total_samples();
        assert_eq!(f.layer_sources().len(), 1);
        assert_eq!(f.layer_sources()[0].samples, total);
        f.more_layers.push(Layer {
            settings: LayerSettings {
                density: 0.5,
                weight: 2.0,
                ..LayerSettings::default()
            },
            xforms: vec![Xform::linear(
                Affine::new(0.5, 0.0, 0.0, 0.5, 0.0, 0.0),
                1.0,
                0.0,
            )],
            ..Layer::default()
        });
        f.more_layers.push(Layer {
            settings: LayerSettings {
                visible: false,
                ..LayerSettings::default()
            },
            xforms: f.xforms.clone(),
            ..Layer::default()
        });
        assert!(f.has_layers());
        let s = f.layer_sources();
        assert_eq!(s.len(), 2);
        assert_eq!(s[0].samples, total / 2);
        assert_eq!(s[1].samples, total / 8);
        assert_eq!(s[1].weight, 2.0);
        assert_eq!(s[1].flame.xforms.len(), 1);
        assert!(s[1].flame.more_layers.is_empty());
    }
}
