//! Explore speed, with criterion:
//! - the Koch curve of order 10 (1,048,576 segments): the derivation walked without building
//!   the string, and drawn into a 1024×1024 picture (target < 1 s);
//! - box counting of 10⁷ chaos-game points on 2 threads (target ≤ 1 s): the Sierpinski
//!   triangle (levels 1–13 from the bitmap suffice) and the Koch curve (its fit reaches past
//!   level 13, so the cell keys are sorted too).
//!
//! Run: `cargo bench --bench explore`.

use std::hint::black_box;

use criterion::{Criterion, criterion_group, criterion_main};

use ugnis::explore::P2;
use ugnis::explore::dimension::box_count_points;
use ugnis::explore::ifs::ChaosGame;
use ugnis::explore::ifs::presets::koch_curve;
use ugnis::explore::lsystem::presets;

fn koch(c: &mut Criterion) {
    let sys = presets::koch_curve().system.compile().unwrap();
    let mut g = c.benchmark_group("lsystem");
    g.sample_size(10);
    g.bench_function("koch order 10: walk 1048576 segments", |b| {
        b.iter(|| black_box(sys.segments(10).unwrap().count()))
    });
    g.bench_function("koch order 10: draw 1024x1024", |b| {
        b.iter(|| black_box(sys.render(10, 1024, 1024, [0, 0, 0]).unwrap()))
    });
    g.finish();
}

fn box_counting(c: &mut Criterion) {
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(2)
        .build()
        .unwrap();
    let pts: Vec<P2> = ChaosGame::triangle(1).take(10_000_000).collect();
    let mut g = c.benchmark_group("dimension");
    g.sample_size(10);
    g.bench_function("box count 10^7 points, 2 threads", |b| {
        b.iter(|| {
            let r = pool.install(|| box_count_points(&pts).unwrap());
            black_box(r.dimension())
        })
    });
    let koch: Vec<P2> = koch_curve().points(10_000_000, 1);
    g.bench_function("box count 10^7 Koch curve points, 2 threads", |b| {
        b.iter(|| {
            let r = pool.install(|| box_count_points(&koch).unwrap());
            black_box(r.dimension())
        })
    });
    g.finish();
}

criterion_group!(benches, koch, box_counting);
criterion_main!(benches);
