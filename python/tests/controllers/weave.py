"""A Webots vehicle controller, written for Webots and run here unchanged: cruise at 20 km/h,
weave left and right, go straight again, and stop when the simulation ends (the world's
`duration`). Prints the time (s) and the speed (km/h) of every step."""

from vehicle import Driver

driver = Driver()
driver.setSteeringAngle(0.0)
driver.setCruisingSpeed(20)

while driver.step() != -1:
    t = driver.getTime()
    if 1.0 <= t < 2.0:
        driver.setSteeringAngle(0.1)
    elif 2.0 <= t < 3.0:
        driver.setSteeringAngle(-0.1)
    else:
        driver.setSteeringAngle(0.0)
    print(f"{t:.3f} {driver.getCurrentSpeed():.6f}")
print("end", driver.getTime())
