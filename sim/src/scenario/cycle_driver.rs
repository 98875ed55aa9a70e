//! The built-in drive-cycle driver: pedals from the trace's acceleration (feedforward) and
//! the speed error (proportional and integral feedback), throttle or brake by the sign of the
//! acceleration asked for; and the meter of the time spent outside the tolerance band.

use super::cycle_trace::Trace;

/// Proportional gain of the speed error (1/s): an error of 1 m/s asks for 1.5 m/s², closing
/// it in about 0.7 s, well inside the band's 1 s window.
const KP: f64 = 1.5;
/// Integral gain (1/s²): learns the road load and grade the feedforward does not know, in a
/// few seconds of cruise.
const KI: f64 = 0.3;
/// Bound of the integral term (m/s²): several times a car's road load at 100 km/h
/// (0.2–0.4 m/s²), so that a long saturation does not wind it up.
const INTEGRAL_LIMIT: f64 = 1.5;
/// Brake intensity that holds the car while the trace stands still (dimensionless).
const HOLD_BRAKE: f64 = 0.3;
/// Below this trace speed (m/s) the trace is at rest.
const AT_REST: f64 = 0.05;
/// Below this car speed (m/s), with the trace at rest, the car is held by the brake: the
/// end of a stop, where the trace's last second reaches 0 and the car is a step behind.
const HOLD_BELOW: f64 = 0.55;

/// What the driver pushes (dimensionless, each in [0, 1]).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Pedals {
    /// Throttle (`wbu_driver_set_throttle`).
    pub throttle: f64,
    /// Brake intensity (`wbu_driver_set_brake_intensity`).
    pub brake: f64,
}

/// A car's pedal authority the driver is tuned to.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PedalAuthority {
    /// Acceleration at full throttle (m/s², > 0), e.g. 27.8 m/s over `time0To100`.
    pub full_throttle: f64,
    /// Deceleration at full brake (m/s², > 0), the brakes' force over the mass limited by
    /// the grip.
    pub full_brake: f64,
}

/// A pedal authority that is not a finite acceleration > 0.
#[derive(Debug, Clone, Copy, PartialEq, thiserror::Error)]
#[error("{name} = {value} m/s²: the pedal authority must be finite and > 0")]
pub struct AuthorityError {
    /// Which authority.
    pub name: &'static str,
    /// Its value (m/s²).
    pub value: f64,
}

/// Drives a car along a [`Trace`].
#[derive(Debug, Clone)]
pub struct CycleDriver {
    trace: Trace,
    authority: PedalAuthority,
    /// Integral of the speed error times [`KI`] (m/s²).
    integral: f64,
}

impl CycleDriver {
    /// A driver of `trace` for a car of `authority`.
    ///
    /// # Errors
    /// An [`AuthorityError`] naming an authority that is not finite and > 0.
    pub fn new(trace: Trace, authority: PedalAuthority) -> Result<Self, AuthorityError> {
        for (name, value) in [
            ("full_throttle", authority.full_throttle),
            ("full_brake", authority.full_brake),
        ] {
            if !(value.is_finite() && value > 0.0) {
                return Err(AuthorityError { name, value });
            }
        }
        Ok(CycleDriver {
            trace,
            authority,
            integral: 0.0,
        })
    }

    /// The trace driven.
    pub fn trace(&self) -> &Trace {
        &self.trace
    }

    /// The pedals for the step from `t` to `t + dt` (s) of a car at `speed` (m/s): aimed at
    /// the trace at the step's end, since they act over the step. `mass_factor`
    /// (dimensionless, ≥ 1) is the car's effective mass in its engaged gear over the one its
    /// [`PedalAuthority`] is for: the engine's inertia through the gear makes every pedal
    /// move the car that much less (Wong's rotating-mass factor; `vehicle_model::Driveline`),
    /// so the pedals are pushed that much more. A factor that is not finite and ≥ 1 counts
    /// as 1. `full_throttle` (m/s², of the same mass as the authority) replaces the
    /// [`PedalAuthority::full_throttle`] for this step where the caller knows what full
    /// throttle gives now (a combustion car: its engine's torque at its speed through the
    /// engaged gear); `None`, or a value that is not finite and > 0, keeps the authority's.
    pub fn pedals(
        &mut self,
        t: f64,
        speed: f64,
        dt: f64,
        mass_factor: f64,
        full_throttle: Option<f64>,
    ) -> Pedals {
        let next = t + dt;
        let target = self.trace.speed(next);
        if target < AT_REST && self.trace.acceleration(next) <= 0.0 && speed < HOLD_BELOW {
            // At rest: held by the brake; the integral keeps what it learnt of the road.
            return Pedals {
                throttle: 0.0,
                brake: HOLD_BRAKE,
            };
        }
        let k = if mass_factor.is_finite() && mass_factor >= 1.0 {
            mass_factor
        } else {
            1.0
        };
        let throttle_authority = full_throttle
            .filter(|a| a.is_finite() && *a > 0.0)
            .unwrap_or(self.authority.full_throttle);
        let (full_throttle, full_brake) = (throttle_authority / k, self.authority.full_brake / k);
        let error = target - speed;
        let feedforward = self.trace.acceleration(next);
        let unbounded = feedforward + KP * error + self.integral;
        let asked = unbounded.clamp(-full_brake, full_throttle);
        // Anti-windup: the integral moves only while the pedals are not saturated against it.
        if unbounded == asked || (unbounded > asked) != (error > 0.0) {
            self.integral =
                (self.integral + KI * error * dt).clamp(-INTEGRAL_LIMIT, INTEGRAL_LIMIT);
        }
        if asked >= 0.0 {
            Pedals {
                throttle: asked / full_throttle,
                brake: 0.0,
            }
        } else {
            Pedals {
                throttle: 0.0,
                brake: -asked / full_brake,
            }
        }
    }
}

