//! `webots/gps.h`, `webots/inertial_unit.h`, `webots/gyro.h`, `webots/accelerometer.h`,
//! `webots/compass.h`: the sensor functions, over the engine's devices (`sim::devices`).
//!
//! Periods are in ms. The `const double *` results point into the robot's storage
//! ([`crate::sensor::Buffers`]), refreshed by each getter call and valid until the robot is
//! freed (Webots: until the next step). The Rust twins of the pointer getters, for the Python
//! package, are in [`values`]: they print the same messages and return arrays.

use std::ffi::{c_char, c_int, c_void};

use sim::devices::{DeviceKind, DeviceSettings, Reading};

use crate::abi::WbDeviceTag;
use crate::guard::call_pointer;
use crate::robot::Robot;
use crate::sensor::{self, device, find, prefix, read};
use crate::session::with_robot;

/// The Rust twins of the getters whose C result is a pointer: the same checks and messages,
/// the values as arrays (`None` where C returns NULL).
pub mod values {
    use super::*;

    /// [`wb_gps_get_values`](super::wb_gps_get_values): the position (m).
    pub fn wb_gps_get_values(tag: WbDeviceTag) -> Option<[f64; 3]> {
        with_robot(|r| gps(r, "wb_gps_get_values", tag)).map(|(_, p, _)| p)
    }

    /// [`wb_gps_get_speed_vector`](super::wb_gps_get_speed_vector): the velocity (m/s).
    pub fn wb_gps_get_speed_vector(tag: WbDeviceTag) -> Option<[f64; 3]> {
        with_robot(|r| gps(r, "wb_gps_get_speed_vector", tag)).map(|(_, _, v)| v)
    }

    /// [`wb_gps_convert_to_degrees_minutes_seconds`](super::wb_gps_convert_to_degrees_minutes_seconds).
    pub fn wb_gps_convert_to_degrees_minutes_seconds(decimal_degrees: f64) -> String {
        degrees_minutes_seconds(decimal_degrees)
    }

    /// [`wb_inertial_unit_get_roll_pitch_yaw`](super::wb_inertial_unit_get_roll_pitch_yaw)
    /// (rad): the shared array, also for a wrong tag.
    pub fn wb_inertial_unit_get_roll_pitch_yaw(tag: WbDeviceTag) -> [f64; 3] {
        with_robot(|r| *roll_pitch_yaw(r, tag))
    }

    /// [`wb_inertial_unit_get_quaternion`](super::wb_inertial_unit_get_quaternion):
    /// `[x, y, z, w]`.
    pub fn wb_inertial_unit_get_quaternion(tag: WbDeviceTag) -> Option<[f64; 4]> {
        with_robot(|r| quaternion(r, tag)).map(|(_, q)| q)
    }

    /// The values of the gyro (rad/s), accelerometer (m/s²) or compass with `tag`.
    pub fn triaxial_values(kind: DeviceKind, tag: WbDeviceTag) -> Option<[f64; 3]> {
        with_robot(|r| triaxial(r, kind, tag)).map(|(_, v)| v)
    }

    /// The lookup table of the gyro, accelerometer or compass with `tag`, row after row
    /// (`None` if empty or a wrong tag).
    pub fn triaxial_lookup_table(kind: DeviceKind, tag: WbDeviceTag) -> Option<Vec<f64>> {
        with_robot(|r| lookup_table(r, kind, tag).map(<[f64]>::to_vec))
    }
}

/// A GPS sample: its index, position (m) and speed vector (m/s).
fn gps(robot: &Robot, function: &str, tag: WbDeviceTag) -> Option<(usize, [f64; 3], [f64; 3])> {
    match read(robot, DeviceKind::Gps, function, tag, true)? {
        (i, Reading::Gps(g)) => Some((i, g.position.coords.into(), g.speed_vector.into())),
        _ => None,
    }
}

/// An inertial unit's quaternion `[x, y, z, w]`, with its index.
fn quaternion(robot: &Robot, tag: WbDeviceTag) -> Option<(usize, [f64; 4])> {
    let function = "wb_inertial_unit_get_quaternion";
    match read(robot, DeviceKind::InertialUnit, function, tag, true)? {
        (i, Reading::InertialUnit(u)) => {
            let q = u.quaternion;
            Some((i, [q.i, q.j, q.k, q.w]))
        }
        _ => None,
    }
}

