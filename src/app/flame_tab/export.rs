//! Export image: size, quality, PNG/BMP; rendered in the background with progress, Stop and
//! Cancel. The render can keep refining past the asked quality until it is stopped, write the
//! picture whenever asked ("Save now"), save its render state beside the picture, and
//! continue a saved render state.
//!
//! Stop takes effect between passes (about a quarter of a second each), so the render is
//! whole and its state can be saved; Cancel stops at once and writes nothing. Every write is
//! atomic, so a file saved before is never lost.

use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Mutex};
use std::time::Instant;

use eframe::egui;

use crate::app::a11y::named;
use crate::app::worker::{TaskWorker, task_worker};
use crate::flame::render::{
    MAX_QUALITY, MIN_QUALITY, Plan, RenderOptions, Renderer, quality_limit, quality_of_samples,
    short_num,
};
use crate::flame::strips;
use crate::flame::{Flame, OutputFormat};
use crate::io;
use crate::io::render_state::StateReader;

/// The extension of render state files.
pub const STATE_EXTENSION: &str = "ugnis-state";

/// Where the render state of an exported picture is saved: beside it, `NAME.ugnis-state`.
pub fn state_path(image: &Path) -> PathBuf {
    image.with_extension(STATE_EXTENSION)
}

/// A saved render state to continue, as its file describes it.
#[derive(Clone, Debug, PartialEq)]
pub struct ResumeInfo {
    pub path: PathBuf,
    /// The flame's name (may be empty).
    pub name: String,
    pub width: u32,
    pub height: u32,
    pub supersample: u32,
    /// The quality the saved render was heading for.
    pub quality: f64,
    /// The quality its samples amount to.
    pub quality_done: f64,
    pub samples_done: u64,
}

impl ResumeInfo {
    /// Read the description of a state file. Errors name the file (not a state, another
    /// version, truncated, or parts that must be merged first).
    pub fn open(path: &Path) -> Result<ResumeInfo, String> {
        let rd = StateReader::open(path).map_err(|e| e.to_string())?;
        let st = &rd.state;
        st.continuation()
            .map_err(|e| format!("{}: {e}", path.display()))?;
        let f = &st.flame;
        Ok(ResumeInfo {
            path: path.to_path_buf(),
            name: f.name.clone(),
            width: f.width,
            height: f.height,
            supersample: f.supersample,
            quality: f.quality,
            quality_done: quality_of_samples(f, st.samples_done),
            samples_done: st.samples_done,
        })
    }

    /// One line: file, flame, size and the quality done.
    pub fn summary(&self) -> String {
        let file = self
            .path
            .file_name()
            .map_or_else(String::new, |n| n.to_string_lossy().into_owned());
        let name = if self.name.is_empty() {
            "(unnamed)"
        } else {
            &self.name
        };
        format!(
            "{file}: '{name}', {}×{}, supersample {}, quality done {} of {} ({} samples)",
            self.width,
            self.height,
            self.supersample,
            quality_text(self.quality_done),
            quality_text(self.quality),
            self.samples_done
        )
    }
}

/// Settings of the export dialog.
#[derive(Clone, Debug, PartialEq)]
pub struct ExportSettings {
    pub width: u32,
    pub height: u32,
    /// Samples per pixel; when continuing a saved state, the samples per pixel to add.
    pub quality: f64,
    pub supersample: u32,
    pub bits16: bool,
    pub transparent: bool,
    pub path: PathBuf,
    /// Width and height keep the flame's proportions.
    pub lock_aspect: bool,
    /// After the quality is reached, go on adding passes until Stop.
    pub refine: bool,
    /// Also write the render state beside the picture ([`state_path`]).
    pub save_state: bool,
    /// Continue this saved state instead of rendering the flame.
    pub resume: Option<ResumeInfo>,
    /// Memory the render may use (`None`: what the system allows); larger exports are
    /// rendered in strips.
    pub memory_limit: Option<u64>,
}

