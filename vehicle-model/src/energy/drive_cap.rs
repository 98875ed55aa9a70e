//! What a car's battery lets its drive give in one step ([`EnergyParams::drive_cap`]).
//!
//! Webots' torque law ignores the battery: an electric car or a hybrid gets its torque curve
//! times the throttle whatever the pack holds. Left at that, a drained pack would still
//! drive the wheels, energy from nowhere ([`Battery::step`](super::Battery::step) gives no
//! more than the cells hold, the wheels would get it all the same). The cap takes the
//! electric machine's part of the drive first: a hybrid's engine keeps driving on an empty
//! pack, and a power-split hybrid's generator still feeds its machine (the series path).
//! Only where the engine's own part needs the pack is that scaled too: Webots' power split
//! holds the engine at `hybridPowerSplitRPM` and gives the wheels `1 − hybridPowerSplitRatio`
//! of its torque at the wheels' engine speed, so above the split speed the wheels get more
//! power than the engine makes, and the generator has to motor.

use ackermann::Real;
use powertrain::{EngineParams, EngineType};

use crate::RAD_PER_S_PER_RPM;

use super::flow::{DriveState, EnergyParams, parts};

/// How much of its asked forward drive a car may give this step.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DriveCap<T> {
    /// The part of the electric machine's share of the drive the battery can feed
    /// (dimensionless, in [0, 1]): what [`DriveState::electric_fraction`] is for the step.
    pub electric_fraction: T,
    /// What the forward drive torques are multiplied by (dimensionless, in [0, 1]):
    /// `(c + k·e)/(c + e)`, with `c` and `e` the engine's combustion and electric torque at
    /// the step's engine speed and `k` the electric fraction.
    pub torque_scale: T,
}

impl<T: Real> DriveCap<T> {
    /// No cap: the drive as asked.
    pub const NONE: DriveCap<T> = DriveCap {
        electric_fraction: T::ONE,
        torque_scale: T::ONE,
    };
}

/// The bracket's least width on the drive's interval (of length 2): 2⁻⁴⁰ ≈ 10⁻¹² of it,
/// below f64's round-off in the battery power and past f32's, so the search ends at the
/// representable answer in both; and how many halvings of the interval that is, the bound
/// on the search's bisection steps.
const HALVINGS: i32 = 41;

/// Steps of the search (see [`EnergyParams::drive_cap`]): a false position that has not
/// halved the bracket in two steps is followed by a bisection, so that [`HALVINGS`] of them
/// are reached within three times as many even where false position crawls; a smooth
/// battery power ends it in a handful.
const SEARCH_STEPS: usize = 3 * HALVINGS as usize;

