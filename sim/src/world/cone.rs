//! A traffic cone standing on its base: the static world object of a `[[cone]]`, its
//! validation and the shapes the physics, the cameras, the replay and the plots draw it with.

use proto_geom::nalgebra::{Point2, Point3, Vector3};
use proto_geom::plausible::{self, Plausible};

use crate::error::ParamError;

/// A traffic cone's default colour (linear RGB, each in [0, 1]): traffic orange.
pub const CONE_COLOR: [f64; 3] = [0.95, 0.35, 0.02];

/// A cone's default height (m): that of the replay's lane-change cones, a small road cone.
pub const DEFAULT_CONE_HEIGHT: f64 = 0.5;

/// A cone's default radius at its base (m): that of the replay's lane-change cones.
pub const DEFAULT_CONE_RADIUS: f64 = 0.15;

/// A cone's default `radarCrossSection` (m², −10 dBsm), an argued value, not a measurement:
/// a hollow plastic shell reflects roughly a tenth of the power a metal one would, and its
/// slanted side sends a radar's specular return up and away instead of back; so a cone is
/// taken an order of magnitude below a pedestrian's ≈ 1 m², and a radar sees it at short range
/// only, as automotive radars see cones.
pub const DEFAULT_CONE_RCS: f64 = 0.1;

/// Plausible cone heights (m): road cones are 0.3 to 1 m high (EN 13422 sizes), a
/// delineator post at most 2 m; 5 cm is a toy.
pub const CONE_HEIGHTS: Plausible = Plausible {
    min: 0.05,
    max: 2.0,
    unit: "m",
};

/// Plausible base radii (m): a cone is at least 1 cm wide and its base at most 1 m across
/// its radius (anything wider is no cone a car meets on a road).
pub const CONE_RADII: Plausible = Plausible {
    min: 0.01,
    max: 1.0,
    unit: "m",
};

/// Flat facets of the polyhedron the cameras and the replay draw a cone with: 24 keep the
/// drawn silhouette within 1 − cos(π/24) ≈ 0.9 % of the true radius. The physics and the rays
/// use rapier's exact cone.
const CONE_FACETS: usize = 24;

/// A right circular cone standing upright, its base on the plane z = `base.z`.
#[derive(Debug, Clone, PartialEq)]
pub struct Cone {
    /// Centre of the base (m, world frame).
    pub base: Point3<f64>,
    /// Height from base to apex (m).
    pub height: f64,
    /// Radius of the base (m).
    pub radius: f64,
    /// Diffuse colour (RGB, each in [0, 1]), as the replay draws it and a camera sees it
    /// unless the world's looks say otherwise.
    pub color: [f64; 3],
}

impl Cone {
    /// A cone of the default size and colour on the ground at `at` (m, world x and y).
    pub fn at(at: Point2<f64>) -> Self {
        Cone {
            base: Point3::new(at.x, at.y, 0.0),
            height: DEFAULT_CONE_HEIGHT,
            radius: DEFAULT_CONE_RADIUS,
            color: CONE_COLOR,
        }
    }

    /// Centre of the cone's axis between base and apex (m, world): where rapier's cone, which
    /// is centred on its axis' middle, is placed.
    pub fn centre(&self) -> Point3<f64> {
        self.base + Vector3::new(0.0, 0.0, self.height / 2.0)
    }

    /// Radius of the smallest sphere about [`Cone::centre`] holding the cone (m).
    pub fn bounding_radius(&self) -> f64 {
        self.radius.hypot(self.height / 2.0)
    }

    /// The corners of a polygon of `n` sides around the base (m, world x and y),
    /// counter-clockwise, its vertices on the circle.
    pub fn base_polygon(&self, n: usize) -> Vec<Point2<f64>> {
        (0..n)
            .map(|k| {
                let a = core::f64::consts::TAU * k as f64 / n as f64;
                Point2::new(
                    self.base.x + self.radius * a.cos(),
                    self.base.y + self.radius * a.sin(),
                )
            })
            .collect()
    }

