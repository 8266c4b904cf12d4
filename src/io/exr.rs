//! Iteration data of an escape-time picture as OpenEXR, in the channels Kalles Fraktaler
//! and zoomasm read: `N` (u32, the integer part of the continuous escape count; 0xFFFFFFFF for
//! a pixel that did not escape), `NF` (f32, its fractional part, so that N + NF is the
//! continuous count) and `DEX`/`DEY` (f32, the distance estimate in pixels as a vector along
//! the gradient of the continuous count, pointing away from the set).

use std::io::Cursor;
use std::path::Path;

use exr::prelude::*;

use crate::escape::Sample;

/// `N` of a pixel that did not escape.
pub const INTERIOR: u32 = u32::MAX;

/// The channels of one picture, row by row from the top.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct IterationData {
    /// Pixels a row.
    pub width: u32,
    /// Rows.
    pub height: u32,
    /// Integer part of the continuous count ([`INTERIOR`] inside).
    pub n: Vec<u32>,
    /// Fractional part of the continuous count.
    pub nf: Vec<f32>,
    /// Distance estimate in pixels, x (to the right).
    pub dex: Vec<f32>,
    /// Distance estimate in pixels, y (up).
    pub dey: Vec<f32>,
}

impl IterationData {
    /// The channels of `w`×`h` samples. Distance estimates come from the samples times
    /// `de_scale` (what makes them pixels; 0 where none was computed); their direction from
    /// the continuous counts of the neighbours.
    pub fn from_samples(samples: &[Sample], w: u32, h: u32, de_scale: f64) -> IterationData {
        let (wu, hu) = (w as usize, h as usize);
        assert_eq!(samples.len(), wu * hu, "one sample per pixel");
        let count = |s: &Sample| (!s.inside).then_some(s.nu.max(0.0));
        let mut d = IterationData {
            width: w,
            height: h,
            n: Vec::with_capacity(samples.len()),
            nf: Vec::with_capacity(samples.len()),
            dex: vec![0.0; samples.len()],
            dey: vec![0.0; samples.len()],
        };
        for s in samples {
            match count(s) {
                Some(nu) => {
                    let n = nu.floor().min(INTERIOR as f64 - 1.0);
                    d.n.push(n as u32);
                    d.nf.push((nu - n) as f32);
                }
                None => {
                    d.n.push(INTERIOR);
                    d.nf.push(0.0);
                }
            }
        }
        for j in 0..hu {
            for i in 0..wu {
                let k = j * wu + i;
                let Some(here) = count(&samples[k]) else {
                    continue;
                };
                let at = |ii: usize, jj: usize| count(&samples[jj * wu + ii]).unwrap_or(here);
                // Central differences (one-sided at the border); x to the right, y up.
                let gx = at((i + 1).min(wu - 1), j) - at(i.saturating_sub(1), j);
                let gy = at(i, j.saturating_sub(1)) - at(i, (j + 1).min(hu - 1));
                let len = gx.hypot(gy);
                let de = samples[k].de as f64 * de_scale;
                if len > 0.0 && de > 0.0 {
                    // The count falls away from the set: the vector points down its gradient.
                    d.dex[k] = (-gx / len * de) as f32;
                    d.dey[k] = (-gy / len * de) as f32;
                } else {
                    d.dex[k] = de as f32;
                }
            }
        }
        d
    }

    /// The continuous count of pixel k (None inside).
    pub fn count(&self, k: usize) -> Option<f64> {
        (self.n[k] != INTERIOR).then(|| self.n[k] as f64 + self.nf[k] as f64)
    }

    /// The file's bytes (ZIP-compressed scan lines).
    pub fn encode(&self) -> std::io::Result<Vec<u8>> {
        let size = (self.width as usize, self.height as usize);
        let list: SmallVec<[AnyChannel<FlatSamples>; 4]> = SmallVec::from_vec(vec![
            AnyChannel::new("N", FlatSamples::U32(self.n.clone())),
            AnyChannel::new("NF", FlatSamples::F32(self.nf.clone())),
            AnyChannel::new("DEX", FlatSamples::F32(self.dex.clone())),
            AnyChannel::new("DEY", FlatSamples::F32(self.dey.clone())),
        ]);
        let channels = AnyChannels::sort(list);
        let layer = Layer::new(
            size,
            LayerAttributes::default(),
            Encoding::SMALL_LOSSLESS,
            channels,
        );
        let mut buf = Vec::new();
        Image::from_layer(layer)
            .write()
            .to_buffered(Cursor::new(&mut buf))
            .map_err(std::io::Error::other)?;
        Ok(buf)
    }

    /// Write the file atomically.
    pub fn save(&self, path: &Path) -> std::io::Result<()> {
        super::atomic::write_atomic(path, &self.encode()?)
    }

    /// Read the four channels back from a file.
    pub fn read(path: &Path) -> std::io::Result<IterationData> {
        let img = read_all_flat_layers_from_file(path).map_err(std::io::Error::other)?;
        let layer = img
            .layer_data
            .first()
            .ok_or_else(|| std::io::Error::other("the EXR file holds no layer"))?;
        let find = |name: &str| {
            layer
                .channel_data
                .list
                .iter()
                .find(|c| c.name.eq(name))
                .map(|c| &c.sample_data)
                .ok_or_else(|| std::io::Error::other(format!("no channel {name}")))
        };
        let f32s =
            |name: &str| -> std::io::Result<Vec<f32>> { Ok(find(name)?.values_as_f32().collect()) };
        let n = match find("N")? {
            FlatSamples::U32(v) => v.clone(),
            _ => return Err(std::io::Error::other("channel N is not u32")),
        };
        Ok(IterationData {
            width: layer.size.width() as u32,
            height: layer.size.height() as u32,
            n,
            nf: f32s("NF")?,
            dex: f32s("DEX")?,
            dey: f32s("DEY")?,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn channels_round_trip_through_a_file() {
        let mut samples = vec![Sample::inside(100); 12];
        for (k, s) in samples.iter_mut().enumerate().take(8) {
            s.inside = false;
            s.nu = 3.25 + k as f64;
            s.n = s.nu as u32;
            s.de = 0.5;
        }
        let d = IterationData::from_samples(&samples, 4, 3, 1.0);
        assert_eq!(d.n[0], 3);
        assert!((d.nf[0] - 0.25).abs() < 1e-6);
        assert_eq!(d.n[11], INTERIOR);
        // The count grows to the right: the distance vector points left, of length 0.5.
        assert!(d.dex[1] < 0.0 && (d.dex[1].hypot(d.dey[1]) - 0.5).abs() < 1e-6);
        let dir = std::env::temp_dir().join(format!("ugnis-exr-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let p = dir.join("view.exr");
        d.save(&p).unwrap();
        let back = IterationData::read(&p).unwrap();
        std::fs::remove_dir_all(&dir).ok();
        assert_eq!(back, d);
    }
}
