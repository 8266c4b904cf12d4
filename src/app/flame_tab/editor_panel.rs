//! The right panel of the flame tab: the triangle editor's toolbar and canvas, and below it
//! one section at a time — the transform list, the selected transform's triangle and colour,
//! its variations, the xaos matrix, the flame's settings.

use eframe::egui::{self, Vec2};

use super::document::Document;
use super::editor_state::{EditorState, Section, Selected};
use super::editor_tools::{self, EditorAction};
use super::transform_list::{self, ListAction};
use super::{FlameTab, pick, settings, triangles, xaos, xform_panel};
use crate::app::options::Options;

const SECTIONS: [(Section, &str, &str); 5] = [
    (
        Section::Transforms,
        "Transforms",
        "every transform: select, reorder, switch off; add, duplicate, delete",
    ),
    (
        Section::Triangle,
        "Triangle",
        "corners, coefficients, weight and colour of the selected transform",
    ),
    (
        Section::Variations,
        "Variations",
        "the variations of the selected transform; Find adds any of about 1,400",
    ),
    (
        Section::Xaos,
        "Xaos",
        "how likely each transform is to follow another",
    ),
    (
        Section::Flame,
        "Settings",
        "size, camera and tone settings of the flame",
    ),
];

impl FlameTab {
    fn doc_and_editor(&mut self) -> (&mut Document, &mut EditorState) {
        (
            pick(self.showing, &mut self.batch, &mut self.file),
            &mut self.editor,
        )
    }

    /// The panel; returns true while a triangle is being dragged.
    pub(super) fn editor_panel(&mut self, ui: &mut egui::Ui, options: &Options) -> bool {
        let auto = self.auto_weights(options);
        let flame = self.doc().flame().clone();
        if let Some(a) = editor_tools::toolbar(ui, &mut self.editor, &flame) {
            self.editor_action(a, options);
        }
        let h = (ui.available_height() * 0.5).max(140.0);
        let mut dragging = false;
        let keyed = self.timeline.keyed_view(self.doc().flame());
        ui.allocate_ui(Vec2::new(ui.available_width(), h), |ui| {
            let (doc, editor) = self.doc_and_editor();
            let out = triangles::canvas(ui, doc, editor, auto, keyed);
            dragging = out.dragging;
            if let Some(a) = out.action {
                self.editor_action(a, options);
            }
        });
        ui.horizontal_wrapped(|ui| {
            for (s, label, tip) in SECTIONS {
                ui.selectable_value(&mut self.editor.section, s, label)
                    .on_hover_text(tip);
            }
        });
        ui.separator();
        let held = ui.input(|i| i.pointer.any_down());
        egui::ScrollArea::vertical()
            .id_salt("xform-panels")
            .auto_shrink([false, false])
            .show(ui, |ui| match self.editor.section {
                Section::Transforms => self.transforms_section(ui, options),
                Section::Triangle => {
                    let (doc, editor) = self.doc_and_editor();
                    xform_panel::triangle_section(ui, doc, editor, auto, held, keyed);
                }
                Section::Variations => {
                    let (doc, editor) = self.doc_and_editor();
                    xform_panel::variations_section(ui, doc, editor, held);
                }
                Section::Xaos => {
                    let (doc, _) = self.doc_and_editor();
                    xaos::section(ui, doc, held);
                }
                Section::Flame => {
                    let (doc, _) = self.doc_and_editor();
                    settings::flame_settings(ui, doc, held);
                }
            });
        dragging
    }

    fn transforms_section(&mut self, ui: &mut egui::Ui, options: &Options) {
        ui.horizontal(|ui| {
            for (label, tip, a) in [
                ("Add", "a new linear transform", EditorAction::Add),
                (
                    "Duplicate",
                    "a copy of the selected transform",
                    EditorAction::Duplicate,
                ),
                (
                    "Delete",
                    "remove the selected transform (two stay)",
                    EditorAction::Delete,
                ),
            ] {
                if ui.button(label).on_hover_text(tip).clicked() {
                    self.editor_action(a, options);
                }
            }
        });
        let flame = self.doc().flame().clone();
        let Some(a) = transform_list::list(ui, &flame, self.editor.selected) else {
            return;
        };
        let current = self.doc().current;
        match a {
            ListAction::Select(s) => self.editor.selected = s,
            ListAction::MoveUp(i) | ListAction::MoveDown(i) => {
                let j = if matches!(a, ListAction::MoveUp(_)) {
                    i - 1
                } else {
                    i + 1
                };
                self.doc_mut()
                    .edit(|f| transform_list::swap_xforms(f, i, j));
                if self.editor.selected == Selected::Xform(i) {
                    self.editor.selected = Selected::Xform(j);
                }
            }
            ListAction::Toggle(i, on) => {
                let old = flame.xforms[i].weight;
                let restore = self
                    .editor
                    .off_weights
                    .remove(&(current, i))
                    .unwrap_or(1.0 / flame.xforms.len() as f64);
                if !on {
                    self.editor.off_weights.insert((current, i), old);
                }
                // A switched transform keeps its weight: the areas rule would undo it.
                self.doc_mut().edit(|f| {
                    f.xforms[i].weight = if on { restore } else { 0.0 };
                    f.auto_weights = Some(false);
                });
            }
        }
    }

    pub(super) fn editor_action(&mut self, a: EditorAction, options: &Options) {
        let auto = self.auto_weights(options);
        let doc = pick(self.showing, &mut self.batch, &mut self.file);
        let editor = &mut self.editor;
        match a {
            EditorAction::AutoZoom => editor.auto_zoom(doc.flame()),
            EditorAction::Delete => {
                if let Err(e) = editor_tools::delete_selected(doc, editor) {
                    self.notices.status(e);
                }
            }
            EditorAction::Duplicate => editor_tools::duplicate_selected(doc, editor, auto),
            EditorAction::Add => editor_tools::add_xform(doc, editor, auto),
            EditorAction::Undo => self.undo(),
            EditorAction::Redo => self.redo(),
        }
    }
}
