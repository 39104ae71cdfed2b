//! The `--output FILE` of every command that prints text: the target checked before
//! the work, the text written atomically after it (a file of its own, so that every
//! command's file beside `cli/mod.rs` can use it without importing `mod.rs`).

use super::error::CliError;
use crate::output::{check_output, write_atomically};

/// What `work` prints, or with `--output FILE` the same bytes written to FILE (the
/// target checked before the work, written atomically after it) and a line saying
/// so: the `--output` of `simulate`, `render` and `compare`.
pub(super) fn deliver(
    output: Option<&std::path::Path>,
    work: impl FnOnce() -> Result<String, CliError>,
) -> Result<String, CliError> {
    let Some(path) = output else {
        return work();
    };
    check_output(path)?;
    let text = work()?;
    // From here a stop signal removes the temporary file and writes nothing.
    crate::signals::watch();
    write_atomically(path, text.as_bytes())?;
    Ok(format!("wrote {}\n", path.display()))
}
