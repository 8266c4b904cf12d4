//! `ugnis escape … --zoom-video OUT.mp4`: a zoom from a wide view into the given one. One
//! keyframe is rendered at each halving of the width (the widths an exponential map of the
//! zoom samples), kept as PNG in a folder so that an interrupted run resumes where it
//! stopped; the frames, evenly spaced in the logarithm of the width, are then drawn from the
//! two keyframes around them (the outer one scaled, the inner one, with twice the detail,
//! over its middle) and sent to the video writer.

use std::path::PathBuf;

use anyhow::{Context, Result, bail};
use image::{Rgb, RgbImage, RgbaImage};

use ugnis::escape::EscapeRenderer;
use ugnis::escape::fx::Fx;
use ugnis::io::escape_view::{self, EscapeDoc};
use ugnis::io::video::{Video, VideoOptions};

/// Most frames a zoom video may have.
pub const MAX_FRAMES: u32 = 100_000;

/// What the zoom is made of.
pub struct ZoomVideo {
    pub out: PathBuf,
    pub frames: u32,
    pub fps: f64,
    /// Where the keyframes are kept (default: beside the video, `NAME.keyframes`).
    pub keyframes: Option<PathBuf>,
    /// The width the zoom starts from.
    pub start_width: f64,
}

/// The keyframe folder of a zoom.
fn folder(z: &ZoomVideo) -> PathBuf {
    z.keyframes.clone().unwrap_or_else(|| {
        let mut p = z.out.clone().into_os_string();
        p.push(".keyframes");
        PathBuf::from(p)
    })
}

/// The document of keyframe k: the target's centre, width start / 2^k.
fn keyframe_doc(doc: &EscapeDoc, start: Fx, k: u32) -> EscapeDoc {
    let mut d = doc.clone();
    d.set_world_width_fx(start.scale(0.5f64.powi(k as i32)));
    d
}

/// Render (or find, when an earlier run left it) every keyframe; returns their paths.
fn keyframes(doc: &EscapeDoc, z: &ZoomVideo, count: u32) -> Result<Vec<PathBuf>> {
    let dir = folder(z);
    std::fs::create_dir_all(&dir)
        .with_context(|| format!("cannot create the keyframe folder '{}'", dir.display()))?;
    // The folder belongs to one zoom: its view is kept there and must match.
    let manifest = dir.join("zoom.esc");
    let text = format!(
        "# keyframes of a zoom from width {} in {count} halvings\n{}",
        z.start_width,
        escape_view::write(doc)
    );
    match std::fs::read_to_string(&manifest) {
        Ok(old) if old != text => bail!(
            "the keyframe folder '{}' holds the keyframes of another zoom; remove it or give \
             another --keyframes folder",
            dir.display()
        ),
        Ok(_) => {}
        Err(_) => ugnis::io::atomic::write_atomic(&manifest, text.as_bytes())
            .with_context(|| format!("cannot write '{}'", manifest.display()))?,
    }
    let start = Fx::from_f64(z.start_width);
    let mut paths = Vec::new();
    let pb = super::progress_bar(count as u64, "keyframes");
    for k in 0..count {
        let p = dir.join(format!("key{k:05}.png"));
        if !p.exists() {
            let d = keyframe_doc(doc, start, k);
            let mut r = EscapeRenderer::new(&d.params, d.view.clone(), d.width, d.height)?;
            if !r.run_exact(super::no_cancel(), &|_| {}) {
                return Err(super::stopped_early());
            }
            ugnis::io::png::save(
                &p,
                &image::DynamicImage::ImageRgb8(r.image()),
                &Default::default(),
            )
            .with_context(|| format!("cannot write '{}'", p.display()))?;
        }
        pb.inc(1);
        paths.push(p);
    }
    pb.finish_and_clear();
    Ok(paths)
}

/// Bilinear sample of `img` at continuous pixel coordinates (pixel centres at i + 0.5).
fn sample(img: &RgbImage, x: f64, y: f64) -> [f64; 3] {
    let (w, h) = (img.width() as i64, img.height() as i64);
    let (fx, fy) = (x - 0.5, y - 0.5);
    let (x0, y0) = (fx.floor(), fy.floor());
    let (tx, ty) = (fx - x0, fy - y0);
    let at = |i: i64, j: i64| -> [f64; 3] {
        let Rgb(p) = *img.get_pixel(i.clamp(0, w - 1) as u32, j.clamp(0, h - 1) as u32);
        [p[0] as f64, p[1] as f64, p[2] as f64]
    };
    let (i, j) = (x0 as i64, y0 as i64);
    let (a, b, c, d) = (at(i, j), at(i + 1, j), at(i, j + 1), at(i + 1, j + 1));
    let mut out = [0.0; 3];
    for ch in 0..3 {
        let top = a[ch] + (b[ch] - a[ch]) * tx;
        let bottom = c[ch] + (d[ch] - c[ch]) * tx;
        out[ch] = top + (bottom - top) * ty;
    }
    out
}

