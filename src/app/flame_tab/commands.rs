//! The flame tab's commands: random flames and batches, weights, undo, export, save, paste,
//! and its windows (export settings, mutations, gradients, palette editor).

use std::path::Path;

use eframe::egui;

use super::export::{self, ExportJob, ExportSettings, JobAction, ResumeInfo};
use super::gradients::GradientAction;
use super::{FlameRequest, FlameTab, pick};
use crate::app::options::Options;
use crate::app::worker::task_worker;
use crate::flame::random::{self, VariationMode};
use crate::flame::rng::FastRng;
use crate::flame::variations::VarId;
use crate::flame::{Flame, NewFlame};
use crate::gradient::Gradient;
use crate::io;

impl FlameTab {
    /// Whether triangle edits re-derive the weights from the triangle areas.
    pub fn auto_weights(&self, options: &Options) -> bool {
        self.doc()
            .flame()
            .auto_weights
            .unwrap_or(options.auto_weights)
    }

    /// Settings of new random flames: the Options defaults, with the current gradient (used
    /// when "random gradient" is off).
    fn random_defaults(&self, options: &Options) -> NewFlame {
        let mut d = options.new_flame();
        d.gradient = self.doc().flame().palette.clone();
        d
    }

    /// The Tools › Variations choice: None is "Random" (one of the seven per transform).
    pub fn set_variation(&mut self, options: &Options, v: Option<VarId>, label: &str) {
        match v {
            None => self.variation_mode = VariationMode::Random(options.probabilities),
            Some(id) => {
                self.variation_mode = VariationMode::Single(id);
                self.doc_mut().edit(|f| {
                    for x in &mut f.xforms {
                        x.vars = vec![crate::flame::Var::new(id, 1.0)];
                    }
                });
            }
        }
        self.notices.status(format!("Variation: {label}"));
    }

    /// Replace the current flame by a random one (undoable).
    pub fn random_flame(&mut self, options: &Options) {
        let seed = self.rng.u64();
        let opts = options.random_options(self.variation_mode.clone());
        let mut g = random::generate(seed, &opts, &self.random_defaults(options)).flame;
        g.name = format!("random-{:08x}", seed as u32);
        let doc = self.doc_mut();
        let cur = doc.current;
        doc.edit_document(|fl, c| {
            fl[cur] = g;
            *c = cur;
        });
        self.edit_started();
        self.notices.status(format!("Random flame (seed {seed})"));
    }

    /// Whether a random batch is being generated.
    pub fn batch_running(&self) -> bool {
        self.batch_job.as_ref().is_some_and(|w| w.is_busy())
    }

    /// Generate a batch of 100 random flames in the background (nothing if one is running).
    pub fn start_batch(&mut self, options: &Options) {
        if self.batch_running() {
            return;
        }
        let seed = self.rng.u64();
        let opts = options.random_options(self.variation_mode.clone());
        let defaults = self.random_defaults(options);
        let w = task_worker("ugnis-batch", self.repaint());
        w.submit(Box::new(move |_, _| {
            random::generate_batch(100, seed, &opts, &defaults)
        }));
        self.batch_job = Some(w);
        self.notices.status("Generating a random batch…");
    }

    /// Give the xforms random weights summing to 1 (automatic weights off).
    pub fn random_weights(&mut self) {
        let mut rng = FastRng::new(self.rng.u64());
        self.doc_mut().edit(|f| {
            let mut w: Vec<f64> = f.xforms.iter().map(|_| rng.f01()).collect();
            let s: f64 = w.iter().sum();
            if s < 0.001 {
                f.set_equal_weights();
            } else {
                w.iter_mut().for_each(|v| *v /= s);
                for (x, v) in f.xforms.iter_mut().zip(w) {
                    x.weight = v;
                }
            }
            f.auto_weights = Some(false);
        });
    }

    /// Give the xforms equal weights (automatic weights off).
    pub fn equal_weights(&mut self) {
        self.doc_mut().edit(|f| {
            f.set_equal_weights();
            f.auto_weights = Some(false);
        });
    }

    /// Weight the xforms by the determinant rule (the areas of their triangles).
    pub fn area_weights(&mut self) {
        self.doc_mut().edit(|f| f.set_determinant_weights());
    }

    /// Undo the last edit of the document shown.
    pub fn undo(&mut self) {
        if !self.doc_mut().undo() {
            self.notices.status("Nothing to undo");
        }
    }

    /// Redo the last edit undone.
    pub fn redo(&mut self) {
        if !self.doc_mut().redo() {
            self.notices.status("Nothing to redo");
        }
    }

