//! The engine sound file name, stored without allocation.

use core::fmt;

/// The engine sound file (Webots field `engineSound`, default `"sounds/engine.wav"`).
///
/// An empty name means "no engine sound" and is stored as `"none"`, as the `Car` PROTO writes it
/// into `customData`. At most [`EngineSound::MAX_LEN`] bytes.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub struct EngineSound(heapless::String<{ EngineSound::MAX_LEN }>);

impl EngineSound {
    /// Longest accepted name (bytes).
    pub const MAX_LEN: usize = 63;
    /// The Webots default, `"sounds/engine.wav"`.
    pub const DEFAULT_FILE: &'static str = "sounds/engine.wav";
    /// The name Webots uses for "no sound".
    pub const NONE: &'static str = "none";

    /// The sound file `name`; `""` becomes `"none"`. `None` if longer than
    /// [`EngineSound::MAX_LEN`] bytes.
    pub fn new(name: &str) -> Option<Self> {
        let name = if name.is_empty() { Self::NONE } else { name };
        heapless::String::try_from(name).ok().map(EngineSound)
    }

    /// No engine sound.
    pub fn none() -> Self {
        Self::new(Self::NONE).unwrap_or_default()
    }

    /// The file name (`"none"` for no sound).
    pub fn as_str(&self) -> &str {
        &self.0
    }

    /// True if the car has no engine sound (Webots: the name is `"none"`).
    pub fn is_none(&self) -> bool {
        self.0.as_str() == Self::NONE
    }
}

impl Default for EngineSound {
    /// `"sounds/engine.wav"`.
    fn default() -> Self {
        let mut s = heapless::String::new();
        // Fits: 17 bytes of a 63-byte capacity.
        let _ = s.push_str(Self::DEFAULT_FILE);
        EngineSound(s)
    }
}

impl fmt::Display for EngineSound {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names() {
        assert_eq!(EngineSound::default().as_str(), "sounds/engine.wav");
        assert!(!EngineSound::default().is_none());
        assert!(EngineSound::new("").unwrap().is_none());
        assert_eq!(EngineSound::none().as_str(), "none");
        assert_eq!(EngineSound::new("a.wav").unwrap().as_str(), "a.wav");
        let bytes = [b'x'; 64];
        let long = core::str::from_utf8(&bytes).unwrap();
        assert_eq!(EngineSound::new(long), None);
        assert!(EngineSound::new(&long[..63]).is_some());
    }
}
