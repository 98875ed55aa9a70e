package com.cyberbotics.webots.controller;

import java.util.HashMap;
import java.util.Map;

/**
 * The robot of the world that {@code VEHICLE_WORLD} names (Webots' {@code Robot}); one per
 * process. Times in s, steps in ms.
 */
public class Robot {
  // webots/nodes.h values of the device types this binding wraps.
  private static final int NODE_ACCELEROMETER = 35;
  private static final int NODE_CAMERA = 38;
  private static final int NODE_COMPASS = 39;
  private static final int NODE_DISPLAY = 41;
  private static final int NODE_DISTANCE_SENSOR = 42;
  private static final int NODE_GPS = 44;
  private static final int NODE_GYRO = 45;
  private static final int NODE_INERTIAL_UNIT = 46;
  private static final int NODE_LIDAR = 48;
  private static final int NODE_RADAR = 54;
  // webots/vehicle/road_sensor.h: VEHICLE_NODE_ROAD_SENSOR, the project's extension.
  private static final int NODE_ROAD_SENSOR = 1000;

  // One Java object per device tag, as in Webots.
  private static final Map<Integer, Device> devices = new HashMap<Integer, Device>();
  private static final Keyboard keyboard = new Keyboard();

  /** Loads the world (the C API's {@code wb_robot_init}: exits with its error otherwise). */
  public Robot() {
    WebotsNative.robotInit();
  }

  /** Frees the simulation and writes {@code VEHICLE_OUT}'s outputs ({@code wb_robot_cleanup}). */
  public synchronized void delete() {
    devices.clear();
    WebotsNative.robotCleanup();
  }

  /** Advances the simulation by {@code duration} ms: 0, or -1 once the world's duration has elapsed. */
  public int step(int duration) {
    return WebotsNative.robotStep(duration);
  }

  /** The simulated time (s). */
  public double getTime() {
    return WebotsNative.robotGetTime();
  }

  /** The world's {@code basicTimeStep} (ms). */
  public double getBasicTimeStep() {
    return WebotsNative.robotGetBasicTimeStep();
  }

  /**
   * Samples the battery's energy every {@code samplingPeriod} ms ({@code wb_robot_battery_sensor_enable}): a car's
   * traction battery when the world file accounts its energy.
   */
  public void batterySensorEnable(int samplingPeriod) {
    WebotsNative.robotBatterySensorEnable(samplingPeriod);
  }

  /** Stops sampling the battery ({@code wb_robot_battery_sensor_disable}). */
  public void batterySensorDisable() {
    WebotsNative.robotBatterySensorDisable();
  }

  /** The battery sensor's period (ms), 0 when disabled. */
  public int getBatterySensorSamplingPeriod() {
    return WebotsNative.robotBatterySensorGetSamplingPeriod();
  }

  /**
   * The battery's energy at the last sample (J); NaN before the first sample and without a battery. When the energy of
   * Webots' {@code battery} field reaches 0 the controller is stopped: {@code step} returns -1 from then on.
   */
  public double getBatteryValue() {
    return WebotsNative.robotBatterySensorGetValue();
  }

  /** The keyboard (the keys the world's programme presses). */
  public Keyboard getKeyboard() {
    return keyboard;
  }

  /** The number of devices of the robot. */
  public int getNumberOfDevices() {
    return WebotsNative.robotGetNumberOfDevices();
  }

  /** The device at {@code index} (0..getNumberOfDevices()-1), {@code null} out of range. */
  public Device getDeviceByIndex(int index) {
    return device(WebotsNative.robotGetDeviceByIndex(index), -1);
  }

  /** The device {@code name}, as its class ({@code GPS}, {@code Lidar}...); {@code null} if none. */
  public Device getDevice(String name) {
    return device(WebotsNative.robotGetDevice(name), -1);
  }

  /** The GPS {@code name}; {@code null} if missing or not a GPS. */
  public GPS getGPS(String name) {
    return (GPS) device(WebotsNative.robotGetDevice(name), NODE_GPS);
  }

  /** The inertial unit {@code name}; {@code null} if missing or not an inertial unit. */
  public InertialUnit getInertialUnit(String name) {
    return (InertialUnit) device(WebotsNative.robotGetDevice(name), NODE_INERTIAL_UNIT);
  }

  /** The gyro {@code name}; {@code null} if missing or not a gyro. */
  public Gyro getGyro(String name) {
    return (Gyro) device(WebotsNative.robotGetDevice(name), NODE_GYRO);
  }

  /** The accelerometer {@code name}; {@code null} if missing or not an accelerometer. */
  public Accelerometer getAccelerometer(String name) {
    return (Accelerometer) device(WebotsNative.robotGetDevice(name), NODE_ACCELEROMETER);
  }

  /** The compass {@code name}; {@code null} if missing or not a compass. */
  public Compass getCompass(String name) {
    return (Compass) device(WebotsNative.robotGetDevice(name), NODE_COMPASS);
  }

  /** The distance sensor {@code name}; {@code null} if missing or not a distance sensor. */
  public DistanceSensor getDistanceSensor(String name) {
    return (DistanceSensor) device(WebotsNative.robotGetDevice(name), NODE_DISTANCE_SENSOR);
  }

  /** The radar {@code name}; {@code null} if missing or not a radar. */
  public Radar getRadar(String name) {
    return (Radar) device(WebotsNative.robotGetDevice(name), NODE_RADAR);
  }

  /** The road sensor {@code name} (the project's extension); {@code null} if missing or not one. */
  public RoadSensor getRoadSensor(String name) {
    return (RoadSensor) device(WebotsNative.robotGetDevice(name), NODE_ROAD_SENSOR);
  }

  /** The camera {@code name}; {@code null} if missing or not a camera. */
  public Camera getCamera(String name) {
    return (Camera) device(WebotsNative.robotGetDevice(name), NODE_CAMERA);
  }

  /** The display {@code name}; {@code null} if missing or not a display. */
  public Display getDisplay(String name) {
    return (Display) device(WebotsNative.robotGetDevice(name), NODE_DISPLAY);
  }

  /** The lidar {@code name}; {@code null} if missing or not a lidar. */
  public Lidar getLidar(String name) {
    return (Lidar) device(WebotsNative.robotGetDevice(name), NODE_LIDAR);
  }

  /**
   * The cached object of device {@code tag}; {@code null} for tag 0 or when {@code expected}
   * (a node type, -1 for any) does not match.
   */
  private static Device device(int tag, int expected) {
    if (tag == 0) return null;
    int type = WebotsNative.deviceGetNodeType(tag);
    if (expected != -1 && type != expected) return null;
    Device device = devices.get(tag);
    if (device == null) {
      switch (type) {
        case NODE_GPS: device = new GPS(tag); break;
        case NODE_INERTIAL_UNIT: device = new InertialUnit(tag); break;
        case NODE_GYRO: device = new Gyro(tag); break;
        case NODE_ACCELEROMETER: device = new Accelerometer(tag); break;
        case NODE_COMPASS: device = new Compass(tag); break;
        case NODE_DISTANCE_SENSOR: device = new DistanceSensor(tag); break;
        case NODE_LIDAR: device = new Lidar(tag); break;
        case NODE_CAMERA: device = new Camera(tag); break;
        case NODE_DISPLAY: device = new Display(tag); break;
        case NODE_RADAR: device = new Radar(tag); break;
        case NODE_ROAD_SENSOR: device = new RoadSensor(tag); break;
        default: device = new Device(tag); break;
      }
      devices.put(tag, device);
    }
    return device;
  }
}
