//! The variations of the selected transform: the ones in use at the top (with their form and
//! parameters), then every variation name — about 1,400 with the `pre_` and `post_` forms —
//! narrowed by the Find box; "all" lists them without typing. Only the rows in view are
//! drawn.

use std::sync::LazyLock;

use eframe::egui;

use crate::flame::variations::{self, Form, VarId};
use crate::flame::{Var, Xform};

/// One name of the list: the variation, its form, the attribute name and its lower case.
pub struct VarName {
    pub id: VarId,
    pub form: Form,
    pub name: String,
    lower: String,
}

/// Every usable variation name (hidden entries left out; post-only variations only in their
/// `post_` form), in registry order, each variation's forms together.
pub static NAMES: LazyLock<Vec<VarName>> = LazyLock::new(|| {
    let mut v = Vec::new();
    for id in 0..variations::count() as VarId {
        let info = variations::info(id);
        if info.has(variations::flag::HIDDEN) {
            continue;
        }
        for form in [Form::Regular, Form::Pre, Form::Post] {
            if info.has(variations::flag::POST_ONLY) && form != Form::Post {
                continue;
            }
            let name = variations::attr_name(id, form);
            // A name that reads back as another variation is left out: flam3's `pre_blur`
            // is the pre form of gaussian_blur, so blur has no pre form of its own.
            if variations::parse_name(&name) != Some((id, form)) {
                continue;
            }
            v.push(VarName {
                id,
                form,
                lower: name.to_ascii_lowercase(),
                name,
            });
        }
    }
    v
});

/// Indices into [`NAMES`] of the names that match `find` (case-insensitive, any part of the
/// name); an empty `find` matches everything.
pub fn matching(find: &str) -> Vec<usize> {
    let f = find.trim().to_ascii_lowercase();
    NAMES
        .iter()
        .enumerate()
        .filter(|(_, n)| f.is_empty() || n.lower.contains(&f))
        .map(|(i, _)| i)
        .collect()
}

/// The Find box and the "all" switch.
#[derive(Clone, Debug, Default)]
pub struct VarFind {
    pub text: String,
    pub all: bool,
}

fn num(ui: &mut egui::Ui, v: &mut f64, label: &str) -> bool {
    let l = ui.label(label);
    ui.add(egui::DragValue::new(v).speed(0.01).max_decimals(6))
        .labelled_by(l.id)
        .changed()
}

/// The panel; edits `x` in place.
pub fn panel(ui: &mut egui::Ui, x: &mut Xform, find: &mut VarFind) {
    ui.horizontal(|ui| {
        let l = ui.label("Find");
        ui.add(egui::TextEdit::singleline(&mut find.text).desired_width(140.0))
            .labelled_by(l.id)
            .on_hover_text("part of a variation name, e.g. julia or pre_");
        ui.checkbox(&mut find.all, "all")
            .on_hover_text("list every variation (narrowed by Find when it has text)");
        if ui
            .button("Normalise")
            .on_hover_text("divide the weights by their sum")
            .clicked()
        {
            let s: f64 = x.vars.iter().map(|v| v.weight).sum();
            if s != 0.0 {
                for v in &mut x.vars {
                    v.weight /= s;
                }
            }
        }
    });
    // In use: always shown, whatever Find says.
    ui.strong("In use");
    let mut remove = None;
    egui::Grid::new("vars-in-use")
        .num_columns(3)
        .striped(true)
        .show(ui, |ui| {
            for (k, v) in x.vars.iter_mut().enumerate() {
                let info = variations::info(v.id);
                num(ui, &mut v.weight, &variations::attr_name(v.id, v.form));
                if ui
                    .small_button("×")
                    .on_hover_text("remove this variation")
                    .clicked()
                {
                    remove = Some(k);
                }
                ui.end_row();
                for pi in 0..info.params.len() {
                    let name = format!("    {}", variations::param_attr_name(v.id, v.form, pi));
                    num(ui, &mut v.params[pi], &name);
                    ui.end_row();
                }
                for (ti, def) in info.texts.iter().enumerate() {
                    let Some(text) = v.texts.get_mut(ti) else {
                        break;
                    };
                    let l = ui.label(format!(
                        "    {}",
                        variations::text_attr_name(v.id, v.form, ti)
                    ));
                    let mut t = text.clone();
                    if ui
                        .add(egui::TextEdit::singleline(&mut t).desired_width(120.0))
                        .labelled_by(l.id)
                        .changed()
                    {
                        *text = def.normalise(&t);
                    }
                    ui.end_row();
                }
            }
        });
    if let Some(k) = remove {
        x.vars.remove(k);
    }
    x.vars.retain(|v| v.weight != 0.0);
    for (n, w) in x.unsupported_vars() {
        ui.label(format!("{n} = {w} (kept, not rendered)"));
    }
    ui.separator();
    if !find.all && find.text.trim().is_empty() {
        ui.label(format!(
            "{} variations: type in Find or tick \"all\" to add one",
            NAMES.len()
        ));
        return;
    }
    let rows: Vec<usize> = matching(&find.text)
        .into_iter()
        .filter(|&i| {
            let n = &NAMES[i];
            !x.vars.iter().any(|v| v.id == n.id && v.form == n.form)
        })
        .collect();
    ui.label(format!("{} of {} names", rows.len(), NAMES.len()));
    let row_h = ui.spacing().interact_size.y + ui.spacing().item_spacing.y;
    let mut add = None;
    egui::ScrollArea::vertical()
        .id_salt("var-list")
        .max_height(280.0)
        .auto_shrink([false, true])
        .show_rows(ui, row_h, rows.len(), |ui, range| {
            for &i in &rows[range] {
                let n = &NAMES[i];
                ui.horizontal(|ui| {
                    let mut w = 0.0;
                    if num(ui, &mut w, &n.name) && w != 0.0 {
                        add = Some((i, w));
                    }
                    if ui
                        .small_button("+")
                        .on_hover_text("add with weight 1")
                        .clicked()
                    {
                        add = Some((i, 1.0));
                    }
                });
            }
        });
    if let Some((i, w)) = add {
        let n = &NAMES[i];
        x.vars.push(Var::with_form(n.id, n.form, w));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_name_parses_back_and_find_narrows() {
        assert!(NAMES.len() > 1000, "{}", NAMES.len());
        for n in NAMES.iter() {
            assert_eq!(
                variations::parse_name(&n.name),
                Some((n.id, n.form)),
                "{}",
                n.name
            );
        }
        let j = matching("JULIA");
        assert!(!j.is_empty() && j.len() < NAMES.len());
        assert!(j.iter().all(|&i| NAMES[i].lower.contains("julia")));
        assert_eq!(matching("").len(), NAMES.len());
        assert!(matching("no-such-variation").is_empty());
    }
}
