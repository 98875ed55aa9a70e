//! Webots' `Camera` (spec §9): a BGRA image of the world through a planar pinhole, and its
//! `Recognition`.
//!
//! The image is rendered from the world's geometry (`solids.rs`: boxes, ramps, dynamic boxes,
//! car bodies, robots, and the ground plane) with each thing's colour
//! ([`crate::appearance`]) under a default light: an upward face shows its colour exactly,
//! other faces are darker (at least half as bright), nothing casts shadows, the sky is
//! Webots' default background, black. The camera's own car's body is not drawn.

mod raster;
mod recognition;
pub(crate) mod roads;
pub(crate) mod solids;

use proto_geom::nalgebra::Isometry3;

use crate::error::ParamError;
use crate::rng::SplitMix64;
use crate::sampling::Schedule;
use crate::vehicle::VehicleId;

use super::noise::gaussian;
use raster::{Frame, Pinhole};
pub use recognition::{Occlusion, RecognitionObject, RecognitionSettings};
use solids::Solids;

/// The largest image side (px): a camera of more is a typo, and its image would not fit a
/// step's budget.
pub const MAX_SIDE: u32 = 4096;

/// The fields of a `Camera` node, with Webots' defaults ([`Default`]). Only the planar
/// projection is rendered; `exposure`, `antiAliasing`, `ambientOcclusionRadius`,
/// `bloomThreshold`, `motionBlur`, `noiseMaskUrl`, `lens`, `focus`, `zoom` and `lensFlare`
/// are not held (`COMPATIBILITY.md`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CameraSettings {
    /// `fieldOfView` (rad, horizontal, in (0, π]; default 0.785398).
    pub field_of_view: f64,
    /// `width` (px, 1 to [`MAX_SIDE`]; default 64).
    pub width: u32,
    /// `height` (px, 1 to [`MAX_SIDE`]; default 64).
    pub height: u32,
    /// `near` (m, > 0; default 0.01): nothing nearer along the camera's axis is drawn.
    pub near: f64,
    /// `far` (m, 0 = infinite (default), else > `near`): nothing farther along the camera's
    /// axis is drawn.
    pub far: f64,
    /// `noise` (in [0, 1]; default 0): standard deviation of the Gaussian noise added to each
    /// channel, as a fraction of full scale.
    pub noise: f64,
    /// The `recognition` node, if any.
    pub recognition: Option<RecognitionSettings>,
}

impl Default for CameraSettings {
    // Webots' `fieldOfView` default is this six-digit literal, not π/4.
    #[allow(clippy::approx_constant)]
    fn default() -> Self {
        CameraSettings {
            field_of_view: 0.785398,
            width: 64,
            height: 64,
            near: 0.01,
            far: 0.0,
            noise: 0.0,
            recognition: None,
        }
    }
}

impl CameraSettings {
    /// Checks every field against Webots' range.
    ///
    /// # Errors
    /// A [`ParamError`] naming the Webots field and the value.
    pub fn validate(&self) -> Result<(), ParamError> {
        ParamError::check(
            "fieldOfView",
            self.field_of_view,
            "in (0, pi] rad (planar projection)",
            |f| f > 0.0 && f <= core::f64::consts::PI,
        )?;
        for (field, side) in [("width", self.width), ("height", self.height)] {
            ParamError::check(field, f64::from(side), "from 1 to 4096 px", |s| {
                (1.0..=f64::from(MAX_SIDE)).contains(&s)
            })?;
        }
        ParamError::positive("near", self.near)?;
        let near = self.near;
        ParamError::check("far", self.far, "0 (infinite) or finite and > near", |f| {
            f == 0.0 || (f.is_finite() && f > near)
        })?;
        ParamError::check("noise", self.noise, "in [0, 1]", |n| {
            (0.0..=1.0).contains(&n)
        })?;
        if let Some(r) = &self.recognition {
            r.validate()?;
        }
        Ok(())
    }

