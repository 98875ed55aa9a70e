//! The readings of a run's devices, in bounded memory: one row per recorded value (time, car,
//! device, quantity, value), as `devices.csv` holds them.
//!
//! A row takes 32 bytes; past [`DEVICE_MEMORY_ROWS`] rows (2 MB) they move to an unnamed
//! temporary file as the [`TelemetryLog`](super::TelemetryLog)'s do, so a run's memory stays
//! bounded whatever its length and number of devices. Reading the log back gives the values
//! bit for bit.

use std::fs::File;
use std::io::{self, BufReader, BufWriter, Read, Seek, SeekFrom, Write};

use super::log::temporary_file;
use crate::devices::RecordedQuantity;

/// Rows kept in memory before they move to the temporary file: 65,536 rows of 32 bytes, 2 MB.
pub const DEVICE_MEMORY_ROWS: usize = 65_536;

/// Bytes of a row in the temporary file.
const ROW_BYTES: usize = 32;

/// One recorded value.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DeviceRow {
    /// Simulated time of the sample (s).
    pub time: f64,
    /// The car: its index in the order the simulation's cars were added.
    pub car: u32,
    /// The device: its index in the car's list.
    pub device: u32,
    /// What the value measures.
    pub quantity: RecordedQuantity,
    /// The value, in the unit of its quantity.
    pub value: f64,
}

/// The rows in time order, in memory and, past [`DEVICE_MEMORY_ROWS`], in a temporary file.
#[derive(Debug, Default)]
pub struct DeviceLog {
    recent: Vec<DeviceRow>,
    spilled: Option<File>,
    spilled_rows: usize,
    /// The quantity names seen: a row in the file holds its name's index here.
    names: Vec<&'static str>,
    /// Why spilling stopped (the rows then stay in memory).
    spill_error: Option<String>,
}

impl DeviceLog {
    /// An empty log.
    pub fn new() -> Self {
        DeviceLog::default()
    }

    /// The number of rows.
    pub fn len(&self) -> usize {
        self.spilled_rows + self.recent.len()
    }

    /// True before the first row.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Why older rows could not be moved to a temporary file (they are kept in memory).
    pub fn spill_error(&self) -> Option<&str> {
        self.spill_error.as_deref()
    }

    /// Appends `row`.
    pub fn push(&mut self, row: DeviceRow) {
        if !self.names.contains(&row.quantity.name) {
            self.names.push(row.quantity.name);
        }
        self.recent.push(row);
        if self.recent.len() >= DEVICE_MEMORY_ROWS
            && self.spill_error.is_none()
            && let Err(e) = self.spill()
        {
            self.spill_error = Some(e.to_string());
        }
    }

    fn spill(&mut self) -> io::Result<()> {
        let file = match &mut self.spilled {
            Some(f) => f,
            None => self.spilled.insert(temporary_file()?),
        };
        file.seek(SeekFrom::End(0))?;
        let mut out = BufWriter::new(&*file);
        for row in &self.recent {
            out.write_all(&encode(row, &self.names))?;
        }
        out.flush()?;
        self.spilled_rows += self.recent.len();
        self.recent.clear();
        Ok(())
    }

    /// Keeps the first `len` rows and drops the rest (nothing if the log holds no more), as
    /// [`super::TelemetryLog`]'s `truncate`.
    ///
    /// # Errors
    /// The error of shortening the temporary file.
    pub(crate) fn truncate(&mut self, len: usize) -> io::Result<()> {
        if len >= self.spilled_rows {
            self.recent.truncate(len - self.spilled_rows);
            return Ok(());
        }
        if let Some(file) = &self.spilled {
            file.set_len((len * ROW_BYTES) as u64)?;
        }
        self.spilled_rows = len;
        self.recent.clear();
        Ok(())
    }

    /// Calls `f` on every row in order.
    ///
    /// # Errors
    /// The error of reading the temporary file back.
    pub fn for_each(&self, mut f: impl FnMut(&DeviceRow)) -> io::Result<()> {
        if let Some(mut file) = self.spilled.as_ref() {
            file.seek(SeekFrom::Start(0))?;
            let mut reader = BufReader::new(file).take((self.spilled_rows * ROW_BYTES) as u64);
            let mut bytes = [0u8; ROW_BYTES];
            for _ in 0..self.spilled_rows {
                reader.read_exact(&mut bytes)?;
                f(&decode(&bytes, &self.names)?);
            }
        }
        self.recent.iter().for_each(f);
        Ok(())
    }

