//! Which axle(s) the engine drives.

use crate::wheel::Wheel;

/// The driven axle(s) of a car (Webots: `WbuCarType`, PROTO field `type`).
///
/// The discriminant is the Webots enum value.
#[repr(u8)]
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum DriveType {
    /// Front-wheel drive (Webots `"traction"`, `WBU_CAR_TRACTION` = 0; the PROTO default).
    #[default]
    Traction = 0,
    /// Rear-wheel drive (Webots `"propulsion"`, `WBU_CAR_PROPULSION` = 1).
    Propulsion = 1,
    /// All-wheel drive (Webots `"4x4"`, `WBU_CAR_FOUR_BY_FOUR` = 2).
    FourByFour = 2,
}

impl DriveType {
    /// All three drive types in Webots enum order.
    pub const ALL: [DriveType; 3] = [
        DriveType::Traction,
        DriveType::Propulsion,
        DriveType::FourByFour,
    ];

    /// True if the engine drives the front axle (traction and 4x4).
    #[inline]
    pub const fn front_driven(self) -> bool {
        matches!(self, DriveType::Traction | DriveType::FourByFour)
    }

    /// True if the engine drives the rear axle (propulsion and 4x4).
    #[inline]
    pub const fn rear_driven(self) -> bool {
        matches!(self, DriveType::Propulsion | DriveType::FourByFour)
    }

    /// True if `wheel` carries a motor for this drive type.
    #[inline]
    pub const fn drives(self, wheel: Wheel) -> bool {
        if wheel.is_front() {
            self.front_driven()
        } else {
            self.rear_driven()
        }
    }

    /// The Webots `WbuCarType` value (0, 1 or 2).
    #[inline]
    pub const fn webots_value(self) -> u8 {
        self as u8
    }

    /// The drive type with Webots `WbuCarType` value `v`, or `None` if `v > 2`.
    #[inline]
    pub const fn from_webots_value(v: u8) -> Option<DriveType> {
        match v {
            0 => Some(DriveType::Traction),
            1 => Some(DriveType::Propulsion),
            2 => Some(DriveType::FourByFour),
            _ => None,
        }
    }

    /// The Webots PROTO field spelling: `"traction"`, `"propulsion"` or `"4x4"`.
    #[inline]
    pub const fn webots_name(self) -> &'static str {
        match self {
            DriveType::Traction => "traction",
            DriveType::Propulsion => "propulsion",
            DriveType::FourByFour => "4x4",
        }
    }

    /// Parses the Webots PROTO field spelling (exact, case-sensitive as in Webots), or `None`.
    #[inline]
    pub fn from_webots_name(name: &str) -> Option<DriveType> {
        match name {
            "traction" => Some(DriveType::Traction),
            "propulsion" => Some(DriveType::Propulsion),
            "4x4" => Some(DriveType::FourByFour),
            _ => None,
        }
    }
}

impl core::fmt::Display for DriveType {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str(self.webots_name())
    }
}

#[cfg(test)]
mod tests {
    use super::DriveType;
    use crate::wheel::Wheel;

    #[test]
    fn driven_wheels() {
        let driven = |d: DriveType| Wheel::ALL.map(|w| d.drives(w));
        assert_eq!(driven(DriveType::Traction), [true, true, false, false]);
        assert_eq!(driven(DriveType::Propulsion), [false, false, true, true]);
        assert_eq!(driven(DriveType::FourByFour), [true; 4]);
    }

    #[test]
    fn webots_names_and_values() {
        for (i, d) in DriveType::ALL.into_iter().enumerate() {
            assert_eq!(usize::from(d.webots_value()), i);
            assert_eq!(DriveType::from_webots_value(d.webots_value()), Some(d));
            assert_eq!(DriveType::from_webots_name(d.webots_name()), Some(d));
        }
        assert_eq!(DriveType::FourByFour.webots_name(), "4x4");
        assert_eq!(DriveType::from_webots_name("4X4"), None);
        assert_eq!(DriveType::from_webots_value(3), None);
        assert_eq!(DriveType::default(), DriveType::Traction);
    }
}
