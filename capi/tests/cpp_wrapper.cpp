// cpp_wrapper: the header-only C++ wrapper (webots::Car, webots::Driver) driving the BmwX5.
//
// World: the default one (VEHICLE_WORLD unset, or VEHICLE_WORLD=BmwX5). Compile as C++11 or
// later against the same headers, link with libdriver and libcar.
//
// Golden values (BmwX5: L = 2.995 m, Tf = 1.628 m, r = 0.374 m, traction):
//   steering a = -0.15 rad (left): cot a = -6.604261, Tf / (2 L) = 0.271786,
//     right (outer) wheel atan(1 / (-6.604261 - 0.271786)) = -0.144165 rad,
//     left (inner) wheel  atan(1 / (-6.604261 + 0.271786)) = -0.156323 rad,
//     getSteeringAngle() = mean = -0.150244 rad;
//   front ratio rho = Rr / (Rl + Rr) with Rr = L / sin(-0.144165), Rl = L / sin(-0.156323):
//     rho = 0.520079; at 30 km/h: right 2 * 30 * rho / 3.6 / 0.374 = 23.176419 rad/s,
//     left 2 * 30 * (1 - rho) / 3.6 / 0.374 = 21.386861 rad/s; current speed 30 km/h.
//   second gear: rpm = |mean wheel speed * 60 / (2 pi) * 8|.
// Tolerances as in cruise_bmw.c: 2 % on settled speeds, 0.01 rad on steering angles.

#include <webots/vehicle/Car.hpp>

#include "check.h"

// Driver.hpp and Car.hpp must not leak the C enumerators (OFF, RIGHT, LEFT, SPEED, DOWN...) into
// the global namespace: controllers often use these names themselves. This declaration fails to
// compile if they leak.
enum ControllerOwnNames { OFF, RIGHT, LEFT, SPEED, TORQUE, DOWN, SLOW, NORMAL, FAST, UNDEFINED_CONTROL_MODE };

using webots::Car;
using webots::Driver;

// Same values as the C enumerations (they cross the C API by value).
static_assert(Driver::INDICATOR_OFF == 0 && Driver::INDICATOR_RIGHT == 1 && Driver::INDICATOR_LEFT == 2,
              "IndicatorState values");
static_assert(Driver::SPEED == 0 && Driver::TORQUE == 1, "ControlMode values");
static_assert(Driver::DOWN == 0 && Driver::SLOW == 1 && Driver::NORMAL == 2 && Driver::FAST == 3, "WiperMode values");
static_assert(Car::TRACTION == 0 && Car::PROPULSION == 1 && Car::FOUR_BY_FOUR == 2, "Type values");
static_assert(Car::COMBUSTION_ENGINE == 0 && Car::ELECTRIC_ENGINE == 1 && Car::PARALLEL_HYBRID_ENGINE == 2 &&
                Car::POWER_SPLIT_HYBRID_ENGINE == 3,
              "EngineType values");
static_assert(Car::WHEEL_FRONT_RIGHT == 0 && Car::WHEEL_FRONT_LEFT == 1 && Car::WHEEL_REAR_RIGHT == 2 &&
                Car::WHEEL_REAR_LEFT == 3 && Car::WHEEL_NB == 4,
              "WheelIndex values");

namespace {
  void run(Car &car, double seconds) {
    const int steps = static_cast<int>(seconds * 1000.0 / car.getBasicTimeStep() + 0.5);
    for (int i = 0; i < steps; ++i) {
      if (car.step() == -1)
        check_fatal("Car::step() returned -1 (simulation ended) at t = %g s", car.getTime());
    }
  }

  double meanWheelSpeed(Car &car) {
    return (car.getWheelSpeed(Car::WHEEL_FRONT_RIGHT) + car.getWheelSpeed(Car::WHEEL_FRONT_LEFT) +
            car.getWheelSpeed(Car::WHEEL_REAR_RIGHT) + car.getWheelSpeed(Car::WHEEL_REAR_LEFT)) /
           4.0;
  }
}  // namespace

