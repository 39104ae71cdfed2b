//! The text prompts (a value typed on the status line, a save name, an export's file
//! name), each owning its line and going through the entries typed into prompts of its
//! kind before; and the question whether to overwrite a saved preset.

use crate::tui::interact::{Input, Interactive};
use crate::tui::line::History;
use crate::tui::vocabulary::{Action, Field, Handled, Mode, TextTarget, Then};

/// A prompt's typed line and what it is typed for.
#[derive(Clone, Debug, PartialEq)]
pub struct Prompt {
    target: TextTarget,
    field: Field,
}

impl Prompt {
    /// A prompt for `target` holding `field`.
    pub fn new(target: TextTarget, field: Field) -> Prompt {
        Prompt { target, field }
    }

    pub fn target(&self) -> TextTarget {
        self.target
    }

    pub fn field(&self) -> &Field {
        &self.field
    }

    /// The line of the value prompt, if this is it.
    pub fn editing_value(&self) -> Option<&Field> {
        (self.target == TextTarget::Value).then_some(&self.field)
    }

    pub(super) fn mode(&self) -> Mode {
        let field = self.field.clone();
        match self.target {
            TextTarget::Value => Mode::Edit(field),
            TextTarget::Name => Mode::SaveName(field),
            TextTarget::Export(kind) => Mode::Export(kind, field),
        }
    }
}

impl Interactive<&Histories> for Prompt {
    /// Typing edits the line, ↑/↓ go through the history, Enter confirms (an empty
    /// line is no answer: it closes as Esc does), Esc cancels; a click does nothing
    /// (it must not end the typing).
    fn handle(&mut self, input: &Input, histories: &Histories) -> Handled {
        let Input::Key(action) = input else {
            return Handled::Ignored;
        };
        match *action {
            Action::Line(request) => self.field.edit(request),
            Action::Up => self.field.earlier(&histories.of(self.target).0),
            Action::Down => self.field.later(&histories.of(self.target).0),
            Action::Cancel => return Handled::Close(Then::Say("cancelled".into())),
            Action::Confirm | Action::Edit if self.field.value().trim().is_empty() => {
                return Handled::Close(Then::Say("cancelled (nothing typed)".into()));
            }
            Action::Confirm | Action::Edit => {
                return Handled::Close(Then::Typed(self.target, self.field.clone()));
            }
            // Ctrl-C quits from anywhere.
            Action::Quit | Action::QuitNow => return Handled::Ignored,
            _ => {}
        }
        Handled::Consumed
    }
}

/// The entries confirmed in each kind of prompt this session, oldest first.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Histories([History; 3]);

impl Histories {
    /// The entries of prompts like `target` (values, names, files).
    pub fn of(&self, target: TextTarget) -> &History {
        &self.0[index(target)]
    }

    pub fn of_mut(&mut self, target: TextTarget) -> &mut History {
        &mut self.0[index(target)]
    }
}

/// Which history the prompt's ↑/↓ go through: values, preset names, file names.
fn index(target: TextTarget) -> usize {
    match target {
        TextTarget::Value => 0,
        TextTarget::Name => 1,
        TextTarget::Export(_) => 2,
    }
}

/// The save found a preset file of this name: overwrite it? (`y` does, any other
/// key does not.)
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Confirm {
    name: String,
}

impl Confirm {
    pub fn new(name: impl Into<String>) -> Confirm {
        Confirm { name: name.into() }
    }

    /// The preset's name.
    pub fn name(&self) -> &str {
        &self.name
    }
}

impl Interactive<()> for Confirm {
    fn handle(&mut self, input: &Input, (): ()) -> Handled {
        match input {
            Input::Key(Action::Type('y' | 'Y')) => {
                Handled::Close(Then::Overwrite(self.name.clone()))
            }
            Input::Key(Action::Quit | Action::QuitNow) | Input::Mouse(..) => Handled::Ignored,
            Input::Key(_) => Handled::Close(Then::Say("not saved".into())),
        }
    }
}
