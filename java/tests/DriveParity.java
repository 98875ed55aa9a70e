import com.cyberbotics.webots.controller.Camera;
import com.cyberbotics.webots.controller.Device;
import com.cyberbotics.webots.controller.DistanceSensor;
import com.cyberbotics.webots.controller.GPS;
import com.cyberbotics.webots.controller.Keyboard;
import com.cyberbotics.webots.controller.Lidar;
import com.cyberbotics.webots.controller.Radar;
import com.cyberbotics.webots.controller.RadarTarget;
import com.cyberbotics.webots.controller.RoadSensor;
import com.cyberbotics.webots.controller.vehicle.Car;
import com.cyberbotics.webots.controller.vehicle.Driver;

/**
 * The Java twin of drive_parity.c (same world, same calls, same printed lines; run.sh diffs
 * stdout and stderr), plus the checks only Java has: the device lookup by type, no exception
 * from bad input, the range image as float[], and the loop ending at the world's duration.
 * Run with -ea.
 */
public class DriveParity {
  static final StringBuilder line = new StringBuilder();
  static int seenTargets = 0;
  static int images = 0;
  static final java.util.List<Integer> keys = new java.util.ArrayList<Integer>();

  static void d(String name, double x) {
    line.append(String.format(" %s=%016x", name, Double.doubleToRawLongBits(x)));
  }

  static void i(String name, int x) {
    line.append(" ").append(name).append("=").append(x);
  }

  static void b(String name, boolean x) {
    i(name, x ? 1 : 0);
  }

  static void flush() {
    System.out.println(line);
    System.out.flush();
    line.setLength(0);
  }

  static void printState(Car car, GPS gps, Lidar lidar, DistanceSensor front, Radar radar, RoadSensor lanes, Camera camera) {
    d("t", car.getTime());
    d("steer", car.getSteeringAngle());
    d("target", car.getTargetCruisingSpeed());
    d("speed", car.getCurrentSpeed());
    d("throttle", car.getThrottle());
    d("brake", car.getBrakeIntensity());
    i("indicator", car.getIndicator());
    b("hazard", car.getHazardFlashers());
    b("dipped", car.getDippedBeams());
    b("antifog", car.getAntifogLights());
    d("rpm", car.getRpm());
    i("gear", car.getGear());
    i("gears", car.getGearNumber());
    i("mode", car.getControlMode());
    i("wiper", car.getWiperMode());
    i("wipers", car.getWipersMode());
    i("type", car.getType());
    i("engine", car.getEngineType());
    d("period", car.getIndicatorPeriod());
    b("backwards", car.getBackwardsLights());
    b("brakelights", car.getBrakeLights());
    d("trackf", car.getTrackFront());
    d("trackr", car.getTrackRear());
    d("wheelbase", car.getWheelbase());
    d("rf", car.getFrontWheelRadius());
    d("rr", car.getRearWheelRadius());
    for (int w = 0; w < Car.WHEEL_NB; ++w) {
      d("enc", car.getWheelEncoder(w));
      d("ws", car.getWheelSpeed(w));
    }
    d("left", car.getLeftSteeringAngle());
    d("right", car.getRightSteeringAngle());
    double[] p = gps.getValues();
    double[] v = gps.getSpeedVector();
    assert p.length == 3 && v.length == 3;
    for (double x : p) d("gps", x);
    for (double x : v) d("gpsv", x);
    d("gpss", gps.getSpeed());
    d("front", front.getValue());
    int[] pixels = camera.getImage();
    if (pixels != null) {
      assert pixels.length == camera.getWidth() * camera.getHeight();
      for (int pixel : pixels) line.append(String.format(" px=%08x", pixel));
      images++;
    }
    i("road", lanes.getRoad());
    i("lane", lanes.getLane());
    d("lookahead", lanes.getLookahead());
    d("station", lanes.getStation());
    d("lateral_offset", lanes.getLateralOffset());
    d("heading_error", lanes.getHeadingError());
    d("curvature", lanes.getCurvature());
    d("curvature_ahead", lanes.getCurvatureAhead());
    d("left_line_distance", lanes.getLeftLineDistance());
    d("right_line_distance", lanes.getRightLineDistance());
    d("left_edge_distance", lanes.getLeftEdgeDistance());
    d("right_edge_distance", lanes.getRightEdgeDistance());
    d("lane_width", lanes.getLaneWidth());
    RadarTarget[] targets = radar.getTargets();
    assert targets.length == radar.getNumberOfTargets();
    for (RadarTarget target : targets) {
      d("rd", target.getDistance());
      d("rp", target.getReceivedPower());
      d("rs", target.getSpeed());
      d("ra", target.getAzimuth());
      seenTargets++;
    }
    for (int key = car.getKeyboard().getKey(); key != -1; key = car.getKeyboard().getKey()) {
      i("key", key);
      keys.add(key);
    }
    // The BmwX5 has no traction battery: NaN, the same bits as C's.
    d("battery", car.getBatteryValue());
    float[] image = lidar.getRangeImage();
    assert image.length == lidar.getHorizontalResolution() * lidar.getNumberOfLayers() : image.length;
    for (float r : image) line.append(String.format(" r=%08x", Float.floatToRawIntBits(r)));
    flush();
  }

