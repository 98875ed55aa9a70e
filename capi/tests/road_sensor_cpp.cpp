// road_sensor_cpp: the C++ webots::RoadSensor (webots/vehicle/RoadSensor.hpp) through
// Driver::getRoadSensor(), against the same closed forms as road_sensor.c.
//
// World: worlds/road.toml, a straight road along x (one 3.5 m lane each way, no borders) and
// a BmwX5 whose origin is at (20, -1.2) heading 0.05 rad, the sensor "lanes" at its origin.
// Compile as C++11 or later, link with libdriver and libcar.
//
// Expected values (the parked body settles by millimetres, hence 0.01 m and 0.001 rad):
//   road 0, lane -1, station 20 m; lateral offset -1.2 - (-1.75) = 0.55 m; heading error
//   0.05 rad; left line (y = 0) 1.2 m, right line (y = -3.5) 2.3 m; left edge 4.7 m, right
//   edge 2.3 m; lane width 3.5 m and curvatures 0 exactly.

#include <webots/vehicle/Driver.hpp>

#include <cmath>

#include "check.h"

using webots::Driver;
using webots::RoadSensor;

int main() {
  check_begin("road_sensor_cpp");
  Driver driver;

  // A name the car lacks: nullptr, after wb_robot_get_device()'s warning.
  check_true(driver.getRoadSensor("nothing") == nullptr, "getRoadSensor(\"nothing\") is nullptr");

  RoadSensor *lanes = driver.getRoadSensor("lanes");
  if (lanes == nullptr)
    check_fatal("getRoadSensor(\"lanes\") is nullptr");
  check_true(driver.getRoadSensor("lanes") == lanes, "the Driver keeps one RoadSensor per device");
  check_int("node type", lanes->getNodeType(), VEHICLE_NODE_ROAD_SENSOR);
  check_close("lookahead (m)", lanes->getLookahead(), 15.0, 0.0);

  lanes->enable(20);
  check_int("sampling period", lanes->getSamplingPeriod(), 20);
  driver.step();
  check_int("lane before the first sample", lanes->getLane(), 0);
  check_int("road before the first sample", lanes->getRoad(), -1);
  check_true(std::isnan(lanes->getLateralOffset()), "offset NaN before the first sample");
  driver.step();

  check_int("road", lanes->getRoad(), 0);
  check_int("lane", lanes->getLane(), -1);
  check_close("station (m)", lanes->getStation(), 20.0, 0.01);
  check_close("lateral offset (m)", lanes->getLateralOffset(), 0.55, 0.01);
  check_close("heading error (rad)", lanes->getHeadingError(), 0.05, 0.001);
  check_close("left line (m)", lanes->getLeftLineDistance(), 1.2, 0.01);
  check_close("right line (m)", lanes->getRightLineDistance(), 2.3, 0.01);
  check_close("left edge (m)", lanes->getLeftEdgeDistance(), 4.7, 0.01);
  check_close("right edge (m)", lanes->getRightEdgeDistance(), 2.3, 0.01);
  check_close("lane width (m)", lanes->getLaneWidth(), 3.5, 0.0);
  check_close("curvature (1/m)", lanes->getCurvature(), 0.0, 0.0);
  check_close("curvature ahead (1/m)", lanes->getCurvatureAhead(), 0.0, 0.0);

  lanes->disable();
  check_int("sampling period once disabled", lanes->getSamplingPeriod(), 0);
  return check_finish();
}
