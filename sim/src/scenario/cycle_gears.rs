//! The cycle driver's gear choice for a car of several forward gears: the rule of UN GTR
//! No. 15 (WLTP), Annex 2, "Gear selection and shift point determination". The regulation
//! writes it for manual transmissions; a car with an automatic one is tested with its own
//! shift logic, which a Webots car does not have (its automatic gearbox,
//! `AutoShiftParams`, is a performance schedule), so every cycle car shifts by the manual
//! rule, the one a regulation defines. Real automatics on their economy schedule often run
//! a gear higher at cruise, so the rule errs toward more fuel, not less.
//! Each step the car takes the highest forward gear in which
//! * the engine turns at least `n_min_drive`: `0.9·n_idle` in second gear,
//!   `n_idle + 0.125·(s − n_idle)` above (Annex 2, §2(k)), `s` being the rated speed where the
//!   engine gives its most power, and below the engine's top speed; and
//! * 90 % of the full-load power at that engine speed covers the power asked for (§3.4 and
//!   §3.5: the 10 % safety margin `SM`);
//!
//! and first gear where no other qualifies (from a standstill, and below idle, where §3.3
//! slips the clutch).
//!
//! A gear is kept at least 2 s (§4(a)), so that one step's throttle does not shift twice. The
//! engine's idle speed is Webots' `engineMinRPM` (the lowest speed its curve is evaluated at)
//! and its full-load curve Webots' `a + b·rpm + c·rpm²`. A performance schedule such as
//! `AutoShiftParams::for_engine` (up at 85 % of the speed range) drives a cycle in first and
//! second gear near 5000 rpm, where the engine's friction is several times the road load's
//! power: no driver of a consumption test shifts that way.

use vehicle_model::{Driver, Gear, RAD_PER_S_PER_RPM};

/// GTR 15 Annex 2 §2(k): `n_min_drive` above second gear is `n_idle` plus this share of the
/// span from idle to the rated speed.
const MIN_DRIVE_SHARE: f64 = 0.125;
/// GTR 15 Annex 2 §2(k): `n_min_drive` in second gear over `n_idle`.
const SECOND_GEAR_MIN: f64 = 0.9;
/// GTR 15 Annex 2 §3.4: the available power is the full-load power less the safety margin
/// `SM` of 10 %.
const AVAILABLE_SHARE: f64 = 0.9;
/// GTR 15 Annex 2 §4(a): a gear is used for at least 2 s (s).
const MIN_DWELL: f64 = 2.0;
/// Points the rated speed is searched over between `engineMinRPM` and `engineMaxRPM`: a step
/// of a few rpm, far below what moves `n_min_drive` (an eighth of the search's step).
const RATED_SEARCH_POINTS: u32 = 1000;

/// The gear rule for one car.
#[derive(Debug, Clone)]
pub(crate) struct GearChoice {
    /// The forward gears' ratios (engine speed over wheel spin), first gear first.
    ratios: Vec<f64>,
    /// Idle speed `n_idle` (rpm): `engineMinRPM`.
    idle: f64,
    /// `n_min_drive` above second gear (rpm).
    min_drive: f64,
    /// The engine's top speed (rpm): `engineMaxRPM`.
    max: f64,
    /// When the engaged gear was chosen (s).
    since: f64,
}

impl GearChoice {
    /// The rule for the car `driver` drives; `None` for a car of fewer than two forward gears
    /// (nothing to choose) or without a combustion engine.
    pub(crate) fn of(driver: &Driver<f64>) -> Option<Self> {
        let engine = driver.powertrain().engine();
        if !engine.params().engine_type.has_combustion() {
            return None;
        }
        let gearbox = driver.powertrain().gearbox();
        let ratios: Vec<f64> = (1..=u8::MAX)
            .map_while(Gear::forward)
            .take_while(|g| gearbox.has(*g))
            .map(|g| gearbox.ratio(g).abs())
            .collect();
        if ratios.len() < 2 {
            return None;
        }
        let (idle, max) = (engine.min_rpm(), engine.max_rpm());
        let power = |rpm: f64| engine.torque(rpm) * rpm;
        let rated = (0..=RATED_SEARCH_POINTS)
            .map(|k| idle + (max - idle) * f64::from(k) / f64::from(RATED_SEARCH_POINTS))
            .fold(
                idle,
                |best, n| if power(n) > power(best) { n } else { best },
            );
        Some(GearChoice {
            ratios,
            idle,
            min_drive: idle + MIN_DRIVE_SHARE * (rated - idle),
            max,
            since: f64::NEG_INFINITY,
        })
    }