  public static void main(String[] args) {
    Car car = new Car();
    assert Driver.getDriverInstance() == car;
    GPS gps = car.getGPS("gps");
    Lidar lidar = car.getLidar("lidar");
    assert gps != null && lidar != null;
    // One object per device, and a typed getter refuses another type or a missing name.
    assert car.getGPS("gps") == gps;
    assert car.getGPS("lidar") == null && car.getLidar("gps") == null;
    assert car.getDevice("lidar") == lidar;
    assert "lidar".equals(lidar.getName());
    int found = 0;
    for (int k = 0; k < car.getNumberOfDevices(); ++k) {
      Device device = car.getDeviceByIndex(k);
      if (device == gps || device == lidar) ++found;
    }
    assert found == 2 : found;
    assert lidar.getHorizontalResolution() == 8 && lidar.getNumberOfLayers() == 2;
    assert lidar.getMaxRange() == 30.0 && lidar.getFov() == 0.8;
    assert gps.getCoordinateSystem() == GPS.LOCAL;
    assert car.getControlMode() == -1 : "no control mode before the first command";
    DistanceSensor front = car.getDistanceSensor("front");
    assert front != null && car.getDistanceSensor("gps") == null;
    assert front.getType() == DistanceSensor.LASER && front.getMaxValue() == 20.0;
    gps.enable(10);
    lidar.enable(10);
    front.enable(10);
    car.getKeyboard().enable(10);
    car.batterySensorEnable(10);
    assert car.getBatterySensorSamplingPeriod() == 10;
    Radar radar = car.getRadar("radar");
    assert radar != null;
    radar.enable(10);
    RoadSensor lanes = car.getRoadSensor("lanes");
    assert lanes != null && car.getRoadSensor("radar") == null;
    lanes.enable(10);
    Camera camera = car.getCamera("camera");
    assert camera != null && camera.getWidth() == 16 && camera.getHeight() == 8;
    camera.enable(100);
    assert car.getKeyboard().getSamplingPeriod() == 10;
    assert gps.getSamplingPeriod() == 10 && lidar.getSamplingPeriod() == 10;

    car.setCruisingSpeed(30.0);
    car.setSteeringAngle(0.1);
    car.setIndicator(Driver.INDICATOR_LEFT);
    car.setDippedBeams(true);
    car.setWiperMode(Driver.SLOW);
    car.setIndicatorPeriod(0.5);
    // Bad input, as in C: a warning on stderr, the value refused or clamped, no exception.
    car.setSteeringAngle(Double.NaN);
    car.setGear(99);
    car.setIndicator(7);
    car.setWiperMode(9);
    car.setBrakeIntensity(-1.0);
    d("badwheel", car.getWheelSpeed(4));
    flush();
    assert car.getIndicator() == Driver.INDICATOR_LEFT && car.getWiperMode() == Driver.SLOW;
    assert car.getBrakeIntensity() == 0.0 : car.getBrakeIntensity();

    int steps = 0;
    while (car.step() != -1) {
      ++steps;
      if (steps == 100) {
        car.setThrottle(0.5);
        car.setGear(1);
        car.setThrottle(2.0);
        car.setHazardFlashers(true);
      }
      if (steps == 150) {
        car.setBrakeIntensity(0.3);
        car.setAntifogLights(true);
        car.enableLimitedSlipDifferential(false);
        car.enableIndicatorAutoDisabling(false);
        car.setLeftSteeringAngle(0.05);
        car.setRightSteeringAngle(0.04);
        car.setWipersMode(Driver.FAST);
        car.setBrake(0.4);
      }
      printState(car, gps, lidar, front, radar, lanes, camera);
    }
    line.append("end steps=").append(steps);
    d("t", car.getTime());
    flush();
    // The loop ends at the world's duration: of the 200 steps of 10 ms in 2 s, the 200th
    // reaches t = 2 s and returns -1, so the body ran 199 times (times are sums of 0.01 s,
    // so compared to 1e-9 s rather than exactly).
    assert steps == 199 : steps;
    assert Math.abs(car.getTime() - 2.0) < 1e-9 : car.getTime();
    assert car.getThrottle() == 1.0 : "throttle 2.0 clamped to 1: " + car.getThrottle();
    assert car.getControlMode() == Driver.TORQUE;
    // The box's face is 11.5 m ahead of the start; the car has driven towards it, so the laser
    // reads less than that but more than 0 (it never reached the box).
    assert lanes.getRoad() == 0 && lanes.getLaneWidth() == 3.5 : lanes.getRoad() + " " + lanes.getLaneWidth();
    assert images > 0 : "the camera gave images";
    assert Camera.pixelGetRed(0x00ab1234) == 0xab && Camera.pixelGetGreen(0x00ab1234) == 0x12
        && Camera.pixelGetBlue(0x00ab1234) == 0x34;
    assert seenTargets > 0 : "the radar sees the parked car";
    assert keys.contains(Keyboard.CONTROL + Keyboard.UP) && keys.contains((int) 'A') : keys;
    assert front.getValue() > 0.0 && front.getValue() < 11.5 : front.getValue();
    car.delete();
  }
}