    /// The focal length (px): `(width/2) / tan(fieldOfView/2)`.
    pub fn focal_length_px(&self) -> f64 {
        f64::from(self.width) / 2.0 / (self.field_of_view / 2.0).tan()
    }

    fn pinhole(&self) -> Pinhole {
        Pinhole {
            width: self.width as usize,
            height: self.height as usize,
            focal: self.focal_length_px(),
            near: self.near,
            far: if self.far == 0.0 {
                f64::INFINITY
            } else {
                self.far
            },
        }
    }
}

/// Where a camera looks from: its pose (camera frame → world, m), the world's solids and the
/// car it rides on (whose body it does not see).
#[derive(Debug, Clone, Copy)]
pub(crate) struct View<'a> {
    pub pose: &'a Isometry3<f64>,
    pub solids: &'a Solids,
    pub own: Option<VehicleId>,
}

/// A camera's images and recognised objects, and its Recognition's sampling.
#[derive(Debug, Clone)]
pub struct CameraState {
    /// The last image: BGRA, row-major from the top-left, `width·height·4` bytes; all zero
    /// before the first.
    image: Vec<u8>,
    /// The objects of the last Recognition sample.
    objects: Vec<RecognitionObject>,
    /// Recognition's sampling.
    recognition: Schedule,
    /// The render buffers, kept between samples.
    frame: Frame,
    /// True once an image was taken.
    has_image: bool,
}

impl CameraState {
    pub(crate) fn new(settings: &CameraSettings) -> Self {
        CameraState {
            image: vec![0; settings.width as usize * settings.height as usize * 4],
            objects: Vec::new(),
            recognition: Schedule::default(),
            frame: Frame::default(),
            has_image: false,
        }
    }

    /// The last image (BGRA, row-major from the top-left; all zero before the first).
    pub fn image(&self) -> &[u8] {
        &self.image
    }

    /// True once the camera has taken an image.
    pub fn has_image(&self) -> bool {
        self.has_image
    }

    /// The objects of Recognition's last sample.
    pub fn objects(&self) -> &[RecognitionObject] {
        &self.objects
    }

    /// Recognition's sampling period (ms), 0 when disabled.
    pub fn recognition_period_ms(&self) -> u32 {
        self.recognition.period_ms()
    }

    /// Enables Recognition with a period of `period_ms` ms at `now_ms` (0 disables), with the
    /// sampling rules of every device.
    pub(crate) fn enable_recognition(&mut self, period_ms: u32, now_ms: u64) {
        self.recognition.enable(period_ms, now_ms);
    }

    /// True if Recognition is to sample at `now_ms`.
    pub(crate) fn recognition_due(&self, now_ms: u64) -> bool {
        self.recognition.due(now_ms)
    }

    /// Renders what the camera of `settings` sees from `view`; keeps the image if `image` is
    /// due (with noise from `rng`), and recognises the objects if Recognition is due at
    /// `now_ms`.
    pub(crate) fn sample(
        &mut self,
        settings: &CameraSettings,
        view: &View<'_>,
        image: bool,
        now_ms: u64,
        rng: &mut SplitMix64,
    ) {
        let View { pose, solids, own } = *view;
        let pin = settings.pinhole();
        self.frame.render(&pin, pose, solids, own);
        if image {
            self.has_image = true;
            for (px, rgb) in self.image.chunks_exact_mut(4).zip(&self.frame.rgb) {
                let [r, g, b] = if settings.noise > 0.0 {
                    rgb.map(|c| {
                        let noisy = f64::from(c) / 255.0 + settings.noise * gaussian(rng);
                        (noisy.clamp(0.0, 1.0) * 255.0).round() as u8
                    })
                } else {
                    *rgb
                };
                px.copy_from_slice(&[b, g, r, 255]);
            }
        }
        if let Some(r) = &settings.recognition
            && self.recognition_due(now_ms)
        {
            self.recognition.sampled(now_ms);
            self.objects = recognition::recognise(r, &pin, pose, &solids.all, own, &self.frame);
        }
    }
}
