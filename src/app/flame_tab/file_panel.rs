//! The left panel of the flame tab: the open file's flames and the last random batch, each with
//! a thumbnail; a click edits a flame, Keep copies a batch flame into the file. Rows are one
//! line high (long names end in "…", the pointer shows them whole), the file's list gets the
//! room it needs up to two thirds of the panel, and the batch folds away.

use eframe::egui::{self, Vec2};

use super::FlameTab;
use super::thumbnails::Slot;

/// Size of a file flame's thumbnail.
const FILE_THUMB: Vec2 = Vec2::new(48.0, 36.0);

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
        ui.add(
            egui::Label::new(
                egui::RichText::new(format!("{name}{}", if dirty { " *" } else { "" })).heading(),
            )
            .truncate(),
        )
        .on_hover_text(
            self.file
                .path
                .as_ref()
                .map_or(name.clone(), |p| p.display().to_string()),
        );
        ui.label(format!("{n} flame(s)"));
        ui.separator();
        let mut select = None;
        let batch_len = self.batch.as_ref().map_or(0, |b| b.flames.len());
        let row_h = FILE_THUMB.y + ui.spacing().item_spacing.y;
        let list_height = if batch_len > 0 && self.batch_shown {
            (n as f32 * row_h)
                .min(ui.available_height() * 0.66)
                .max(row_h)
        } else {
            f32::INFINITY
        };
        let current = (!self.viewing_batch()).then_some(self.file.current);
        egui::ScrollArea::vertical()
            .id_salt("file-flames")
            .max_height(list_height)
            .auto_shrink([false, true])
            .show_rows(ui, FILE_THUMB.y, n, |ui, range| {
                for i in range {
                    let f = &self.file.flames[i];
                    let label = if f.name.is_empty() {
                        format!("flame {}", i + 1)
                    } else {
                        f.name.clone()
                    };
                    let tex = self.thumbnail((FILE_LIST, i));
                    ui.horizontal(|ui| {
                        let r = match tex {
                            Some(t) => ui
                                .add(egui::Image::new((t, FILE_THUMB)).sense(egui::Sense::click())),
                            None => ui.add(egui::Button::new("…").min_size(FILE_THUMB)),
                        };
                        let l = ui
                            .add(egui::Button::selectable(current == Some(i), &label).truncate())
                            .on_hover_text(&label);
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
        let header = egui::CollapsingHeader::new(format!("Last random batch ({batch_len})"))
            .id_salt("batch-header")
            .open(Some(self.batch_shown))
            .show(ui, |ui| {
                ui.label("Click to edit; Keep copies into the file.");
            });
        if header.header_response.clicked() {
            self.batch_shown = !self.batch_shown;
        }
        if !self.batch_shown {
            return;
        }
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
                                let l = ui
                                    .add(
                                        egui::Button::selectable(current == Some(i), &name)
                                            .truncate(),
                                    )
                                    .on_hover_text(&name);
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
