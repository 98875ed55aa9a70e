//! Where a step's wheel power comes from, engine type by engine type, as Webots' `Car`
//! defines its torque (`powertrain::Engine::torque`): the combustion curve `f(rpm)`, the
//! electric part `e(rpm)`, and for the power-split hybrid the engine held at
//! `hybridPowerSplitRPM` giving `1 − hybridPowerSplitRatio` of its torque to the wheels and
//! the rest to its generator. Webots scales their sum by the throttle, so each part gives
//! the wheels its share `c/(c + e)` or `e/(c + e)` of the wheel power.
//!
//! The wheel power arrives through a lossless gearbox (the driveline's losses are the
//! [`crate::RoadLoad`] set's, at the wheels); the electric machine's losses are
//! [`MotorLosses`], the engine's fuel [`FuelModel`]'s, and braking torque on the driven
//! wheels goes back through the machine as far as [`RegenBlend`] lets it and it returns
//! energy (never at a cost to the battery: below that the friction brakes stop the car alone,
//! as a brake controller does). A machine neither
//! driving nor braking is not charged its spin losses: the road-load set's drag holds them.

use ackermann::Real;
use powertrain::{EngineParams, EngineType};

use super::{Battery, FuelModel, MotorLosses, RegenBlend};

use crate::RAD_PER_S_PER_RPM;

/// The energy parts of a car's powertrain: the machine, battery and regeneration of an
/// electric or hybrid car, the fuel model of a combustion engine or hybrid.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EnergyParams<T> {
    /// The electric machine's losses; `None` for a combustion car.
    pub motor: Option<MotorLosses<T>>,
    /// The traction battery; `None` for a combustion car.
    pub battery: Option<Battery<T>>,
    /// Regenerative braking; `None` without a machine.
    pub regen: Option<RegenBlend<T>>,
    /// The combustion engine's fuel; `None` for an electric car.
    pub fuel: Option<FuelModel<T>>,
    /// The state of charge below which a power-split hybrid's engine charges its pack
    /// (dimensionless, in [0, 1]; `None`: never): it runs at full load at
    /// `hybridPowerSplitRPM`, the wheels take their share of it as Webots' torque law gives
    /// it, and the generator the rest, as far as the pack takes it. Webots' hybrids have no
    /// such strategy; without one a pack that empties leaves Webots' hybrid, electric alone
    /// below `engineMinRPM`, unable to launch. Unused by other engine types.
    pub sustain_below: Option<T>,
}

/// The default [`EnergyParams::sustain_below`] of a power-split hybrid (dimensionless): half
/// the pack, an assumption (Toyota does not publish the window its Prius keeps its pack in).
pub const SUSTAIN_BELOW: f64 = 0.5;

/// A step's power flows (W, and kg/s of fuel).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct PowerFlow<T> {
    /// Power the battery gives at its terminals (W; negative while it charges).
    pub battery: T,
    /// The electric machine's losses (W, ≥ 0), the generator's included.
    pub motor_loss: T,
    /// Power the machine takes back from braking, at the wheels (W, ≥ 0).
    pub regenerated: T,
    /// Braking torque left to the friction brakes of the driven wheels (N·m, ≥ 0).
    pub friction_brake: T,
    /// Fuel burnt (kg/s, ≥ 0).
    pub fuel_rate: T,
}

