//! Reading a user's file whole, safely: only a regular file (after following
//! symlinks), checked against a size limit before a byte is read, so `/dev/zero`, a
//! FIFO or a directory fail at once instead of hanging or filling memory.

use crate::output::kind;
use std::io::Read;
use std::path::Path;

/// Largest user file (measured data, preset) read: far above any real series or
/// preset, far below what would strain memory.
pub const MAX_FILE_BYTES: u64 = 64 * 1024 * 1024;

/// Why a user file was not read; one line naming the file and what is allowed.
#[derive(Debug, thiserror::Error)]
#[error("cannot read {what} {}: {why}", path.display())]
pub struct FileError {
    pub what: FileRole,
    pub path: std::path::PathBuf,
    pub why: Unreadable,
}

/// What a user file is for, as its errors name it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FileRole {
    /// A preset's TOML file.
    Preset,
    /// A file `groovelab data` reports on.
    Data,
    /// A file `--data` names.
    DataOption,
}

impl std::fmt::Display for FileRole {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            FileRole::Preset => "preset file",
            FileRole::Data => "data file",
            FileRole::DataOption => "--data",
        })
    }
}

/// What is wrong with a user file.
#[derive(Debug, thiserror::Error)]
pub enum Unreadable {
    /// The system's refusal, in words with what is allowed ([`io_words`]).
    #[error("{}", io_words(.0))]
    Io(#[from] std::io::Error),
    /// A directory, a FIFO, a device (see [`kind`]).
    #[error("it is {0}, allowed a regular file")]
    NotRegular(&'static str),
    /// Over `limit` bytes: `size` of them, or `None` when it grew while read.
    #[error(
        "it has {} bytes, allowed a file of at most {limit} bytes ({} MiB)",
        size.map_or(format!("more than {limit}"), |s| s.to_string()),
        limit / (1024 * 1024)
    )]
    TooBig { size: Option<u64>, limit: u64 },
    /// The `byte`-th byte (from 1) starts no UTF-8 character.
    #[error("byte {byte} is not UTF-8 text, allowed a UTF-8 text file")]
    NotUtf8 { byte: usize },
}

/// A file the system would not open, in words with what is allowed: "no such file,
/// allowed an existing file" (the system's own "No such file or directory (os error
/// 2)" names no remedy); other errors in the system's words.
pub fn io_words(e: &std::io::Error) -> String {
    match e.kind() {
        std::io::ErrorKind::NotFound => "no such file, allowed an existing file".into(),
        std::io::ErrorKind::PermissionDenied => {
            "permission denied, allowed a file you may read".into()
        }
        _ => e.to_string(),
    }
}

/// Reads `path` as UTF-8 text if it is a regular file of at most `limit` bytes;
/// `what` names the file's role in errors.
pub fn read_user_file(path: &Path, what: FileRole, limit: u64) -> Result<String, FileError> {
    let fail = |why: Unreadable| FileError {
        what,
        path: path.to_path_buf(),
        why,
    };
    let io = |e: std::io::Error| fail(Unreadable::Io(e));
    // Checked before opening: opening a FIFO would block until a writer comes.
    let meta = std::fs::metadata(path).map_err(io)?;
    if !meta.is_file() {
        return Err(fail(Unreadable::NotRegular(kind(&meta))));
    }
    if meta.len() > limit {
        return Err(fail(Unreadable::TooBig {
            size: Some(meta.len()),
            limit,
        }));
    }
    let file = std::fs::File::open(path).map_err(io)?;
    // The path may have been swapped between the check and the open.
    let meta = file.metadata().map_err(io)?;
    if !meta.is_file() {
        return Err(fail(Unreadable::NotRegular(kind(&meta))));
    }
    // A file growing while read is still cut at the limit.
    let mut bytes = Vec::with_capacity(meta.len().min(limit) as usize);
    file.take(limit + 1).read_to_end(&mut bytes).map_err(io)?;
    if bytes.len() as u64 > limit {
        return Err(fail(Unreadable::TooBig { size: None, limit }));
    }
    String::from_utf8(bytes).map_err(|e| {
        fail(Unreadable::NotUtf8 {
            byte: e.utf8_error().valid_up_to() + 1,
        })
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scratch(name: &str) -> std::path::PathBuf {
        let dir = std::env::temp_dir().join(format!("groovelab-file-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        dir.join(name)
    }

    #[test]
    fn regular_files_are_read_others_refused_at_once() {
        let p = scratch("ok.csv");
        std::fs::write(&p, "t,v_cm,v_t\n").unwrap();
        assert_eq!(
            read_user_file(&p, FileRole::DataOption, 100).unwrap(),
            "t,v_cm,v_t\n"
        );
        let e = read_user_file(&p, FileRole::DataOption, 5)
            .unwrap_err()
            .to_string();
        assert!(e.contains("at most 5 bytes"), "{e}");
        let e = read_user_file(p.parent().unwrap(), FileRole::DataOption, 100).unwrap_err();
        assert!(e.to_string().contains("a directory"), "{e}");
        #[cfg(unix)]
        {
            for dev in ["/dev/zero", "/dev/urandom", "/dev/null"] {
                let e = read_user_file(Path::new(dev), FileRole::DataOption, MAX_FILE_BYTES)
                    .unwrap_err();
                assert!(e.to_string().contains("a device"), "{e}");
            }
            let link = scratch("link.csv");
            let _ = std::fs::remove_file(&link);
            std::os::unix::fs::symlink(&p, &link).unwrap();
            assert!(read_user_file(&link, FileRole::DataOption, 100).is_ok());
        }
        std::fs::write(&p, [b'a', 0xff, b'b']).unwrap();
        let e = read_user_file(&p, FileRole::DataOption, 100)
            .unwrap_err()
            .to_string();
        assert!(e.contains("byte 2 is not UTF-8"), "{e}");
        let e = read_user_file(&scratch("missing"), FileRole::DataOption, 100).unwrap_err();
        assert!(e.to_string().starts_with("cannot read --data "), "{e}");
    }
}
