/*
 * cruise_bmw: cruise control (SPEED mode) with Ackermann steering on the BmwX5.
 *
 * World: the default one (VEHICLE_WORLD unset, or VEHICLE_WORLD=BmwX5): a BmwX5 on flat ground,
 * basicTimeStep 10 ms.
 *
 * Golden values (spec sections 2.8, 2.9, 2.6; BmwX5 of section 5.1: wheelbase L = 2.995 m,
 * track Tf = Tr = 1.628 m, tyre radius r = 0.374 m, traction = front-wheel drive):
 *
 * Straight at v = 20 km/h: every wheel turns at 20 / 3.6 / 0.374 = 14.854427 rad/s.
 *
 * Steering a = 0.2 rad:
 *   cot a = 1 / tan 0.2 = 4.933155;  Tf / (2 L) = 1.628 / 5.99 = 0.271786
 *   right wheel dR = atan(1 / (4.933155 - 0.271786)) = 0.211326 rad
 *   left wheel  dL = atan(1 / (4.933155 + 0.271786)) = 0.189812 rad
 *   wbu_driver_get_steering_angle() = (dR + dL) / 2 = 0.200569 rad
 *   front differential ratio: Rr = L / sin dR = 14.278443 m, Rl = L / sin dL = 15.873899 m,
 *     rho = Rr / (Rl + Rr) = 0.473543
 *   driven wheels: wFR = 2 * 20 * rho / 3.6 / 0.374 = 14.068432 rad/s,
 *                  wFL = 2 * 20 * (1 - rho) / 3.6 / 0.374 = 15.640422 rad/s
 *   (their mean is the 14.854427 rad/s of 20 km/h, so the current speed stays 20 km/h)
 *   free rear wheels roll about the turn centre, L / tan a = 14.774799 m to the right of the
 *   rear-axle centre, at the yaw rate W = 2 * (20 / 3.6) / (Rl + Rr) = 0.368499 rad/s:
 *     wRR = W * (14.774799 - 0.814) / 0.374 = 13.755460 rad/s,
 *     wRL = W * (14.774799 + 0.814) / 0.374 = 15.359515 rad/s
 *
 * Tolerances: 2 % on speeds measured after settling (driven wheels, current speed, straight
 * line), 5 % on the undriven rear wheels in the turn (their speed comes from tyre contact, and
 * tyres slip sideways a little at 2.1 m/s^2 of lateral acceleration), 0.01 rad on steering
 * angles (the steering motors hold position against the tyre forces with a 10 000 N*m motor).
 * Speeds are averaged over a 1 s window to smooth the suspension's oscillation.
 */

#include "drive.h"

/* Speeds averaged over `seconds` of driving, and the encoder advance over the same window. */
struct window {
  double wheel_speed[4];     /* rad/s, wbu_car_get_wheel_speed() */
  double encoder_advance[4]; /* rad, wbu_car_get_wheel_encoder() at the end minus at the start */
  double current_speed;      /* km/h, wbu_driver_get_current_speed() */
};

static struct window measure_window(double seconds) {
  struct window w;
  double start_encoder[4];
  const int steps = drive_steps_for(seconds);
  int i, wheel;
  for (wheel = 0; wheel < 4; ++wheel) {
    start_encoder[wheel] = wbu_car_get_wheel_encoder((WbuCarWheelIndex)wheel);
    w.wheel_speed[wheel] = 0.0;
  }
  w.current_speed = 0.0;
  for (i = 0; i < steps; ++i) {
    drive_steps(1);
    for (wheel = 0; wheel < 4; ++wheel)
      w.wheel_speed[wheel] += wbu_car_get_wheel_speed((WbuCarWheelIndex)wheel) / steps;
    w.current_speed += wbu_driver_get_current_speed() / steps;
  }
  for (wheel = 0; wheel < 4; ++wheel)
    w.encoder_advance[wheel] = wbu_car_get_wheel_encoder((WbuCarWheelIndex)wheel) - start_encoder[wheel];
  return w;
}

