//! The whole command line as a function: arguments in, exit status and the text for
//! stdout and stderr out. `main.rs` only prints what this returns (and runs the
//! interactive app); tests and the fuzz harness call it in-process.

use std::ffi::OsString;

use super::Response;
use super::args::Cli;
use super::error::CliError;
use crate::tui::app::App;
use crate::tui::theme::ThemeChoice;

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

    /// One `error:` line on stderr, nothing on stdout. A line break inside the message
    /// (a value or a preset name that holds one) is shown escaped, so the message stays
    /// one line.
    fn error(code: u8, message: &str) -> Exit {
        Exit {
            code,
            stdout: String::new(),
            stderr: format!("error: {}\n", escape_breaks(message)),
        }
    }
}

/// What a command line asks for: a finished run, or the interactive app (which needs
/// the real terminal, so only `main.rs` can run it).
pub enum Entry {
    Exit(Exit),
    Interactive {
        app: Box<App>,
        ascii: bool,
        theme: ThemeChoice,
    },
}

/// The message when the app is asked for without a terminal.
pub const NO_TERMINAL: &str = "the interactive app needs a terminal, and stdin or stdout is not one; use `groovelab render` for the screen as text or `groovelab simulate` for the numbers";

/// Parses and runs `args` (the program name first, as `std::env::args_os` gives).
pub fn dispatch(args: &[OsString]) -> Entry {
    let parsed = super::args::command()
        .try_get_matches_from(args)
        .and_then(|m| <Cli as clap::FromArgMatches>::from_arg_matches(&m));
    let cli = match parsed {
        Ok(cli) => cli,
        Err(e) => {
            // Help and version go to stdout with status 0; usage errors to stderr, as
            // one line like every other error.
            let text = e.render().to_string();
            let code = u8::try_from(e.exit_code()).unwrap_or(2);
            return Entry::Exit(if e.use_stderr() {
                Exit::error(code, &with_allowed(&e, clap_one_line(&text), args))
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
        Ok(Response::Interactive(app)) => Entry::Interactive {
            app,
            ascii: cli.ascii,
            // Checked by `run`: an unknown GROOVELAB_THEME is an error before this.
            theme: super::theme_choice(&cli).unwrap_or_default(),
        },
        Ok(Response::Print(out)) => Entry::Exit(Exit {
            stderr: bare_notes(args),
            ..Exit::ok(out)
        }),
        Err(CliError::Interrupted) => {
            Entry::Exit(Exit::error(130, &CliError::Interrupted.to_string()))
        }
        Err(e) => Entry::Exit(Exit::error(2, &with_unit_hint(&e, args))),
    }
}

/// `e`'s message, and where it is a scene value out of range that was typed as a bare
/// number of a length or a mass: that such a number is metres or kilograms (SI), and
/// how to write the value in the unit people read (`--width 4.9` is 4.9 m; a
/// groove's width is 4.9cm); where it is a width too wide for the radius the command
/// line gave, that radius.
fn with_unit_hint(e: &CliError, args: &[OsString]) -> String {
    use crate::settings::params::PARAMS;
    use crate::settings::spec::{Allowed, SceneError};
    use crate::settings::units::{Dimension, show};
    let message = e.to_string();
    let CliError::Scene(SceneError::OutOfRange { key, allowed, .. }) = e else {
        return message;
    };
    // Said only where the number read in that unit is allowed (1e308 g is no more
    // a mass than 1e308 kg), and is 1 or more: a bare number under 1 is as likely
    // metres or kilograms meant (`--width 0.06`, 6 cm, just wider than 2R = 5.5 cm,
    // is no 0.06 cm mistyped).
    let bare = PARAMS
        .iter()
        .filter(|p| p.key == *key || p.sets.contains(key))
        .filter(|p| p.dim.display_unit().1 != 0)
        .find_map(|p| bare_value(args, p.flag).map(|v| (p, v)))
        .filter(|(_, (_, x))| x.abs() >= 1.0)
        .filter(|(p, (_, x))| allowed.admits(x * 10f64.powi(p.dim.display_unit().1)));
    let message = match bare {
        Some((p, (v, _))) => format!(
            "{message}; --{} {v} has no unit, so it is {v} {} (a bare number is SI); in {unit} write {v}{unit}",
            p.flag,
            p.dim.si_unit(),
            unit = p.dim.display_unit().0,
        ),
        None => message,
    };
    // A width out of range for the radius the command line gave: the radius named too
    // (`--radius 0.5mm` is what made the preset's 4.9 cm too wide).
    match (allowed, given_value(args, "radius")) {
        (Allowed::BelowTwiceRadius { radius }, Some(r)) => format!(
            "{message} (R = {} from --radius {r})",
            show(*radius, Dimension::Length)
        ),
        _ => message,
    }
}

/// A `note:` line on stderr for each length or mass given as a bare number of 1 or
/// more, which is metres or kilograms (SI) and so accepted where in range, though
/// people mean centimetres or grams (`--mass 167` ran with two 167 kg balls).
fn bare_notes(args: &[OsString]) -> String {
    use crate::settings::params::PARAMS;
    PARAMS
        .iter()
        .filter(|p| p.dim.display_unit().1 != 0)
        .filter_map(|p| bare_value(args, p.flag).map(|(v, x)| (p, v, x)))
        .filter(|(_, _, x)| x.abs() >= 1.0)
        .map(|(p, v, _)| {
            format!(
                "note: --{} {v} has no unit, so it is {v} {} (a bare number is SI); in {unit} write {v}{unit}\n",
                p.flag,
                p.dim.si_unit(),
                unit = p.dim.display_unit().0,
            )
        })
        .collect()
}

/// The value given to `--flag` (the last one, as clap takes it), as typed.
fn given_value(args: &[OsString], flag: &str) -> Option<String> {
    let long = format!("--{flag}");
    let joined = format!("--{flag}=");
    let mut found = None;
    let mut words = args.iter().filter_map(|a| a.to_str());
    while let Some(w) = words.next() {
        if w == long {
            found = words.next().map(str::to_string);
        } else if let Some(v) = w.strip_prefix(&joined) {
            found = Some(v.to_string());
        }
    }
    found
}

/// The value given to `--flag` (the last one, as clap takes it), as typed and as a
/// number, where it is a bare number, without a unit.
fn bare_value(args: &[OsString], flag: &str) -> Option<(String, f64)> {
    let found = given_value(args, flag)?;
    let x = found.trim().parse::<f64>().ok()?;
    Some((found, x))
}

/// clap's message as one line: its sentences joined, without the usage block, the
/// tips and the "For more information" hint (`--help` is always there).
fn clap_one_line(text: &str) -> String {
    let mut parts = Vec::new();
    for line in text.lines() {
        let line = line.trim();
        if line.starts_with("Usage:") || line.starts_with("For more information") {
            break;
        }
        if line.is_empty() || line.starts_with("tip:") {
            continue;
        }
        parts.push(line.strip_prefix("error: ").unwrap_or(line));
    }
    parts.join(" ")
}

/// An unknown option's message with what is allowed: clap's suggestion when it has
/// one ("a similar argument exists: '--width'"), else the options the command takes.
fn with_allowed(e: &clap::Error, line: String, args: &[OsString]) -> String {
    use clap::error::{ContextKind, ContextValue, ErrorKind};
    let left_over = matches!(
        e.kind(),
        ErrorKind::UnknownArgument | ErrorKind::InvalidSubcommand
    );
    if let Some(swallowed) = option_taken_as_value(args).filter(|_| left_over) {
        return swallowed;
    }
    if let Some(joined) = unit_apart(e, args) {
        return format!("{line}; a value and its unit are one word: write {joined}");
    }
    if e.kind() != ErrorKind::UnknownArgument {
        return clip_invalid_value(e, line);
    }
    let top = super::args::command();
    // The subcommand named on the line, if any: its options, else the app's.
    let sub = args
        .iter()
        .skip(1)
        .filter_map(|a| a.to_str())
        .find_map(|a| top.find_subcommand(a));
    let (name, command) = match sub {
        Some(c) => (format!("groovelab {}", c.get_name()), c),
        None => ("groovelab".to_string(), &top),
    };
    // clap suggests options the command hides too (global ones it does not take).
    let hidden = |similar: &str| {
        command
            .get_arguments()
            .any(|a| a.is_hide_set() && a.get_long().is_some_and(|l| similar == format!("--{l}")))
    };
    match e.get(ContextKind::SuggestedArg) {
        Some(ContextValue::String(similar)) if !hidden(similar) => {
            return format!("{line}; a similar option exists: '{similar}'");
        }
        Some(ContextValue::Strings(similar))
            if !similar.iter().any(|s| hidden(s)) && !similar.is_empty() =>
        {
            return format!("{line}; similar options exist: '{}'", similar.join("', '"));
        }
        _ => {}
    }
    // A command's own options, and the global ones it takes (those it does not take
    // it holds as hidden copies: `args::command`).
    let own = |id: &clap::Id| command.get_arguments().any(|a| a.get_id() == id);
    let options: Vec<String> = command
        .get_arguments()
        .chain(
            top.get_arguments()
                .filter(|a| sub.is_some() && a.is_global_set() && !own(a.get_id())),
        )
        .filter(|a| !a.is_hide_set())
        .filter_map(|a| a.get_long().map(|l| format!("--{l}")))
        .collect();
    if options.is_empty() {
        return format!("{line}; `{name}` takes no options");
    }
    format!(
        "{line}, allowed options of `{name}`: {} (`{name} --help` says what each does)",
        options.join(", ")
    )
}

/// `--width 4.9cm` where the word clap found unexpected is a unit written apart from
/// the number before it (`--width 4.9 cm`, as people write quantities): the option,
/// its number and the unit as one word.
fn unit_apart(e: &clap::Error, args: &[OsString]) -> Option<String> {
    use crate::settings::units::{Dimension, unit_factor};
    use clap::error::{ContextKind, ContextValue};
    let Some(ContextValue::String(word)) = e.get(ContextKind::InvalidArg) else {
        return None;
    };
    let dims = [
        Dimension::Length,
        Dimension::Mass,
        Dimension::Speed,
        Dimension::Time,
        Dimension::Acceleration,
    ];
    if !dims.iter().any(|&d| unit_factor(word, d).is_ok()) {
        return None;
    }
    let words: Vec<&str> = args.iter().filter_map(|a| a.to_str()).collect();
    let number = |w: &str| w.parse::<f64>().is_ok_and(f64::is_finite);
    let option = |w: &str| w.starts_with("--");
    // `--width 4.9 cm`, or `--width=4.9 cm`.
    words
        .windows(3)
        .find_map(|w| match *w {
            [flag, value, unit] if unit == word && option(flag) && number(value) => {
                Some(format!("{flag} {value}{unit}"))
            }
            _ => None,
        })
        .or_else(|| {
            words.windows(2).find_map(|w| match *w {
                [flag_value, unit] if unit == word && option(flag_value) => {
                    let (_, value) = flag_value.split_once('=')?;
                    number(value).then(|| format!("{flag_value}{unit}"))
                }
                _ => None,
            })
        })
}

/// An option given without its value, the next option taken as the value instead
/// (`--ball-at --output t.txt`): options whose values may begin with a hyphen
/// (negative numbers) take whatever follows, so clap reports the word left over
/// (`t.txt`) as unexpected. Said as the option missing its value, naming the option
/// that followed it.
fn option_taken_as_value(args: &[OsString]) -> Option<String> {
    use clap::CommandFactory;
    let top = Cli::command();
    let words: Vec<&str> = args.iter().skip(1).filter_map(|a| a.to_str()).collect();
    let sub = words.iter().find_map(|w| top.find_subcommand(w));
    let known = |long: &str| {
        let has = |c: &clap::Command| c.get_arguments().any(|a| a.get_long() == Some(long));
        has(&top) || sub.is_some_and(has)
    };
    let hyphen_valued = |long: &str| {
        sub.into_iter()
            .flat_map(|c| c.get_arguments())
            .chain(top.get_arguments())
            .find(|a| a.get_long() == Some(long))
            .filter(|a| a.is_allow_hyphen_values_set())
            .and_then(|a| a.get_value_names().and_then(|v| v.first().cloned()))
    };
    words.windows(2).find_map(|pair| {
        let option = pair.first()?.strip_prefix("--")?;
        let next = pair.get(1)?.strip_prefix("--")?;
        let value = hyphen_valued(option)?;
        known(next.split('=').next().unwrap_or(next)).then(|| {
            format!(
                "a value is required for '--{option} <{value}>', found the option '--{next}' after it"
            )
        })
    })
}

/// clap's message with the value it echoes (`invalid value '…'`) cut to a sane length.
fn clip_invalid_value(e: &clap::Error, line: String) -> String {
    use clap::error::{ContextKind, ContextValue};
    match e.get(ContextKind::InvalidValue) {
        Some(ContextValue::String(value)) => {
            let clipped = crate::settings::quote::clip(value).to_string();
            line.replacen(&format!("'{value}'"), &format!("'{clipped}'"), 1)
        }
        _ => line,
    }
}

/// `\n` and `\r` inside a message, spelt out.
fn escape_breaks(message: &str) -> String {
    message.replace('\r', "\\r").replace('\n', "\\n")
}

/// [`dispatch`] for callers without a terminal: the interactive app is refused as
/// `main.rs` refuses it when stdin or stdout is not a terminal.
pub fn main_with(args: &[OsString]) -> Exit {
    match dispatch(args) {
        Entry::Exit(exit) => exit,
        Entry::Interactive { .. } => Exit::error(2, NO_TERMINAL),
    }
}
