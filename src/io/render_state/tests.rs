//! Tests of the render state format: chunks bit for bit, bands of rows, compression of whole
//! numbers.

use super::chunk::{compress, decompress};
use super::*;
use crate::flame::histogram::Bucket;

/// Chunks come back bit for bit whatever their values: whole colours and alphas (stored as
/// integers), fractional ones, both mixed in one chunk, and the edge of f32's whole numbers.
#[test]
fn chunks_round_trip_bit_for_bit() {
    let mut rng = crate::flame::rng::FastRng::new(5);
    let whole = |rng: &mut crate::flame::rng::FastRng| -> Bucket {
        let n = (rng.f01() * 60.0).floor() as f32;
        let c = |rng: &mut crate::flame::rng::FastRng| (rng.f01() * 255.0).floor() as f32 * n;
        [c(rng), c(rng), c(rng), n]
    };
    let cases: Vec<Vec<Bucket>> = vec![
        (0..500).map(|_| whole(&mut rng)).collect(),
        (0..500)
            .map(|i| {
                let mut b = whole(&mut rng);
                if i == 250 {
                    b[1] += 0.5; // one fractional colour: the chunk stores bits
                }
                b
            })
            .collect(),
        (0..500)
            .map(|_| [rng.f01() as f32, 0.3, 1e-9, rng.f01() as f32 * 7.0])
            .collect(),
        vec![
            [16_777_216.0, 16_777_215.0, 0.0, 1.0],
            [0.0; 4],
            [1.0, 2.0, 3.0, 16_777_216.0],
        ],
        vec![[-1.0, 2.0, f32::NAN, 4.0], [1e30, 0.0, 0.0, -0.0]],
    ];
    for rows in cases {
        let bytes = compress(&rows).unwrap();
        let mut back = vec![[9.0f32; 4]; rows.len()];
        decompress("t", 0, &bytes, &mut back).unwrap();
        for (a, b) in rows.iter().zip(&back) {
            assert_eq!(a.map(f32::to_bits), b.map(f32::to_bits));
        }
    }
}

/// Rows cut out of the middle of chunks (32 rows each) read as the same rows of the whole
/// histogram, bit for bit; a destination of the wrong size is refused.
#[test]
fn a_band_of_rows_reads_as_the_same_rows_of_the_whole() {
    use crate::flame::render::{RenderOptions, Renderer};
    let f = crate::flame::model::test_sierpinski(40, 90, 3.0);
    let mut r = Renderer::new(&f, &RenderOptions::default()).unwrap();
    assert!(r.run_all(1, &std::sync::atomic::AtomicBool::new(false), |_| {}));
    let (st, hist) = r.into_state().unwrap();
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("s.ugnis-state");
    save(&path, &st, &hist).unwrap();
    let mut rd = StateReader::open(&path).unwrap();
    let all = rd.read_all().unwrap();
    assert_eq!(all.data, hist.data);
    let bw = hist.bw;
    for rows in [10..75, 0..32, 31..33, 64..hist.bh, 40..40] {
        let band = rd.read_rows(rows.clone()).unwrap();
        assert_eq!(
            band.data,
            hist.data[rows.start * bw..rows.end * bw],
            "{rows:?}"
        );
    }
    let mut wrong = Histogram::new(bw, 5);
    let e = rd
        .read_rows_into(10..20, &mut wrong)
        .unwrap_err()
        .to_string();
    assert!(e.contains("s.ugnis-state") && e.contains("buckets"), "{e}");
    assert!(rd.read_rows(80..hist.bh + 1).is_err());
}

/// Sums of 8-bit palette entries (whole palette units) take far less room than the same
/// colours in units of 1.0, as version 1 stored them.
#[test]
fn whole_colours_compress_better_than_their_fractions() {
    let mut rng = crate::flame::rng::FastRng::new(8);
    let rows: Vec<Bucket> = (0..4096)
        .map(|_| {
            let n = 1.0 + (rng.f01() * 40.0).floor();
            let mut c = [0.0f64; 3];
            for _ in 0..n as usize {
                for v in &mut c {
                    *v += (rng.f01() * 256.0).floor().min(255.0);
                }
            }
            [c[0] as f32, c[1] as f32, c[2] as f32, n as f32]
        })
        .collect();
    let units = compress(&rows).unwrap().len();
    let fractions: Vec<Bucket> = rows
        .iter()
        .map(|b| [b[0] / 255.0, b[1] / 255.0, b[2] / 255.0, b[3]])
        .collect();
    let ones = compress(&fractions).unwrap().len();
    let raw = rows.len() * 16;
    assert!(units * 10 < raw * 4, "{units} of {raw}");
    assert!(units * 10 < ones * 8, "{units} vs {ones}");
}

#[test]
fn the_memory_estimate_counts_what_the_writer_holds() {
    use crate::flame::render::{SAVE_BUFFER_BYTES, SAVE_CHUNK_ROWS, save_chunks_in_flight};
    assert_eq!(SAVE_CHUNK_ROWS, CHUNK_ROWS as u64);
    // Two chunks per thread while they fit in the save buffer, never none.
    let chunk = |bw: u64| CHUNK_ROWS as u64 * bw * 16;
    assert_eq!(save_chunks_in_flight(chunk(640), 4), 8);
    let wide = save_chunks_in_flight(chunk(60_000), 32);
    assert!(
        wide as u64 * 2 * chunk(60_000) <= SAVE_BUFFER_BYTES,
        "{wide}"
    );
    assert_eq!(save_chunks_in_flight(chunk(400_000), 32), 1);
}
