/*
 * acc.c: adaptive cruise control with a radar alone, as a Webots C controller.
 *
 *   VEHICLE_WORLD=sim/worlds/acc.toml ./acc
 *
 * The car cruises at SET_SPEED until its radar (named "radar") reports a target ahead; then it
 * follows the nearest target at the distance STANDSTILL + TIME_GAP * v (v its own speed, m/s):
 * the cruising speed it commands is the target's speed (its own plus the target's radial
 * speed) plus GAIN times the distance error, between 0 and SET_SPEED. Below CREEP it stops
 * (0), and once stopped it waits for a command above RESUME, so that the radar's noise
 * (0.5 m, 0.12 m/s) neither makes it crawl nor restart behind a stopped target. The gap error
 * then decays as exp(-GAIN t) behind a target at constant speed. Every 0.5 s it prints
 * "acc: t v d" (s, m/s, m; d = -1 without a target).
 *
 * Build: cc acc.c $(pkg-config --cflags --libs webots-vehicle) -lm (see capi/README.md).
 */

#include <math.h>
#include <stdio.h>
#include <webots/radar.h>
#include <webots/robot.h>
#include <webots/vehicle/driver.h>

#define TIME_GAP 1.5    /* s */
#define STANDSTILL 7.0  /* m: radar distance to the target's origin (its rear axle) at rest */
#define SET_SPEED 25.0  /* m/s */
#define GAIN 0.4        /* 1/s */
#define CREEP 0.5       /* m/s */
#define RESUME 1.5      /* m/s */
#define RADAR_PERIOD 50 /* ms */

int main(void) {
  WbDeviceTag radar;
  int steps = 0;
  wbu_driver_init();
  radar = wb_robot_get_device("radar");
  wb_radar_enable(radar, RADAR_PERIOD);
  while (wbu_driver_step() != -1) {
    /* The driver library's speed, from the driven wheels (NaN until they are measurable). */
    double v = wbu_driver_get_current_speed() / 3.6;
    double command = SET_SPEED, distance = -1.0;
    const WbRadarTarget *targets = wb_radar_get_targets(radar);
    int i, n = wb_radar_get_number_of_targets(radar);
    if (isnan(v))
      v = 0.0;
    for (i = 0; i < n; ++i)
      if (distance < 0.0 || targets[i].distance < distance) {
        double lead = v + targets[i].speed;
        distance = targets[i].distance;
        command = lead + GAIN * (distance - (STANDSTILL + TIME_GAP * v));
      }
    if (command < (v < 0.1 ? RESUME : CREEP))
      command = 0.0;
    if (command > SET_SPEED)
      command = SET_SPEED;
    wbu_driver_set_cruising_speed(command * 3.6);
    if (++steps % 50 == 0)
      printf("acc: %.2f %.4f %.4f\n", wb_robot_get_time(), v, distance);
  }
  wbu_driver_cleanup();
  return 0;
}