/// Updates the shared roll/pitch/yaw array from the unit with `tag` (left as it is for a wrong
/// tag, as Webots does) and returns it.
fn roll_pitch_yaw(robot: &mut Robot, tag: WbDeviceTag) -> &[f64; 3] {
    let function = "wb_inertial_unit_get_roll_pitch_yaw";
    if let Some((_, Reading::InertialUnit(u))) =
        read(robot, DeviceKind::InertialUnit, function, tag, true)
    {
        let rpy = u.roll_pitch_yaw();
        *robot.controller_mut().buffers.roll_pitch_yaw = [rpy.roll, rpy.pitch, rpy.yaw];
    }
    &robot.controller().buffers.roll_pitch_yaw
}

/// A three-axis sensor's values, with its index. The accelerometer's getter says nothing of a
/// wrong tag (Webots).
fn triaxial(robot: &Robot, kind: DeviceKind, tag: WbDeviceTag) -> Option<(usize, [f64; 3])> {
    let function = format!("wb_{}_get_values", prefix(kind));
    let report = kind != DeviceKind::Accelerometer;
    match read(robot, kind, &function, tag, report)? {
        (i, Reading::Vector(v)) => Some((i, v.into())),
        _ => None,
    }
}

/// A three-axis sensor's lookup table (row-major), `None` if empty or a wrong tag.
fn lookup_table(robot: &Robot, kind: DeviceKind, tag: WbDeviceTag) -> Option<&[f64]> {
    let function = format!("wb_{}_get_lookup_table", prefix(kind));
    let (_, index) = find(robot, tag, kind, &function, true)?;
    Some(robot.controller().buffers.table(index)).filter(|t| !t.is_empty())
}

/// Webots' `"%d° %d′ %d″"` of a decimal angle: whole degrees, minutes and seconds, each
/// truncated toward zero as C's `(int)` does.
fn degrees_minutes_seconds(x: f64) -> String {
    let degrees = x as i32;
    let fraction = (x - f64::from(degrees)) * 60.0;
    let minutes = fraction as i32;
    let seconds = ((fraction - f64::from(minutes)) * 60.0) as i32;
    format!("{degrees}\u{b0} {minutes}\u{2032} {seconds}\u{2033}")
}

/// Copies `values` into sensor `index`'s storage and points at it.
fn store(robot: &mut Robot, index: usize, values: &[f64]) -> Option<*const f64> {
    let slot = robot.controller_mut().buffers.slot(index)?;
    slot.values[..values.len()].copy_from_slice(values);
    Some(slot.values.as_ptr())
}

unsafe extern "C" {
    /// The C library's allocator: the caller frees the text with `free()`.
    fn malloc(size: usize) -> *mut c_void;
}

entry_points! {
    /// Samples the GPS every `sampling_period` ms. Webots: `wb_gps_enable`.
    fn wb_gps_enable(tag: WbDeviceTag, sampling_period: c_int) {
        with_robot(|r| sensor::enable(r, DeviceKind::Gps, "wb_gps_enable", tag, sampling_period))
    }

    /// Stops sampling the GPS. Webots: `wb_gps_disable`.
    fn wb_gps_disable(tag: WbDeviceTag) {
        with_robot(|r| sensor::enable(r, DeviceKind::Gps, "wb_gps_disable", tag, 0))
    }

    /// The GPS's period (ms), 0 when disabled. Webots: `wb_gps_get_sampling_period`.
    fn wb_gps_get_sampling_period(tag: WbDeviceTag) -> c_int {
        with_robot(|r| sensor::sampling_period(r, DeviceKind::Gps, tag))
    }

    /// The GPS's speed (m/s); NaN before the first sample and for a wrong tag. Webots:
    /// `wb_gps_get_speed`.
    fn wb_gps_get_speed(tag: WbDeviceTag) -> f64 {
        with_robot(|r| match read(r, DeviceKind::Gps, "wb_gps_get_speed", tag, true) {
            Some((_, Reading::Gps(g))) => g.speed,
            _ => f64::NAN,
        })
    }

    /// The world's `gpsCoordinateSystem`: `WB_GPS_LOCAL_COORDINATE` (0) or
    /// `WB_GPS_WGS84_COORDINATE` (1); LOCAL for a wrong tag. Webots:
    /// `wb_gps_get_coordinate_system`.
    fn wb_gps_get_coordinate_system(tag: WbDeviceTag) -> c_int {
        with_robot(|r| {
            find(r, tag, DeviceKind::Gps, "wb_gps_get_coordinate_system", true)
                .map_or(0, |_| r.simulation.gps_frame().system.webots_value())
        })
    }

    /// Samples the inertial unit every `sampling_period` ms. Webots: `wb_inertial_unit_enable`.
    fn wb_inertial_unit_enable(tag: WbDeviceTag, sampling_period: c_int) {
        with_robot(|r| {
            let f = "wb_inertial_unit_enable";
            sensor::enable(r, DeviceKind::InertialUnit, f, tag, sampling_period)
        })
    }

    /// Stops sampling the inertial unit. Webots: `wb_inertial_unit_disable`.
    fn wb_inertial_unit_disable(tag: WbDeviceTag) {
        with_robot(|r| {
            sensor::enable(r, DeviceKind::InertialUnit, "wb_inertial_unit_disable", tag, 0)
        })
    }

    /// The inertial unit's period (ms), 0 when disabled. Webots:
    /// `wb_inertial_unit_get_sampling_period`.
    fn wb_inertial_unit_get_sampling_period(tag: WbDeviceTag) -> c_int {
        with_robot(|r| sensor::sampling_period(r, DeviceKind::InertialUnit, tag))
    }

    /// The inertial unit's `noise` field; 0 for a wrong tag. Webots:
    /// `wb_inertial_unit_get_noise`.
    fn wb_inertial_unit_get_noise(tag: WbDeviceTag) -> f64 {
        with_robot(|r| {
            let f = "wb_inertial_unit_get_noise";
            let found = find(r, tag, DeviceKind::InertialUnit, f, true);
            match found.and_then(|found| device(r, found)).map(|d| d.settings()) {
                Some(DeviceSettings::InertialUnit(s)) => s.noise,
                _ => 0.0,
            }
        })
    }
}

