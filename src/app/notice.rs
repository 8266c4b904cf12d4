//! What the application tells the user: a line in the status bar, or a message box for
//! errors and warnings that must not be missed. Every tab keeps its own [`Notices`]; the shell
//! shows the current tab's status line and every tab's message boxes.

/// One thing to tell the user.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Notice {
    /// A line for the status bar (replaces the previous one).
    Status(String),
    /// A message box with a title (errors, warnings about a file).
    Message { title: String, text: String },
}

/// The notices of one tab.
#[derive(Clone, Debug, Default)]
pub struct Notices {
    /// The current status line.
    pub status: String,
    messages: Vec<(String, String)>,
}

impl Notices {
    /// Replace the status line.
    pub fn status(&mut self, text: impl Into<String>) {
        self.status = text.into();
    }

    /// Ask for a message box.
    pub fn message(&mut self, title: impl Into<String>, text: impl Into<String>) {
        self.messages.push((title.into(), text.into()));
    }

    pub fn push(&mut self, n: Notice) {
        match n {
            Notice::Status(s) => self.status(s),
            Notice::Message { title, text } => self.message(title, text),
        }
    }

    /// The message boxes asked for since the last call.
    pub fn take_messages(&mut self) -> Vec<(String, String)> {
        std::mem::take(&mut self.messages)
    }
}