int main() {
  check_begin("cpp_wrapper");
  check_true(Driver::isInitialisationPossible(), "Driver::isInitialisationPossible() on the BmwX5");

  Car car;
  check_true(Driver::getDriverInstance() == &car, "Driver::getDriverInstance() is the Car");
  if (car.getType() != Car::TRACTION || check_abs(car.getWheelbase() - 2.995) > 1e-9)
    check_fatal("this program needs VEHICLE_WORLD=BmwX5 (or unset); the loaded car has type %d, wheelbase %g m",
                static_cast<int>(car.getType()), car.getWheelbase());
  check_int("Car::getType()", car.getType(), Car::TRACTION);
  check_int("Car::getEngineType()", car.getEngineType(), Car::COMBUSTION_ENGINE);
  check_close("Car::getWheelbase() (m)", car.getWheelbase(), 2.995, 1e-9);
  check_close("Car::getTrackFront() (m)", car.getTrackFront(), 1.628, 1e-9);
  check_close("Car::getTrackRear() (m)", car.getTrackRear(), 1.628, 1e-9);
  check_close("Car::getFrontWheelRadius() (m)", car.getFrontWheelRadius(), 0.374, 1e-9);
  check_close("Car::getRearWheelRadius() (m)", car.getRearWheelRadius(), 0.374, 1e-9);
  check_int("Driver::getGearNumber()", car.getGearNumber(), 6);
  check_close("Car::getIndicatorPeriod() (s)", car.getIndicatorPeriod(), 0.34, 1e-12);
  check_close("Driver::getBasicTimeStep() (ms)", car.getBasicTimeStep(), 10.0, 0.0);
  // The default world's BmwX5 has its 27 car-library tags and no sensor.
  check_int("Driver::getNumberOfDevices()", car.getNumberOfDevices(), 27);
  check_true(car.getGPS("gps") == nullptr, "Driver::getGPS(\"gps\") is nullptr without a GPS");
  check_true(car.getCompass("right_steer") == nullptr, "Driver::getCompass(\"right_steer\") is nullptr (a motor)");
  check_true(webots::Device("brake_lights").getNodeType() == WB_NODE_LED, "brake_lights is an LED");

  // Cruise control, turning left.
  car.setCruisingSpeed(30.0);
  car.setSteeringAngle(-0.15);
  run(car, 8.0);
  check_int("Driver::getControlMode()", car.getControlMode(), Driver::SPEED);
  check_close("Driver::getTargetCruisingSpeed() (km/h)", car.getTargetCruisingSpeed(), 30.0, 0.0);
  check_rel("Driver::getCurrentSpeed() (km/h)", car.getCurrentSpeed(), 30.0, 0.02);
  check_close("Car::getRightSteeringAngle() (rad)", car.getRightSteeringAngle(), -0.144165, 0.01);
  check_close("Car::getLeftSteeringAngle() (rad)", car.getLeftSteeringAngle(), -0.156323, 0.01);
  check_close("Driver::getSteeringAngle() (rad)", car.getSteeringAngle(), -0.150244, 0.01);
  check_rel("Car::getWheelSpeed(WHEEL_FRONT_RIGHT) (rad/s)", car.getWheelSpeed(Car::WHEEL_FRONT_RIGHT), 23.176419, 0.02);
  check_rel("Car::getWheelSpeed(WHEEL_FRONT_LEFT) (rad/s)", car.getWheelSpeed(Car::WHEEL_FRONT_LEFT), 21.386861, 0.02);
  check_true(car.getWheelEncoder(Car::WHEEL_REAR_LEFT) > 0.0, "Car::getWheelEncoder(WHEEL_REAR_LEFT) = %g rad advanced",
             car.getWheelEncoder(Car::WHEEL_REAR_LEFT));
  check_close("Driver::getTime() after 8 s (s)", car.getTime(), 8.0, 0.005);

  // The left indicator cancels once the steering comes back 0.1 rad from -0.15.
  car.setIndicator(Driver::INDICATOR_LEFT);
  check_int("Driver::getIndicator()", car.getIndicator(), Driver::INDICATOR_LEFT);
  car.setSteeringAngle(0.0);
  check_int("Driver::getIndicator() after steering back to 0", car.getIndicator(), Driver::INDICATOR_OFF);

  // Torque mode, second gear.
  car.setGear(2);
  car.setThrottle(0.3);
  check_int("Driver::getControlMode() after setThrottle", car.getControlMode(), Driver::TORQUE);
  check_int("Driver::getGear()", car.getGear(), 2);
  check_close("Driver::getThrottle()", car.getThrottle(), 0.3, 0.0);
  run(car, 1.0);
  const double expected_rpm = check_abs(meanWheelSpeed(car) * 60.0 / 6.283185307179586 * 8.0);
  check_close("Driver::getRpm() in second gear (rpm)", car.getRpm(), expected_rpm, 1e-5 * expected_rpm + 1e-6);
  check_true(car.getRpm() > 0.0, "Driver::getRpm() = %g rpm while moving in gear", car.getRpm());

  // Brake and lights.
  car.setBrakeIntensity(0.5);
  check_close("Driver::getBrakeIntensity()", car.getBrakeIntensity(), 0.5, 0.0);
  run(car, 0.1);
  check_true(car.getBrakeLights(), "Car::getBrakeLights() while braking");
  car.setBrakeIntensity(0.0);
  run(car, 0.1);
  check_true(!car.getBrakeLights(), "Car::getBrakeLights() off after releasing");
  car.setGear(-1);
  run(car, 0.1);
  check_true(car.getBackwardsLights(), "Car::getBackwardsLights() in reverse gear");
  car.setGear(1);
  car.setDippedBeams(true);
  check_true(car.getDippedBeams(), "Driver::getDippedBeams()");
  car.setAntifogLights(true);
  run(car, 0.1);
  check_true(car.getAntifogLights(), "Driver::getAntifogLights()");
  check_true(!car.getBackwardsLights(), "Car::getBackwardsLights() off in first gear");
  car.setHazardFlashers(true);
  check_true(car.getHazardFlashers(), "Driver::getHazardFlashers()");
  car.setHazardFlashers(false);
  car.setIndicatorPeriod(0.5);
  check_close("Car::getIndicatorPeriod() after set (s)", car.getIndicatorPeriod(), 0.5, 0.0);

  // Wipers, including the deprecated names (they print a warning on stderr).
  car.setWiperMode(Driver::NORMAL);
  check_int("Driver::getWiperMode()", car.getWiperMode(), Driver::NORMAL);
  car.setWipersMode(Driver::FAST);
  check_int("deprecated Driver::getWipersMode()", car.getWipersMode(), Driver::FAST);
  car.setWiperMode(Driver::DOWN);
  car.setBrake(0.2);
  check_close("Driver::getBrakeIntensity() after deprecated setBrake(0.2)", car.getBrakeIntensity(), 0.2, 0.0);
  car.setBrake(0.0);

  // Direct wheel steering (no Ackermann geometry).
  car.setThrottle(0.0);
  car.setRightSteeringAngle(0.1);
  car.setLeftSteeringAngle(0.1);
  run(car, 1.0);
  check_close("Car::getRightSteeringAngle() after setRightSteeringAngle(0.1) (rad)", car.getRightSteeringAngle(), 0.1, 0.01);
  check_close("Car::getLeftSteeringAngle() after setLeftSteeringAngle(0.1) (rad)", car.getLeftSteeringAngle(), 0.1, 0.01);

  car.enableLimitedSlipDifferential(false);
  car.enableIndicatorAutoDisabling(false);
  car.setIndicator(Driver::INDICATOR_RIGHT);
  car.setSteeringAngle(-0.3);
  check_int("Driver::getIndicator() with auto-disabling off", car.getIndicator(), Driver::INDICATOR_RIGHT);
  car.enableLimitedSlipDifferential(true);
  car.enableIndicatorAutoDisabling(true);
  run(car, 0.1);

  return check_finish();
}
