//! The static obstacles a world fixes to the ground: boxes, ramps and cones.

use proto_geom::nalgebra::{Point2, Point3, Vector3};
use proto_geom::plausible;

use crate::error::ParamError;
use crate::geom::ground_rectangle;
use crate::world::Cone;

/// Static geometry of the world, fixed to the ground.
///
/// Every obstacle uses the same contact model as the ground: Coulomb friction `friction` (or the
/// ground's when `None`), no restitution.
#[derive(Debug, Clone, PartialEq)]
pub enum Obstacle {
    /// An axis-aligned box turned by `yaw` about +z.
    Box {
        /// Centre (m, world frame).
        center: Point3<f64>,
        /// Half lengths along the box's own x, y, z (m).
        half_extents: Vector3<f64>,
        /// Heading (rad, counter-clockwise about +z).
        yaw: f64,
        /// Coulomb friction (dimensionless, 0 to 100); `None` = the ground's.
        friction: Option<f64>,
        /// Webots' `radarCrossSection` (m², ≥ 0; 0, the default: radars do not see it).
        radar_cross_section: f64,
    },
    /// A wedge rising from the ground: a rectangle of `length` × `width` whose far edge is
    /// `height` above its near edge, with a vertical back face.
    Ramp {
        /// Centre of the near (low) edge on the ground (m, world x and y).
        start: Point2<f64>,
        /// Direction of climb (rad, counter-clockwise about +z from +x).
        yaw: f64,
        /// Horizontal length along the climb direction (m).
        length: f64,
        /// Width across the climb direction (m).
        width: f64,
        /// Height of the far edge (m).
        height: f64,
        /// Coulomb friction (dimensionless, 0 to 100); `None` = the ground's.
        friction: Option<f64>,
        /// Webots' `radarCrossSection` (m², ≥ 0; 0, the default: radars do not see it).
        radar_cross_section: f64,
    },
    /// A traffic cone standing on its base (rapier's exact cone).
    Cone {
        /// Its place, size and colour.
        cone: Cone,
        /// Coulomb friction (dimensionless, 0 to 100); `None` = the ground's.
        friction: Option<f64>,
        /// Webots' `radarCrossSection` (m², ≥ 0; 0: radars do not see it).
        radar_cross_section: f64,
    },
}

/// The six corners of a ramp's wedge in its own frame (m): x along the climb from the low
/// edge at x = 0 to the vertical back face at x = `length`, y across, z up. In order: the low
/// edge (right, left), the back face's foot (right, left), its top (right, left). The rapier
/// collider and the replay's mesh are both built from them.
pub(crate) fn ramp_corners(length: f64, width: f64, height: f64) -> [[f64; 3]; 6] {
    let (l, w, h) = (length, width / 2.0, height);
    [
        [0.0, -w, 0.0],
        [0.0, w, 0.0],
        [l, -w, 0.0],
        [l, w, 0.0],
        [l, -w, h],
        [l, w, h],
    ]
}

impl Obstacle {
    /// Where the obstacle's own frame stands: its origin (m, world frame; a box's centre, the
    /// middle of a ramp's low edge on the ground, a cone's base centre) and its heading (rad,
    /// counter-clockwise about +z; 0 for a cone, which looks the same at every heading). The
    /// replay's node is placed by it, and the rapier collider of a box or ramp.
    pub fn placement(&self) -> (Point3<f64>, f64) {
        match *self {
            Obstacle::Box { center, yaw, .. } => (center, yaw),
            Obstacle::Ramp { start, yaw, .. } => (Point3::new(start.x, start.y, 0.0), yaw),
            Obstacle::Cone { ref cone, .. } => (cone.base, 0.0),
        }
    }

    /// Its `radarCrossSection` (m², ≥ 0; 0: radars do not see it).
    pub fn radar_cross_section(&self) -> f64 {
        match *self {
            Obstacle::Box {
                radar_cross_section,
                ..
            }
            | Obstacle::Ramp {
                radar_cross_section,
                ..
            }
            | Obstacle::Cone {
                radar_cross_section,
                ..
            } => radar_cross_section,
        }
    }

    /// Its Coulomb friction; `None` = the ground's.
    pub fn friction(&self) -> Option<f64> {
        match *self {
            Obstacle::Box { friction, .. }
            | Obstacle::Ramp { friction, .. }
            | Obstacle::Cone { friction, .. } => friction,
        }
    }

