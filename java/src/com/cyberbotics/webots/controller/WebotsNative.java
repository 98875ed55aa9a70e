package com.cyberbotics.webots.controller;

/**
 * The native methods of the controller package: each is one function of the C API
 * (libvehicle_java, java/src/robot.rs, sensors.rs, display.rs, recognition.rs and
 * point_cloud.rs). Units are the C API's: ms, s, m, m/s, rad, rad/s, m/s^2, px.
 */
final class WebotsNative {
  static {
    try {
      System.loadLibrary("vehicle_java");
    } catch (UnsatisfiedLinkError e) {
      // Webots' (SWIG's) message and exit status when its JNI library is missing.
      System.err.println("Native code library failed to load. See the chapter on Dynamic Linking Problems in the SWIG Java documentation for help.\n" + e);
      System.exit(1);
    }
  }

  private WebotsNative() {}

  static native int robotInit();
  static native void robotCleanup();
  static native int robotStep(int duration);
  static native double robotGetTime();
  static native double robotGetBasicTimeStep();
  static native void robotBatterySensorEnable(int period);
  static native void robotBatterySensorDisable();
  static native int robotBatterySensorGetSamplingPeriod();
  static native double robotBatterySensorGetValue();
  static native int robotGetNumberOfDevices();
  static native int robotGetDeviceByIndex(int index);
  static native int robotGetDevice(String name);
  static native void keyboardEnable(int samplingPeriod);
  static native void keyboardDisable();
  static native int keyboardGetSamplingPeriod();
  static native int keyboardGetKey();
  static native int deviceGetNodeType(int tag);
  static native String deviceGetName(int tag);
  static native String deviceGetModel(int tag);

  static native void gpsEnable(int tag, int samplingPeriod);
  static native void gpsDisable(int tag);
  static native int gpsGetSamplingPeriod(int tag);
  static native double[] gpsGetValues(int tag);
  static native double gpsGetSpeed(int tag);
  static native double[] gpsGetSpeedVector(int tag);
  static native int gpsGetCoordinateSystem(int tag);

  static native void inertialUnitEnable(int tag, int samplingPeriod);
  static native void inertialUnitDisable(int tag);
  static native int inertialUnitGetSamplingPeriod(int tag);
  static native double inertialUnitGetNoise(int tag);
  static native double[] inertialUnitGetRollPitchYaw(int tag);
  static native double[] inertialUnitGetQuaternion(int tag);

  static native void gyroEnable(int tag, int samplingPeriod);
  static native void gyroDisable(int tag);
  static native int gyroGetSamplingPeriod(int tag);
  static native double[] gyroGetValues(int tag);

  static native void accelerometerEnable(int tag, int samplingPeriod);
  static native void accelerometerDisable(int tag);
  static native int accelerometerGetSamplingPeriod(int tag);
  static native double[] accelerometerGetValues(int tag);

  static native void compassEnable(int tag, int samplingPeriod);
  static native void compassDisable(int tag);
  static native int compassGetSamplingPeriod(int tag);
  static native double[] compassGetValues(int tag);

  static native void distanceSensorEnable(int tag, int samplingPeriod);
  static native void distanceSensorDisable(int tag);
  static native int distanceSensorGetSamplingPeriod(int tag);
  static native double distanceSensorGetValue(int tag);
  static native double distanceSensorGetMaxValue(int tag);
  static native double distanceSensorGetMinValue(int tag);
  static native double distanceSensorGetAperture(int tag);
  static native int distanceSensorGetType(int tag);

  static native void radarEnable(int tag, int samplingPeriod);
  static native void radarDisable(int tag);
  static native int radarGetSamplingPeriod(int tag);
  static native int radarGetNumberOfTargets(int tag);
  static native double[] radarGetTargets(int tag);
  static native double radarGetMinRange(int tag);
  static native double radarGetMaxRange(int tag);
  static native double radarGetHorizontalFov(int tag);
  static native double radarGetVerticalFov(int tag);

