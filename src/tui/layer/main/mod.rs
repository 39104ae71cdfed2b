//! The main screen, the bottom layer of the compositor (issue 36, helix's editor view
//! at the bottom of its stack): the views, each a component that owns its state, its
//! keys (its rows of the one key table) and its slow work (a gitui tab holding its own
//! job), and which of them is shown. What the popups leave reaches here: the view shown
//! first, then the others whose keys work from every view; what none takes is the
//! app's (playback, the parameters, the popups' keys). Like the popups, this knows
//! nothing of the app: it is handed the lab, the jobs and the moment ([`PaneCx`]).
//! The views draw in `view/` (they read the whole app there).

pub mod charts;
mod figure;
pub mod fit;
pub mod forces;
pub mod map;
pub mod methods;
mod pane;
pub mod params;
pub mod video;
pub mod zoom;

use crate::tui::interact::Input;
use crate::tui::jobs::Notice;
use crate::tui::vocabulary::{Action, Handled, View};

pub use figure::{Figure, FigureCx, NoFigure};
pub use pane::{AnyPane, Pane, PaneCx, Pointer};

/// The main screen: the view shown and every view's pane.
#[derive(Debug)]
pub struct MainScreen {
    shown: View,
    panes: Vec<Box<dyn Pane>>,
}

impl Default for MainScreen {
    /// The views, registered: a new view is its line here.
    fn default() -> Self {
        MainScreen {
            shown: View::Charts,
            panes: vec![
                Box::new(charts::Charts::default()),
                Box::new(forces::ForcesState::default()),
                Box::new(methods::Methods::default()),
                Box::new(map::MapPane),
                Box::new(fit::FitRuns::default()),
                Box::new(video::VideoRun::default()),
                // Last: a view's own arrows (the zoom's, the fit window's) go first.
                Box::new(params::ParamsState::default()),
            ],
        }
    }
}

impl Clone for MainScreen {
    fn clone(&self) -> Self {
        MainScreen {
            shown: self.shown,
            panes: self.panes.iter().map(|p| p.boxed()).collect(),
        }
    }
}

impl MainScreen {
    /// The pane of type `T` (every view's is registered).
    pub fn get<T: Pane + 'static>(&self) -> &T {
        self.panes
            .iter()
            .find_map(|p| p.as_any().downcast_ref())
            .expect("every pane is registered in MainScreen::default")
    }

    pub fn get_mut<T: Pane + 'static>(&mut self) -> &mut T {
        self.panes
            .iter_mut()
            .find_map(|p| p.as_any_mut().downcast_mut())
            .expect("every pane is registered in MainScreen::default")
    }

    /// The panes, the one of the view shown first (its keys before the others': the
    /// ball key is the Forces view's there, the charts' elsewhere).
    fn panes(&mut self) -> impl Iterator<Item = &mut Box<dyn Pane>> {
        let shown = Some(self.shown);
        let first = self.panes.iter().position(|p| p.view() == shown);
        let (before, from) = self.panes.split_at_mut(first.unwrap_or(0));
        let (own, after) = from.split_at_mut(from.len().min(1));
        own.iter_mut()
            .chain(before.iter_mut())
            .chain(after.iter_mut())
    }

    /// The view shown.
    pub fn shown(&self) -> View {
        self.shown
    }

    /// True while the view shown shows the charts (its pane says so).
    pub fn charts_shown(&self) -> bool {
        self.panes
            .iter()
            .any(|p| p.view() == Some(self.shown) && p.shows_charts())
    }

    /// Shows `view` (the predict key shows the Forces view).
    pub fn show(&mut self, view: View) {
        self.shown = view;
    }

    /// What `W` writes from the view shown: its figure or why none; a view that shows
    /// the charts writes theirs.
    pub fn figure(&self, cx: &FigureCx) -> Result<Figure, NoFigure> {
        self.panes
            .iter()
            .filter(|p| p.view() == Some(self.shown))
            .find_map(|p| p.figure(cx))
            .unwrap_or_else(|| self.get::<charts::Charts>().state.figure())
    }

    /// Offers `input` to the views, the one shown first; a view key shows its view
    /// (or the charts again) and tells the views. [`Handled::Ignored`]: none took it.
    pub fn handle(&mut self, input: &Input, cx: &mut PaneCx<'_>) -> Handled {
        // Esc leaves a view for the charts, as its own key again does (a new user
        // pressed Esc in the Forces view and was told only that q quits); a view that
        // takes Esc itself keeps it.
        if let Input::Key(Action::Cancel) = *input
            && self.shown != View::Charts
        {
            let answer = self.offer(input, cx);
            if answer != Handled::Ignored {
                return answer;
            }
            return self.handle(&Input::Key(Action::ShowView(self.shown)), cx);
        }
        if let Input::Key(Action::ShowView(view)) = *input {
            self.shown = if self.shown == view {
                View::Charts
            } else {
                view
            };
            cx.shown = self.shown;
            cx.charts_shown = self.charts_shown();
            let answer = self.offer(input, cx);
            return if answer == Handled::Ignored {
                Handled::Consumed
            } else {
                answer
            };
        }
        self.offer(input, cx)
    }

    fn offer(&mut self, input: &Input, cx: &mut PaneCx<'_>) -> Handled {
        for pane in self.panes() {
            let answer = pane.handle(input, cx);
            if answer != Handled::Ignored {
                return answer;
            }
        }
        Handled::Ignored
    }

    /// Every view asks for the work it wants of this scene.
    pub fn sync(&mut self, cx: &PaneCx<'_>) {
        for pane in self.panes() {
            pane.sync(cx);
        }
    }

    /// A job's notice offered to the views: what the one whose job it was says.
    pub fn notice(&mut self, notice: Notice, cx: &mut PaneCx<'_>) -> Handled {
        for pane in self.panes() {
            let answer = pane.notice(notice, cx);
            if answer != Handled::Ignored {
                return answer;
            }
        }
        Handled::Ignored
    }

    /// The cursor moved to `t`; the charts' unzoomed span is `span`.
    pub fn moved(&mut self, t: f64, span: (f64, f64)) {
        for pane in self.panes() {
            pane.moved(t, span);
        }
    }

    /// Other data than before: what the views chose for the old ones goes.
    pub fn data_changed(&mut self) {
        for pane in self.panes() {
            pane.data_changed();
        }
    }
}
