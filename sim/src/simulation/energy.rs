//! A car's energy over a run ([`EnergyMeter`]): after every physics step, the driven wheels'
//! power goes through `vehicle_model::energy` (machine losses, battery, regenerative braking,
//! fuel) and the meter integrates what flowed, and keeps the battery's state of charge. An
//! electric car whose battery is empty gets no more drive torque, and the drive torque of a
//! car with a battery (electric or hybrid) is capped before each step to what its battery
//! can feed ([`EnergyMeter::cap_drive`]): a hybrid's machine part first, so that its engine
//! drives on when the pack is empty.
//!
//! The wheel power is the driven wheels' commanded torque times their spin, so the meter
//! counts torque control (throttle and brake, Webots' `wbu_driver_set_throttle`); in speed
//! control the spin is imposed and no torque is known, and the step counts no wheel power.

use vehicle_model::energy::{DriveState, EnergyParams, PowerFlow};
use vehicle_model::{
    Commands, ControlMode, Driver, EngineParams, EngineType, PerWheel, RAD_PER_S_PER_RPM, Wheel,
    WheelDrive,
};

use crate::vehicle::VehicleState;

/// What a car's powertrain did since it was added (SI units) and its battery's charge.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct EnergyReport {
    /// The battery's state of charge (dimensionless, in [0, 1]; 0 without a battery).
    pub soc: f64,
    /// Energy the battery gave at its terminals (J; net of what it took back).
    pub battery_energy: f64,
    /// Heat in the battery's internal resistance (J).
    pub battery_loss: f64,
    /// The electric machine's losses (J).
    pub motor_loss: f64,
    /// Energy the driven wheels received from the powertrain (J; net, a combustion engine's
    /// braking curve counted negative).
    pub wheel_energy: f64,
    /// Energy regenerative braking took back at the wheels (J).
    pub regenerated: f64,
    /// Fuel burnt (kg).
    pub fuel: f64,
    /// Distance driven (m, the chassis' forward speed integrated).
    pub distance: f64,
    /// The power the driven wheels received over the last step (W; what
    /// [`EnergyReport::wheel_energy`] adds up).
    pub wheel_power: f64,
    /// The power the battery gave at its terminals over the last step (W, negative while it
    /// charges; what [`EnergyReport::battery_energy`] adds up; 0 without a battery).
    pub battery_power: f64,
    /// The last step's flows.
    pub last: PowerFlow<f64>,
}

/// A car's energy accounting.
#[derive(Debug, Clone)]
pub(crate) struct EnergyMeter {
    params: EnergyParams<f64>,
    engine: EngineParams<f64>,
    report: EnergyReport,
    /// True if the battery is Webots' Robot battery: empty, it powers the controller off.
    powers_controller: bool,
    /// The part of the machine's share of the drive the last cap left
    /// ([`EnergyMeter::cap_drive`]; 1 uncapped), for the step it capped.
    electric_fraction: f64,
}

impl EnergyMeter {
    /// A meter for a car of `engine` with `params`, its battery at `soc` (clamped to [0, 1]).
    /// With `powers_controller`, the battery is Webots' Robot battery
    /// ([`EnergyMeter::powered_off`]).
    pub(crate) fn new(
        params: EnergyParams<f64>,
        engine: EngineParams<f64>,
        soc: f64,
        powers_controller: bool,
    ) -> Self {
        let soc = if params.battery.is_some() {
            soc.clamp(0.0, 1.0)
        } else {
            0.0
        };
        EnergyMeter {
            params,
            engine,
            report: EnergyReport {
                soc,
                ..EnergyReport::default()
            },
            powers_controller,
            electric_fraction: 1.0,
        }
    }

    /// The energy stored in the battery (J) at its state of charge; `None` without one.
    pub(crate) fn stored_energy(&self) -> Option<f64> {
        self.params.battery.map(|b| b.energy(self.report.soc))
    }

    /// True once the battery powering the controller is empty (Webots: the robot's
    /// `battery` energy reached 0).
    pub(crate) fn powered_off(&self) -> bool {
        self.powers_controller && self.params.battery.is_some() && self.report.soc <= 0.0
    }

