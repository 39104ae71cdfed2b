//! The physics of two balls in a groove (physics.md): the scene, one ball's model and
//! the impact law, the paper's closed forms, the exact event-driven engine, its
//! solution and the derived values every front end shows. No flags, no I/O.

pub mod closed_form;
pub mod derived;
pub mod engine;
pub mod forces;
pub mod model;
pub mod scene;
pub mod solution;
pub mod story;