/// A driven car's state for one step, as the driver library sees it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DriveState<T> {
    /// The engine speed estimate (rpm, ≥ 0): Webots' from the wheel speed and the gear.
    pub rpm: T,
    /// Power the engine gives the driven wheels (W): the sum of their drive torque times
    /// spin; negative for a combustion engine's braking curve.
    pub wheel_power: T,
    /// The friction brake torque asked for on the driven wheels (N·m, ≥ 0, their sum).
    pub brake_torque: T,
    /// The driven wheels' mean spin (rad/s).
    pub wheel_speed: T,
    /// The driven wheels' mean rim speed (m/s): their spin times their rolling radius, the
    /// speed regeneration fades with ([`RegenBlend::split`]). Locked wheels have none,
    /// whatever the car's speed.
    pub rim_speed: T,
    /// Engine speed over wheel spin (dimensionless, the gear's ratio; 0 in neutral).
    pub ratio: T,
    /// The battery's state of charge at the step's start (dimensionless, in [0, 1]): the
    /// power it can take bounds what regeneration returns ([`Battery::max_charge_power`]).
    /// Unused without a battery.
    pub soc: T,
    /// The part of the electric machine's share of the drive that ran (dimensionless, in
    /// [0, 1]; 1 as Webots drives): what the battery could feed, [`DriveCap`]'s. The
    /// engine's part of a hybrid's drive is not scaled with it.
    ///
    /// [`DriveCap`]: super::DriveCap
    pub electric_fraction: T,
}

impl<T: Real> EnergyParams<T> {
    /// The defaults for `engine`: an electric car gets a machine rated at its
    /// `engineMaxTorque`/`engineMaxPower` ([`MotorLosses::rated`]), the electric car's pack
    /// ([`Battery::electric_car`]) and full regeneration up to its power; a hybrid the same
    /// machine, the hybrid pack ([`Battery::hybrid`]) and a petrol engine of its curve's
    /// torque; a combustion car that engine alone.
    pub fn of_engine(engine: &EngineParams<T>) -> Self {
        Self::of_engine_displacing(engine, None)
    }

    /// [`EnergyParams::of_engine`] with the combustion engine's `displacement` (m³) where it
    /// is known: its friction is sized from it ([`FuelModel::petrol_of_displacement`]), not
    /// from the torque curve's peak ([`FuelModel::petrol`]). `None`, or a displacement that
    /// is not a finite positive number, falls back on the curve. The shipped models' is the
    /// real car's ([`Model::energy_params`](crate::Model::energy_params)).
    pub fn of_engine_displacing(engine: &EngineParams<T>, displacement: Option<T>) -> Self {
        let t = engine.engine_type;
        let machine = t.has_electric();
        let peak = peak_torque(engine);
        let top_speed = engine.max_rpm * T::from_f64(RAD_PER_S_PER_RPM);
        EnergyParams {
            motor: machine
                .then(|| MotorLosses::rated(engine.max_torque, engine.max_power, top_speed)),
            battery: machine.then(|| match t {
                EngineType::Electric => Battery::electric_car(),
                _ => Battery::hybrid(),
            }),
            regen: machine.then(|| RegenBlend::of_machine(engine.max_power)),
            fuel: t.has_combustion().then(|| {
                match displacement.filter(|d| d.is_finite() && *d > T::ZERO) {
                    Some(d) => FuelModel::petrol_of_displacement(d, top_speed),
                    None => FuelModel::petrol(peak, top_speed),
                }
            }),
            sustain_below: (t == EngineType::PowerSplitHybrid).then(|| T::from_f64(SUSTAIN_BELOW)),
        }
    }

    /// The same parts for a car whose driveline drag is a road-load set
    /// ([`crate::RoadLoad`], `losses = "road-load"`): the machine's spin losses (iron and
    /// windage, [`MotorLosses::without_spin_losses`]) are in that drag already, since a
    /// coast-down measures the car with its rotor turning, so the battery is not charged them
    /// a second time. The US EPA's coast-down of the Tesla Model 3 RWD shows how small they
    /// are: its whole speed-proportional term `B` (0.047 lbf/mph) is 10.4 N at 80 km/h, about
    /// 230 W, where [`MotorLosses::rated`]'s iron term alone gives the shipped model 4.6 kW
    /// there (it scales the rated point's iron loss linearly to speeds far above the corner).
    #[must_use]
    pub fn with_spin_losses_in_road_load(self) -> Self {
        EnergyParams {
            motor: self.motor.map(MotorLosses::without_spin_losses),
            ..self
        }
    }