    /// Writes the rows as CSV ([`DEVICES_CSV_HEADER`]) to `out`, each car and device named by
    /// `names` (car index, device index → car name, device name); values in Rust's shortest
    /// form that reads back to the same f64 (`inf`, `NaN` as such).
    ///
    /// # Errors
    /// The write error, or that of reading the temporary file back.
    pub fn write_csv<'a>(
        &self,
        out: impl Write,
        names: impl Fn(u32, u32) -> (&'a str, &'a str),
    ) -> Result<(), csv::Error> {
        let mut w = csv::WriterBuilder::new()
            .has_headers(false)
            .from_writer(out);
        w.write_record(DEVICES_CSV_HEADER.split(','))?;
        let mut result = Ok(());
        self.for_each(|r| {
            if result.is_ok() {
                let (car, device) = names(r.car, r.device);
                result = w.write_record([
                    r.time.to_string().as_str(),
                    car,
                    device,
                    r.quantity.to_string().as_str(),
                    r.value.to_string().as_str(),
                ]);
            }
        })?;
        result?;
        w.flush()?;
        Ok(())
    }
}

/// The header of `devices.csv`.
pub const DEVICES_CSV_HEADER: &str = "time,car,device,quantity,value";

/// `row` as the file holds it: time, car, device, name index, target (`u16::MAX` for none),
/// 2 bytes of padding, value; native-endian.
fn encode(row: &DeviceRow, names: &[&'static str]) -> [u8; ROW_BYTES] {
    let name = names.iter().position(|n| *n == row.quantity.name);
    let mut b = [0u8; ROW_BYTES];
    b[0..8].copy_from_slice(&row.time.to_ne_bytes());
    b[8..12].copy_from_slice(&row.car.to_ne_bytes());
    b[12..16].copy_from_slice(&row.device.to_ne_bytes());
    // `push` interned every name before the row was stored.
    b[16..20].copy_from_slice(&(name.unwrap_or(0) as u32).to_ne_bytes());
    b[20..22].copy_from_slice(&row.quantity.target.unwrap_or(u16::MAX).to_ne_bytes());
    b[24..32].copy_from_slice(&row.value.to_ne_bytes());
    b
}

/// The row of `b` ([`encode`]).
fn decode(b: &[u8; ROW_BYTES], names: &[&'static str]) -> io::Result<DeviceRow> {
    let u32_at = |i: usize| u32::from_ne_bytes([b[i], b[i + 1], b[i + 2], b[i + 3]]);
    let f64_at = |i: usize| {
        let mut x = [0u8; 8];
        x.copy_from_slice(&b[i..i + 8]);
        f64::from_ne_bytes(x)
    };
    let name = names
        .get(u32_at(16) as usize)
        .ok_or_else(|| io::Error::other("device log: a row names an unknown quantity"))?;
    let target = u16::from_ne_bytes([b[20], b[21]]);
    Ok(DeviceRow {
        time: f64_at(0),
        car: u32_at(8),
        device: u32_at(12),
        quantity: RecordedQuantity {
            name,
            target: (target != u16::MAX).then_some(target),
        },
        value: f64_at(24),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn row(i: usize) -> DeviceRow {
        let names = ["x", "speed", "distance"];
        DeviceRow {
            time: 0.01 * i as f64,
            car: (i % 3) as u32,
            device: (i % 5) as u32,
            quantity: RecordedQuantity {
                name: names[i % 3],
                target: i.is_multiple_of(2).then_some((i % 7) as u16),
            },
            value: (i as f64).sqrt() - 1e-300,
        }
    }

    #[test]
    fn a_long_log_spills_and_reads_back_bit_for_bit() {
        let n = 2 * DEVICE_MEMORY_ROWS + 5;
        let mut log = DeviceLog::new();
        for i in 0..n {
            log.push(row(i));
        }
        assert_eq!(log.spill_error(), None);
        assert_eq!(log.recent.len(), 5);
        assert_eq!(log.len(), n);
        let mut back = Vec::new();
        log.for_each(|r| back.push(*r)).unwrap();
        assert_eq!(back.len(), n);
        for (i, r) in back.iter().enumerate() {
            assert_eq!(*r, row(i), "row {i}");
            assert_eq!(r.value.to_bits(), row(i).value.to_bits());
        }
    }
}
