//! The Fit view's own state, keys and jobs (issue 36, a gitui tab holding its own
//! job): the line fit's window, the fits of the measured series (asked while the view
//! is shown), the window's keys, `a` (the fit into the scene) and `M` (its models).

use super::figure::{Figure, FigureCx, NoFigure};
use super::pane::{Pane, PaneCx, VideoData};
use crate::lab::jobs::{Job, State};
use crate::lab::{FitWindow, FitWindowError, Generation, Lab, analyses};
use crate::settings::params::Key;
use crate::settings::units::show;
use crate::study::fit::{FitError, Fits, ModelFit};
use crate::tui::interact::Input;
use crate::tui::jobs::{Jobs, Notice};
use crate::tui::vocabulary::{Action, Handled, Then, View};

/// The Fit view's fits of the measured series, and the line fit's window.
#[derive(Clone, Debug, Default)]
pub struct FitRuns {
    /// Line-fit window (None: the sliding phase).
    pub window: FitWindow,
    fits: Job<(Generation, FitWindow), Result<Fits, FitError>>,
}

impl FitRuns {
    /// Asks for this scene's fits while the Fit view is `shown`; leaving it stops a
    /// running fit (a finished one is kept); without data it is forgotten, so a fit of
    /// data no longer shown is neither drawn nor applied.
    pub fn sync(&mut self, shown: bool, lab: &Lab, jobs: &Jobs) {
        let Some(fits) = analyses::fits(lab, self.window) else {
            self.fits.cancel();
            return;
        };
        if !shown {
            self.fits.stop_running();
            return;
        }
        let generation = lab.generation();
        self.fits
            .request(jobs, (generation, self.window), Notice::Fits, fits);
    }

    pub fn fits(&self) -> State<'_, Result<Fits, FitError>> {
        self.fits.state()
    }

    /// Moves one end of the line-fit window by one measured frame (the fits follow at
    /// the next [`FitRuns::sync`]).
    pub fn move_window(&mut self, lab: &Lab, end: bool, later: bool) -> Result<(), FitWindowError> {
        let fitted = match self.fits.ready() {
            Some(Ok(f)) => f.line_fit.as_ref().map(|l| (l.from, l.to)),
            _ => None,
        };
        self.window = analyses::moved_fit_window(lab, self.window, fitted, end, later)?;
        Ok(())
    }

    /// The model fit `a` applies, and what to call it: the headline fit (of the model
    /// the data support; of a position track fitted to the positions), the one the
    /// panel shows first.
    fn to_apply(&self) -> Result<(ModelFit, &'static str), NoFitToApply> {
        match self.fits() {
            State::Ready(Ok(f)) => Ok((
                f.model_fit.clone(),
                match f.model_fit.fitted_to {
                    "positions" => "the position fit",
                    _ => "the fit",
                },
            )),
            State::Ready(Err(e)) => Err(NoFitToApply::Failed(e.clone())),
            State::Computing { .. } => Err(NoFitToApply::Running),
            State::Idle => Err(NoFitToApply::NoData),
        }
    }

    /// Fit view: puts the fitted μ_k (and v0, e where the fit freed them) into the
    /// scene: of a position track the position fit, the one the panel says to quote.
    fn apply(&self, lab: &mut Lab) -> Handled {
        if let (None, Some(unfit)) = (lab.measured(), lab.unfit()) {
            return Handled::Refused(format!(
                "no fit to apply: {} has none (f says why)",
                unfit.name
            ));
        }
        let (fitted, which) = match self.to_apply() {
            Ok(f) => f,
            Err(e) => return Handled::Refused(e.to_string()),
        };
        if let Some(n) = fitted.undetermined("mu") {
            return Handled::Refused(format!(
                "not applied: {which} does not determine μ_k ({})",
                n.reason
            ));
        }
        // μ_k is always fitted; v0, e and c_rr only when the fit freed them (they have
        // an uncertainty then): the scene becomes the fitted one.
        let mut changes = vec![(Key::Mu, fitted.mu, fitted.mu_se)];
        let freed = [
            (Key::V0, fitted.v0, fitted.v0_se),
            (Key::Restitution, fitted.restitution, fitted.restitution_se),
            (
                Key::RollingResistance,
                fitted.rolling_resistance,
                fitted.rolling_resistance_se,
            ),
        ];
        changes.extend(freed.into_iter().filter_map(|(k, v, se)| Some((k, v, se?))));
        // The refit of a scene a fit was applied to lands within a hair of it (its
        // frames move with the scene, and v0 stays free): each value within a tenth
        // of its ± of the scene's is the fit already there.
        let there = changes
            .iter()
            .all(|&(key, value, se)| (lab.value(key) - value).abs() <= 0.1 * se);
        let values: Vec<(Key, f64)> = changes.iter().map(|&(k, v, _)| (k, v)).collect();
        // All or nothing: a fit is never left half applied.
        let edits = lab.settings().edits().len();
        if !there && let Err(e) = lab.set_fitted(&values) {
            return Handled::Refused(format!("fit not applied: {e}"));
        }
        let applied: Vec<String> = values
            .iter()
            .map(|&(key, value)| {
                format!("{} = {}", key.param().symbol, show(value, key.dimension()))
            })
            .collect();
        // A second `a` changes nothing: no undo step, and it says so.
        Handled::Say(if lab.settings().edits().len() == edits {
            format!("{which} is in the scene already: {}", applied.join(", "))
        } else {
            format!("applied {which}: {}", applied.join(", "))
        })
    }
}

