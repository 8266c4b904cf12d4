//! Motion blur in the live preview: the timeline's current frame drawn from its sub-frames
//! through the engine path `ugnis animate` takes ([`Source::frame`], then
//! [`Renderer::motion`]), so the editor shows the blur the exported frame will have. Quick
//! frames (playing, scrubbing, a drag) are drawn from fewer sub-frames, for speed.

use crate::flame::Flame;
use crate::flame::render::{RenderError, RenderOptions, Renderer};
use crate::io::animation::{Cursor, Source};

/// Sub-frames a quick frame (playing, scrubbing, a drag) is drawn from at most.
pub const MOVING_SUBFRAMES: u32 = 16;

/// A motion-blurred frame for the preview: the animation and the frame's time.
#[derive(Clone, Debug, PartialEq)]
pub struct MotionJob {
    /// What moves (a flame with keyframes, or a flam3 sequence).
    pub source: Source,
    /// The frame's time (the frame number for keyframes, the sequence's time otherwise).
    pub time: f64,
    /// Sub-frames the frame asks for (its `temporal_samples`).
    pub asked: u32,
    /// Sub-frames drawn: `asked`, or fewer while the frames run by.
    pub drawn: u32,
}

impl MotionJob {
    /// The blurred frame of `source` at `time` when the flame there (`shown`) asks for more
    /// than one sub-frame; `moving`: a quick frame (fewer sub-frames).
    pub fn of(source: Source, time: f64, shown: &Flame, moving: bool) -> Option<MotionJob> {
        let asked = shown
            .anim
            .temporal_samples
            .min(crate::flame::sequence::MAX_TEMPORAL_SAMPLES);
        (asked > 1).then(|| MotionJob {
            source,
            time,
            asked,
            drawn: if moving {
                asked.min(MOVING_SUBFRAMES)
            } else {
                asked
            },
        })
    }

    /// The renderer of the frame at `width`×`height` pixels (the framing kept) and `quality`
    /// samples per pixel, or None when nothing moves during the exposure (the preview then
    /// renders the flame as a still).
    pub fn renderer(
        &self,
        width: u32,
        height: u32,
        quality: f64,
        opts: &RenderOptions,
    ) -> Option<Result<Renderer, RenderError>> {
        let drawn = self.drawn.max(1);
        let adjust = move |f: &mut Flame| {
            f.resize_keep_framing(width, height);
            f.quality = quality;
            f.anim.temporal_samples = f.anim.temporal_samples.min(drawn);
        };
        let frame = self
            .source
            .frame(self.time, true, &adjust, &mut Cursor::default());
        if frame.is_still() {
            return None;
        }
        Some(Renderer::motion(&frame, opts))
    }

