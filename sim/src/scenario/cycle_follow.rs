//! A car handed to the built-in [`CycleDriver`] along a speed trace: the one implementation
//! behind the `ftp75`/`hwfet` scenarios and the programme's `cycle` command
//! ([`CycleCommand`]), so that both drive, measure and report a cycle alike.
//!
//! From its start the follower sets the car's throttle and brake every step (torque control,
//! from first gear; a combustion car of several gears shifts by the consumption tests' rule,
//! `cycle_gears`, any other car by the automatic gearbox), counts the time outside the tolerance band,
//! and at the trace's end keeps the car's energy report for the metrics. After the end it
//! sets nothing: the last pedals stay, as any programme command stays until a later one.

use vehicle_model::{AutoShiftParams, EngineType};

use crate::simulation::{EnergyReport, Simulation};
use crate::vehicle::VehicleId;
use crate::world_file::{CarDescription, default_energy_params};

use super::car::KMH;
use super::car_programmes::brake_deceleration;
use super::cycle_driver::{BandMeter, CycleDriver, PedalAuthority};
use super::cycle_gears::GearChoice;
use super::cycle_trace::{Band, Cycle, Trace};
use super::{Metric, ScenarioError};

/// Density of petrol (kg/l) the cycles' l/100 km use: the energy model's own
/// ([`vehicle_model::energy::PETROL_DENSITY`], 0.745, the middle of EN 228's 0.720–0.775 kg/l
/// at 15 °C), so that the fuel burnt and the litres reported share one figure.
pub use vehicle_model::energy::PETROL_DENSITY as FUEL_DENSITY;
/// J per Wh.
const J_PER_WH: f64 = 3600.0;
/// Time within which the trace counts as ended (s): far below a step, so that rounding of
/// the summed step lengths does not add a step.
const END_TOLERANCE: f64 = 1e-9;

/// Where a programme's trace comes from.
#[derive(Debug, Clone, PartialEq)]
pub enum CycleSource {
    /// A shipped cycle (`cycle = "hwfet"`).
    Shipped(Cycle),
    /// A user's 1 Hz table (`cycle_file`), by the path the world file gave.
    File(String),
}

/// A `cycle` step of a car's `[[vehicle.programme]]`: from `at` the built-in
/// [`CycleDriver`] follows `trace` with the car's throttle and brake.
#[derive(Debug, Clone, PartialEq)]
pub struct CycleCommand {
    /// When the trace's time 0 is (s, ≥ 0).
    pub at: f64,
    /// Where the trace comes from.
    pub source: CycleSource,
    /// The speed trace (m/s at each second).
    pub trace: Trace,
}

impl CycleCommand {
    /// When the trace ends (s): its start plus its duration.
    pub fn end(&self) -> f64 {
        self.at + self.trace.duration()
    }

    /// What the trace is, for messages: the cycle's name or the file's path.
    pub fn label(&self) -> String {
        match &self.source {
            CycleSource::Shipped(c) => c.name().to_string(),
            CycleSource::File(path) => path.clone(),
        }
    }

    /// The band the trace is measured against: a shipped cycle's own, the EPA's for a file.
    pub fn band(&self) -> Band {
        match &self.source {
            CycleSource::Shipped(c) => c.band(),
            CycleSource::File(_) => Band::EPA,
        }
    }
}

/// Turns on the energy accounting of the car named `car` of `cars` (the defaults of its
/// engine type, battery full) if the world has not, as a cycle's consumption needs it; the
/// notes that say what the run's car then is.
pub(super) fn account_energy(cars: &mut [CarDescription], car: &str) -> Vec<String> {
    let mut notes = Vec::new();
    let Some(c) = cars.iter_mut().find(|c| c.name == car) else {
        return notes;
    };
    if c.energy.is_none() {
        c.energy = Some(default_energy_params(
            c.model,
            &c.params.engine,
            c.road_load.is_some(),
        ));
        notes.push(format!(
            "{car}: energy accounting turned on for the drive cycle (the defaults of its engine \
             type, battery full)"
        ));
    }
    if c.road_load.is_none() {
        notes.push(format!(
            "{car}: Webots' wheelsDampingConstant is its only driveline loss: the consumption \
             includes what that damping costs (losses = \"road-load\" for a real car's)"
        ));
    }
    notes
}

/// A car following a trace, and what it measured.
#[derive(Debug, Clone)]
pub(crate) struct CycleFollower {
    driver: CycleDriver,
    /// The gear rule of a combustion car of several gears; `None`: the automatic gearbox.
    gears: Option<GearChoice>,
    /// The tolerance band the tracking is measured against.
    tolerance: Band,
    /// The car's mass plus its wheels' spin inertia over their radius squared (kg): the
    /// effective mass its pedal authority is for.
    rolling_mass: f64,
    /// The driven wheels' radius (m).
    driven_radius: f64,
    band: BandMeter,
    /// The simulated time of the trace's time 0 (s).
    start: f64,
    /// The car's energy when the trace started, `None` without accounting.
    start_energy: Option<EnergyReport>,
    /// The car's energy when the trace ended; `None` before.
    end_energy: Option<Option<EnergyReport>>,
}

