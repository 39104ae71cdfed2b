//! The source's own rules (docs/development.md): layers, one name per type, typed errors.

mod errors;
pub(crate) mod layers;
mod names;
