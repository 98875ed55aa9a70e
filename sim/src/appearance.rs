//! How the world's things look to a camera and what a camera's Recognition reports of them:
//! their colour, their `recognitionColors` and their `model` name (Webots' `Solid` fields).
//!
//! The world's physics knows shapes, not colours: a [`Simulation`](crate::Simulation) keeps one
//! [`Appearance`] per box, ramp, cone, dynamic box, car and robot, by default the colours the
//! replay (`replay.glb`) draws them with, and no recognition colour, so that, as in Webots,
//! nothing is recognised until it is given one.

use crate::error::ParamError;
use crate::road::LaneKind;

/// The ground's colour (linear RGB, each in [0, 1]): the replay's ground material.
pub const GROUND_COLOR: [f64; 3] = [0.3, 0.33, 0.3];
/// A driving lane's colour, to a camera and in the replay: asphalt, a dark grey.
pub const ASPHALT_COLOR: [f64; 3] = [0.18, 0.18, 0.19];
/// Any other lane's (a border, a shoulder, a sidewalk): a lighter grey.
pub const VERGE_COLOR: [f64; 3] = [0.45, 0.45, 0.43];
/// The colour of a lane of kind `kind`: asphalt for a driving lane, else the verge's grey.
pub fn lane_color(kind: LaneKind) -> [f64; 3] {
    if kind == LaneKind::Driving {
        ASPHALT_COLOR
    } else {
        VERGE_COLOR
    }
}
/// The static boxes' and ramps' default colour: the replay's concrete.
pub const OBSTACLE_COLOR: [f64; 3] = [0.55, 0.55, 0.52];
/// The dynamic boxes' default colour: the replay's wood.
pub const BODY_COLOR: [f64; 3] = [0.65, 0.45, 0.25];
/// The default body colours of the cars and robots in the order they were added, reused past
/// the last: the replay's palette.
pub const PALETTE: [[f64; 3]; 5] = [
    [0.1, 0.25, 0.7],
    [0.1, 0.5, 0.2],
    [0.75, 0.75, 0.75],
    [0.5, 0.15, 0.55],
    [0.85, 0.6, 0.05],
];

/// The most recognition colours a thing may have: more is a typo, not a use.
pub const MAX_RECOGNITION_COLORS: usize = 64;

/// One thing of the world a camera can see.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum SceneObject {
    /// The static box, ramp or cone of index `i` in `WorldConfig::obstacles`.
    Obstacle(usize),
    /// The dynamic box of index `i` in `WorldConfig::bodies`.
    Body(usize),
    /// The car of index `i` in `World::vehicles` (the order they were added).
    Car(usize),
    /// The DifferentialWheels robot of index `i` in `World::robots`.
    Robot(usize),
}

/// A thing's look: Webots' `Material.diffuseColor` (or `PBRAppearance.baseColor`) of its
/// shapes, its `Solid.recognitionColors` and `Solid.model`.
#[derive(Debug, Clone, PartialEq)]
pub struct Appearance {
    /// Diffuse colour (RGB, each in [0, 1]).
    pub color: [f64; 3],
    /// `recognitionColors` (RGB, each in [0, 1]); empty: a camera's Recognition ignores it.
    pub recognition_colors: Vec<[f64; 3]>,
    /// `model` (Webots' default: empty).
    pub model: String,
}

impl Appearance {
    /// A thing of colour `color`, not recognised, without a model name.
    pub fn of_color(color: [f64; 3]) -> Self {
        Appearance {
            color,
            recognition_colors: Vec::new(),
            model: String::new(),
        }
    }

    /// Checks the colours: every channel finite and in [0, 1], at most
    /// [`MAX_RECOGNITION_COLORS`] recognition colours.
    ///
    /// # Errors
    /// A [`ParamError`] naming `color` or `recognitionColors` and the value.
    pub fn validate(&self) -> Result<(), ParamError> {
        for &c in &self.color {
            check_channel("color", c)?;
        }
        ParamError::check(
            "recognitionColors",
            self.recognition_colors.len() as f64,
            "at most 64 colours",
            |n| n <= MAX_RECOGNITION_COLORS as f64,
        )?;
        for &c in self.recognition_colors.iter().flatten() {
            check_channel("recognitionColors", c)?;
        }
        Ok(())
    }
}

/// A colour channel: finite and in [0, 1].
fn check_channel(field: &'static str, c: f64) -> Result<(), ParamError> {
    ParamError::check(field, c, "in [0, 1]", |c| (0.0..=1.0).contains(&c)).map(|_| ())
}

/// The looks of a world's things, by [`SceneObject`]; a thing without one has its default
/// (the module's colour constants, no recognition colours).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Appearances {
    set: Vec<(SceneObject, Appearance)>,
}

impl Appearances {
    /// Gives `object` the look `appearance` (replacing the one it had).
    ///
    /// # Errors
    /// As [`Appearance::validate`].
    pub fn set(&mut self, object: SceneObject, appearance: Appearance) -> Result<(), ParamError> {
        appearance.validate()?;
        match self.set.iter_mut().find(|(o, _)| *o == object) {
            Some((_, a)) => *a = appearance,
            None => self.set.push((object, appearance)),
        }
        Ok(())
    }

    /// The look of `object` if one was set.
    pub fn explicit(&self, object: SceneObject) -> Option<&Appearance> {
        self.set.iter().find(|(o, _)| *o == object).map(|(_, a)| a)
    }

    /// The colour of `object` in a world of `vehicles` cars: the one set, else its default
    /// (obstacles concrete, dynamic boxes wood, cars and then robots the [`PALETTE`] in turn).
    pub fn color(&self, object: SceneObject, vehicles: usize) -> [f64; 3] {
        self.explicit(object).map_or_else(
            || match object {
                SceneObject::Obstacle(_) => OBSTACLE_COLOR,
                SceneObject::Body(_) => BODY_COLOR,
                SceneObject::Car(i) => PALETTE[i % PALETTE.len()],
                SceneObject::Robot(i) => PALETTE[(vehicles + i) % PALETTE.len()],
            },
            |a| a.color,
        )
    }

    /// Every look set, in the order they were first set.
    pub fn iter(&self) -> impl Iterator<Item = &(SceneObject, Appearance)> {
        self.set.iter()
    }
}
