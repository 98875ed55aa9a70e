// Webots' reference Java vehicle controller (projects/vehicles/controllers/vehicle_driver),
// as README.md shows it: it must compile against vehicle.jar and run unchanged, its loop
// ending when the world's duration has elapsed.
import com.cyberbotics.webots.controller.vehicle.Driver;

public class VehicleDriver {
  public static void main(String[] args) {
    Driver driver = new Driver();
    driver.setCruisingSpeed(20.0); // km/h
    while (driver.step() != -1)
      driver.setSteeringAngle(0.3 * Math.cos(driver.getTime())); // rad
  }
}
