// webots/vehicle/Driver.hpp: header-only C++ wrapper of the driver library (webots/vehicle/driver.h).
//
// Part of the `capi` crate. SPDX-License-Identifier: MIT OR Apache-2.0
//
// Same class, method names and enumerations as Webots' webots::Driver. Units: angles in rad
// (positive steers right), speeds in km/h, engine speed in rpm, time in s.
//
// Differences from Webots:
// * Webots' Driver derives from webots::Supervisor (itself a webots::Robot). This simulator has
//   no Supervisor or Robot C++ classes, so Driver derives from nothing; of the Robot methods it
//   offers getTime(), getBasicTimeStep(), getNumberOfDevices(), the battery sensor
//   (batterySensorEnable, batterySensorDisable, getBatterySensorSamplingPeriod,
//   getBatteryValue) and the typed device getters of
//   the sensors this simulator has (getGPS, getInertialUnit, getGyro, getAccelerometer,
//   getCompass, getDistanceSensor, getRadar, getLidar, getCamera, getDisplay, getKeyboard, and
//   the project extension's getRoadSensor; nullptr for a name the car lacks or a device of
//   another type).
// * Header-only: every method is inline and calls the C function of the same meaning, so only
//   libdriver.so and libcar.so are needed at link time (no libCppDriver).
// * The destructor releases the singleton, so a new Driver may be created after the previous
//   one was destroyed (Webots exits in that case too).
// Requires C++11.

#ifndef WB_VEHICLE_DRIVER_HPP
#define WB_VEHICLE_DRIVER_HPP

#if !(__cplusplus >= 201103L || (defined(_MSVC_LANG) && _MSVC_LANG >= 201103L))
#error "webots/vehicle/Driver.hpp requires C++11 or later"
#endif

// Declares the C functions without defining the global C enumerators (OFF, LEFT, SPEED...), so
// that they do not clash with the controller's own names.
#define WB_VEHICLE_DRIVER_HPP_NO_ENUMERATORS
#include <webots/vehicle/driver.h>
#undef WB_VEHICLE_DRIVER_HPP_NO_ENUMERATORS
#include <webots/Accelerometer.hpp>
#include <webots/Camera.hpp>
#include <webots/Compass.hpp>
#include <webots/Display.hpp>
#include <webots/DistanceSensor.hpp>
#include <webots/GPS.hpp>
#include <webots/Gyro.hpp>
#include <webots/InertialUnit.hpp>
#include <webots/Keyboard.hpp>
#include <webots/Lidar.hpp>
#include <webots/Radar.hpp>
#include <webots/vehicle/RoadSensor.hpp>
#include <webots/nodes.h>
#include <webots/robot.h>

#include <cstdlib>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

namespace webots {
  // The driver of a Car: steering, cruise control or throttle and gears, brake, lights,
  // indicators, wipers. A singleton: create exactly one (or one webots::Car) at the start of
  // the controller; a second one prints "Only one instance of the Driver class should be
  // created" and exits the process, as in Webots.
  class Driver {
  public:
    // Indicator lever state (same values as the C enumeration: 0, 1, 2).
    typedef enum { INDICATOR_OFF, INDICATOR_RIGHT, INDICATOR_LEFT } IndicatorState;

    // Control mode: SPEED (cruise control) = 0, TORQUE (engine model) = 1. The C library's
    // UNDEFINED_CONTROL_MODE (-1, before either is chosen) has no name here, as in Webots:
    // getControlMode() then returns ControlMode(-1).
    typedef enum { SPEED, TORQUE } ControlMode;

    // Wiper mode (same values as the C enumeration: 0 to 3).
    typedef enum { DOWN, SLOW, NORMAL, FAST } WiperMode;

    // true if the robot is a Car whose parameters the libraries can read; callable before any
    // Driver exists (creating a Driver on another robot exits the process).
    static bool isInitialisationPossible() { return wbu_driver_initialization_is_possible(); }

    // Initialises the driver and car libraries (wbu_driver_init()).
    Driver() {
      if (instanceSlot() != nullptr) {
        std::cerr << "Only one instance of the Driver class should be created" << std::endl;
        std::exit(-1);
      }
      instanceSlot() = this;
      wbu_driver_init();
    }

    // The existing Driver, or a new one if none exists yet.
    static Driver *getDriverInstance() {
      if (instanceSlot() != nullptr)
        return instanceSlot();
      return new Driver();
    }