    /// The cone as a pyramid of [`CONE_FACETS`] sides in a frame at its base's centre: its
    /// corners (the base's ring, then the apex) and faces (the sides, then the base), each
    /// counter-clockwise seen from outside.
    pub(crate) fn polyhedron(&self) -> (Vec<Point3<f64>>, Vec<Vec<usize>>) {
        let n = CONE_FACETS;
        let mut corners: Vec<Point3<f64>> = (0..n)
            .map(|k| {
                let a = core::f64::consts::TAU * k as f64 / n as f64;
                Point3::new(self.radius * a.cos(), self.radius * a.sin(), 0.0)
            })
            .collect();
        corners.push(Point3::new(0.0, 0.0, self.height));
        let mut faces: Vec<Vec<usize>> = (0..n).map(|k| vec![k, (k + 1) % n, n]).collect();
        faces.push((0..n).rev().collect());
        (corners, faces)
    }

    /// Checks the cone: a plausible position, height and radius, colour channels in [0, 1].
    ///
    /// # Errors
    /// A [`ParamError`] naming `obstacle.cone.<field>` and the value.
    pub fn validate(&self) -> Result<(), ParamError> {
        for c in self.base.iter() {
            ParamError::within("obstacle.cone.base", *c, plausible::POSITION)?;
        }
        ParamError::within("obstacle.cone.height", self.height, CONE_HEIGHTS)?;
        ParamError::within("obstacle.cone.radius", self.radius, CONE_RADII)?;
        for &c in &self.color {
            ParamError::check("obstacle.cone.color", c, "in [0, 1]", |c| {
                (0.0..=1.0).contains(&c)
            })?;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn polyhedron_is_closed_and_stands_on_its_base() {
        let cone = Cone {
            base: Point3::new(3.0, -1.0, 0.0),
            height: 0.7,
            radius: 0.2,
            color: CONE_COLOR,
        };
        let (corners, faces) = cone.polyhedron();
        assert_eq!(corners.len(), CONE_FACETS + 1);
        assert_eq!(corners[CONE_FACETS], Point3::new(0.0, 0.0, 0.7));
        // Every ring corner lies on the base circle (to the rounding of cos and sin).
        for c in &corners[..CONE_FACETS] {
            assert!((c.coords.xy().norm() - 0.2).abs() < 1e-15 && c.z == 0.0);
        }
        // Closed: every edge is shared by exactly two faces.
        let mut edges = std::collections::HashMap::new();
        for f in &faces {
            for (i, &a) in f.iter().enumerate() {
                let b = f[(i + 1) % f.len()];
                *edges.entry((a.min(b), a.max(b))).or_insert(0) += 1;
            }
        }
        assert!(edges.values().all(|&n| n == 2));
        assert_eq!(cone.centre(), Point3::new(3.0, -1.0, 0.35));
        assert!((cone.bounding_radius() - 0.2f64.hypot(0.35)).abs() < 1e-15);
    }

    #[test]
    fn implausible_sizes_and_colours_are_refused() {
        let ok = Cone::at(Point2::new(0.0, 0.0));
        assert!(ok.validate().is_ok());
        for (cone, field, value) in [
            (
                Cone {
                    height: 3.0,
                    ..ok.clone()
                },
                "obstacle.cone.height",
                3.0,
            ),
            (
                Cone {
                    radius: 0.0,
                    ..ok.clone()
                },
                "obstacle.cone.radius",
                0.0,
            ),
            (
                Cone {
                    color: [1.5, 0.0, 0.0],
                    ..ok.clone()
                },
                "obstacle.cone.color",
                1.5,
            ),
            (
                Cone {
                    base: Point3::new(f64::NAN, 0.0, 0.0),
                    ..ok.clone()
                },
                "obstacle.cone.base",
                f64::NAN,
            ),
        ] {
            let e = cone.validate().unwrap_err();
            assert_eq!(e.field, field);
            assert!(e.value == value || (e.value.is_nan() && value.is_nan()));
        }
    }
}
