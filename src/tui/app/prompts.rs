//! The popups that take keys of their own: the preset picker and the text prompts
//! (typing a value, a save name, an export file name), and what confirming them does
//! (set the value, save the preset, write the export).

use crate::input::preset::{PresetFile, SaveError, ToSave};
use crate::settings::units::parse_typed;

use super::{Action, App, Field, Library, Mode, NO_FILES, ROWS, Status, TextTarget};
use crate::tui::line::History;

impl App {
    pub(super) fn apply_picker(&mut self, i: usize, action: Action) {
        let n = self.library.presets.len().max(1);
        match action {
            Action::Up => self.mode = Mode::Picker((i + n - 1) % n),
            Action::Down | Action::NextParam => self.mode = Mode::Picker((i + 1) % n),
            // A click: on another preset selects it, on the selected one loads it (a
            // double click does both).
            Action::Select(j) if j != i && j < self.library.presets.len() => {
                self.mode = Mode::Picker(j);
            }
            Action::Select(j) if j != i => {}
            Action::Confirm | Action::Edit | Action::Select(_) => {
                self.mode = Mode::Normal;
                if let Some(p) = self.library.presets.get(i).cloned() {
                    let (name, description) = (p.name.clone(), p.description.clone());
                    match self.lab.load_preset(p) {
                        Ok(()) => {
                            self.fit.window = (None, None);
                            self.t = self.lab.solution.t_start;
                            self.status = Status::Info(match self.lab.own_data() {
                                // The student's data stay (the status line names
                                // them); the preset is the model.
                                Some(_) => {
                                    format!("model: preset {name}; your data kept (D drops them)")
                                }
                                None => description,
                            });
                        }
                        Err(e) => self.status = Status::Error(format!("preset {name}: {e}")),
                    }
                }
            }
            Action::Cancel | Action::Presets => self.mode = Mode::Normal,
            _ => {}
        }
    }

    pub(super) fn apply_text(&mut self, mut field: Field, action: Action, target: TextTarget) {
        let reopen = |field: Field| match target {
            TextTarget::Value => Mode::Edit(field),
            TextTarget::Name => Mode::SaveName(field),
            TextTarget::Export(kind) => Mode::Export(kind, field),
        };
        match action {
            Action::Line(request) => field.edit(request),
            Action::Up => field.earlier(&self.history(target).0),
            Action::Down => field.later(&self.history(target).0),
            Action::Cancel => {
                self.mode = Mode::Normal;
                self.status = Status::Info("cancelled".into());
                return;
            }
            Action::Confirm | Action::Edit => {
                self.mode = Mode::Normal;
                let text = field.value().to_string();
                // Enter on an empty line is no answer: the prompt closes as with Esc.
                if text.trim().is_empty() {
                    self.status = Status::Info("cancelled (nothing typed)".into());
                    return;
                }
                self.history_mut(target).push(&text);
                match target {
                    TextTarget::Value => self.typed_value(&text),
                    TextTarget::Name => self.save(&text, false),
                    TextTarget::Export(kind) => {
                        if let Err(e) = self.export(kind, &text) {
                            // Keep the prompt open with the name, and say why.
                            self.status = Status::Error(format!("not written: {e}"));
                            self.mode = Mode::Export(kind, field);
                        }
                    }
                }
                return;
            }
            _ => {}
        }
        self.mode = reopen(field);
    }

    /// The entries confirmed earlier in prompts like `target` (values, names, files).
    fn history(&self, target: TextTarget) -> &History {
        &self.histories[target.index()]
    }

    fn history_mut(&mut self, target: TextTarget) -> &mut History {
        &mut self.histories[target.index()]
    }

    fn typed_value(&mut self, text: &str) {
        let p = ROWS[self.selected];
        match parse_typed(text, p.dim) {
            Ok(v) => self.set_value(p.key, v),
            Err(e) => self.status = Status::Error(format!("not applied: {} {e}", p.screen_label())),
        }
    }

    /// Saves the scene as a user preset, asking before it replaces a file.
    pub(super) fn save(&mut self, name: &str, overwrite: bool) {
        let spec = self.lab.saved_spec();
        let scene = ToSave {
            spec: &spec,
            measured: self.lab.measured(),
            started_from: &self.lab.preset().name,
        };
        let file = PresetFile::new(scene, self.library.dir.as_deref(), name, overwrite);
        let file = match file {
            Ok(file) if !self.writes_files => {
                self.status = Status::Info(format!(
                    "{NO_FILES}: would save preset {} as {}",
                    name.trim(),
                    file.path.display()
                ));
                return;
            }
            other => other.and_then(PresetFile::write),
        };
        match file {
            Ok(path) => {
                self.library = Library::at(self.library.dir.clone());
                self.status = Status::Info(format!("saved {}", path.display()));
            }
            Err(SaveError::Exists(_)) => self.mode = Mode::ConfirmOverwrite(name.trim().into()),
            Err(e @ SaveError::BadName { .. }) => {
                // Keep the dialog open with the name as typed, and say why.
                self.status = Status::Error(format!("not saved: {e}"));
                self.mode = Mode::SaveName(Field::new(name));
            }
            Err(e) => self.status = Status::Error(format!("not saved: {e}")),
        }
    }
}

impl TextTarget {
    /// Which history the prompt's ↑/↓ go through: values, preset names, file names.
    fn index(self) -> usize {
        match self {
            TextTarget::Value => 0,
            TextTarget::Name => 1,
            TextTarget::Export(_) => 2,
        }
    }
}