/// Defines the functions of a three-axis sensor: enable, disable, sampling period, values,
/// lookup table and its size.
macro_rules! triaxial_entry_points {
    ($kind:expr, $enable:ident, $disable:ident, $period:ident, $values:ident, $size:ident,
     $table:ident) => {
        entry_points! {
            /// Samples the sensor every `sampling_period` ms (Webots: `wb_<device>_enable`).
            fn $enable(tag: WbDeviceTag, sampling_period: c_int) {
                with_robot(|r| {
                    sensor::enable(r, $kind, stringify!($enable), tag, sampling_period)
                })
            }

            /// Stops sampling the sensor (Webots: `wb_<device>_disable`).
            fn $disable(tag: WbDeviceTag) {
                with_robot(|r| sensor::enable(r, $kind, stringify!($disable), tag, 0))
            }

            /// The sensor's period (ms), 0 when disabled.
            fn $period(tag: WbDeviceTag) -> c_int {
                with_robot(|r| sensor::sampling_period(r, $kind, tag))
            }

            /// The rows of the sensor's `lookupTable` (0 if empty or a wrong tag).
            fn $size(tag: WbDeviceTag) -> c_int {
                with_robot(|r| {
                    let rows = lookup_table(r, $kind, tag).map_or(0, |t| t.len() / 3);
                    c_int::try_from(rows).unwrap_or(c_int::MAX)
                })
            }
        }

        /// The sensor's three values (NaN before the first sample and on a disabled axis);
        /// NULL for a wrong tag.
        #[unsafe(no_mangle)]
        pub extern "C" fn $values(tag: WbDeviceTag) -> *const f64 {
            call_pointer(stringify!($values), || {
                with_robot(|r| {
                    let (i, v) = triaxial(r, $kind, tag)?;
                    store(r, i, &v)
                })
            })
        }

        /// The sensor's `lookupTable`, rows `[input, output, noise]` one after the other;
        /// NULL if empty or a wrong tag.
        #[unsafe(no_mangle)]
        pub extern "C" fn $table(tag: WbDeviceTag) -> *const f64 {
            call_pointer(stringify!($table), || {
                with_robot(|r| lookup_table(r, $kind, tag).map(<[f64]>::as_ptr))
            })
        }
    };
}

triaxial_entry_points!(
    DeviceKind::Gyro,
    wb_gyro_enable,
    wb_gyro_disable,
    wb_gyro_get_sampling_period,
    wb_gyro_get_values,
    wb_gyro_get_lookup_table_size,
    wb_gyro_get_lookup_table
);
triaxial_entry_points!(
    DeviceKind::Accelerometer,
    wb_accelerometer_enable,
    wb_accelerometer_disable,
    wb_accelerometer_get_sampling_period,
    wb_accelerometer_get_values,
    wb_accelerometer_get_lookup_table_size,
    wb_accelerometer_get_lookup_table
);
triaxial_entry_points!(
    DeviceKind::Compass,
    wb_compass_enable,
    wb_compass_disable,
    wb_compass_get_sampling_period,
    wb_compass_get_values,
    wb_compass_get_lookup_table_size,
    wb_compass_get_lookup_table
);

