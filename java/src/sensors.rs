//! `WebotsNative`, device part: the GPS, inertial unit, gyro, accelerometer, compass, distance
//! sensor, radar, camera, lidar and road sensor (the project's extension, `vehicle_road_sensor_*`)
//! functions for the Java device classes, through the C API's Rust twins of its array getters
//! (`car::values`, `car::lidar_values`: the same checks and messages as the C functions).
//! Units: m, m/s, rad, rad/s, m/s², periods in ms.

use jni::objects::JString;
use jni::sys::{jdouble, jdoubleArray, jfloatArray, jint, jintArray};
use sim::devices::DeviceKind;

use crate::{c_ptr, c_string, double_array, float_array, int_array, tag};

natives! { "com_cyberbotics_webots_controller_WebotsNative";
    /// `wb_gps_enable` (ms).
    fn gpsEnable(env, device: jint, period: jint) => car::wb_gps_enable(tag(device), period);
    /// `wb_gps_disable`.
    fn gpsDisable(env, device: jint) => car::wb_gps_disable(tag(device));
    /// `wb_gps_get_sampling_period` (ms).
    fn gpsGetSamplingPeriod(env, device: jint) -> jint => car::wb_gps_get_sampling_period(tag(device));
    /// `wb_gps_get_values` (m).
    fn gpsGetValues(env, device: jint) -> jdoubleArray =>
        double_array(&mut env, car::values::wb_gps_get_values(tag(device)).as_ref().map(|v| &v[..]));
    /// `wb_gps_get_speed` (m/s).
    fn gpsGetSpeed(env, device: jint) -> jdouble => car::wb_gps_get_speed(tag(device));
    /// `wb_gps_get_speed_vector` (m/s).
    fn gpsGetSpeedVector(env, device: jint) -> jdoubleArray =>
        double_array(&mut env, car::values::wb_gps_get_speed_vector(tag(device)).as_ref().map(|v| &v[..]));
    /// `wb_gps_get_coordinate_system` (0 local, 1 WGS84).
    fn gpsGetCoordinateSystem(env, device: jint) -> jint => car::wb_gps_get_coordinate_system(tag(device));

    /// `wb_inertial_unit_enable` (ms).
    fn inertialUnitEnable(env, device: jint, period: jint) => car::wb_inertial_unit_enable(tag(device), period);
    /// `wb_inertial_unit_disable`.
    fn inertialUnitDisable(env, device: jint) => car::wb_inertial_unit_disable(tag(device));
    /// `wb_inertial_unit_get_sampling_period` (ms).
    fn inertialUnitGetSamplingPeriod(env, device: jint) -> jint => car::wb_inertial_unit_get_sampling_period(tag(device));
    /// `wb_inertial_unit_get_noise` (rad).
    fn inertialUnitGetNoise(env, device: jint) -> jdouble => car::wb_inertial_unit_get_noise(tag(device));
    /// `wb_inertial_unit_get_roll_pitch_yaw` (rad).
    fn inertialUnitGetRollPitchYaw(env, device: jint) -> jdoubleArray =>
        double_array(&mut env, Some(&car::values::wb_inertial_unit_get_roll_pitch_yaw(tag(device))[..]));
    /// `wb_inertial_unit_get_quaternion` (`[x, y, z, w]`).
    fn inertialUnitGetQuaternion(env, device: jint) -> jdoubleArray =>
        double_array(&mut env, car::values::wb_inertial_unit_get_quaternion(tag(device)).as_ref().map(|v| &v[..]));

    /// `wb_gyro_enable` (ms).
    fn gyroEnable(env, device: jint, period: jint) => car::wb_gyro_enable(tag(device), period);
    /// `wb_gyro_disable`.
    fn gyroDisable(env, device: jint) => car::wb_gyro_disable(tag(device));
    /// `wb_gyro_get_sampling_period` (ms).
    fn gyroGetSamplingPeriod(env, device: jint) -> jint => car::wb_gyro_get_sampling_period(tag(device));
    /// `wb_gyro_get_values` (rad/s).
    fn gyroGetValues(env, device: jint) -> jdoubleArray => triaxial(&mut env, DeviceKind::Gyro, device);

    /// `wb_accelerometer_enable` (ms).
    fn accelerometerEnable(env, device: jint, period: jint) => car::wb_accelerometer_enable(tag(device), period);
    /// `wb_accelerometer_disable`.
    fn accelerometerDisable(env, device: jint) => car::wb_accelerometer_disable(tag(device));
    /// `wb_accelerometer_get_sampling_period` (ms).
    fn accelerometerGetSamplingPeriod(env, device: jint) -> jint => car::wb_accelerometer_get_sampling_period(tag(device));
    /// `wb_accelerometer_get_values` (m/s²).
    fn accelerometerGetValues(env, device: jint) -> jdoubleArray => triaxial(&mut env, DeviceKind::Accelerometer, device);

    /// `wb_compass_enable` (ms).
    fn compassEnable(env, device: jint, period: jint) => car::wb_compass_enable(tag(device), period);
    /// `wb_compass_disable`.
    fn compassDisable(env, device: jint) => car::wb_compass_disable(tag(device));
    /// `wb_compass_get_sampling_period` (ms).
    fn compassGetSamplingPeriod(env, device: jint) -> jint => car::wb_compass_get_sampling_period(tag(device));
    /// `wb_compass_get_values` (the north direction, unit vector).
    fn compassGetValues(env, device: jint) -> jdoubleArray => triaxial(&mut env, DeviceKind::Compass, device);

    /// `wb_distance_sensor_enable` (ms).
    fn distanceSensorEnable(env, device: jint, period: jint) => car::wb_distance_sensor_enable(tag(device), period);
    /// `wb_distance_sensor_disable`.
    fn distanceSensorDisable(env, device: jint) => car::wb_distance_sensor_disable(tag(device));
    /// `wb_distance_sensor_get_sampling_period` (ms).
    fn distanceSensorGetSamplingPeriod(env, device: jint) -> jint => car::wb_distance_sensor_get_sampling_period(tag(device));
    /// `wb_distance_sensor_get_value` (the lookup table's output for the measured distance).
    fn distanceSensorGetValue(env, device: jint) -> jdouble => car::wb_distance_sensor_get_value(tag(device));
    /// `wb_distance_sensor_get_max_value`.
    fn distanceSensorGetMaxValue(env, device: jint) -> jdouble => car::wb_distance_sensor_get_max_value(tag(device));
    /// `wb_distance_sensor_get_min_value`.
    fn distanceSensorGetMinValue(env, device: jint) -> jdouble => car::wb_distance_sensor_get_min_value(tag(device));
    /// `wb_distance_sensor_get_aperture` (rad).
    fn distanceSensorGetAperture(env, device: jint) -> jdouble => car::wb_distance_sensor_get_aperture(tag(device));
    /// `wb_distance_sensor_get_type` (`GENERIC`, `INFRA_RED`, `SONAR`, `LASER`).
    fn distanceSensorGetType(env, device: jint) -> jint => car::wb_distance_sensor_get_type(tag(device));

    /// `wb_radar_enable` (ms).
    fn radarEnable(env, device: jint, period: jint) => car::wb_radar_enable(tag(device), period);
    /// `wb_radar_disable`.
    fn radarDisable(env, device: jint) => car::wb_radar_disable(tag(device));
    /// `wb_radar_get_sampling_period` (ms).
    fn radarGetSamplingPeriod(env, device: jint) -> jint => car::wb_radar_get_sampling_period(tag(device));
    /// `wb_radar_get_number_of_targets`.
    fn radarGetNumberOfTargets(env, device: jint) -> jint => car::wb_radar_get_number_of_targets(tag(device));
    /// `wb_radar_get_targets`, flattened: distance (m), received power (dBm), radial speed
    /// (m/s) and azimuth (rad) of each target in turn (`Radar.getTargets` builds the objects).
    fn radarGetTargets(env, device: jint) -> jdoubleArray => {
        let flat: Vec<f64> = car::radar_targets(tag(device))
            .iter()
            .flat_map(|t| [t.distance, t.received_power, t.speed, t.azimuth])
            .collect();
        double_array(&mut env, Some(&flat))
    };
    /// `wb_radar_get_min_range` (m).
    fn radarGetMinRange(env, device: jint) -> jdouble => car::wb_radar_get_min_range(tag(device));
    /// `wb_radar_get_max_range` (m).
    fn radarGetMaxRange(env, device: jint) -> jdouble => car::wb_radar_get_max_range(tag(device));
    /// `wb_radar_get_horizontal_fov` (rad).
    fn radarGetHorizontalFov(env, device: jint) -> jdouble => car::wb_radar_get_horizontal_fov(tag(device));
    /// `wb_radar_get_vertical_fov` (rad).
    fn radarGetVerticalFov(env, device: jint) -> jdouble => car::wb_radar_get_vertical_fov(tag(device));

    /// `vehicle_road_sensor_enable` (ms).
    fn roadSensorEnable(env, device: jint, period: jint) => car::vehicle_road_sensor_enable(tag(device), period);
    /// `vehicle_road_sensor_disable`.
    fn roadSensorDisable(env, device: jint) => car::vehicle_road_sensor_disable(tag(device));
    /// `vehicle_road_sensor_get_sampling_period` (ms).
    fn roadSensorGetSamplingPeriod(env, device: jint) -> jint => car::vehicle_road_sensor_get_sampling_period(tag(device));
    /// `vehicle_road_sensor_get_lookahead`.
    fn roadSensorGetLookahead(env, device: jint) -> jdouble => car::vehicle_road_sensor_get_lookahead(tag(device));
    /// `vehicle_road_sensor_get_road`.
    fn roadSensorGetRoad(env, device: jint) -> jint => car::vehicle_road_sensor_get_road(tag(device));
    /// `vehicle_road_sensor_get_lane`.
    fn roadSensorGetLane(env, device: jint) -> jint => car::vehicle_road_sensor_get_lane(tag(device));
    /// `vehicle_road_sensor_get_station`.
    fn roadSensorGetStation(env, device: jint) -> jdouble => car::vehicle_road_sensor_get_station(tag(device));
    /// `vehicle_road_sensor_get_lateral_offset`.
    fn roadSensorGetLateralOffset(env, device: jint) -> jdouble => car::vehicle_road_sensor_get_lateral_offset(tag(device));
    /// `vehicle_road_sensor_get_heading_error`.
    fn roadSensorGetHeadingError(env, device: jint) -> jdouble => car::vehicle_road_sensor_get_heading_error(tag(device));
    /// `vehicle_road_sensor_get_curvature`.
    fn roadSensorGetCurvature(env, device: jint) -> jdouble => car::vehicle_road_sensor_get_curvature(tag(device));
    /// `vehicle_road_sensor_get_curvature_ahead`.
    fn roadSensorGetCurvatureAhead(env, device: jint) -> jdouble => car::vehicle_road_sensor_get_curvature_ahead(tag(device));
    /// `vehicle_road_sensor_get_left_line_distance`.
    fn roadSensorGetLeftLineDistance(env, device: jint) -> jdouble => car::vehicle_road_sensor_get_left_line_distance(tag(device));
    /// `vehicle_road_sensor_get_right_line_distance`.
    fn roadSensorGetRightLineDistance(env, device: jint) -> jdouble => car::vehicle_road_sensor_get_right_line_distance(tag(device));
    /// `vehicle_road_sensor_get_left_edge_distance`.
    fn roadSensorGetLeftEdgeDistance(env, device: jint) -> jdouble => car::vehicle_road_sensor_get_left_edge_distance(tag(device));
    /// `vehicle_road_sensor_get_right_edge_distance`.
    fn roadSensorGetRightEdgeDistance(env, device: jint) -> jdouble => car::vehicle_road_sensor_get_right_edge_distance(tag(device));
    /// `vehicle_road_sensor_get_lane_width`.
    fn roadSensorGetLaneWidth(env, device: jint) -> jdouble => car::vehicle_road_sensor_get_lane_width(tag(device));

    /// `wb_camera_enable` (ms).
    fn cameraEnable(env, device: jint, period: jint) => car::wb_camera_enable(tag(device), period);
    /// `wb_camera_disable`.
    fn cameraDisable(env, device: jint) => car::wb_camera_disable(tag(device));
    /// `wb_camera_get_sampling_period` (ms).
    fn cameraGetSamplingPeriod(env, device: jint) -> jint => car::wb_camera_get_sampling_period(tag(device));
    /// `wb_camera_get_width` (pixels).
    fn cameraGetWidth(env, device: jint) -> jint => car::wb_camera_get_width(tag(device));
    /// `wb_camera_get_height` (pixels).
    fn cameraGetHeight(env, device: jint) -> jint => car::wb_camera_get_height(tag(device));
    /// `wb_camera_get_fov` (rad).
    fn cameraGetFov(env, device: jint) -> jdouble => car::wb_camera_get_fov(tag(device));
    /// `wb_camera_get_min_fov` (rad).
    fn cameraGetMinFov(env, device: jint) -> jdouble => car::wb_camera_get_min_fov(tag(device));
    /// `wb_camera_get_max_fov` (rad).
    fn cameraGetMaxFov(env, device: jint) -> jdouble => car::wb_camera_get_max_fov(tag(device));
    /// `wb_camera_save_image` (PNG; `quality` is JPEG's): 0, or -1 with the C API's error.
    fn cameraSaveImage(env, device: jint, filename: JString<'_>, quality: jint) -> jint => {
        let filename = c_string(&mut env, &filename);
        // SAFETY: NULL or a NUL-terminated string that lives until the call returns.
        unsafe { car::wb_camera_save_image(tag(device), c_ptr(filename.as_ref()), quality) }
    };
    /// `wb_camera_get_near` (m).
    fn cameraGetNear(env, device: jint) -> jdouble => car::wb_camera_get_near(tag(device));
    /// `wb_camera_get_image` as Webots' Java gives it: one `int` per pixel, `0xAARRGGBB`
    /// (the C image's BGRA bytes read as a little-endian 32-bit word), row after row.
    fn cameraGetImage(env, device: jint) -> jintArray => {
        let pixels = car::camera_values::wb_camera_get_image(tag(device)).map(|bgra| {
            bgra.chunks_exact(4)
                .map(|p| i32::from_le_bytes([p[0], p[1], p[2], p[3]]))
                .collect::<Vec<_>>()
        });
        int_array(&mut env, pixels.as_deref())
    };

    /// `wb_lidar_enable` (ms).
    fn lidarEnable(env, device: jint, period: jint) => car::wb_lidar_enable(tag(device), period);
    /// `wb_lidar_disable`.
    fn lidarDisable(env, device: jint) => car::wb_lidar_disable(tag(device));
    /// `wb_lidar_get_sampling_period` (ms).
    fn lidarGetSamplingPeriod(env, device: jint) -> jint => car::wb_lidar_get_sampling_period(tag(device));
    /// `wb_lidar_get_range_image` (m, layer after layer).
    fn lidarGetRangeImage(env, device: jint) -> jfloatArray =>
        float_array(&mut env, car::lidar_values::range_image(tag(device)).as_deref());
    /// `wb_lidar_get_layer_range_image` (m).
    fn lidarGetLayerRangeImage(env, device: jint, layer: jint) -> jfloatArray =>
        float_array(&mut env, car::lidar_values::layer_range_image(tag(device), layer).as_deref());
    /// `wb_lidar_get_horizontal_resolution`.
    fn lidarGetHorizontalResolution(env, device: jint) -> jint => car::wb_lidar_get_horizontal_resolution(tag(device));
    /// `wb_lidar_get_number_of_layers`.
    fn lidarGetNumberOfLayers(env, device: jint) -> jint => car::wb_lidar_get_number_of_layers(tag(device));
    /// `wb_lidar_get_frequency` (Hz).
    fn lidarGetFrequency(env, device: jint) -> jdouble => car::wb_lidar_get_frequency(tag(device));
    /// `wb_lidar_set_frequency` (Hz, refused with the C API's error outside the lidar's range).
    fn lidarSetFrequency(env, device: jint, frequency: jdouble) => car::wb_lidar_set_frequency(tag(device), frequency);
    /// `wb_lidar_get_min_frequency` (Hz).
    fn lidarGetMinFrequency(env, device: jint) -> jdouble => car::wb_lidar_get_min_frequency(tag(device));
    /// `wb_lidar_get_max_frequency` (Hz).
    fn lidarGetMaxFrequency(env, device: jint) -> jdouble => car::wb_lidar_get_max_frequency(tag(device));
    /// `wb_lidar_get_fov` (rad).
    fn lidarGetFov(env, device: jint) -> jdouble => car::wb_lidar_get_fov(tag(device));
    /// `wb_lidar_get_vertical_fov` (rad).
    fn lidarGetVerticalFov(env, device: jint) -> jdouble => car::wb_lidar_get_vertical_fov(tag(device));
    /// `wb_lidar_get_min_range` (m).
    fn lidarGetMinRange(env, device: jint) -> jdouble => car::wb_lidar_get_min_range(tag(device));
    /// `wb_lidar_get_max_range` (m).
    fn lidarGetMaxRange(env, device: jint) -> jdouble => car::wb_lidar_get_max_range(tag(device));
}

/// The three values of the gyro, accelerometer or compass `device` as a Java `double[]`.
fn triaxial(env: &mut jni::JNIEnv<'_>, kind: DeviceKind, device: jint) -> jdoubleArray {
    double_array(
        env,
        car::values::triaxial_values(kind, tag(device))
            .as_ref()
            .map(|v| &v[..]),
    )
}