    /// The centre (m, world) and radius (m) of a sphere around it: what a radar's field of
    /// view must meet for it to be a candidate target.
    pub fn bounding_sphere(&self) -> (Point3<f64>, f64) {
        match *self {
            Obstacle::Box {
                center,
                half_extents,
                ..
            } => (center, half_extents.norm()),
            Obstacle::Ramp {
                length,
                width,
                height,
                ..
            } => {
                let (origin, yaw) = self.placement();
                // The wedge's box: x from 0 to `length`, y ±width/2, z from 0 to `height`.
                let local = Vector3::new(length / 2.0, 0.0, height / 2.0);
                let (s, c) = yaw.sin_cos();
                let centre = origin
                    + Vector3::new(
                        c * local.x - s * local.y,
                        s * local.x + c * local.y,
                        local.z,
                    );
                let radius = Vector3::new(length, width, height).norm() / 2.0;
                (centre, radius)
            }
            Obstacle::Cone { ref cone, .. } => (cone.centre(), cone.bounding_radius()),
        }
    }

    /// Half its length along its own x axis (m): a radar target nearer than `minRange` by
    /// more than this is not reported.
    pub fn half_length(&self) -> f64 {
        match *self {
            Obstacle::Box { half_extents, .. } => half_extents.x,
            Obstacle::Ramp { length, .. } => length / 2.0,
            Obstacle::Cone { ref cone, .. } => cone.radius,
        }
    }

    /// The corners of its footprint on the ground (m, world x and y), counter-clockwise; a
    /// cone's is the square around its base.
    pub fn footprint(&self) -> [Point2<f64>; 4] {
        let (origin, yaw) = self.placement();
        let origin = origin.xy();
        match *self {
            Obstacle::Box { half_extents, .. } => ground_rectangle(
                origin,
                yaw,
                [-half_extents.x, half_extents.x],
                half_extents.y,
            ),
            Obstacle::Ramp { length, width, .. } => {
                ground_rectangle(origin, yaw, [0.0, length], width / 2.0)
            }
            Obstacle::Cone { ref cone, .. } => {
                ground_rectangle(origin, 0.0, [-cone.radius, cone.radius], cone.radius)
            }
        }
    }

    pub(super) fn validate(&self) -> Result<(), ParamError> {
        match self {
            Obstacle::Box {
                center,
                half_extents,
                yaw,
                friction,
                radar_cross_section,
            } => {
                ParamError::non_negative("obstacle.box.radarCrossSection", *radar_cross_section)?;
                for c in center.iter() {
                    ParamError::within("obstacle.box.center", *c, plausible::POSITION)?;
                }
                for h in half_extents.iter() {
                    ParamError::within("obstacle.box.half_extents", *h, plausible::LENGTH)?;
                }
                ParamError::finite("obstacle.box.yaw", *yaw)?;
                if let Some(f) = friction {
                    ParamError::friction("obstacle.box.friction", *f)?;
                }
            }
            Obstacle::Ramp {
                start,
                yaw,
                length,
                width,
                height,
                friction,
                radar_cross_section,
            } => {
                ParamError::non_negative("obstacle.ramp.radarCrossSection", *radar_cross_section)?;
                for c in start.iter() {
                    ParamError::within("obstacle.ramp.start", *c, plausible::POSITION)?;
                }
                ParamError::finite("obstacle.ramp.yaw", *yaw)?;
                ParamError::within("obstacle.ramp.length", *length, plausible::LENGTH)?;
                ParamError::within("obstacle.ramp.width", *width, plausible::LENGTH)?;
                ParamError::within("obstacle.ramp.height", *height, plausible::LENGTH)?;
                if let Some(f) = friction {
                    ParamError::friction("obstacle.ramp.friction", *f)?;
                }
            }
            Obstacle::Cone {
                cone,
                friction,
                radar_cross_section,
            } => {
                ParamError::non_negative("obstacle.cone.radarCrossSection", *radar_cross_section)?;
                cone.validate()?;
                if let Some(f) = friction {
                    ParamError::friction("obstacle.cone.friction", *f)?;
                }
            }
        }
        Ok(())
    }
}