impl CycleFollower {
    /// Hands car `id` of `sim` to a driver of `trace` from now on: its pedal authority from
    /// the car (100 km/h over `time0To100`, the brakes' deceleration within the grip), the
    /// car in first gear, shifting by [`GearChoice`] if it is a combustion car of several
    /// gears, else by the automatic gearbox; its tracking measured against `tolerance`. A
    /// note if the car refused the gearbox.
    ///
    /// # Errors
    /// An unknown car, or a car whose pedal authority is not a finite acceleration > 0.
    pub(crate) fn engage(
        sim: &mut Simulation,
        id: VehicleId,
        trace: Trace,
        tolerance: Band,
    ) -> Result<(Self, Option<String>), ScenarioError> {
        let spec = *sim.world().vehicle(id)?.spec();
        let c = sim.world().config();
        let ground = (c.ground_friction, -c.gravity.z);
        let driver = sim.driver(id)?;
        let authority = PedalAuthority {
            full_throttle: 100.0 / KMH / driver.params().time_0_to_100,
            full_brake: brake_deceleration(&spec, driver, ground),
        };
        let cycle_driver = CycleDriver::new(trace, authority)?;
        let rolling_mass = spec.effective_mass();
        let driven_radius = driver.params().driven_radius();
        let gears = GearChoice::of(driver);
        let auto = AutoShiftParams::for_engine(driver.powertrain().engine());
        let driver = sim.driver_mut(id)?;
        // A combustion car shifts by the cycle rule (`GearChoice`), any other by the
        // automatic gearbox.
        let note = if gears.is_some() {
            driver
                .set_automatic_gearbox(None)
                .err()
                .map(|e| format!("automatic gearbox not released ({e})"))
        } else {
            driver
                .set_automatic_gearbox(Some(auto))
                .err()
                .map(|e| format!("automatic gearbox refused ({e}): first gear only"))
        };
        driver.set_gear(1);
        Ok((
            CycleFollower {
                driver: cycle_driver,
                gears,
                tolerance,
                rolling_mass,
                driven_radius,
                band: BandMeter::default(),
                start: sim.world().time(),
                start_energy: sim.energy(id)?,
                end_energy: None,
            },
            note,
        ))
    }

    /// The trace followed.
    pub(crate) fn trace(&self) -> &Trace {
        self.driver.trace()
    }

    /// True once the trace has ended.
    pub(crate) fn finished(&self) -> bool {
        self.end_energy.is_some()
    }

    /// The trace's time now (s).
    fn trace_time(&self, sim: &Simulation) -> f64 {
        sim.world().time() - self.start
    }

    /// Sets car `id`'s pedals for the coming step, until the trace has ended.
    ///
    /// # Errors
    /// An unknown car.
    pub(crate) fn drive(
        &mut self,
        sim: &mut Simulation,
        id: VehicleId,
    ) -> Result<(), ScenarioError> {
        if self.finished() {
            return Ok(());
        }
        let t = self.trace_time(sim);
        let vehicle = sim.world().vehicle(id)?;
        let speed = vehicle.state().forward_speed;
        // The engine's inertia in the gear of the last step (its commands'), as a mass at the
        // driven wheels' rim.
        let engine = vehicle
            .commands()
            .map_or(0.0, |c| c.driveline.reflected_inertia())
            / (self.driven_radius * self.driven_radius);
        let mass_factor = 1.0 + engine / self.rolling_mass;
        // A combustion car's throttle gives its engine's torque at the engine's speed through
        // the engaged gear: the mean acceleration to 100 km/h overstates it tenfold in a top
        // gear at 1500 rpm, and a driver pushing by that mean lags a trace's acceleration.
        let full_throttle = self.gears.as_ref().and_then(|_| {
            let d = sim.driver(id).ok()?;
            let (gear, rpm) = (d.gear().ok()?, d.rpm().ok()?);
            let wheel_torque = d.powertrain().output_torque(rpm, 1.0, gear, 0.0);
            Some(wheel_torque / (self.driven_radius * self.rolling_mass))
        });
        let pedals = self
            .driver
            .pedals(t, speed, sim.world().dt(), mass_factor, full_throttle);
        let d = sim.driver_mut(id)?;
        if let Some(gears) = &mut self.gears
            && let (Ok(gear), Ok(rpm)) = (d.gear(), d.rpm())
            && let Ok(engaged) = usize::try_from(gear.number())
            && let Some(next) = gears.choose(d, t, engaged, rpm, pedals.throttle)
            && let Ok(next) = i32::try_from(next)
        {
            d.set_gear(next);
        }
        d.set_throttle(pedals.throttle);
        d.set_brake_intensity(pedals.brake);
        Ok(())
    }

