//! The world as a car's ray devices see it: every other car, dynamic box, static box or
//! ramp and robot with a radar cross-section as a radar echo.

use proto_geom::nalgebra::Vector3;

use super::World;
use crate::body;
use crate::devices::rays::{RadarEcho, Scene};
use crate::error::SimError;
use crate::vehicle::VehicleId;

impl World {
    /// The world as the ray devices of car `own` see it after the last step (its own bodies
    /// transparent), with the other cars, the dynamic boxes, the static boxes and ramps and
    /// the robots of `radarCrossSection` > 0 as radar targets, in that order, when `radar` is
    /// true.
    pub(crate) fn scene(&self, own: VehicleId, radar: bool) -> Result<Scene<'_>, SimError> {
        let echoes = if radar {
            let boxes = self
                .bodies
                .iter()
                .zip(&self.config.bodies)
                .filter(|(_, spec)| spec.radar_cross_section > 0.0)
                .filter_map(|(&h, spec)| {
                    let pose = body::pose(&self.physics, h)?;
                    Some(RadarEcho {
                        position: pose.position,
                        velocity: pose.velocity,
                        cross_section: spec.radar_cross_section,
                        centre: pose.position,
                        radius: spec.size.norm() / 2.0,
                        half_length: spec.size.x / 2.0,
                        bodies: vec![h],
                        colliders: Vec::new(),
                    })
                });
            let robots = self
                .robots
                .iter()
                .filter(|r| r.radar_cross_section() > 0.0)
                .map(|r| {
                    let (p, position) = (r.params(), r.pose().position);
                    // The solid the camera draws: a cylinder of the wheels' radius across the
                    // axle, standing on the ground under the axle.
                    let half = Vector3::new(p.wheel_radius, p.axle_length / 2.0, p.wheel_radius);
                    RadarEcho {
                        position,
                        velocity: r.velocity(&self.physics),
                        cross_section: r.radar_cross_section(),
                        centre: position + Vector3::new(0.0, 0.0, p.wheel_radius),
                        radius: half.norm(),
                        half_length: p.wheel_radius,
                        bodies: r.bodies(),
                        colliders: Vec::new(),
                    }
                });
            let statics = self.obstacles.iter().filter_map(|&(i, h)| {
                let o = self.config.obstacles.get(i)?;
                (o.radar_cross_section() > 0.0).then(|| {
                    let (centre, radius) = o.bounding_sphere();
                    RadarEcho {
                        position: o.placement().0,
                        velocity: Vector3::zeros(),
                        cross_section: o.radar_cross_section(),
                        centre,
                        radius,
                        half_length: o.half_length(),
                        bodies: Vec::new(),
                        colliders: vec![h],
                    }
                })
            });
            self.vehicles
                .iter()
                .filter(|v| v.id() != own && v.radar_cross_section() > 0.0)
                .map(|v| {
                    let (s, chassis) = (v.state(), &v.spec().chassis);
                    RadarEcho {
                        position: s.position,
                        velocity: s.velocity,
                        cross_section: v.radar_cross_section(),
                        centre: s.position + s.orientation * chassis.box_center.coords,
                        radius: chassis.box_half_extents.norm(),
                        half_length: chassis.box_half_extents.x,
                        bodies: v.bodies(),
                        colliders: Vec::new(),
                    }
                })
                .chain(boxes)
                .chain(statics)
                .chain(robots)
                .collect()
        } else {
            Vec::new()
        };
        Ok(Scene::new(
            &self.physics,
            self.vehicle(own)?.bodies(),
            echoes,
        ))
    }
}