    /// What the car's powertrain did so far.
    pub(crate) fn report(&self) -> &EnergyReport {
        &self.report
    }

    /// True if the car is electric and its battery is empty: its drive gives nothing.
    pub(crate) fn drained(&self) -> bool {
        self.engine.engine_type == EngineType::Electric
            && self.params.battery.is_some()
            && self.report.soc <= 0.0
    }

    /// Cuts the forward drive torque of `commands` if [`EnergyMeter::drained`], and all of
    /// it (either way, speed control included) if [`EnergyMeter::powered_off`]: Webots sets
    /// a powered-off robot's motors' available torque to 0.
    pub(crate) fn limit(&self, commands: &mut Commands<f64>) {
        if self.powered_off() {
            for w in Wheel::ALL {
                commands.drive[w] = WheelDrive::Torque(0.0);
            }
        } else if self.drained() {
            for w in Wheel::ALL {
                if let WheelDrive::Torque(t) = commands.drive[w]
                    && t > 0.0
                {
                    commands.drive[w] = WheelDrive::Torque(0.0);
                }
            }
        }
    }

    /// Scales the forward drive torques in `commands` of a car with a battery down to what
    /// it can feed over the step of `dt` s ([`EnergyParams::drive_cap`]: a hybrid's machine
    /// part first) with the driven wheels spinning at `spin` (rad/s, wheel order), the
    /// step's starting spin,
    /// through a gear of `ratio` (`None` outside torque control: no cap), and keeps the
    /// machine's part it left for the step's accounting ([`EnergyMeter::step`]). The meter
    /// counts the step at its end spin, so a step whose driven wheels speed up from `ω₀` to
    /// `ω₁` may ask the battery for up to `ω₁/ω₀` times its most: the end spin is not known
    /// before the physics step, and the cap holds at the known one.
    pub(crate) fn cap_drive(
        &mut self,
        commands: &mut Commands<f64>,
        spin: &PerWheel<f64>,
        ratio: Option<f64>,
        dt: f64,
    ) {
        self.electric_fraction = 1.0;
        let Some(ratio) = ratio.filter(|r| r.is_finite() && *r != 0.0) else {
            return;
        };
        let driven = Driven::sum(commands, spin, [0.0; 4]);
        let asked = driven.forward_power;
        // Standing, a drive asks no power yet: the cap still sees it, since an empty pack
        // launches nothing.
        if !driven.pushing || !asked.is_finite() {
            return;
        }
        let wheel_speed = driven.mean_spin();
        let cap = self.params.drive_cap(
            &self.engine,
            &DriveState {
                rpm: wheel_speed * ratio.abs() / RAD_PER_S_PER_RPM,
                wheel_power: asked,
                brake_torque: 0.0,
                wheel_speed,
                rim_speed: 0.0,
                ratio: ratio.abs(),
                soc: self.report.soc,
                electric_fraction: 1.0,
            },
            dt,
        );
        self.electric_fraction = cap.electric_fraction;
        if cap.torque_scale < 1.0 {
            for w in Wheel::ALL {
                if let WheelDrive::Torque(t) = commands.drive[w]
                    && t > 0.0
                {
                    commands.drive[w] = WheelDrive::Torque(t * cap.torque_scale);
                }
            }
        }
    }

