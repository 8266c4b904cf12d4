//! The left panel of the flame tab: the open file's flames and the last random batch, each with
//! a thumbnail; a click edits a flame, Keep copies a batch flame into the file.

use eframe::egui::{self, Vec2};

use super::FlameTab;
use super::thumbnails::Slot;

/// Thumbnail lists.
const FILE_LIST: u8 = 0;
const BATCH_LIST: u8 = 1;

impl FlameTab {
    fn thumbnail(&mut self, slot: Slot) -> Option<egui::TextureId> {
        let doc = if slot.0 == FILE_LIST {
            &self.file
        } else {
            self.batch.as_ref()?
        };
        let f = doc.flames.get(slot.1)?;
        self.thumbs.get(slot, f)
    }

    pub(super) fn file_panel(&mut self, ui: &mut egui::Ui) {
        let file = &self.file;
        let (name, n, dirty) = (file.name.clone(), file.flames.len(), file.dirty);
        ui.heading(format!("{name}{}", if dirty { " *" } else { "" }));
        ui.label(format!("{n} flame(s)"));
        ui.separator();
        let mut select = None;
        let batch_len = self.batch.as_ref().map_or(0, |b| b.flames.len());
        let list_height = if batch_len > 0 {
            (ui.available_height() * 0.35).max(80.0)
        } else {
            f32::INFINITY
        };
        let current = (!self.viewing_batch()).then_some(self.file.current);
        egui::ScrollArea::vertical()
            .id_salt("file-flames")
            .max_height(list_height)
            .show(ui, |ui| {
                for i in 0..n {
                    let f = &self.file.flames[i];
                    let label = if f.name.is_empty() {
                        format!("flame {}", i + 1)
                    } else {
                        f.name.clone()
                    };
                    let tex = self.thumbnail((FILE_LIST, i));
                    ui.horizontal(|ui| {
                        let size = Vec2::new(64.0, 48.0);
                        let r = match tex {
                            Some(t) => {
                                ui.add(egui::Image::new((t, size)).sense(egui::Sense::click()))
                            }
                            None => ui.add(egui::Button::new("…").min_size(size)),
                        };
                        let l = ui.selectable_label(current == Some(i), label);
                        if r.clicked() || l.clicked() {
                            select = Some(i);
                        }
                    });
                }
            });
        self.thumbs.truncate(FILE_LIST, n);
        if let Some(i) = select {
            self.view_file();
            self.file.current = i;
            self.edit_started();
        }
        if batch_len == 0 {
            return;
        }
        ui.separator();
        ui.horizontal(|ui| {
            ui.strong(format!("Last random batch ({batch_len})"));
        });
        ui.label("Click to edit; Keep copies into the file.");
        // A grid of thumbnails; only the visible rows are drawn and asked for, so the
        // pictures in view render first.
        let cols = ((ui.available_width() / 86.0).floor() as usize).max(1);
        let rows = batch_len.div_ceil(cols);
        let row_h = 60.0 + 2.0 * ui.spacing().interact_size.y + 6.0;
        let mut open = None;
        let mut keep = None;
        let current = self
            .viewing_batch()
            .then(|| self.batch.as_ref().map(|b| b.current))
            .flatten();
        egui::ScrollArea::vertical()
            .id_salt("batch-grid")
            .show_rows(ui, row_h, rows, |ui, range| {
                for r in range {
                    ui.horizontal(|ui| {
                        for c in 0..cols {
                            let i = r * cols + c;
                            if i >= batch_len {
                                break;
                            }
                            let tex = self.thumbnail((BATCH_LIST, i));
                            let name = self
                                .batch
                                .as_ref()
                                .map(|b| b.flames[i].name.clone())
                                .unwrap_or_default();
                            ui.vertical(|ui| {
                                ui.set_width(80.0);
                                let size = Vec2::new(80.0, 60.0);
                                let r = match tex {
                                    Some(t) => ui.add(
                                        egui::Image::new((t, size)).sense(egui::Sense::click()),
                                    ),
                                    None => ui.add(egui::Button::new("…").min_size(size)),
                                };
                                let l = ui.selectable_label(current == Some(i), name);
                                if r.clicked() || l.clicked() {
                                    open = Some(i);
                                }
                                if ui
                                    .small_button("Keep")
                                    .on_hover_text("copy this flame into the open file")
                                    .clicked()
                                {
                                    keep = Some(i);
                                }
                            });
                        }
                    });
                }
            });
        if let Some(i) = open {
            self.view_batch(i);
        }
        if let Some(i) = keep {
            self.keep_from_batch(i);
        }
    }
}