/// Why `a` finds no fit to apply.
#[derive(Debug, thiserror::Error)]
enum NoFitToApply {
    #[error("no fit to apply: {0}")]
    Failed(FitError),
    #[error("the fit is still running: try again")]
    Running,
    #[error("no fit to apply: this preset has no data")]
    NoData,
}

impl Pane for FitRuns {
    fn view(&self) -> Option<View> {
        Some(View::Fit)
    }

    fn shows_charts(&self) -> bool {
        true
    }

    /// The fit's figure with data (withheld with the Fit panel: it names the regimes);
    /// without data the view shows the charts.
    fn figure(&self, cx: &FigureCx) -> Option<Result<Figure, NoFigure>> {
        cx.measured.then_some(if cx.hide.derived() {
            Err(NoFigure::Hidden("the fit"))
        } else {
            Ok(Figure::Fit)
        })
    }

    fn handle(&mut self, input: &Input, cx: &mut PaneCx<'_>) -> Handled {
        let Input::Key(action) = *input else {
            return Handled::Ignored;
        };
        let shown = cx.shown == View::Fit;
        let moved = |fit: &mut FitRuns, end, later| match fit.move_window(cx.lab, end, later) {
            Ok(()) => Handled::Consumed,
            Err(e) => Handled::Refused(e.to_string()),
        };
        match action {
            // Opening the view without data says there are none to fit, or none yet
            // (the video still tracked: the preset's own would be none only until then).
            Action::ShowView(View::Fit)
                if shown && cx.lab.measured().is_none() && cx.lab.unfit().is_none() =>
            {
                match &cx.video {
                    Some(VideoData::Tracking(name)) => {
                        return Handled::Refused(format!(
                            "{name} is still being tracked: its data are fitted here when it is done"
                        ));
                    }
                    Some(VideoData::Refused { name, first_frame }) => {
                        return Handled::Refused(format!(
                            "{name} was not tracked, so there are no data to fit{}",
                            if *first_frame {
                                " (V: its first frame; click a ball there to track it again seeded)"
                            } else {
                                ""
                            }
                        ));
                    }
                    None => {}
                }
                Handled::Refused(format!(
                    "preset {} has no measured data to fit (the paper-b* presets have)",
                    cx.lab.preset().name
                ))
            }
            Action::FitStartEarlier => moved(self, false, false),
            Action::FitStartLater => moved(self, false, true),
            Action::FitEndEarlier => moved(self, true, false),
            Action::FitEndLater => moved(self, true, true),
            Action::ApplyFit if !shown => {
                Handled::Refused("a applies a fit: open the Fit view first (f)".into())
            }
            Action::ApplyFit => self.apply(cx.lab),
            Action::ModelsTable
                if shown && !cx.derived && matches!(self.fits(), State::Ready(Ok(_))) =>
            {
                Handled::Ask(Then::OpenModels)
            }
            Action::ModelsTable => Handled::Refused(
                "M lists the fit's models: in the Fit view (f), once the fit is there".into(),
            ),
            _ => Handled::Ignored,
        }
    }

    fn sync(&mut self, cx: &PaneCx<'_>) {
        self.sync(cx.shown == View::Fit, cx.lab, cx.jobs);
    }

    fn data_changed(&mut self) {
        // The window was chosen for the data before.
        self.window = (None, None);
    }
}
