//! The fields of the Webots `VehicleWheel` PROTO, as plain data.

use ackermann::{Real, Wheel};

/// Which side of the vehicle a wheel is mounted on (Webots field `wheelSide`).
///
/// Webots: `wheelSide FALSE` (the default) for right wheels, `TRUE` for left wheels. A left
/// wheel's *tyre* mesh is rotated by π about the wheel's local z axis (so the tread pattern runs
/// the same way on both sides); the rim and the bounding cylinder are not rotated.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum WheelSide {
    /// `wheelSide FALSE`: right-hand wheel (the default).
    #[default]
    Right,
    /// `wheelSide TRUE`: left-hand wheel.
    Left,
}

impl WheelSide {
    /// The side of the slot `wheel` (FR/RR → right, FL/RL → left), as set by every shipped model.
    #[inline]
    pub const fn of(wheel: Wheel) -> Self {
        if wheel.is_right() {
            WheelSide::Right
        } else {
            WheelSide::Left
        }
    }

    /// From the Webots `wheelSide` boolean.
    #[inline]
    pub const fn from_webots(wheel_side: bool) -> Self {
        if wheel_side {
            WheelSide::Left
        } else {
            WheelSide::Right
        }
    }

    /// The Webots `wheelSide` boolean (`true` for left).
    #[inline]
    pub const fn webots_value(self) -> bool {
        matches!(self, WheelSide::Left)
    }
}

/// The density of Webots' default `Physics {}` node (kg/m³): a wheel whose model gives it no
/// mass weighs its bounding cylinder of water.
pub const DEFAULT_WHEEL_DENSITY: f64 = 1000.0;

/// The wheel's `Physics` node (Webots field `physics`).
///
/// Webots derives a wheel's mass and inertia from its bounding object when the `Physics` node
/// gives no inertia matrix; for a VehicleWheel that is the bounding cylinder
/// (radius `tireRadius`, height `thickness`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum WheelPhysics<T> {
    /// `physics NULL`: the wheel has no mass of its own (the shipped wheel PROTOs default to this;
    /// the car PROTOs then give each wheel a `Physics` node).
    None,
    /// `Physics { density d mass -1 }`: uniform density `d` (kg/m³), mass = `d` × the bounding
    /// cylinder volume `π·tireRadius²·thickness`. The Webots default `Physics {}` is
    /// `Density(1000)`.
    Density(T),
    /// `Physics { density -1 mass m }`: total mass `m` (kg), uniformly spread over the bounding
    /// cylinder.
    Mass(T),
}

impl<T: Real> WheelPhysics<T> {
    /// The Webots default `Physics {}`: density [`DEFAULT_WHEEL_DENSITY`] (1000 kg/m³), mass
    /// −1 (derived).
    #[inline]
    pub fn webots_default() -> Self {
        WheelPhysics::Density(T::from_f64(DEFAULT_WHEEL_DENSITY))
    }
}

impl<T: Real> Default for WheelPhysics<T> {
    /// `Physics {}` (density 1000 kg/m³), the `VehicleWheel` default.
    fn default() -> Self {
        Self::webots_default()
    }
}

/// A physically based appearance (the subset of Webots `PBRAppearance` this crate uses for
/// export; textures are not represented).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PbrAppearance<T> {
    /// Linear RGB base colour, each in [0, 1] (Webots `baseColor`).
    pub base_color: [T; 3],
    /// Roughness in [0, 1] (Webots `roughness`).
    pub roughness: T,
    /// Metalness in [0, 1] (Webots `metalness`).
    pub metalness: T,
}

impl<T: Real> PbrAppearance<T> {
    /// Builds from a base colour, a roughness and a metalness (all in [0, 1]).
    #[inline]
    pub fn new(base_color: [f64; 3], roughness: f64, metalness: f64) -> Self {
        PbrAppearance {
            base_color: base_color.map(T::from_f64),
            roughness: T::from_f64(roughness),
            metalness: T::from_f64(metalness),
        }
    }

