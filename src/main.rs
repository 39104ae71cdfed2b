//! The `groovelab` binary: parse and run (`cli::entry`), print, exit with its status;
//! the interactive app runs here because it needs the real terminal.

use std::io::{IsTerminal, Write};
use std::process::ExitCode;

use groovelab::cli::entry::{self, Entry, Exit};

fn main() -> ExitCode {
    let args: Vec<_> = std::env::args_os().collect();
    let exit = match entry::dispatch(&args) {
        Entry::Interactive { app, ascii, theme } => {
            if !(std::io::stdout().is_terminal() && std::io::stdin().is_terminal()) {
                eprintln!("error: {}", entry::NO_TERMINAL);
                return ExitCode::from(2);
            }
            return match groovelab::tui::run(*app, ascii, theme) {
                Ok(()) => ExitCode::SUCCESS,
                Err(e) => {
                    eprintln!("error: terminal: {e}");
                    ExitCode::from(2)
                }
            };
        }
        Entry::Exit(exit) => exit,
    };
    print(exit)
}

/// Writes a finished run's output and gives its status.
fn print(exit: Exit) -> ExitCode {
    let mut stdout = std::io::stdout().lock();
    let written = stdout
        .write_all(exit.stdout.as_bytes())
        .and_then(|()| stdout.flush());
    let _ = std::io::stderr().write_all(exit.stderr.as_bytes());
    match written {
        // A closed pipe (`groovelab simulate | head`) is the reader's choice.
        Ok(()) => ExitCode::from(exit.code),
        Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => ExitCode::from(exit.code),
        Err(e) => {
            eprintln!("error: cannot write output: {e}");
            ExitCode::from(2)
        }
    }
}
