//! Regenerative braking blended with the friction brakes: of the brake torque the driver asks
//! for on the driven wheels, the electric machine takes a share, within its torque and power
//! and only above a speed, and the friction brakes the rest. "Series" blending, as the brake
//! controllers of electric and hybrid cars do it: the car slows the same, the machine
//! recovers what it can.

use ackermann::Real;

/// How the brake torque is shared between the machine and the friction brakes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RegenBlend<T> {
    /// The largest share of the driven wheels' brake torque the machine takes
    /// (dimensionless, in [0, 1]; 0 turns regeneration off).
    pub max_share: T,
    /// The largest power the machine takes back (W, ≥ 0), at its wheels.
    pub max_power: T,
    /// The speed below which regeneration fades out linearly to 0 at standstill (m/s, > 0):
    /// the machine's torque at a crawl is not worth its losses, and the friction brakes must
    /// hold the stopped car.
    pub fade_speed: T,
}

/// A brake request split between the machine and the friction brakes (N·m at the wheels).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BrakeSplit<T> {
    /// The machine's braking torque (N·m, ≥ 0) over the driven wheels.
    pub regenerative: T,
    /// What the friction brakes of the driven wheels still give (N·m, ≥ 0).
    pub friction: T,
}

/// The speed regeneration fades out below (m/s): about 7 km/h, where production cars
/// hand the last of a stop to the friction brakes.
const FADE_SPEED: f64 = 2.0;

impl<T: Real> RegenBlend<T> {
    /// The default blend for a machine of `max_power` (W): all of the brake torque while
    /// the machine can take it, up to its power, fading below 2 m/s.
    pub fn of_machine(max_power: T) -> Self {
        RegenBlend {
            max_share: T::ONE,
            max_power,
            fade_speed: T::from_f64(FADE_SPEED),
        }
    }

    /// Splits `brake` (N·m, the driven wheels' total, ≥ 0) at the wheels' rim `speed` (m/s) and
    /// spin `omega` (rad/s), with the machine's largest torque at the wheels `machine_torque`
    /// (N·m): the machine takes `min(share·brake, machine_torque, max_power/ω)` scaled by the
    /// fade, the friction brakes the rest. Non-finite inputs regenerate nothing.
    pub fn split(&self, brake: T, speed: T, omega: T, machine_torque: T) -> BrakeSplit<T> {
        let brake = brake.finite_or(T::ZERO).max(T::ZERO);
        let omega = omega.finite_or(T::ZERO).abs();
        let fade = (speed.finite_or(T::ZERO).abs() / self.fade_speed).min(T::ONE);
        let by_power = if omega > T::ZERO {
            self.max_power / omega
        } else {
            T::ZERO
        };
        let regenerative = (self.max_share * brake)
            .min(machine_torque.finite_or(T::ZERO).max(T::ZERO))
            .min(by_power)
            * fade;
        BrakeSplit {
            regenerative,
            friction: brake - regenerative,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_machine_takes_what_its_torque_power_and_speed_allow_and_friction_the_rest() {
        let blend = RegenBlend::of_machine(50_000.0);
        // Light braking at speed: all regenerative.
        let s = blend.split(500.0, 20.0, 60.0, 3000.0);
        assert_eq!(
            s,
            BrakeSplit {
                regenerative: 500.0,
                friction: 0.0
            }
        );
        // Hard braking: the power limit, 50 kW / 60 rad/s.
        let s = blend.split(5000.0, 20.0, 60.0, 3000.0);
        assert!((s.regenerative - 50_000.0 / 60.0).abs() < 1e-9);
        assert!((s.regenerative + s.friction - 5000.0).abs() < 1e-9);
        // Half the fade speed: half of it.
        let s = blend.split(500.0, 1.0, 3.0, 3000.0);
        assert!((s.regenerative - 250.0).abs() < 1e-9);
        // Standing still: friction alone.
        let s = blend.split(500.0, 0.0, 0.0, 3000.0);
        assert_eq!(s.regenerative, 0.0);
    }
}
