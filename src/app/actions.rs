//! Every command of the menus, the toolbar and the keyboard, with its menu and shortcut.

use eframe::egui::{Key, KeyboardShortcut, Modifiers};

use crate::flame::variations::{self, VarId};

/// Every command of the menus, toolbar and shortcuts.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Action {
    /// File ▸ New: a new flame.
    New,
    /// File ▸ Open…
    Open,
    /// File ▸ Save.
    Save,
    /// File ▸ Save As…
    SaveAs,
    /// File ▸ Load gradient…
    LoadGradient,
    /// File ▸ Create gradient from image…
    GradientFromImage,
    /// File ▸ Export image…
    Export,
    /// Continue a saved render state in the export window.
    ResumeState,
    /// File ▸ Random batch: a file of random flames.
    RandomBatch,
    /// File ▸ Exit.
    Exit,
    /// Edit ▸ Undo.
    Undo,
    /// Edit ▸ Redo.
    Redo,
    /// Edit ▸ History: the list of undo steps.
    ShowHistory,
    /// Edit ▸ Copy flame (XML).
    CopyFlame,
    /// Edit ▸ Paste flame (XML).
    PasteFlame,
    /// View ▸ Toolbar: show or hide it.
    ToggleToolbar,
    /// View ▸ Status bar: show or hide it.
    ToggleStatusBar,
    /// View ▸ File contents: show or hide the list of the file's flames.
    ToggleFilePanel,
    /// Tools ▸ Editor: show or hide the triangle editor.
    ToggleEditor,
    /// View ▸ Full-window preview: the preview over the whole window, or back.
    ToggleFullView,
    /// View ▸ Preview in its own window, or back between the panels.
    TogglePreviewWindow,
    /// View ▸ Fit preview.
    FitPreview,
    /// View ▸ Zoom in.
    ZoomIn,
    /// View ▸ Zoom out.
    ZoomOut,
    /// None: "Random" (one of the seven per transform).
    SetVariation(Option<VarId>),
    /// Tools ▸ Gradient.
    ShowGradient,
    /// Tools ▸ Mutations…
    ShowMutations,
    /// Tools ▸ Random flame.
    RandomFlame,
    /// Tools ▸ Animate: start or stop the animation.
    ToggleAnimate,
    /// Play flam3-style in-betweens from the current flame to the next one of the file.
    ToggleMorph,
    /// Show or hide the timeline under the preview.
    ToggleTimeline,
    /// Play or pause the timeline.
    PlayPause,
    /// One frame back on the timeline.
    PreviousFrame,
    /// One frame on, on the timeline.
    NextFrame,
    /// The timeline's first frame.
    FirstFrame,
    /// The timeline's last frame.
    LastFrame,
    /// Key the timeline's parameter at the current frame.
    AddKey,
    /// Delete the timeline's selected key.
    DeleteKey,
    /// Animation ▸ Loop tools…
    ShowLoopTools,
    /// Animation ▸ Export animation…
    ExportAnimation,
    /// Tools ▸ Random weights.
    RandomWeights,
    /// Tools ▸ Equal weights.
    EqualWeights,
    /// Tools ▸ Weights from triangle areas.
    AreaWeights,
    /// Tools ▸ Options…
    ShowOptions,
    /// Tools ▸ Palette editor…
    ShowPaletteEditor,
    /// Tools ▸ Variations filter…
    ShowVariationFilter,
    /// Random flames draw their variations from the variations filter.
    UseVariationFilter,
    /// Help ▸ Keyboard shortcuts.
    ShowShortcuts,
    /// Help ▸ What the panels do.
    ShowPanelHelp,
    /// Help ▸ About ugnis.
    ShowAbout,
}

/// A menu entry: menu, label, action, shortcut.
pub struct MenuItem {
    /// The menu it is in ("File", "Edit", …).
    pub menu: &'static str,
    /// Its label.
    pub label: &'static str,
    /// What it does.
    pub action: Action,
    /// Its keyboard shortcut, if any.
    pub shortcut: Option<KeyboardShortcut>,
}

