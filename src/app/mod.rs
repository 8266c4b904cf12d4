//! The desktop application (egui/eframe, glow renderer).

use std::path::PathBuf;

/// Start the editor window.
pub fn run(file: Option<PathBuf>) -> Result<(), eframe::Error> {
    let options = eframe::NativeOptions {
        viewport: eframe::egui::ViewportBuilder::default()
            .with_title("ugnis")
            .with_inner_size([1200.0, 800.0]),
        renderer: eframe::Renderer::Glow,
        ..Default::default()
    };
    eframe::run_native(
        "ugnis",
        options,
        Box::new(move |_cc| Ok(Box::new(Placeholder { file }))),
    )
}

struct Placeholder {
    file: Option<PathBuf>,
}

impl eframe::App for Placeholder {
    fn ui(&mut self, ui: &mut eframe::egui::Ui, _frame: &mut eframe::Frame) {
        ui.heading("ugnis");
        if let Some(f) = &self.file {
            ui.label(format!("file: {}", f.display()));
        }
    }
}
