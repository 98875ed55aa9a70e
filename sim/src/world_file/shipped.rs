//! The world files shipped in `sim/worlds`, embedded in the library (by `sim/build.rs`) so
//! that an installed `vehicle-sim` runs them by name: `--world two-cars` (or `two-cars.toml`)
//! loads `sim/worlds/two-cars.toml` when no file of that name exists. The files a shipped
//! world includes (e.g. `road = "hilly-banked.xodr"`) are read from the same embedded set.

use std::borrow::Cow;
use std::path::{Path, PathBuf};

/// Every file of `sim/worlds` by file name, sorted by name: `(file name, text)`.
const FILES: &[(&str, &str)] = include!(concat!(env!("OUT_DIR"), "/shipped_worlds.rs"));

/// The directory that the source of a shipped world names (e.g. `<shipped>/two-cars.toml`),
/// so that a file it includes resolves, as for a world on disk, relative to it.
pub const SHIPPED_DIR: &str = "<shipped>";

/// The extension of a world file.
const WORLD_EXTENSION: &str = ".toml";

/// A shipped world file.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ShippedWorld {
    /// Its name: the file name without `.toml`, e.g. `two-cars`.
    pub name: &'static str,
    /// Its file name, e.g. `two-cars.toml`.
    pub file_name: &'static str,
    /// Its text.
    pub text: &'static str,
}

impl ShippedWorld {
    /// The text of its first comment line (without `#`), which says what the world is;
    /// empty when it has none.
    pub fn summary(&self) -> &'static str {
        self.text
            .lines()
            .map(str::trim)
            .find_map(|l| l.strip_prefix('#'))
            .map_or("", str::trim)
    }

    /// The source under which its messages name it: `<shipped>/two-cars.toml`.
    pub fn source(&self) -> String {
        format!("{SHIPPED_DIR}/{}", self.file_name)
    }
}

/// Every shipped world, sorted by name.
pub fn worlds() -> impl Iterator<Item = ShippedWorld> {
    FILES.iter().filter_map(|&(file_name, text)| {
        file_name
            .strip_suffix(WORLD_EXTENSION)
            .map(|name| ShippedWorld {
                name,
                file_name,
                text,
            })
    })
}

/// The shipped world called `name`, with or without `.toml` (e.g. `two-cars`).
pub fn world(name: &str) -> Option<ShippedWorld> {
    let name = name.strip_suffix(WORLD_EXTENSION).unwrap_or(name);
    worlds().find(|w| w.name == name)
}

/// The names and file names of the shipped worlds, for suggestions.
pub(crate) fn names() -> impl Iterator<Item = &'static str> {
    worlds().flat_map(|w| [w.name, w.file_name])
}

/// The text of the embedded file that `path` names when it is in [`SHIPPED_DIR`] (a file a
/// shipped world includes), else `None`: the path is read from disk.
pub(crate) fn included(path: &Path) -> Option<&'static str> {
    let name = path.strip_prefix(SHIPPED_DIR).ok()?.to_str()?;
    FILES
        .iter()
        .find(|(f, _)| *f == name)
        .map(|&(_, text)| text)
}

/// The path of the file `name` that the world file `world` includes (relative to its
/// directory).
pub(crate) fn include_path(world: &str, name: &str) -> PathBuf {
    Path::new(world)
        .parent()
        .unwrap_or(Path::new(""))
        .join(name)
}

/// The text of the included file at `path`: the embedded copy for a file a shipped world
/// includes ([`included`]), else the file on disk.
///
/// # Errors
/// The disk read's error.
pub(crate) fn read_included(path: &Path) -> std::io::Result<Cow<'static, str>> {
    match included(path) {
        Some(text) => Ok(Cow::Borrowed(text)),
        None => std::fs::read_to_string(path).map(Cow::Owned),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_shipped_worlds_are_embedded_with_their_includes() {
        let two_cars = world("two-cars").unwrap();
        assert_eq!(world("two-cars.toml"), Some(two_cars));
        assert_eq!(two_cars.file_name, "two-cars.toml");
        assert!(two_cars.summary().starts_with("Two cars and a robot"));
        assert!(world("no-such-world").is_none());
        let xodr = included(Path::new("<shipped>/hilly-banked.xodr")).unwrap();
        assert!(xodr.contains("OpenDRIVE"));
        assert!(included(Path::new("hilly-banked.xodr")).is_none());
        // Every shipped world loads from its embedded text, includes and all.
        for w in worlds() {
            let loaded = super::super::load(w.name).unwrap_or_else(|e| panic!("{e}"));
            assert_eq!(loaded.source, w.source());
        }
    }
}