    /// The power flows of one step of a car with `engine` in `state`.
    pub fn flow(&self, engine: &EngineParams<T>, state: &DriveState<T>) -> PowerFlow<T> {
        let zero = PowerFlow {
            friction_brake: state.brake_torque.max(T::ZERO),
            ..PowerFlow::default()
        };
        let rpm = state.rpm.finite_or(T::ZERO).abs();
        let omega = rpm * T::from_f64(RAD_PER_S_PER_RPM);
        let wheel_power = state.wheel_power.finite_or(T::ZERO);
        let (combustion, electric) = parts(engine, rpm);
        let electric = electric
            * state
                .electric_fraction
                .finite_or(T::ONE)
                .clamp(T::ZERO, T::ONE);
        let total = combustion + electric;
        let electric_share = if total > T::ZERO && electric > T::ZERO {
            (electric / total).clamp(T::ZERO, T::ONE)
        } else {
            T::ZERO
        };
        let mut flow = zero;
        // The machine's share, at its own speed.
        let electric_power = wheel_power * electric_share;
        if let Some(motor) = self.motor
            && omega > T::ZERO
            && electric_power != T::ZERO
        {
            let torque = electric_power / omega;
            flow.battery += motor.electrical_power(torque, omega);
            flow.motor_loss += motor.loss(torque, omega);
        }
        // The engine's share.
        let combustion_power = wheel_power - electric_power;
        if let Some(fuel) = self.fuel {
            match engine.engine_type {
                EngineType::PowerSplitHybrid => {
                    self.power_split(engine, fuel, state, combustion_power, omega, &mut flow);
                }
                _ if combustion_power > T::ZERO => {
                    let w = omega.max(engine.min_rpm * T::from_f64(RAD_PER_S_PER_RPM));
                    flow.fuel_rate += fuel.fuel_rate(combustion_power / w, w);
                }
                _ => {}
            }
        }
        // A combustion engine not driving: below its idle speed (`engineMinRPM`; the car at
        // rest or crawling, the clutch open) it idles and burns its friction's fuel; above it
        // the wheels turn it and the fuel is cut (overrun cut-off).
        if let Some(fuel) = self.fuel
            && engine.engine_type == EngineType::Combustion
            && combustion_power <= T::ZERO
            && rpm <= engine.min_rpm
        {
            flow.fuel_rate += fuel.idle_rate(engine.min_rpm * T::from_f64(RAD_PER_S_PER_RPM));
        }
        // Braking: the machine's share of the driven wheels' brake torque, back through the
        // gear to the machine.
        if let (Some(regen), Some(motor)) = (self.regen, self.motor) {
            let ratio = state.ratio.finite_or(T::ZERO).abs();
            let wheel_speed = state.wheel_speed.finite_or(T::ZERO).abs();
            let machine_speed = wheel_speed * ratio;
            // The machine's torque, and what the battery can take: the generating torque
            // whose electrical power is the battery's largest charge (none when full).
            let mut most = engine.max_torque * ratio;
            if let Some(battery) = self.battery {
                let charge = battery.max_charge_power(state.soc.finite_or(T::ONE));
                let by_battery = motor
                    .generating_torque_within(charge, machine_speed)
                    .map_or(most, |t| t * ratio);
                most = most.min(by_battery);
            }
            let split = regen.split(state.brake_torque, state.rim_speed, wheel_speed, most);
            let torque = if ratio > T::ZERO {
                -split.regenerative / ratio
            } else {
                T::ZERO
            };
            let electrical = motor.electrical_power(torque, machine_speed);
            // The brake controller regenerates only where the machine returns energy: at a
            // crawl its losses exceed what it takes back, and the friction brakes do it all.
            if machine_speed > T::ZERO && split.regenerative > T::ZERO && electrical < T::ZERO {
                flow.regenerated = split.regenerative * wheel_speed;
                flow.friction_brake = split.friction;
                flow.battery += electrical;
                flow.motor_loss += motor.loss(torque, machine_speed);
            }
        }
        flow
    }

