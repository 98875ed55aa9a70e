//! The world description: gravity, time step, ground, static obstacles, dynamic boxes and
//! solver settings, and the outlines of the obstacles and boxes seen from above.

use crate::body::BodySpec;
use crate::error::ParamError;
use crate::geom::DEFAULT_FRICTION;
use crate::road::RoadNetwork;
use proto_geom::nalgebra::Vector3;

mod obstacle;
mod outline;
pub use obstacle::Obstacle;
pub(crate) use obstacle::ramp_corners;
pub use outline::{Outline, OutlineKind};

/// Webots default `WorldInfo.basicTimeStep` used by the car worlds (ms).
pub const DEFAULT_BASIC_TIME_STEP_MS: u32 = 10;

/// Largest gravity a world may have (m/s²): ten times the Earth's, beyond which no car model
/// of this crate is meaningful.
pub(crate) const MAX_GRAVITY: f64 = 100.0;

/// Solver settings handed to rapier.
///
/// They govern what rapier solves: the chassis' collisions with walls, ramps and other cars,
/// and the DifferentialWheels robots in physics mode (bodies, hinge joints, wheel contacts).
/// A car's suspension, tyres and brakes are solved by the car itself and do not depend on
/// them.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct SolverSettings {
    /// rapier solver substeps per rapier step (`IntegrationParameters::num_solver_iterations`,
    /// ≥ 1). Each substep re-evaluates the contacts as body-fixed points, which a spinning
    /// robot wheel breaks (see [`World::last_substeps`](crate::World::last_substeps)).
    pub iterations: usize,
    /// Projected Gauss–Seidel sweeps per substep
    /// (`IntegrationParameters::num_internal_pgs_iterations`, ≥ 1).
    pub pgs_iterations: usize,
    /// Unbiased sweeps per substep, the only ones that solve contact friction
    /// (`IntegrationParameters::num_internal_stabilization_iterations`, ≥ 1).
    pub friction_iterations: usize,
}

impl Default for SolverSettings {
    /// 1 substep, 1 biased sweep, [`DEFAULT_FRICTION_ITERATIONS`] friction sweeps (rapier's
    /// own default uses 4 substeps): a physics-mode DifferentialWheels robot's wheel contacts
    /// stay exact at any wheel speed and a step costs one constraint build. More substeps only
    /// add cost and, on a fast wheel, the body-fixed contact error.
    fn default() -> Self {
        SolverSettings {
            iterations: 1,
            pgs_iterations: 1,
            friction_iterations: DEFAULT_FRICTION_ITERATIONS,
        }
    }
}

/// Friction sweeps per substep of [`SolverSettings::default`].
///
/// A robot wheel's hinge motor and its ground friction act on the same light body (50 g
/// against the robot's 0.6 kg) and the friction is solved after the motor: with one sweep the
/// wheel ends each step where the ground drags it rather than at the motor's target, the motor
/// acts only through the next steps' warm start, and the wheel speed rings around its command
/// (+50 % and −35 % on the e-puck after a speed step) so the wheels turn short of the
/// commanded angle. Measured on the e-puck `square` in physics mode (end distance from the
/// start, end heading error), the sweeps converge: 1 → 56 mm, −0.157 rad; 4 → 18 mm,
/// −0.054 rad; 8 → 11 mm, −0.030 rad; 16 → 6.4 mm, −0.016 rad; 32 → 7.1 mm, −0.018 rad;
/// 64 biased and 64 friction sweeps → 6.7 mm, −0.018 rad. 16 is where more sweeps stop
/// changing the answer (the rest is the wheels' slip when a command steps the speed); a car's chassis contacts (walls, bodies) only get more accurate from them, at a
/// cost proportional to the number of contacts, which is small.
pub const DEFAULT_FRICTION_ITERATIONS: usize = 16;

