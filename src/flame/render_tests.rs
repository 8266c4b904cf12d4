//! Tests of the progressive renderer: palette accumulation and reused memory.

use super::*;
use crate::flame::histogram::Bucket;
use crate::gradient::Gradient;

/// An 8-bit palette adds whole palette units, so the colour sums of a render are whole
/// numbers (exact, whatever the order of the adds) — what makes saved states small.
#[test]
fn an_8_bit_palette_accumulates_whole_colour_sums() {
    let flame = Flame {
        palette: Gradient::grey_ramp(),
        ..crate::flame::model::test_sierpinski(64, 48, 20.0)
    };
    let opts = RenderOptions {
        threads: 2,
        ..RenderOptions::default()
    };
    let mut r = Renderer::new(&flame, &opts).unwrap();
    assert!(r.run_all(1, &AtomicBool::new(false), |_| {}));
    let (_, hist) = r.into_state().unwrap();
    let mut hit = 0;
    for b in &hist.data {
        for v in &b[..3] {
            assert_eq!(v.fract(), 0.0, "{b:?}");
        }
        hit += (b[0] > 0.0) as usize;
    }
    assert!(hit > 100, "{hit} buckets with colour");
}

/// A render made from the memory of another (a different flame and size, its buckets and
/// kept samples still full) is the render made from fresh memory, bit for bit — and it
/// does reuse that memory when it fits.
#[test]
fn a_render_reusing_spare_memory_is_a_fresh_render() {
    let opts = RenderOptions {
        threads: 2,
        keep_samples: true,
        ..RenderOptions::default()
    };
    let never = AtomicBool::new(false);
    let flame = crate::flame::model::test_sierpinski(64, 48, 20.0);
    let fresh = {
        let mut r = Renderer::new(&flame, &opts).unwrap();
        assert!(r.run_all(3, &never, |_| {}));
        r.into_state().unwrap().1
    };
    for (w, h) in [(64, 48), (70, 50), (200, 150), (8, 6)] {
        let mut other = Renderer::new(
            &Flame {
                palette: Gradient::grey_ramp(),
                ..crate::flame::model::test_sierpinski(w, h, 30.0)
            },
            &opts,
        )
        .unwrap();
        assert!(other.run_all(2, &never, |_| {}));
        let mut spare = other.into_spare();
        let held: Vec<*const Bucket> = spare.hists.iter().map(|h| h.data.as_ptr()).collect();
        let mut r = Renderer::reusing(&flame, &opts, &mut spare).unwrap();
        let reused = r.hists.iter().any(|h| held.contains(&h.data.as_ptr()));
        // Buffers are taken when they hold the 64×48 grid without twice its size.
        assert_eq!(reused, (w, h) == (64, 48) || (w, h) == (70, 50), "{w}×{h}");
        assert!(r.logs.as_ref().unwrap().iter().all(|l| l.is_empty()));
        assert!(r.run_all(3, &never, |_| {}));
        let hist = r.into_state().unwrap().1;
        assert_eq!((hist.bw, hist.bh), (fresh.bw, fresh.bh));
        let bits =
            |h: &Histogram| -> Vec<u32> { h.data.iter().flatten().map(|v| v.to_bits()).collect() };
        assert!(bits(&hist) == bits(&fresh), "{w}×{h}: histograms differ");
    }
}
