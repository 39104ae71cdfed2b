//! The command line: options and their errors, the parameter table's round trip,
//! the wording of errors and notes, and the fuzz harness over every command.

mod fuzz;
mod options;
mod params;
mod themes;
mod wording;
