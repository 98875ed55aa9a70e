//! The cars' built-in lane-following driver on the simulation ([`crate::lane_following`]).

use super::Simulation;
use crate::error::SimError;
use crate::lane_following::{FollowLane, LaneFollower};
use crate::vehicle::VehicleId;

impl Simulation {
    /// Makes car `id` follow a lane from now on ([`crate::lane_following`]): before each of
    /// its driver steps the built-in driver sets its steering angle. A car already following
    /// takes `request` as a new target: another lane starts a lane change.
    ///
    /// ```
    /// use sim::lane_following::FollowLane;
    /// use sim::road::{Curve, Road, RoadNetwork};
    /// use sim::nalgebra::Point2;
    /// use sim::{CarBuilder, Simulation, VehiclePlacement, World, WorldConfig};
    /// use vehicle_model::Model;
    /// let road = Road::two_way("r", Point2::origin(), 0.0, &[(300.0, Curve::Line)], 3.5)?;
    /// let config = WorldConfig {
    ///     roads: RoadNetwork { roads: vec![road], junctions: vec![] },
    ///     ..WorldConfig::default()
    /// };
    /// let mut sim = Simulation::new(World::new(config)?);
    /// // Half a metre right of the right lane's centre (y = −1.75 m).
    /// let at = VehiclePlacement { x: 5.0, y: -2.25, ..Default::default() };
    /// let (car, _) = sim.add_car(CarBuilder::of_model(Model::BmwX5).placement(at))?;
    /// sim.follow_lane(car, FollowLane::default())?;
    /// sim.driver_mut(car)?.set_cruising_speed(30.0); // km/h
    /// for _ in 0..800 {
    ///     sim.step()?;
    /// }
    /// let y = sim.telemetry(car)?.state.position.y;
    /// assert!((y + 1.75).abs() < 0.05, "{y}"); // m: back on the lane centre
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    ///
    /// # Errors
    /// [`SimError::UnknownVehicle`]; [`SimError::Param`] for a request out of range
    /// ([`FollowLane::validate`]) or a lane change across the centre line.
    pub fn follow_lane(&mut self, id: VehicleId, request: FollowLane) -> Result<(), SimError> {
        let t = self.world.time();
        let car = self.car_mut(id)?;
        match &mut car.follower {
            Some(f) => f.request(request, t)?,
            None => car.follower = Some(LaneFollower::new(car.driver.params(), request)?),
        }
        Ok(())
    }

    /// Stops car `id`'s lane following: the steering stays where it was.
    ///
    /// # Errors
    /// [`SimError::UnknownVehicle`].
    pub fn stop_following_lane(&mut self, id: VehicleId) -> Result<(), SimError> {
        self.car_mut(id)?.follower = None;
        Ok(())
    }

    /// Car `id`'s lane follower, while it follows a lane.
    ///
    /// # Errors
    /// [`SimError::UnknownVehicle`].
    pub fn lane_follower(&self, id: VehicleId) -> Result<Option<&LaneFollower>, SimError> {
        Ok(self.car(id)?.follower.as_ref())
    }
}
