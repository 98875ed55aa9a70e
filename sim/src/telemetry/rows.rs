//! Telemetry rows in a block of memory that front-ends can share without a copy.
//!
//! A [`TelemetryLog`](super::TelemetryLog) keeps the rows it holds in memory in a [`Block`]:
//! `SAMPLE_COLUMNS` f64 values per row, row after row, behind an [`Arc`]. A front-end asks
//! for a [`SharedRows`] (the Python package makes a read-only numpy array of it) that holds
//! the block alive, so the array stays valid however the log goes on (it grows into a new
//! block, spills to its file, is rewound or dropped).
//!
//! The values a [`SharedRows`] covers never change: the log only writes rows past those it
//! has handed out, and copies its block first when it would write into a row that a shared
//! block may show (a ring overwriting its oldest row, a rewind writing again). The cells are
//! [`AtomicU64`] (the bits of an f64) so that the log writes through the shared [`Arc`]
//! without `unsafe`; their memory is that of plain f64 values.

use std::sync::Arc;
use std::sync::atomic::{AtomicU64, Ordering};

use super::{Row, SAMPLE_COLUMNS};

/// Rows of a log as they sit in its memory: see the module docs.
#[derive(Debug, Clone)]
pub struct SharedRows {
    cells: Arc<[AtomicU64]>,
    /// Index of the first value shown (a multiple of `SAMPLE_COLUMNS`).
    first: usize,
    rows: usize,
}

impl SharedRows {
    /// The number of rows.
    pub fn rows(&self) -> usize {
        self.rows
    }

    /// The first value of the first row: `rows() * SAMPLE_COLUMNS` native-endian f64 values
    /// follow, row-major, and stay valid and unchanged as long as this `SharedRows` exists.
    pub fn as_ptr(&self) -> *const f64 {
        self.cells[self.first..].as_ptr().cast()
    }

    /// Row `i`, if there is one.
    pub fn row(&self, i: usize) -> Option<Row> {
        (i < self.rows).then(|| read_row(&self.cells, self.first + i * SAMPLE_COLUMNS))
    }

    /// True if `self` and `other` show the same memory (the same rows of the same block).
    pub fn same_memory(&self, other: &SharedRows) -> bool {
        Arc::ptr_eq(&self.cells, &other.cells) && self.first == other.first
    }
}

/// A log's memory: room for `capacity` rows.
#[derive(Debug)]
pub(super) struct Block {
    cells: Arc<[AtomicU64]>,
}

impl Block {
    /// Room for `rows` rows, all zero.
    pub(super) fn new(rows: usize) -> Block {
        Block {
            cells: (0..rows * SAMPLE_COLUMNS)
                .map(|_| AtomicU64::new(0))
                .collect(),
        }
    }

    /// The number of rows it has room for.
    pub(super) fn capacity(&self) -> usize {
        self.cells.len() / SAMPLE_COLUMNS
    }

    /// True while a [`SharedRows`] of it exists.
    pub(super) fn is_shared(&self) -> bool {
        Arc::strong_count(&self.cells) > 1
    }

    /// Row `slot`.
    pub(super) fn read(&self, slot: usize) -> Row {
        read_row(&self.cells, slot * SAMPLE_COLUMNS)
    }

    /// Writes `row` into slot `slot`. The caller writes no slot a [`SharedRows`] shows.
    pub(super) fn write(&mut self, slot: usize, row: &Row) {
        let cells = &self.cells[slot * SAMPLE_COLUMNS..(slot + 1) * SAMPLE_COLUMNS];
        for (cell, v) in cells.iter().zip(row) {
            cell.store(v.to_bits(), Ordering::Relaxed);
        }
    }

    /// A block of room for `rows` rows holding this block's rows `from..to` at slots
    /// `at..`: the copy made before writing where a shared block is shown, or to grow.
    pub(super) fn copied(&self, rows: usize, from: usize, to: usize, at: usize) -> Block {
        let out = Block::new(rows);
        let src = &self.cells[from * SAMPLE_COLUMNS..to * SAMPLE_COLUMNS];
        let dst = &out.cells[at * SAMPLE_COLUMNS..(at + to - from) * SAMPLE_COLUMNS];
        for (d, s) in dst.iter().zip(src) {
            d.store(s.load(Ordering::Relaxed), Ordering::Relaxed);
        }
        out
    }

    /// Rows `first..first + rows` shared.
    pub(super) fn share(&self, first: usize, rows: usize) -> SharedRows {
        SharedRows {
            cells: Arc::clone(&self.cells),
            first: first * SAMPLE_COLUMNS,
            rows,
        }
    }
}

/// The row starting at value `at` of `cells`.
fn read_row(cells: &[AtomicU64], at: usize) -> Row {
    let mut row = [0.0; SAMPLE_COLUMNS];
    for (v, cell) in row.iter_mut().zip(&cells[at..at + SAMPLE_COLUMNS]) {
        *v = f64::from_bits(cell.load(Ordering::Relaxed));
    }
    row
}
