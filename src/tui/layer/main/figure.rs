//! What `W` writes from the view shown ([`Figure`]), or why it writes nothing
//! ([`NoFigure`]): each view answers for itself ([`super::Pane::figure`]) from what is
//! hidden and whether there are data ([`FigureCx`]).

use crate::tui::hide::Hide;

/// The figure `W` writes: the one on screen.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Figure {
    Velocities,
    Positions,
    /// The regime over b and e (the Map view).
    Map,
    /// Error against work of every method (the Methods view).
    Methods,
    /// The measured series, the fitted model and the residuals (the Fit view).
    Fit,
}

impl Figure {
    /// The file name's part after the preset's name.
    pub fn name(self) -> &'static str {
        match self {
            Figure::Velocities => "chart",
            Figure::Positions => "positions",
            Figure::Map => "map",
            Figure::Methods => "methods",
            Figure::Fit => "fit",
        }
    }

    /// What the file will hold, for the prompt.
    pub fn describe(self) -> &'static str {
        match self {
            Figure::Velocities => "the velocity chart on screen",
            Figure::Positions => "the position chart on screen",
            Figure::Map => "the regime map over b and e (the Map view)",
            Figure::Methods => {
                "error against work of every method, as on screen (the Methods view)"
            }
            Figure::Fit => "the data, the fitted model and the residuals (the Fit view)",
        }
    }
}

/// Why the view shown has no figure to write (the app's export says it in its words).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum NoFigure {
    /// The Forces view draws no SVG.
    Forces,
    /// The energy chart draws no SVG yet.
    Energy,
    /// The screen withholds it while the outcome is hidden (predict mode, b hidden).
    Hidden(&'static str),
}

/// What a view needs to say what `W` writes: what is hidden, and whether the lab
/// holds measured data.
#[derive(Clone, Copy, Debug)]
pub struct FigureCx {
    pub hide: Hide,
    pub measured: bool,
}