impl ExportSettings {
    /// The state file written with the picture, if any.
    pub fn state_file(&self) -> Option<PathBuf> {
        self.save_state.then(|| state_path(&self.path))
    }
}

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
    let format = OutputFormat {
        bits16: s.bits16,
        transparent: s.transparent,
    };
    let mut r = match source {
        Source::Flame(f) => {
            let opts = RenderOptions {
                seed: f.seed.unwrap_or(1),
                threads,
                format,
                memory_limit: s.memory_limit,
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
                return run_strips(&f, &opts, &fit, s, control, cancel, progress);
            }
            Renderer::new(&f, &opts).map_err(|e| e.to_string())?
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
            r
        }
    };
    let asked = r.flame().quality;
    let limit = quality_limit(r.flame());
    let start = (Instant::now(), r.samples_done());
    let mut pass: u64 = 100_000;
    let mut limit_note = None;
    let report = |r: &Renderer| {
        let secs = start.0.elapsed().as_secs_f64();
        let done = r.quality_done();
        control.update(|st| {
            st.asked = asked;
            st.quality_done = done;
            st.samples_done = r.samples_done();
            st.samples_per_second = if secs > 0.0 {
                (r.samples_done() - start.1) as f64 / secs
            } else {
                0.0
            };
            st.refining = r.flame().quality > asked;
        });
        progress((done / asked.max(MIN_QUALITY)).min(1.0));
    };
    report(&r);
    loop {
        if control.stop.load(Ordering::SeqCst) {
            break;
        }
        if r.is_done() {
            if !s.refine {
                break;
            }
            let q = r.flame().quality;
            let add = step.min(limit - q);
            if add < MIN_QUALITY {
                limit_note = Some(format!(
                    "quality {} reached: the most a render of this size and zoom may have \
                     (at most {} samples per pixel, {:.0e} samples in all)",
                    short_num(q),
                    short_num(MAX_QUALITY),
                    crate::flame::render::MAX_TOTAL_SAMPLES
                ));
                break;
            }
            if let Err(e) = r.extend(add) {
                limit_note = Some(format!("refining ends: {e}"));
                break;
            }
        }
        let t = Instant::now();
        if !r.run(pass, cancel) {
            return Err("export cancelled (files saved before are kept)".into());
        }
        // Passes of about PASS_SECONDS, whatever the flame and the machine.
        let dt = t.elapsed().as_secs_f64().max(1e-3);
        pass = ((pass as f64) * (PASS_SECONDS / dt).clamp(0.25, 4.0)).clamp(1e4, 1e10) as u64;
        report(&r);
        if control.save_now.swap(false, Ordering::SeqCst) {
            let note = match write(&r, s) {
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
    write(&r, s)?;
    Ok(Finished {
        quality_done: r.quality_done(),
        samples_done: r.samples_done(),
        state: s.state_file(),
        limit: limit_note,
    })
}

/// An export larger than memory, band by band (see [`strips`]): every strip iterates the
/// whole render and keeps its band; the PNG is streamed, so neither the picture nor the whole
/// histogram is ever in memory. Written atomically when the last strip is done.
fn run_strips(
    f: &Flame,
    opts: &RenderOptions,
    fit: &strips::Fit,
    s: &ExportSettings,
    control: &Control,
    cancel: &AtomicBool,
    progress: &dyn Fn(f64),
) -> Result<Finished, String> {
    let cannot = |e: &dyn std::fmt::Display| format!("cannot write {}: {e}", s.path.display());
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
    let mut file = io::atomic::AtomicFile::create(&s.path).map_err(|e| cannot(&e))?;
    let out = file.file().try_clone().map_err(|e| cannot(&e))?;
    let mut png = io::png::PngStream::new(
        out,
        f.width,
        f.height,
        opts.format,
        &io::png::PngMeta::for_flame(f),
    )
    .map_err(|e| cannot(&e))?;
    let start = Instant::now();
    let mut samples = 0u64;
    control.update(|st| {
        st.asked = f.quality;
        st.strips = k;
        st.note = format!("{}: rendering in {k} strips", fit.describe());
    });
    for (i, strip) in plan.iter().enumerate() {
        let part = Plan {
            strip: Some(strip.clone()),
            ..Plan::default()
        };
        let mut r = Renderer::with_plan(f, opts, &part).map_err(|e| e.to_string())?;
        while !r.is_done() {
            if !r.run(1_000_000, cancel) {
                return Err("export cancelled (files saved before are kept)".into());
            }
            let done = (i as f64 + r.fraction()) / k as f64;
            let secs = start.elapsed().as_secs_f64().max(1e-3);
            let all = samples + r.samples_done();
            control.update(|st| {
                st.quality_done = f.quality * done;
                st.samples_done = all;
                st.samples_per_second = all as f64 / secs;
                st.note = format!("strip {} of {k}", i + 1);
            });
            progress(done);
        }
        samples += r.samples_done();
        png.write_rows(&r.finish()).map_err(|e| cannot(&e))?;
    }
    png.finish().map_err(|e| cannot(&e))?;
    file.commit().map_err(|e| cannot(&e))?;
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
        let (st, hist) = r
            .snapshot()
            .ok_or_else(|| "the render was cancelled; no state to save".to_string())?;
        io::render_state::save(&sp, &st, &hist)
            .map_err(|e| format!("cannot write {}: {e}", sp.display()))?;
    }
    Ok(())
}

/// A quality for people: whole numbers as they are, others with one decimal.
pub fn quality_text(q: f64) -> String {
    if (q - q.round()).abs() < 1e-9 {
        format!("{q:.0}")
    } else {
        format!("{q:.1}")
    }
}

/// Millions with one decimal, or the number itself below a million.
fn count(n: f64) -> String {
    if n >= 1e6 {
        format!("{:.1} M", n / 1e6)
    } else {
        format!("{n:.0}")
    }
}

/// The running export's window: what is done, Save now, Stop and Cancel.
pub fn job_window(ui: &mut egui::Ui, job: &ExportJob) -> Option<JobAction> {
    let st = job.status();
    let mut r = None;
    ui.set_width(440.0);
    ui.add(egui::Label::new(format!("Rendering {}", job.path.display())).truncate());
    if st.loading {
        ui.label("Reading the render state…");
    } else {
        let text = format!(
            "Quality reached: {} of {}",
            quality_text(st.quality_done),
            quality_text(st.asked)
        );
        if st.refining || st.quality_done >= st.asked {
            ui.label(format!("{text} — refining until stopped"));
        } else {
            ui.add(
                egui::ProgressBar::new((st.quality_done / st.asked.max(MIN_QUALITY)) as f32)
                    .desired_width(420.0)
                    .text(text),
            );
        }
        ui.label(format!(
            "Samples: {}, {} per second",
            count(st.samples_done as f64),
            count(st.samples_per_second)
        ));
    }
    // Always one line (empty until there is something to say), so the buttons stay put.
    ui.add(egui::Label::new(&st.note).truncate());
    ui.horizontal(|ui| {
        let whole = st.strips <= 1;
        if ui
            .add_enabled(whole && st.samples_done > 0, egui::Button::new("Save now"))
            .on_hover_text("write the picture of what is rendered so far and go on")
            .clicked()
        {
            r = Some(JobAction::SaveNow);
        }
        if ui
            .add_enabled(whole, egui::Button::new("Stop"))
            .on_hover_text("end after this pass and write the picture of what is rendered")
            .on_disabled_hover_text(
                "a render in strips writes its picture when the last strip is done",
            )
            .clicked()
        {
            r = Some(JobAction::Stop);
        }
        if ui
            .button("Cancel")
            .on_hover_text("end at once and write nothing (files saved before stay)")
            .clicked()
        {
            r = Some(JobAction::Cancel);
        }
    });
    r
}

/// The export settings dialog. Returns Some(true) to start, Some(false) to cancel; `browse`
/// is set when the user wants to choose the file.
pub fn dialog(ui: &mut egui::Ui, s: &mut ExportSettings, browse: &mut bool) -> Option<bool> {
    let mut r = None;
    if let Some(info) = &s.resume {
        ui.label(format!("Continue the render state {}", info.summary()));
    }
    let resuming = s.resume.is_some();
    egui::Grid::new("export-grid")
        .num_columns(2)
        .show(ui, |ui| {
            if !resuming {
                size_row(ui, s);
            }
            if resuming {
                let l = ui.label("Add quality");
                ui.add(
                    egui::DragValue::new(&mut s.quality)
                        .range(0.0..=MAX_QUALITY)
                        .speed(1.0),
                )
                .labelled_by(l.id)
                .on_hover_text("samples per pixel to add to the saved render (0: as it is)");
            } else {
                let l = ui.label("Quality");
                ui.add(
                    egui::DragValue::new(&mut s.quality)
                        .range(0.1..=100000.0)
                        .speed(1.0),
                )
                .labelled_by(l.id)
                .on_hover_text("samples per pixel (more: smoother, slower)");
            }
            ui.end_row();
            if !resuming {
                let l = ui.label("Supersample");
                ui.add(egui::DragValue::new(&mut s.supersample).range(1..=4))
                    .labelled_by(l.id)
                    .on_hover_text("render this many times larger and shrink (smoother edges)");
                ui.end_row();
            }
            ui.label("Refine");
            ui.checkbox(&mut s.refine, "keep refining until stopped")
                .on_hover_text(
                    "after the quality is reached, go on adding samples until Stop; \
                     Save now and Stop write the picture of what is rendered",
                );
            ui.end_row();
            ui.label("File");
            ui.horizontal(|ui| {
                let mut t = s.path.display().to_string();
                if named(ui.text_edit_singleline(&mut t), "Export file")
                    .on_hover_text("where the picture is written (.png or .bmp)")
                    .changed()
                {
                    s.path = PathBuf::from(t);
                }
                if ui
                    .button("Choose…")
                    .on_hover_text("choose the file")
                    .clicked()
                {
                    *browse = true;
                }
            });
            ui.end_row();
            ui.label("Render state");
            ui.checkbox(&mut s.save_state, "also save the render state")
                .on_hover_text(format!(
                    "write {} beside the picture, to continue the render later \
                     (File › Resume render state…)",
                    state_path(&s.path)
                        .file_name()
                        .map_or_else(String::new, |n| n.to_string_lossy().into_owned())
                ));
            ui.end_row();
            let png = !s
                .path
                .extension()
                .is_some_and(|e| e.eq_ignore_ascii_case("bmp"));
            ui.label("PNG options");
            ui.horizontal(|ui| {
                ui.add_enabled(png, egui::Checkbox::new(&mut s.bits16, "16 bits"));
                ui.add_enabled(png, egui::Checkbox::new(&mut s.transparent, "transparent"));
            });
            ui.end_row();
        });
    let ext_ok = s
        .path
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("png") || e.eq_ignore_ascii_case("bmp"));
    if !ext_ok {
        ui.colored_label(
            egui::Color32::from_rgb(230, 150, 80),
            "The file must end in .png or .bmp",
        );
    }
    ui.horizontal(|ui| {
        if ui
            .add_enabled(ext_ok, egui::Button::new("Render"))
            .clicked()
        {
            r = Some(true);
        }
        if ui.button("Cancel").clicked() {
            r = Some(false);
        }
    });
    r
}

/// The size row: width × height, optionally keeping the proportions.
fn size_row(ui: &mut egui::Ui, s: &mut ExportSettings) {
    ui.label("Size");
    ui.horizontal(|ui| {
        let aspect = s.width as f64 / s.height.max(1) as f64;
        let w = named(
            ui.add(egui::DragValue::new(&mut s.width).range(1..=30000)),
            "Export width",
        )
        .on_hover_text("width in pixels");
        ui.label("×");
        let h = named(
            ui.add(egui::DragValue::new(&mut s.height).range(1..=30000)),
            "Export height",
        )
        .on_hover_text("height in pixels");
        ui.checkbox(&mut s.lock_aspect, "keep proportions")
            .on_hover_text("changing one side changes the other");
        if s.lock_aspect {
            if w.changed() {
                s.height = ((s.width as f64 / aspect).round() as u32).clamp(1, 30000);
            } else if h.changed() {
                s.width = ((s.height as f64 * aspect).round() as u32).clamp(1, 30000);
            }
        }
    });
    ui.end_row();
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
