//! The triangle editor's commands: its toolbar (modes, pivot, post/final, grid, auto zoom,
//! the transform chooser) and add, duplicate and delete.

use eframe::egui;

use super::document::Document;
use super::editor_state::{EditorState, Mode, Pivot, Selected, xform_of};
use crate::app::a11y::named;
use crate::flame::{Affine, Flame, Xform};

/// Actions the editor's context menu asks for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum EditorAction {
    AutoZoom,
    Delete,
    Duplicate,
    Add,
    Undo,
    Redo,
}

/// Delete the selected xform, refused below 2 (a flame needs two maps to be more than a single
/// curve; Fraktalai's rule). Returns an explanation when refused.
pub fn delete_selected(doc: &mut Document, st: &mut EditorState) -> Result<(), String> {
    match st.selected {
        Selected::Final => {
            doc.edit(|f| f.final_xform = None);
            st.selected = Selected::Xform(0);
            Ok(())
        }
        Selected::Xform(i) => {
            if doc.flame().xforms.len() <= 2 {
                return Err("Delete refused: a flame needs at least 2 transforms".into());
            }
            doc.edit(|f| {
                f.xforms.remove(i);
                for x in &mut f.xforms {
                    if i < x.chaos.len() {
                        x.chaos.remove(i);
                    }
                }
            });
            st.selected = Selected::Xform(i.saturating_sub(1));
            Ok(())
        }
    }
}

/// Duplicate the selected xform (the copy is selected).
pub fn duplicate_selected(doc: &mut Document, st: &mut EditorState, auto_weights: bool) {
    let Some(x) = xform_of(doc.flame(), st.selected).cloned() else {
        return;
    };
    doc.edit(|f| {
        let mut x = x;
        x.weight = x.weight.max(0.0);
        f.xforms.push(x);
        if auto_weights {
            f.set_determinant_weights();
        }
    });
    st.selected = Selected::Xform(doc.flame().xforms.len() - 1);
}

/// Add a new linear xform: weight 0.5, colour 1, a half-size square beside the reference
/// triangle.
pub fn add_xform(doc: &mut Document, st: &mut EditorState, auto_weights: bool) {
    doc.edit(|f| {
        let n = f.xforms.len() + 1;
        f.xforms.push(Xform {
            weight: 0.5,
            ..Xform::linear(Affine::new(0.5, 0.0, 0.0, 0.5, 0.25, -0.25), 0.5, 1.0)
        });
        // Spread the colours i/(n − 1).
        for (i, x) in f.xforms.iter_mut().enumerate() {
            if n > 1 && i == n - 1 {
                x.color = 1.0;
            }
        }
        if auto_weights {
            f.set_determinant_weights();
        }
    });
    st.selected = Selected::Xform(doc.flame().xforms.len() - 1);
}

/// The editor's toolbar: modes, pivot, post/final toggles, grid, auto zoom, the transform
/// chooser.
pub fn toolbar(ui: &mut egui::Ui, st: &mut EditorState, flame: &Flame) -> Option<EditorAction> {
    let mut action = None;
    ui.horizontal_wrapped(|ui| {
        for (m, label, tip) in [
            (
                Mode::Move,
                "Move",
                "drag inside a triangle to move it, a corner to reshape it",
            ),
            (
                Mode::Rotate,
                "Rotate",
                "drag a triangle to turn it about the pivot (Shift: 15° steps)",
            ),
            (
                Mode::Scale,
                "Scale",
                "drag a triangle to grow or shrink it about the pivot",
            ),
        ] {
            ui.selectable_value(&mut st.mode, m, label)
                .on_hover_text(tip);
        }
        ui.separator();
        ui.selectable_value(&mut st.pivot, Pivot::Local, "Local pivot")
            .on_hover_text("rotate and scale about the triangle's centre");
        ui.selectable_value(&mut st.pivot, Pivot::World, "World pivot")
            .on_hover_text("rotate and scale about the origin (0, 0)");
        ui.separator();
        ui.toggle_value(&mut st.edit_post, "Post")
            .on_hover_text("show and edit the post transforms (applied after the variations)");
        ui.toggle_value(&mut st.show_final, "Final")
            .on_hover_text("show the final transform (dashed white)");
        ui.toggle_value(&mut st.grid, "Grid")
            .on_hover_text("show the grid behind the triangles");
        if ui
            .button("Auto zoom")
            .on_hover_text("fit every triangle in the canvas")
            .clicked()
        {
            action = Some(EditorAction::AutoZoom);
        }
        ui.separator();
        let r = egui::ComboBox::from_id_salt("xform-select")
            .selected_text(match st.selected {
                Selected::Xform(i) => format!("Transform {}", i + 1),
                Selected::Final => "Final".to_string(),
            })
            .show_ui(ui, |ui| {
                for i in 0..flame.xforms.len() {
                    ui.selectable_value(
                        &mut st.selected,
                        Selected::Xform(i),
                        format!("Transform {}", i + 1),
                    );
                }
                if flame.final_xform.is_some() {
                    ui.selectable_value(&mut st.selected, Selected::Final, "Final");
                }
            });
        named(r.response, "Selected transform").on_hover_text("the transform the panels edit");
    });
    action
}
