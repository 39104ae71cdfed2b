//! The `groovelab` binary: parse, run, print, map failures to exit status 2.

use std::io::{IsTerminal, Write};
use std::process::ExitCode;

use clap::Parser;
use groovelab::cli::{self, Cli, Outcome};

fn main() -> ExitCode {
    let cli = Cli::parse();
    match cli::run(&cli) {
        Ok(Outcome::Interactive(app)) => {
            if !(std::io::stdout().is_terminal() && std::io::stdin().is_terminal()) {
                eprintln!(
                    "error: the interactive app needs a terminal, and stdin or stdout is not one; use `groovelab render` for the screen as text or `groovelab simulate` for the numbers"
                );
                return ExitCode::from(2);
            }
            match groovelab::tui::run(*app, cli.ascii) {
                Ok(()) => ExitCode::SUCCESS,
                Err(e) => {
                    eprintln!("error: terminal: {e}");
                    ExitCode::from(2)
                }
            }
        }
        Ok(Outcome::Print(out)) => {
            let mut stdout = std::io::stdout().lock();
            match stdout
                .write_all(out.as_bytes())
                .and_then(|()| stdout.flush())
            {
                // A closed pipe (`groovelab simulate | head`) is the reader's choice.
                Ok(()) => ExitCode::SUCCESS,
                Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => ExitCode::SUCCESS,
                Err(e) => {
                    eprintln!("error: cannot write output: {e}");
                    ExitCode::from(2)
                }
            }
        }
        Err(cli::CliError::Interrupted) => {
            eprintln!("error: interrupted: nothing was written");
            ExitCode::from(130)
        }
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::from(2)
        }
    }
}
