//! What the export keys write: `w` the run as CSV, its scene in comment lines first
//! (so that it loads back as data with its scene), `W` the figure of the view on
//! screen (the velocity or position chart, the regime map, the Methods diagram, the
//! fit) as SVG; written as a job through the one atomic writer.

use crate::lab::Exported;
use crate::lab::jobs::State;
use crate::settings::units::{Dimension, show};
use crate::study::figures;

pub use crate::tui::layer::main::Figure;
use crate::tui::layer::main::{FigureCx, NoFigure};

use super::{App, ChartBall, Export, NO_FILES, Status};
use crate::tui::vocabulary::WorkAxis;

/// Grid of the exported regime map: finer than a terminal's cells.
const MAP_GRID: (usize, usize) = (160, 80);

/// Why `w` or `W` writes nothing, told before any job starts (the prompt stays open
/// or is not opened, and the status line says this).
#[derive(Debug, thiserror::Error)]
pub enum NoExport {
    #[error(
        "the Forces view has no SVG export: W writes the charts, the Map, the Methods and the Fit view"
    )]
    Forces,
    #[error("the energy chart has no SVG export yet: press e for the velocities, x for positions")]
    Energy,
    /// The screen withholds what the file would show (predict mode, b hidden).
    #[error("{0} would tell the hidden outcome: it can be written once the outcome shows")]
    Hidden(&'static str),
    #[error("give a file name")]
    NoName,
    #[error("cannot write {}: no folder {}", path.display(), dir.display())]
    NoFolder {
        path: std::path::PathBuf,
        dir: std::path::PathBuf,
    },
    #[error("the methods are still running: export when the diagram is drawn")]
    MethodsRunning,
    #[error("no fit to draw: {0}")]
    NoFit(crate::study::fit::FitError),
    #[error("the fit is still being computed: export when it is shown")]
    FitRunning,
}

impl From<NoFigure> for NoExport {
    fn from(why: NoFigure) -> NoExport {
        match why {
            NoFigure::Forces => NoExport::Forces,
            NoFigure::Energy => NoExport::Energy,
            NoFigure::Hidden(what) => NoExport::Hidden(what),
        }
    }
}