/// Everything that defines a world before any vehicle is added.
///
/// ```
/// use sim::WorldConfig;
/// use sim::nalgebra::Vector3;
/// let cfg = WorldConfig::default();
/// assert_eq!(cfg.basic_time_step_ms, 10);
/// assert_eq!(cfg.gravity, Vector3::new(0.0, 0.0, -9.81));
/// assert!(cfg.validate().is_ok());
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct WorldConfig {
    /// Gravity (m/s², world frame, z up). Webots: `WorldInfo.gravity` (9.81 downward).
    pub gravity: Vector3<f64>,
    /// The fixed physics step (ms, ≥ 1). Webots: `WorldInfo.basicTimeStep`.
    pub basic_time_step_ms: u32,
    /// Coulomb friction between the ground (and obstacles without their own) and anything on it
    /// (dimensionless, 0 to 100: [`proto_geom::plausible::FRICTION`]). Webots:
    /// `ContactProperties.coulombFriction` (default 1).
    pub ground_friction: f64,
    /// Static boxes, ramps and traffic cones.
    pub obstacles: Vec<Obstacle>,
    /// Dynamic boxes, in the order [`World::bodies`](crate::World::bodies) reports them.
    pub bodies: Vec<BodySpec>,
    /// Solver settings.
    pub solver: SolverSettings,
    /// The roads on the ground (none by default), validated when the world is built
    /// ([`RoadNetwork::validate`]).
    pub roads: RoadNetwork,
    /// The wind (m/s, world frame; calm by default): the air's velocity, which the cars'
    /// aerodynamic forces ([`VehicleSpec::aero`](crate::VehicleSpec::aero)) are relative
    /// to. At most 70 m/s (a category 5 hurricane). Webots has no wind.
    pub wind: Vector3<f64>,
}

/// The strongest wind accepted (m/s): a category 5 hurricane's sustained wind starts at about
/// 70 m/s (Saffir-Simpson scale); no road test runs in more.
pub(crate) const MAX_WIND: f64 = 70.0;

impl Default for WorldConfig {
    fn default() -> Self {
        WorldConfig {
            gravity: Vector3::new(0.0, 0.0, -9.81),
            basic_time_step_ms: DEFAULT_BASIC_TIME_STEP_MS,
            ground_friction: DEFAULT_FRICTION,
            obstacles: Vec::new(),
            bodies: Vec::new(),
            solver: SolverSettings::default(),
            roads: RoadNetwork::default(),
            wind: Vector3::zeros(),
        }
    }
}

impl WorldConfig {
    /// The step length (s).
    pub fn dt(&self) -> f64 {
        f64::from(self.basic_time_step_ms) / 1000.0
    }

