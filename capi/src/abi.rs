//! The C representations of the headers' types.

/// `WbDeviceTag` (`unsigned short` in `webots/types.h`): a device of the robot, 0 for none.
pub type WbDeviceTag = u16;

/// A C `bool` result: 1 for true, 0 for false. (Arguments arrive as one byte, any non-zero
/// value meaning true.)
pub(crate) fn c_bool(b: bool) -> u8 {
    u8::from(b)
}