    /// Where exports of the current flame go first, and the name they start from: the folder
    /// of the last export or of the file, and the flame's name as a file name.
    pub(super) fn export_place(&self) -> (std::path::PathBuf, String) {
        let f = self.doc().flame();
        let dir = self.last_export_dir.clone().or_else(|| {
            self.doc()
                .path
                .as_ref()
                .and_then(|p| p.parent().map(Path::to_path_buf))
        });
        let name = if f.name.is_empty() {
            "flame".to_string()
        } else {
            io::ifs::entry_name(&f.name)
        };
        (dir.unwrap_or_default(), name)
    }

    /// Open the export dialog for the current flame.
    pub fn open_export_dialog(&mut self, options: &Options) {
        if self.export_job.is_some() {
            self.notices
                .status("An export is running: stop it before starting another");
            return;
        }
        let f = self.doc().flame();
        let (dir, name) = self.export_place();
        self.export_dialog = Some(ExportSettings {
            width: f.width,
            height: f.height,
            quality: f.quality.max(options.main_quality),
            supersample: f.supersample,
            bits16: false,
            transparent: false,
            path: dir.join(format!("{name}.png")),
            lock_aspect: true,
            refine: false,
            save_state: false,
            resume: None,
            memory_limit: None,
        });
    }

    /// Open the export dialog to continue the render state saved in `path`; a file that is
    /// not a state this ugnis reads is told in a message box naming it.
    pub fn open_resume_dialog(&mut self, path: &Path) {
        if self.export_job.is_some() {
            self.notices
                .status("An export is running: stop it before starting another");
            return;
        }
        match ResumeInfo::open(path) {
            Ok(info) => {
                self.export_dialog = Some(ExportSettings {
                    width: info.width,
                    height: info.height,
                    quality: info.quality,
                    supersample: info.supersample,
                    bits16: false,
                    transparent: false,
                    path: path.with_extension("png"),
                    lock_aspect: true,
                    refine: true,
                    save_state: true,
                    resume: Some(info),
                    memory_limit: None,
                });
            }
            Err(e) => self.notices.message("Cannot resume the render state", e),
        }
    }

    /// Save the open file (atomically). Returns true on success.
    pub fn save_to(&mut self, path: &Path) -> bool {
        let d = &self.file;
        match io::write_flames(path, &d.name, &d.flames) {
            Ok(w) => {
                self.file.path = Some(path.to_path_buf());
                self.file.dirty = false;
                self.notices.status(format!("Saved {}", path.display()));
                if !w.is_empty() {
                    self.notices.message("Saved with losses", w.join("\n"));
                }
                true
            }
            Err(e) => {
                self.notices.message("Cannot save", e.to_string());
                false
            }
        }
    }

    /// Give the current flame gradient `g` (undoable).
    pub fn apply_gradient(&mut self, g: Gradient) {
        self.doc_mut().edit(|f| f.palette = g);
    }

    /// Add the flames of pasted XML to the document.
    pub fn paste(&mut self, text: &str) {
        match io::flam3_xml::read(text, &Default::default()) {
            Ok(p) => {
                let mut new: Vec<Flame> = p.value.flames;
                new.iter_mut()
                    .for_each(crate::app::loading::keep_file_weights);
                let n = new.len();
                self.doc_mut().edit_document(|fl, cur| {
                    fl.extend(new);
                    *cur = fl.len() - 1;
                });
                self.notices.status(format!("Pasted {n} flame(s)"));
            }
            Err(e) => self
                .notices
                .status(format!("Clipboard holds no flame: {e}")),
        }
    }

    /// Collect what the background jobs finished.
    fn poll_jobs(&mut self) {
        if let Some(j) = &mut self.export_job {
            match j.poll() {
                Some(Ok(done)) => {
                    let mut text = format!(
                        "Exported {} at quality {} ({} samples)",
                        j.path.display(),
                        export::quality_text(done.quality_done),
                        done.samples_done
                    );
                    if let Some(sp) = &done.state {
                        text.push_str(&format!("; render state in {}", sp.display()));
                    }
                    self.export_job = None;
                    if let Some(limit) = done.limit {
                        self.notices
                            .message("Refining ended", format!("{text}.\n\nThe {limit}."));
                    }
                    self.notices.status(text);
                }
                Some(Err(e)) => {
                    self.export_job = None;
                    self.notices.status(e);
                }
                None => {}
            }
        }
        let done = self.batch_job.as_ref().and_then(|w| w.poll().pop());
        if let Some(flames) = done {
            self.batch_job = None;
            let path = self.data_dir.as_ref().map(|d| d.join("last-batch.fla"));
            if let Some(p) = &path {
                let _ = std::fs::create_dir_all(p.parent().unwrap_or(Path::new(".")));
                if let Err(e) = io::write_flames(p, "last-batch", &flames) {
                    self.notices.status(e.to_string());
                }
            }
            self.show_files = true;
            self.set_batch(flames, path);
            self.notices.status("Random batch ready");
        }
    }

