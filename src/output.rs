//! The one way groovelab writes a file (`--output` of every command, the
//! app's saved presets and exports): a temporary file beside the target, renamed
//! over it only when complete and not interrupted. The target must be a regular file
//! or a new path (never a symlink, FIFO, device or directory); a replaced file keeps
//! its mode (and its owner and group where the user may set them); the temporary
//! file is removed on every error and on a stop signal (see `signals`).
//!
//! The rule for interruptions is one thing: if a stop signal arrives before the
//! output is committed (renamed into place, or handed to stdout), the run exits 130
//! and nothing is written.

use std::fs::{File, Metadata, OpenOptions};
use std::io::{self, BufWriter, Write};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, Ordering};

/// Why an output was not written.
#[derive(Debug, thiserror::Error)]
pub enum OutputError {
    #[error("cannot write {}: it is {kind}, allowed a regular file or a new path", path.display())]
    NotRegular { path: PathBuf, kind: &'static str },
    #[error("cannot write {}: it names no file, allowed a file path", path.display())]
    NoFileName { path: PathBuf },
    #[error("cannot write {}: {source}", path.display())]
    Io { path: PathBuf, source: io::Error },
    /// The temporary file could not be made in the target's folder; `why` says why in
    /// words about that folder (the OS error alone, "No such file or directory" for an
    /// existing `/proc/version`, names the wrong thing).
    #[error("cannot write {}: {why} (the file is written beside it first, then renamed into place)", path.display())]
    Folder { path: PathBuf, why: FolderError },
    /// The output is a file the command reads (or another output): written, it would
    /// replace its input.
    #[error("cannot write {}: it is also {clash}; allowed another file", path.display())]
    IsInput { path: PathBuf, clash: Clash },
    /// The output, a picture, lies in a folder of frames the command reads: written
    /// there it would replace a frame, or be read as one the next time.
    #[error("cannot write {}: it lies in the folder of frames {} this command reads (a file there replaces a frame or is taken for one); allowed a file outside it", path.display(), folder.display())]
    InFramesFolder { path: PathBuf, folder: PathBuf },
    #[error("interrupted: nothing was written")]
    Interrupted,
}

/// Another file of the command that an output must not be: one it reads (`kind`:
/// "video", "data file", "preset file"), or another of its outputs (`flag`).
#[derive(Clone, Debug, PartialEq)]
pub enum Clash {
    Reads { kind: &'static str, file: PathBuf },
    Writes { flag: &'static str, file: PathBuf },
}

impl Clash {
    fn file(&self) -> &Path {
        match self {
            Clash::Reads { file, .. } | Clash::Writes { file, .. } => file,
        }
    }
}

impl std::fmt::Display for Clash {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Clash::Reads { kind, file } => {
                write!(f, "the {kind} {} this command reads", file.display())
            }
            Clash::Writes { flag, .. } => write!(f, "the {flag} file"),
        }
    }
}

/// Why no new file could be made in a target's folder, said of the folder.
#[derive(Debug, thiserror::Error)]
pub enum FolderError {
    #[error("its folder {} does not exist", .0.display())]
    Missing(PathBuf),
    /// The folder is there but refuses new names: a pseudo-file system (/proc, /sys).
    #[error("its folder {} takes no new files", .0.display())]
    TakesNoFiles(PathBuf),
    #[error("its folder {} is not writable (permission denied)", .0.display())]
    NotWritable(PathBuf),
    #[error("its folder {} is on a read-only file system", .0.display())]
    ReadOnly(PathBuf),
    #[error("no new file can be made in its folder {}: {source}", folder.display())]
    Other { folder: PathBuf, source: io::Error },
}

/// The target's metadata if it is an existing regular file, `None` if nothing is
/// there; an error for anything else (a symlink is refused, not followed: replacing
/// it would turn the link into a file).
fn check_target(path: &Path) -> Result<Option<Metadata>, OutputError> {
    match std::fs::symlink_metadata(path) {
        Err(e) if e.kind() == io::ErrorKind::NotFound => Ok(None),
        Err(e) => Err(io_error(path, e)),
        Ok(m) if m.file_type().is_symlink() => Err(OutputError::NotRegular {
            path: path.to_path_buf(),
            kind: "a symlink",
        }),
        Ok(m) if !m.is_file() => Err(OutputError::NotRegular {
            path: path.to_path_buf(),
            kind: kind(&m),
        }),
        Ok(m) => Ok(Some(m)),
    }
}

/// Checks an output path before the work that fills it: a regular file or a new
/// path, else the error `AtomicFile::create` would give after the work.
pub fn check_output(path: &Path) -> Result<(), OutputError> {
    check_target(path)?;
    // A folder that is not there is said before the work, not after it.
    match path.parent().filter(|d| !d.as_os_str().is_empty()) {
        Some(dir) if !dir.is_dir() => Err(OutputError::Folder {
            path: path.to_path_buf(),
            why: FolderError::Missing(dir.to_path_buf()),
        }),
        _ => Ok(()),
    }
}

/// Refuses an output that is one of the files the command reads or writes besides
/// it (`others`): written atomically, it would replace the video being
/// tracked, or the data being fitted, with its own result; and a `picture` (a file
/// a folder of frames reads as one) inside a folder it reads.
pub fn check_apart(path: &Path, picture: bool, others: &[Clash]) -> Result<(), OutputError> {
    if let Some(c) = others.iter().find(|c| same_target(path, c.file())) {
        return Err(OutputError::IsInput {
            path: path.to_path_buf(),
            clash: c.clone(),
        });
    }
    if !picture {
        return Ok(());
    }
    // A folder read (a video given as its frames): no picture is written inside
    // it, where it would replace a frame or be read as one (a text file there is
    // passed over).
    let folder = others.iter().find_map(|c| match c {
        Clash::Reads { file, .. } if file.is_dir() && inside(path, file) => Some(file),
        _ => None,
    });
    match folder {
        Some(d) => Err(OutputError::InFramesFolder {
            path: path.to_path_buf(),
            folder: d.clone(),
        }),
        None => Ok(()),
    }
}

/// The folder the file `path` (made or not) lies in, resolved: "." for a bare name.
fn folder_of(path: &Path) -> io::Result<PathBuf> {
    let parent = path.parent().filter(|d| !d.as_os_str().is_empty());
    std::fs::canonicalize(parent.unwrap_or(Path::new(".")))
}

/// True when the file `path` (made or not) would lie in the folder `dir` or in one
/// of its subfolders.
fn inside(path: &Path, dir: &Path) -> bool {
    match (folder_of(path), std::fs::canonicalize(dir)) {
        (Ok(p), Ok(d)) => p.starts_with(d),
        _ => false,
    }
}

/// True when `a` and `b` are one file: the same file where both exist, else the
/// same name in the same folder (two outputs not yet made).
fn same_target(a: &Path, b: &Path) -> bool {
    // By the files' device and inode, from `stat`: never opened (opening a FIFO
    // waits for a writer).
    if let (Ok(x), Ok(y)) = (std::fs::metadata(a), std::fs::metadata(b)) {
        use std::os::unix::fs::MetadataExt;
        return (x.dev(), x.ino()) == (y.dev(), y.ino());
    }
    match (folder_of(a), folder_of(b)) {
        (Ok(x), Ok(y)) => x == y && a.file_name() == b.file_name(),
        _ => false,
    }
}

fn io_error(path: &Path, source: io::Error) -> OutputError {
    OutputError::Io {
        path: path.to_path_buf(),
        source,
    }
}

/// Why no new file could be made in `dir`, the target's folder, said of the folder.
fn folder_error(target: &Path, dir: &Path, e: io::Error) -> OutputError {
    let folder = dir.to_path_buf();
    let why = match e.kind() {
        io::ErrorKind::NotFound if !dir.is_dir() => FolderError::Missing(folder),
        io::ErrorKind::NotFound => FolderError::TakesNoFiles(folder),
        io::ErrorKind::PermissionDenied => FolderError::NotWritable(folder),
        io::ErrorKind::ReadOnlyFilesystem => FolderError::ReadOnly(folder),
        _ => FolderError::Other { folder, source: e },
    };
    OutputError::Folder {
        path: target.to_path_buf(),
        why,
    }
}

/// A file being written: bytes go to `.NAME.PID.tmp` beside the target; [`commit`]
/// renames it over the target; dropping it uncommitted removes it.
///
/// [`commit`]: AtomicFile::commit
pub struct AtomicFile {
    target: PathBuf,
    tmp: PathBuf,
    out: Option<BufWriter<File>>,
}

impl AtomicFile {
    /// Checks the target and creates the temporary file (with the replaced file's
    /// mode, or the usual mode of a new file).
    pub fn create(target: &Path) -> Result<AtomicFile, OutputError> {
        let old = check_target(target)?;
        let name = target
            .file_name()
            .ok_or_else(|| OutputError::NoFileName {
                path: target.to_path_buf(),
            })?
            .to_string_lossy()
            .into_owned();
        let dir = target
            .parent()
            .filter(|d| !d.as_os_str().is_empty())
            .unwrap_or(Path::new("."));
        let pid = std::process::id();
        // `create_new`: never truncate someone else's file of the same name.
        let mut attempt = 0;
        let (tmp, file) = loop {
            let suffix = if attempt == 0 {
                String::new()
            } else {
                format!(".{attempt}")
            };
            let tmp = dir.join(format!(".{name}.{pid}{suffix}.tmp"));
            match OpenOptions::new().write(true).create_new(true).open(&tmp) {
                Ok(f) => break (tmp, f),
                Err(e) if e.kind() == io::ErrorKind::AlreadyExists && attempt < 100 => {
                    attempt += 1;
                }
                Err(e) => return Err(folder_error(target, dir, e)),
            }
        };
        let me = AtomicFile {
            target: target.to_path_buf(),
            tmp,
            out: Some(BufWriter::with_capacity(1 << 16, file)),
        };
        if let Some(old) = old {
            let file = me.out.as_ref().expect("just made").get_ref();
            file.set_permissions(old.permissions())
                .map_err(|e| io_error(target, e))?;
            // The owner and group too where allowed (root, or a group of the user's);
            // otherwise the file becomes the user's, as any rewrite would make it.
            #[cfg(unix)]
            {
                use std::os::unix::fs::MetadataExt;
                let _ = std::os::unix::fs::fchown(file, Some(old.uid()), Some(old.gid()));
                let _ = std::os::unix::fs::fchown(file, None, Some(old.gid()));
            }
        }
        Ok(me)
    }

