//! Saved render states that carry more than the histogram: the orbits of the stateful
//! variations (gingerbread_man keeps its own point from call to call, per worker thread), and
//! the samples an extended render skipped after a partial sub-batch. A resumed render is the
//! uninterrupted one, bucket for bucket.

mod common;

use std::sync::atomic::AtomicBool;

use ugnis::flame::render::Renderer;
use ugnis::flame::{Flame, Histogram, RenderState};
use ugnis::gradient::Gradient;
use ugnis::io::render_state::{self, StateReader};

use common::{opts, run};

/// The histogram's bits. With an 8-bit palette every sum is a whole number (exact in any
/// order of the adds), so a resumed render's histogram equals the uninterrupted one's.
fn bits(h: &Histogram) -> Vec<u32> {
    h.data.iter().flatten().map(|v| v.to_bits()).collect()
}

/// Save and read back through a file, as `ugnis render --save-state` / `--resume` do.
fn through_file(tag: &str, st: &RenderState, hist: &Histogram) -> (RenderState, Histogram) {
    let dir = common::temp_dir(tag);
    let path = dir.join("s.ugnis-state");
    render_state::save(&path, st, hist).unwrap();
    let mut rd = StateReader::open(&path).unwrap();
    assert_eq!(&rd.state, st, "the state reads back as written");
    let back = rd.read_all().unwrap();
    let _ = std::fs::remove_dir_all(&dir);
    (rd.state, back)
}

/// A JWildfire flame of two xforms, one of them the gingerbread man's orbit, at 64×48.
fn gingerbread(quality: f64) -> Flame {
    let dir = common::temp_dir("gingerbread-flame");
    let path = dir.join("g.flame");
    std::fs::write(
        &path,
        r#"<flame name="g" version="JWildfire V6.00" size="64 48" center="1 1.5" scale="5" quality="30" brightness="4" gamma="4" background="0 0 0">
<xform weight="1" color="0" gingerbread_man="1" coefs="1 0 0 1 0 0"/>
<xform weight="0.5" color="1" linear="1" coefs="0.5 0 0 0.5 0.2 0.1"/>
<palette count="2" format="RGB">FFFFFF FF8000</palette></flame>"#,
    )
    .unwrap();
    let mut f = ugnis::io::read_flames(&path, &Default::default())
        .unwrap()
        .value
        .remove(0);
    let _ = std::fs::remove_dir_all(&dir);
    f.palette = Gradient::grey_ramp();
    f.quality = quality;
    f
}

#[test]
fn a_resumed_orbit_variation_continues_its_orbits() {
    // The render stops after 8 of its sub-batches (between passes) and is saved, read back
    // and run to the end.
    let f = gingerbread(50.0);
    let o = opts(4, 2);
    let mut whole = Renderer::new(&f, &o).unwrap();
    run(&mut whole);
    let (_, whole) = whole.into_state().unwrap();
    let mut r = Renderer::new(&f, &o).unwrap();
    assert!(r.run(80_000, &AtomicBool::new(false)));
    let (st, hist) = r.snapshot().unwrap();
    assert_eq!(st.var_states.len(), 2, "one variation state per thread");
    assert!(st.var_states.iter().all(|v| v.len() == 8));
    assert_ne!(
        st.var_states[0], st.var_states[1],
        "each thread its own orbit"
    );
    let (st, hist) = through_file("gingerbread", &st, &hist);
    let mut resumed = Renderer::resume(&st, hist.clone(), 0.0, &o, None).unwrap();
    run(&mut resumed);
    let (_, resumed_hist) = resumed.into_state().unwrap();
    assert!(
        bits(&resumed_hist) == bits(&whole),
        "the resumed render differs from the uninterrupted one"
    );
    // Without the variations' orbits the resumed render starts them again: another picture.
    let forgot = RenderState {
        var_states: Vec::new(),
        ..st
    };
    let mut restarted = Renderer::resume(&forgot, hist, 0.0, &o, None).unwrap();
    run(&mut restarted);
    let (_, restarted) = restarted.into_state().unwrap();
    assert!(
        bits(&restarted) != bits(&whole),
        "the orbits made no difference"
    );
}

/// The orchid example at 81×50: 4050 samples per unit of quality.
fn orchid(quality: f64) -> Flame {
    let mut f = ugnis::io::read_flames(&common::example("orchid.flame"), &Default::default())
        .unwrap()
        .value
        .remove(0);
    f.resize_keep_framing(80, 50);
    f.resize_keep_framing(81, 50);
    f.palette = Gradient::grey_ramp();
    f.quality = quality;
    f
}

#[test]
fn a_state_saved_mid_way_through_an_extension_keeps_its_gap() {
    // Quality 5: 20 250 samples in 3 sub-batches, the last of 250. Extended by 5 more, the
    // render goes on with whole sub-batches after it (9 750 samples of its range skipped):
    // sub-batches 3, 4 and 5 (the last again of 250). Saved after sub-batch 4, the state
    // resumes with sub-batch 5 and ends where the uninterrupted render ends.
    let o = opts(7, 2);
    let mut r = Renderer::new(&orchid(5.0), &o).unwrap();
    run(&mut r);
    let (st, hist) = r.into_state().unwrap();
    assert_eq!((st.samples_done, st.batches_done, st.gap), (20_250, 3, 0));
    let mut r = Renderer::resume(&st, hist, 5.0, &o, None).unwrap();
    assert_eq!(r.total_samples(), 40_500);
    assert!(r.run(20_000, &AtomicBool::new(false)));
    let (mid, mid_hist) = r.snapshot().unwrap();
    assert_eq!((mid.samples_done, mid.batches_done), (40_250, 5));
    assert_eq!(mid.gap, 9_750);
    assert!(!mid.is_finished(), "one sub-batch is left");
    run(&mut r);
    assert_eq!(r.samples_done(), 40_500);
    let (_, whole) = r.into_state().unwrap();
    let (mid, mid_hist) = through_file("gap", &mid, &mid_hist);
    let mut resumed = Renderer::resume(&mid, mid_hist, 0.0, &o, None).unwrap();
    assert_eq!(resumed.total_samples(), 40_500);
    run(&mut resumed);
    assert_eq!(resumed.samples_done(), 40_500);
    assert!((resumed.quality_done() - 10.0).abs() < 1e-9);
    let (end, resumed) = resumed.into_state().unwrap();
    assert!(end.is_finished());
    assert!(
        bits(&resumed) == bits(&whole),
        "the resumed render differs from the uninterrupted one"
    );
}
