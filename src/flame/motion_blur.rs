//! The sub-frames of a motion-blurred frame, as flam3-animate renders a sequence: frame t is
//! drawn from `temporal_samples` flames at the times t + δᵢ spread over the exposure
//! (`temporal_filter_width`), each flame's colours weighted by the temporal filter, the frame's
//! samples shared among them (so a blurred frame costs what a still costs). The picture is
//! developed with the settings flam3 uses: brightness, contrast and the log scale of the last
//! sub-frame (the scale divided by the filter's mean weight), gamma, vibrancy and background
//! averaged over the sub-frames, density estimation of the first, highlight power of the frame
//! and the spatial filter of the sequence's first flame.

use rayon::prelude::*;

use crate::flame::interpolate::interpolate_at;
use crate::flame::model::Flame;
use crate::flame::sequence::TemporalFilter;

/// One sub-frame: the flame at its time, its weight, and its share of the frame's samples.
#[derive(Clone, Debug)]
pub struct SubFrame {
    /// The flame at the sub-frame's time, on the frame's bucket grid (its size and
    /// supersampling) with the spatial filter of the animation's first flame.
    pub flame: Flame,
    /// The temporal filter's weight, in (0, 1]: the sub-frame's colours are multiplied by it.
    pub weight: f64,
    /// The sub-frame's share of the frame's samples: the flame's quality·4^zoom samples per
    /// pixel over the picture, divided among the sub-frames.
    pub samples: u64,
}

/// A frame to render with motion blur.
#[derive(Clone, Debug)]
pub struct MotionFrame {
    /// The settings the picture is developed with (size, filter, tone, log scale).
    pub develop: Flame,
    /// The sub-frames in time order (at least one; exactly one without motion blur).
    pub subframes: Vec<SubFrame>,
    /// The filter's mean weight (flam3's `sumfilt`): the log scale divides the density by it.
    pub mean_weight: f64,
}

impl MotionFrame {
    /// Samples of the whole frame.
    pub fn total_samples(&self) -> u64 {
        self.subframes.iter().map(|s| s.samples).sum()
    }

    /// True when every sub-frame is the same flame (a still: nothing moves).
    pub fn is_still(&self) -> bool {
        let first = &self.subframes[0].flame;
        self.subframes.iter().all(|s| {
            s.flame.xforms == first.xforms
                && s.flame.final_xform == first.final_xform
                && s.flame.more_finals == first.more_finals
                && s.flame.palette == first.palette
                && s.flame.center == first.center
                && s.flame.scale == first.scale
                && s.flame.zoom == first.zoom
                && s.flame.rotate == first.rotate
                && s.flame.cam == first.cam
                && s.flame.cam_zoom == first.cam_zoom
        })
    }
}

/// The frame at `time` of a sequence of control points sorted by time (see
/// [`crate::flame::interpolate::check_times`]), with `temporal_samples` sub-frames as the
/// flame at that time says (`limit` caps them: a frame needs enough samples per sub-frame).
pub fn frame_at(cps: &[Flame], time: f64, limit: u32) -> MotionFrame {
    frame_from(time, limit, &cps[0], |t| interpolate_at(cps, t))
}

