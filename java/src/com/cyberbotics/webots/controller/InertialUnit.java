package com.cyberbotics.webots.controller;

/** Webots' {@code InertialUnit}: attitude (rad). */
public class InertialUnit extends Device {
  InertialUnit(int tag) {
    super(tag);
  }

  /** Samples every {@code samplingPeriod} ms. */
  public void enable(int samplingPeriod) {
    WebotsNative.inertialUnitEnable(getTag(), samplingPeriod);
  }

  /** Stops sampling. */
  public void disable() {
    WebotsNative.inertialUnitDisable(getTag());
  }

  /** The sampling period (ms), 0 when disabled. */
  public int getSamplingPeriod() {
    return WebotsNative.inertialUnitGetSamplingPeriod(getTag());
  }

  /** The noise (rad). */
  public double getNoise() {
    return WebotsNative.inertialUnitGetNoise(getTag());
  }

  /** {roll, pitch, yaw} (rad). */
  public double[] getRollPitchYaw() {
    return WebotsNative.inertialUnitGetRollPitchYaw(getTag());
  }

  /** The attitude quaternion {x, y, z, w}. */
  public double[] getQuaternion() {
    return WebotsNative.inertialUnitGetQuaternion(getTag());
  }
}
