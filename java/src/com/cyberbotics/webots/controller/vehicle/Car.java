package com.cyberbotics.webots.controller.vehicle;

/**
 * Webots' car library ({@code wbu_car_*}) as its Java class. Units: m, rad, rad/s, s.
 */
public class Car extends Driver {
  public final static int TRACTION = 0;
  public final static int PROPULSION = 1;
  public final static int FOUR_BY_FOUR = 2;
  public final static int COMBUSTION_ENGINE = 0;
  public final static int ELECTRIC_ENGINE = 1;
  public final static int PARALLEL_HYBRID_ENGINE = 2;
  public final static int POWER_SPLIT_HYBRID_ENGINE = 3;
  public final static int WHEEL_FRONT_RIGHT = 0;
  public final static int WHEEL_FRONT_LEFT = 1;
  public final static int WHEEL_REAR_RIGHT = 2;
  public final static int WHEEL_REAR_LEFT = 3;
  public final static int WHEEL_NB = 4;

  /** Loads the world and initialises the car and driver libraries. */
  public Car() {
    super();
  }

  public int getType() {
    return VehicleNative.getType();
  }

  public int getEngineType() {
    return VehicleNative.getEngineType();
  }

  public void setIndicatorPeriod(double period) {
    VehicleNative.setIndicatorPeriod(period);
  }

  public double getIndicatorPeriod() {
    return VehicleNative.getIndicatorPeriod();
  }

  public boolean getBackwardsLights() {
    return VehicleNative.getBackwardsLights();
  }

  public boolean getBrakeLights() {
    return VehicleNative.getBrakeLights();
  }

  public double getTrackFront() {
    return VehicleNative.getTrackFront();
  }

  public double getTrackRear() {
    return VehicleNative.getTrackRear();
  }

  public double getWheelbase() {
    return VehicleNative.getWheelbase();
  }

  public double getFrontWheelRadius() {
    return VehicleNative.getFrontWheelRadius();
  }

  public double getRearWheelRadius() {
    return VehicleNative.getRearWheelRadius();
  }

  public double getWheelEncoder(int wheel) {
    return VehicleNative.getWheelEncoder(wheel);
  }

  public double getWheelSpeed(int wheel) {
    return VehicleNative.getWheelSpeed(wheel);
  }

  public void setLeftSteeringAngle(double angle) {
    VehicleNative.setLeftSteeringAngle(angle);
  }

  public void setRightSteeringAngle(double angle) {
    VehicleNative.setRightSteeringAngle(angle);
  }

  public double getLeftSteeringAngle() {
    return VehicleNative.getLeftSteeringAngle();
  }

  public double getRightSteeringAngle() {
    return VehicleNative.getRightSteeringAngle();
  }

  public void enableLimitedSlipDifferential(boolean enable) {
    VehicleNative.enableLimitedSlipDifferential(enable);
  }

  public void enableIndicatorAutoDisabling(boolean enable) {
    VehicleNative.enableIndicatorAutoDisabling(enable);
  }
}
