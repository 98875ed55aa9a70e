//! `VehicleNative`: the driver library (`wbu_driver_*`) and the car library (`wbu_car_*`) for
//! `com.cyberbotics.webots.controller.vehicle.Driver` and `Car`. Units are the C API's: rad
//! (positive steers right), km/h, rev/min, s, m, rad/s.

use jni::sys::{jboolean, jdouble, jint};

natives! { "com_cyberbotics_webots_controller_vehicle_VehicleNative";
    /// `wbu_driver_initialization_is_possible`.
    fn driverInitializationIsPossible(env) -> jboolean => car::vehicle_capi_driver_initialization_is_possible();
    /// `wbu_driver_init` (which initialises the car library too).
    fn driverInit(env) => car::vehicle_capi_driver_init();
    /// `wbu_driver_cleanup`.
    fn driverCleanup(env) => car::vehicle_capi_driver_cleanup();
    /// `wbu_driver_step`: 0, or -1 once the world's duration has elapsed.
    fn driverStep(env) -> jint => car::vehicle_capi_driver_step();
    /// `wbu_driver_set_steering_angle` (rad).
    fn setSteeringAngle(env, angle: jdouble) => car::vehicle_capi_driver_set_steering_angle(angle);
    /// `wbu_driver_get_steering_angle` (rad).
    fn getSteeringAngle(env) -> jdouble => car::vehicle_capi_driver_get_steering_angle();
    /// `wbu_driver_set_cruising_speed` (km/h).
    fn setCruisingSpeed(env, speed: jdouble) => car::vehicle_capi_driver_set_cruising_speed(speed);
    /// `wbu_driver_get_target_cruising_speed` (km/h).
    fn getTargetCruisingSpeed(env) -> jdouble => car::vehicle_capi_driver_get_target_cruising_speed();
    /// `wbu_driver_get_current_speed` (km/h).
    fn getCurrentSpeed(env) -> jdouble => car::vehicle_capi_driver_get_current_speed();
    /// `wbu_driver_set_throttle` (0..1).
    fn setThrottle(env, throttle: jdouble) => car::vehicle_capi_driver_set_throttle(throttle);
    /// `wbu_driver_get_throttle` (0..1).
    fn getThrottle(env) -> jdouble => car::vehicle_capi_driver_get_throttle();
    /// `wbu_driver_set_brake_intensity` (0..1).
    fn setBrakeIntensity(env, intensity: jdouble) => car::vehicle_capi_driver_set_brake_intensity(intensity);
    /// `wbu_driver_get_brake_intensity` (0..1).
    fn getBrakeIntensity(env) -> jdouble => car::vehicle_capi_driver_get_brake_intensity();
    /// `wbu_driver_set_brake`, the old name of `set_brake_intensity`.
    fn setBrake(env, intensity: jdouble) => car::vehicle_capi_driver_set_brake(intensity);
    /// `wbu_driver_set_indicator` (`INDICATOR_*`).
    fn setIndicator(env, state: jint) => car::vehicle_capi_driver_set_indicator(state);
    /// `wbu_driver_get_indicator`.
    fn getIndicator(env) -> jint => car::vehicle_capi_driver_get_indicator();
    /// `wbu_driver_set_hazard_flashers`.
    fn setHazardFlashers(env, state: jboolean) => car::vehicle_capi_driver_set_hazard_flashers(state);
    /// `wbu_driver_get_hazard_flashers`.
    fn getHazardFlashers(env) -> jboolean => car::vehicle_capi_driver_get_hazard_flashers();
    /// `wbu_driver_set_dipped_beams`.
    fn setDippedBeams(env, state: jboolean) => car::vehicle_capi_driver_set_dipped_beams(state);
    /// `wbu_driver_get_dipped_beams`.
    fn getDippedBeams(env) -> jboolean => car::vehicle_capi_driver_get_dipped_beams();
    /// `wbu_driver_set_antifog_lights`.
    fn setAntifogLights(env, state: jboolean) => car::vehicle_capi_driver_set_antifog_lights(state);
    /// `wbu_driver_get_antifog_lights`.
    fn getAntifogLights(env) -> jboolean => car::vehicle_capi_driver_get_antifog_lights();
    /// `wbu_driver_get_rpm` (rev/min).
    fn getRpm(env) -> jdouble => car::vehicle_capi_driver_get_rpm();
    /// `wbu_driver_get_gear` (-1 reverse, 0 neutral).
    fn getGear(env) -> jint => car::vehicle_capi_driver_get_gear();
    /// `wbu_driver_set_gear`.
    fn setGear(env, gear: jint) => car::vehicle_capi_driver_set_gear(gear);
    /// `wbu_driver_get_gear_number`.
    fn getGearNumber(env) -> jint => car::vehicle_capi_driver_get_gear_number();
    /// `wbu_driver_get_control_mode` (-1 before a mode is set, 0 speed, 1 torque).
    fn getControlMode(env) -> jint => car::vehicle_capi_driver_get_control_mode();
    /// `wbu_driver_set_wiper_mode` (`DOWN`..`FAST`).
    fn setWiperMode(env, mode: jint) => car::vehicle_capi_driver_set_wiper_mode(mode);
    /// `wbu_driver_get_wiper_mode`.
    fn getWiperMode(env) -> jint => car::vehicle_capi_driver_get_wiper_mode();
    /// `wbu_driver_set_wipers_mode`, the old name of `set_wiper_mode`.
    fn setWipersMode(env, mode: jint) => car::vehicle_capi_driver_set_wipers_mode(mode);
    /// `wbu_driver_get_wipers_mode`, the old name of `get_wiper_mode`.
    fn getWipersMode(env) -> jint => car::vehicle_capi_driver_get_wipers_mode();

    /// `wbu_car_get_type` (`TRACTION`, `PROPULSION`, `FOUR_BY_FOUR`).
    fn getType(env) -> jint => car::wbu_car_get_type();
    /// `wbu_car_get_engine_type`.
    fn getEngineType(env) -> jint => car::wbu_car_get_engine_type();
    /// `wbu_car_set_indicator_period` (s).
    fn setIndicatorPeriod(env, period: jdouble) => car::wbu_car_set_indicator_period(period);
    /// `wbu_car_get_indicator_period` (s).
    fn getIndicatorPeriod(env) -> jdouble => car::wbu_car_get_indicator_period();
    /// `wbu_car_get_backwards_lights`.
    fn getBackwardsLights(env) -> jboolean => car::wbu_car_get_backwards_lights();
    /// `wbu_car_get_brake_lights`.
    fn getBrakeLights(env) -> jboolean => car::wbu_car_get_brake_lights();
    /// `wbu_car_get_track_front` (m).
    fn getTrackFront(env) -> jdouble => car::wbu_car_get_track_front();
    /// `wbu_car_get_track_rear` (m).
    fn getTrackRear(env) -> jdouble => car::wbu_car_get_track_rear();
    /// `wbu_car_get_wheelbase` (m).
    fn getWheelbase(env) -> jdouble => car::wbu_car_get_wheelbase();
    /// `wbu_car_get_front_wheel_radius` (m).
    fn getFrontWheelRadius(env) -> jdouble => car::wbu_car_get_front_wheel_radius();
    /// `wbu_car_get_rear_wheel_radius` (m).
    fn getRearWheelRadius(env) -> jdouble => car::wbu_car_get_rear_wheel_radius();
    /// `wbu_car_get_wheel_encoder` (rad).
    fn getWheelEncoder(env, wheel: jint) -> jdouble => car::wbu_car_get_wheel_encoder(wheel);
    /// `wbu_car_get_wheel_speed` (rad/s).
    fn getWheelSpeed(env, wheel: jint) -> jdouble => car::wbu_car_get_wheel_speed(wheel);
    /// `wbu_car_set_left_steering_angle` (rad).
    fn setLeftSteeringAngle(env, angle: jdouble) => car::wbu_car_set_left_steering_angle(angle);
    /// `wbu_car_set_right_steering_angle` (rad).
    fn setRightSteeringAngle(env, angle: jdouble) => car::wbu_car_set_right_steering_angle(angle);
    /// `wbu_car_get_left_steering_angle` (rad).
    fn getLeftSteeringAngle(env) -> jdouble => car::wbu_car_get_left_steering_angle();
    /// `wbu_car_get_right_steering_angle` (rad).
    fn getRightSteeringAngle(env) -> jdouble => car::wbu_car_get_right_steering_angle();
    /// `wbu_car_enable_limited_slip_differential`.
    fn enableLimitedSlipDifferential(env, enable: jboolean) => car::wbu_car_enable_limited_slip_differential(enable);
    /// `wbu_car_enable_indicator_auto_disabling`.
    fn enableIndicatorAutoDisabling(env, enable: jboolean) => car::wbu_car_enable_indicator_auto_disabling(enable);
}