  static native void roadSensorEnable(int tag, int samplingPeriod);
  static native void roadSensorDisable(int tag);
  static native int roadSensorGetSamplingPeriod(int tag);
  static native double roadSensorGetLookahead(int tag);
  static native int roadSensorGetRoad(int tag);
  static native int roadSensorGetLane(int tag);
  static native double roadSensorGetStation(int tag);
  static native double roadSensorGetLateralOffset(int tag);
  static native double roadSensorGetHeadingError(int tag);
  static native double roadSensorGetCurvature(int tag);
  static native double roadSensorGetCurvatureAhead(int tag);
  static native double roadSensorGetLeftLineDistance(int tag);
  static native double roadSensorGetRightLineDistance(int tag);
  static native double roadSensorGetLeftEdgeDistance(int tag);
  static native double roadSensorGetRightEdgeDistance(int tag);
  static native double roadSensorGetLaneWidth(int tag);

  static native void cameraEnable(int tag, int samplingPeriod);
  static native void cameraDisable(int tag);
  static native int cameraGetSamplingPeriod(int tag);
  static native int cameraGetWidth(int tag);
  static native int cameraGetHeight(int tag);
  static native double cameraGetFov(int tag);
  static native double cameraGetMinFov(int tag);
  static native double cameraGetMaxFov(int tag);
  static native int cameraSaveImage(int tag, String filename, int quality);
  static native double cameraGetNear(int tag);
  static native int[] cameraGetImage(int tag);

  static native void lidarEnable(int tag, int samplingPeriod);
  static native void lidarDisable(int tag);
  static native int lidarGetSamplingPeriod(int tag);
  static native float[] lidarGetRangeImage(int tag);
  static native float[] lidarGetLayerRangeImage(int tag, int layer);
  static native int lidarGetHorizontalResolution(int tag);
  static native int lidarGetNumberOfLayers(int tag);
  static native double lidarGetFrequency(int tag);
  static native void lidarSetFrequency(int tag, double frequency);
  static native double lidarGetMinFrequency(int tag);
  static native double lidarGetMaxFrequency(int tag);
  static native double lidarGetFov(int tag);
  static native double lidarGetVerticalFov(int tag);
  static native double lidarGetMinRange(int tag);
  static native double lidarGetMaxRange(int tag);

  static native int displayGetWidth(int tag);
  static native int displayGetHeight(int tag);
  static native void displaySetColor(int tag, int color);
  static native void displaySetAlpha(int tag, double alpha);
  static native void displaySetOpacity(int tag, double opacity);
  static native void displaySetFont(int tag, String font, int size, boolean antiAliasing);
  static native void displayDrawText(int tag, String text, int x, int y);
  static native void displayDrawPixel(int tag, int x, int y);
  static native void displayDrawLine(int tag, int x1, int y1, int x2, int y2);
  static native void displayDrawRectangle(int tag, int x, int y, int width, int height);
  static native void displayFillRectangle(int tag, int x, int y, int width, int height);
  static native void displayDrawOval(int tag, int cx, int cy, int a, int b);
  static native void displayFillOval(int tag, int cx, int cy, int a, int b);
  static native void displayDrawPolygon(int tag, int[] x, int[] y, int size);
  static native void displayFillPolygon(int tag, int[] x, int[] y, int size);
  static native long displayImageNew(int tag, int width, int height, int[] data, int format);
  static native long displayImageCopy(int tag, int x, int y, int width, int height);
  static native void displayImagePaste(int tag, long image, int x, int y, boolean blend);
  static native void displayImageDelete(int tag, long image);
  static native void displayImageSave(int tag, long image, String filename);
  static native long displayImageLoad(int tag, String filename);

  static native boolean cameraHasRecognition(int tag);
  static native void cameraRecognitionEnable(int tag, int samplingPeriod);
  static native void cameraRecognitionDisable(int tag);
  static native int cameraRecognitionGetSamplingPeriod(int tag);
  static native int cameraRecognitionGetNumberOfObjects(int tag);
  static native boolean cameraRecognitionHasSegmentation(int tag);
  static native CameraRecognitionObject[] cameraRecognitionGetObjects(int tag);

  static native void lidarEnablePointCloud(int tag);
  static native void lidarDisablePointCloud(int tag);
  static native boolean lidarIsPointCloudEnabled(int tag);
  static native int lidarGetNumberOfPoints(int tag);
  static native LidarPoint[] lidarGetPointCloud(int tag);
  static native LidarPoint[] lidarGetLayerPointCloud(int tag, int layer);
}