/// Why an export job wrote nothing.
#[derive(Debug, thiserror::Error)]
pub enum ExportError {
    #[error(transparent)]
    Csv(#[from] csv::Error),
    #[error("cannot draw the figure: {0}")]
    Figure(#[from] figures::FigureError),
    #[error(transparent)]
    Write(#[from] crate::output::OutputError),
}

/// The body of an export job: the file's bytes and what they are, or why not.
type ExportWork = dyn FnOnce() -> Result<(Vec<u8>, String), ExportError> + Send;

impl App {
    /// Whether b is no longer the preset's (a preset's name may state b: paper-b4.9):
    /// set on the command line or in the app.
    pub(super) fn scene_edited(&self) -> bool {
        use crate::lab::Edit;
        use crate::settings::params::Key;
        let settings = self.lab.settings();
        settings
            .in_force()
            .iter()
            .any(|e| matches!(e, Edit::Values(v) | Edit::Fitted(v) if v.iter().any(|(k, _)| *k == Key::Width)))
            || settings
                .flags_in_force()
                .is_some_and(|f| f.given().any(|(k, _)| k == Key::Width))
    }

    /// The figure `W` writes from the view on screen, or why there is none (a view
    /// the screen withholds while the outcome is hidden is not written either): the
    /// view shown answers.
    pub fn figure_on_screen(&self) -> Result<Figure, NoExport> {
        let cx = FigureCx {
            hide: self.hidden(),
            measured: self.lab.measured().is_some(),
        };
        Ok(self.layers().main().figure(&cx)?)
    }

    /// Writes the run (CSV) or the figure on screen (SVG) to `name` (in `export_dir`
    /// unless absolute), through a temporary file; says where in the status line.
    pub(super) fn export(&mut self, kind: Export, name: &str) -> Result<(), NoExport> {
        let name = name.trim();
        if name.is_empty() {
            return Err(NoExport::NoName);
        }
        // A name without an extension gets the file's kind's (a typed "run" is
        // run.csv; "fig.v2" keeps its own).
        let name = if std::path::Path::new(name).extension().is_some() {
            name.to_string()
        } else {
            format!("{name}.{}", kind.extension())
        };
        let path = self.export_dir.join(name);
        // What can be told at once keeps the prompt open; the writing itself (the SVG
        // takes milliseconds) runs as a job and reports in the status line.
        if let Some(dir) = path
            .parent()
            .filter(|d| !d.as_os_str().is_empty() && !d.is_dir())
        {
            return Err(NoExport::NoFolder {
                dir: dir.to_path_buf(),
                path,
            });
        }
        let work = match kind {
            // The run's file holds the whole run (and b): nothing of it while hidden.
            Export::Csv if self.hidden().derived() => return Err(NoExport::Hidden("the run")),
            Export::Csv => self.csv_work(),
            Export::Svg => self.svg_work(self.figure_on_screen()?)?,
        };
        if !self.writes_files {
            self.status = Status::Info(format!("{NO_FILES}: would write {}", path.display()));
            return Ok(());
        }
        if kind == Export::Csv {
            // The run's file holds its scene, which `--data FILE` loads back.
            self.kept = Some(self.lab.scene);
        }
        self.status = Status::Info(format!("writing {}…", path.display()));
        self.export.start(&self.jobs, move || {
            let (bytes, what) = work()?;
            crate::output::write_atomically(&path, &bytes)?;
            Ok::<_, ExportError>(Exported { path, what })
        });
        Ok(())
    }

    /// The run sampled as `simulate --format csv --sample` gives it, after its scene
    /// as comment lines.
    fn csv_work(&self) -> Box<ExportWork> {
        let sol = std::sync::Arc::clone(&self.lab.solution);
        let scene = crate::study::export::scene_comments(&self.lab.saved_spec());
        Box::new(move || {
            let dt = export_step(sol.t_end - sol.t_start);
            let samples = sol.sample(dt);
            let text = crate::study::export::run_csv(&sol, Some(&samples))?;
            let what = format!(
                "its scene and {} samples every {}",
                samples.len(),
                show(dt, Dimension::Time)
            );
            Ok((format!("{scene}{text}").into_bytes(), what))
        })
    }

    /// `figure`, with what it needs taken from the lab now.
    fn svg_work(&self, figure: Figure) -> Result<Box<ExportWork>, NoExport> {
        let scene = self.lab.scene;
        let what = figure.describe().trim_start_matches("the ").to_string();
        let done = move |svg: Result<String, figures::FigureError>| Ok((svg?.into_bytes(), what));
        Ok(match figure {
            Figure::Velocities | Figure::Positions => {
                let sol = std::sync::Arc::clone(&self.lab.solution);
                let which = if figure == Figure::Positions {
                    figures::RunChart::Positions
                } else {
                    figures::RunChart::Velocities {
                        left: self.charts().ball() != ChartBall::Right,
                        right: self.charts().ball() != ChartBall::Left,
                    }
                };
                let measured = self
                    .lab
                    .measured()
                    .filter(|_| {
                        self.charts().ball() != ChartBall::Right && figure == Figure::Velocities
                    })
                    .cloned();
                // What the screen shows beside the run: the pinned run, and the caption
                // of data measured in another groove; and as much of it as the screen
                // shows: its time zoom, nothing past the cursor while the outcome is
                // hidden, no b while b is.
                let hide = self.hidden();
                let label = |scene| match hide.b() {
                    true => "run".to_string(),
                    false => pinned_label(scene),
                };
                let pinned = self
                    .lab
                    .pinned
                    .as_ref()
                    .map(|p| (std::sync::Arc::clone(&p.solution), label(&p.scene)));
                let note = measured
                    .as_ref()
                    .and(self.lab.resolved().other_groove.as_ref().map(|o| {
                        if hide.b() {
                            "the data were measured in another groove (b hidden)".to_string()
                        } else {
                            o.describe()
                        }
                    }));
                let range = (hide.derived() || self.chart_range() != self.chart_span())
                    .then(|| self.chart_range());
                let until = hide.derived().then_some(self.t);
                Box::new(move || {
                    let beside = figures::Beside {
                        pinned: pinned.as_ref().map(|(p, l)| (p.as_ref(), l.as_str())),
                        note: note.as_deref(),
                        range,
                        until,
                        b_hidden: hide.b(),
                    };
                    done(figures::run_chart(&sol, which, measured.as_ref(), beside))
                })
            }
            Figure::Map => {
                let preset = self.lab.preset().name.clone();
                Box::new(move || {
                    let (points, x, y) = regime_grid(&scene);
                    done(figures::regime_map(&points, &x, Some(&y), &scene, &preset))
                })
            }
            Figure::Methods => match self.methods().state() {
                State::Ready(rows) => {
                    let rows = rows.clone();
                    let work = match self.methods_state().axis() {
                        WorkAxis::Steps => figures::Cost::Steps,
                        WorkAxis::RhsEvals => figures::Cost::RhsEvals,
                        WorkAxis::Time => figures::Cost::Time,
                    };
                    Box::new(move || done(figures::work_precision_against(&rows, &scene, work)))
                }
                _ => return Err(NoExport::MethodsRunning),
            },
            Figure::Fit => match (self.fit().fits(), self.lab.measured()) {
                (State::Ready(Ok(fits)), Some(m)) => {
                    let (fits, m) = (fits.clone(), m.clone());
                    Box::new(move || done(figures::fit_figure(&scene, &m, &fits)))
                }
                (State::Ready(Err(e)), _) => return Err(NoExport::NoFit(e.clone())),
                _ => return Err(NoExport::FitRunning),
            },
        })
    }
}

/// The Map view's regime over b (0 … 2R·0.99) and e (0 … 1) of `scene`, as the view
/// computes it (the analytic regime of each cell), on [`MAP_GRID`].
fn regime_grid(
    scene: &crate::physics::scene::Scene,
) -> (
    Vec<crate::study::sweep::GridPoint>,
    crate::study::sweep::SweepAxis,
    crate::study::sweep::SweepAxis,
) {
    use crate::settings::params::Key;
    use crate::study::sweep::{GridPoint, SweepAxis};
    let x = SweepAxis {
        key: Key::Width,
        lo: 0.0,
        hi: 2.0 * scene.radius * 0.99,
        n: MAP_GRID.0,
    };
    let y = SweepAxis {
        key: Key::Restitution,
        lo: 0.0,
        hi: 1.0,
        n: MAP_GRID.1,
    };
    let points = (0..y.n)
        .flat_map(|j| (0..x.n).map(move |i| (i, j)))
        .map(|(i, j)| {
            let cell = crate::physics::scene::Scene {
                width: x.value(i),
                restitution: y.value(j),
                ..*scene
            };
            GridPoint {
                x: cell.width,
                y: Some(cell.restitution),
                regime: crate::physics::derived::Derived::of(&cell).regime,
                v_ratio: None,
                t_roll: None,
                impacts: 0,
                t_accumulation: None,
            }
        })
        .collect();
    (points, x, y)
}

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

/// A pinned run as the chart's legend names it: its groove width.
fn pinned_label(scene: &crate::physics::scene::Scene) -> String {
    format!("b = {}", show(scene.width, Dimension::Length))
}

/// The part of an export's file name that says which scene it shows: the preset's
/// name (or the data file's) while b is the preset's, else the groove width shown
/// (`b3.5cm`), and the pinned run's beside it (`b3.5cm-vs-b4.9cm`); while the outcome
/// is hidden (`hidden`) neither (a preset's name may state b or the outcome), only
/// `prediction`.
pub fn shown_name(lab: &crate::lab::Lab, edited: bool, hidden: bool) -> String {
    if hidden {
        return "prediction".into();
    }
    let width = |scene: &crate::physics::scene::Scene| {
        let shown = Dimension::Length.to_display(scene.width);
        let unit = Dimension::Length.display_unit().0;
        format!("b{}{unit}", crate::settings::units::significant(shown, 4))
    };
    // A data file that names its own scene names the export, until the app changes it.
    let own_file = lab.scene_name() != lab.preset().name && lab.settings().in_force().is_empty();
    let own = if edited && !own_file {
        width(&lab.scene)
    } else {
        lab.scene_name()
    };
    match &lab.pinned {
        Some(p) if p.scene.width != lab.scene.width => format!("{own}-vs-{}", width(&p.scene)),
        Some(p) if p.scene != lab.scene => format!("{own}-and-pinned"),
        _ => own,
    }
}
