//! `sweep-merge`: the output directories of a sweep's shards put back together into one
//! `results.csv` in case order, identical to the whole sweep's, after checking that the
//! shards come from one sweep and that every case is there exactly once.
//!
//! The rows are read as streams, one from each shard in turn (case `c` is in shard
//! `c mod n`), so memory does not grow with the number of cases. Each row's checksum is
//! checked: a value edited by hand in a shard's file stops the merge.
//!
//! The merged files are written into a fresh directory inside the output directory
//! ([`STAGING_PREFIX`] and the process id) and moved into place only when all of them are
//! written, `sweep.json` last: a failed merge leaves the output directory as it was (an
//! earlier merge's files whole and consistent), never a truncated `results.csv` beside a
//! manifest that says it is complete.

use std::fs::File;
use std::io::BufWriter;
use std::path::{Path, PathBuf};

use super::color::ColorBy;
use super::error::{OutputError, csv_at, io_at};
use super::manifest::{MANIFEST_JSON, Manifest};
use super::output::{PLOTS_DIR, RESULTS_CSV, TIMINGS_CSV, finish};
use super::plots::write_plots;
use super::row::{ERROR_COLUMN, checksum_matches, csv_writer};
use super::shard::{MAX_SHARDS, Shard};

/// Why shards cannot be merged.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum MergeError {
    /// No directory was given.
    #[error("no shard directory to merge")]
    NoInput,
    /// A directory has no readable manifest.
    #[error("{0}")]
    Manifest(String),
    /// Two directories come from different sweeps (or program versions).
    #[error(
        "{} is not a shard of the sweep of {}: {what}",
        other.display(),
        first.display()
    )]
    DifferentSweep {
        /// The first directory.
        first: PathBuf,
        /// The one that differs.
        other: PathBuf,
        /// What differs.
        what: String,
    },
    /// Two directories hold the same shard.
    #[error("shard {shard} is given twice: {} and {}", dirs[0].display(), dirs[1].display())]
    DuplicateShard {
        /// The shard.
        shard: Shard,
        /// Its two directories.
        dirs: [PathBuf; 2],
    },
    /// Shards are missing.
    #[error("{} missing: merge the outputs of all {count} shards", list(missing, *absent))]
    MissingShards {
        /// The first missing shards, in shard order: at most [`LISTED_MISSING`].
        missing: Vec<Shard>,
        /// How many shards are missing in all.
        absent: usize,
        /// The number of shards.
        count: usize,
    },
    /// A shard's run did not finish.
    #[error(
        "shard {shard} in {} did not finish: it has {rows} of its {expected} rows (run it again)",
        dir.display()
    )]
    Incomplete {
        /// The shard.
        shard: Shard,
        /// Its directory.
        dir: PathBuf,
        /// Rows written.
        rows: usize,
        /// Rows it should have.
        expected: usize,
    },
    /// A case's row is not where it should be.
    #[error("case {case} is missing: {}/{file} {found}", dir.display())]
    MissingCase {
        /// The case.
        case: usize,
        /// The directory of the shard that should have it.
        dir: PathBuf,
        /// The file.
        file: &'static str,
        /// What the file has instead (`ends before it`, `has case 12 in its place`).
        found: String,
    },
    /// A file has rows after its shard's last case.
    #[error(
        "{}/{file} has a row after its shard's last case (case {case}): a case is duplicated \
         or the sweep had more cases",
        dir.display()
    )]
    ExtraRow {
        /// The directory.
        dir: PathBuf,
        /// The file.
        file: &'static str,
        /// The row's case.
        case: String,
    },
    /// A `results.csv` whose header is not the manifest's columns.
    #[error("{}/{RESULTS_CSV}: its header is not the columns of {MANIFEST_JSON}", dir.display())]
    Header {
        /// The directory.
        dir: PathBuf,
    },
    /// The output directory is one of the shards'.
    #[error("--out {} is one of the shard directories: merge into another", .0.display())]
    OutputIsInput(PathBuf),
    /// A row's checksum does not match its cells: the file was edited or damaged.
    #[error(
        "{}/{RESULTS_CSV} line {line}: case {case}'s checksum does not match its cells (the row \
         was edited or damaged; run the shard again)",
        dir.display()
    )]
    Checksum {
        /// The shard's directory.
        dir: PathBuf,
        /// The line of the row (1 is the header).
        line: u64,
        /// The row's case.
        case: usize,
    },
    /// A file could not be read or written.
    #[error(transparent)]
    Output(#[from] OutputError),
}