int main(void) {
  static const char *const wheel_names[4] = {"front right", "front left", "rear right", "rear left"};
  const double straight_speed = 14.854427; /* rad/s, 20 km/h on 0.374 m tyres */
  const double turn_speed[4] = {14.068432, 15.640422, 13.755460, 15.359515};
  const double turn_tolerance[4] = {0.02, 0.02, 0.05, 0.05};
  char what[96];
  struct window w;
  int wheel;

  check_begin("cruise_bmw");
  wbu_driver_init();
  drive_require_model(drive_bmw_x5());
  check_close("wb_robot_get_basic_time_step() (ms)", wb_robot_get_basic_time_step(), 10.0, 0.0);
  check_true(wb_robot_get_device("right_steer") != 0, "wb_robot_get_device(\"right_steer\") is a device");
  check_true(wb_robot_get_device("engine_speaker") != 0, "wb_robot_get_device(\"engine_speaker\") is a device");
  check_int("wb_robot_get_device(\"no such device\")", wb_robot_get_device("no such device"), 0);
  check_int("initial wbu_driver_get_control_mode()", wbu_driver_get_control_mode(), UNDEFINED_CONTROL_MODE);
  check_close("initial wbu_driver_get_target_cruising_speed() (km/h)", wbu_driver_get_target_cruising_speed(), 0.0, 0.0);
  check_close("initial wbu_car_get_indicator_period() (s)", wbu_car_get_indicator_period(), 0.34, 1e-12);

  /* Straight line at 20 km/h: 1.4 s of acceleration at the motors' 10.61 rad/s^2, then steady. */
  wbu_driver_set_cruising_speed(20.0);
  check_int("wbu_driver_get_control_mode() after set_cruising_speed", wbu_driver_get_control_mode(), SPEED);
  check_close("wbu_driver_get_target_cruising_speed() (km/h)", wbu_driver_get_target_cruising_speed(), 20.0, 0.0);
  drive_for(5.0);
  w = measure_window(1.0);
  for (wheel = 0; wheel < 4; ++wheel) {
    sprintf(what, "straight: %s wheel speed (rad/s)", wheel_names[wheel]);
    check_rel(what, w.wheel_speed[wheel], straight_speed, 0.02);
    sprintf(what, "straight: %s encoder advance over 1 s (rad)", wheel_names[wheel]);
    check_rel(what, w.encoder_advance[wheel], straight_speed * 1.0, 0.02);
  }
  check_rel("straight: wbu_driver_get_current_speed() (km/h)", w.current_speed, 20.0, 0.02);
  check_close("straight: wbu_car_get_right_steering_angle() (rad)", wbu_car_get_right_steering_angle(), 0.0, 0.01);
  check_close("straight: wbu_car_get_left_steering_angle() (rad)", wbu_car_get_left_steering_angle(), 0.0, 0.01);

  /* Steady right turn: steering 0.2 rad, still 20 km/h. */
  wbu_driver_set_steering_angle(0.2);
  check_int("wbu_driver_get_control_mode() after steering", wbu_driver_get_control_mode(), SPEED);
  check_close("wbu_driver_get_target_cruising_speed() after steering (km/h)", wbu_driver_get_target_cruising_speed(), 20.0,
              0.0);
  drive_for(10.0);
  w = measure_window(1.0);
  check_close("turn: wbu_car_get_right_steering_angle() (rad)", wbu_car_get_right_steering_angle(), 0.211326, 0.01);
  check_close("turn: wbu_car_get_left_steering_angle() (rad)", wbu_car_get_left_steering_angle(), 0.189812, 0.01);
  check_close("turn: wbu_driver_get_steering_angle() (rad)", wbu_driver_get_steering_angle(), 0.200569, 0.01);
  check_true(wbu_car_get_right_steering_angle() > wbu_car_get_left_steering_angle(),
             "turn: the inner (right) wheel steers more than the outer (left) one");
  for (wheel = 0; wheel < 4; ++wheel) {
    sprintf(what, "turn: %s wheel speed (rad/s)", wheel_names[wheel]);
    check_rel(what, w.wheel_speed[wheel], turn_speed[wheel], turn_tolerance[wheel]);
  }
  check_rel("turn: front right encoder advance over 1 s (rad)", w.encoder_advance[0], turn_speed[0] * 1.0, 0.02);
  check_rel("turn: front left encoder advance over 1 s (rad)", w.encoder_advance[1], turn_speed[1] * 1.0, 0.02);
  check_rel("turn: wbu_driver_get_current_speed() (km/h)", w.current_speed, 20.0, 0.02);

  /* 5 s + 1 s + 10 s + 1 s of 10 ms steps. */
  check_close("wb_robot_get_time() (s)", wb_robot_get_time(), 17.0, 0.005);

  wbu_driver_cleanup();
  return check_finish();
}
