//! `sweep.json`: what a sweep's output directory holds (which sweep, which shard, how many
//! rows), so that `sweep-merge` can check that shards belong together and are complete.

use core::fmt;
use std::path::Path;

use serde::{Deserialize, Serialize};

use super::draw::fnv1a;
use super::shard::Shard;

/// The manifest's file name in an output directory.
pub const MANIFEST_JSON: &str = "sweep.json";

/// A fingerprint of a sweep: an FNV-1a hash of the program's version, the sweep file's text
/// and the base world's text. Shards of one sweep have the same; a sweep file or base world
/// edited between two shards' runs (or another version of the program) gives another.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct Fingerprint(u64);

impl Fingerprint {
    /// The fingerprint of a sweep file's text and its base world's text.
    pub(crate) fn of(sweep_text: &str, world_text: &str) -> Fingerprint {
        let mut bytes = Vec::with_capacity(sweep_text.len() + world_text.len() + 32);
        bytes.extend_from_slice(env!("CARGO_PKG_VERSION").as_bytes());
        bytes.push(0);
        bytes.extend_from_slice(sweep_text.as_bytes());
        bytes.push(0);
        bytes.extend_from_slice(world_text.as_bytes());
        Fingerprint(fnv1a(&bytes))
    }
}

impl fmt::Display for Fingerprint {
    /// 16 hexadecimal digits.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{:016x}", self.0)
    }
}

/// The manifest of a sweep's output directory (`sweep.json`).
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
pub struct Manifest {
    /// The sweep file, as given to the run.
    pub sweep: String,
    /// The sweep's [`Fingerprint`].
    pub fingerprint: String,
    /// The version of `vehicle-sim` that ran it.
    pub version: String,
    /// The scenario's name.
    pub scenario: String,
    /// The number of cases of the whole sweep.
    pub cases: usize,
    /// The shard's index (0 for a whole sweep).
    pub shard_index: usize,
    /// The number of shards (1 for a whole sweep).
    pub shard_count: usize,
    /// The axes' keys (their columns follow `case`).
    pub axes: Vec<String>,
    /// The columns of `results.csv`.
    pub columns: Vec<String>,
    /// Rows written to `results.csv` so far.
    pub rows: usize,
    /// Rows of failed cases among them.
    pub errors: usize,
    /// True once every case of the shard has its row: a shard whose run was stopped stays
    /// `false`.
    pub complete: bool,
    /// The sweep file's `color_by` ([`ColorBy::key`](super::ColorBy::key)): the axis the
    /// plots colour the cases by, `"none"`, or absent for the automatic choice.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub color_by: Option<String>,
}

impl Manifest {
    /// The shard, if its index and count make one.
    pub fn shard(&self) -> Option<Shard> {
        Shard::new(self.shard_index, self.shard_count)
    }

    /// Reads `dir/sweep.json`.
    ///
    /// # Errors
    /// The file cannot be read or is not a manifest: a sentence saying which.
    pub fn read(dir: &Path) -> Result<Manifest, String> {
        let path = dir.join(MANIFEST_JSON);
        let text = crate::world_file::read_text(&path).map_err(|e| {
            format!(
                "{}: {e} (not an output directory of vehicle-sim sweep?)",
                path.display()
            )
        })?;
        serde_json::from_str(&text)
            .map_err(|e| format!("{}: not a sweep manifest: {e}", path.display()))
    }

    /// Writes `dir/sweep.json`: into a temporary file beside it, then renamed over it, so
    /// that a run killed while writing leaves the previous manifest whole, never half of one.
    ///
    /// # Errors
    /// What the system reported.
    pub fn write(&self, dir: &Path) -> std::io::Result<()> {
        // Strings, numbers and booleans always serialise.
        let text = serde_json::to_string_pretty(self).unwrap_or_default();
        let temporary = dir.join(format!(".{MANIFEST_JSON}.{}", std::process::id()));
        std::fs::write(&temporary, text + "\n")?;
        std::fs::rename(&temporary, dir.join(MANIFEST_JSON)).inspect_err(|_| {
            let _ = std::fs::remove_file(&temporary);
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fingerprints_change_with_either_text() {
        let a = Fingerprint::of("s", "w");
        assert_eq!(a, Fingerprint::of("s", "w"));
        assert_ne!(a, Fingerprint::of("s ", "w"));
        assert_ne!(a, Fingerprint::of("s", "w "));
        // The separator keeps "ab" + "c" apart from "a" + "bc".
        assert_ne!(Fingerprint::of("ab", "c"), Fingerprint::of("a", "bc"));
        assert_eq!(a.to_string().len(), 16);
    }
}