/// The start of the name of the directory a merge writes into before moving its files into
/// the output directory; a failed merge removes it.
pub const STAGING_PREFIX: &str = ".sweep-merge-";

/// Most missing shards a [`MergeError::MissingShards`] names: a merge given one shard of
/// 100,000 says so in one line, and finding them takes no memory per missing shard.
pub const LISTED_MISSING: usize = 8;

/// `shard 1/3 is`, `shards 1/3 and 2/3 are`, `shards 1/9, 2/9 and 4 more are`… of the first
/// missing `shards` of `absent` in all.
fn list(shards: &[Shard], absent: usize) -> String {
    let names: Vec<String> = shards.iter().map(ToString::to_string).collect();
    let more = absent.saturating_sub(names.len());
    match names.split_last() {
        Some((last, [])) if more == 0 => format!("shard {last} is"),
        Some((last, rest)) if more == 0 => format!("shards {} and {last} are", rest.join(", ")),
        Some(_) => format!("shards {} and {more} more are", names.join(", ")),
        None => "no shard is".to_string(),
    }
}

/// What merging did.
#[derive(Debug, Clone, PartialEq)]
pub struct MergeSummary {
    /// The number of shards merged.
    pub shards: usize,
    /// Rows written (the sweep's cases).
    pub rows: usize,
    /// Rows of failed cases among them.
    pub errors: usize,
    /// The files written, `results.csv` first.
    pub files: Vec<PathBuf>,
}

/// The manifests of `dirs` checked to be the complete set of shards of one sweep, in shard
/// order.
fn shards_of(dirs: &[PathBuf]) -> Result<Vec<(PathBuf, Manifest)>, MergeError> {
    let mut found: Vec<(PathBuf, Manifest)> = Vec::with_capacity(dirs.len());
    for dir in dirs {
        let m = Manifest::read(dir).map_err(MergeError::Manifest)?;
        let shard = m.shard().ok_or_else(|| {
            MergeError::Manifest(format!(
                "{}: shard {}/{} is not a shard (0 <= I < N <= {MAX_SHARDS})",
                dir.join(MANIFEST_JSON).display(),
                m.shard_index,
                m.shard_count
            ))
        })?;
        if let Some((first, f)) = found.first() {
            let differs = |what: String| MergeError::DifferentSweep {
                first: first.clone(),
                other: dir.clone(),
                what,
            };
            if f.fingerprint != m.fingerprint {
                return Err(differs(format!(
                    "its fingerprint {} differs from {} (sweep '{}' against '{}': the sweep \
                     file, its base world or vehicle-sim's version {} against {} changed)",
                    m.fingerprint, f.fingerprint, m.sweep, f.sweep, m.version, f.version
                )));
            }
            if f.shard_count != m.shard_count {
                return Err(differs(format!(
                    "it is shard {shard} where {} is shard {}/{}: shards of one run share \
                     their count",
                    first.display(),
                    f.shard_index,
                    f.shard_count
                )));
            }
            if f.columns != m.columns || f.cases != m.cases || f.axes != m.axes {
                return Err(differs("its columns or number of cases differ".to_string()));
            }
        }
        if let Some((other, _)) = found.iter().find(|(_, o)| o.shard_index == m.shard_index) {
            return Err(MergeError::DuplicateShard {
                shard,
                dirs: [other.clone(), dir.clone()],
            });
        }
        let expected = shard.len(m.cases);
        if !m.complete || m.rows != expected {
            return Err(MergeError::Incomplete {
                shard,
                dir: dir.clone(),
                rows: m.rows,
                expected,
            });
        }
        found.push((dir.clone(), m));
    }
    let count = found.first().map_or(0, |(_, m)| m.shard_count);
    // The shards found are distinct shards of `count`: the others are missing. Only the first
    // few are named, found in order with no allocation per missing shard (the walk stops
    // after the found ones and the listed ones).
    found.sort_by_key(|(_, m)| m.shard_index);
    let absent = count - found.len();
    if absent > 0 {
        let mut present = found.iter().map(|(_, m)| m.shard_index).peekable();
        let missing: Vec<Shard> = (0..count)
            .filter(|&i| present.next_if_eq(&i).is_none())
            .filter_map(|i| Shard::new(i, count))
            .take(LISTED_MISSING)
            .collect();
        return Err(MergeError::MissingShards {
            missing,
            absent,
            count,
        });
    }
    Ok(found)
}

