package com.cyberbotics.webots.controller.vehicle;

/**
 * The native methods of the vehicle package: each is one {@code wbu_driver_*} or
 * {@code wbu_car_*} function of the C API (libvehicle_java, java/src/vehicle.rs).
 */
final class VehicleNative {
  static {
    try {
      System.loadLibrary("vehicle_java");
    } catch (UnsatisfiedLinkError e) {
      System.err.println("Native code library failed to load. See the chapter on Dynamic Linking Problems in the SWIG Java documentation for help.\n" + e);
      System.exit(1);
    }
  }

  private VehicleNative() {}

  static native boolean driverInitializationIsPossible();
  static native void driverInit();
  static native void driverCleanup();
  static native int driverStep();
  static native void setSteeringAngle(double angle);
  static native double getSteeringAngle();
  static native void setCruisingSpeed(double speed);
  static native double getTargetCruisingSpeed();
  static native double getCurrentSpeed();
  static native void setThrottle(double throttle);
  static native double getThrottle();
  static native void setBrakeIntensity(double intensity);
  static native double getBrakeIntensity();
  static native void setBrake(double intensity);
  static native void setIndicator(int state);
  static native int getIndicator();
  static native void setHazardFlashers(boolean state);
  static native boolean getHazardFlashers();
  static native void setDippedBeams(boolean state);
  static native boolean getDippedBeams();
  static native void setAntifogLights(boolean state);
  static native boolean getAntifogLights();
  static native double getRpm();
  static native int getGear();
  static native void setGear(int gear);
  static native int getGearNumber();
  static native int getControlMode();
  static native void setWiperMode(int mode);
  static native int getWiperMode();
  static native void setWipersMode(int mode);
  static native int getWipersMode();

  static native int getType();
  static native int getEngineType();
  static native void setIndicatorPeriod(double period);
  static native double getIndicatorPeriod();
  static native boolean getBackwardsLights();
  static native boolean getBrakeLights();
  static native double getTrackFront();
  static native double getTrackRear();
  static native double getWheelbase();
  static native double getFrontWheelRadius();
  static native double getRearWheelRadius();
  static native double getWheelEncoder(int wheel);
  static native double getWheelSpeed(int wheel);
  static native void setLeftSteeringAngle(double angle);
  static native void setRightSteeringAngle(double angle);
  static native double getLeftSteeringAngle();
  static native double getRightSteeringAngle();
  static native void enableLimitedSlipDifferential(boolean enable);
  static native void enableIndicatorAutoDisabling(boolean enable);
}
