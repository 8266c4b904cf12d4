//! The undo history as a list (Edit › History, as Apophysis' and Photoshop's history
//! panels): each step named by what it changed, found by comparing the flame before and
//! after; a click goes back or forward to that step.

use eframe::egui;

use super::FlameTab;
use crate::flame::{Flame, Xform};

/// What changed in one transform, in a word or two.
fn xform_change(a: &Xform, b: &Xform) -> &'static str {
    if a.coefs != b.coefs {
        "triangle"
    } else if a.post != b.post {
        "post triangle"
    } else if a.vars != b.vars {
        "variations"
    } else if a.weight != b.weight {
        "weight"
    } else if (a.color, a.color_speed, a.opacity) != (b.color, b.color_speed, b.opacity) {
        "colour"
    } else if a.chaos != b.chaos {
        "xaos"
    } else {
        "settings"
    }
}

/// The name of an edit of one flame, from the flame before and after it.
pub fn describe(before: &Flame, after: &Flame) -> String {
    use std::cmp::Ordering;
    match after.xforms.len().cmp(&before.xforms.len()) {
        Ordering::Greater => return "Add transform".into(),
        Ordering::Less => return "Delete transform".into(),
        Ordering::Equal => {}
    }
    let mut parts: Vec<String> = Vec::new();
    let changed: Vec<usize> = (0..after.xforms.len())
        .filter(|&i| before.xforms[i] != after.xforms[i])
        .collect();
    match changed.as_slice() {
        [] => {}
        [i] => parts.push(format!(
            "Transform {} {}",
            i + 1,
            xform_change(&before.xforms[*i], &after.xforms[*i])
        )),
        many => {
            let what = xform_change(&before.xforms[many[0]], &after.xforms[many[0]]);
            parts.push(format!("{} transforms' {what}", many.len()));
        }
    }
    if before.final_xform != after.final_xform {
        parts.push(match (&before.final_xform, &after.final_xform) {
            (None, Some(_)) => "Add final transform".into(),
            (Some(_), None) => "Delete final transform".into(),
            (Some(a), Some(b)) => format!("Final transform {}", xform_change(a, b)),
            (None, None) => unreachable!("they differ"),
        });
    }
    let groups: [(&str, bool); 9] = [
        (
            "Gradient",
            before.palette != after.palette || before.palette_mode != after.palette_mode,
        ),
        (
            "Camera",
            (before.center, before.scale, before.zoom, before.rotate)
                != (after.center, after.scale, after.zoom, after.rotate),
        ),
        ("3-D camera", before.cam != after.cam),
        (
            "Size",
            (before.width, before.height) != (after.width, after.height),
        ),
        ("Name", before.name != after.name),
        (
            "Tone",
            (
                before.brightness,
                before.gamma,
                before.gamma_threshold,
                before.vibrancy,
            ) != (
                after.brightness,
                after.gamma,
                after.gamma_threshold,
                after.vibrancy,
            ) || (before.highlight_power, before.contrast, before.background)
                != (after.highlight_power, after.contrast, after.background),
        ),
        (
            "Render settings",
            (before.quality, before.filter, before.estimator_radius)
                != (after.quality, after.filter, after.estimator_radius)
                || (before.supersample, before.filter_shape)
                    != (after.supersample, after.filter_shape)
                || (before.estimator_minimum, before.estimator_curve)
                    != (after.estimator_minimum, after.estimator_curve),
        ),
        ("Keyframes", before.keys != after.keys),
        ("Motion blur", before.anim != after.anim),
    ];
    parts.extend(groups.iter().filter(|g| g.1).map(|g| g.0.to_string()));
    match parts.len() {
        0 => "Flame settings".into(),
        1..=2 => parts.join(", "),
        n => format!("{}, {} and {} more", parts[0], parts[1], n - 2),
    }
}

/// The name of a change of the set of flames.
pub fn describe_document(before: &[Flame], after: &[Flame]) -> String {
    use std::cmp::Ordering;
    match after.len().cmp(&before.len()) {
        Ordering::Greater if after.len() == before.len() + 1 => "Add flame".into(),
        Ordering::Greater => format!("Add {} flames", after.len() - before.len()),
        Ordering::Less if after.len() + 1 == before.len() => "Delete flame".into(),
        Ordering::Less => format!("Delete {} flames", before.len() - after.len()),
        Ordering::Equal => match before.iter().zip(after).filter(|(a, b)| a != b).count() {
            1 => "Replace flame".into(),
            _ => "Replace flames".into(),
        },
    }
}

impl FlameTab {
    /// The History window: the steps of the document shown, the current state marked; a
    /// click on a step goes to the state after it.
    pub(super) fn history_window(&mut self, ctx: &egui::Context) {
        if !self.history_open {
            return;
        }
        let mut open = true;
        let mut go = None;
        let screen = ctx.content_rect();
        egui::Window::new("History")
            .open(&mut open)
            .default_size([260.0, 320.0])
            .default_pos([screen.left() + 220.0, screen.top() + 80.0])
            .show(ctx, |ui| {
                let (done, undone) = self.doc().history();
                let at = done.len();
                egui::ScrollArea::vertical().show(ui, |ui| {
                    if ui
                        .selectable_label(at == 0, "Start")
                        .on_hover_text("the oldest state kept")
                        .clicked()
                    {
                        go = Some(0);
                    }
                    for (k, label) in done.iter().chain(undone.iter()).enumerate() {
                        let pos = k + 1;
                        let text = egui::RichText::new(format!("{pos}. {label}"));
                        // Undone steps are greyed, as in Apophysis' and Photoshop's lists.
                        let text = if pos > at { text.weak() } else { text };
                        let r = ui.selectable_label(pos == at, text);
                        if r.clicked() {
                            go = Some(pos);
                        }
                    }
                });
            });
        if let Some(p) = go
            && self.doc_mut().go_to(p)
        {
            let f = self.doc().flame().clone();
            self.editor.fix_selection(&f);
        }
        self.history_open = open;
    }
}
