//! The popups that take keys of their own: the preset picker and the text prompts
//! (typing a value, a save name, an export file name), and what confirming them does
//! (set the value, save the preset, write the export).

use crate::input::preset::{SaveError, save};
use crate::lab::Exported;
use crate::settings::params::Param;
use crate::settings::units::{Dimension, parse_typed, show};

use super::{Action, App, ChartBall, Export, Field, Library, Mode, ROWS, Status};
use crate::tui::line::History;

impl App {
    pub(super) fn apply_picker(&mut self, i: usize, action: Action) {
        let n = self.library.presets.len().max(1);
        match action {
            Action::Up => self.mode = Mode::Picker((i + n - 1) % n),
            Action::Down | Action::NextParam => self.mode = Mode::Picker((i + 1) % n),
            Action::Confirm | Action::Edit => {
                self.mode = Mode::Normal;
                if let Some(p) = self.library.presets.get(i).cloned() {
                    let (name, description) = (p.name.clone(), p.description.clone());
                    match self.lab.load_preset(p) {
                        Ok(()) => {
                            self.t = self.lab.solution.t_start;
                            self.status = Status::Info(match self.lab.own_data() {
                                // The student's data stay; the preset is the model.
                                Some(d) => format!(
                                    "preset {name} for the model; your data {} kept (D drops them)",
                                    d.name
                                ),
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

    /// Writes the run (CSV) or the chart on screen (SVG) to `name` (in `export_dir`
    /// unless absolute), through a temporary file; says where in the status line.
    fn export(&mut self, kind: Export, name: &str) -> Result<(), String> {
        let name = name.trim();
        if name.is_empty() {
            return Err("give a file name".into());
        }
        let path = self.export_dir.join(name);
        // What can be told at once keeps the prompt open; the writing itself (the SVG
        // takes milliseconds) runs as a job and reports in the status line.
        if let Some(dir) = path
            .parent()
            .filter(|d| !d.as_os_str().is_empty() && !d.is_dir())
        {
            return Err(format!(
                "cannot write {}: no folder {}",
                path.display(),
                dir.display()
            ));
        }
        let sol = std::sync::Arc::clone(&self.lab.solution);
        let work: Box<ExportWork> = match kind {
            Export::Csv => Box::new(move || {
                let dt = export_step(sol.t_end - sol.t_start);
                let samples = sol.sample(dt);
                let text = crate::study::export::run_csv(&sol, Some(&samples))?;
                let what = format!(
                    "{} samples every {}",
                    samples.len(),
                    show(dt, Dimension::Time)
                );
                Ok((text.into_bytes(), what))
            }),
            Export::Svg => {
                if self.show_energy {
                    return Err(
                        "the energy chart has no SVG export yet: press e for the velocities, x for positions"
                            .into(),
                    );
                }
                let which = if self.show_positions {
                    crate::study::figures::RunChart::Positions
                } else {
                    crate::study::figures::RunChart::Velocities {
                        left: self.chart_ball != ChartBall::Right,
                        right: self.chart_ball != ChartBall::Left,
                    }
                };
                let measured = self
                    .lab
                    .measured()
                    .filter(|_| self.chart_ball != ChartBall::Right && !self.show_positions)
                    .cloned();
                Box::new(move || {
                    let text = crate::study::figures::run_chart(&sol, which, measured.as_ref())?;
                    Ok((text.into_bytes(), "the chart".to_string()))
                })
            }
        };
        self.status = Status::Info(format!("writing {}…", path.display()));
        self.lab.start_export(move || {
            let (bytes, what) = work()?;
            crate::output::write_atomically(&path, &bytes)?;
            Ok::<_, ExportError>(Exported { path, what })
        });
        Ok(())
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
            Err(e) => self.status = Status::Error(format!("not applied: {} {e}", p.label)),
        }
    }

    /// Saves the scene as a user preset, asking before it replaces a file.
    pub(super) fn save(&mut self, name: &str, overwrite: bool) {
        match save(&self.lab, self.library.dir.as_deref(), name, overwrite) {
            Ok(path) => {
                self.library = Library::at(self.library.dir.clone());
                self.status = Status::Info(format!("saved {}", path.display()));
            }
            Err(SaveError::Exists(_)) => self.mode = Mode::ConfirmOverwrite(name.trim().into()),
            Err(e @ SaveError::BadName(_)) => {
                // Keep the dialog open with the name as typed, and say why.
                self.status = Status::Error(format!("not saved: {e}"));
                self.mode = Mode::SaveName(Field::new(name));
            }
            Err(e) => self.status = Status::Error(format!("not saved: {e}")),
        }
    }
}

/// Why an export wrote nothing.
#[derive(Debug, thiserror::Error)]
pub enum ExportError {
    #[error(transparent)]
    Csv(#[from] csv::Error),
    #[error("cannot draw the chart: {0}")]
    Chart(#[from] crate::study::figures::FigureError),
    #[error(transparent)]
    Write(#[from] crate::output::OutputError),
}

/// The body of an export job: the file's bytes and what they are, or why not.
type ExportWork = dyn FnOnce() -> Result<(Vec<u8>, String), ExportError> + Send;

#[derive(Clone, Copy)]
pub(super) enum TextTarget {
    Value,
    Name,
    Export(Export),
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

/// One history per kind of prompt ([`TextTarget::index`]).
pub(super) type Histories = [History; 3];

/// The CSV export's sample step for a run `span` seconds long: 1 ms, coarser (1-2-5)
/// for long runs so that a file stays under about 10,000 rows.
pub fn export_step(span: f64) -> f64 {
    let mut dt = 1e-3;
    for factor in [2.0, 2.5, 2.0].iter().cycle() {
        if span / dt <= 10_000.0 || !dt.is_finite() {
            break;
        }
        dt *= factor;
    }
    dt
}

/// The prompt of the typing field for parameter `p`: which unit a bare number is in.
pub fn typing_prompt(p: &Param) -> String {
    let (unit, _) = p.dim.display_unit();
    let example = match p.dim {
        Dimension::Length => "44mm",
        Dimension::Mass => "0.2kg",
        Dimension::Speed => "60cm/s",
        Dimension::Time => "200ms",
        Dimension::Acceleration => "9.81",
        Dimension::Ratio => "",
    };
    let name = p.label;
    if unit.is_empty() {
        format!("{name}: a plain number (e.g. 0.17), Enter applies, Esc cancels")
    } else {
        format!("{name} in {unit} (or with a unit, e.g. {example}), Enter applies, Esc cancels")
    }
}
