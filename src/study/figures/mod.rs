//! Figures exported as SVG (plotters): the work–precision diagram of the methods, the
//! fit figure, the regime map, and a run's chart as the app shows it (`run_chart`).
//! Every axis range goes through `drawing`'s `linear_axis` or `log_axis`: plotters
//! loops forever on an infinite, NaN or too thin range.

mod drawing;
mod fit;
mod map;
mod run;
mod work_precision;

pub use drawing::FigureError;
pub use fit::fit_figure;
pub use map::regime_map;
pub use run::{Beside, RunChart, run_chart};
pub use work_precision::{Cost, work_precision, work_precision_against};
