//! Keyframe animations of a [`Scene`](super::Scene)'s nodes (glTF 2.0 animations).
//!
//! An [`Animation`] holds timelines (keyframe times in s) and channels, each of which moves one
//! property (translation, rotation or scale) of one node along one timeline. Values are in the
//! scene's convention: relative to the node's parent, in the z-up vehicle frame (translations
//! in m); the glTF writer's root node maps them to y-up once. Several channels may share a
//! timeline, which the glTF file then stores once.

use core::fmt;
use std::string::String;
use std::vec::Vec;

/// How a channel moves between keyframes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Interpolation {
    /// Linear for translation and scale, spherical linear (slerp) for rotations.
    #[default]
    Linear,
    /// The value of a keyframe holds until the next one (e.g. a light switched on or off).
    Step,
}

/// The keyframe values of a channel, one per time of its timeline.
#[derive(Debug, Clone, PartialEq)]
pub enum Keyframes {
    /// Translations relative to the parent (m, z-up frame).
    Translation(Vec<[f32; 3]>),
    /// Rotations relative to the parent as unit quaternions `[x, y, z, w]` (glTF's order,
    /// nalgebra's `coords`). The writer normalises them and picks, for each, the sign nearest
    /// the previous one, so that slerp takes the short way.
    Rotation(Vec<[f32; 4]>),
    /// Scale factors along the node's axes (dimensionless); all zero hides the node and its
    /// children.
    Scale(Vec<[f32; 3]>),
}

impl Keyframes {
    /// Number of keyframes.
    pub fn len(&self) -> usize {
        match self {
            Keyframes::Translation(v) | Keyframes::Scale(v) => v.len(),
            Keyframes::Rotation(v) => v.len(),
        }
    }

    /// True without keyframes.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The animated property.
    pub const fn property(&self) -> Property {
        match self {
            Keyframes::Translation(_) => Property::Translation,
            Keyframes::Rotation(_) => Property::Rotation,
            Keyframes::Scale(_) => Property::Scale,
        }
    }

    fn all_finite(&self) -> bool {
        match self {
            Keyframes::Translation(v) | Keyframes::Scale(v) => {
                v.iter().flatten().all(|c| c.is_finite())
            }
            Keyframes::Rotation(v) => v.iter().all(|q| {
                q.iter().all(|c| c.is_finite()) && q.iter().map(|c| c * c).sum::<f32>() > 1e-12
            }),
        }
    }
}

/// A node property a channel animates.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Property {
    /// glTF `translation`.
    Translation,
    /// glTF `rotation`.
    Rotation,
    /// glTF `scale`.
    Scale,
}

/// One animated property of one node.
#[derive(Debug, Clone, PartialEq)]
pub struct Channel {
    /// Index into [`Scene::nodes`](super::Scene::nodes).
    pub node: usize,
    /// Index into [`Animation::timelines`].
    pub timeline: usize,
    /// How values change between keyframes.
    pub interpolation: Interpolation,
    /// One value per time of the timeline.
    pub values: Keyframes,
}

/// A named keyframe animation (glTF `animation`): what a viewer lists and plays as one clip.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Animation {
    /// The clip's name, e.g. a scenario's.
    pub name: String,
    /// Keyframe times (s), each strictly increasing from ≥ 0.
    pub timelines: Vec<Vec<f32>>,
    /// The channels; no two may animate the same property of the same node.
    pub channels: Vec<Channel>,
}

impl Animation {
    /// An empty animation called `name`.
    pub fn new(name: &str) -> Self {
        Animation {
            name: name.into(),
            ..Animation::default()
        }
    }

    /// Adds keyframe times (s) and returns the timeline's index.
    pub fn add_timeline(&mut self, times: Vec<f32>) -> usize {
        self.timelines.push(times);
        self.timelines.len() - 1
    }

    /// Adds a channel moving `values` of `node` along `timeline`.
    pub fn add_channel(
        &mut self,
        node: usize,
        timeline: usize,
        interpolation: Interpolation,
        values: Keyframes,
    ) {
        self.channels.push(Channel {
            node,
            timeline,
            interpolation,
            values,
        });
    }

    /// The time of the last keyframe over all timelines (s); 0 for an empty animation.
    pub fn duration(&self) -> f32 {
        self.timelines
            .iter()
            .filter_map(|t| t.last().copied())
            .fold(0.0, f32::max)
    }

