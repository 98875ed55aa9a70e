import com.cyberbotics.webots.controller.Camera;
import com.cyberbotics.webots.controller.CameraRecognitionObject;
import com.cyberbotics.webots.controller.Device;
import com.cyberbotics.webots.controller.Display;
import com.cyberbotics.webots.controller.ImageRef;
import com.cyberbotics.webots.controller.DistanceSensor;
import com.cyberbotics.webots.controller.GPS;
import com.cyberbotics.webots.controller.Keyboard;
import com.cyberbotics.webots.controller.Lidar;
import com.cyberbotics.webots.controller.LidarPoint;
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
  static int recognised = 0;
  static int clouds = 0;
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

  static void n(String name, Object x) {
    line.append(" ").append(name).append("=").append(x == null ? "null" : "image");
  }

  /** The bytes of the file {@code name} (in the working directory) in hex, as a line. */
  static void printFile(String label, String name) throws java.io.IOException {
    line.append(label);
    java.io.File file = new java.io.File(name);
    if (!file.exists()) {
      line.append(" missing");
    } else {
      for (byte b : java.nio.file.Files.readAllBytes(file.toPath()))
        line.append(String.format("%02x", b & 0xff));
    }
    flush();
  }

  /** drive_parity.c's draw(): every Display method, bad input included, read back as PNG files. */
  static void draw(Display screen) throws java.io.IOException {
    i("display_width", screen.getWidth());
    i("display_height", screen.getHeight());
    screen.setColor(0x3366cc);
    screen.fillRectangle(0, 0, 16, 8);
    screen.setColor(0xff0000);
    screen.drawPixel(15, 0);
    screen.drawLine(0, 7, 15, 0);
    screen.setOpacity(0.5);
    screen.drawRectangle(2, 2, 5, 4);
    screen.setOpacity(1.0);
    screen.setAlpha(0.25);
    screen.drawOval(8, 4, 3, 2);
    screen.setAlpha(1.0);
    screen.setColor(0x00ff00);
    screen.fillOval(12, 3, 2, 2);
    // The three-argument form with longer arrays and the two-argument form: the same corners.
    screen.drawPolygon(new int[] {1, 6, 3, 99}, new int[] {1, 2, 6, 99}, 3);
    screen.fillPolygon(new int[] {9, 14, 12, 10}, new int[] {5, 5, 7, 7});
    screen.setFont("Arial", 8, true);
    screen.drawText("Hi", 0, 0);
    screen.setColor(0x1000000);
    screen.setAlpha(2.0);
    screen.setOpacity(-1.0);
    screen.setFont("NoSuchFont", 8, false);
    screen.setFont("Arial", 0, false);
    int[] argb = {0x80ff0000, 0xff00ff00, 0x000000ff, 0xffffffff};
    n("bad_format", screen.imageNew(2, 2, argb, 9));
    n("off_copy", screen.imageCopy(100, 100, 2, 2));
    ImageRef made = screen.imageNew(2, 2, argb, Display.ARGB);
    ImageRef flat = screen.imageNew(2, 1, new int[] {0x102030, 0x405060}, Display.RGB);
    screen.imagePaste(made, 3, 5, true);
    screen.imagePaste(flat, 13, 6);
    ImageRef copy = screen.imageCopy(0, 0, 8, 4);
    screen.imagePaste(copy, 8, 4, false);
    screen.imageSave(copy, "copy.png");
    ImageRef loaded = screen.imageLoad("copy.png");
    screen.imagePaste(loaded, 9, 5, true);
    screen.imageSave(null, "screen.png");
    screen.imageDelete(made);
    screen.imageDelete(flat);
    screen.imageDelete(copy);
    screen.imageDelete(loaded);
    flush();
    printFile("copy.png ", "copy.png");
    printFile("screen.png ", "screen.png");
    // The files are PNG images of the sizes saved; the red pixel drawn at (15, 0), which later
    // drawing does not touch, reads back opaque red (ImageIO's ARGB).
    java.awt.image.BufferedImage saved = javax.imageio.ImageIO.read(new java.io.File("screen.png"));
    java.awt.image.BufferedImage copied = javax.imageio.ImageIO.read(new java.io.File("copy.png"));
    assert saved.getWidth() == 16 && saved.getHeight() == 8 && copied.getWidth() == 8 && copied.getHeight() == 4;
    assert saved.getRGB(15, 0) == 0xffff0000 : Integer.toHexString(saved.getRGB(15, 0));
    boolean thrown = false;
    try {
      screen.drawPolygon(new int[] {1, 2}, new int[] {1, 2, 3}, 3);
    } catch (ArrayIndexOutOfBoundsException e) {
      thrown = true;
    }
    assert thrown : "a polygon longer than its arrays is refused before the C call";
  }

  static void f(String name, float x) {
    line.append(String.format(" %s=%08x", name, Float.floatToRawIntBits(x)));
  }

  /** drive_parity.c's print_cloud: the points, "null" for a null array. */
  static void printCloud(String name, LidarPoint[] points) {
    line.append(" ").append(name).append("=");
    if (points == null) {
      line.append("null");
      return;
    }
    line.append(points.length);
    for (LidarPoint p : points) {
      f("px", p.getX());
      f("py", p.getY());
      f("pz", p.getZ());
      i("pl", p.getLayerId());
      f("pt", p.getTime());
    }
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
    int count = camera.getRecognitionNumberOfObjects();
    CameraRecognitionObject[] objects = camera.getRecognitionObjects();
    assert objects.length == count : objects.length + " " + count;
    i("objects", count);
    for (CameraRecognitionObject o : objects) {
      i("id", o.getId());
      for (double x : o.getPosition()) d("opos", x);
      for (double x : o.getOrientation()) d("orot", x);
      for (double x : o.getSize()) d("osize", x);
      for (int x : o.getPositionOnImage()) i("oimg", x);
      for (int x : o.getSizeOnImage()) i("oimgsize", x);
      i("ncolors", o.getNumberOfColors());
      for (double x : o.getColors()) d("ocolor", x);
      line.append(" model=").append(o.getModel());
      assert o.getColors().length == 3 * o.getNumberOfColors();
      recognised++;
    }
    LidarPoint[] cloud = lidar.getPointCloud();
    assert cloud.length == lidar.getNumberOfPoints();
    printCloud("cloud", cloud);
    printCloud("layer1", lidar.getLayerPointCloud(1));
    for (int k = 0; k < cloud.length; ++k) {
      assert cloud[k].getLayerId() == k / lidar.getHorizontalResolution();
      clouds++;
    }
    float[] image = lidar.getRangeImage();
    assert image.length == lidar.getHorizontalResolution() * lidar.getNumberOfLayers() : image.length;
    for (float r : image) line.append(String.format(" r=%08x", Float.floatToRawIntBits(r)));
    flush();
  }

  public static void main(String[] args) throws java.io.IOException {
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
    Display screen = car.getDisplay("screen");
    assert screen != null && car.getDisplay("camera") == null && car.getDevice("screen") == screen;
    draw(screen);
    b("has_recognition", camera.hasRecognition());
    b("segmentation", camera.hasRecognitionSegmentation());
    i("recognition_period", camera.getRecognitionSamplingPeriod());
    i("objects", camera.getRecognitionNumberOfObjects());
    CameraRecognitionObject[] none = camera.getRecognitionObjects();
    // Java's empty array where C returns NULL (recognition disabled).
    n("objects", none.length == 0 ? null : none);
    camera.recognitionEnable(50);
    i("recognition_period", camera.getRecognitionSamplingPeriod());
    b("cloud_enabled", lidar.isPointCloudEnabled());
    i("points", lidar.getNumberOfPoints());
    printCloud("cloud", lidar.getPointCloud());
    lidar.enablePointCloud();
    b("cloud_enabled", lidar.isPointCloudEnabled());
    printCloud("layer5", lidar.getLayerPointCloud(5));
    flush();
    assert camera.hasRecognition() && !camera.hasRecognitionSegmentation();
    assert camera.getRecognitionSamplingPeriod() == 50 && lidar.isPointCloudEnabled();
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
    d("min_fov", camera.getMinFov());
    d("max_fov", camera.getMaxFov());
    d("frequency", lidar.getFrequency());
    d("min_frequency", lidar.getMinFrequency());
    d("max_frequency", lidar.getMaxFrequency());
    lidar.setFrequency(lidar.getMaxFrequency() + 1.0);
    lidar.setFrequency(lidar.getMinFrequency());
    d("frequency", lidar.getFrequency());
    flush();
    assert lidar.getFrequency() == lidar.getMinFrequency() : "max + 1 Hz refused, min accepted";
    assert car.getIndicator() == Driver.INDICATOR_LEFT && car.getWiperMode() == Driver.SLOW;
    assert car.getBrakeIntensity() == 0.0 : car.getBrakeIntensity();

    int steps = 0;
    while (car.step() != -1) {
      ++steps;
      if (steps == 50) {
        // The camera's image as a PNG file (read back as bytes), and a refused extension.
        i("save", camera.saveImage("camera.png", 100));
        i("save_bmp", camera.saveImage("camera.bmp", 100));
        flush();
        printFile("camera.png ", "camera.png");
        java.awt.image.BufferedImage saved = javax.imageio.ImageIO.read(new java.io.File("camera.png"));
        assert saved.getWidth() == 16 && saved.getHeight() == 8;
      }
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
    assert recognised > 0 : "the camera recognised the box";
    assert clouds > 0 : "the lidar gave point clouds";
    assert Camera.pixelGetRed(0x00ab1234) == 0xab && Camera.pixelGetGreen(0x00ab1234) == 0x12
        && Camera.pixelGetBlue(0x00ab1234) == 0x34;
    assert seenTargets > 0 : "the radar sees the parked car";
    assert keys.contains(Keyboard.CONTROL + Keyboard.UP) && keys.contains((int) 'A') : keys;
    assert front.getValue() > 0.0 && front.getValue() < 11.5 : front.getValue();
    car.delete();
  }
}
