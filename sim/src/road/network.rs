//! A network of roads: the roads, how their ends link, and the junctions that join them.

use proto_geom::nalgebra::Point2;

use super::{Road, RoadError, RoadPosition};

/// Which end of a road a link reaches.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ContactPoint {
    /// Its start (s = 0).
    Start,
    /// Its end (s = length).
    End,
}

/// What a road's start or end joins.
#[derive(Debug, Clone, PartialEq)]
pub enum RoadLink {
    /// Another road's end (or this road's own other end: a closed loop).
    Road {
        /// The other road's id.
        id: String,
        /// Which of its ends.
        contact: ContactPoint,
    },
    /// A junction.
    Junction {
        /// The junction's id.
        id: String,
    },
}

/// A connection of a junction: a road coming in and the road (usually a connecting road of
/// the junction) that carries on from it.
#[derive(Debug, Clone, PartialEq)]
pub struct JunctionConnection {
    /// The incoming road's id.
    pub incoming: String,
    /// The connecting road's id.
    pub connecting: String,
    /// Which end of the connecting road meets the incoming road.
    pub contact: ContactPoint,
}

/// A junction: where several roads meet.
#[derive(Debug, Clone, PartialEq)]
pub struct Junction {
    /// Its id.
    pub id: String,
    /// Its connections.
    pub connections: Vec<JunctionConnection>,
}

/// Largest gap (m) between two linked road ends.
pub const LINK_TOLERANCE: f64 = 0.01;

/// Roads and junctions.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct RoadNetwork {
    /// The roads.
    pub roads: Vec<Road>,
    /// The junctions.
    pub junctions: Vec<Junction>,
}

impl RoadNetwork {
    /// True when there is no road.
    pub fn is_empty(&self) -> bool {
        self.roads.is_empty()
    }

    /// The road `id`.
    pub fn road(&self, id: &str) -> Option<&Road> {
        self.roads.iter().find(|r| r.id == id)
    }

    /// Validates every road, checks that ids are unique, that links and junction connections
    /// name existing roads and junctions, and that two road ends linked directly meet within
    /// [`LINK_TOLERANCE`].
    pub fn validate(&self) -> Result<(), RoadError> {
        for (i, r) in self.roads.iter().enumerate() {
            r.validate()?;
            if self.roads[..i].iter().any(|o| o.id == r.id) {
                return Err(error(&r.id, "id", "another road has the same id"));
            }
        }
        for r in &self.roads {
            for (end, link) in [
                (ContactPoint::Start, &r.predecessor),
                (ContactPoint::End, &r.successor),
            ] {
                let field = match end {
                    ContactPoint::Start => "predecessor",
                    ContactPoint::End => "successor",
                };
                match link {
                    Some(RoadLink::Road { id, contact }) => {
                        let other = self.road(id).ok_or_else(|| {
                            error(&r.id, field, &format!("no road has the id '{id}'"))
                        })?;
                        let gap = (end_point(r, end) - end_point(other, *contact)).norm();
                        if gap > LINK_TOLERANCE {
                            return Err(error(
                                &r.id,
                                field,
                                &format!(
                                    "its end is {gap:.3} m from the {} of road '{id}': linked ends must meet within {LINK_TOLERANCE} m",
                                    match contact {
                                        ContactPoint::Start => "start",
                                        ContactPoint::End => "end",
                                    }
                                ),
                            ));
                        }
                    }
                    Some(RoadLink::Junction { id })
                        if !self.junctions.iter().any(|j| j.id == *id) =>
                    {
                        return Err(error(
                            &r.id,
                            field,
                            &format!("no junction has the id '{id}'"),
                        ));
                    }
                    Some(RoadLink::Junction { .. }) | None => {}
                }
            }
        }
        for j in &self.junctions {
            for c in &j.connections {
                for id in [&c.incoming, &c.connecting] {
                    if self.road(id).is_none() {
                        return Err(RoadError {
                            road: id.clone(),
                            field: format!("junction '{}' connection", j.id),
                            message: "no road has this id".into(),
                        });
                    }
                }
            }
        }
        Ok(())
    }

    /// Where `p` (m, world x and y) is on the network: the road (its index) whose lanes hold
    /// it, the nearest reference line first when several do.
    pub fn locate(&self, p: &Point2<f64>) -> Option<(usize, RoadPosition)> {
        self.roads
            .iter()
            .enumerate()
            .filter_map(|(i, r)| r.locate(p).map(|at| (i, at)))
            .min_by(|a, b| a.1.t.abs().total_cmp(&b.1.t.abs()))
    }
}

/// The plan-view point of `road`'s end `end`.
fn end_point(road: &Road, end: ContactPoint) -> Point2<f64> {
    match end {
        ContactPoint::Start => road.plan_at(0.0).point,
        ContactPoint::End => road.plan_at(road.length()).point,
    }
}

fn error(road: &str, field: &str, message: &str) -> RoadError {
    RoadError {
        road: road.to_owned(),
        field: field.to_owned(),
        message: message.to_owned(),
    }
}
