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

/// The length-unit mix-ups by the power of ten they make lengths too large: (factor,
/// the unit meant, the unit it was read as). mm read as cm is 10×, cm as m 100×, mm
/// as m 1000×; read the other way round, as many times too small.
pub const MIX_UPS: [(f64, &str, &str); 3] =
    [(10.0, "mm", "cm"), (100.0, "cm", "m"), (1000.0, "mm", "m")];
