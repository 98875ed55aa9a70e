//! The replay's glTF cameras: a chase camera behind and above each car, riding with it, and an
//! overview camera that frames the whole run, so that any glTF viewer can follow a car or show
//! everything without being told where to look.

use proto_geom::export::{Camera, ChassisBox, Scene};
use proto_geom::nalgebra::Point3;

use super::shapes::Rect;

/// Vertical field of view of every camera (rad): 40°, a normal lens; a viewer wider than high
/// sees more sideways, never less.
pub const FIELD_OF_VIEW: f64 = 0.7;
/// How far behind the body's rear the chase camera rides, in body lengths.
pub const CHASE_BEHIND: f64 = 1.1;
/// How far above the roof the chase camera rides, in body heights.
pub const CHASE_ABOVE: f64 = 0.6;
/// Nearest distance a chase camera draws (m): closer than the body's rear ever is.
const CHASE_NEAR: f64 = 0.1;
/// How far the overview camera looks down (rad from the horizontal): 50°, steep enough to
/// see lane changes, shallow enough to read heights.
pub const OVERVIEW_PITCH: f64 = 0.87;

/// The chase camera's eye and target (m, car frame): behind and above the body, looking at
/// its centre.
pub(crate) fn chase_eye_target(body: &ChassisBox<f64>) -> (Point3<f64>, Point3<f64>) {
    let (c, s) = (body.centre, body.size);
    let eye = Point3::new(
        c.x - s.x / 2.0 - CHASE_BEHIND * s.x,
        0.0,
        c.z + s.z / 2.0 + CHASE_ABOVE * s.z,
    );
    (eye, c)
}

/// Adds the chase camera `chase_camera` of a car whose root node is `car` and whose body is
/// `body`, drawing up to `far` (m) away; `None` for a body of no size (nothing to look at).
pub(crate) fn add_chase(
    scene: &mut Scene,
    car: usize,
    body: &ChassisBox<f64>,
    far: f64,
) -> Option<usize> {
    let (eye, target) = chase_eye_target(body);
    let camera = Camera::perspective("chase", FIELD_OF_VIEW, CHASE_NEAR, far.max(1.0)).ok()?;
    scene
        .add_camera(Some(car), "chase_camera", eye, target, camera)
        .ok()
}

/// The overview camera's eye and target (m, world frame) for the ground rectangle `rect` the
/// run covers: looking at its centre, [`OVERVIEW_PITCH`] down, from the side of its longer
/// edge (−y for a run along x, +x for one along y), just far enough for the sphere around
/// the rectangle to fit the vertical field of view.
pub(crate) fn overview_eye_target(rect: Rect) -> (Point3<f64>, Point3<f64>, f64) {
    let centre = Point3::new((rect[0] + rect[2]) / 2.0, (rect[1] + rect[3]) / 2.0, 0.0);
    let (dx, dy) = (rect[2] - rect[0], rect[3] - rect[1]);
    let radius = dx.hypot(dy) / 2.0;
    let distance = radius / (FIELD_OF_VIEW / 2.0).sin();
    let (h, v) = (
        distance * OVERVIEW_PITCH.cos(),
        distance * OVERVIEW_PITCH.sin(),
    );
    let eye = if dx >= dy {
        Point3::new(centre.x, centre.y - h, v)
    } else {
        Point3::new(centre.x + h, centre.y, v)
    };
    (eye, centre, radius)
}

/// Adds the overview camera `overview_camera` under `world` for the ground rectangle `rect`
/// (m); `None` for an empty rectangle.
pub(crate) fn add_overview(scene: &mut Scene, world: usize, rect: Rect) -> Option<usize> {
    let (eye, target, radius) = overview_eye_target(rect);
    let distance = (target - eye).norm();
    // Everything lies within `radius` of the target: the clipping planes bracket it.
    let camera = Camera::perspective(
        "overview",
        FIELD_OF_VIEW,
        0.5 * (distance - radius),
        1.01 * (distance + radius),
    )
    .ok()?;
    scene
        .add_camera(Some(world), "overview_camera", eye, target, camera)
        .ok()
}
