//! Per-step telemetry of a run (one [`Telemetry`] per vehicle and scenario), its CSV form, and
//! the [`TelemetryLog`] that keeps a run of any length in bounded memory.

mod csv_table;
mod device_log;
mod device_readings;
mod log;
mod rows;

pub use csv_table::{CsvWriter, ReadError, read_csv, to_csv, write_csv};
pub use device_log::{DEVICE_MEMORY_ROWS, DEVICES_CSV_HEADER, DeviceLog, DeviceRow};
pub use device_readings::DeviceReadings;
pub use log::{LogMark, MEMORY_ROWS, Retention, Row, TelemetryLog};
pub use rows::SharedRows;

use vehicle_model::{EngineType, KMH_PER_MS, PerWheel, Wheel};

use crate::diff_wheels::RobotId;
use crate::error::SimError;
use crate::simulation::Simulation;
use crate::vehicle::{TyreTelemetry, VehicleId};
use crate::world::World;

/// One sample: the state at the start of a run (time 0) or after a world step. Car-only
/// quantities are `None` for a DifferentialWheels robot, and `rpm`/`gear` are `None` in speed
/// (cruise-control) mode, where Webots has no engine model.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Sample {
    /// Time since the scenario started (s).
    pub time: f64,
    /// Position of the vehicle origin (rear-axle centre, or the robot's axle midpoint), m.
    pub x: f64,
    /// Position of the vehicle origin, m.
    pub y: f64,
    /// Heading (rad, counter-clockwise about +z).
    pub yaw: f64,
    /// Speed of the vehicle origin along its heading, measured on the body (km/h).
    pub speed_kmh: f64,
    /// The driver library's speed estimate from the wheel encoders (km/h; Webots:
    /// `wbu_driver_get_current_speed`).
    pub driver_speed_kmh: Option<f64>,
    /// Engine speed (rpm; Webots: `wbu_driver_get_rpm`).
    pub rpm: Option<f64>,
    /// Engaged gear (−1 reverse, 0 neutral, 1… forward; Webots: `wbu_driver_get_gear`).
    pub gear: Option<i32>,
    /// Commanded central steering angle (rad, positive = right).
    pub steering_command: Option<f64>,
    /// Measured steering angle, the mean of both front wheels (rad, positive = right).
    pub steering: Option<f64>,
    /// Throttle (dimensionless, [0, 1]).
    pub throttle: Option<f64>,
    /// Brake intensity (dimensionless, [0, 1]).
    pub brake: Option<f64>,
    /// Lateral acceleration of the body (m/s², positive to the left).
    pub lateral_accel: Option<f64>,
    /// Longitudinal acceleration of the body (m/s², positive forward).
    pub longitudinal_accel: Option<f64>,
    /// What each tyre did over the step (slips, forces in N, friction use), in wheel order
    /// FR, FL, RR, RL.
    pub tyres: Option<PerWheel<TyreTelemetry>>,
    /// Power the driven wheels received over the step (W; negative for a combustion
    /// engine's braking curve), from the car's energy accounting (`None` without).
    pub wheel_power: Option<f64>,
    /// Power the battery gave at its terminals over the step (W, negative while charging),
    /// for a car with a battery and energy accounting.
    pub battery_power: Option<f64>,
    /// The battery's state of charge after the step (%, 0 to 100), likewise.
    pub soc_percent: Option<f64>,
    /// Fuel the combustion engine burnt per second over the step (g/s), for a car with a
    /// combustion engine and energy accounting.
    pub fuel_rate: Option<f64>,
    /// The magnitude of the air's drag on the body over the step (N), for a car with air
    /// (`Vehicle::drag_force`: from the velocity at the step's start).
    pub drag_force: Option<f64>,
}

impl Sample {
    /// The state of car `id` of `sim` now, as its driver and the chassis measure it.
    ///
    /// # Errors
    /// [`SimError::UnknownVehicle`] for a car without a driver in `sim`.
    pub fn of_car(sim: &Simulation, id: VehicleId) -> Result<Sample, SimError> {
        let t = sim.telemetry(id)?;
        let d = sim.driver(id)?;
        let s = &t.state;
        let engine = d.params().engine.engine_type;
        let energy = sim.energy(id)?;
        let battery = energy.filter(|_| engine != EngineType::Combustion);
        let fuel = energy.filter(|_| engine != EngineType::Electric);
        Ok(Sample {
            time: t.time,
            x: s.position.x,
            y: s.position.y,
            yaw: s.roll_pitch_yaw.yaw,
            speed_kmh: t.speed * KMH_PER_MS,
            driver_speed_kmh: Some(t.estimated_speed_kmh).filter(|v| v.is_finite()),
            rpm: t.rpm,
            gear: t.gear.map(|g| g.number()),
            steering_command: Some(d.commanded_steering_angle()),
            steering: Some(d.steering_angle()),
            throttle: Some(t.throttle),
            brake: Some(t.brake),
            lateral_accel: Some(s.lateral_acceleration),
            longitudinal_accel: Some(s.longitudinal_acceleration),
            tyres: Some(s.tyres),
            wheel_power: energy.map(|e| e.wheel_power),
            battery_power: battery.map(|e| e.battery_power),
            soc_percent: battery.map(|e| 100.0 * e.soc),
            fuel_rate: fuel.map(|e| G_PER_KG * e.last.fuel_rate),
            drag_force: sim.world().vehicle(id)?.drag_force(),
        })
    }

