//! Why a sweep cannot be loaded, or a case asked for does not exist.

use crate::world_file::WorldFileError;

/// A sweep file that cannot be loaded, or a case index past the last.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum SweepError {
    /// The sweep file cannot be read: the system's message.
    #[error("{file}: cannot read the sweep file: {message}")]
    Io {
        /// The path as given.
        file: String,
        /// What the system reported.
        message: String,
    },
    /// The sweep file is invalid: the error names the sweep file, its line, column and key,
    /// as a world file's errors do (e.g. `s.toml:5:1: unknown key 'vehicle.brakeCoeficient';
    /// did you mean 'brakeCoefficient'?` for an axis over a key that worlds do not have).
    #[error("{0}")]
    File(Box<WorldFileError>),
    /// The base world cannot be loaded: the world file's error.
    #[error("{0}")]
    World(Box<WorldFileError>),
    /// No case has this index.
    #[error("no case {index}: the sweep has {cases} cases, numbered from 0")]
    NoSuchCase {
        /// The index asked for.
        index: usize,
        /// The number of cases.
        cases: usize,
    },
}

impl SweepError {
    /// [`SweepError::File`] of `e`.
    pub(crate) fn file(e: WorldFileError) -> SweepError {
        SweepError::File(Box::new(e))
    }

    /// [`SweepError::World`] of `e`.
    pub(crate) fn world(e: WorldFileError) -> SweepError {
        SweepError::World(Box::new(e))
    }

    /// The located error of a sweep file or base world (its file, line, column and key).
    pub fn file_error(&self) -> Option<&WorldFileError> {
        match self {
            SweepError::File(e) | SweepError::World(e) => Some(e.as_ref()),
            _ => None,
        }
    }
}
