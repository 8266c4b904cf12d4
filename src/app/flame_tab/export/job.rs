//! The export job: a render on its own thread with progress, Save now, Stop and Cancel,
//! in one go or, larger than memory, in strips.

use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Mutex};
use std::time::Instant;

use super::resume::quality_text;
use super::settings::ExportSettings;
use crate::app::worker::{TaskWorker, task_worker};
use crate::flame::render::{
    MAX_QUALITY, MIN_QUALITY, Plan, RenderOptions, Renderer, quality_limit, short_num,
};
use crate::flame::strips;
use crate::flame::{Flame, OutputFormat};
use crate::io;
use crate::io::render_state::StateReader;

/// What a running export has done, for the window and the tests.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct JobStatus {
    /// The histogram of a saved state is being read.
    pub loading: bool,
    /// The quality asked for (with a resumed state: its quality plus the added quality).
    pub asked: f64,
    /// The quality the samples done amount to.
    pub quality_done: f64,
    pub samples_done: u64,
    pub samples_per_second: f64,
    /// The asked quality is reached and the render goes on.
    pub refining: bool,
    /// Pictures written by "Save now".
    pub saves: u32,
    /// The last thing worth telling: a save, a failed save.
    pub note: String,
    /// Rendered in this many strips (0 or 1: the whole image at once); the picture is written
    /// when the last one is done.
    pub strips: usize,
}

/// How a finished export ended.
#[derive(Clone, Debug, PartialEq)]
pub struct Finished {
    pub quality_done: f64,
    pub samples_done: u64,
    /// The state file written, if any.
    pub state: Option<PathBuf>,
    /// Why refining ended by itself (the quality limit), if it did.
    pub limit: Option<String>,
}

/// What the running export's window asks for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum JobAction {
    SaveNow,
    Stop,
    Cancel,
}

/// Flags and status shared by the window and the render thread.
#[derive(Default)]
struct Control {
    stop: AtomicBool,
    save_now: AtomicBool,
    status: Mutex<JobStatus>,
}

impl Control {
    fn update(&self, f: impl FnOnce(&mut JobStatus)) {
        if let Ok(mut s) = self.status.lock() {
            f(&mut s);
        }
    }
}

/// Where the samples come from.
enum Source {
    Flame(Box<Flame>),
    /// A saved state and the quality to add.
    State(PathBuf, f64),
}

/// A running export, with progress, Save now, Stop and Cancel.
pub struct ExportJob {
    pub path: PathBuf,
    pub refine: bool,
    worker: TaskWorker<Result<Finished, String>>,
    control: Arc<Control>,
}

/// Seconds one pass should take: Stop and Save now wait at most this long.
const PASS_SECONDS: f64 = 0.25;

impl ExportJob {
    /// Start rendering `flame` (or continuing the state of `s.resume`) as `s` says. Fails
    /// before any work when a file cannot be written there or the state cannot be saved.
    pub fn start(
        flame: &Flame,
        s: &ExportSettings,
        threads: usize,
        repaint: impl Fn() + Send + 'static,
    ) -> Result<ExportJob, String> {
        let cannot = |p: &Path, e: std::io::Error| format!("cannot write {}: {e}", p.display());
        io::atomic::check_writable(&s.path).map_err(|e| cannot(&s.path, e))?;
        if let Some(sp) = s.state_file() {
            io::atomic::check_writable(&sp).map_err(|e| cannot(&sp, e))?;
        }
        let source = match &s.resume {
            Some(info) => Source::State(info.path.clone(), s.quality.max(0.0)),
            None => {
                if s.save_state && flame.ifs3d.is_some() {
                    return Err("a render state of a 3-D IFS cannot be saved (its maps have no flame XML form); export it without the state".into());
                }
                let mut f = flame.clone();
                f.resize_keep_framing(s.width, s.height);
                f.quality = s.quality;
                f.supersample = s.supersample.max(1);
                Source::Flame(Box::new(f))
            }
        };
        // Each round of refining adds the quality of the first one.
        let step = match &s.resume {
            Some(info) => info.quality.max(s.quality),
            None => s.quality,
        }
        .max(MIN_QUALITY);
        let settings = s.clone();
        let control = Arc::new(Control::default());
        let c = control.clone();
        let worker = task_worker("ugnis-export", repaint);
        worker.submit(Box::new(move |cancel, progress| {
            run(source, &settings, step, threads, &c, cancel, progress)
        }));
        Ok(ExportJob {
            path: s.path.clone(),
            refine: s.refine,
            worker,
            control,
        })
    }