    /// The temporary file's path (for tests and messages).
    pub fn temp_path(&self) -> &Path {
        &self.tmp
    }

    /// Writes all of `bytes`, with errors naming the target.
    pub fn write_bytes(&mut self, bytes: &[u8]) -> Result<(), OutputError> {
        let out = self.out.as_mut().expect("open until commit");
        out.write_all(bytes).map_err(|e| io_error(&self.target, e))
    }

    /// Flushes, syncs and renames over the target, unless `stop` is set: then the
    /// temporary file is removed and nothing is written.
    pub fn commit(mut self, stop: &AtomicBool) -> Result<(), OutputError> {
        let out = self.out.take().expect("open until commit");
        let file = out
            .into_inner()
            .map_err(|e| io_error(&self.target, e.into_error()))?;
        file.sync_all().map_err(|e| io_error(&self.target, e))?;
        drop(file);
        if stop.load(Ordering::Relaxed) {
            return Err(OutputError::Interrupted);
        }
        // The target may have changed while we wrote (a FIFO put in its place).
        check_target(&self.target)?;
        std::fs::rename(&self.tmp, &self.target).map_err(|e| io_error(&self.target, e))?;
        self.tmp = PathBuf::new();
        Ok(())
    }
}

impl Write for AtomicFile {
    fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
        self.out.as_mut().expect("open until commit").write(buf)
    }
    fn flush(&mut self) -> io::Result<()> {
        self.out.as_mut().expect("open until commit").flush()
    }
}