    /// The power-split hybrid's engine and generator in a step whose wheels take
    /// `combustion_power` (W) of the engine at the engine-speed estimate `omega` (rad/s):
    /// the engine at the split speed gives its torque `θ·f`, the wheels get `(1 − r)·θ·f` at
    /// `omega`, the generator the rest of the engine's power. Below
    /// [`EnergyParams::sustain_below`] the engine runs at full load `f` instead (or less,
    /// where the pack takes no more: the generator's most is the pack's charge power plus
    /// what the machine draws this step), so the generator charges the pack.
    fn power_split(
        &self,
        engine: &EngineParams<T>,
        fuel: FuelModel<T>,
        state: &DriveState<T>,
        combustion_power: T,
        omega: T,
        flow: &mut PowerFlow<T>,
    ) {
        let split = engine.hybrid_power_split_rpm * T::from_f64(RAD_PER_S_PER_RPM);
        let to_wheels = T::ONE - engine.hybrid_power_split_ratio;
        let driving = combustion_power > T::ZERO && omega > T::ZERO && to_wheels > T::ZERO;
        let mut engine_torque = if driving {
            combustion_power / (to_wheels * omega)
        } else {
            T::ZERO
        };
        let wheels = if driving { combustion_power } else { T::ZERO };
        let sustaining = self
            .sustain_below
            .is_some_and(|low| state.soc.finite_or(T::ONE) < low);
        if sustaining
            && split > T::ZERO
            && let (Some(battery), Some(motor)) = (self.battery, self.motor)
        {
            let room = battery.max_charge_power(state.soc.finite_or(T::ONE)) + flow.battery;
            let full = curve(engine, engine.hybrid_power_split_rpm).max(T::ZERO);
            // Where the machine cannot return what the pack takes, the pack does not bound
            // the generator, and the engine's full load does.
            let most_generator = motor.generating_torque_within(room, split).unwrap_or(full);
            engine_torque = engine_torque.max(full.min(wheels / split + most_generator));
        }
        if engine_torque <= T::ZERO {
            return;
        }
        flow.fuel_rate += fuel.fuel_rate(engine_torque, split);
        let generator = engine_torque * split - wheels;
        if let Some(motor) = self.motor {
            let torque = -generator / split;
            flow.battery += motor.electrical_power(torque, split);
            flow.motor_loss += motor.loss(torque, split);
        }
    }
}

/// The combustion and electric parts of `engine`'s torque at `rpm` (N·m, before the
/// throttle), as `powertrain::Engine::torque` sums them.
pub(super) fn parts<T: Real>(engine: &EngineParams<T>, rpm: T) -> (T, T) {
    if rpm >= engine.max_rpm {
        return (T::ZERO, T::ZERO);
    }
    let on = rpm >= engine.min_rpm;
    let combustion = match engine.engine_type {
        EngineType::Combustion => curve(engine, rpm.max(engine.min_rpm)),
        EngineType::Electric => T::ZERO,
        EngineType::ParallelHybrid if on => curve(engine, rpm),
        EngineType::PowerSplitHybrid if on => {
            (T::ONE - engine.hybrid_power_split_ratio)
                * curve(engine, engine.hybrid_power_split_rpm)
        }
        EngineType::ParallelHybrid | EngineType::PowerSplitHybrid => T::ZERO,
    };
    let electric = if engine.engine_type.has_electric() {
        let omega = rpm * T::from_f64(RAD_PER_S_PER_RPM);
        if omega > T::ZERO {
            engine.max_torque.min(engine.max_power / omega)
        } else {
            engine.max_torque
        }
    } else {
        T::ZERO
    };
    (combustion.max(T::ZERO), electric)
}

/// The combustion curve `a + b·x + c·x²` (N·m) at `x` rpm.
fn curve<T: Real>(engine: &EngineParams<T>, x: T) -> T {
    let [a, b, c] = engine.function_coefficients;
    a + b * x + c * x * x
}

