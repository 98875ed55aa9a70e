//! The world as the ray-based devices (`DistanceSensor`, `Radar`, `Lidar`) see it: rays cast
//! through rapier's query pipeline against every collider (ground, ramps, boxes, other cars,
//! robots) except those of the device's own car, the radar targets, and the red of every
//! surface for the infra-red distance sensor. Every ray device measures through this one
//! module.

use proto_geom::nalgebra::{Point3, Vector3};
use rapier3d::prelude::{
    Collider, ColliderHandle, PhysicsWorld, QueryFilter, Ray, RigidBodyHandle,
};

use crate::appearance::GROUND_COLOR;
use crate::geom;

/// Where a ray stopped.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Hit {
    /// Distance from the ray's origin (m).
    pub distance: f64,
    /// The surface's outward unit normal at the hit (world axes).
    pub normal: Vector3<f64>,
    /// The collider hit.
    pub collider: ColliderHandle,
}

/// A solid with a `radarCrossSection` above 0, as a radar sees it.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct RadarEcho {
    /// Its origin (m, world): Webots measures a target at the position of its solid.
    pub position: Point3<f64>,
    /// Its origin's velocity (m/s, world axes).
    pub velocity: Vector3<f64>,
    /// `radarCrossSection` (m², > 0).
    pub cross_section: f64,
    /// The centre of the sphere around its collision box (m, world): a target is a candidate
    /// when this sphere meets the radar's field of view.
    pub centre: Point3<f64>,
    /// That sphere's radius (m).
    pub radius: f64,
    /// Half its length along its own x axis (m): a target nearer than `minRange` by more than
    /// this is not reported.
    pub half_length: f64,
    /// Its rapier bodies: a ray stopping on one of them reached it.
    pub bodies: Vec<RigidBodyHandle>,
    /// Its colliders that belong to no body (a static box's, a ramp's): a ray stopping on
    /// one of them reached it too.
    pub colliders: Vec<ColliderHandle>,
}

/// The red channel (in [0, 1]) of the world's surfaces: their colour's first component
/// (`crate::appearance`), which is what an infra-red distance sensor sees of them.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Reds {
    /// Colliders that belong to no body (static boxes, ramps, road lanes), with their red.
    pub colliders: Vec<(ColliderHandle, f64)>,
    /// Bodies (dynamic boxes, cars, robots), with their red: each of their colliders has it.
    pub bodies: Vec<(RigidBodyHandle, f64)>,
    /// The red of every other collider: the ground.
    pub ground: f64,
}

impl Default for Reds {
    /// Every surface the ground's red.
    fn default() -> Self {
        Reds {
            colliders: Vec::new(),
            bodies: Vec::new(),
            ground: GROUND_COLOR[0],
        }
    }
}

/// The world without one car: what that car's ray devices see after a step.
pub(crate) struct Scene<'a> {
    physics: &'a PhysicsWorld,
    /// The bodies of the car the devices ride on, invisible to them.
    own: Vec<RigidBodyHandle>,
    /// The radar targets other than the car itself: the world's vehicles, then its boxes.
    echoes: Vec<RadarEcho>,
    /// The surfaces' red (left at its default when no infra-red sensor samples: building it
    /// costs a pass over the world's things).
    reds: Reds,
}

impl<'a> Scene<'a> {
    /// The scene of `physics` seen from the car of bodies `own`, with the radar targets
    /// `echoes` (left empty when no radar is enabled: they cost a pass over the vehicles).
    pub(crate) fn new(
        physics: &'a PhysicsWorld,
        own: Vec<RigidBodyHandle>,
        echoes: Vec<RadarEcho>,
    ) -> Self {
        Scene {
            physics,
            own,
            echoes,
            reds: Reds::default(),
        }
    }

    /// The scene with the surfaces' red `reds`.
    pub(crate) fn with_reds(self, reds: Reds) -> Self {
        Scene { reds, ..self }
    }

    /// The red channel (in [0, 1]) of the surface of `collider`.
    pub(crate) fn red(&self, collider: ColliderHandle) -> f64 {
        let reds = &self.reds;
        if let Some((_, r)) = reds.colliders.iter().find(|(c, _)| *c == collider) {
            return *r;
        }
        let parent = self
            .physics
            .colliders
            .get(collider)
            .and_then(Collider::parent);
        parent
            .and_then(|p| reds.bodies.iter().find(|(b, _)| *b == p))
            .map_or(reds.ground, |(_, r)| *r)
    }

    /// The radar targets.
    pub(crate) fn echoes(&self) -> &[RadarEcho] {
        &self.echoes
    }

    /// True if a ray stopping on `collider` reached the target `echo`.
    pub(crate) fn reaches(&self, collider: ColliderHandle, echo: &RadarEcho) -> bool {
        echo.colliders.contains(&collider) || self.belongs(collider, &echo.bodies)
    }

    /// True if `collider` belongs to one of `bodies`.
    pub(crate) fn belongs(&self, collider: ColliderHandle, bodies: &[RigidBodyHandle]) -> bool {
        self.physics
            .colliders
            .get(collider)
            .and_then(Collider::parent)
            .is_some_and(|p| bodies.contains(&p))
    }

    /// The first surface along the ray from `origin` (m, world) in the unit direction `dir`
    /// (world axes) within `max` (m); the own car's colliders are transparent. A ray starting
    /// inside a shape stops at once (distance 0), as a sensor buried in an obstacle reads 0.
    pub(crate) fn cast(&self, origin: &Point3<f64>, dir: &Vector3<f64>, max: f64) -> Option<Hit> {
        if max.is_nan() || max <= 0.0 {
            return None;
        }
        let ray = Ray::new(geom::point(origin), geom::vector(dir));
        let own = &self.own;
        let visible =
            |_: ColliderHandle, c: &Collider| c.parent().is_none_or(|p| !own.contains(&p));
        let (collider, hit) =
            self.physics
                .cast_ray_and_get_normal(&ray, max as f32, true, self.filter(&visible))?;
        Some(Hit {
            distance: f64::from(hit.time_of_impact),
            normal: geom::to_vector(hit.normal),
            collider,
        })
    }

    /// The distance (m) of [`Scene::cast`]'s hit, without its normal: what a lidar's ray
    /// measures, 28,800 times a sample for a 16-layer lidar.
    pub(crate) fn distance(
        &self,
        origin: &Point3<f64>,
        dir: &Vector3<f64>,
        max: f64,
    ) -> Option<f64> {
        if max.is_nan() || max <= 0.0 {
            return None;
        }
        let ray = Ray::new(geom::point(origin), geom::vector(dir));
        let own = &self.own;
        let visible =
            |_: ColliderHandle, c: &Collider| c.parent().is_none_or(|p| !own.contains(&p));
        let (_, toi) = self
            .physics
            .cast_ray(&ray, max as f32, true, self.filter(&visible))?;
        Some(f64::from(toi))
    }

    /// The query filter that makes the own car transparent: rapier's test of one excluded body
    /// (a cast car has one), else the predicate `visible` (a car on joints has five bodies),
    /// which costs a dynamic call and a search per collider the ray's tree walk reaches.
    fn filter<'f>(
        &self,
        visible: &'f dyn Fn(ColliderHandle, &Collider) -> bool,
    ) -> QueryFilter<'f> {
        match self.own.as_slice() {
            [] => QueryFilter::default(),
            [body] => QueryFilter::default().exclude_rigid_body(*body),
            _ => QueryFilter {
                predicate: Some(visible),
                ..QueryFilter::default()
            },
        }
    }
}
