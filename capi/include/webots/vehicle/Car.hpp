// webots/vehicle/Car.hpp: header-only C++ wrapper of the car library (webots/vehicle/car.h).
//
// Part of the `capi` crate. SPDX-License-Identifier: MIT OR Apache-2.0
//
// Same class, method names and enumerations as Webots' webots::Car, a webots::Driver that adds
// the car characteristics and low-level settings. Units: lengths in m, angles in rad (positive
// steers right), wheel speeds in rad/s, time in s. Requires C++11 (see Driver.hpp for the
// differences from Webots).

#ifndef WB_VEHICLE_CAR_HPP
#define WB_VEHICLE_CAR_HPP

#include <webots/vehicle/Driver.hpp>
#include <webots/vehicle/car.h>

namespace webots {
  // A Driver with access to the car library. Like Driver, a singleton: create exactly one.
  class Car : public Driver {
  public:
    // Driven axle(s) (same values as WbuCarType).
    typedef enum { TRACTION = 0, PROPULSION, FOUR_BY_FOUR } Type;

    // Engine model (same values as WbuCarEngineType).
    typedef enum { COMBUSTION_ENGINE = 0, ELECTRIC_ENGINE, PARALLEL_HYBRID_ENGINE, POWER_SPLIT_HYBRID_ENGINE } EngineType;

    // Wheel index (same values as WbuCarWheelIndex); WHEEL_NB (4) is the number of wheels.
    typedef enum { WHEEL_FRONT_RIGHT = 0, WHEEL_FRONT_LEFT, WHEEL_REAR_RIGHT, WHEEL_REAR_LEFT, WHEEL_NB } WheelIndex;

    // Initialises the driver and car libraries.
    Car() : Driver() {}
    virtual ~Car() {}

    // Driven axle(s): TRACTION (front), PROPULSION (rear) or FOUR_BY_FOUR.
    Type getType() { return static_cast<Type>(wbu_car_get_type()); }
    // Engine model (Car field engineType).
    EngineType getEngineType() { return static_cast<EngineType>(wbu_car_get_engine_type()); }

    // Indicator blink period in s: duration of each on and each off phase (> 0).
    void setIndicatorPeriod(double period) { wbu_car_set_indicator_period(period); }
    // Indicator blink period in s (0.34 by default).
    double getIndicatorPeriod() { return wbu_car_get_indicator_period(); }

    // State of the reversing lights LED.
    bool getBackwardsLights() { return wbu_car_get_backwards_lights(); }
    // State of the brake lights LED.
    bool getBrakeLights() { return wbu_car_get_brake_lights(); }

    // Distance between the front wheels, m.
    double getTrackFront() { return wbu_car_get_track_front(); }
    // Distance between the rear wheels, m.
    double getTrackRear() { return wbu_car_get_track_rear(); }
    // Distance between the axles, m.
    double getWheelbase() { return wbu_car_get_wheelbase(); }
    // Front tyre radius, m (-1 if unknown).
    double getFrontWheelRadius() { return wbu_car_get_front_wheel_radius(); }
    // Rear tyre radius, m (-1 if unknown).
    double getRearWheelRadius() { return wbu_car_get_rear_wheel_radius(); }

    // Wheel rotation in rad (position sensor).
    double getWheelEncoder(WheelIndex wheel) { return wbu_car_get_wheel_encoder(static_cast<WbuCarWheelIndex>(wheel)); }
    // Wheel rotation speed in rad/s measured by the last step().
    double getWheelSpeed(WheelIndex wheel) { return wbu_car_get_wheel_speed(static_cast<WbuCarWheelIndex>(wheel)); }
    // Steers the front left wheel directly, rad (no Ackermann geometry).
    void setLeftSteeringAngle(double angle) { wbu_car_set_left_steering_angle(angle); }
    // Steers the front right wheel directly, rad (no Ackermann geometry).
    void setRightSteeringAngle(double angle) { wbu_car_set_right_steering_angle(angle); }
    // Measured front right steering angle, rad.
    double getRightSteeringAngle() { return wbu_car_get_right_steering_angle(); }
    // Measured front left steering angle, rad.
    double getLeftSteeringAngle() { return wbu_car_get_left_steering_angle(); }

    // Limited-slip differential on (default) or off.
    void enableLimitedSlipDifferential(bool enable) { wbu_car_enable_limited_slip_differential(enable); }
    // Indicator auto-cancelling on (default) or off.
    void enableIndicatorAutoDisabling(bool enable) { wbu_car_enable_indicator_auto_disabling(enable); }
  };
}  // namespace webots

#endif  // WB_VEHICLE_CAR_HPP