const CMD: Modifiers = Modifiers::COMMAND;
const CMD_SHIFT: Modifiers = Modifiers::COMMAND.plus(Modifiers::SHIFT);

const fn sc(m: Modifiers, k: Key) -> Option<KeyboardShortcut> {
    Some(KeyboardShortcut::new(m, k))
}

const fn item(
    menu: &'static str,
    label: &'static str,
    action: Action,
    shortcut: Option<KeyboardShortcut>,
) -> MenuItem {
    MenuItem {
        menu,
        label,
        action,
        shortcut,
    }
}

/// The menus, in order (Fraktalai's, with Apophysis conventions where it is silent).
pub const MENUS: [&str; 6] = ["File", "Edit", "View", "Tools", "Animation", "Help"];

/// The menu entries.
pub const MENU: &[MenuItem] = &[
    item("File", "New", Action::New, sc(CMD, Key::N)),
    item("File", "Open…", Action::Open, sc(CMD, Key::O)),
    item("File", "Save", Action::Save, sc(CMD, Key::S)),
    item("File", "Save As…", Action::SaveAs, sc(CMD_SHIFT, Key::S)),
    item("File", "Load gradient…", Action::LoadGradient, None),
    item(
        "File",
        "Create gradient from image…",
        Action::GradientFromImage,
        None,
    ),
    item("File", "Export image…", Action::Export, sc(CMD, Key::E)),
    item("File", "Resume render state…", Action::ResumeState, None),
    item("File", "Random batch", Action::RandomBatch, sc(CMD, Key::B)),
    item("File", "Exit", Action::Exit, sc(CMD, Key::Q)),
    item("Edit", "Undo", Action::Undo, sc(CMD, Key::Z)),
    item("Edit", "Redo", Action::Redo, sc(CMD, Key::Y)),
    item("Edit", "History", Action::ShowHistory, sc(CMD, Key::H)),
    item(
        "Edit",
        "Copy flame (XML)",
        Action::CopyFlame,
        sc(CMD_SHIFT, Key::C),
    ),
    item(
        "Edit",
        "Paste flame (XML)",
        Action::PasteFlame,
        sc(CMD_SHIFT, Key::V),
    ),
    item("View", "Toolbar", Action::ToggleToolbar, None),
    item("View", "Status bar", Action::ToggleStatusBar, None),
    item("View", "File contents", Action::ToggleFilePanel, None),
    item(
        "View",
        "Full-window preview",
        Action::ToggleFullView,
        sc(Modifiers::NONE, Key::F11),
    ),
    item(
        "View",
        "Preview in its own window",
        Action::TogglePreviewWindow,
        None,
    ),
    item(
        "View",
        "Fit preview",
        Action::FitPreview,
        sc(CMD, Key::Num0),
    ),
    item("View", "Zoom in", Action::ZoomIn, sc(CMD, Key::Plus)),
    item("View", "Zoom out", Action::ZoomOut, sc(CMD, Key::Minus)),
    item(
        "Tools",
        "Editor",
        Action::ToggleEditor,
        sc(Modifiers::NONE, Key::F4),
    ),
    item("Tools", "Gradient", Action::ShowGradient, sc(CMD, Key::G)),
    item(
        "Tools",
        "Palette editor…",
        Action::ShowPaletteEditor,
        sc(CMD_SHIFT, Key::G),
    ),
    item(
        "Tools",
        "Random flame",
        Action::RandomFlame,
        sc(CMD, Key::R),
    ),
    item(
        "Tools",
        "Mutations…",
        Action::ShowMutations,
        sc(CMD, Key::U),
    ),
    item("Tools", "Animate", Action::ToggleAnimate, sc(CMD, Key::M)),
    item(
        "Tools",
        "Morph to next flame",
        Action::ToggleMorph,
        sc(CMD_SHIFT, Key::M),
    ),
    item("Tools", "Random weights", Action::RandomWeights, None),
    item("Tools", "Equal weights", Action::EqualWeights, None),
    item(
        "Tools",
        "Weights from triangle areas",
        Action::AreaWeights,
        None,
    ),
    item(
        "Tools",
        "Variations filter…",
        Action::ShowVariationFilter,
        None,
    ),
    item(
        "Tools",
        "Options…",
        Action::ShowOptions,
        sc(CMD, Key::Comma),
    ),
    item(
        "Animation",
        "Timeline",
        Action::ToggleTimeline,
        sc(CMD, Key::T),
    ),
    item(
        "Animation",
        "Play / pause",
        Action::PlayPause,
        sc(Modifiers::NONE, Key::Space),
    ),
    item(
        "Animation",
        "Previous frame",
        Action::PreviousFrame,
        sc(Modifiers::NONE, Key::ArrowLeft),
    ),
    item(
        "Animation",
        "Next frame",
        Action::NextFrame,
        sc(Modifiers::NONE, Key::ArrowRight),
    ),
    item(
        "Animation",
        "First frame",
        Action::FirstFrame,
        sc(Modifiers::NONE, Key::Home),
    ),
    item(
        "Animation",
        "Last frame",
        Action::LastFrame,
        sc(Modifiers::NONE, Key::End),
    ),
    item(
        "Animation",
        "Key the parameter",
        Action::AddKey,
        sc(Modifiers::NONE, Key::K),
    ),
    item(
        "Animation",
        "Delete key",
        Action::DeleteKey,
        sc(Modifiers::NONE, Key::Delete),
    ),
    item("Animation", "Loop tools…", Action::ShowLoopTools, None),
    item(
        "Animation",
        "Export animation…",
        Action::ExportAnimation,
        sc(CMD_SHIFT, Key::E),
    ),
    item(
        "Help",
        "Keyboard shortcuts",
        Action::ShowShortcuts,
        sc(Modifiers::NONE, Key::F1),
    ),
    item("Help", "What the panels do", Action::ShowPanelHelp, None),
    item("Help", "About ugnis", Action::ShowAbout, None),
];