    /// Accounts one step of `dt` s in which `commands` drove the car now in `state`, on tyres
    /// of `radii` (m, wheel order), through a gear of `ratio` (engine speed over wheel spin;
    /// `None` outside torque control). The
    /// engine speed is the driven wheels' end-of-step spin times the ratio, as Webots
    /// estimates it.
    pub(crate) fn step(
        &mut self,
        commands: &Commands<f64>,
        state: &VehicleState,
        radii: [f64; 4],
        ratio: Option<f64>,
        dt: f64,
    ) {
        let driven = Driven::sum(commands, &state.wheel_speeds, radii);
        let (wheel_power, brake_torque) = (driven.power, driven.brake);
        let ratio = ratio.filter(|r| r.is_finite()).unwrap_or(0.0).abs();
        let wheel_speed = driven.mean_spin();
        // Regeneration fades with the speed the machine turns at: the driven wheels' rim
        // speed, not the car's (locked wheels of a sliding car turn the machine not at all).
        let rim_speed = driven.mean_rim();
        let rpm = wheel_speed * ratio / RAD_PER_S_PER_RPM;
        let flow = self.params.flow(
            &self.engine,
            &DriveState {
                rpm,
                wheel_power: if wheel_power.is_finite() {
                    wheel_power
                } else {
                    0.0
                },
                brake_torque,
                wheel_speed,
                rim_speed,
                ratio,
                soc: self.report.soc,
                electric_fraction: self.electric_fraction,
            },
        );
        self.electric_fraction = 1.0;
        let r = &mut self.report;
        if let Some(battery) = self.params.battery {
            let s = battery.step(r.soc, flow.battery, dt);
            r.soc = s.soc;
            r.battery_power = s.power;
            r.battery_energy += s.power * dt;
            r.battery_loss += s.loss * dt;
        }
        r.motor_loss += flow.motor_loss * dt;
        r.wheel_power = wheel_power;
        r.wheel_energy += wheel_power * dt;
        r.regenerated += flow.regenerated * dt;
        r.fuel += flow.fuel_rate * dt;
        r.distance += state.forward_speed * dt;
        r.last = flow;
    }
}

/// The torque-driven wheels of a step, summed: what the cap and the accounting read of them.
#[derive(Debug, Clone, Copy, Default)]
struct Driven {
    /// How many wheels are under a torque command.
    count: f64,
    /// Their power, `Σ T·ω` (W; a braking curve's torque counted negative).
    power: f64,
    /// Their forward drive's power, `Σ max(T, 0)·ω` (W).
    forward_power: f64,
    /// True if one of them is driven forward (`T > 0`), standing or not (so `count` > 0).
    pushing: bool,
    /// `Σ |ω|` (rad/s).
    spin: f64,
    /// `Σ |ω|·r` (m/s).
    rim: f64,
    /// Their brakes' torque, `Σ max(T_brake, 0)` (N·m).
    brake: f64,
}

impl Driven {
    /// The wheels `commands` drive by torque, spinning at `spin` (rad/s) on tyres of `radii`
    /// (m, wheel order).
    fn sum(commands: &Commands<f64>, spin: &PerWheel<f64>, radii: [f64; 4]) -> Self {
        let mut d = Driven::default();
        for (k, w) in Wheel::ALL.into_iter().enumerate() {
            if let WheelDrive::Torque(t) = commands.drive[w] {
                let omega = spin[w];
                d.count += 1.0;
                d.power += t * omega;
                d.forward_power += t.max(0.0) * omega;
                d.pushing |= t > 0.0;
                d.spin += omega.abs();
                d.rim += omega.abs() * radii[k];
                d.brake += commands.brake_torque[w].max(0.0);
            }
        }
        d
    }

    /// Their mean spin (rad/s, ≥ 0; 0 with none).
    fn mean_spin(&self) -> f64 {
        self.mean(self.spin)
    }

    /// Their mean rim speed (m/s, ≥ 0; 0 with none).
    fn mean_rim(&self) -> f64 {
        self.mean(self.rim)
    }

    fn mean(&self, sum: f64) -> f64 {
        if self.count > 0.0 {
            sum / self.count
        } else {
            0.0
        }
    }
}

/// The gear ratio (engine speed over wheel spin) `driver` drives through; `None` outside
/// torque control or without a gear: what the meter and the drive cap turn the wheels' spin
/// into the machine's speed with.
pub(crate) fn drive_ratio(driver: &Driver<f64>) -> Option<f64> {
    (driver.control_mode() == ControlMode::Torque)
        .then(|| driver.gear().ok())
        .flatten()
        .map(|g| driver.powertrain().gearbox().ratio(g))
}