    /// The pose and speed of DifferentialWheels robot `id` of `world` now (its speed is the
    /// mean of its wheels' rim speeds).
    ///
    /// # Errors
    /// [`SimError::UnknownRobot`] for a robot not in `world`.
    pub fn of_robot(world: &World, id: RobotId) -> Result<Sample, SimError> {
        let robot = world.robot(id)?;
        let pose = robot.pose();
        let [l, r] = robot.wheel_speeds();
        Ok(Sample {
            time: world.time(),
            x: pose.position.x,
            y: pose.position.y,
            yaw: pose.heading,
            speed_kmh: 0.5 * (l + r) * robot.params().wheel_radius * KMH_PER_MS,
            ..Sample::default()
        })
    }

    /// The sample whose [`Sample::values`] are `row` (NaN for `None`): the inverse of
    /// [`Sample::values`] for finite values. The tyres are present if any tyre value is.
    pub fn from_row(row: &Row) -> Sample {
        let opt = |v: f64| (!v.is_nan()).then_some(v);
        let tyre_values = &row[14..ENERGY_COLUMN];
        let tyres = tyre_values.iter().any(|v| !v.is_nan()).then(|| {
            PerWheel::from_fn(|w| {
                let i = Wheel::ALL.iter().position(|&v| v == w).unwrap_or(0) * 6;
                let c = &tyre_values[i..i + 6];
                TyreTelemetry {
                    slip_ratio: c[0],
                    slip_angle: c[1],
                    fx: c[2],
                    fy: c[3],
                    fz: c[4],
                    friction_use: c[5],
                }
            })
        });
        Sample {
            time: row[0],
            x: row[1],
            y: row[2],
            yaw: row[3],
            speed_kmh: row[4],
            driver_speed_kmh: opt(row[5]),
            rpm: opt(row[6]),
            // A gear is a small whole number (−1 to the gear count).
            gear: opt(row[7]).map(|g| g as i32),
            steering_command: opt(row[8]),
            steering: opt(row[9]),
            throttle: opt(row[10]),
            brake: opt(row[11]),
            lateral_accel: opt(row[12]),
            longitudinal_accel: opt(row[13]),
            tyres,
            wheel_power: opt(row[ENERGY_COLUMN]),
            battery_power: opt(row[ENERGY_COLUMN + 1]),
            soc_percent: opt(row[ENERGY_COLUMN + 2]),
            fuel_rate: opt(row[ENERGY_COLUMN + 3]),
            drag_force: opt(row[ENERGY_COLUMN + 4]),
        }
    }

    /// The speed along the heading (m/s).
    pub fn speed(&self) -> f64 {
        self.speed_kmh / KMH_PER_MS
    }

    /// The values of the columns of [`CSV_HEADER`] after `scenario` and `car`, in its order and
    /// units (`None` where the quantity does not exist).
    pub fn values(&self) -> [Option<f64>; SAMPLE_COLUMNS] {
        let mut out = [None; SAMPLE_COLUMNS];
        let vehicle = [
            Some(self.time),
            Some(self.x),
            Some(self.y),
            Some(self.yaw),
            Some(self.speed_kmh),
            self.driver_speed_kmh,
            self.rpm,
            self.gear.map(f64::from),
            self.steering_command,
            self.steering,
            self.throttle,
            self.brake,
            self.lateral_accel,
            self.longitudinal_accel,
        ];
        let tyres = Wheel::ALL.into_iter().flat_map(|w| {
            let tyre = self.tyres.map(|t| t[w]);
            TYRE_CELLS.map(|v| tyre.map(v))
        });
        let energy = [
            self.wheel_power,
            self.battery_power,
            self.soc_percent,
            self.fuel_rate,
            self.drag_force,
        ];
        for (cell, v) in out
            .iter_mut()
            .zip(vehicle.into_iter().chain(tyres).chain(energy))
        {
            *cell = v;
        }
        out
    }
}