    /// Checks the animation against a scene of `node_count` nodes: every channel names an
    /// existing node and timeline and has one finite value (a non-zero quaternion for
    /// rotations) per keyframe, timelines are non-empty, finite, ≥ 0 and strictly increasing,
    /// and no two channels share a target.
    ///
    /// # Errors
    /// The first problem found, as an [`AnimationError`].
    pub fn validate(&self, node_count: usize) -> Result<(), AnimationError> {
        if self.channels.is_empty() {
            return Err(AnimationError::NoChannel);
        }
        for (timeline, times) in self.timelines.iter().enumerate() {
            if times.is_empty() {
                return Err(AnimationError::EmptyTimeline { timeline });
            }
            let mut previous = None;
            for (index, &time) in times.iter().enumerate() {
                let ok = time.is_finite() && time >= 0.0 && previous.is_none_or(|p| time > p);
                if !ok {
                    return Err(AnimationError::BadTime {
                        timeline,
                        index,
                        time,
                    });
                }
                previous = Some(time);
            }
        }
        for (channel, c) in self.channels.iter().enumerate() {
            if c.node >= node_count {
                return Err(AnimationError::UnknownNode {
                    channel,
                    node: c.node,
                });
            }
            let Some(times) = self.timelines.get(c.timeline) else {
                return Err(AnimationError::UnknownTimeline {
                    channel,
                    timeline: c.timeline,
                });
            };
            if c.values.len() != times.len() {
                return Err(AnimationError::CountMismatch {
                    channel,
                    times: times.len(),
                    values: c.values.len(),
                });
            }
            if !c.values.all_finite() {
                return Err(AnimationError::BadValue { channel });
            }
            let duplicate = self.channels[..channel]
                .iter()
                .any(|o| o.node == c.node && o.values.property() == c.values.property());
            if duplicate {
                return Err(AnimationError::DuplicateTarget {
                    channel,
                    node: c.node,
                    property: c.values.property(),
                });
            }
        }
        Ok(())
    }
}

/// Why an [`Animation`] cannot be written.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum AnimationError {
    /// The animation has no channel (glTF requires at least one).
    NoChannel,
    /// A timeline without keyframes.
    EmptyTimeline {
        /// Index of the timeline.
        timeline: usize,
    },
    /// A keyframe time (s) that is not finite, negative, or not after the previous one.
    BadTime {
        /// Index of the timeline.
        timeline: usize,
        /// Index of the keyframe.
        index: usize,
        /// The time given (s).
        time: f32,
    },
    /// A channel names a node the scene does not have.
    UnknownNode {
        /// Index of the channel.
        channel: usize,
        /// The node index given.
        node: usize,
    },
    /// A channel names a timeline the animation does not have.
    UnknownTimeline {
        /// Index of the channel.
        channel: usize,
        /// The timeline index given.
        timeline: usize,
    },
    /// A channel with a different number of values than its timeline has times.
    CountMismatch {
        /// Index of the channel.
        channel: usize,
        /// Keyframe times of its timeline.
        times: usize,
        /// Values given.
        values: usize,
    },
    /// A channel with a non-finite value or a zero quaternion.
    BadValue {
        /// Index of the channel.
        channel: usize,
    },
    /// Two channels animate the same property of the same node.
    DuplicateTarget {
        /// Index of the second channel.
        channel: usize,
        /// The node.
        node: usize,
        /// The property.
        property: Property,
    },
}

impl fmt::Display for AnimationError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            AnimationError::NoChannel => write!(f, "animation without channels"),
            AnimationError::EmptyTimeline { timeline } => {
                write!(f, "animation timeline {timeline} has no keyframe")
            }
            AnimationError::BadTime {
                timeline,
                index,
                time,
            } => write!(
                f,
                "animation timeline {timeline}: keyframe {index} at {time} s is not finite, \
                 negative or not after the previous one"
            ),
            AnimationError::UnknownNode { channel, node } => {
                write!(f, "animation channel {channel}: no node {node}")
            }
            AnimationError::UnknownTimeline { channel, timeline } => {
                write!(f, "animation channel {channel}: no timeline {timeline}")
            }
            AnimationError::CountMismatch {
                channel,
                times,
                values,
            } => write!(
                f,
                "animation channel {channel}: {values} values for {times} keyframe times"
            ),
            AnimationError::BadValue { channel } => write!(
                f,
                "animation channel {channel}: a value is not finite (or a quaternion is zero)"
            ),
            AnimationError::DuplicateTarget {
                channel,
                node,
                property,
            } => write!(
                f,
                "animation channel {channel}: node {node}'s {property:?} is animated twice"
            ),
        }
    }
}

impl std::error::Error for AnimationError {}