    pub fn fraction(&self) -> f64 {
        self.worker.progress()
    }

    /// What the render has done so far.
    pub fn status(&self) -> JobStatus {
        self.control
            .status
            .lock()
            .map(|s| s.clone())
            .unwrap_or_default()
    }

    /// Write the picture (and state) of what is accumulated, after the current pass.
    pub fn save_now(&self) {
        self.control.save_now.store(true, Ordering::SeqCst);
    }

    /// End after the current pass and write the picture (and state) of what is accumulated.
    pub fn stop(&self) {
        self.control.stop.store(true, Ordering::SeqCst);
    }

    /// Stop at once, writing nothing (files written before stay as they are).
    pub fn cancel(&self) {
        self.worker.cancel();
    }

    /// The result once the job has finished.
    pub fn poll(&mut self) -> Option<Result<Finished, String>> {
        self.worker.poll().pop()
    }
}

/// The render thread: passes until the asked quality is reached (or, refining, until Stop or
/// the quality limit), writing on "Save now" and at the end.
fn run(
    source: Source,
    s: &ExportSettings,
    step: f64,
    threads: usize,
    control: &Control,
    cancel: &AtomicBool,
    progress: &dyn Fn(f64),
) -> Result<Finished, String> {
    let mut r = match start(source, s, threads, control)? {
        Started::Whole(r) => *r,
        Started::Strips(f, opts, fit) => {
            return run_strips(&f, &opts, &fit, s, control, cancel, progress);
        }
    };
    let asked = r.flame().quality;
    let clock = (Instant::now(), r.samples_done());
    let report = |r: &Renderer| {
        let secs = clock.0.elapsed().as_secs_f64();
        let done = r.quality_done();
        control.update(|st| {
            st.asked = asked;
            st.quality_done = done;
            st.samples_done = r.samples_done();
            st.samples_per_second = if secs > 0.0 {
                (r.samples_done() - clock.1) as f64 / secs
            } else {
                0.0
            };
            st.refining = r.flame().quality > asked;
        });
        progress((done / asked.max(MIN_QUALITY)).min(1.0));
    };
    report(&r);
    let limit_note = run_passes(&mut r, s, step, control, cancel, &report)?;
    write(&r, s)?;
    Ok(Finished {
        quality_done: r.quality_done(),
        samples_done: r.samples_done(),
        state: s.state_file(),
        limit: limit_note,
    })
}

/// How an export starts: a renderer for the whole picture, or a flame too large for memory
/// that is rendered in strips.
enum Started {
    Whole(Box<Renderer>),
    Strips(Box<Flame>, RenderOptions, strips::Fit),
}

/// The renderer of the export: a fresh render of the flame (or its strips, when it does not
/// fit in memory) or the continued saved state.
fn start(
    source: Source,
    s: &ExportSettings,
    threads: usize,
    control: &Control,
) -> Result<Started, String> {
    let format = OutputFormat {
        bits16: s.bits16,
        transparent: s.transparent,
    };
    match source {
        Source::Flame(f) => {
            let opts = RenderOptions {
                seed: f.seed.unwrap_or(1),
                threads,
                format,
                memory_limit: s.memory_limit,
                save_state: s.save_state,
                ..RenderOptions::default()
            };
            let fit = strips::fit(&f, &opts).map_err(|e| e.to_string())?;
            if fit.strips > 1 {
                if s.refine || s.save_state {
                    return Err(format!(
                        "this export {}: it can only be rendered in {} strips, which cannot \
                         keep refining or save a render state; turn those off, or make the \
                         picture smaller",
                        fit.describe(),
                        fit.strips
                    ));
                }
                return Ok(Started::Strips(f, fit.options(&opts), fit));
            }
            Ok(Started::Whole(Box::new(
                Renderer::new(&f, &opts).map_err(|e| e.to_string())?,
            )))
        }
        Source::State(path, add) => {
            control.update(|st| st.loading = true);
            let mut rd = StateReader::open(&path).map_err(|e| e.to_string())?;
            let opts = RenderOptions {
                seed: rd.state.seed,
                threads,
                format,
                ..RenderOptions::default()
            };
            let r = rd.renderer(add, &opts, None)?;
            control.update(|st| st.loading = false);
            Ok(Started::Whole(Box::new(r)))
        }
    }
}

