//! Physical quantities at the edges: parsing `2.75cm`, `167g`, `60cm/s` into SI and
//! formatting SI values back for people (`parse`, `show`), both from the one unit table
//! here. Nothing inside the physics uses this module.

mod dimension;
mod parse;
mod show;

pub use dimension::Dimension;
pub use parse::{
    Expected, MIN_MAGNITUDE, UnitError, parse_option, parse_quantity, parse_typed, unit_factor,
};
pub use show::{
    SMALLEST_UNCERTAINTY, Shown, fit_digits, fit_number, fixed, show, show_below, show_exact,
    show_small, sig_figs, significant, with_uncertainty,
};