    /// Webots `GenericTireAppearance {}` (metalness 0, roughness 0.8). Its colour comes from a
    /// tyre texture, which is not represented: the base colour here is a dark grey standing in
    /// for the texture's average.
    #[inline]
    pub fn generic_tire() -> Self {
        Self::new([0.05, 0.05, 0.05], 0.8, 0.0)
    }

    /// Webots `PBRAppearance { roughness 0.4 }`, the `VehicleWheel` rim default (base colour
    /// white, metalness 1).
    #[inline]
    pub fn default_rim() -> Self {
        Self::new([1.0, 1.0, 1.0], 0.4, 1.0)
    }

    /// Webots `Appearance { material Material {} }` (the 2014 `AutomobileWheel` default),
    /// approximated as a non-metallic rough surface of the VRML default diffuse colour 0.8.
    #[inline]
    pub fn vrml_default() -> Self {
        Self::new([0.8, 0.8, 0.8], 1.0, 0.0)
    }
}

/// What the wheel really is in Webots (not a Webots field).
///
/// Most shipped wheels are `VehicleWheel`s, whose meshes this crate reproduces. A few shipped
/// "vehicle wheel" slots hold other PROTOs; their [`WheelParams`] carry their real radius, width
/// and mass, and the `VehicleWheel` defaults for the other (unused) fields.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum WheelShape {
    /// A `VehicleWheel`: tyre, rim contour and rim centre meshes as generated by Webots.
    #[default]
    VehicleWheel,
    /// A plain textured `Cylinder` of radius `tireRadius` and height `thickness` (the Tractor
    /// wheels). Meshes are a capped cylinder about the local x axis.
    Cylinder,
    /// A custom mesh this crate does not reproduce (`TeslaModel3Wheel`, the GreenPower EVStar
    /// wheels); exports draw the bounding cylinder as a stand-in.
    CustomMesh,
}

/// The fields of a Webots `VehicleWheel` (R2023b), unvalidated.
///
/// `Default` gives the R2023b PROTO defaults; [`WheelParams::automobile_wheel_2014`] the older
/// `AutomobileWheel` ones. Lengths are in m. Call [`WheelParams::validate`] to apply the PROTO's
/// parameter checks before building meshes or layouts.
///
/// The `logoSlot` field (arbitrary user nodes, e.g. the BMW logo) is not represented.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WheelParams<T> {
    /// Solid name (Webots field `name`, default `"vehicle wheel"`).
    pub name: &'static str,
    /// Tyre width along the axle (m; Webots field `thickness`, default 0.3).
    pub thickness: T,
    /// Outer tyre radius (m; Webots field `tireRadius`, default 0.4).
    pub tire_radius: T,
    /// Number of segments around the axle (Webots field `subdivision`, default 36).
    pub subdivision: i32,
    /// Relative size of the rounded tyre shoulder, in [0, 1] (Webots field `curvatureFactor`,
    /// default 0.35): the shoulder is a quarter circle of radius `thickness·curvatureFactor/2` m.
    pub curvature_factor: T,
    /// Number of segments of each rounded shoulder (Webots field `edgeSubdivision`, default 3).
    pub edge_subdivision: i32,
    /// Radius of the rim, where the tyre sidewall starts (m; Webots field `rimRadius`, default
    /// 0.28).
    pub rim_radius: T,
    /// Number of rim beams (spokes) (Webots field `rimBeamNumber`, default 5).
    pub rim_beam_number: i32,
    /// Width of a rim beam (m; Webots field `rimBeamWidth`, default 0.1).
    pub rim_beam_width: T,
    /// Radius of the innermost hub disc (m; Webots field `centralInnerRadius`, default 0.09).
    pub central_inner_radius: T,
    /// Radius of the hub, where the beams start (m; Webots field `centralOuterRadius`, default
    /// 0.13).
    pub central_outer_radius: T,
    /// Thickness of the beams and hub along the axle (m; Webots field `rimBeamThickness`,
    /// default 0.2).
    pub rim_beam_thickness: T,
    /// Shift of the beams towards the wheel's outer face, −x (m; Webots field `rimBeamOffset`,
    /// default 0.03): the beams span x ∈ [−b/2 − off/2, b/2 − off/2] with b = `rimBeamThickness`.
    pub rim_beam_offset: T,
    /// Contact material name (Webots field `contactMaterial`, default `"default"`).
    pub contact_material: &'static str,
    /// Tyre appearance (Webots field `tireAppearance`, default `GenericTireAppearance {}`).
    pub tire_appearance: PbrAppearance<T>,
    /// Rim appearance (Webots field `rimAppearance`, default `PBRAppearance { roughness 0.4 }`).
    pub rim_appearance: PbrAppearance<T>,
    /// Mass model (Webots field `physics`, default `Physics {}`).
    pub physics: WheelPhysics<T>,
    /// Whether the wheel collides and has physics (Webots field `boundingObject`, default
    /// `TRUE`). When `false` Webots omits the contact material, bounding object and physics.
    pub bounding_object: bool,
    /// Mounting side (Webots field `wheelSide`, default `FALSE` = right).
    pub side: WheelSide,
    /// What the wheel is in Webots (not a Webots field; default [`WheelShape::VehicleWheel`]).
    pub shape: WheelShape,
}