/// The frame `s` halvings (0 ≤ s < 1) past keyframe `outer`: the outer keyframe magnified
/// by 2^s, the inner one (half its width, twice the detail) where it reaches.
pub fn interpolate(outer: &RgbImage, inner: Option<&RgbImage>, s: f64) -> RgbaImage {
    let (w, h) = outer.dimensions();
    let (wf, hf) = (w as f64, h as f64);
    let zoom = 2f64.powf(s);
    let mut out = RgbaImage::new(w, h);
    for (i, j, px) in out.enumerate_pixels_mut() {
        // Offset from the centre in frame pixels, then in outer- and inner-keyframe pixels.
        let (ox, oy) = (i as f64 + 0.5 - wf / 2.0, j as f64 + 0.5 - hf / 2.0);
        let (ux, uy) = (ox / zoom, oy / zoom);
        let (vx, vy) = (ux * 2.0, uy * 2.0);
        let c = match inner {
            Some(inn) if vx.abs() <= wf / 2.0 - 0.5 && vy.abs() <= hf / 2.0 - 0.5 => {
                sample(inn, vx + wf / 2.0, vy + hf / 2.0)
            }
            _ => sample(outer, ux + wf / 2.0, uy + hf / 2.0),
        };
        *px = image::Rgba([
            c[0].round() as u8,
            c[1].round() as u8,
            c[2].round() as u8,
            255,
        ]);
    }
    out
}

/// Make the zoom video of `doc` (its view is where the zoom ends).
pub fn run(doc: &EscapeDoc, z: &ZoomVideo) -> Result<()> {
    if z.frames < 2 || z.frames > MAX_FRAMES {
        bail!("--frames {} must be between 2 and {MAX_FRAMES}", z.frames);
    }
    if !(z.start_width.is_finite() && z.start_width > 0.0) {
        bail!("--zoom-from {} must be a positive width", z.start_width);
    }
    let end = doc.world_width_fx();
    let halvings = (Fx::from_f64(z.start_width).log2() - end.log2()).ceil();
    // NaN (a width that is not a number) is refused too.
    if halvings.is_nan() || halvings < 1.0 {
        bail!(
            "the view's width {end:.3} is not narrower than the start width {}; give a \
             deeper --width or a wider --zoom-from",
            z.start_width
        );
    }
    if halvings > 40_000.0 {
        bail!("{halvings} halvings: a zoom video goes at most 40000 halvings deep");
    }
    let count = halvings as u32 + 1;
    let keys = keyframes(doc, z, count)?;
    let load = |k: usize| -> Result<RgbImage> {
        Ok(image::open(&keys[k])
            .with_context(|| format!("cannot read the keyframe '{}'", keys[k].display()))?
            .to_rgb8())
    };
    let opts = VideoOptions {
        fps: z.fps,
        ..VideoOptions::default()
    };
    let mut video = Video::create(&z.out, doc.width, doc.height, z.frames, &opts)?;
    let pb = super::progress_bar(z.frames as u64, "frames");
    let mut cache: Option<(usize, RgbImage, Option<RgbImage>)> = None;
    for f in 0..z.frames {
        // Position in halvings, evenly spaced from the first keyframe to the last.
        let t = f as f64 * (count - 1) as f64 / (z.frames - 1) as f64;
        let k = (t.floor() as usize).min(count as usize - 1);
        let s = t - k as f64;
        if cache.as_ref().is_none_or(|c| c.0 != k) {
            let inner = if k + 1 < count as usize {
                Some(load(k + 1)?)
            } else {
                None
            };
            cache = Some((k, load(k)?, inner));
        }
        let (_, outer, inner) = cache.as_ref().expect("loaded");
        // Opaque frames: the background colour is never seen.
        video.push(&interpolate(outer, inner.as_ref(), s), [0; 3])?;
        pb.inc(1);
    }
    pb.finish_and_clear();
    video.finish()?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_frame_between_keyframes_is_the_outer_one_magnified() {
        // Outer keyframe: a horizontal ramp; inner: its middle half at twice the detail.
        let (w, h) = (64u32, 48u32);
        let ramp = |scale: f64| {
            RgbImage::from_fn(w, h, |i, _| {
                let x = (i as f64 + 0.5 - w as f64 / 2.0) * scale + 128.0;
                Rgb([x as u8, 0, 0])
            })
        };
        let outer = ramp(2.0);
        let inner = ramp(1.0);
        // s = 0: the outer keyframe itself (the inner one agrees where it covers).
        let f0 = interpolate(&outer, Some(&inner), 0.0);
        for i in 0..w {
            let want = outer.get_pixel(i, 10)[0] as i32;
            assert!((f0.get_pixel(i, 10)[0] as i32 - want).abs() <= 1, "{i}");
        }
        // s → 1: the inner keyframe.
        let f1 = interpolate(&outer, Some(&inner), 0.999_999);
        for i in 2..w - 2 {
            let want = inner.get_pixel(i, 10)[0] as i32;
            assert!((f1.get_pixel(i, 10)[0] as i32 - want).abs() <= 1, "{i}");
        }
    }
}
