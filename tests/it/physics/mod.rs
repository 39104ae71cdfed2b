//! The exact engine against physics: closed forms, invariants over the parameter
//! space, pressed contact, the run told in words, the presets' golden JSON, regime maps.

mod closed_forms;
mod presets;
mod pressed_contact;
mod properties;
mod story;
mod sweep;