    /// Checks every field: finite gravity, a step of 1 ms to 1 s, a friction from 0 to 100
    /// ([`proto_geom::plausible::FRICTION`]), valid
    /// obstacles and dynamic boxes and 1 to 64 iterations of each solver kind.
    pub fn validate(&self) -> Result<(), ParamError> {
        for &g in self.gravity.iter() {
            ParamError::finite("gravity", g)?;
        }
        let gz = self.gravity.z;
        ParamError::check(
            "gravity",
            self.gravity.norm(),
            "at most 100 m/s² and pointing down (z ≤ 0)",
            |g| g <= MAX_GRAVITY && gz <= 0.0,
        )?;
        ParamError::check(
            "basicTimeStep",
            f64::from(self.basic_time_step_ms),
            "between 1 and 1000 ms",
            |v| (1.0..=1000.0).contains(&v),
        )?;
        ParamError::friction("ground.friction", self.ground_friction)?;
        for &w in self.wind.iter() {
            ParamError::finite("wind", w)?;
        }
        ParamError::check("wind", self.wind.norm(), "at most 70 m/s in speed", |w| {
            w <= MAX_WIND
        })?;
        for o in &self.obstacles {
            o.validate()?;
        }
        for b in &self.bodies {
            b.validate()?;
        }
        let s = &self.solver;
        for (field, n) in [
            ("solver.iterations", s.iterations),
            ("solver.pgs_iterations", s.pgs_iterations),
            ("solver.friction_iterations", s.friction_iterations),
        ] {
            ParamError::check(field, n as f64, "between 1 and 64", |v| {
                (1.0..=64.0).contains(&v)
            })?;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::BodySpec;
    use proto_geom::nalgebra::{Point2, Point3};

    #[test]
    fn rejects_bad_fields() {
        let mut c = WorldConfig {
            basic_time_step_ms: 0,
            ..WorldConfig::default()
        };
        assert_eq!(c.validate().unwrap_err().field, "basicTimeStep");
        c.basic_time_step_ms = 16;
        c.ground_friction = f64::NAN;
        assert_eq!(c.validate().unwrap_err().field, "ground.friction");
        c.ground_friction = 0.8;
        c.obstacles.push(Obstacle::Ramp {
            start: Point2::origin(),
            yaw: 0.0,
            length: 5.0,
            width: 3.0,
            height: -1.0,
            friction: None,
            radar_cross_section: 0.0,
        });
        let e = c.validate().unwrap_err();
        assert_eq!((e.field, e.value), ("obstacle.ramp.height", -1.0));
        assert!((c.dt() - 0.016).abs() < 1e-15);
        c.obstacles.clear();
        c.solver.friction_iterations = 0;
        let e = c.validate().unwrap_err();
        assert_eq!((e.field, e.value), ("solver.friction_iterations", 0.0));
        c.solver.friction_iterations = 16;
        c.solver.pgs_iterations = 65;
        let e = c.validate().unwrap_err();
        assert_eq!((e.field, e.value), ("solver.pgs_iterations", 65.0));
    }

    #[test]
    fn obstacles_stand_where_their_fields_say() {
        // A ramp's frame is its low edge's middle on the ground; its footprint runs `length`
        // along its heading (a quarter turn: along +y) and `width` across.
        let ramp = Obstacle::Ramp {
            start: Point2::new(5.0, 1.0),
            yaw: core::f64::consts::FRAC_PI_2,
            length: 10.0,
            width: 4.0,
            height: 1.0,
            friction: Some(0.5),
            radar_cross_section: 0.0,
        };
        assert_eq!(
            ramp.placement(),
            (Point3::new(5.0, 1.0, 0.0), core::f64::consts::FRAC_PI_2)
        );
        assert_eq!(ramp.friction(), Some(0.5));
        let corners = ramp.footprint().map(|p| [p.x, p.y]);
        let expected = [[7.0, 1.0], [7.0, 11.0], [3.0, 11.0], [3.0, 1.0]];
        for (c, e) in corners.iter().zip(expected) {
            // cos(π/2) is 6e-17, not 0.
            assert!(
                (c[0] - e[0]).abs() < 1e-12 && (c[1] - e[1]).abs() < 1e-12,
                "{corners:?}"
            );
        }
        // A box's frame is its centre.
        let wall = Obstacle::Box {
            center: Point3::new(1.0, 2.0, 3.0),
            half_extents: Vector3::new(0.5, 1.0, 3.0),
            yaw: 0.0,
            friction: None,
            radar_cross_section: 0.0,
        };
        assert_eq!(wall.placement(), (Point3::new(1.0, 2.0, 3.0), 0.0));
        assert_eq!(wall.friction(), None);
        let xy = wall.footprint().map(|p| [p.x, p.y]);
        assert_eq!(xy, [[0.5, 1.0], [1.5, 1.0], [1.5, 3.0], [0.5, 3.0]]);
    }

    #[test]
    fn outlines_of_boxes_ramps_and_bodies() {
        let config = WorldConfig {
            obstacles: vec![
                Obstacle::Box {
                    center: Point3::new(10.0, 5.0, 0.5),
                    half_extents: Vector3::new(1.0, 2.0, 0.5),
                    yaw: core::f64::consts::FRAC_PI_2,
                    friction: None,
                    radar_cross_section: 0.0,
                },
                Obstacle::Ramp {
                    start: Point2::origin(),
                    yaw: 0.0,
                    length: 10.0,
                    width: 4.0,
                    height: 1.0,
                    friction: None,
                    radar_cross_section: 0.0,
                },
            ],
            bodies: vec![BodySpec {
                center: Point3::new(3.0, 0.0, 0.5),
                size: Vector3::repeat(1.0),
                yaw: 0.0,
                mass: 10.0,
                friction: None,
                radar_cross_section: 0.0,
            }],
            ..WorldConfig::default()
        };
        let o = Outline::of_world(&config);
        let kinds: Vec<OutlineKind> = o.iter().map(|o| o.kind).collect();
        assert_eq!(
            kinds,
            [OutlineKind::Box, OutlineKind::Ramp, OutlineKind::Body]
        );
        // The box turned a quarter turn: its 2 m (x) by 4 m (y) footprint spans 4 m in x.
        let xs: Vec<f64> = o[0].points.iter().map(|p| p[0]).collect();
        let span = xs.iter().copied().fold(f64::MIN, f64::max)
            - xs.iter().copied().fold(f64::MAX, f64::min);
        assert!((span - 4.0).abs() < 1e-12, "{xs:?}");
        assert_eq!(
            o[1].points,
            [[0.0, -2.0], [10.0, -2.0], [10.0, 2.0], [0.0, 2.0]]
        );
    }
}