    /// The tab's windows: export settings, mutations, gradients. Returns a request for the
    /// shell.
    pub fn windows(&mut self, ctx: &egui::Context, options: &Options) -> Option<FlameRequest> {
        let mut req = None;
        self.poll_jobs();
        if let Some(j) = &self.export_job {
            let mut act = None;
            // Anchored at its top centre with a fixed width: the buttons stay where they are
            // while the numbers change.
            let r0 = ctx.content_rect();
            egui::Window::new("Export image")
                .id(egui::Id::unique("export-running"))
                .collapsible(false)
                .resizable(false)
                .pivot(egui::Align2::CENTER_TOP)
                .default_pos([r0.center().x, r0.top() + 80.0])
                .min_width(440.0)
                .max_width(440.0)
                .show(ctx, |ui| act = export::job_window(ui, j));
            match act {
                Some(JobAction::SaveNow) => j.save_now(),
                Some(JobAction::Stop) => j.stop(),
                Some(JobAction::Cancel) => j.cancel(),
                None => {}
            }
            // The numbers move without events from the render thread.
            ctx.request_repaint_after(std::time::Duration::from_millis(200));
        }
        if let Some(s) = &mut self.export_dialog {
            let mut browse = false;
            let mut r = None;
            egui::Window::new("Export image")
                .collapsible(false)
                .pivot(egui::Align2::CENTER_CENTER)
                .default_pos(ctx.content_rect().center())
                .show(ctx, |ui| {
                    r = export::dialog(ui, s, &mut browse);
                });
            if browse {
                req = Some(FlameRequest::ChooseExportFile);
            }
            match r {
                Some(true) => {
                    let s = s.clone();
                    self.last_export_dir = s.path.parent().map(Path::to_path_buf);
                    let f = self.doc().flame().clone();
                    match ExportJob::start(&f, &s, options.threads, self.repaint()) {
                        Ok(j) => {
                            self.export_job = Some(j);
                            self.export_dialog = None;
                        }
                        Err(e) => self.notices.message("Cannot export", e),
                    }
                }
                Some(false) => self.export_dialog = None,
                None => {}
            }
        }
        let opts = options.random_options(self.variation_mode.clone());
        let centre = self.doc().flame().clone();
        if let Some(m) = self
            .mutations
            .show(ctx, &centre, &opts, self.preview.is_some())
        {
            self.doc_mut().edit(|f| *f = m);
            let f = self.doc().flame().clone();
            self.editor.fix_selection(&f);
            self.editor.auto_zoom(&f);
            self.notices.status("Mutant chosen (Undo returns)");
        }
        let dragging = ctx.input(|i| i.pointer.any_down());
        let doc = pick(self.showing, &mut self.batch, &mut self.file);
        if let Some(a) = self
            .gradients
            .show(ctx, doc, &mut self.palette_editor, dragging)
        {
            match a {
                GradientAction::Apply(g) => self.apply_gradient(g),
                GradientAction::Load => req = Some(FlameRequest::LoadGradient),
                GradientAction::FromImage => req = Some(FlameRequest::GradientFromImage),
            }
        }
        self.history_window(ctx);
        self.loop_window(ctx);
        if self.sound_window(ctx) == Some(super::timeline::SoundAsk::Browse) {
            req = Some(FlameRequest::ChooseSoundFile);
        }
        if let Some(r) = self.anim_windows(ctx, options) {
            req = Some(r);
        }
        req
    }
}

/// File › New: three half-size linear transforms (a Sierpinski triangle) with the Options'
/// size, quality and gradient, so that the new flame shows a picture at once.
pub fn new_flame(options: &Options) -> Flame {
    let mut f = options.new_flame().flame();
    f.name = "untitled".into();
    for (k, (e, y)) in [(0.0, 0.0), (0.5, 0.0), (0.25, 0.5)]
        .into_iter()
        .enumerate()
    {
        f.xforms.push(crate::flame::Xform::linear(
            crate::flame::Affine::new(0.5, 0.0, 0.0, 0.5, e, y),
            1.0,
            k as f64 / 2.0,
        ));
    }
    f.set_determinant_weights();
    crate::flame::framing::apply_auto_frame(&mut f);
    f
}
