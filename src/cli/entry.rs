//! The whole command line as a function: arguments in, exit status and the text for
//! stdout and stderr out. `main.rs` only prints what this returns (and runs the
//! interactive app); tests and the fuzz harness call it in-process.

use std::ffi::OsString;

use clap::Parser;

use super::{Cli, CliError, Outcome};
use crate::tui::app::App;

/// How a non-interactive run ends: the exit status and everything it prints.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Exit {
    pub code: u8,
    pub stdout: String,
    pub stderr: String,
}

impl Exit {
    fn ok(stdout: String) -> Exit {
        Exit {
            code: 0,
            stdout,
            stderr: String::new(),
        }
    }

    /// One `error:` line on stderr, nothing on stdout.
    fn error(code: u8, message: &str) -> Exit {
        Exit {
            code,
            stdout: String::new(),
            stderr: format!("error: {message}\n"),
        }
    }
}

/// What a command line asks for: a finished run, or the interactive app (which needs
/// the real terminal, so only `main.rs` can run it).
pub enum Entry {
    Exit(Exit),
    Interactive { app: Box<App>, ascii: bool },
}

/// The message when the app is asked for without a terminal.
pub const NO_TERMINAL: &str = "the interactive app needs a terminal, and stdin or stdout is not one; use `groovelab render` for the screen as text or `groovelab simulate` for the numbers";

/// Parses and runs `args` (the program name first, as `std::env::args_os` gives).
pub fn dispatch(args: &[OsString]) -> Entry {
    let cli = match Cli::try_parse_from(args) {
        Ok(cli) => cli,
        Err(e) => {
            // Help and version go to stdout with status 0; usage errors to stderr.
            let text = e.render().to_string();
            let code = u8::try_from(e.exit_code()).unwrap_or(2);
            return Entry::Exit(if e.use_stderr() {
                Exit {
                    code,
                    stdout: String::new(),
                    stderr: text,
                }
            } else {
                Exit {
                    code,
                    stdout: text,
                    stderr: String::new(),
                }
            });
        }
    };
    match super::run(&cli) {
        Ok(Outcome::Interactive(app)) => Entry::Interactive {
            app,
            ascii: cli.ascii,
        },
        Ok(Outcome::Print(out)) => Entry::Exit(Exit::ok(out)),
        Err(CliError::Interrupted) => {
            Entry::Exit(Exit::error(130, &CliError::Interrupted.to_string()))
        }
        Err(e) => Entry::Exit(Exit::error(2, &e.to_string())),
    }
}

/// [`dispatch`] for callers without a terminal: the interactive app is refused as
/// `main.rs` refuses it when stdin or stdout is not a terminal.
pub fn main_with(args: &[OsString]) -> Exit {
    match dispatch(args) {
        Entry::Exit(exit) => exit,
        Entry::Interactive { .. } => Exit::error(2, NO_TERMINAL),
    }
}