impl<T: Real> Default for WheelParams<T> {
    /// The `VehicleWheel` R2023b defaults (see the field docs).
    fn default() -> Self {
        WheelParams {
            name: "vehicle wheel",
            thickness: T::from_f64(0.3),
            tire_radius: T::from_f64(0.4),
            subdivision: 36,
            curvature_factor: T::from_f64(0.35),
            edge_subdivision: 3,
            rim_radius: T::from_f64(0.28),
            rim_beam_number: 5,
            rim_beam_width: T::from_f64(0.1),
            central_inner_radius: T::from_f64(0.09),
            central_outer_radius: T::from_f64(0.13),
            rim_beam_thickness: T::from_f64(0.2),
            rim_beam_offset: T::from_f64(0.03),
            contact_material: "default",
            tire_appearance: PbrAppearance::generic_tire(),
            rim_appearance: PbrAppearance::default_rim(),
            physics: WheelPhysics::webots_default(),
            bounding_object: true,
            side: WheelSide::Right,
            shape: WheelShape::VehicleWheel,
        }
    }
}

impl<T: Real> WheelParams<T> {
    /// The `VehicleWheel` R2023b defaults (same as `Default`).
    #[inline]
    pub fn vehicle_wheel() -> Self {
        Self::default()
    }

    /// The defaults of the older `AutomobileWheel` PROTO (2014 manual): as `VehicleWheel` except
    /// `subdivision 24`, `edgeSubdivision 1`, `Appearance { material Material {} }` for tyre and
    /// rim, name `"automobile wheel"`, and no `wheelSide`/`boundingObject` fields (right side,
    /// bounding object present).
    pub fn automobile_wheel_2014() -> Self {
        WheelParams {
            name: "automobile wheel",
            subdivision: 24,
            edge_subdivision: 1,
            tire_appearance: PbrAppearance::vrml_default(),
            rim_appearance: PbrAppearance::vrml_default(),
            ..Self::default()
        }
    }

    /// The same wheel placed in the AckermannVehicle slot `wheel`: name as the `Car` PROTO sets
    /// it (`"front right wheel"`, `"front left wheel"`, `"rear right wheel"`, `"rear left
    /// wheel"`) and `wheelSide TRUE` on the left.
    pub fn in_slot(self, wheel: Wheel) -> Self {
        WheelParams {
            name: slot_name(wheel),
            side: WheelSide::of(wheel),
            ..self
        }
    }
}

/// The solid name the `Car` PROTO gives the wheel in slot `wheel`.
pub const fn slot_name(wheel: Wheel) -> &'static str {
    match wheel {
        Wheel::FrontRight => "front right wheel",
        Wheel::FrontLeft => "front left wheel",
        Wheel::RearRight => "rear right wheel",
        Wheel::RearLeft => "rear left wheel",
    }
}