/// How closely a run followed a trace: time outside the band, longest excursion, largest
/// speed error.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct BandMeter {
    /// Time outside the band (s).
    pub outside: f64,
    /// Longest single excursion outside the band (s).
    pub longest: f64,
    /// Largest |speed − trace speed| (m/s).
    pub max_error: f64,
    /// The excursion under way (s).
    current: f64,
}

impl BandMeter {
    /// Counts the step of `dt` s ending at `t` s, the car at `speed` (m/s), against the band
    /// of `trace` with `window` s and `tolerance` m/s.
    pub fn sample(
        &mut self,
        trace: &Trace,
        t: f64,
        speed: f64,
        dt: f64,
        window: f64,
        tolerance: f64,
    ) {
        let (lo, hi) = trace.band(t, window, tolerance);
        self.max_error = self.max_error.max((speed - trace.speed(t)).abs());
        // Where the band reaches 0 the car is at rest: a creep of mm/s backwards on the
        // holding brake is no miss.
        let below = lo > 0.0 && speed < lo;
        if below || speed > hi {
            self.outside += dt;
            self.current += dt;
            self.longest = self.longest.max(self.current);
        } else {
            self.current = 0.0;
        }
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]
    use super::*;

    const AUTHORITY: PedalAuthority = PedalAuthority {
        full_throttle: 3.0,
        full_brake: 8.0,
    };

    /// The throttle is the acceleration asked for over what full throttle gives: the
    /// authority's, or the one the caller knows for this step.
    #[test]
    fn a_known_full_throttle_acceleration_replaces_the_authority_s() {
        let trace = Trace::new((0..=20).map(f64::from).collect()).unwrap();
        let mut d = CycleDriver::new(trace.clone(), AUTHORITY).unwrap();
        // At t = 5 s on a trace accelerating at 1 m/s², 0.5 m/s behind: 1 + 1.5·0.5 = 1.75
        // m/s² asked, before the integral moves.
        let asked = 1.0 + KP * 0.5;
        let p = d.pedals(4.99, 4.5, 0.01, 1.0, None);
        assert!(
            (p.throttle - asked / AUTHORITY.full_throttle).abs() < 1e-9,
            "{p:?}"
        );
        let mut d = CycleDriver::new(trace.clone(), AUTHORITY).unwrap();
        let p = d.pedals(4.99, 4.5, 0.01, 1.0, Some(2.0));
        assert!((p.throttle - asked / 2.0).abs() < 1e-9, "{p:?}");
        // A top gear's 0.7 m/s² saturates the pedal; a bad value keeps the authority.
        let mut d = CycleDriver::new(trace.clone(), AUTHORITY).unwrap();
        assert_eq!(d.pedals(4.99, 4.5, 0.01, 1.0, Some(0.7)).throttle, 1.0);
        for bad in [f64::NAN, 0.0, -1.0, f64::INFINITY] {
            let mut d = CycleDriver::new(trace.clone(), AUTHORITY).unwrap();
            let p = d.pedals(4.99, 4.5, 0.01, 1.0, Some(bad));
            assert!(
                (p.throttle - asked / AUTHORITY.full_throttle).abs() < 1e-9,
                "{bad}"
            );
        }
    }

    /// A point mass with a road load of 0.2 m/s² follows a ramp to 20 m/s and back within a
    /// few cm/s: the integral learns the road load the feedforward does not know.
    #[test]
    fn a_point_mass_follows_a_ramp() {
        let speeds: Vec<f64> = (0..=60)
            .map(|s| match s {
                0..=4 => 0.0,
                5..=24 => f64::from(s - 4),
                25..=44 => 20.0,
                _ => (20.0 - 1.25 * f64::from(s - 44)).max(0.0),
            })
            .collect();
        let trace = Trace::new(speeds).unwrap();
        let mut d = CycleDriver::new(trace.clone(), AUTHORITY).unwrap();
        let mut meter = BandMeter::default();
        let (dt, mut v) = (0.01, 0.0_f64);
        for i in 0..6000 {
            let t = f64::from(i) * dt;
            let p = d.pedals(t, v, dt, 1.0, None);
            let drag = if v > 0.0 { 0.2 } else { 0.0 };
            let a = p.throttle * AUTHORITY.full_throttle - p.brake * AUTHORITY.full_brake - drag;
            v = (v + a * dt).max(0.0);
            meter.sample(&trace, t + dt, v, dt, 1.0, 0.894);
        }
        assert_eq!(meter.outside, 0.0, "{meter:?}");
        assert!(meter.max_error < 0.5, "{meter:?}");
    }

    #[test]
    fn bad_authority_is_refused() {
        let t = Trace::new(vec![0.0, 1.0]).unwrap();
        let bad = PedalAuthority {
            full_throttle: f64::NAN,
            ..AUTHORITY
        };
        let e = CycleDriver::new(t, bad).unwrap_err();
        assert_eq!(e.name, "full_throttle");
    }
}