/// Interleaves the `file` of each shard directory (in shard order) into `out/file`, checking
/// that the row of case `c` is the next of shard `c mod n`; `header` (`results.csv`'s
/// columns) is checked against the first line of each when given, and then each row's
/// checksum too. Returns the rows written and those whose `error` cell is not empty.
fn interleave(
    shards: &[(PathBuf, Manifest)],
    file: &'static str,
    cases: usize,
    header: Option<&[String]>,
    out: &Path,
) -> Result<(usize, usize), MergeError> {
    let mut readers = Vec::with_capacity(shards.len());
    let mut first_header = None;
    for (dir, _) in shards {
        let path = dir.join(file);
        let mut r = csv::ReaderBuilder::new()
            .from_path(&path)
            .map_err(csv_at(&path))?;
        let h = r.headers().map_err(csv_at(&path))?.clone();
        if header.is_some_and(|cols| !h.iter().eq(cols.iter().map(String::as_str))) {
            return Err(MergeError::Header { dir: dir.clone() });
        }
        first_header.get_or_insert(h);
        readers.push((dir, path, r.into_records()));
    }
    let out_path = out.join(file);
    let mut w = csv_writer(BufWriter::new(
        File::create(&out_path).map_err(io_at(&out_path))?,
    ));
    if let Some(h) = &first_header {
        w.write_record(h).map_err(csv_at(&out_path))?;
    }
    let n = readers.len().max(1);
    let error_at = header.and_then(|cols| cols.iter().position(|c| c == ERROR_COLUMN));
    let mut errors = 0;
    for case in 0..cases {
        let Some((dir, path, records)) = readers.get_mut(case % n) else {
            break;
        };
        let missing = |found: String| MergeError::MissingCase {
            case,
            dir: dir.to_path_buf(),
            file,
            found,
        };
        let record = match records.next() {
            None => return Err(missing("ends before it".to_string())),
            Some(r) => r.map_err(csv_at(path))?,
        };
        let index = record.get(0).unwrap_or("");
        if index != case.to_string() {
            return Err(missing(format!("has case {index} in its place")));
        }
        if header.is_some() && !checksum_matches(&record) {
            return Err(MergeError::Checksum {
                dir: dir.to_path_buf(),
                line: record.position().map_or(0, csv::Position::line),
                case,
            });
        }
        errors += usize::from(
            error_at
                .and_then(|i| record.get(i))
                .is_some_and(|e| !e.is_empty()),
        );
        w.write_record(&record).map_err(csv_at(&out_path))?;
    }
    for (dir, path, records) in &mut readers {
        if let Some(r) = records.next() {
            let r = r.map_err(csv_at(path))?;
            return Err(MergeError::ExtraRow {
                dir: dir.to_path_buf(),
                file,
                case: r.get(0).unwrap_or("").to_string(),
            });
        }
    }
    finish(w, &out_path)?;
    Ok((cases, errors))
}

