//! The car's sensor readings as outputs: one Real per scalar quantity of each device the
//! world gives the car (`[[vehicle.device]]`), named `<device>.<quantity>`, from value
//! reference 2000 on (100 per device, in the world's order). The packager and the instance
//! derive the list from the same world with the same code, so the description and the served
//! values agree.
//!
//! The quantities are those `devices.csv` records ([`sim::devices::Device::for_each_recorded`]), with
//! a fixed shape, as FMI variables cannot come and go: a radar gives its target count and the
//! first [`RADAR_TARGETS`] targets, a lidar the number of returns and the closest. A quantity
//! the last sample does not have (a target beyond the count, a lidar with no return, the lane
//! off the roads) reads NaN, as in `devices.csv`. Cameras and displays have no scalar
//! reading and give no output (and are not enabled: they would render every step for
//! nothing).
//!
//! Sampling: a device the world enables (`samplingPeriod`) keeps its period; every other
//! device with outputs is enabled at the world's basicTimeStep, as a run without a controller
//! has no one else to enable it. Between samples an output holds the last sample, as the
//! device's C function does.

use std::collections::HashSet;

use sim::devices::{Device, DeviceKind, RecordedQuantity};
use sim::{Simulation, VehicleId};

/// The value reference of the first device's first quantity.
pub const FIRST_REFERENCE: u32 = 2000;
/// Value references per device.
pub const PER_DEVICE: u32 = 100;
/// Radar targets given as outputs (the first of the sample's list).
pub const RADAR_TARGETS: u16 = 4;

/// One device output.
#[derive(Debug, Clone, PartialEq)]
pub struct DeviceOutput {
    /// `<device>.<quantity>`.
    pub name: String,
    /// Its value reference.
    pub reference: u32,
    /// Its unit, one of [`crate::variables::UNITS`], `None` for a number.
    pub unit: Option<&'static str>,
    /// What it is.
    pub description: String,
    /// The device's index on the car.
    device: usize,
    /// The quantity of the device's sample.
    quantity: RecordedQuantity,
}

/// A quantity of a sample and its unit.
type Quantity = (&'static str, Option<&'static str>);

/// The scalar quantities of a device of `kind`, in output order.
fn quantities(kind: DeviceKind) -> &'static [Quantity] {
    const M: Option<&str> = Some("m");
    const MS: Option<&str> = Some("m/s");
    match kind {
        DeviceKind::Gps => &[
            ("x", M),
            ("y", M),
            ("z", M),
            ("speed", MS),
            ("speed_vector_x", MS),
            ("speed_vector_y", MS),
            ("speed_vector_z", MS),
        ],
        DeviceKind::InertialUnit => &[("qx", None), ("qy", None), ("qz", None), ("qw", None)],
        DeviceKind::Gyro => &[
            ("x", Some("rad/s")),
            ("y", Some("rad/s")),
            ("z", Some("rad/s")),
        ],
        DeviceKind::Accelerometer => &[
            ("x", Some("m/s2")),
            ("y", Some("m/s2")),
            ("z", Some("m/s2")),
        ],
        DeviceKind::Compass => &[("x", None), ("y", None), ("z", None)],
        DeviceKind::DistanceSensor => &[("value", None)],
        DeviceKind::Radar => &[("targets", None)],
        DeviceKind::Lidar => &[("returns", None), ("closest", M)],
        DeviceKind::RoadSensor => &[
            ("road", None),
            ("lane", None),
            ("s", M),
            ("lateral_offset", M),
            ("heading_error", Some("rad")),
            ("curvature", None),
            ("curvature_ahead", None),
            ("left_line", M),
            ("right_line", M),
            ("left_edge", M),
            ("right_edge", M),
            ("lane_width", M),
        ],
        DeviceKind::Camera | DeviceKind::Display => &[],
    }
}

/// Each radar target's quantities.
const TARGET: [Quantity; 4] = [
    ("distance", Some("m")),
    ("received_power", None),
    ("speed", Some("m/s")),
    ("azimuth", Some("rad")),
];

/// What a quantity is, for the description.
fn describe(kind: DeviceKind, device: &str, quantity: &RecordedQuantity) -> String {
    let what = match (kind, quantity.name) {
        (DeviceKind::Radar, "received_power") => "received power (dBm)".to_string(),
        (DeviceKind::RoadSensor, "curvature" | "curvature_ahead") => {
            format!("{} (1/m)", quantity.name)
        }
        (DeviceKind::InertialUnit, q) => format!("{q} of the orientation quaternion"),
        (_, q) => q.replace('_', " "),
    };
    match quantity.target {
        Some(k) => format!("{kind:?} {device}: target {k}'s {what} (NaN without it)"),
        None => format!("{kind:?} {device}: {what}"),
    }
}

/// The outputs of `devices`, the devices of the FMU's car.
pub fn outputs(devices: &[Device]) -> Vec<DeviceOutput> {
    let mut out = Vec::new();
    let mut names = HashSet::new();
    for (index, device) in devices.iter().enumerate() {
        let kind = device.kind();
        // Webots does not require distinct device names; the FMU's variables must differ.
        let mut stem = device.name().to_string();
        if !names.insert(stem.clone()) {
            stem = format!("{stem}_{index}");
            names.insert(stem.clone());
        }
        let mut all: Vec<(RecordedQuantity, Option<&'static str>)> = quantities(kind)
            .iter()
            .map(|&(name, unit)| (RecordedQuantity { name, target: None }, unit))
            .collect();
        if kind == DeviceKind::Radar {
            for k in 0..RADAR_TARGETS {
                all.extend(TARGET.iter().map(|&(name, unit)| {
                    (
                        RecordedQuantity {
                            name,
                            target: Some(k),
                        },
                        unit,
                    )
                }));
            }
        }
        let base = FIRST_REFERENCE + PER_DEVICE * index as u32;
        for (q, (quantity, unit)) in (0..).zip(all) {
            out.push(DeviceOutput {
                name: format!("{stem}.{quantity}"),
                reference: base + q,
                unit,
                description: describe(kind, device.name(), &quantity),
                device: index,
                quantity,
            });
        }
    }
    out
}

/// The value of `output` in the last samples of `devices`; NaN where the sample lacks it.
pub fn value(devices: &[Device], output: &DeviceOutput) -> f64 {
    let mut found = f64::NAN;
    if let Some(device) = devices.get(output.device) {
        device.for_each_recorded(|q, v| {
            if q == output.quantity {
                found = v;
            }
        });
    }
    found
}

/// Enables every device of car `id` that has outputs and that the world left disabled, at
/// `period_ms` (the basicTimeStep).
///
/// # Errors
/// What the engine refuses, as a sentence.
pub fn enable(simulation: &mut Simulation, id: VehicleId, period_ms: u32) -> Result<(), String> {
    let idle: Vec<usize> = simulation
        .devices(id)
        .map_err(|e| e.to_string())?
        .iter()
        .enumerate()
        .filter(|(_, d)| d.period_ms() == 0 && !quantities(d.kind()).is_empty())
        .map(|(i, _)| i)
        .collect();
    for index in idle {
        simulation
            .enable_device(id, index, period_ms)
            .map_err(|e| e.to_string())?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_kind_has_a_fixed_list_and_references_stay_within_a_device() {
        for kind in DeviceKind::ALL {
            let n = quantities(kind).len()
                + if kind == DeviceKind::Radar {
                    TARGET.len() * usize::from(RADAR_TARGETS)
                } else {
                    0
                };
            assert!(n < PER_DEVICE as usize, "{kind:?}");
        }
    }
}
