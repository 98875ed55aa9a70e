//! Why a sweep cannot be loaded, a case asked for does not exist, or the outputs cannot be
//! written.

#[cfg(feature = "app")]
use std::path::{Path, PathBuf};

#[cfg(feature = "app")]
use crate::report::PlotError;
use crate::world_file::WorldFileError;

#[cfg(feature = "app")]
use super::runner::RunError;

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

/// Why a sweep's outputs could not be written.
#[cfg(feature = "app")]
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum OutputError {
    /// A file or directory could not be written or read.
    #[error("{}: {source}", path.display())]
    Io {
        /// The path concerned.
        path: PathBuf,
        /// What the system reported.
        source: std::io::Error,
    },
    /// A CSV file could not be written or read.
    #[error("{}: {source}", path.display())]
    Csv {
        /// The file.
        path: PathBuf,
        /// What the CSV library reported.
        source: csv::Error,
    },
    /// The run could not start its threads.
    #[error(transparent)]
    Run(RunError),
    /// `--resume` was asked for a directory that holds another run, or damaged rows.
    #[error("cannot resume the run in {}: {reason}", dir.display())]
    Resume {
        /// The output directory.
        dir: PathBuf,
        /// Why not.
        reason: String,
    },
    /// A plot could not be drawn.
    #[error(transparent)]
    Plot(#[from] PlotError),
    /// The axis the plots are to be coloured by is not one of the sweep's, or has more values
    /// than there are colours.
    #[error("cannot colour the plots by '{axis}': {reason}")]
    ColorBy {
        /// The axis asked for.
        axis: String,
        /// Why not.
        reason: String,
    },
}

/// A closure turning an I/O error into an [`OutputError`] about `path`.
#[cfg(feature = "app")]
pub(crate) fn io_at(path: &Path) -> impl FnOnce(std::io::Error) -> OutputError + '_ {
    move |source| OutputError::Io {
        path: path.to_path_buf(),
        source,
    }
}

/// A closure turning a CSV error into an [`OutputError`] about `path`.
#[cfg(feature = "app")]
pub(crate) fn csv_at(path: &Path) -> impl Fn(csv::Error) -> OutputError + '_ {
    move |source| OutputError::Csv {
        path: path.to_path_buf(),
        source,
    }
}
