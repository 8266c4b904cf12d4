//! Tests of the progressive renderer: palette accumulation, reused memory and reproducible
//! random forms.

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

/// A flame whose random forms run in batch loops (flam3's `pre_blur`, a `post_` form and
/// gaussian_blur in a final xform): the same seed and thread count give the same histogram
/// bit for bit, another seed another one.
#[test]
fn random_forms_render_the_same_picture_from_the_same_seed() {
    use crate::flame::model::{Affine, Var, Xform};
    use crate::flame::variations::{self, Form};
    let mut flame = crate::flame::model::test_sierpinski(64, 48, 10.0);
    let blur = variations::by_name("gaussian_blur").unwrap();
    flame.xforms[0]
        .vars
        .push(Var::with_form(blur, Form::Pre, 0.05));
    flame.xforms[1]
        .vars
        .push(Var::with_form(variations::SPHERICAL, Form::Post, 0.3));
    let mut fin = Xform::linear(Affine::IDENTITY, 0.9, 0.0);
    fin.vars.push(Var::new(blur, 0.02));
    fin.vars.push(Var::with_form(blur, Form::Pre, 0.02));
    flame.final_xform = Some(fin);
    let never = AtomicBool::new(false);
    let run = |seed: u64| {
        let opts = RenderOptions {
            threads: 2,
            seed,
            ..RenderOptions::default()
        };
        let mut r = Renderer::new(&flame, &opts).unwrap();
        assert!(r.run_all(1, &never, |_| {}));
        let h = r.into_state().unwrap().1;
        h.data
            .iter()
            .flatten()
            .map(|v| v.to_bits())
            .collect::<Vec<u32>>()
    };
    let a = run(7);
    assert!(a.iter().any(|&b| b != 0), "nothing drawn");
    assert!(a == run(7), "the same seed gave another histogram");
    assert!(a != run(8), "another seed gave the same histogram");
}
