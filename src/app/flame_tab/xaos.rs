//! The xaos editor: the from → to matrix of weight multipliers (Apophysis' "Xaos" tab,
//! Fractorium's xaos editor). Row i says how likely each transform is to follow transform i:
//! 1 keeps the plain weight, 0 forbids the step, larger values favour it.

use eframe::egui;

use super::document::Document;
use super::transform_list::xform_name;
use crate::app::a11y::named;
use crate::flame::Flame;

/// Largest multiplier the editor accepts.
pub const MAX_XAOS: f64 = 1e6;

/// The multiplier from transform `from` to transform `to` (missing entries are 1).
pub fn get(f: &Flame, from: usize, to: usize) -> f64 {
    f.xforms
        .get(from)
        .and_then(|x| x.chaos.get(to).copied())
        .unwrap_or(1.0)
}

/// Set the multiplier from `from` to `to`; rows that are all 1 are stored empty.
pub fn set(f: &mut Flame, from: usize, to: usize, v: f64) {
    let n = f.xforms.len();
    let Some(x) = f.xforms.get_mut(from) else {
        return;
    };
    if to >= n {
        return;
    }
    if x.chaos.len() < n {
        x.chaos.resize(n, 1.0);
    }
    x.chaos[to] = v.clamp(0.0, MAX_XAOS);
    if x.chaos.iter().all(|&c| c == 1.0) {
        x.chaos.clear();
    }
}

/// The Xaos section: edits go to the current flame; `dragging`: a pointer is held (a drag
/// of a number is one undo step).
pub fn section(ui: &mut egui::Ui, doc: &mut Document, dragging: bool) {
    let f = doc.flame().clone();
    let n = f.xforms.len();
    let mut edits: Vec<(usize, usize, f64)> = Vec::new();
    ui.label("Row: from this transform; column: to that one. 1 = plain weight, 0 = never.");
    let reset = ui
        .button("All 1")
        .on_hover_text("plain weights everywhere (no xaos)")
        .clicked();
    egui::ScrollArea::horizontal()
        .id_salt("xaos-scroll")
        .show(ui, |ui| {
            egui::Grid::new("xaos-grid").striped(true).show(ui, |ui| {
                ui.label("from \\ to");
                for j in 0..n {
                    ui.strong(format!("{}", j + 1))
                        .on_hover_text(xform_name(&f.xforms[j], j));
                }
                ui.end_row();
                for i in 0..n {
                    ui.label(format!("{} {}", i + 1, xform_name(&f.xforms[i], i)));
                    for j in 0..n {
                        let mut v = get(&f, i, j);
                        let name = format!("xaos {} to {}", i + 1, j + 1);
                        let r = named(
                            ui.add(
                                egui::DragValue::new(&mut v)
                                    .speed(0.01)
                                    .range(0.0..=MAX_XAOS)
                                    .clamp_existing_to_range(false)
                                    .max_decimals(4),
                            ),
                            &name,
                        )
                        .on_hover_text(format!(
                            "how much the weight of {} counts right after {}",
                            j + 1,
                            i + 1
                        ));
                        if r.changed() {
                            edits.push((i, j, v));
                        }
                    }
                    ui.end_row();
                }
            });
        });
    if reset {
        doc.edit(|f| f.xforms.iter_mut().for_each(|x| x.chaos.clear()));
    } else if !edits.is_empty() {
        doc.edit_while(dragging, |f| {
            for (i, j, v) in edits {
                set(f, i, j, v);
            }
        });
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::flame::Xform;

    #[test]
    fn entries_default_to_one_and_plain_rows_stay_empty() {
        let mut f = Flame {
            xforms: vec![Xform::default(), Xform::default(), Xform::default()],
            ..Flame::default()
        };
        assert_eq!(get(&f, 1, 2), 1.0);
        set(&mut f, 1, 2, 0.0);
        assert_eq!(f.xforms[1].chaos, vec![1.0, 1.0, 0.0]);
        assert_eq!(get(&f, 1, 2), 0.0);
        set(&mut f, 1, 2, -5.0);
        assert_eq!(get(&f, 1, 2), 0.0, "negative multipliers are clamped");
        set(&mut f, 1, 2, 1.0);
        assert!(f.xforms[1].chaos.is_empty());
        set(&mut f, 7, 0, 3.0);
        set(&mut f, 0, 7, 3.0);
        assert!(f.xforms.iter().all(|x| x.chaos.is_empty()));
    }
}
