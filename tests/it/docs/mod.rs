//! The documents: README and guide examples run (trycmd), completions and man page.

mod manual;
mod readme;