    // Releases the libraries (wbu_driver_cleanup()).
    virtual ~Driver() {
      wbu_driver_cleanup();
      if (instanceSlot() == this)
        instanceSlot() = nullptr;
    }

    // A copy would clean the shared libraries up twice.
    Driver(const Driver &) = delete;
    Driver &operator=(const Driver &) = delete;

    // Runs one basic time step (wbu_driver_step()). Returns 0, or -1 when the simulation ended.
    virtual int step() { return wbu_driver_step(); }

    // Simulation time in s (wb_robot_get_time()).
    double getTime() { return wb_robot_get_time(); }

    // The world's basicTimeStep in ms (wb_robot_get_basic_time_step()).
    double getBasicTimeStep() { return wb_robot_get_basic_time_step(); }

    // The number of devices (wb_robot_get_number_of_devices()).
    int getNumberOfDevices() { return wb_robot_get_number_of_devices(); }

    // Webots' Robot battery sensor (wb_robot_battery_sensor_*): the battery's energy in J.
    void batterySensorEnable(int samplingPeriod) { wb_robot_battery_sensor_enable(samplingPeriod); }
    void batterySensorDisable() { wb_robot_battery_sensor_disable(); }
    int getBatterySensorSamplingPeriod() const { return wb_robot_battery_sensor_get_sampling_period(); }
    double getBatteryValue() const { return wb_robot_battery_sensor_get_value(); }
    // The sensors of the car by name, owned by the Driver; nullptr if it has none of that type.
    GPS *getGPS(const std::string &name) { return device<GPS>(name, WB_NODE_GPS); }
    InertialUnit *getInertialUnit(const std::string &name) { return device<InertialUnit>(name, WB_NODE_INERTIAL_UNIT); }
    Gyro *getGyro(const std::string &name) { return device<Gyro>(name, WB_NODE_GYRO); }
    Accelerometer *getAccelerometer(const std::string &name) { return device<Accelerometer>(name, WB_NODE_ACCELEROMETER); }
    Compass *getCompass(const std::string &name) { return device<Compass>(name, WB_NODE_COMPASS); }
    Camera *getCamera(const std::string &name) { return device<Camera>(name, WB_NODE_CAMERA); }
    Display *getDisplay(const std::string &name) { return device<Display>(name, WB_NODE_DISPLAY); }
    // The keyboard, owned by the Driver (its keys: the world's programme's).
    Keyboard *getKeyboard() {
      if (!keyboard_)
        keyboard_.reset(new Keyboard());
      return keyboard_.get();
    }
    DistanceSensor *getDistanceSensor(const std::string &name) {
      return device<DistanceSensor>(name, WB_NODE_DISTANCE_SENSOR);
    }
    Radar *getRadar(const std::string &name) { return device<Radar>(name, WB_NODE_RADAR); }
    Lidar *getLidar(const std::string &name) { return device<Lidar>(name, WB_NODE_LIDAR); }
    // The project's RoadSensor extension (webots/vehicle/RoadSensor.hpp).
    RoadSensor *getRoadSensor(const std::string &name) { return device<RoadSensor>(name, RoadSensor::NODE_TYPE); }

    // Steers with Ackermann geometry: rad, positive right, negative left.
    void setSteeringAngle(double steeringAngle) { wbu_driver_set_steering_angle(steeringAngle); }
    // Measured steering angle in rad (mean of the two front-wheel steering sensors).
    double getSteeringAngle() { return wbu_driver_get_steering_angle(); }

    // Cruise control (SPEED mode) at `speed` km/h (negative: backwards).
    void setCruisingSpeed(double speed) { wbu_driver_set_cruising_speed(speed); }
    // Target of the last setCruisingSpeed(), km/h.
    double getTargetCruisingSpeed() { return wbu_driver_get_target_cruising_speed(); }

    // Current speed in km/h, from the driven wheels' measured speed.
    double getCurrentSpeed() { return wbu_driver_get_current_speed(); }

    // TORQUE mode with throttle in [0, 1] (clamped with a warning).
    void setThrottle(double throttle) { wbu_driver_set_throttle(throttle); }
    // Throttle in [0, 1].
    double getThrottle() { return wbu_driver_get_throttle(); }

    // Brake in [0, 1] (clamped with a warning); 1 brakes each wheel with brakeCoefficient N*m.
    void setBrakeIntensity(double intensity) { wbu_driver_set_brake_intensity(intensity); }
    // Brake in [0, 1].
    double getBrakeIntensity() { return wbu_driver_get_brake_intensity(); }

