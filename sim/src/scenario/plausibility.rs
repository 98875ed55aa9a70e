//! Notes on worlds whose cars the simulation can run but whose results are not a car's
//! (issue #37): values each within its own range that together leave the physics unable to
//! say anything about the car. They are notes on the run (the CLI's summary, `metrics.json`,
//! a sweep's `notes` column), not errors: the run is what the world asks for, and the note says
//! why its numbers should not be trusted.

use core::f64::consts::TAU;

use ackermann::Wheel;
use vehicle_model::TyreModel;

use crate::vehicle::VehicleSpec;
use crate::world_file::{CarDescription, WorldDescription};

/// Fewest steps per bounce period of the body on its springs for its motion to be the car's.
///
/// The suspension's spring is integrated implicitly (stable at any step), and that damps a
/// motion by itself: an undamped spring sampled `N` times per period keeps
/// `(1 + (2π/N)²)^(−N/2)` of its amplitude over a period, 0.19 at `N = 10`, as much as a car's
/// own dampers take (0.15 at a damping ratio of 0.3). Below 10 steps the body's pitch, roll and
/// bounce, and with them the wheel loads and the tyre forces, are the integrator's.
pub const MIN_STEPS_PER_BOUNCE: f64 = 10.0;

/// The least friction coefficient a car's tyre reaches at its static load on a road of friction
/// 1 (dimensionless), within a slip ratio of 1 and a slip angle of 45°: snow gives about 0.2
/// and ice 0.1 as road frictions, a tyre on dry asphalt about 1. Below this, the tyre's own
/// coefficients (a nominal load or a load sensitivity far from the car's), not the road, take
/// the car's grip away.
pub const MIN_TYRE_FRICTION: f64 = 0.3;

/// The body's share of the weight on one wheel of each axle, `[front, rear]` (kg), from the
/// centre of mass between the axles (the rear axle at x = 0, the front at the wheelbase).
fn corner_masses(spec: &VehicleSpec) -> [f64; 2] {
    let wheelbase = spec.wheels[Wheel::FrontRight].position.x;
    let front = (spec.chassis.center_of_mass.x / wheelbase).clamp(0.0, 1.0);
    [front, 1.0 - front].map(|share| spec.chassis.mass * share / 2.0)
}

/// The shortest bounce period (s) of a car's body on its springs: `2π·√(m/k)` of each axle's
/// corner (its share `m` of the body's weight on one spring of stiffness `k`), the shorter.
/// Infinite for a car without springs. A step longer than a tenth of it
/// ([`MIN_STEPS_PER_BOUNCE`]) leaves the body's motion to the integrator.
pub fn bounce_period(spec: &VehicleSpec) -> f64 {
    let [front, rear] = corner_masses(spec);
    [(front, spec.front_suspension), (rear, spec.rear_suspension)]
        .into_iter()
        .filter(|(m, springs)| *m > 0.0 && springs.stiffness > 0.0)
        .map(|(m, springs)| TAU * (m / springs.stiffness).sqrt())
        .fold(f64::INFINITY, f64::min)
}

/// The notes on every car of `world`, in the order of its cars: a centre of mass outside
/// the body, tyres without grip at the car's load, a time step too long for the body's motion.
/// Every scenario's first result carries them.
pub fn notes(world: &WorldDescription) -> Vec<String> {
    let g = world.config.gravity.norm();
    let dt = world.config.dt();
    world
        .cars
        .iter()
        .flat_map(|car| car_notes(car, g, dt))
        .collect()
}

/// The notes of one car under gravity `g` (m/s²) stepped every `dt` (s).
fn car_notes(car: &CarDescription, g: f64, dt: f64) -> Vec<String> {
    let Ok(spec) = VehicleSpec::from_car_with(&car.params, &car.tyre) else {
        return Vec::new();
    };
    let mut notes = Vec::new();
    let chassis = &spec.chassis;
    let (com, centre, half) = (
        chassis.center_of_mass,
        chassis.box_center,
        chassis.box_half_extents,
    );
    let outside = (0..3).any(|i| (com[i] - centre[i]).abs() > half[i]);
    if outside {
        notes.push(format!(
            "the centre of mass ({:.3}, {:.3}, {:.3}) m of {} lies outside its body (x {:.3} to \
             {:.3}, y {:.3} to {:.3}, z {:.3} to {:.3} m): its weight hangs where no body is, \
             and the results are not a car's",
            com.x,
            com.y,
            com.z,
            car.name,
            centre.x - half.x,
            centre.x + half.x,
            centre.y - half.y,
            centre.y + half.y,
            centre.z - half.z,
            centre.z + half.z,
        ));
    }
    let shortest = bounce_period(&spec);
    let [front_corner, rear_corner] = corner_masses(&spec);
    for (front, corner) in [(true, front_corner), (false, rear_corner)] {
        let wheel = if front {
            Wheel::FrontRight
        } else {
            Wheel::RearRight
        };
        let load = (corner + spec.wheels[wheel].mass) * g;
        if let TyreModel::MagicFormula(tyre) = spec.tyres.of(wheel)
            && load > 0.0
        {
            // The most force within the slips a car reaches: a slip ratio of at most 1 (a
            // locked wheel braking) and a slip angle of at most 45°. A tyre whose curve peaks
            // beyond them never gives its peak friction.
            let peak = tyre.peak_slip(load, 1.0);
            let mu = [
                tyre.force([peak[0].min(1.0), 0.0], load, 1.0)[0],
                tyre.force([0.0, peak[1].min(1.0)], load, 1.0)[1],
            ]
            .map(|f| f.abs() / load);
            let least = mu[0].min(mu[1]);
            if least < MIN_TYRE_FRICTION {
                notes.push(format!(
                    "the {} tyres of {} reach a friction of {least:.2} at most at their static \
                     load of {load:.0} N on a road of friction 1 (a car's tyre about 1): their \
                     coefficients, not the road, take the car's grip away",
                    if front { "front" } else { "rear" },
                    car.name
                ));
            }
        }
    }
    if dt * MIN_STEPS_PER_BOUNCE > shortest {
        notes.push(format!(
            "basicTimeStep {:.0} ms is more than a tenth of the bounce period of {} on its \
             springs ({:.2} s): its body's motion, wheel loads and tyre forces are the \
             integrator's, not the car's (use at most {:.0} ms)",
            dt * 1000.0,
            car.name,
            shortest,
            (shortest / MIN_STEPS_PER_BOUNCE * 1000.0).floor()
        ));
    }
    notes
}