/// The number of columns of a [`Sample`] in [`CSV_HEADER`] (all but `scenario` and `car`).
pub const SAMPLE_COLUMNS: usize = ENERGY_COLUMN + 5;

/// The index of the first of the five energy columns among a [`Sample`]'s: after the
/// vehicle's 14 and the tyres' 6 × 4.
const ENERGY_COLUMN: usize = 14 + 6 * 4;

/// g per kg.
const G_PER_KG: f64 = 1000.0;

/// The six columns of one tyre, prefixed with the wheel's short name.
macro_rules! tyre_columns {
    ($w:literal) => {
        concat!(
            ",",
            $w,
            "_slip_ratio,",
            $w,
            "_slip_angle_rad,",
            $w,
            "_fx_n,",
            $w,
            "_fy_n,",
            $w,
            "_fz_n,",
            $w,
            "_friction_use"
        )
    };
}

/// The CSV header written by [`write_csv`]: the vehicle's columns, then six per tyre in
/// wheel order `fr`, `fl`, `rr`, `rl` ([`TyreTelemetry`]: slip ratio, slip angle in rad,
/// the road's forces along the wheel's heading and axis and the load in N, friction use 0–1),
/// then the energy columns ([`Sample::wheel_power`] … [`Sample::drag_force`]: W, W, %, g/s,
/// N; empty for a car without energy accounting, or without air for the drag).
pub const CSV_HEADER: &str = concat!(
    "scenario,car,time_s,x_m,y_m,yaw_rad,speed_kmh,driver_speed_kmh,rpm,gear,",
    "steering_command_rad,steering_rad,throttle,brake,lateral_accel_mps2,longitudinal_accel_mps2",
    tyre_columns!("fr"),
    tyre_columns!("fl"),
    tyre_columns!("rr"),
    tyre_columns!("rl"),
    ",wheel_power_w,battery_power_w,soc_percent,fuel_rate_gps,drag_force_n",
);

/// What kind of vehicle a [`Telemetry`] follows.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum VehicleKind {
    /// A car.
    #[default]
    Car,
    /// A DifferentialWheels robot.
    Robot,
}

/// One vehicle's samples in one scenario, in time order.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Telemetry {
    /// Name of the scenario (or run) that produced them.
    pub scenario: String,
    /// Name of the vehicle (the `car` column).
    pub vehicle: String,
    /// A car or a robot.
    pub kind: VehicleKind,
    /// The samples.
    pub samples: Vec<Sample>,
}

