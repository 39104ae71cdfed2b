//! The Methods view's own state, keys and job (issue 26, 36): what its work axis
//! shows, and its rows (every method's run, timed or not), asked while it is shown.
//! Its key works from every view (the axis is kept for when the view opens).

use super::figure::{Figure, FigureCx, NoFigure};
use super::pane::{Pane, PaneCx};
use crate::lab::jobs::{Job, State};
use crate::lab::{Generation, Lab, analyses};
use crate::study::compare::Row;
use crate::tui::interact::{Input, Interactive};
use crate::tui::jobs::{Jobs, Notice};
use crate::tui::vocabulary::{Action, Handled, View, WorkAxis};

/// The Methods view's work axis.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct MethodsState {
    axis: WorkAxis,
}

impl MethodsState {
    /// What the work axis shows: steps, right-hand-side evaluations or time.
    pub fn axis(&self) -> WorkAxis {
        self.axis
    }

    /// What `action` does to the view: `X` cycles the work axis.
    fn key(&mut self, action: Action) -> Handled {
        match action {
            Action::CycleWorkAxis => {
                self.axis = self.axis.next();
                Handled::Say(format!("work axis: {}", self.axis.name()))
            }
            _ => Handled::Ignored,
        }
    }
}

impl Interactive<()> for MethodsState {
    fn handle(&mut self, input: &Input, (): ()) -> Handled {
        match input {
            Input::Key(action) => self.key(*action),
            Input::Mouse(..) => Handled::Ignored,
        }
    }
}

/// The Methods view's rows, timed or not.
#[derive(Clone, Debug, Default)]
pub struct MethodRows {
    rows: Job<(Generation, bool), Vec<Row>>,
}

impl MethodRows {
    /// Asks for this scene's rows while the view is `shown` (timed if `timed`: the
    /// timing runs cost more, and only the time axis shows them); leaving the view
    /// stops a running job and keeps finished rows until the scene changes.
    pub fn sync(&mut self, shown: bool, timed: bool, lab: &Lab, jobs: &Jobs) {
        let generation = lab.generation();
        if !shown {
            match self.rows.key() {
                Some((g, _)) if *g != generation => self.rows.cancel(),
                _ => self.rows.stop_running(),
            }
            return;
        }
        // Timed rows serve every axis: going back to steps keeps the scene's timed rows.
        let timed = timed || self.rows.key() == Some(&(generation, true));
        let work = analyses::method_rows(lab, timed);
        self.rows
            .request(jobs, (generation, timed), Notice::MethodRows, work);
    }

    pub fn state(&self) -> State<'_, Vec<Row>> {
        self.rows.state()
    }
}

/// The Methods view: its work axis and its rows.
#[derive(Clone, Debug, Default)]
pub struct Methods {
    pub state: MethodsState,
    pub rows: MethodRows,
}

impl Pane for Methods {
    fn view(&self) -> Option<View> {
        Some(View::Methods)
    }

    /// The diagram, withheld while the outcome is hidden (its runs name it).
    fn figure(&self, cx: &FigureCx) -> Option<Result<Figure, NoFigure>> {
        Some(if cx.hide.derived() {
            Err(NoFigure::Hidden("the Methods diagram"))
        } else {
            Ok(Figure::Methods)
        })
    }

    fn handle(&mut self, input: &Input, _: &mut PaneCx<'_>) -> Handled {
        self.state.handle(input, ())
    }

    fn sync(&mut self, cx: &PaneCx<'_>) {
        let timed = self.state.axis() == WorkAxis::Time;
        let shown = cx.shown == View::Methods;
        self.rows.sync(shown, timed, cx.lab, cx.jobs);
    }
}
