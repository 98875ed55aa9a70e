//! The cast car (`mounting = "cast"`): its chassis body and its shape-cast wheel contacts (see
//! the [`vehicle`](super) module docs).

use ackermann::Wheel;
use rapier3d::parry::query::ShapeCastOptions;
use rapier3d::prelude::{
    CoefficientCombineRule, ColliderBuilder, Cylinder, MassProperties, Mat3, PhysicsWorld, Pose,
    QueryFilter, RigidBodyBuilder, RigidBodyHandle, Rotation, Vector,
};

use super::contact::{Contact, Spring, Support};
use super::spec::{ChassisSpec, VehicleSpec};
use super::{Frame, MIN_GROUND_COSINE};
use crate::geom::{self, G_CAR_BODY};

/// The rapier side of one car: its single rigid body.
#[derive(Debug, Clone)]
pub(crate) struct Parts {
    pub chassis: RigidBodyHandle,
    /// 1/total mass (1/kg).
    pub inv_mass: f32,
    /// Inverse inertia tensor of the whole car about its centre of mass, in the car frame
    /// (1/(kg·m²)).
    pub inv_inertia: Mat3,
}

/// Mass properties of the whole car in the car frame: the body (`Physics` of the Car: mass,
/// centre of mass, inertia tensor) plus the four wheels as solid cylinders at their unloaded
/// positions (axis along y). The wheels ride with the chassis, so they add to its mass and to
/// its inertia (their spin is a separate coordinate, see the tyre solve).
pub(crate) fn mass_properties(spec: &VehicleSpec) -> MassProperties {
    let c = &spec.chassis;
    let inertia = body_inertia(c);
    let mut total =
        MassProperties::with_inertia_matrix(geom::point(&c.center_of_mass), c.mass as f32, inertia);
    for s in spec.wheels.iter() {
        let transverse = s.transverse_inertia();
        let spin = s.spin_inertia();
        total += MassProperties::new(
            geom::point(&s.position),
            s.mass as f32,
            Vector::new(transverse as f32, spin as f32, transverse as f32),
        );
    }
    total
}

/// The inertia tensor of the car body about its centre of mass (kg·m², car frame).
pub(crate) fn body_inertia(c: &ChassisSpec) -> Mat3 {
    let [xx, yy, zz, xy, xz, yz] = c.inertia.map(|v| v as f32);
    Mat3::from_cols(
        Vector::new(xx, xy, xz),
        Vector::new(xy, yy, yz),
        Vector::new(xz, yz, zz),
    )
}

/// Creates the chassis of `spec` with the car origin at `origin`: one dynamic body with the
/// whole car's mass properties, whose frame is the car frame, and the collision box. Gravity
/// is applied by the tyre solve (the body's gravity scale is 0), so that the suspension and
/// tyres answer it within the same step.
pub(crate) fn build(world: &mut PhysicsWorld, spec: &VehicleSpec, origin: Pose) -> Parts {
    let mass_properties = mass_properties(spec);
    let chassis = world.insert_body(
        RigidBodyBuilder::dynamic()
            .pose(origin)
            .additional_mass_properties(mass_properties)
            .gravity_scale(0.0)
            .can_sleep(false),
    );
    let half = geom::vector(&spec.chassis.box_half_extents);
    world.insert_collider(
        ColliderBuilder::cuboid(half.x, half.y, half.z)
            .translation(geom::point(&spec.chassis.box_center))
            .density(0.0)
            .friction(1.0)
            .friction_combine_rule(CoefficientCombineRule::Multiply)
            .collision_groups(geom::groups(G_CAR_BODY)),
        Some(chassis),
    );
    Parts {
        chassis,
        inv_mass: mass_properties.inv_mass,
        inv_inertia: mass_properties.reconstruct_inverse_inertia_matrix(),
    }
}

/// Wheel `w`'s ground contact and the ground's friction: the tyre (turned by `steer`, spin
/// axis `axis` in world axes) swept down the suspension axis from one radius above its hard
/// point to the hard point (the unloaded spring length); the first static surface it meets,
/// unless too steep to stand on.
pub(crate) fn find_contact(
    world: &PhysicsWorld,
    spec: &VehicleSpec,
    w: Wheel,
    frame: &Frame,
    steer: Rotation,
    axis: Vector,
) -> Option<(Contact, f32)> {
    let s = spec.wheels[w];
    let suspension = if w.is_front() {
        spec.front_suspension
    } else {
        spec.rear_suspension
    };
    let (up, q) = (frame.up, frame.pose.rotation);
    let radius = s.radius as f32;
    let hard_point = frame.pose.transform_point(geom::point(&s.position));
    let start = Pose::from_parts(hard_point + up * radius, q * steer);
    let tyre = Cylinder::new((0.5 * s.width) as f32, radius);
    let options = ShapeCastOptions {
        max_time_of_impact: radius,
        target_distance: 0.0,
        stop_at_penetration: true,
        compute_impact_geometry_on_penetration: true,
    };
    let (collider, hit) =
        world.cast_shape(&start, -up, &tyre, options, QueryFilter::exclude_dynamic())?;
    let n = hit.normal1;
    if n.dot(up) < MIN_GROUND_COSINE {
        return None;
    }
    let compression = radius - hit.time_of_impact;
    let centre = hard_point + up * compression;
    let friction = world.colliders.get(collider).map_or(1.0, |c| c.friction());
    let spring = Spring {
        hardpoint_arm: hard_point - frame.com,
        up,
        compression,
        stiffness: suspension.stiffness as f32,
        damping: suspension.damping as f32,
    };
    let contact = Contact::on_ground(Support::Spring(spring), n, axis, centre, radius, frame.com)?;
    Some((contact, friction))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::vehicle::VehicleSpec;
    use vehicle_model::Model;

    #[test]
    fn wheels_add_their_mass_and_move_the_centre_of_mass() {
        let spec = VehicleSpec::from_car(&Model::BmwX5.params()).unwrap_or_else(|e| panic!("{e}"));
        let mp = mass_properties(&spec);
        // 2000 kg body + 4 × 30 kg wheels.
        assert!((mp.mass() - 2120.0).abs() < 1e-3);
        // x: (2000·x_body + 60·L + 60·0)/2120.
        let x = (2000.0 * spec.chassis.center_of_mass.x + 60.0 * 2.995) / 2120.0;
        assert!(
            (f64::from(mp.local_com.x) - x).abs() < 1e-4,
            "{}",
            mp.local_com.x
        );
    }
}