/// The GPS's position `[x, y, z]` (m, world: x east, y north, z up); NULL for a wrong tag.
/// Webots: `wb_gps_get_values`.
#[unsafe(no_mangle)]
pub extern "C" fn wb_gps_get_values(tag: WbDeviceTag) -> *const f64 {
    call_pointer("wb_gps_get_values", || {
        with_robot(|r| {
            let (i, p, _) = gps(r, "wb_gps_get_values", tag)?;
            store(r, i, &p)
        })
    })
}

/// The GPS's velocity `[vx, vy, vz]` (m/s, world axes); NULL for a wrong tag. Webots:
/// `wb_gps_get_speed_vector`.
#[unsafe(no_mangle)]
pub extern "C" fn wb_gps_get_speed_vector(tag: WbDeviceTag) -> *const f64 {
    call_pointer("wb_gps_get_speed_vector", || {
        with_robot(|r| {
            let (i, _, v) = gps(r, "wb_gps_get_speed_vector", tag)?;
            let slot = r.controller_mut().buffers.slot(i)?;
            slot.speed_vector = v;
            Some(slot.speed_vector.as_ptr())
        })
    })
}

/// `"D° M′ S″"` of `decimal_degrees` in memory from `malloc` (the caller frees it); NULL if
/// the allocation fails. Webots: `wb_gps_convert_to_degrees_minutes_seconds`.
#[unsafe(no_mangle)]
pub extern "C" fn wb_gps_convert_to_degrees_minutes_seconds(decimal_degrees: f64) -> *const c_char {
    call_pointer("wb_gps_convert_to_degrees_minutes_seconds", || {
        let text = degrees_minutes_seconds(decimal_degrees);
        // SAFETY: malloc has no precondition; its result is checked for NULL below.
        let p = unsafe { malloc(text.len() + 1) }.cast::<u8>();
        if p.is_null() {
            return None;
        }
        // SAFETY: `p` holds text.len() + 1 bytes, freshly allocated, so it overlaps nothing.
        unsafe {
            std::ptr::copy_nonoverlapping(text.as_ptr(), p, text.len());
            *p.add(text.len()) = 0;
        }
        Some(p.cast_const().cast::<c_char>())
    })
}

/// `[roll, pitch, yaw]` (rad) of the inertial unit, in the array all units share (returned,
/// unchanged, for a wrong tag too). Webots: `wb_inertial_unit_get_roll_pitch_yaw`.
#[unsafe(no_mangle)]
pub extern "C" fn wb_inertial_unit_get_roll_pitch_yaw(tag: WbDeviceTag) -> *const f64 {
    call_pointer("wb_inertial_unit_get_roll_pitch_yaw", || {
        with_robot(|r| Some(roll_pitch_yaw(r, tag).as_ptr()))
    })
}

/// The inertial unit's quaternion `[x, y, z, w]`; NULL for a wrong tag. Webots:
/// `wb_inertial_unit_get_quaternion`.
#[unsafe(no_mangle)]
pub extern "C" fn wb_inertial_unit_get_quaternion(tag: WbDeviceTag) -> *const f64 {
    call_pointer("wb_inertial_unit_get_quaternion", || {
        with_robot(|r| {
            let (i, q) = quaternion(r, tag)?;
            store(r, i, &q)
        })
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn degrees_minutes_seconds_truncate_like_c() {
        // 12.625° = 12° 37.5′ = 12° 37′ 30″ (every step exact in binary).
        assert_eq!(degrees_minutes_seconds(12.625), "12° 37′ 30″");
        // 12.5125° is 12° 30′ 45″ in decimal, but 0.5125 is a little below itself in binary:
        // 44.99… seconds, truncated to 44 as Webots' C code does.
        assert_eq!(degrees_minutes_seconds(12.5125), "12° 30′ 44″");
        // Negative angles truncate toward zero in every part, as Webots' (int) casts.
        assert_eq!(degrees_minutes_seconds(-12.625), "-12° -37′ -30″");
        assert_eq!(degrees_minutes_seconds(0.0), "0° 0′ 0″");
    }
}