impl<T: Real> EnergyParams<T> {
    /// The cap on a step of `dt` (s) of the forward drive of a car with `engine` in `state`, whose
    /// `wheel_power` (W) is the drive asked at the driven wheels' spin `wheel_speed`, at the
    /// engine speed `rpm` and the battery's `soc` (the state's `electric_fraction` is
    /// ignored): the largest drive whose battery power ([`EnergyParams::flow`]) is within
    /// the battery's largest discharge
    /// ([`Battery::max_discharge_power`](super::Battery::max_discharge_power), or what
    /// charge is left for the step, [`Battery::step`](super::Battery::step)), taking the
    /// machine's part away first and then the engine's, found by a bracketed search (false
    /// position, bisecting where it crawls), since a power-split hybrid's generator makes the
    /// battery power no simple function of it; an electric car's in closed form.
    ///
    /// [`DriveCap::NONE`] without a battery or machine, for an engine with no electric
    /// part at that speed, and for a drive that asks no power (standing, or rolling back
    /// against it: the torque curve bounds the launch) with charge in the pack. An
    /// electric car on an empty pack gets a torque scale of 0, a parallel hybrid its
    /// engine's share `c/(c + e)` (nothing below `engineMinRPM`, where Webots' hybrid is
    /// electric alone), standing too.
    pub fn drive_cap(&self, engine: &EngineParams<T>, state: &DriveState<T>, dt: T) -> DriveCap<T> {
        let (Some(battery), Some(motor)) = (self.battery, self.motor) else {
            return DriveCap::NONE;
        };
        let asked = state.wheel_power.finite_or(T::ZERO);
        let (combustion, electric) = parts(engine, state.rpm.finite_or(T::ZERO).abs());
        let total = combustion + electric;
        if electric <= T::ZERO || total <= T::ZERO {
            return DriveCap::NONE;
        }
        // What the pack can give over the step: its most power, or less where the charge
        // left runs out within the step.
        let most = battery
            .step(state.soc, battery.max_discharge_power(state.soc), dt)
            .power
            .max(T::ZERO);
        if asked <= T::ZERO {
            // Standing (or rolling back against the drive) no power flows at the step's
            // start, whatever the torque: the torque curve bounds the launch, but an empty
            // pack gives the machine nothing to launch with.
            return if most > T::ZERO {
                DriveCap::NONE
            } else {
                DriveCap {
                    electric_fraction: T::ZERO,
                    torque_scale: combustion / total,
                }
            };
        }
        // The drive at `u` in [0, 2]: above 1 the engine's part whole and the fraction
        // `u − 1` of the machine's; below it the machine's none and the fraction `u` of the
        // engine's.
        let at = |u: T| {
            let k = (u - T::ONE).max(T::ZERO);
            let scale = if u >= T::ONE {
                (combustion + k * electric) / total
            } else {
                u * combustion / total
            };
            (k, scale)
        };
        let drawn = |u: T| {
            let (k, scale) = at(u);
            let step = DriveState {
                wheel_power: asked * scale,
                electric_fraction: k,
                ..*state
            };
            self.flow(engine, &step).battery
        };
        let drawn_at_two = drawn(T::TWO);
        if drawn_at_two <= most {
            return DriveCap::NONE;
        }
        // An electric car's machine draws the drive's power alone: the torque at the pack's
        // most is the inverse of its losses, with no search (a step of a capped launch
        // would otherwise cost several flows).
        let omega = state.rpm.finite_or(T::ZERO).abs() * T::from_f64(RAD_PER_S_PER_RPM);
        if engine.engine_type == EngineType::Electric
            && let Some(torque) = motor.torque_for_electrical(most, omega)
            && torque > T::ZERO
        {
            let k = (torque * omega / asked).min(T::ONE);
            return DriveCap {
                electric_fraction: k,
                torque_scale: k,
            };
        }
        // The largest `u` whose battery power is within the pack's most, bracketed:
        // `g(lo) ≤ 0 < g(hi)` with `g(u) = drawn(u) − most` (at 0 no power flows). The
        // battery power is smooth in `u` on either side of 1 (the machine's part, then the
        // engine's), with a kink at 1, so the bracket starts on the side of 1 the answer is
        // on, and shrinks by false position (Illinois: a side kept twice has its value
        // halved, so that a convex curve does not hold one end still), by bisection where
        // that crawls. It ends when the bracket is 2⁻⁴⁰ wide, or when `lo`'s power is within
        // 10⁻¹² of the most (or the float's round-off): 42 flows a cap by bisection alone,
        // 7 to 12 for most of the tests' states this way, up to 43 where the power has a
        // kink (the `energy` bench's `drive_cap` against one `flow`).
        let g = |u: T| drawn(u) - most;
        let g_one = g(T::ONE);
        let (mut lo, mut hi, mut g_lo, mut g_hi) = if g_one <= T::ZERO {
            (T::ONE, T::TWO, g_one, drawn_at_two - most)
        } else {
            (T::ZERO, T::ONE, g(T::ZERO), g_one)
        };
        let width = T::TWO * T::from_f64(0.5_f64.powi(HALVINGS));
        let round_off = most.abs() * T::from_f64(1e-12).max(T::EPSILON * T::from_f64(4.0));
        // `lo`'s own value: `g_lo` is the one false position uses, halved where kept.
        let mut lo_short = -g_lo;
        let mut kept = 0_i8;
        // The bracket's width two steps back: a false position that has not halved it since
        // is crawling, and the next step bisects.
        let (mut before, mut last) = (T::INFINITY, hi - lo);
        for _ in 0..SEARCH_STEPS {
            if hi - lo <= width || (lo > T::ZERO && lo_short <= round_off) {
                break;
            }
            let false_position = lo - g_lo * (hi - lo) / (g_hi - g_lo);
            let crawling = hi - lo > before / T::TWO;
            let mid = if crawling || !(false_position > lo && false_position < hi) {
                (lo + hi) / T::TWO
            } else {
                false_position
            };
            (before, last) = (last, hi - lo);
            let g_mid = g(mid);
            if g_mid <= T::ZERO {
                (lo, g_lo, lo_short) = (mid, g_mid, -g_mid);
                if kept < 0 {
                    g_hi /= T::TWO;
                }
                kept = -1;
            } else {
                (hi, g_hi) = (mid, g_mid);
                if kept > 0 {
                    g_lo /= T::TWO;
                }
                kept = 1;
            }
        }
        // Charge left that no drive fits in (less than the machine's standing loss over the
        // step) goes in the least drive there is, which the battery clips to it: the pack
        // ends empty, rather than keeping joules nothing can use.
        let u = if at(lo).1 == T::ZERO && most > T::ZERO {
            hi
        } else {
            lo
        };
        let (electric_fraction, torque_scale) = at(u);
        DriveCap {
            electric_fraction,
            torque_scale,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Model;

    /// The step (s).
    const DT: f64 = 0.01;

    /// A drive asking `wheel_power` (W) with the driven wheels at `spin` (rad/s) through a
    /// gear of 9, the battery at `soc`.
    fn asking(wheel_power: f64, spin: f64, soc: f64) -> DriveState<f64> {
        DriveState {
            rpm: spin * 9.0 / RAD_PER_S_PER_RPM,
            wheel_power,
            brake_torque: 0.0,
            wheel_speed: spin,
            rim_speed: spin * 0.35,
            ratio: 9.0,
            soc,
            electric_fraction: 1.0,
        }
    }

    /// The flow of the drive `asked` capped by `cap`.
    fn capped(asked: &DriveState<f64>, cap: DriveCap<f64>) -> DriveState<f64> {
        DriveState {
            wheel_power: asked.wheel_power * cap.torque_scale,
            electric_fraction: cap.electric_fraction,
            ..*asked
        }
    }

    #[test]
    fn an_electric_car_s_capped_drive_draws_the_battery_s_largest_power() {
        let engine = Model::TeslaModel3.params::<f64>().engine;
        let e = EnergyParams::of_engine(&engine);
        let (battery, motor) = (e.battery.unwrap(), e.motor.unwrap());
        // 1 MW asked at the wheels: far beyond the pack. The scaled torque, back through
        // the gear to the machine at 540 rad/s, draws the battery's most at that charge.
        let cap = e.drive_cap(&engine, &asking(1e6, 60.0, 0.8), DT);
        assert_eq!(cap.electric_fraction, cap.torque_scale);
        let torque = 1e6 * cap.torque_scale / 540.0;
        let drawn = motor.electrical_power(torque, 540.0);
        let most = battery.max_discharge_power(0.8);
        // Closed form: equal to round-off; 10⁻⁹ of the most is a loose bound on it.
        assert!((drawn - most).abs() < 1e-9 * most, "{drawn} vs {most}");
        // Within the pack's power: as asked. Empty: nothing.
        assert_eq!(
            e.drive_cap(&engine, &asking(20_000.0, 60.0, 0.8), DT),
            DriveCap::NONE
        );
        let empty = e.drive_cap(&engine, &asking(20_000.0, 60.0, 0.0), DT);
        assert_eq!((empty.electric_fraction, empty.torque_scale), (0.0, 0.0));
        // Charge left below the machine's standing loss over the step (1e-8 of the pack,
        // 2.7 J): the least drive, which the battery clips to that charge, so the pack
        // ends empty rather than keeping joules no drive can use.
        let residue = e.drive_cap(&engine, &asking(20_000.0, 60.0, 1e-8), DT);
        assert!(
            residue.torque_scale > 0.0 && residue.torque_scale < 1e-9,
            "{residue:?}"
        );
    }

    #[test]
    fn standing_on_a_charged_pack_a_combustion_car_or_asking_nothing_is_not_capped() {
        let engine = Model::TeslaModel3.params::<f64>().engine;
        let e = EnergyParams::of_engine(&engine);
        // Standing the asked torque meets no spin: no power.
        let mut standing = asking(0.0, 0.0, 0.3);
        assert_eq!(e.drive_cap(&engine, &standing, DT), DriveCap::NONE);
        // Standing on an empty pack: nothing to launch with.
        standing.soc = 0.0;
        let empty = e.drive_cap(&engine, &standing, DT);
        assert_eq!((empty.electric_fraction, empty.torque_scale), (0.0, 0.0));
        assert_eq!(
            e.drive_cap(&engine, &asking(-5e4, 60.0, 0.3), DT),
            DriveCap::NONE
        );
        let bmw = Model::BmwX5.params::<f64>().engine;
        let c = EnergyParams::of_engine(&bmw);
        assert_eq!(
            c.drive_cap(&bmw, &asking(1e6, 60.0, 0.0), DT),
            DriveCap::NONE
        );
    }

    #[test]
    fn a_parallel_hybrid_on_an_empty_pack_drives_on_its_engine_alone() {
        // The TeslaModel3's machine behind a petrol curve: a parallel hybrid.
        let mut engine = Model::TeslaModel3.params::<f64>().engine;
        engine.engine_type = EngineType::ParallelHybrid;
        engine.function_coefficients = [150.0, 0.1, 0.0];
        let e = EnergyParams::of_engine(&engine);
        let s = asking(60_000.0, 60.0, 0.0);
        let (c, el) = parts(&engine, s.rpm);
        assert!(c > 0.0 && el > 0.0);
        let cap = e.drive_cap(&engine, &s, DT);
        assert_eq!(cap.electric_fraction, 0.0);
        assert!((cap.torque_scale - c / (c + el)).abs() < 1e-15, "{cap:?}");
        // The capped step draws nothing from the pack and burns fuel for all of it.
        let f = e.flow(&engine, &capped(&s, cap));
        assert_eq!((f.battery, f.motor_loss), (0.0, 0.0));
        assert!(f.fuel_rate > 0.0);
    }

    #[test]
    fn a_power_split_hybrid_on_an_empty_pack_feeds_its_machine_from_its_generator() {
        // Webots' power split alone: no charge-sustaining engine.
        let engine = Model::ToyotaPrius.params::<f64>().engine;
        let e = EnergyParams {
            sustain_below: None,
            ..EnergyParams::of_engine(&engine)
        };
        // 40 kW asked at 25 rad/s: the engine speed estimate, 2 149 rpm, is below the
        // split speed (3 000 rpm), so the generator charges, and it keeps part of the
        // machine's share: between none and all.
        let slow = asking(40_000.0, 25.0, 0.0);
        let (c, el) = parts(&engine, slow.rpm);
        let cap = e.drive_cap(&engine, &slow, DT);
        assert!(
            cap.electric_fraction > 0.0 && cap.electric_fraction < 1.0,
            "{cap:?}"
        );
        assert!(cap.torque_scale > c / (c + el) && cap.torque_scale < 1.0);
        // The machine draws what the generator gives: the pack's net power is zero, within
        // the search's end (a bracket of 2⁻⁴⁰ of the drive times the battery power's slope,
        // tens of kW per unit, or 10⁻¹² of the most: well under a milliwatt).
        let f = e.flow(&engine, &capped(&slow, cap));
        assert!(f.battery <= 0.0 && f.battery > -1e-3, "{f:?}");
        // With charge in the pack the same drive is not capped.
        assert_eq!(
            e.drive_cap(&engine, &asking(40_000.0, 25.0, 0.6), DT),
            DriveCap::NONE
        );
        // At 60 rad/s (5 157 rpm) the wheels would get more than the engine at the split
        // speed makes: the generator would motor, on the pack, and draw the machine's
        // standing losses at any drive. On an empty pack nothing drives there; with 2 kW
        // left the engine's part is scaled to what they give.
        let fast = asking(40_000.0, 60.0, 0.0);
        let none = e.drive_cap(&engine, &fast, DT);
        assert_eq!((none.electric_fraction, none.torque_scale), (0.0, 0.0));
        let mut low = e;
        let mut battery = low.battery.unwrap();
        battery.max_discharge_current = 2_000.0 / battery.open_circuit_voltage(0.3);
        low.battery = Some(battery);
        let fast = asking(40_000.0, 60.0, 0.3);
        let (c, el) = parts(&engine, fast.rpm);
        let cap = low.drive_cap(&engine, &fast, DT);
        assert_eq!(cap.electric_fraction, 0.0);
        assert!(
            cap.torque_scale > 0.0 && cap.torque_scale < c / (c + el),
            "{cap:?}"
        );
        let most = battery.max_discharge_power(0.3);
        let f = low.flow(&engine, &capped(&fast, cap));
        assert!(
            f.battery <= most && f.battery > most - 1e-3,
            "{f:?} vs {most}"
        );
    }

    #[test]
    fn a_charge_sustaining_power_split_hybrid_drives_on_its_generator_s_charge() {
        // With the engine charging below half the pack, the empty pack's ToyotaPrius at
        // 25 rad/s gets more of its machine's share than without, and still asks the pack
        // for nothing.
        let engine = Model::ToyotaPrius.params::<f64>().engine;
        let sustaining = EnergyParams::of_engine(&engine);
        let pure = EnergyParams {
            sustain_below: None,
            ..sustaining
        };
        let slow = asking(40_000.0, 25.0, 0.0);
        let (with, without) = (
            sustaining.drive_cap(&engine, &slow, DT),
            pure.drive_cap(&engine, &slow, DT),
        );
        assert!(
            with.torque_scale > without.torque_scale,
            "{with:?} {without:?}"
        );
        let f = sustaining.flow(&engine, &capped(&slow, with));
        assert!(f.battery <= 0.0 && f.fuel_rate > 0.0, "{f:?}");
    }

    #[test]
    fn a_hybrid_s_capped_drive_draws_the_pack_s_most_over_a_grid_of_states() {
        // The search's answer, wherever the pack limits: its battery power within the most
        // and short of it by no more than the float's round-off of the bracket (10⁻⁹ of
        // the most), on both sides of the kink at the machine's part (small and large
        // drives), on both hybrids, sustaining or not, near empty and half full.
        let prius = Model::ToyotaPrius.params::<f64>().engine;
        let mut parallel = Model::TeslaModel3.params::<f64>().engine;
        parallel.engine_type = EngineType::ParallelHybrid;
        parallel.function_coefficients = [150.0, 0.1, 0.0];
        let mut capped_states = 0;
        for engine in [prius, parallel] {
            let params = EnergyParams::of_engine(&engine);
            for e in [
                params,
                EnergyParams {
                    sustain_below: None,
                    ..params
                },
            ] {
                let battery = e.battery.unwrap();
                for (power, spin, soc) in [20e3, 60e3, 200e3]
                    .into_iter()
                    .flat_map(|p| [5.0, 30.0, 80.0].map(|w| (p, w)))
                    .flat_map(|(p, w)| [1e-3, 0.05, 0.3].map(|soc| (p, w, soc)))
                {
                    let s = asking(power, spin, soc);
                    let cap = e.drive_cap(&engine, &s, DT);
                    if cap == DriveCap::NONE || cap.torque_scale == 0.0 {
                        continue;
                    }
                    capped_states += 1;
                    let most = battery
                        .step(soc, battery.max_discharge_power(soc), DT)
                        .power;
                    let drawn = e.flow(&engine, &capped(&s, cap)).battery;
                    assert!(
                        drawn <= most && drawn >= most - 1e-9 * most,
                        "{power} W at {spin} rad/s, soc {soc}: {drawn} vs {most} ({cap:?})"
                    );
                }
            }
        }
        assert!(capped_states >= 20, "{capped_states} states capped");
    }
}