    /// Counts the step just taken against the band, and keeps the energy at the trace's end.
    ///
    /// # Errors
    /// An unknown car.
    pub(crate) fn measure(&mut self, sim: &Simulation, id: VehicleId) -> Result<(), ScenarioError> {
        if self.finished() {
            return Ok(());
        }
        let t = self.trace_time(sim);
        let speed = sim.world().vehicle(id)?.state().forward_speed;
        let trace = self.driver.trace();
        self.band.sample(
            trace,
            t,
            speed,
            sim.world().dt(),
            self.tolerance.time,
            self.tolerance.speed,
        );
        if t >= trace.duration() - END_TOLERANCE {
            self.end_energy = Some(sim.energy(id)?);
        }
        Ok(())
    }

    /// The cycle's metrics for a car of `engine`: the tracking, and with energy accounting
    /// the consumption between the trace's start and its end (or now, if it has not ended).
    ///
    /// # Errors
    /// An unknown car.
    pub(crate) fn metrics(
        &self,
        sim: &Simulation,
        id: VehicleId,
        engine: EngineType,
    ) -> Result<Vec<Metric>, ScenarioError> {
        let end = match self.end_energy {
            Some(e) => e,
            None => sim.energy(id)?,
        };
        let (start, end) = (
            self.start_energy.unwrap_or_default(),
            end.unwrap_or_default(),
        );
        Ok(metrics(
            engine,
            &self.tolerance,
            &self.band,
            &start,
            &end,
            self.trace().distance(),
        ))
    }
}

/// The cycle's metrics from the tracking and the energy at its start and end.
fn metrics(
    engine: EngineType,
    tolerance: &Band,
    band: &BandMeter,
    start: &EnergyReport,
    end: &EnergyReport,
    trace_distance: f64,
) -> Vec<Metric> {
    let distance = end.distance - start.distance;
    let km = distance / 1000.0;
    let per_km = |x: f64| if km > 0.0 { Some(x / km) } else { None };
    let mut m = vec![
        Metric::number("distance_km", "distance driven", "km", km),
        Metric::number(
            "trace_distance_km",
            "distance of the trace",
            "km",
            trace_distance / 1000.0,
        ),
        Metric::number(
            "time_outside_band_s",
            tolerance.outside_label,
            "s",
            band.outside,
        ),
        Metric::number(
            "longest_excursion_s",
            "longest excursion outside the band",
            "s",
            band.longest,
        ),
        Metric::number(
            "max_speed_error_kmh",
            "largest speed error",
            "km/h",
            band.max_error * KMH,
        ),
    ];
    if engine != EngineType::Combustion {
        let battery = (end.battery_energy - start.battery_energy) / J_PER_WH;
        m.push(Metric::maybe(
            "battery_wh_per_km",
            "battery energy per km (net of regeneration)",
            "Wh/km",
            per_km(battery),
        ));
        m.push(Metric::number(
            "battery_wh",
            "energy the battery gave at its terminals (net)",
            "Wh",
            battery,
        ));
        m.push(Metric::number(
            "motor_loss_wh",
            "electric machine losses",
            "Wh",
            (end.motor_loss - start.motor_loss) / J_PER_WH,
        ));
        m.push(Metric::number(
            "regenerated_wh",
            "energy regenerative braking took back at the wheels",
            "Wh",
            (end.regenerated - start.regenerated) / J_PER_WH,
        ));
        m.push(Metric::number(
            "soc_start",
            "state of charge at the start",
            "",
            start.soc,
        ));
        m.push(Metric::number(
            "soc_end",
            "state of charge at the end",
            "",
            end.soc,
        ));
    }
    if engine != EngineType::Electric {
        let litres = (end.fuel - start.fuel) / FUEL_DENSITY;
        m.push(Metric::maybe(
            "fuel_l_per_100km",
            "fuel per 100 km (petrol, 0.745 kg/l)",
            "l/100 km",
            per_km(100.0 * litres),
        ));
    }
    let wheel = (end.wheel_energy - start.wheel_energy) / J_PER_WH;
    m.push(Metric::number(
        "wheel_wh",
        "energy at the driven wheels",
        "Wh",
        wheel,
    ));
    m.push(Metric::number(
        "wheel_wh_per_km",
        "energy at the driven wheels per km",
        "Wh/km",
        per_km(wheel).unwrap_or(0.0),
    ));
    m
}
