//! Presets as files: a preset named on the command line or in the app (built-in, in
//! the user's preset folder, or a path), the user's folder listed, and a scene
//! saved there. The text form itself is `study::preset`'s.

use std::path::{Path, PathBuf};

use crate::input::file::{FileError, FileRole, MAX_FILE_BYTES, read_user_file};
use crate::settings::spec::SceneSpec;
use crate::study::measured::Measured;
use crate::study::preset::{self, Preset, PresetError, PresetOrigin};

/// Why a preset named on the command line or in the app could not be loaded.
#[derive(Debug, thiserror::Error)]
pub enum LoadError {
    /// No built-in preset, no file: `name` as the user typed it.
    #[error(
        "unknown preset '{}', allowed: a name from `groovelab presets` or a .toml file",
        crate::settings::quote::clip(name)
    )]
    Unknown { name: String },
    #[error(transparent)]
    Io(FileError),
    #[error(transparent)]
    Malformed(#[from] PresetError),
}

/// Why a scene could not be saved as a preset.
#[derive(Debug, thiserror::Error)]
pub enum SaveError {
    /// A name, as the user typed it, that cannot name a preset file.
    #[error(
        "name '{name}', allowed letters, digits, - _ . (no spaces: it is typed after --preset)"
    )]
    BadName { name: String },
    #[error("no preset folder (set GROOVELAB_PRESETS)")]
    NoFolder,
    #[error("{0} exists")]
    Exists(PathBuf),
    /// The preset's text could not be made.
    #[error("cannot write the preset: {0}")]
    Text(toml::ser::Error),
    /// What would be written does not load again (a bug: never write it).
    #[error("the file would not load again: {0}")]
    WouldNotLoad(PresetError),
    #[error("{0}")]
    Folder(std::io::Error),
    #[error(transparent)]
    Write(crate::output::OutputError),
}

/// A built-in preset by name, or a preset file by path.
pub fn load(name_or_path: &str) -> Result<Preset, LoadError> {
    if let Some(preset) = Preset::built_in_named(name_or_path) {
        return Ok(preset?);
    }
    let user = user_dir().map(|d| d.join(format!("{name_or_path}.toml")));
    let path = match user {
        Some(p) if p.exists() => p,
        _ => PathBuf::from(name_or_path),
    };
    if !path.exists() {
        return Err(LoadError::Unknown {
            name: name_or_path.to_string(),
        });
    }
    // Something is there: it must be a regular file of sane size (not a FIFO
    // that would block, not /dev/zero).
    let text = read_user_file(&path, FileRole::Preset, MAX_FILE_BYTES).map_err(LoadError::Io)?;
    Ok(Preset::parse(
        &text,
        &path.display().to_string(),
        PresetOrigin::File(path),
    )?)
}

/// Built-in presets, then the user's (from [`user_dir`]); unreadable user files are
/// returned as errors beside the good ones.
pub fn all() -> (Vec<Preset>, Vec<LoadError>) {
    all_in(user_dir().as_deref())
}

/// Built-in presets, then those in `dir` (if any).
pub fn all_in(dir: Option<&Path>) -> (Vec<Preset>, Vec<LoadError>) {
    let mut presets = Preset::built_in();
    let mut errors = Vec::new();
    if let Some(dir) = dir
        && let Ok(entries) = std::fs::read_dir(dir)
    {
        let mut paths: Vec<PathBuf> = entries
            .filter_map(|e| e.ok().map(|e| e.path()))
            .filter(|p| p.extension().is_some_and(|x| x == "toml"))
            .collect();
        paths.sort();
        for path in paths {
            match load(&path.display().to_string()) {
                Ok(p) => presets.push(p),
                Err(e) => errors.push(e),
            }
        }
    }
    (presets, errors)
}

/// What a user preset is saved from: the scene's settings (SI), its measured series,
/// and the preset it started from (named in a new file's description).
#[derive(Clone, Copy, Debug)]
pub struct ToSave<'a> {
    pub spec: &'a SceneSpec,
    pub measured: Option<&'a Measured>,
    pub started_from: &'a str,
}

/// Saves a scene (and its measured series) as a user preset in `dir`; never over an
/// existing file unless `overwrite`. Returns the path written.
pub fn save(
    scene: ToSave,
    dir: Option<&Path>,
    name: &str,
    overwrite: bool,
) -> Result<PathBuf, SaveError> {
    PresetFile::new(scene, dir, name, overwrite)?.write()
}

/// A user preset ready to be written: its path and its text, checked to load again.
#[derive(Clone, Debug)]
pub struct PresetFile {
    pub path: PathBuf,
    text: String,
}

impl PresetFile {
    /// The preset [`save`] would write, or why it would not.
    pub fn new(
        scene: ToSave,
        dir: Option<&Path>,
        name: &str,
        overwrite: bool,
    ) -> Result<PresetFile, SaveError> {
        // A name typed as its file's ("x.toml") is that preset's name.
        let name = name.trim();
        let name = name.strip_suffix(".toml").unwrap_or(name);
        let valid = !name.is_empty()
            && name
                .chars()
                .all(|c| c.is_ascii_alphanumeric() || c == '-' || c == '_' || c == '.');
        if !valid {
            return Err(SaveError::BadName {
                name: name.to_string(),
            });
        }
        let dir = dir.ok_or(SaveError::NoFolder)?;
        let path = dir.join(format!("{name}.toml"));
        if path.exists() && !overwrite {
            return Err(SaveError::Exists(path));
        }
        // Overwriting keeps the description of the file it replaces.
        let kept = path
            .is_file()
            .then(|| load(&path.display().to_string()).ok())
            .flatten()
            .map(|p| p.description);
        let description = kept.unwrap_or_else(|| {
            format!("Saved from groovelab (started from {})", scene.started_from)
        });
        let text = preset::to_toml(name, &description, scene.spec, scene.measured)
            .map_err(SaveError::Text)?;
        // What is written must load again: check before reporting success.
        Preset::parse(&text, name, PresetOrigin::BuiltIn).map_err(SaveError::WouldNotLoad)?;
        Ok(PresetFile { path, text })
    }

    /// Writes the file (its folder made first); returns its path.
    pub fn write(self) -> Result<PathBuf, SaveError> {
        if let Some(dir) = self.path.parent() {
            std::fs::create_dir_all(dir).map_err(SaveError::Folder)?;
        }
        crate::output::write_atomically(&self.path, self.text.as_bytes())
            .map_err(SaveError::Write)?;
        Ok(self.path)
    }
}

/// Where user presets live: `$GROOVELAB_PRESETS`, else
/// `$XDG_CONFIG_HOME/groovelab/presets`, else `~/.config/groovelab/presets`.
pub fn user_dir() -> Option<PathBuf> {
    if let Some(dir) = std::env::var_os("GROOVELAB_PRESETS") {
        return Some(PathBuf::from(dir));
    }
    let config = std::env::var_os("XDG_CONFIG_HOME")
        .map(PathBuf::from)
        .or_else(|| std::env::var_os("HOME").map(|h| Path::new(&h).join(".config")))?;
    Some(config.join("groovelab").join("presets"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn preset_files_must_be_regular_files() {
        let dir = std::env::temp_dir();
        let e = load(&dir.display().to_string()).unwrap_err();
        assert!(e.to_string().contains("a directory"), "{e}");
        #[cfg(unix)]
        {
            let e = load("/dev/zero").unwrap_err();
            assert!(e.to_string().contains("a device"), "{e}");
        }
    }
}