/// Merges the output directories `dirs` of a sweep's shards (`vehicle-sim sweep --shard`)
/// into `out` (created if needed): `results.csv` in case order, byte for byte what the whole
/// sweep writes, `timings.csv`, `sweep.json` (as for shard 0/1) and the plots.
///
/// # Errors
/// A [`MergeError`] saying which directory is not of the sweep, which shard is missing or
/// given twice or did not finish, which case is missing or duplicated, or which file could
/// not be read or written.
pub fn merge(dirs: &[PathBuf], out: &Path) -> Result<MergeSummary, MergeError> {
    if dirs.is_empty() {
        return Err(MergeError::NoInput);
    }
    if let Ok(o) = out.canonicalize()
        && dirs.iter().any(|d| d.canonicalize().is_ok_and(|d| d == o))
    {
        return Err(MergeError::OutputIsInput(out.to_path_buf()));
    }
    let shards = shards_of(dirs)?;
    let Some((_, first)) = shards.first() else {
        return Err(MergeError::NoInput);
    };
    let mut manifest = first.clone();
    std::fs::create_dir_all(out).map_err(io_at(out))?;
    let staging = out.join(format!("{STAGING_PREFIX}{}", std::process::id()));
    // A directory of that name is a merge of this process id that died: its files are stale.
    if staging.exists() {
        std::fs::remove_dir_all(&staging).map_err(io_at(&staging))?;
    }
    std::fs::create_dir(&staging).map_err(io_at(&staging))?;
    let written = write_merged(&shards, &mut manifest, &staging);
    let moved = written.and_then(|(rows, errors, staged)| {
        move_into(&staging, out, &staged)?;
        Ok((rows, errors, staged))
    });
    // Whatever happened, the staging directory goes (on success it is empty).
    let _ = std::fs::remove_dir_all(&staging);
    let (rows, errors, staged) = moved?;
    Ok(MergeSummary {
        shards: shards.len(),
        rows,
        errors,
        files: staged.iter().map(|name| out.join(name)).collect(),
    })
}

/// Writes the merged files into `staging`: `results.csv`, `timings.csv`, `sweep.json` and
/// the plots. Returns the rows, the failed rows and the names of the files written (relative
/// to `staging`, `results.csv` first).
fn write_merged(
    shards: &[(PathBuf, Manifest)],
    manifest: &mut Manifest,
    staging: &Path,
) -> Result<(usize, usize, Vec<PathBuf>), MergeError> {
    let (rows, errors) = interleave(
        shards,
        RESULTS_CSV,
        manifest.cases,
        Some(&manifest.columns),
        staging,
    )?;
    interleave(shards, TIMINGS_CSV, manifest.cases, None, staging)?;
    manifest.shard_index = 0;
    manifest.shard_count = 1;
    manifest.rows = rows;
    manifest.errors = errors;
    manifest.complete = true;
    let manifest_path = staging.join(MANIFEST_JSON);
    manifest.write(staging).map_err(io_at(&manifest_path))?;
    let results = staging.join(RESULTS_CSV);
    let mut files = vec![results.clone(), staging.join(TIMINGS_CSV), manifest_path];
    files.extend(write_plots(
        &results,
        &manifest.axes,
        &manifest.scenario,
        &ColorBy::from_key(manifest.color_by.as_deref()),
        &staging.join(PLOTS_DIR),
    )?);
    let names = files
        .iter()
        .map(|f| f.strip_prefix(staging).unwrap_or(f).to_path_buf())
        .collect();
    Ok((rows, errors, names))
}

/// Moves the merged files from `staging` into `out`: the old manifest goes first (so that
/// no moment shows the new rows beside an old manifest claiming completeness), the old plots
/// directory is replaced whole, and the new manifest comes last.
fn move_into(staging: &Path, out: &Path, staged: &[PathBuf]) -> Result<(), MergeError> {
    let rename = |from: PathBuf, to: PathBuf| -> Result<(), MergeError> {
        std::fs::rename(&from, &to).map_err(|e| MergeError::Output(io_at(&to)(e)))
    };
    let old_manifest = out.join(MANIFEST_JSON);
    if old_manifest.exists() {
        std::fs::remove_file(&old_manifest)
            .map_err(|e| MergeError::Output(io_at(&old_manifest)(e)))?;
    }
    let old_plots = out.join(PLOTS_DIR);
    if old_plots.is_dir() {
        std::fs::remove_dir_all(&old_plots)
            .map_err(|e| MergeError::Output(io_at(&old_plots)(e)))?;
    }
    for name in [RESULTS_CSV, TIMINGS_CSV, PLOTS_DIR, MANIFEST_JSON] {
        let from = staging.join(name);
        if from.exists() && staged.iter().any(|s| s.starts_with(name)) {
            rename(from, out.join(name))?;
        }
    }
    Ok(())
}
