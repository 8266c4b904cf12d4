//! Every variation with extreme parameter values (±1e308, ±1e9, −1, 0, 1e-300, NaN), one
//! parameter at a time and all at once: none panics, none takes more than a moment to prepare,
//! and no evaluation takes more than tens of microseconds (counts, loop bounds, recursion
//! depths and table sizes are limited to what the variation can use).
//!
//! The variations that grow a structure when they are prepared (a crystal, an aggregate: a
//! tenth of a second or more each time) are tried with every parameter at once and with their
//! limited parameters, at ±1e308, 0 and NaN, in the test run by `cargo test`; with every
//! parameter and value in `benches/hardening.sh` (`--ignored`).

use std::panic::{AssertUnwindSafe, catch_unwind};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use ugnis::flame::Affine;
use ugnis::flame::rng::FastRng;
use ugnis::flame::variations::{self, Acc, Form, Prepared, eval_prepared, flag};

/// The processor time this thread has used (the wall clock where it is not known): the other
/// tests running meanwhile do not count.
fn thread_cpu_time() -> Duration {
    #[cfg(unix)]
    {
        let mut t = libc::timespec {
            tv_sec: 0,
            tv_nsec: 0,
        };
        // SAFETY: clock_gettime only writes the timespec it is given.
        if unsafe { libc::clock_gettime(libc::CLOCK_THREAD_CPUTIME_ID, &mut t) } == 0 {
            return Duration::new(t.tv_sec as u64, t.tv_nsec as u32);
        }
    }
    static START: std::sync::OnceLock<Instant> = std::sync::OnceLock::new();
    START.get_or_init(Instant::now).elapsed()
}

const VALUES: [f64; 8] = [1e308, -1e308, 1e9, -1e9, -1.0, 0.0, 1e-300, f64::NAN];

/// The values a variation that is slow to prepare is tried with.
const HEAVY_VALUES: [f64; 4] = [1e308, -1e308, 0.0, f64::NAN];

/// Evaluations timed per case (their mean is compared with the limit).
const EVALS: u32 = 24;

/// Most processor time of one evaluation, on average over [`EVALS`] points.
const EVAL_LIMIT: Duration = Duration::from_micros(100);

/// Most processor time of preparing a variation (its shared data: a grown crystal, an
/// aggregate, a table), and the wall-clock time after which a case counts as hung. dla3d_wf's
/// aggregate at its cap of 10 million walker steps takes about 4 s of one core in the test
/// build: the limit leaves room for that, and stops what has no cap.
const PREPARE_LIMIT: Duration = Duration::from_secs(10);
const HUNG: Duration = Duration::from_secs(60);

/// Preparation, with the default parameters, of a variation tried on fewer cases.
const HEAVY: Duration = Duration::from_millis(20);

/// One case: variation `id` with parameter `which` (all when `None`) set to `value`. Returns
/// what was too slow, if anything.
fn run_case(id: u16, which: Option<usize>, value: f64) -> Option<String> {
    let d = variations::info(id);
    let mut ps: Vec<f64> = d.params.iter().map(|p| p.default).collect();
    match which {
        Some(i) => ps[i] = value,
        None => ps.iter_mut().for_each(|p| *p = value),
    }
    let form = if d.has(flag::POST_ONLY) {
        Form::Post
    } else {
        Form::Regular
    };
    let t = thread_cpu_time();
    let v = Prepared::new(id, form, 1.0, &ps, Affine::default(), true);
    let prepare = thread_cpu_time() - t;
    let mut rng = FastRng::new(7);
    let t = thread_cpu_time();
    for i in 0..EVALS {
        let a = i as f64 * 0.37;
        let r = 0.01 + (i % 17) as f64 * 0.2;
        let p = [r * a.cos(), r * a.sin(), 0.3 - (i % 5) as f64 * 0.2];
        std::hint::black_box(eval_prepared(&v, p, Acc::default(), false, &mut rng));
    }
    let eval = (thread_cpu_time() - t) / EVALS;
    (prepare > PREPARE_LIMIT || eval > EVAL_LIMIT)
        .then(|| format!("prepared in {prepare:?}, {eval:?} per evaluation"))
}

