package com.cyberbotics.webots.controller.vehicle;

import com.cyberbotics.webots.controller.Supervisor;

/**
 * Webots' driver library ({@code wbu_driver_*}) as its Java class: the car of the world that
 * {@code VEHICLE_WORLD} names. Units: rad (positive steers right), km/h, rev/min.
 */
public class Driver extends Supervisor {
  public final static int INDICATOR_OFF = 0;
  public final static int INDICATOR_RIGHT = 1;
  public final static int INDICATOR_LEFT = 2;
  /** {@link #getControlMode()}: cruising speed. */
  public final static int SPEED = 0;
  /** {@link #getControlMode()}: throttle and brake. */
  public final static int TORQUE = 1;
  public final static int DOWN = 0;
  public final static int SLOW = 1;
  public final static int NORMAL = 2;
  public final static int FAST = 3;

  private static Driver instance;

  /** Loads the world and initialises the driver library ({@code wbu_driver_init}). */
  public Driver() {
    super();
    VehicleNative.driverInit();
    instance = this;
  }

  /** True if the world's robot is a car ({@code wbu_driver_initialization_is_possible}). */
  public static boolean isInitialisationPossible() {
    return VehicleNative.driverInitializationIsPossible();
  }

  /** The driver this process created, {@code null} before. */
  public static Driver getDriverInstance() {
    return instance;
  }

  /** Frees the driver and car libraries and the simulation ({@code wbu_driver_cleanup}). */
  @Override
  public synchronized void delete() {
    VehicleNative.driverCleanup();
    super.delete();
  }

  /** One driver step of {@code basicTimeStep}: 0, or -1 once the world's duration has elapsed. */
  public int step() {
    return VehicleNative.driverStep();
  }

  public void setSteeringAngle(double steeringAngle) {
    VehicleNative.setSteeringAngle(steeringAngle);
  }

  public double getSteeringAngle() {
    return VehicleNative.getSteeringAngle();
  }

  public void setCruisingSpeed(double speed) {
    VehicleNative.setCruisingSpeed(speed);
  }

  public double getTargetCruisingSpeed() {
    return VehicleNative.getTargetCruisingSpeed();
  }

  public double getCurrentSpeed() {
    return VehicleNative.getCurrentSpeed();
  }

  public void setThrottle(double throttle) {
    VehicleNative.setThrottle(throttle);
  }

  public double getThrottle() {
    return VehicleNative.getThrottle();
  }

  public void setBrakeIntensity(double intensity) {
    VehicleNative.setBrakeIntensity(intensity);
  }

  public double getBrakeIntensity() {
    return VehicleNative.getBrakeIntensity();
  }

  /** Deprecated in Webots: {@link #setBrakeIntensity(double)}. */
  @Deprecated
  public void setBrake(double brake) {
    VehicleNative.setBrake(brake);
  }

  public void setIndicator(int state) {
    VehicleNative.setIndicator(state);
  }

  public int getIndicator() {
    return VehicleNative.getIndicator();
  }

  public void setHazardFlashers(boolean state) {
    VehicleNative.setHazardFlashers(state);
  }

  public boolean getHazardFlashers() {
    return VehicleNative.getHazardFlashers();
  }

  public void setDippedBeams(boolean state) {
    VehicleNative.setDippedBeams(state);
  }

  public boolean getDippedBeams() {
    return VehicleNative.getDippedBeams();
  }

  public void setAntifogLights(boolean state) {
    VehicleNative.setAntifogLights(state);
  }

  public boolean getAntifogLights() {
    return VehicleNative.getAntifogLights();
  }

  public double getRpm() {
    return VehicleNative.getRpm();
  }

  public int getGear() {
    return VehicleNative.getGear();
  }

  public void setGear(int gear) {
    VehicleNative.setGear(gear);
  }

  public int getGearNumber() {
    return VehicleNative.getGearNumber();
  }

  /** {@link #SPEED}, {@link #TORQUE}, or -1 before a mode is set. */
  public int getControlMode() {
    return VehicleNative.getControlMode();
  }

  public void setWiperMode(int mode) {
    VehicleNative.setWiperMode(mode);
  }

  public int getWiperMode() {
    return VehicleNative.getWiperMode();
  }

  /** Deprecated in Webots: {@link #setWiperMode(int)}. */
  @Deprecated
  public void setWipersMode(int mode) {
    VehicleNative.setWipersMode(mode);
  }

  /** Deprecated in Webots: {@link #getWiperMode()}. */
  @Deprecated
  public int getWipersMode() {
    return VehicleNative.getWipersMode();
  }
}
