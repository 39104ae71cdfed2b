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
    /// The `byte`-th byte (from 1), on line `line`, starts no UTF-8 character: a file
    /// saved in a Windows code page (an "ß" or "µ" in a note), most likely.
    #[error(
        "line {line} (byte {byte}) is not UTF-8 text, allowed a UTF-8 text file: saved as Windows-1252 or Latin-1? Save it as UTF-8 (in Excel: CSV UTF-8)"
    )]
    NotUtf8 { byte: usize, line: usize },
    /// UTF-16 text by its byte-order mark (Excel's "Unicode text", Notepad's
    /// "Unicode"): read as UTF-8 it failed at its second byte, with no hint.
    #[error(
        "it is UTF-16 text by its first bytes, allowed a UTF-8 text file: save it as UTF-8 (in Excel: CSV UTF-8; in Notepad: UTF-8)"
    )]
    Utf16,
    /// Not text but a video or a picture by its first bytes (`kind`: "an MP4 or MOV
    /// video"), named without the extension that would have it tracked.
    #[error(
        "it is {kind} by its first bytes, not a text file: name it with its extension (.mp4, .mov, .mkv, .avi, .gif …) to have it tracked as a video, or track it with `groovelab track`"
    )]
    Video { kind: &'static str },
}

/// What a file's first bytes say it is, of the videos and pictures ffmpeg reads
/// (their containers' signatures), if any.
fn video_kind(head: &[u8]) -> Option<&'static str> {
    let at = |i: usize, sig: &[u8]| head.get(i..i + sig.len()) == Some(sig);
    if at(4, b"ftyp") {
        Some("an MP4 or MOV video")
    } else if at(0, &[0x1a, 0x45, 0xdf, 0xa3]) {
        Some("a Matroska or WebM video")
    } else if at(0, b"RIFF") && at(8, b"AVI ") {
        Some("an AVI video")
    } else if at(0, b"GIF8") {
        Some("a GIF animation")
    } else if at(0, &[0x00, 0x00, 0x01, 0xba]) {
        Some("an MPEG video")
    } else {
        None
    }
}

/// [`video_kind`] of the file at `path` (its first 12 bytes or fewer), if it can be
/// read.
fn video_file_kind(path: &Path) -> Option<&'static str> {
    let mut head = Vec::with_capacity(12);
    std::fs::File::open(path)
        .ok()?
        .take(12)
        .read_to_end(&mut head)
        .ok()?;
    video_kind(&head)
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
        if let Some(kind) = video_file_kind(path) {
            return Err(fail(Unreadable::Video { kind }));
        }
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
        let bytes = e.as_bytes();
        let head = bytes.get(..bytes.len().min(12)).unwrap_or_default();
        let valid = e.utf8_error().valid_up_to();
        fail(match video_kind(head) {
            Some(kind) => Unreadable::Video { kind },
            None if head.starts_with(&[0xff, 0xfe]) || head.starts_with(&[0xfe, 0xff]) => {
                Unreadable::Utf16
            }
            None => Unreadable::NotUtf8 {
                byte: valid + 1,
                line: 1 + bytes.iter().take(valid).filter(|&&b| b == b'\n').count(),
            },
        })
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A Windows-1252 "ß" in a note on line 3 is named by its line, with the fix; a
    /// UTF-16 file (either byte order) is named as such. Both said only "byte N is not
    /// UTF-8 text" (a new user's trial: byte 44, byte 1).
    #[test]
    fn text_not_in_utf8_is_named_with_its_line_and_how_to_save_it() {
        let dir = crate::output::Scratch::new("file-not-utf8");
        let cp1252 = b"t,v_cm,note\n0,0.79,ok\n0.01,0.79,Stra\xdfe\n".to_vec();
        let mut le = vec![0xff, 0xfe];
        le.extend("t,v_cm\n".encode_utf16().flat_map(u16::to_le_bytes));
        let mut be = vec![0xfe, 0xff];
        be.extend("t,v_cm\n".encode_utf16().flat_map(u16::to_be_bytes));
        for (name, bytes, want) in [
            ("cp1252.csv", cp1252, "line 3 (byte 37) is not UTF-8 text"),
            ("le.csv", le, "it is UTF-16 text by its first bytes"),
            ("be.csv", be, "it is UTF-16 text by its first bytes"),
        ] {
            let path = dir.join(name);
            std::fs::write(&path, bytes).unwrap();
            let e = read_user_file(&path, FileRole::Data, MAX_FILE_BYTES)
                .unwrap_err()
                .to_string();
            assert!(e.contains(want) && e.contains("CSV UTF-8"), "{name}: {e}");
        }
    }

    #[test]
    fn a_video_named_without_its_extension_is_said_to_be_one() {
        let dir = crate::output::Scratch::new("file-video-named");
        let mut mp4 = vec![0, 0, 0, 0x20];
        mp4.extend_from_slice(b"ftypisom\0\0\x02\0\xff\xfe");
        let cases: [(&[u8], &str); 4] = [
            (&mp4, "an MP4 or MOV video"),
            (b"GIF89a\x10\0\x10\0\xf7\0\0", "a GIF animation"),
            (
                &[0x1a, 0x45, 0xdf, 0xa3, 0x9f, 0x42, 0x86, 0x81, 0x01, 0xff],
                "a Matroska or WebM video",
            ),
            (b"RIFF\x10\0\0\0AVI LIST\xff", "an AVI video"),
        ];
        for (i, (bytes, kind)) in cases.into_iter().enumerate() {
            let p = dir.join(format!("noext{i}"));
            std::fs::write(&p, bytes).unwrap();
            let e = read_user_file(&p, FileRole::Data, 1 << 20)
                .unwrap_err()
                .to_string();
            assert!(
                e.contains(&format!("it is {kind} by its first bytes")),
                "{e}"
            );
            assert!(e.contains("groovelab track"), "{e}");
            // Over the size limit too (a real clip is larger than any table).
            let e = read_user_file(&p, FileRole::Data, 4)
                .unwrap_err()
                .to_string();
            assert!(e.contains(kind), "{e}");
        }
        // Other binary bytes: where the text breaks.
        let p = dir.join("binary");
        std::fs::write(&p, b"t,x\n\xff\xfe").unwrap();
        let e = read_user_file(&p, FileRole::Data, 1 << 20)
            .unwrap_err()
            .to_string();
        assert!(e.contains("line 2 (byte 5) is not UTF-8"), "{e}");
    }

    #[test]
    fn regular_files_are_read_others_refused_at_once() {
        let dir = crate::output::Scratch::new("file-regular");
        let p = dir.join("ok.csv");
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
            let link = dir.join("link.csv");
            std::os::unix::fs::symlink(&p, &link).unwrap();
            assert!(read_user_file(&link, FileRole::DataOption, 100).is_ok());
        }
        std::fs::write(&p, [b'a', 0xff, b'b']).unwrap();
        let e = read_user_file(&p, FileRole::DataOption, 100)
            .unwrap_err()
            .to_string();
        assert!(e.contains("line 1 (byte 2) is not UTF-8"), "{e}");
        let e = read_user_file(&dir.join("missing"), FileRole::DataOption, 100).unwrap_err();
        assert!(e.to_string().starts_with("cannot read --data "), "{e}");
    }
}
