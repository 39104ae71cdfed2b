//! Measured data in: students' files and the video tools' formats, tracks, hints,
//! units, where scene values come from, and data beside their scene in the lab.

mod files;
pub(crate) mod formats;
mod hints;
mod lab_data;
mod new_user_files;
mod origins;
mod point_sigma;
mod rules;
mod scene;
mod series_rules;
mod side_by_side;
mod sources_said;
mod table_shapes;
mod tracks;
mod unfit;
mod units_checked;