/// The values of a tyre's six columns, in the order of [`CSV_HEADER`].
const TYRE_CELLS: [fn(TyreTelemetry) -> f64; 6] = [
    |t| t.slip_ratio,
    |t| t.slip_angle,
    |t| t.fx,
    |t| t.fy,
    |t| t.fz,
    |t| t.friction_use,
];

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn csv_rows_and_blank_cells() {
        let t = Telemetry {
            scenario: "brake".into(),
            vehicle: "BmwX5".into(),
            kind: VehicleKind::Car,
            samples: vec![Sample {
                time: 0.01,
                x: 1.0 / 3.0,
                // Rounds to -0 at six decimals: written 0.
                y: -4e-8,
                speed_kmh: 100.0,
                gear: Some(2),
                rpm: Some(f64::NAN),
                ..Sample::default()
            }],
        };
        let csv = to_csv([&t]);
        let mut lines = csv.lines();
        assert_eq!(lines.next(), Some(CSV_HEADER));
        let row = lines.next().unwrap();
        // 16 vehicle columns, then 24 empty tyre cells and 5 empty energy cells.
        assert_eq!(
            row,
            format!(
                "brake,BmwX5,0.01,0.333333,0,0,100,,,2,,,,,,{}",
                ",".repeat(24 + 5)
            )
        );
        assert!(!row.contains("-0"), "{row}");
        assert_eq!(row.split(',').count(), CSV_HEADER.split(',').count());
        assert_eq!(lines.next(), None);
    }

    #[test]
    fn a_csv_reads_back_as_its_telemetry() {
        let car = Telemetry {
            scenario: "run".into(),
            vehicle: "a".into(),
            kind: VehicleKind::Car,
            samples: (0..3)
                .map(|i| Sample {
                    time: 0.25 * f64::from(i),
                    x: 1.5,
                    steering_command: Some(0.125),
                    gear: Some(i),
                    ..Sample::default()
                })
                .collect(),
        };
        let robot = Telemetry {
            scenario: "run".into(),
            vehicle: "r".into(),
            kind: VehicleKind::Robot,
            samples: vec![Sample::default()],
        };
        let back = read_csv(to_csv([&car, &robot]).as_bytes()).unwrap();
        // Values with at most six decimals come back exactly.
        assert_eq!(back, vec![car, robot]);
        assert!(matches!(
            read_csv("a,b\n".as_bytes()),
            Err(ReadError::Header)
        ));
        let bad = format!("{CSV_HEADER}\nrun,a,x{}", ",".repeat(SAMPLE_COLUMNS - 1));
        let e = read_csv(bad.as_bytes()).unwrap_err();
        assert_eq!(
            e.to_string(),
            "line 2, column 'time_s': 'x' is not a number"
        );
    }

    #[test]
    fn a_csv_written_before_the_energy_columns_reads_with_them_empty() {
        let car = Telemetry {
            scenario: "run".into(),
            vehicle: "a".into(),
            kind: VehicleKind::Car,
            samples: vec![Sample {
                time: 0.5,
                speed_kmh: 36.0,
                steering_command: Some(0.1),
                ..Sample::default()
            }],
        };
        // The previous version's file: every line without its last five cells.
        let old: String = to_csv([&car])
            .lines()
            .map(|l| {
                let cells: Vec<&str> = l.split(',').collect();
                cells[..cells.len() - 5].join(",") + "\n"
            })
            .collect();
        assert!(old.starts_with("scenario,car,time_s,") && !old.contains("wheel_power_w"));
        assert_eq!(read_csv(old.as_bytes()).unwrap(), vec![car]);
    }

    #[test]
    fn energy_columns_last_with_their_units() {
        let columns: Vec<&str> = CSV_HEADER.split(',').collect();
        assert_eq!(
            columns[40..],
            [
                "wheel_power_w",
                "battery_power_w",
                "soc_percent",
                "fuel_rate_gps",
                "drag_force_n"
            ]
        );
        let s = Sample {
            wheel_power: Some(20_000.0),
            battery_power: Some(-1500.5),
            soc_percent: Some(87.25),
            fuel_rate: Some(1.125),
            drag_force: Some(412.0),
            ..Sample::default()
        };
        let t = Telemetry {
            scenario: "hwfet".into(),
            vehicle: "car".into(),
            kind: VehicleKind::Car,
            samples: vec![s],
        };
        let csv = to_csv([&t]);
        let row: Vec<&str> = csv.lines().nth(1).unwrap().split(',').collect();
        assert_eq!(row[40..], ["20000", "-1500.5", "87.25", "1.125", "412"]);
        assert_eq!(read_csv(csv.as_bytes()).unwrap()[0].samples, [s]);
    }

    #[test]
    fn tyre_columns_in_wheel_order() {
        let columns: Vec<&str> = CSV_HEADER.split(',').collect();
        assert_eq!(columns.len(), 16 + 24 + 5);
        assert_eq!(
            columns[16..22],
            [
                "fr_slip_ratio",
                "fr_slip_angle_rad",
                "fr_fx_n",
                "fr_fy_n",
                "fr_fz_n",
                "fr_friction_use"
            ]
        );
        assert_eq!(columns[22], "fl_slip_ratio");
        assert_eq!(columns[28], "rr_slip_ratio");
        assert_eq!(columns[39], "rl_friction_use");

        // Wheel i gets slip ratio 0.01·i, slip angle −0.02 rad, forces 100·i, −50, 4000 + i N
        // and friction use 0.25.
        let tyres = PerWheel::from_fn(|w| {
            let i = Wheel::ALL.iter().position(|&v| v == w).unwrap() as f64;
            TyreTelemetry {
                slip_ratio: 0.01 * i,
                slip_angle: -0.02,
                fx: 100.0 * i,
                fy: -50.0,
                fz: 4000.0 + i,
                friction_use: 0.25,
            }
        });
        let t = Telemetry {
            scenario: "lane-change".into(),
            vehicle: "car".into(),
            kind: VehicleKind::Car,
            samples: vec![Sample {
                tyres: Some(tyres),
                ..Sample::default()
            }],
        };
        let csv = to_csv([&t]);
        let row: Vec<&str> = csv.lines().nth(1).unwrap().split(',').collect();
        assert_eq!(row.len(), columns.len());
        assert_eq!(row[16..22], ["0", "-0.02", "0", "-50", "4000", "0.25"]);
        assert_eq!(row[22..28], ["0.01", "-0.02", "100", "-50", "4001", "0.25"]);
        assert_eq!(row[34..40], ["0.03", "-0.02", "300", "-50", "4003", "0.25"]);
    }
}
