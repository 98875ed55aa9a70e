/*
 * drive.h: helpers shared by the capi test programs that drive a Car through the driver library.
 *
 * Simulation time is counted in driver steps of the world's basicTimeStep (10 ms in the default
 * world). Wheel order: 0 front right, 1 front left, 2 rear right, 3 rear left.
 */

#ifndef CAPI_TEST_DRIVE_H
#define CAPI_TEST_DRIVE_H

#include <webots/robot.h>
#include <webots/vehicle/car.h>
#include <webots/vehicle/driver.h>

#include "check.h"

/* 2*pi, for rad/s to rev/min conversions (no libm). */
#define DRIVE_TWO_PI 6.283185307179586

/* Number of driver steps in `seconds` of simulated time, rounded to the nearest step. */
static inline int drive_steps_for(double seconds) {
  const double step_ms = wb_robot_get_basic_time_step();
  if (!(step_ms > 0.0))
    check_fatal("wb_robot_get_basic_time_step() = %g ms, expected a positive time step", step_ms);
  return (int)(seconds * 1000.0 / step_ms + 0.5);
}

/* Runs `steps` driver steps; a step returning -1 (simulation ended) is fatal. */
static inline void drive_steps(int steps) {
  int i;
  for (i = 0; i < steps; ++i) {
    if (wbu_driver_step() == -1)
      check_fatal("wbu_driver_step() returned -1 (simulation ended) at t = %g s", wb_robot_get_time());
  }
}

/* Runs `seconds` of simulated time. */
static inline void drive_for(double seconds) {
  drive_steps(drive_steps_for(seconds));
}

/* Mean of the four wheel speeds measured by the last step, rad/s. */
static inline double drive_mean_wheel_speed(void) {
  return (wbu_car_get_wheel_speed(WBU_CAR_WHEEL_FRONT_RIGHT) + wbu_car_get_wheel_speed(WBU_CAR_WHEEL_FRONT_LEFT) +
          wbu_car_get_wheel_speed(WBU_CAR_WHEEL_REAR_RIGHT) + wbu_car_get_wheel_speed(WBU_CAR_WHEEL_REAR_LEFT)) /
         4.0;
}

/*
 * The engine speed the library must report for the last step (spec section 2.3): the mean of
 * the four wheel speeds (rad/s) in rev/min, times the gear's ratio `k` (positive: for reverse
 * k = -gearRatio[0]), in absolute value, capped at engineMaxRPM.
 */
static inline double drive_expected_rpm(double k, double max_rpm) {
  double rpm = check_abs(drive_mean_wheel_speed() * 60.0 / DRIVE_TWO_PI * k);
  if (rpm != rpm)
    rpm = 0.0;
  else if (rpm > max_rpm)
    rpm = max_rpm;
  return rpm;
}

/* What a test expects of the car selected by VEHICLE_WORLD (spec section 5.1). */
struct drive_model {
  const char *vehicle_world; /* the VEHICLE_WORLD value that selects it */
  WbuCarType type;
  WbuCarEngineType engine;
  double wheelbase;    /* m */
  double track_front;  /* m */
  double track_rear;   /* m */
  double front_radius; /* m */
  double rear_radius;  /* m */
  int gear_number;     /* gearRatio entries, reverse included */
};

/* BmwX5: traction, combustion, gearRatio [-12.5 12.5 8 5.35 4.3 4]. The default world's car. */
static inline struct drive_model drive_bmw_x5(void) {
  struct drive_model m;
  m.vehicle_world = "BmwX5 (or unset)";
  m.type = WBU_CAR_TRACTION;
  m.engine = WBU_CAR_COMBUSTION_ENGINE;
  m.wheelbase = 2.995;
  m.track_front = 1.628;
  m.track_rear = 1.628;
  m.front_radius = 0.374;
  m.rear_radius = 0.374;
  m.gear_number = 6;
  return m;
}

/* TeslaModel3: propulsion, electric, gearRatio [-6.3 9]. */
static inline struct drive_model drive_tesla_model_3(void) {
  struct drive_model m;
  m.vehicle_world = "TeslaModel3";
  m.type = WBU_CAR_PROPULSION;
  m.engine = WBU_CAR_ELECTRIC_ENGINE;
  m.wheelbase = 2.94;
  m.track_front = 1.72;
  m.track_rear = 1.72;
  m.front_radius = 0.36;
  m.rear_radius = 0.36;
  m.gear_number = 2;
  return m;
}

/*
 * Stops the program with a clear message if the loaded car is not `m` (wrong VEHICLE_WORLD),
 * then checks every characteristic the car library reports.
 */
static inline void drive_require_model(struct drive_model m) {
  if (wbu_car_get_type() != m.type || wbu_car_get_engine_type() != m.engine ||
      check_abs(wbu_car_get_wheelbase() - m.wheelbase) > 1e-9 || wbu_driver_get_gear_number() != m.gear_number)
    check_fatal("this program needs VEHICLE_WORLD=%s; the loaded car has type %d, engine type %d, wheelbase %g m, %d gears",
                m.vehicle_world, (int)wbu_car_get_type(), (int)wbu_car_get_engine_type(), wbu_car_get_wheelbase(),
                wbu_driver_get_gear_number());
  check_int("wbu_car_get_type()", (long)wbu_car_get_type(), (long)m.type);
  check_int("wbu_car_get_engine_type()", (long)wbu_car_get_engine_type(), (long)m.engine);
  check_close("wbu_car_get_wheelbase() (m)", wbu_car_get_wheelbase(), m.wheelbase, 1e-9);
  check_close("wbu_car_get_track_front() (m)", wbu_car_get_track_front(), m.track_front, 1e-9);
  check_close("wbu_car_get_track_rear() (m)", wbu_car_get_track_rear(), m.track_rear, 1e-9);
  check_close("wbu_car_get_front_wheel_radius() (m)", wbu_car_get_front_wheel_radius(), m.front_radius, 1e-9);
  check_close("wbu_car_get_rear_wheel_radius() (m)", wbu_car_get_rear_wheel_radius(), m.rear_radius, 1e-9);
  check_int("wbu_driver_get_gear_number()", wbu_driver_get_gear_number(), m.gear_number);
}

#endif /* CAPI_TEST_DRIVE_H */