    /// For the status bar: "motion blur 16 of 200 sub-frames".
    pub fn describe(&self) -> String {
        if self.drawn < self.asked {
            format!(
                "motion blur {} of {} sub-frames while moving",
                self.drawn, self.asked
            )
        } else {
            format!("motion blur {} sub-frames", self.asked)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::app::flame_tab::preview::{PreviewEvent, PreviewJob, PreviewWorker};
    use crate::flame::keyframes::{FlameParam, Key, Target};
    use crate::io::animation::{FrameSpec, Job};
    use std::time::Duration;

    const SIZE: (u32, u32) = (96, 72);
    const QUALITY: f64 = 60.0;

    /// Orchid turning a quarter turn over 10 frames, blurred over 40 sub-frames of 2 frames.
    fn keyed() -> Flame {
        let path = concat!(env!("CARGO_MANIFEST_DIR"), "/examples/orchid.flame");
        let mut f = crate::io::read_flames(std::path::Path::new(path), &Default::default())
            .unwrap()
            .value
            .remove(0);
        f.keys.frames = 10;
        let c = f.keys.curve_mut(Target::Flame(FlameParam::Rotate));
        c.insert(Key::new(0.0, 0.0)).unwrap();
        c.insert(Key::new(10.0, 90.0)).unwrap();
        f.anim.temporal_samples = 40;
        f.anim.temporal_filter_width = 2.0;
        f
    }

    /// The preview's refined picture of the frame at `time` (RGB).
    fn preview(f: &Flame, time: f64, motion: Option<MotionJob>) -> Vec<u8> {
        let w = PreviewWorker::new(|| {});
        w.submit(PreviewJob {
            flame: f.keys.apply(f, time),
            width: SIZE.0,
            height: SIZE.1,
            first_quality: 1.0,
            final_quality: QUALITY,
            noise_target: None,
            least_quality: 0.0,
            threads: 2,
            generation: 1,
            motion,
        });
        loop {
            match w.wait(Duration::from_secs(60)) {
                Some(PreviewEvent::Frame(fr)) if fr.done => {
                    return fr
                        .image
                        .pixels
                        .iter()
                        .flat_map(|p| [p.r(), p.g(), p.b()])
                        .collect();
                }
                Some(PreviewEvent::Frame(_)) => {}
                Some(PreviewEvent::Error { message, .. }) => panic!("{message}"),
                None => panic!("no preview within a minute"),
            }
        }
    }

    fn psnr(a: &[u8], b: &[u8]) -> f64 {
        assert_eq!(a.len(), b.len());
        let mse = a
            .iter()
            .zip(b)
            .map(|(x, y)| (*x as f64 - *y as f64).powi(2))
            .sum::<f64>()
            / a.len() as f64;
        10.0 * (255.0f64.powi(2) / mse.max(1e-12)).log10()
    }

    #[test]
    fn the_preview_of_a_blurred_keyed_frame_is_the_frame_ugnis_animate_writes() {
        let f = keyed();
        let dir = tempfile::tempdir().unwrap();
        // The job `ugnis animate` runs (its default seed and a fixed thread count).
        let job = Job {
            source: Source::Keys(f.clone()),
            frames: vec![FrameSpec {
                time: 5.0,
                name: "00005.png".into(),
            }],
            dir: dir.path().to_path_buf(),
            video: None,
            render: RenderOptions {
                seed: 1,
                threads: 2,
                ..RenderOptions::default()
            },
            size: Some(SIZE),
            quality: Some(QUALITY),
            blur: true,
        };
        job.run(&std::sync::atomic::AtomicBool::new(false), |_| {})
            .unwrap();
        let cli = image::open(dir.path().join("00005.png"))
            .unwrap()
            .to_rgb8()
            .into_raw();
        let m = MotionJob::of(Source::Keys(f.clone()), 5.0, &f.keys.apply(&f, 5.0), false);
        assert_eq!(m.as_ref().map(|m| (m.asked, m.drawn)), Some((40, 40)));
        let blurred = preview(&f, 5.0, m);
        let still = preview(&f, 5.0, None);
        let (b, s) = (psnr(&blurred, &cli), psnr(&still, &cli));
        eprintln!("blurred preview vs CLI {b:.1} dB, still preview vs CLI {s:.1} dB");
        assert!(
            b > 40.0,
            "the blurred preview is the CLI's frame: {b:.1} dB"
        );
        assert!(
            b > s + 6.0,
            "without blur the preview differs: {s:.1} dB vs {b:.1} dB"
        );
    }

    #[test]
    fn moving_frames_draw_fewer_sub_frames_and_say_so() {
        let f = keyed();
        let shown = f.keys.apply(&f, 3.0);
        let m = MotionJob::of(Source::Keys(f.clone()), 3.0, &shown, true).unwrap();
        assert_eq!((m.asked, m.drawn), (40, MOVING_SUBFRAMES));
        assert_eq!(m.describe(), "motion blur 16 of 40 sub-frames while moving");
        let mut one = shown.clone();
        one.anim.temporal_samples = 1;
        assert!(MotionJob::of(Source::Keys(f), 3.0, &one, false).is_none());
    }
}
