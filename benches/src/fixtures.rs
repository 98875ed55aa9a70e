//! Inputs of the kernel benchmarks: a car geometry, one engine of each type, a sensor frame,
//! a tyre at a combined slip.
//!
//! Every benchmark starts from these, so that the criterion benches and the callgrind harness
//! measure the same work.

use ackermann::{DifferentialRatios, Geometry, GeometryError, PerWheel, Real};
use powertrain::{Engine, EngineParams, EngineType, PowertrainError};
use vehicle_model::{ContactVelocity, MagicFormula, TransientSlip, TyreClass, TyreError};

/// The BMW X5 of Webots' car models: wheelbase 2.995 m, front and rear track 1.628 m, front and
/// rear tyre radius 0.374 m.
///
/// # Errors
/// Never for these constants; [`GeometryError`] is forwarded so that a change of
/// [`Geometry::new`]'s rules shows up as a failed bench setup rather than a panic here.
pub fn bmw_x5<T: Real>() -> Result<Geometry<T>, GeometryError> {
    let f = T::from_f64;
    Geometry::new(f(2.995), f(1.628), f(1.628), f(0.374), f(0.374))
}

/// One engine of `engine_type`, with the parameters of a Webots car that ships that engine:
///
/// * combustion: the `Car` PROTO defaults (150 + 0.1·rpm N·m, 1000 to 4500 rpm);
/// * electric: Tesla Model 3 (639 N·m, 147 kW, up to 25 000 rpm);
/// * parallel hybrid: the PROTO defaults with both parts active;
/// * power-split hybrid: Toyota Prius (350 N·m, 33 kW, split 0.2778 at 3000 rpm).
///
/// # Errors
/// Never for these constants (see [`bmw_x5`]).
pub fn engine<T: Real>(engine_type: EngineType) -> Result<Engine<T>, PowertrainError> {
    let f = T::from_f64;
    let params = match engine_type {
        EngineType::Combustion | EngineType::ParallelHybrid => EngineParams {
            engine_type,
            ..EngineParams::default()
        },
        EngineType::Electric => EngineParams {
            engine_type,
            max_torque: f(639.0),
            max_power: f(147_000.0),
            max_rpm: f(25_000.0),
            ..EngineParams::default()
        },
        EngineType::PowerSplitHybrid => EngineParams {
            engine_type,
            max_torque: f(350.0),
            max_power: f(33_000.0),
            min_rpm: f(1200.0),
            max_rpm: f(6500.0),
            function_coefficients: [f(65.0), f(0.0225), f(-0.000_002_5)],
            hybrid_power_split_ratio: f(0.2778),
            hybrid_power_split_rpm: f(3000.0),
        },
    };
    Engine::new(params)
}

/// The engine speed (rpm) at which [`engine`] torques are benchmarked: 2500 rpm, above
/// `engineMinRPM` of every fixture, so that each model takes its full code path (combustion
/// curve and electric part where the model has them).
pub fn bench_rpm<T: Real>() -> T {
    T::from_f64(2500.0)
}

/// Wheel speeds (rad/s) of a car turning right at about 30 km/h with some wheel slip: every
/// wheel turns at a different speed, so the limited-slip integrators all move.
pub fn turning_wheel_speeds<T: Real>() -> PerWheel<T> {
    let f = T::from_f64;
    PerWheel::new(f(21.3), f(23.9), f(20.6), f(23.1))
}

/// The geometric differential ratios (dimensionless) of [`bmw_x5`] steered 0.2 rad to the
/// right, as Webots computes them after `wbu_driver_set_steering_angle(0.2)`.
///
/// # Errors
/// As [`bmw_x5`].
pub fn turning_ratios<T: Real>() -> Result<DifferentialRatios<T>, GeometryError> {
    Ok(bmw_x5::<T>()?.ackermann_ratios(T::from_f64(0.2)))
}

/// The tyre of the tyre benchmarks: a passenger tyre (radius 0.35 m, nominal load 4 kN) at a
/// braking slip with a slip angle.
#[derive(Debug, Clone, Copy)]
pub struct TyreCase<T> {
    /// The slip-based tyre.
    pub tyre: MagicFormula<T>,
    /// `[κ, tan α]` of the force evaluation: −0.08, 0.05.
    pub slip: [T; 2],
    /// Load (N): 4200.
    pub load: T,
    /// Transient slip the linearisation starts from: κ′ −0.07, tan α′ 0.045.
    pub state: TransientSlip<T>,
    /// Contact velocities of the linearisation (m/s): 20 forward, slip `[1.6, −0.9]`.
    pub velocity: ContactVelocity<T>,
}

/// The [`TyreCase`] in `T`.
///
/// # Errors
/// Never for these constants (see [`bmw_x5`]).
pub fn tyre_case<T: Real>() -> Result<TyreCase<T>, TyreError> {
    let f = T::from_f64;
    Ok(TyreCase {
        tyre: TyreClass::PassengerCar
            .params(f(0.35), f(4000.0))
            .validate()?,
        slip: [f(-0.08), f(0.05)],
        load: f(4200.0),
        state: TransientSlip {
            ratio: f(-0.07),
            angle_tan: f(0.045),
        },
        velocity: ContactVelocity {
            forward: f(20.0),
            slip: [f(1.6), f(-0.9)],
        },
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_engine_fixture_is_valid_and_pulls_at_the_bench_speed() {
        for t in EngineType::ALL {
            let e = engine::<f64>(t).unwrap();
            assert_eq!(e.engine_type(), t);
            assert!(bench_rpm::<f64>() > e.min_rpm());
        }
        // Combustion at 2500 rpm: 150 + 0.1·2500 = 400 N·m.
        let c = engine::<f64>(EngineType::Combustion).unwrap();
        assert!((c.torque(bench_rpm()) - 400.0).abs() < 1e-9);
        // Parallel hybrid: 400 N·m combustion + min(250, 50 000·60/(2π·2500)) = 190.99 N·m.
        let p = engine::<f64>(EngineType::ParallelHybrid).unwrap();
        assert!((p.torque(bench_rpm()) - 590.986).abs() < 1e-3);
    }

    #[test]
    fn turning_ratios_favour_the_outer_wheels() {
        let r = turning_ratios::<f64>().unwrap();
        // Turning right: the right (inner) wheels get less than half of each axle's torque.
        assert!(r.front < 0.5 && r.rear < 0.5);
        // Central ratio: 1 / (1 + cos 0.2) = 0.505 034, whatever the tyre radii.
        assert!((r.central - 1.0 / (1.0 + 0.2_f64.cos())).abs() < 1e-12);
        let w = turning_wheel_speeds::<f32>();
        assert!(w.iter().zip(w.iter().skip(1)).all(|(a, b)| a != b));
    }
}