#[test]
fn extreme_parameters_never_hang_or_panic_a_variation() {
    fuzz(false);
}

#[test]
#[ignore = "minutes: run by benches/hardening.sh"]
fn extreme_parameters_never_hang_or_panic_a_variation_every_parameter() {
    fuzz(true);
}

fn fuzz(every: bool) {
    let current = Arc::new(Mutex::new((String::new(), Instant::now())));
    let done = Arc::new(AtomicBool::new(false));
    // A case that never ends cannot fail a test: name it and stop the process instead.
    let watchdog = {
        let (current, done) = (current.clone(), done.clone());
        std::thread::spawn(move || {
            while !done.load(Ordering::Relaxed) {
                std::thread::sleep(Duration::from_millis(200));
                let (case, since) = current.lock().unwrap().clone();
                if since.elapsed() > HUNG {
                    eprintln!("{case}: still evaluating after {HUNG:?}");
                    std::process::abort();
                }
            }
        })
    };
    let start = Instant::now();
    let mut failures = Vec::new();
    let mut cases = 0;
    let mut slowest = Vec::new();
    for id in 0..variations::count() as u16 {
        let d = variations::info(id);
        if d.has(flag::HIDDEN) {
            continue;
        }
        let began = Instant::now();
        let heavy = !every && {
            let t = thread_cpu_time();
            let _ = Prepared::new(id, Form::Regular, 1.0, &[], Affine::default(), true);
            thread_cpu_time() - t > HEAVY
        };
        let which = (0..d.params.len())
            .filter(|&i| !heavy || d.params[i].limited)
            .map(Some)
            .chain([None]);
        for w in which {
            for &value in if heavy {
                &HEAVY_VALUES[..]
            } else {
                &VALUES[..]
            } {
                let name = w.map_or("every parameter", |i| d.params[i].name);
                let case = format!("{}: {name} = {value:e}", d.name);
                *current.lock().unwrap() = (case.clone(), Instant::now());
                cases += 1;
                match catch_unwind(AssertUnwindSafe(|| run_case(id, w, value))) {
                    Ok(None) => {}
                    Ok(Some(slow)) => failures.push(format!("{case}: {slow}")),
                    Err(_) => failures.push(format!("{case}: panicked")),
                }
            }
        }
        slowest.push((d.name, began.elapsed()));
    }
    done.store(true, Ordering::Relaxed);
    watchdog.join().unwrap();
    println!(
        "{cases} cases over {} variations in {:.1} s",
        variations::count(),
        start.elapsed().as_secs_f64()
    );
    slowest.sort_by_key(|s| std::cmp::Reverse(s.1));
    for (name, t) in slowest.iter().take(5) {
        println!("  {name}: {:.1} s", t.as_secs_f64());
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// The case of the report: `nBlur_numEdges="1e308"` pinned the processor for good. The file is
/// read with a warning naming the parameter and the limit used, and renders at once.
#[test]
fn a_flame_with_a_huge_count_renders_with_a_warning() {
    let dir = super::common::temp_dir("hard-var-count");
    let f = dir.join("n.flame");
    std::fs::write(
        &f,
        "<flame name=\"n\" size=\"32 24\" scale=\"8\" quality=\"2\">\
         <xform weight=\"1\" nBlur=\"1\" nBlur_numEdges=\"1e308\" nBlur_numStripes=\"-1e9\" \
         coefs=\"0.5 0 0 0.5 0 0\"/>\
         <xform weight=\"1\" linear=\"1\" coefs=\"0.5 0 0 0.5 1 0\"/></flame>",
    )
    .unwrap();
    let out = dir.join("n.png");
    let t = Instant::now();
    let (code, _, err) = super::ugnis(&["render", super::s(&f), "-o", super::s(&out)]);
    assert_eq!(code, 0, "{err}");
    assert!(t.elapsed() < Duration::from_secs(30), "{:?}", t.elapsed());
    assert!(
        err.contains("nBlur_numEdges=\"1e308\"") && err.contains("1000 is used"),
        "{err}"
    );
    assert!(
        err.contains("nBlur_numStripes=\"-1e9\"") && err.contains("-1000 is used"),
        "{err}"
    );
    assert!(out.exists());
    std::fs::remove_dir_all(&dir).unwrap();
}
