//! All integration tests in one binary (one link of the crate instead of one per file):
//! one folder per area (what the tests exercise), shared helpers in `common`, and
//! `regression` for tests that each name what once broke.

#[macro_use]
mod common;

mod cli;
mod code;
mod data;
mod docs;
mod fit;
mod methods;
mod physics;
mod regression;
mod tui;
mod video;
