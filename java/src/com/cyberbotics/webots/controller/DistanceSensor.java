package com.cyberbotics.webots.controller;

/** Webots' {@code DistanceSensor}: the lookup table's output for the measured distance (m). */
public class DistanceSensor extends Device {
  public static final int GENERIC = 0;
  public static final int INFRA_RED = 1;
  public static final int SONAR = 2;
  public static final int LASER = 3;

  DistanceSensor(int tag) {
    super(tag);
  }

  /** Samples every {@code samplingPeriod} ms. */
  public void enable(int samplingPeriod) {
    WebotsNative.distanceSensorEnable(getTag(), samplingPeriod);
  }

  /** Stops sampling. */
  public void disable() {
    WebotsNative.distanceSensorDisable(getTag());
  }

  /** The sampling period (ms), 0 when disabled. */
  public int getSamplingPeriod() {
    return WebotsNative.distanceSensorGetSamplingPeriod(getTag());
  }

  /** The value: the lookup table's output for the measured distance. */
  public double getValue() {
    return WebotsNative.distanceSensorGetValue(getTag());
  }

  /** The lookup table's largest output. */
  public double getMaxValue() {
    return WebotsNative.distanceSensorGetMaxValue(getTag());
  }

  /** The lookup table's smallest output. */
  public double getMinValue() {
    return WebotsNative.distanceSensorGetMinValue(getTag());
  }

  /** The aperture (rad). */
  public double getAperture() {
    return WebotsNative.distanceSensorGetAperture(getTag());
  }

  /** {@link #GENERIC}, {@link #INFRA_RED}, {@link #SONAR} or {@link #LASER}. */
  public int getType() {
    return WebotsNative.distanceSensorGetType(getTag());
  }
}