impl Drop for AtomicFile {
    fn drop(&mut self) {
        drop(self.out.take());
        if !self.tmp.as_os_str().is_empty() {
            let _ = std::fs::remove_file(&self.tmp);
        }
    }
}

/// Writes `bytes` to `path` atomically (see the module): the target is replaced only
/// by the complete bytes. It changes no signal handling (the app can call it); a
/// command that calls [`crate::signals::watch`] first gets "a stop signal during the
/// write leaves nothing" too.
pub fn write_atomically(path: &Path, bytes: &[u8]) -> Result<(), OutputError> {
    let mut file = AtomicFile::create(path)?;
    file.write_bytes(bytes)?;
    file.commit(crate::signals::stop_flag())
}

/// The kind of a non-regular file, for messages ("a FIFO", "a directory").
pub fn kind(meta: &std::fs::Metadata) -> &'static str {
    let t = meta.file_type();
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileTypeExt;
        if t.is_fifo() {
            return "a FIFO";
        }
        if t.is_char_device() || t.is_block_device() {
            return "a device";
        }
        if t.is_socket() {
            return "a socket";
        }
    }
    if t.is_dir() {
        "a directory"
    } else {
        "not a regular file"
    }
}

/// A unit test's own folder in the system's temporary folder, removed when the test
/// ends, passed or failed (unit tests have no `CARGO_TARGET_TMPDIR`; runs left one
/// folder per test and run behind).
#[cfg(test)]
pub(crate) struct Scratch(PathBuf);