/// The frame at `time` of any animation: `flame_at(t)` gives the flame at time t (of a
/// sequence, or with keyframes applied); `first` is the animation's first flame, whose spatial
/// filter every frame uses (as flam3 does).
pub fn frame_from(
    time: f64,
    limit: u32,
    first: &Flame,
    flame_at: impl Fn(f64) -> Flame + Sync,
) -> MotionFrame {
    let frame = flame_at(time);
    let mut anim = frame.anim;
    anim.temporal_samples = anim.temporal_samples.clamp(1, limit.max(1));
    let filter = TemporalFilter::of(&anim);
    let n = filter.deltas.len();
    let (w, h) = (frame.width, frame.height);
    let px = w as f64 * h as f64;
    // Flames at the sub-frame times, made in parallel (a sequence's blend takes tens of
    // microseconds, and a frame has up to thousands of sub-frames).
    let subframes: Vec<SubFrame> = filter
        .deltas
        .par_iter()
        .zip(filter.weights.par_iter())
        .map(|(delta, weight)| {
            let mut f = if n == 1 {
                frame.clone()
            } else {
                flame_at(time + delta)
            };
            // The bucket grid is the frame's; each sub-frame brings its own camera.
            f.width = w;
            f.height = h;
            f.supersample = frame.supersample;
            f.filter = first.filter;
            f.filter_shape = first.filter_shape;
            let density = f.quality.max(0.0) * 4f64.powf(f.zoom);
            let samples = (density * px / n as f64).round() as u64;
            SubFrame {
                flame: f,
                weight: *weight,
                samples,
            }
        })
        .collect();
    let k = subframes.len() as f64;
    let mean = |get: fn(&Flame) -> f64| subframes.iter().map(|s| get(&s.flame)).sum::<f64>() / k;
    let mut develop = subframes[subframes.len() - 1].flame.clone();
    develop.gamma = mean(|f| f.gamma);
    develop.vibrancy = mean(|f| f.vibrancy);
    develop.background = [
        mean(|f| f.background[0]),
        mean(|f| f.background[1]),
        mean(|f| f.background[2]),
    ];
    let first = &subframes[0].flame;
    develop.estimator_radius = first.estimator_radius;
    develop.estimator_minimum = first.estimator_minimum;
    develop.estimator_curve = first.estimator_curve;
    develop.highlight_power = frame.highlight_power;
    develop.anim.time = time;
    MotionFrame {
        develop,
        subframes,
        mean_weight: filter.mean_weight,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::flame::model::{Affine, Xform};
    use crate::flame::sequence::TemporalFilterType;

    fn cp(time: f64, center: f64, gamma: f64) -> Flame {
        let mut f = Flame {
            width: 40,
            height: 30,
            quality: 100.0,
            center: [center, 0.0],
            gamma,
            xforms: vec![Xform::linear(
                Affine::new(0.5, 0.0, 0.0, 0.5, 0.0, 0.0),
                1.0,
                0.0,
            )],
            ..Flame::default()
        };
        f.anim.time = time;
        f.anim.temporal_samples = 5;
        f
    }

    #[test]
    fn sub_frames_span_the_exposure_and_share_the_samples() {
        let cps = [cp(0.0, 0.0, 2.0), cp(10.0, 10.0, 4.0)];
        let m = frame_at(&cps, 5.0, 1000);
        assert_eq!(m.subframes.len(), 5);
        let centers: Vec<f64> = m.subframes.iter().map(|s| s.flame.center[0]).collect();
        assert_eq!(centers, vec![4.5, 4.75, 5.0, 5.25, 5.5]);
        assert_eq!(m.total_samples(), 40 * 30 * 100);
        assert_eq!(m.mean_weight, 1.0);
        assert!(!m.is_still());
        // The develop settings: gamma averaged, the camera of the last sub-frame.
        assert!((m.develop.gamma - 3.0).abs() < 1e-12);
        assert_eq!(m.develop.center[0], 5.5);
        // A cap on sub-frames, and one flame is a still.
        assert_eq!(frame_at(&cps, 5.0, 2).subframes.len(), 2);
        assert!(frame_at(&cps[..1], 5.0, 1000).is_still());
    }

    /// A flame whose every point lands on (0, 0): one bright dot, moved by the camera.
    fn dot_at(time: f64, center_x: f64) -> Flame {
        let mut f = Flame {
            width: 64,
            height: 16,
            scale: 64.0,
            quality: 50.0,
            center: [center_x, 0.0],
            estimator_radius: 0.0,
            filter: 0.2,
            xforms: vec![Xform::linear(
                Affine::new(0.0, 0.0, 0.0, 0.0, 0.0, 0.0),
                1.0,
                0.5,
            )],
            ..Flame::default()
        };
        f.palette.colors = vec![[1.0, 1.0, 1.0, 1.0]; 256];
        f.anim.time = time;
        f.anim.temporal_samples = 64;
        f
    }

    fn lit_columns(img: &image::DynamicImage) -> Vec<u32> {
        let rgba = img.to_rgba8();
        (0..rgba.width())
            .filter(|&x| (0..rgba.height()).any(|y| rgba.get_pixel(x, y)[0] > 40))
            .collect()
    }

    #[test]
    fn a_moving_camera_smears_a_dot_over_the_exposure() {
        use crate::flame::render::{RenderOptions, Renderer};
        let opts = RenderOptions {
            threads: 2,
            ..RenderOptions::default()
        };
        let never = std::sync::atomic::AtomicBool::new(false);
        let render = |m: &MotionFrame| {
            let mut r = Renderer::motion(m, &opts).unwrap();
            assert!(r.run_all(2, &never, |_| {}));
            r.finish()
        };
        // The camera moves 0.25 units (16 pixels) a frame to the right: the dot moves left.
        let cps = [dot_at(0.0, -1.0), dot_at(8.0, 1.0)];
        let cols = lit_columns(&render(&frame_at(&cps, 4.0, 1000)));
        let (first, last) = (cols[0], *cols.last().unwrap());
        assert!(
            (22..=26).contains(&first) && (38..=42).contains(&last),
            "{cols:?}"
        );
        assert_eq!(
            cols.len() as u32,
            last - first + 1,
            "one unbroken streak: {cols:?}"
        );
        // Without motion the dot stays a dot.
        let still = [dot_at(0.0, 0.0), dot_at(8.0, 0.0)];
        let m = frame_at(&still, 4.0, 1000);
        assert!(m.is_still());
        assert!(lit_columns(&render(&m)).len() <= 3);
        // The same frame renders the same bits whatever the passes.
        let once = render(&frame_at(&cps, 4.0, 1000));
        let mut r = Renderer::motion(&frame_at(&cps, 4.0, 1000), &opts).unwrap();
        assert!(r.run_all(7, &never, |_| {}));
        assert_eq!(r.finish().to_rgba8().as_raw(), once.to_rgba8().as_raw());
    }

    #[test]
    fn an_exp_filter_weights_the_late_sub_frames() {
        let mut a = cp(0.0, 0.0, 2.0);
        a.anim.temporal_filter_type = TemporalFilterType::Exp;
        a.anim.temporal_filter_exp = 1.0;
        let m = frame_at(&[a.clone(), cp(10.0, 10.0, 2.0)], 0.0, 1000);
        let w: Vec<f64> = m.subframes.iter().map(|s| s.weight).collect();
        assert_eq!(w, vec![0.2, 0.4, 0.6, 0.8, 1.0]);
        assert!((m.mean_weight - 0.6).abs() < 1e-12);
    }
}