    /// The forward gear (1 = first) for the step from `t` (s) of a car in forward gear
    /// `gear` whose engine turns at `rpm` with the `throttle` (in [0, 1]) its driver asks
    /// for, `None` to keep the engaged one.
    pub(crate) fn choose(
        &mut self,
        driver: &Driver<f64>,
        t: f64,
        gear: usize,
        rpm: f64,
        throttle: f64,
    ) -> Option<usize> {
        if t - self.since < MIN_DWELL || gear == 0 || gear > self.ratios.len() {
            return None;
        }
        let engine = driver.powertrain().engine();
        let full_load = |n: f64| engine.torque(n) * n.max(self.idle) * RAD_PER_S_PER_RPM;
        // The power asked for: the throttle's share of the full-load power in the engaged
        // gear (Webots scales the curve's torque by the throttle).
        let asked = throttle.clamp(0.0, 1.0) * full_load(rpm);
        let wheel_rpm = rpm / self.ratios[gear - 1];
        let chosen = (2..=self.ratios.len())
            .rev()
            .find(|&i| {
                let n = wheel_rpm * self.ratios[i - 1];
                let min = if i == 2 {
                    SECOND_GEAR_MIN * self.idle
                } else {
                    self.min_drive
                };
                n >= min && n < self.max && AVAILABLE_SHARE * full_load(n) >= asked
            })
            .unwrap_or(1);
        (chosen != gear).then(|| {
            self.since = t;
            chosen
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use vehicle_model::Model;

    fn driver(model: Model) -> Driver<f64> {
        Driver::new(model.params(), 20).0
    }

    /// The BmwX5's curve `34.11 + 0.136·n − 1.461·10⁻⁵·n²` (N·m) gives the most power where
    /// `f + n·f′ = 0`: `34.11 + 0.272·n − 4.383·10⁻⁵·n² = 0`, at 6328.7 rpm.
    const BMW_X5_RATED: f64 = 6328.7;

    #[test]
    fn n_min_drive_is_an_eighth_of_the_way_from_idle_to_the_rated_speed() {
        let d = driver(Model::BmwX5);
        let g = GearChoice::of(&d).unwrap();
        assert_eq!(g.ratios, vec![12.5, 8.0, 5.35, 4.3, 4.0]);
        assert_eq!((g.idle, g.max), (1000.0, 6500.0));
        // The search's step is 5.5 rpm; an eighth of it moves n_min_drive by 0.7 rpm.
        let expected = 1000.0 + 0.125 * (BMW_X5_RATED - 1000.0);
        assert!((g.min_drive - expected).abs() < 0.7, "{}", g.min_drive);
    }

    #[test]
    fn electric_and_single_gear_cars_have_no_rule() {
        assert!(GearChoice::of(&driver(Model::TeslaModel3)).is_none());
        assert!(GearChoice::of(&driver(Model::CitroenCZero)).is_none());
    }

    #[test]
    fn light_load_takes_the_highest_gear_above_n_min_drive_and_full_load_kicks_down() {
        let d = driver(Model::BmwX5);
        let mut g = GearChoice::of(&d).unwrap();
        // Third gear at 3000 rpm: the wheels turn 3000/5.35 rpm, fifth gear would turn the
        // engine at 2243 rpm, above n_min_drive (1666 rpm), and at a tenth of the throttle
        // its full-load power less 10 % covers the demand.
        assert_eq!(g.choose(&d, 10.0, 3, 3000.0, 0.1), Some(5));
        // Kept at least 2 s, whatever is asked.
        assert_eq!(g.choose(&d, 11.0, 5, 2243.0, 1.0), None);
        // Full throttle in third at 3000 rpm asks the curve's 310.6 N·m there: no gear from
        // third up has 10 % more power at its speed; second (4486 rpm, 350.2 N·m) has.
        let mut g = GearChoice::of(&d).unwrap();
        assert_eq!(g.choose(&d, 10.0, 3, 3000.0, 1.0), Some(2));
        // Below idle in second (second's floor is 0.9·n_idle): first.
        let mut g = GearChoice::of(&d).unwrap();
        assert_eq!(g.choose(&d, 10.0, 2, 850.0, 0.2), Some(1));
        // Already in the chosen gear: nothing to do.
        let mut g = GearChoice::of(&d).unwrap();
        assert_eq!(g.choose(&d, 10.0, 5, 2243.0, 0.1), None);
    }
}
