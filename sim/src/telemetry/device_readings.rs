//! A finished run's device readings with the names `devices.csv` gives them: what the
//! `programme` scenario hands its [`ScenarioResult`](crate::scenario::ScenarioResult), so that
//! `vehicle-sim`'s outputs hold the readings of the devices its world enables
//! (`samplingPeriod`).

use std::fmt;
use std::io::Write;
use std::sync::Arc;

use super::DeviceLog;

/// The readings of a run's devices ([`DeviceLog`], in bounded memory) and the names of its
/// cars and devices. Cloning shares the log.
#[derive(Clone, Default)]
pub struct DeviceReadings {
    log: Arc<DeviceLog>,
    /// Each car's name and its devices' names, by index in the simulation's order.
    cars: Vec<(String, Vec<String>)>,
}

impl DeviceReadings {
    /// The readings of `log`, whose rows index the cars and devices of `cars` (each car's name
    /// and its devices' names).
    pub fn new(log: DeviceLog, cars: Vec<(String, Vec<String>)>) -> Self {
        DeviceReadings {
            log: Arc::new(log),
            cars,
        }
    }

    /// The number of rows.
    pub fn len(&self) -> usize {
        self.log.len()
    }

    /// True when no device was sampled.
    pub fn is_empty(&self) -> bool {
        self.log.is_empty()
    }

    /// The log of the rows.
    pub fn log(&self) -> &DeviceLog {
        &self.log
    }

    /// Writes the rows as `devices.csv` ([`DeviceLog::write_csv`]).
    ///
    /// # Errors
    /// The write error, or that of reading the log's temporary file back.
    pub fn write_csv(&self, out: impl Write) -> Result<(), csv::Error> {
        self.log.write_csv(out, |car, device| {
            let c = self.cars.get(car as usize);
            (
                c.map_or("", |c| c.0.as_str()),
                c.and_then(|c| c.1.get(device as usize))
                    .map_or("", String::as_str),
            )
        })
    }
}

impl fmt::Debug for DeviceReadings {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("DeviceReadings")
            .field("rows", &self.len())
            .field("cars", &self.cars)
            .finish()
    }
}

/// Equal when both are empty, or when they share one log (a clone) and name the same cars and
/// devices: comparing rows would read a spilled log back from its file.
impl PartialEq for DeviceReadings {
    fn eq(&self, other: &Self) -> bool {
        (self.is_empty() && other.is_empty())
            || (Arc::ptr_eq(&self.log, &other.log) && self.cars == other.cars)
    }
}
