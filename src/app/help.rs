//! The Help menu's windows: keyboard shortcuts (made from the menu table, so they are always
//! right), what each panel does, and About.

use eframe::egui;

use super::actions::{EXTRA_SHORTCUTS, MENU, MENUS};

/// Which help window is open.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum HelpPage {
    /// Keyboard shortcuts.
    Shortcuts,
    /// What the panels do.
    Panels,
    /// About ugnis.
    About,
}

/// What each part of the window does (title, text).
pub const PANELS: &[(&str, &str)] = &[
    (
        "Flame tab",
        "Left: the flames of the open file and the last random batch (click to edit, Keep \
         copies a batch flame into the file). Centre: the live preview — wheel zooms at the \
         pointer, drag moves the camera, right-drag rotates it. Right: the triangle editor and \
         the numbers of the selected transform.",
    ),
    (
        "Triangle editor",
        "Every transform is a triangle: the image of the dashed reference triangle O, X, Y. \
         Drag inside a triangle to move it, drag a corner to reshape it; Rotate and Scale turn \
         or grow it about its centre (local pivot) or the origin (world pivot). Post edits the \
         post transform; Final shows the final transform. Wheel zooms, right-drag pans, the \
         context menu adds, duplicates and deletes. y points up, as in Apophysis.",
    ),
    (
        "Transform sections",
        "Transforms: the list of transforms (select, reorder, switch off). Triangle: corners, \
         coefficients, weight and colour. Variations: the variations in use, and Find to add \
         any of about 1,400 names. Xaos: how likely each transform is to follow another. \
         Flame: size, camera and tone settings.",
    ),
    (
        "Gradient and palette",
        "Gradient (Ctrl+G): the library of gradients, load .ugr/.map/.ggr files or make one \
         from an image. Palette editor (Ctrl+Shift+G): move keys and pick their colours, adjust \
         hue, saturation, brightness, contrast, frequency and blur, and bend colour curves.",
    ),
    (
        "Random flames",
        "Random flame (Ctrl+R) and Random batch (Ctrl+B) use Options › Random and the \
         Variations choice of the Tools menu; the Variations filter lists which variations \
         they may use. Mutations (Ctrl+U) shows eight variants of the current flame.",
    ),
    (
        "Timeline and animation",
        "Animation › Timeline (Ctrl+T) shows the frames under the preview; the preview and \
         the editor's numbers are those of the current frame. Choose a parameter (the \
         flame's, the selected transform's and its variations', the palette's), press Key (K) \
         to key it at the current frame; with Auto-key, changing an animated value keys it. \
         Drag keys on the ruler, right-click them for interpolation and easing; Curve shows \
         the value against the frame with Bézier handles. Space plays, Left and Right step, \
         Home and End jump. Loop tools make a rotation loop as keys and play flam3-genome's \
         morphs and loops; Export animation (Ctrl+Shift+E) writes PNG frames or a video, and \
         resumes where a cancelled export stopped. Motion blur is set in Settings.",
    ),
    (
        "Escape-time tab",
        "Mandelbrot, Julia and relatives. Wheel zooms at the pointer, drag pans, right-drag \
         zooms to a rectangle, a click on the Mandelbrot set opens the Julia set of that \
         point. Back and Forward walk the view history; views save as .esc files.",
    ),
    (
        "Scene tab",
        "A textured Bézier scene: drag to orbit, wheel to zoom, right-drag to pan, Ctrl+drag \
         moves the selected light. Each object's texture can be the current flame, the current \
         escape-time view, a procedural texture or an image. Scenes save as .toml files.",
    ),
    (
        "Explore tab",
        "Teaching topics, chosen in the list at the left: classic constructions step by step, \
         the chaos game, L-systems (open and edit Fractint .l files, export SVG or PNG), \
         fractal interpolation (click to add points, drag them), Julia sets by inverse \
         iteration, the Lorenz attractor (drag to turn it) and fractal dimension. Each shows \
         its parameters, an explanation and its numbers on the right.",
    ),
];

/// The title of a help window.
pub fn title(page: HelpPage) -> &'static str {
    match page {
        HelpPage::Shortcuts => "Keyboard shortcuts",
        HelpPage::Panels => "What the panels do",
        HelpPage::About => "About ugnis",
    }
}

/// Show the open help window; returns false when it was closed.
pub fn show(ctx: &egui::Context, page: HelpPage) -> bool {
    let mut open = true;
    let title = title(page);
    egui::Window::new(title)
        .open(&mut open)
        .collapsible(false)
        .default_width(460.0)
        .show(ctx, |ui| match page {
            HelpPage::Shortcuts => {
                // The scroll bar always shows: the list is longer than the window.
                egui::ScrollArea::vertical()
                    .max_height(420.0)
                    .auto_shrink([false, true])
                    .scroll_bar_visibility(egui::scroll_area::ScrollBarVisibility::AlwaysVisible)
                    .show(ui, |ui| {
                        egui::Grid::new("shortcut-grid")
                            .striped(true)
                            .show(ui, |ui| {
                                for menu in MENUS {
                                    for m in MENU.iter().filter(|m| m.menu == menu) {
                                        if let Some(s) = &m.shortcut {
                                            ui.label(ctx.format_shortcut(s));
                                            ui.label(format!("{menu} › {}", m.label));
                                            ui.end_row();
                                        }
                                    }
                                }
                                for (s, a) in EXTRA_SHORTCUTS {
                                    let what = MENU.iter().find(|m| m.action == *a);
                                    ui.label(ctx.format_shortcut(s));
                                    ui.label(what.map_or_else(
                                        || format!("{a:?}"),
                                        |m| format!("{} › {}", m.menu, m.label),
                                    ));
                                    ui.end_row();
                                }
                                for (keys, what) in [
                                    ("Alt+Left / Alt+Right", "Escape-time › Back / Forward"),
                                    ("Shift while rotating", "turn in 15° steps"),
                                    ("Ctrl+drag (scene)", "move the selected light"),
                                ] {
                                    ui.label(keys);
                                    ui.label(what);
                                    ui.end_row();
                                }
                            });
                    });
            }
            HelpPage::Panels => {
                egui::ScrollArea::vertical()
                    .max_height(420.0)
                    .show(ui, |ui| {
                        for (t, text) in PANELS {
                            ui.strong(*t);
                            ui.label(*text);
                            ui.add_space(6.0);
                        }
                    });
            }
            HelpPage::About => {
                ui.heading(format!("ugnis {}", crate::VERSION));
                ui.label(
                    "A fractal editor: fractal flames and IFS (flam3-compatible renderer), \
                     escape-time fractals and textured Bézier scenes.",
                );
                ui.label(
                    "Flames after Draves and Reckase, \"The Fractal Flame Algorithm\"; the \
                     editor follows the 2006 Urbonavičius thesis program and Apophysis.",
                );
                ui.label("Licence: MIT or Apache-2.0.");
            }
        });
    open
}
