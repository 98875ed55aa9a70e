/*
 * outputs: a controller whose run writes its outputs (VEHICLE_OUT). It gives through the driver
 * library the commands that the programme of worlds/outputs.toml gives to vehicle-sim, at the
 * same instants (before the step that starts there), and steps until the world's duration
 * ends the run (wbu_driver_step() returns -1). The test compares the two telemetry files.
 * It also samples the world's GPS every 50 ms, whose readings go to devices.csv.
 */

#include <webots/gps.h>
#include <webots/robot.h>
#include <webots/vehicle/driver.h>

int main(void) {
  int cruising = 0, steered = 0, braked = 0;
  wbu_driver_init();
  wb_gps_enable(wb_robot_get_device("gps"), 50);
  do {
    const double t = wb_robot_get_time();
    if (!cruising && t >= 0.0 - 1e-9) {
      wbu_driver_set_cruising_speed(40.0);
      cruising = 1;
    }
    if (!steered && t >= 1.5 - 1e-9) {
      wbu_driver_set_steering_angle(0.1);
      steered = 1;
    }
    if (!braked && t >= 3.0 - 1e-9) {
      wbu_driver_set_brake_intensity(0.6);
      braked = 1;
    }
  } while (wbu_driver_step() != -1);
  wbu_driver_cleanup();
  return 0;
}
