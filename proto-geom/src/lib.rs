#![no_std]
#![forbid(unsafe_code)]
//! Geometry of the Webots vehicle PROTOs: `VehicleWheel` parameters and meshes, and the
//! `AckermannVehicle` wheel and joint layout.
//!
//! * [`WheelParams`]: every `VehicleWheel` field (R2023b defaults), [`WheelParams::validate`]
//!   applies the PROTO's checks and returns a [`ValidWheel`] plus typed [`WheelWarnings`];
//!   [`WheelPreset`] holds the wheels shipped with Webots, looked up by PROTO name.
//! * Meshes without allocation ([`TriMesh`]): [`TyreMesh`] (Webots' exact vertex order and
//!   topology, texture coordinates), [`RimContourMesh`], [`RimCentreMesh`] (Webots' beam
//!   topology with its off-by-one fixed), plus [`CylinderMesh`] and [`BoxMesh`].
//! * [`BoundingCylinder`] and [`MassProperties`]: the collision shape and the mass Webots derives.
//! * [`VehicleLayout`]: wheel frames and joint axes of an `AckermannVehicle`; [`SensorSlots`]
//!   of the shipped models; [`ShippedVehicle`] ties models to their wheels and dimensions.
//! * With the `std` feature (on by default), the `export` module writes Wavefront OBJ and
//!   binary glTF (.glb); with `alloc`, `RenderMesh` gives owned, shading-split meshes.
//!
//! Frame (as everywhere in this workspace): x forward, y left, z up, origin at the rear-axle
//! centre at wheel-centre height; lengths in m, angles in rad. Inside a wheel, the axle is the
//! local x axis.
//!
//! Geometry is [`nalgebra`] (re-exported, so users get the matching version): positions are
//! [`Point3`](nalgebra::Point3), directions and offsets [`Vector3`](nalgebra::Vector3) (unit
//! axes [`UnitVector3`](nalgebra::UnitVector3)), rotations
//! [`UnitQuaternion`](nalgebra::UnitQuaternion) and frames [`Isometry3`](nalgebra::Isometry3)
//! (rotate, then translate), all generic over the crate's `f32`/`f64` scalar. Only the flat
//! vertex buffers that meshes copy into caller memory stay `[T; 3]` arrays.
//!
//! ```
//! use proto_geom::{TriMesh, WheelPreset};
//!
//! let (wheel, warnings) = WheelPreset::BmwX5Wheel.params::<f32>().validate();
//! assert!(warnings.is_empty());
//! let tyre = wheel.tyre();
//! // (2E + 4)(S + 1) vertices and 2S(2E + 3) triangles with S = 36, E = 3.
//! assert_eq!((tyre.vertex_count(), tyre.triangle_count()), (370, 648));
//! let mut positions = [[0.0_f32; 3]; 370];
//! tyre.fill_positions(&mut positions).unwrap();
//! ```

#[cfg(feature = "alloc")]
extern crate alloc;
#[cfg(feature = "std")]
extern crate std;

mod glue;
mod layout;
pub mod mesh;
pub mod plausible;
mod sensors;
mod shipped;
pub mod wheel;

#[cfg(feature = "std")]
pub mod export;
#[cfg(feature = "alloc")]
mod render;

pub use layout::{
    AckermannField, LayoutWarning, LayoutWarnings, VehicleDimensions, VehicleLayout, WheelFrame,
};
pub use mesh::{
    BoxMesh, BufferTooSmall, CylinderMesh, RimCentreMesh, RimContourMesh, TriMesh, TyreMesh,
};
pub use nalgebra;
pub use plausible::Plausible;
pub use sensors::{SensorSlot, SensorSlots};
pub use shipped::ShippedVehicle;
pub use wheel::{
    BoundingCylinder, DEFAULT_WHEEL_DENSITY, MassProperties, PbrAppearance, ValidWheel, WheelField,
    WheelParams, WheelPhysics, WheelPreset, WheelRule, WheelShape, WheelSide, WheelWarning,
    WheelWarnings,
};

#[cfg(feature = "alloc")]
pub use render::{RenderMesh, RenderVertex};

/// The README's examples, compiled and run as doctests.
#[cfg(all(doctest, feature = "std"))]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;