/// The combustion curve's largest torque between `engineMinRPM` and `engineMaxRPM` (N·m,
/// at least 1): at an end or at the parabola's vertex.
fn peak_torque<T: Real>(engine: &EngineParams<T>) -> T {
    let [_, b, c] = engine.function_coefficients;
    let mut best = curve(engine, engine.min_rpm).max(curve(engine, engine.max_rpm));
    if c < T::ZERO {
        let vertex = -b / (T::TWO * c);
        if vertex > engine.min_rpm && vertex < engine.max_rpm {
            best = best.max(curve(engine, vertex));
        }
    }
    best.finite_or(T::ONE).max(T::ONE)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Model;

    /// A car in a gear of ratio 9 whose engine turns at `rpm`, on 0.35 m wheels.
    fn state(rpm: f64, wheel_power: f64, brake: f64) -> DriveState<f64> {
        let wheel_speed = rpm * RAD_PER_S_PER_RPM / 9.0;
        DriveState {
            rpm,
            wheel_power,
            brake_torque: brake,
            wheel_speed,
            rim_speed: wheel_speed * 0.35,
            ratio: 9.0,
            soc: 0.5,
            electric_fraction: 1.0,
        }
    }

    #[test]
    fn an_electric_car_draws_the_wheel_power_plus_the_machine_s_losses() {
        let engine = Model::TeslaModel3.params::<f64>().engine;
        let e = EnergyParams::of_engine(&engine);
        assert!(e.fuel.is_none() && e.battery.is_some());
        let rpm = 50.0 * 9.0 / RAD_PER_S_PER_RPM;
        let f = e.flow(&engine, &state(rpm, 20_000.0, 0.0));
        assert!((f.battery - 20_000.0 - f.motor_loss).abs() < 1e-9, "{f:?}");
        assert!(f.motor_loss > 0.0 && f.fuel_rate == 0.0);
        // Braking at 800 N·m on the wheels spinning at 50 rad/s: 40 kW, within the machine's
        // torque and power, so it takes it all; the battery gets it less the losses.
        let f = e.flow(&engine, &state(rpm, 0.0, 800.0));
        assert!((f.regenerated - 800.0 * 50.0).abs() < 1e-9, "{f:?}");
        assert_eq!(f.friction_brake, 0.0);
        assert!(
            (f.battery + f.regenerated - f.motor_loss).abs() < 1e-9,
            "{f:?}"
        );
    }

    #[test]
    fn on_a_road_load_set_the_battery_pays_the_machine_s_copper_and_constant_alone() {
        let engine = Model::TeslaModel3.params::<f64>().engine;
        let full = EnergyParams::of_engine(&engine);
        let e = full.with_spin_losses_in_road_load();
        let m = e.motor.unwrap();
        // 20 kW at 50 rad/s of wheel spin through 9:1: the machine at 450 rad/s.
        let (speed, torque) = (450.0, 20_000.0 / 450.0);
        let rpm = speed / RAD_PER_S_PER_RPM;
        let f = e.flow(&engine, &state(rpm, 20_000.0, 0.0));
        let expected = m.copper * torque * torque + m.constant;
        assert!((f.motor_loss - expected).abs() < 1e-9, "{f:?}");
        assert!((f.battery - 20_000.0 - expected).abs() < 1e-9, "{f:?}");
        // The spin losses the road load holds are what the full machine loses on top.
        let spin = full.motor.unwrap().iron * speed + full.motor.unwrap().windage * speed.powi(3);
        let g = full.flow(&engine, &state(rpm, 20_000.0, 0.0));
        assert!(
            (g.motor_loss - f.motor_loss - spin).abs() < 1e-6,
            "{g:?} {f:?}"
        );
        // The battery and the rest are the engine type's defaults.
        assert_eq!(
            (e.battery, e.regen, e.fuel),
            (full.battery, full.regen, full.fuel)
        );
    }

    #[test]
    fn locked_driven_wheels_regenerate_nothing_and_draw_nothing() {
        // A sliding car's locked wheels turn the machine not at all: the friction brakes
        // take all of the brake torque, and the machine is not asked for a torque it could
        // only hold by drawing current.
        let engine = Model::TeslaModel3.params::<f64>().engine;
        let e = EnergyParams::of_engine(&engine);
        let locked = DriveState {
            rpm: 0.0,
            wheel_power: 0.0,
            brake_torque: 3000.0,
            wheel_speed: 0.0,
            rim_speed: 0.0,
            ratio: 9.0,
            soc: 0.5,
            electric_fraction: 1.0,
        };
        let f = e.flow(&engine, &locked);
        assert_eq!((f.regenerated, f.battery, f.motor_loss), (0.0, 0.0, 0.0));
        assert_eq!(f.friction_brake, 3000.0);
    }

    #[test]
    fn a_combustion_car_burns_fuel_and_has_no_battery() {
        let engine = Model::BmwX5.params::<f64>().engine;
        let e = EnergyParams::of_engine(&engine);
        assert!(e.battery.is_none() && e.regen.is_none());
        let f = e.flow(&engine, &state(3000.0, 30_000.0, 500.0));
        assert!(f.fuel_rate > 0.0 && f.battery == 0.0);
        assert_eq!(f.friction_brake, 500.0);
        // The fuel's power over the wheel power: the engine's efficiency, 0.2–0.38.
        let eta = 30_000.0 / (f.fuel_rate * crate::energy::PETROL_LHV);
        assert!((0.2..0.38).contains(&eta), "{eta}");
        // At rest it idles at `engineMinRPM`; coasting in gear above it, the fuel is cut.
        let fuel = e.fuel.unwrap();
        let idle = fuel.idle_rate(engine.min_rpm * RAD_PER_S_PER_RPM);
        assert!(idle > 0.0);
        assert_eq!(e.flow(&engine, &state(0.0, 0.0, 500.0)).fuel_rate, idle);
        assert_eq!(e.flow(&engine, &state(2500.0, 0.0, 500.0)).fuel_rate, 0.0);
    }

    #[test]
    fn a_power_split_hybrid_charges_from_the_generator_what_the_wheels_do_not_take() {
        let engine = Model::ToyotaPrius.params::<f64>().engine;
        let e = EnergyParams::of_engine(&engine);
        let rpm = 2000.0_f64.max(engine.min_rpm);
        let (c, el) = parts(&engine, rpm);
        let wheel = 20_000.0;
        let f = e.flow(&engine, &state(rpm, wheel, 0.0));
        // The engine's share of the wheel power, and the generator's power: the engine's
        // output at the split speed less that share.
        let omega = rpm * RAD_PER_S_PER_RPM;
        let combustion_power = wheel * c / (c + el);
        let split = engine.hybrid_power_split_rpm * RAD_PER_S_PER_RPM;
        let engine_torque = combustion_power / ((1.0 - engine.hybrid_power_split_ratio) * omega);
        let generator = engine_torque * split - combustion_power;
        let motor = e.motor.unwrap();
        let expected = motor.electrical_power(wheel * el / (c + el) / omega, omega)
            + motor.electrical_power(-generator / split, split);
        assert!((f.battery - expected).abs() < 1e-9, "{f:?} vs {expected}");
        assert!(f.fuel_rate > 0.0);
    }

    #[test]
    fn below_its_sustaining_charge_a_power_split_hybrid_s_engine_charges_the_pack() {
        let engine = Model::ToyotaPrius.params::<f64>().engine;
        let e = EnergyParams::of_engine(&engine);
        assert_eq!(e.sustain_below, Some(SUSTAIN_BELOW));
        let split = engine.hybrid_power_split_rpm * RAD_PER_S_PER_RPM;
        let full = curve(&engine, engine.hybrid_power_split_rpm);
        let (battery, motor, fuel) = (e.battery.unwrap(), e.motor.unwrap(), e.fuel.unwrap());
        // Standing at 0.3: the engine's power all through the generator, as much as the
        // hybrid pack takes (less than the engine's full load gives).
        let mut standing = state(0.0, 0.0, 0.0);
        standing.soc = 0.3;
        let f = e.flow(&engine, &standing);
        let taken = battery.max_charge_power(0.3);
        assert!((f.battery + taken).abs() < 1e-6 * taken, "{f:?} vs {taken}");
        assert!(
            f.fuel_rate > 0.0 && f.fuel_rate < fuel.fuel_rate(full, split),
            "{f:?}"
        );
        // The engine at full load at the split speed, its generator returning what `machine`
        // makes of all of it.
        let at_full_load = |f: PowerFlow<f64>, machine: MotorLosses<f64>| {
            let generating = machine.electrical_power(-full, split);
            assert!(
                (f.battery - generating).abs() < 1e-9,
                "{f:?} vs {generating}"
            );
            assert!(
                (f.fuel_rate - fuel.fuel_rate(full, split)).abs() < 1e-15,
                "{f:?}"
            );
        };
        // A pack that takes it all (1 000 A): the engine at full load.
        let mut big = e;
        let mut b = battery;
        b.max_charge_current = 1000.0;
        big.battery = Some(b);
        at_full_load(big.flow(&engine, &standing), motor);
        // A machine that cannot return what that pack takes at the split speed (no spin
        // losses, copper `k_c = ω²/(2·room)`: its largest return `ω²/(4k_c)` is half the
        // room) no longer bounds the engine by the pack: full load, returning what the
        // machine makes of it.
        let room = b.max_charge_power(0.3);
        let lossy = MotorLosses {
            copper: split * split / (2.0 * room),
            iron: 0.0,
            windage: 0.0,
            constant: 0.0,
        };
        assert!(
            lossy.electrical_power(-full, split) < 0.0,
            "still generating"
        );
        big.motor = Some(lossy);
        at_full_load(big.flow(&engine, &standing), lossy);
        // At 0.6, or with no strategy, the engine is off standing: nothing flows.
        standing.soc = 0.6;
        assert_eq!(e.flow(&engine, &standing), PowerFlow::default());
        standing.soc = 0.3;
        let pure = EnergyParams {
            sustain_below: None,
            ..e
        };
        assert_eq!(pure.flow(&engine, &standing), PowerFlow::default());
        // Other engine types have none.
        for model in [Model::TeslaModel3, Model::BmwX5] {
            let engine = model.params::<f64>().engine;
            assert_eq!(EnergyParams::of_engine(&engine).sustain_below, None);
        }
    }

    #[test]
    fn regeneration_returns_no_more_than_the_battery_takes() {
        // A pack whose charge limit (20 A) is far below the machine's power: braking hard at
        // speed, the machine takes only the torque whose returned power the battery can
        // take, and the friction brakes the rest; full, it takes none.
        let engine = Model::TeslaModel3.params::<f64>().engine;
        let mut e = EnergyParams::of_engine(&engine);
        let mut battery = e.battery.unwrap();
        battery.max_charge_current = 20.0;
        e.battery = Some(battery);
        let rpm = 60.0 * 9.0 / RAD_PER_S_PER_RPM;
        let mut s = state(rpm, 0.0, 3000.0);
        s.soc = 0.5;
        let f = e.flow(&engine, &s);
        let taken = battery.max_charge_power(0.5);
        assert!((f.battery + taken).abs() < 1e-6 * taken, "{f:?} vs {taken}");
        assert!(f.regenerated > 0.0);
        assert!(
            (f.regenerated / 60.0 + f.friction_brake - 3000.0).abs() < 1e-9,
            "{f:?}"
        );
        // What the battery then takes in a step is what the flow returned: the balance
        // closes.
        let step = battery.step(0.5, f.battery, 0.01);
        assert!((step.power - f.battery).abs() < 1e-6 * taken, "{step:?}");
        s.soc = 1.0;
        let full = e.flow(&engine, &s);
        assert_eq!((full.regenerated, full.battery), (0.0, 0.0));
        assert_eq!(full.friction_brake, 3000.0);
    }
}