/// Run passes of about [`PASS_SECONDS`] until the asked quality is reached, or, refining,
/// until Stop or the quality limit (whose reason is returned); `report` after every pass,
/// the picture written on "Save now".
fn run_passes(
    r: &mut Renderer,
    s: &ExportSettings,
    step: f64,
    control: &Control,
    cancel: &AtomicBool,
    report: &dyn Fn(&Renderer),
) -> Result<Option<String>, String> {
    let limit = quality_limit(r.flame());
    let mut pass: u64 = 100_000;
    loop {
        if control.stop.load(Ordering::SeqCst) {
            return Ok(None);
        }
        if r.is_done() {
            if !s.refine {
                return Ok(None);
            }
            let q = r.flame().quality;
            let add = step.min(limit - q);
            if add < MIN_QUALITY {
                return Ok(Some(format!(
                    "quality {} reached: the most a render of this size and zoom may have \
                     (at most {} samples per pixel, {:.0e} samples in all)",
                    short_num(q),
                    short_num(MAX_QUALITY),
                    crate::flame::render::MAX_TOTAL_SAMPLES
                )));
            }
            if let Err(e) = r.extend(add) {
                return Ok(Some(format!("refining ends: {e}")));
            }
        }
        let t = Instant::now();
        if !r.run(pass, cancel) {
            return Err(CANCELLED.into());
        }
        // Passes of about PASS_SECONDS, whatever the flame and the machine.
        let dt = t.elapsed().as_secs_f64().max(1e-3);
        pass = ((pass as f64) * (PASS_SECONDS / dt).clamp(0.25, 4.0)).clamp(1e4, 1e10) as u64;
        report(r);
        if control.save_now.swap(false, Ordering::SeqCst) {
            let note = match write(r, s) {
                Ok(()) => {
                    control.update(|st| st.saves += 1);
                    format!(
                        "saved at quality {} ({})",
                        quality_text(r.quality_done()),
                        s.path.display()
                    )
                }
                Err(e) => e,
            };
            control.update(|st| st.note = note);
        }
    }
}

/// What a cancelled export says.
const CANCELLED: &str = "export cancelled (files saved before are kept)";

/// An export larger than memory, band by band (see [`strips`] and [`io::strip_png`]): every
/// strip iterates the whole render and keeps its band; the PNG is streamed, so neither the
/// picture nor the whole histogram is ever in memory. Written atomically when the last strip
/// is done.
fn run_strips(
    f: &Flame,
    opts: &RenderOptions,
    fit: &strips::Fit,
    s: &ExportSettings,
    control: &Control,
    cancel: &AtomicBool,
    progress: &dyn Fn(f64),
) -> Result<Finished, String> {
    use io::strip_png::{StripError, StripFiles, StripHooks, StripProgress, render_strips};
    let message = |e: StripError| match e {
        StripError::Write { source, .. } => {
            format!("cannot write {}: {source}", s.path.display())
        }
        StripError::Cancelled => CANCELLED.into(),
        e => e.to_string(),
    };
    if io::kind_of(&s.path) != io::FileKind::Png {
        return Err(format!(
            "this export {}: it must be rendered in {} strips, which writes PNG only (a BMP \
             needs the whole picture in memory)",
            fit.describe(),
            fit.strips
        ));
    }
    let k = fit.strips;
    let plan = strips::plan(f, k).map_err(|e| e.to_string())?;
    let files = StripFiles::new()
        .with_png(
            &s.path,
            (f.width, f.height),
            opts.format,
            &io::png::PngMeta::for_flame(f),
        )
        .map_err(message)?;
    let start = Instant::now();
    control.update(|st| {
        st.asked = f.quality;
        st.strips = k;
        st.note = format!("{}: rendering in {k} strips", fit.describe());
    });
    let mut report = |p: &StripProgress| {
        let done = p.fraction();
        let secs = start.elapsed().as_secs_f64().max(1e-3);
        control.update(|st| {
            st.quality_done = f.quality * done;
            st.samples_done = p.samples_done;
            st.samples_per_second = p.samples_done as f64 / secs;
            st.note = format!("strip {} of {k}", p.strip + 1);
        });
        progress(done);
    };
    let renderer = |strip: &strips::Strip| {
        let part = Plan {
            strip: Some(strip.clone()),
            ..Plan::default()
        };
        Renderer::with_plan(f, opts, &part).map_err(|e| StripError::Render(e.to_string()))
    };
    let hooks = StripHooks {
        cancel,
        pass: Some(1_000_000),
        progress: &mut report,
    };
    let samples = render_strips(&plan, files, renderer, hooks).map_err(message)?;
    Ok(Finished {
        quality_done: f.quality,
        samples_done: samples,
        state: None,
        limit: None,
    })
}