    // Indicator lever: INDICATOR_OFF, INDICATOR_RIGHT or INDICATOR_LEFT.
    void setIndicator(IndicatorState state) {
      wbu_driver_set_indicator(static_cast<WbuDriverIndicatorState>(state));
    }
    // Hazard flashers on (true) or off (false).
    void setHazardFlashers(bool state) { wbu_driver_set_hazard_flashers(state); }

    // Indicator lever state (back to INDICATOR_OFF once auto-cancelled).
    IndicatorState getIndicator() { return static_cast<IndicatorState>(wbu_driver_get_indicator()); }
    // true if the hazard flashers are on.
    bool getHazardFlashers() { return wbu_driver_get_hazard_flashers(); }

    // Dipped beams (front and rear lights) on or off.
    void setDippedBeams(bool state) { wbu_driver_set_dipped_beams(state); }
    // Anti-fog lights on or off (no effect if the car has none).
    void setAntifogLights(bool state) { wbu_driver_set_antifog_lights(state); }

    // Last state given to setDippedBeams().
    bool getDippedBeams() { return wbu_driver_get_dipped_beams(); }
    // State of the anti-fog lights LED (false if the car has none).
    bool getAntifogLights() { return wbu_driver_get_antifog_lights(); }

    // Estimated engine speed in rpm (warning and 0 in SPEED mode).
    double getRpm() { return wbu_driver_get_rpm(); }
    // Engaged gear: -1 reverse, 0 neutral, >= 1 forward (warning and 0 in SPEED mode).
    int getGear() { return wbu_driver_get_gear(); }
    // Engages a gear: -1 reverse, 0 neutral, 1 to getGearNumber() - 1 forward.
    void setGear(int gear) { wbu_driver_set_gear(gear); }
    // Number of gearRatio entries (forward gears plus reverse).
    int getGearNumber() { return wbu_driver_get_gear_number(); }
    // SPEED or TORQUE (ControlMode(-1) before either is chosen).
    ControlMode getControlMode() { return static_cast<ControlMode>(wbu_driver_get_control_mode()); }

    // Wiper mode: DOWN, SLOW, NORMAL or FAST (ignored if the car has no wipers).
    void setWiperMode(WiperMode mode) { wbu_driver_set_wiper_mode(static_cast<WbuDriverWiperMode>(mode)); }
    // Current wiper mode.
    WiperMode getWiperMode() { return static_cast<WiperMode>(wbu_driver_get_wiper_mode()); }

    // Deprecated: prints a warning, then setBrakeIntensity(brake).
    void setBrake(double brake) {
      std::cerr << "Warning: Deprecated 'setBrake' use 'setBrakeIntensity' instead." << std::endl;
      setBrakeIntensity(brake);
    }

    // Deprecated: prints a warning, then setWiperMode(mode).
    void setWipersMode(WiperMode mode) {
      std::cerr << "Warning: Deprecated 'setWipersMode' use 'setWiperMode' instead." << std::endl;
      setWiperMode(mode);
    }
    // Deprecated: prints a warning, then returns getWiperMode().
    WiperMode getWipersMode() {
      std::cerr << "Warning: Deprecated 'getWipersMode' use 'getWiperMode' instead." << std::endl;
      return getWiperMode();
    }

  private:
    // The device `name` as a T if its node type is `type`, created once and kept.
    template <class T> T *device(const std::string &name, int type) {
      const WbDeviceTag tag = wb_robot_get_device(name.c_str());
      if (tag == 0 || wb_device_get_node_type(tag) != type)
        return nullptr;
      for (const std::unique_ptr<Device> &d : devices_)
        if (d->getTag() == tag)
          return static_cast<T *>(d.get());
      devices_.emplace_back(new T(tag));
      return static_cast<T *>(devices_.back().get());
    }

    std::vector<std::unique_ptr<Device>> devices_;
    std::unique_ptr<Keyboard> keyboard_;

    // The driver step takes no duration (it always runs one basic time step); as in Webots,
    // step(int) cannot be called on a Driver.
    int step(int duration) = delete;

    // The singleton, shared by every translation unit (a function-local static of an inline
    // function has a single instance per program).
    static Driver *&instanceSlot() {
      static Driver *instance = nullptr;
      return instance;
    }
  };
}  // namespace webots

#endif  // WB_VEHICLE_DRIVER_HPP
