//! All integration tests in one binary (one link of the crate instead of one per file):
//! one module per area, shared helpers in `common`.

#[macro_use]
mod common;

mod chart_zoom;
mod classroom;
mod cli;
mod closed_forms;
mod data_files;
mod data_hints;
mod data_rules;
mod data_scene;
mod errors;
mod exports;
mod fit;
mod fit_verdicts;
mod forces;
mod formats;
mod fuzz;
mod headless;
mod lab_data;
mod lab_jobs;
mod layers;
mod long_runs;
mod manual;
mod methods;
mod motion;
mod names;
mod nested_fits;
mod new_user_trial;
mod numbers;
mod origins;
mod params;
mod point_sigma;
mod presets;
mod pressed_contact;
mod properties;
mod readme;
mod reliability;
mod side_by_side;
mod small_screens;
mod story;
mod sweep;
mod table_shapes;
mod tracks;
mod tui;
mod units_checked;
mod video;
mod video_app;
mod wording;
mod wrong_scene;