/// Write the picture of what is accumulated (exposed for the samples actually done) and, if
/// asked, the render state; both atomically.
fn write(r: &Renderer, s: &ExportSettings) -> Result<(), String> {
    if r.samples_done() == 0 {
        return Err("nothing is rendered yet".into());
    }
    let img = r.preview();
    // The embedded flame says the quality the picture has.
    let mut flame = r.flame().clone();
    if !r.is_done() {
        flame.quality = r.quality_done().max(MIN_QUALITY);
    }
    let rate = r.bad_values() as f64 / r.samples_done().max(1) as f64;
    io::save_flame_image(&s.path, &img, &flame, r.samples_done(), Some(rate))
        .map_err(|e| format!("cannot write {}: {e}", s.path.display()))?;
    if let Some(sp) = s.state_file() {
        let (st, hist) = r.snapshot().ok_or_else(|| {
            if r.flame().draws_solid() {
                "the picture is saved, but a flame JWildfire draws solid keeps no render state \
                 (its depth buffers are kept in memory only)"
                    .to_string()
            } else {
                "the render was cancelled; no state to save".to_string()
            }
        })?;
        io::render_state::save(&sp, &st, &hist)
            .map_err(|e| format!("cannot write {}: {e}", sp.display()))?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn settings(path: PathBuf, memory_limit: Option<u64>) -> ExportSettings {
        ExportSettings {
            width: 64,
            height: 48,
            quality: 10.0,
            supersample: 1,
            bits16: false,
            transparent: false,
            path,
            lock_aspect: true,
            refine: false,
            save_state: false,
            resume: None,
            memory_limit,
        }
    }

    /// An export that does not fit in its memory is rendered in strips, and its pixels are
    /// those of the export made at once; refining, a saved state or a BMP are refused then.
    #[test]
    fn an_export_larger_than_memory_is_rendered_in_strips_with_the_same_pixels() {
        let mut f = crate::io::read_flames(
            Path::new(concat!(
                env!("CARGO_MANIFEST_DIR"),
                "/examples/sierpinski.flame"
            )),
            &Default::default(),
        )
        .unwrap()
        .value
        .remove(0);
        f.resize_keep_framing(64, 48);
        f.quality = 10.0;
        let dir = std::env::temp_dir().join(format!("ugnis-export-strips-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let never = AtomicBool::new(false);
        let export = |s: &ExportSettings, c: &Control| {
            run(
                Source::Flame(Box::new(f.clone())),
                s,
                10.0,
                2,
                c,
                &never,
                &|_| {},
            )
        };
        let whole = settings(dir.join("whole.png"), None);
        export(&whole, &Control::default()).unwrap();
        let opts = RenderOptions {
            threads: 2,
            ..RenderOptions::default()
        };
        let need = crate::flame::render::estimate_memory(&f, &opts).total;
        let banded = settings(dir.join("strips.png"), Some(need - 1));
        let c = Control::default();
        let done = export(&banded, &c).unwrap();
        let st = c.status.lock().unwrap().clone();
        assert!(st.strips > 1, "{st:?}");
        assert!(done.samples_done >= 10 * 64 * 48, "{done:?}");
        let (a, b) = (
            image::open(&whole.path).unwrap().to_rgb8(),
            image::open(&banded.path).unwrap().to_rgb8(),
        );
        assert!(a.pixels().any(|p| p.0 != [0, 0, 0]));
        assert_eq!(a.as_raw(), b.as_raw());
        // The PNG carries its flame, as every export does.
        assert_eq!(
            crate::io::read_flames(&banded.path, &Default::default())
                .unwrap()
                .value
                .len(),
            1
        );
        for s in [
            ExportSettings {
                refine: true,
                ..banded.clone()
            },
            settings(dir.join("strips.bmp"), Some(need - 1)),
        ] {
            let e = export(&s, &Control::default()).unwrap_err();
            assert!(e.contains("strips"), "{e}");
            // One sentence, as the window shows it (no runs of spaces from the source's layout).
            assert!(!e.contains("  ") && !e.contains('\n'), "{e:?}");
        }
        assert!(!dir.join("strips.bmp").exists());
        let _ = std::fs::remove_dir_all(&dir);
    }
}
