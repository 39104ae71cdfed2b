//! The time-stepping methods: where each works and fails, and long analyses bounded.

mod long_runs;
mod stepping;