#[cfg(test)]
impl Scratch {
    pub(crate) fn new(test: &str) -> Self {
        let dir =
            std::env::temp_dir().join(format!("groovelab-unit-{}-{test}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        Scratch(dir)
    }
}

#[cfg(test)]
impl std::ops::Deref for Scratch {
    type Target = Path;
    fn deref(&self) -> &Path {
        &self.0
    }
}

#[cfg(test)]
impl Drop for Scratch {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scratch(test: &str) -> Scratch {
        Scratch::new(&format!("output-{test}"))
    }

    fn leftovers(dir: &Path) -> Vec<String> {
        std::fs::read_dir(dir)
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .filter(|n| n.ends_with(".tmp"))
            .collect()
    }

    #[test]
    fn writes_new_files_and_replaces_regular_ones_keeping_their_mode() {
        let dir = scratch("replace");
        let p = dir.join("out.csv");
        write_atomically(&p, b"one\n").unwrap();
        assert_eq!(std::fs::read(&p).unwrap(), b"one\n");
        #[cfg(unix)]
        {
            use std::os::unix::fs::PermissionsExt;
            std::fs::set_permissions(&p, std::fs::Permissions::from_mode(0o640)).unwrap();
            write_atomically(&p, b"two\n").unwrap();
            let mode = std::fs::metadata(&p).unwrap().permissions().mode() & 0o7777;
            assert_eq!(mode, 0o640);
            // A read-only file is replaced too, and stays read-only.
            std::fs::set_permissions(&p, std::fs::Permissions::from_mode(0o444)).unwrap();
            write_atomically(&p, b"three\n").unwrap();
            let mode = std::fs::metadata(&p).unwrap().permissions().mode() & 0o7777;
            assert_eq!(mode, 0o444);
        }
        assert_eq!(std::fs::read(&p).unwrap(), b"three\n");
        assert!(leftovers(&dir).is_empty());
    }

    #[test]
    fn refuses_targets_that_are_not_regular_files() {
        let dir = scratch("nonregular");
        let e = write_atomically(&dir, b"x").unwrap_err();
        assert!(e.to_string().contains("a directory"), "{e}");
        #[cfg(unix)]
        {
            let e = write_atomically(Path::new("/dev/null"), b"x").unwrap_err();
            assert!(e.to_string().contains("a device"), "{e}");
            let real = dir.join("real.csv");
            std::fs::write(&real, "keep").unwrap();
            let link = dir.join("link.csv");
            std::os::unix::fs::symlink(&real, &link).unwrap();
            let e = write_atomically(&link, b"x").unwrap_err();
            assert!(e.to_string().contains("a symlink"), "{e}");
            assert_eq!(std::fs::read_to_string(&real).unwrap(), "keep");
            assert!(
                std::fs::symlink_metadata(&link)
                    .unwrap()
                    .file_type()
                    .is_symlink()
            );
        }
        let e = write_atomically(&dir.join("no-such-dir").join("x.csv"), b"x").unwrap_err();
        assert!(e.to_string().starts_with("cannot write "), "{e}");
        assert!(leftovers(&dir).is_empty());
    }

    /// An existing file whose folder takes no new files (procfs): the message says so,
    /// not "No such file or directory", which the OS error would say of a file that is
    /// plainly there.
    #[cfg(target_os = "linux")]
    #[test]
    fn an_existing_file_in_a_folder_that_takes_no_files_says_so() {
        let target = Path::new("/proc/version");
        if !target.is_file() {
            return;
        }
        let err = write_atomically(target, b"x").unwrap_err().to_string();
        assert!(!err.contains("No such file"), "{err}");
        assert!(err.contains("its folder /proc takes no new files"), "{err}");
    }

    #[test]
    fn a_missing_folder_is_named() {
        let dir = scratch("missing-folder");
        let target = dir.join("nowhere/run.csv");
        let err = write_atomically(&target, b"x").unwrap_err().to_string();
        let folder = dir.join("nowhere");
        assert!(
            err.contains(&format!("its folder {} does not exist", folder.display())),
            "{err}"
        );
        // And before the work (`--overlay nodir/a.png` was refused only after a
        // whole tracking): the same words from the check.
        let early = check_output(&target).unwrap_err().to_string();
        assert!(early.contains("does not exist"), "{early}");
        assert!(check_output(&dir.join("run.csv")).is_ok());
        assert!(check_output(Path::new("bare-name.csv")).is_ok());
    }

    #[test]
    fn a_stop_before_commit_writes_nothing_and_removes_the_temp_file() {
        let dir = scratch("stop");
        let p = dir.join("out.csv");
        std::fs::write(&p, "old").unwrap();
        let mut f = AtomicFile::create(&p).unwrap();
        f.write_bytes(b"new, complete").unwrap();
        let tmp = f.temp_path().to_path_buf();
        assert!(tmp.exists());
        // Ctrl-C after all the work, before the rename.
        let stop = AtomicBool::new(true);
        assert!(matches!(f.commit(&stop), Err(OutputError::Interrupted)));
        assert!(!tmp.exists());
        assert_eq!(std::fs::read_to_string(&p).unwrap(), "old");
        // An error part-way (dropped uncommitted) removes it too.
        let mut f = AtomicFile::create(&p).unwrap();
        f.write_bytes(b"half").unwrap();
        drop(f);
        assert!(leftovers(&dir).is_empty());
        assert_eq!(std::fs::read_to_string(&p).unwrap(), "old");
    }
}
