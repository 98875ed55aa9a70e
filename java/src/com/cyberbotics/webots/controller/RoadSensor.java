package com.cyberbotics.webots.controller;

/**
 * The project's RoadSensor (an extension, no Webots counterpart; C: webots/vehicle/road_sensor.h,
 * C++: webots::RoadSensor, Python: controller.RoadSensor, same method names): the car's place
 * on the world's roads. Before the first sample, off the roads and for a wrong tag: NaN, road
 * -1, lane 0.
 */
public class RoadSensor extends Device {
  RoadSensor(int tag) {
    super(tag);
  }

  /** Samples every {@code samplingPeriod} ms. */
  public void enable(int samplingPeriod) {
    WebotsNative.roadSensorEnable(getTag(), samplingPeriod);
  }

  /** Stops sampling. */
  public void disable() {
    WebotsNative.roadSensorDisable(getTag());
  }

  /** The sampling period (ms), 0 when disabled. */
  public int getSamplingPeriod() {
    return WebotsNative.roadSensorGetSamplingPeriod(getTag());
  }

  /** The lookahead distance (m). */
  public double getLookahead() {
    return WebotsNative.roadSensorGetLookahead(getTag());
  }

  /** The index of the road under the sensor, -1 off the roads. */
  public int getRoad() {
    return WebotsNative.roadSensorGetRoad(getTag());
  }

  /** The lane (1 = rightmost forward lane), 0 off the roads. */
  public int getLane() {
    return WebotsNative.roadSensorGetLane(getTag());
  }

  /** The distance along the road (m). */
  public double getStation() {
    return WebotsNative.roadSensorGetStation(getTag());
  }

  /** The offset from the lane centre (m, positive left). */
  public double getLateralOffset() {
    return WebotsNative.roadSensorGetLateralOffset(getTag());
  }

  /** The heading relative to the lane (rad, positive left). */
  public double getHeadingError() {
    return WebotsNative.roadSensorGetHeadingError(getTag());
  }

  /** The lane curvature here (1/m, positive turning left). */
  public double getCurvature() {
    return WebotsNative.roadSensorGetCurvature(getTag());
  }

  /** The lane curvature at the lookahead (1/m). */
  public double getCurvatureAhead() {
    return WebotsNative.roadSensorGetCurvatureAhead(getTag());
  }

  /** The distance to the left lane line (m, positive inside). */
  public double getLeftLineDistance() {
    return WebotsNative.roadSensorGetLeftLineDistance(getTag());
  }

  /** The distance to the right lane line (m, positive inside). */
  public double getRightLineDistance() {
    return WebotsNative.roadSensorGetRightLineDistance(getTag());
  }

  /** The distance to the road's left edge (m, positive inside). */
  public double getLeftEdgeDistance() {
    return WebotsNative.roadSensorGetLeftEdgeDistance(getTag());
  }

  /** The distance to the road's right edge (m, positive inside). */
  public double getRightEdgeDistance() {
    return WebotsNative.roadSensorGetRightEdgeDistance(getTag());
  }

  /** The lane width (m). */
  public double getLaneWidth() {
    return WebotsNative.roadSensorGetLaneWidth(getTag());
  }
}