/// Shortcuts that are not shown in a menu: Ctrl+Shift+Z redo.
pub const EXTRA_SHORTCUTS: &[(KeyboardShortcut, Action)] =
    &[(KeyboardShortcut::new(CMD_SHIFT, Key::Z), Action::Redo)];

/// The Variations submenu: "Random" and the seven variations of Fraktalai.
pub const VARIATION_MENU: [(&str, Option<VarId>); 8] = [
    ("Random", None),
    ("Linear", Some(variations::LINEAR)),
    ("Sinusoidal", Some(variations::SINUSOIDAL)),
    ("Spherical", Some(variations::SPHERICAL)),
    ("Swirl", Some(variations::SWIRL)),
    ("Horseshoe", Some(variations::HORSESHOE)),
    ("Polar", Some(variations::POLAR)),
    ("Bent", Some(variations::BENT)),
];

/// Commands of the timeline whose shortcuts are plain keys: they act only while the timeline
/// is shown and no text field has the keyboard.
pub fn is_timeline_key(a: Action) -> bool {
    matches!(
        a,
        Action::PlayPause
            | Action::PreviousFrame
            | Action::NextFrame
            | Action::FirstFrame
            | Action::LastFrame
            | Action::AddKey
            | Action::DeleteKey
    )
}

/// Every shortcut with its action, the ones with more modifiers first: egui matches shortcuts
/// ignoring extra Shift, so Ctrl+Shift+S must be tried before Ctrl+S.
pub fn shortcuts() -> Vec<(KeyboardShortcut, Action)> {
    let mut all: Vec<(KeyboardShortcut, Action)> = EXTRA_SHORTCUTS
        .iter()
        .copied()
        .chain(
            MENU.iter()
                .filter_map(|m| m.shortcut.map(|s| (s, m.action))),
        )
        .collect();
    let weight = |m: Modifiers| m.shift as u8 + m.alt as u8 + (m.command || m.ctrl) as u8;
    all.sort_by_key(|(s, _)| std::cmp::Reverse(weight(s.modifiers)));
    all
}
