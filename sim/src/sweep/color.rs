//! Which axis colours the cases of a sweep's plots: the sweep file's `color_by`, recorded in
//! the manifest so that `sweep-merge` draws the shards' plots alike.

/// Most values of the axis the cases are coloured by: one colour each, all distinct (the
/// plots' palette, Okabe–Ito, has 7).
pub const MAX_COLOURS: usize = 7;
/// The `color_by` value that turns colouring off (an axis is a world-file key: never this).
pub const NO_COLOR: &str = "none";

/// Which axis the cases of a sweep's plots are coloured by (the sweep file's `color_by`).
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub enum ColorBy {
    /// The first other axis, in file order, of 2 to [`MAX_COLOURS`] distinct values; none
    /// when there is no such axis.
    #[default]
    Auto,
    /// No colours: every case alike.
    Off,
    /// This axis (its key), in every figure but its own.
    Axis(String),
}

impl ColorBy {
    /// From the sweep file's or manifest's `color_by`: absent is [`ColorBy::Auto`],
    /// [`NO_COLOR`] is [`ColorBy::Off`], anything else an axis key.
    pub fn from_key(key: Option<&str>) -> ColorBy {
        match key {
            None => ColorBy::Auto,
            Some(NO_COLOR) => ColorBy::Off,
            Some(axis) => ColorBy::Axis(axis.to_string()),
        }
    }

    /// The key [`ColorBy::from_key`] reads back.
    pub fn key(&self) -> Option<&str> {
        match self {
            ColorBy::Auto => None,
            ColorBy::Off => Some(NO_COLOR),
            ColorBy::Axis(axis) => Some(axis),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn keys_read_back() {
        assert_eq!(ColorBy::from_key(None), ColorBy::Auto);
        assert_eq!(ColorBy::from_key(Some("none")), ColorBy::Off);
        for c in [
            ColorBy::Auto,
            ColorBy::Off,
            ColorBy::Axis("ground.friction".into()),
        ] {
            assert_eq!(ColorBy::from_key(c.key()), c);
        }
    }
}
