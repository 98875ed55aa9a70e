//! OpenDRIVE import (ASAM OpenDRIVE 1.4 to 1.7): the plan view (line, arc, spiral, poly3,
//! paramPoly3), elevation and superelevation profiles, lane offsets, lane sections with
//! polynomial widths, lane types, road marks and lane friction (`material`), road links and
//! junction connections. Every other record is skipped with a warning naming the file, the
//! line and the record (once per kind of record, with how many there were); a file that is
//! not OpenDRIVE, or whose values make no road, is an error naming the file and line.
//!
//! The XML is read by `roxmltree` (see ARCHITECTURE.md): a read-only tree that keeps each
//! node's byte range, from which the messages' line numbers come.

use core::fmt;
use std::io::Read;
use std::path::Path;

use roxmltree::{Document, Node};

use super::{
    ContactPoint, Cubic, Junction, JunctionConnection, Profile, Road, RoadLink, RoadNetwork,
};

/// Largest OpenDRIVE file read (bytes): 256 MiB, well above a city's network.
pub const MAX_FILE_BYTES: u64 = 256 << 20;
/// Most plan-view geometries in one file: a 10,000 km network at 50 m a segment.
pub const MAX_GEOMETRIES: usize = 200_000;

/// An OpenDRIVE file that could not be imported: where, and why.
#[derive(Debug, Clone, PartialEq)]
pub struct OpenDriveError {
    /// The file.
    pub file: String,
    /// The line (1-based), if the error has one.
    pub line: Option<u32>,
    /// What is wrong.
    pub message: String,
}

impl fmt::Display for OpenDriveError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.line {
            Some(l) => write!(f, "{}:{l}: {}", self.file, self.message),
            None => write!(f, "{}: {}", self.file, self.message),
        }
    }
}

impl std::error::Error for OpenDriveError {}

/// A record of the file that the import skipped.
#[derive(Debug, Clone, PartialEq)]
pub struct OpenDriveWarning {
    /// The file.
    pub file: String,
    /// The line of its first occurrence (1-based).
    pub line: u32,
    /// The record, e.g. `road/objects`.
    pub record: String,
    /// How many such records the file has.
    pub count: usize,
}

impl fmt::Display for OpenDriveWarning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{}:{}: unsupported OpenDRIVE record <{}> skipped ({} in the file)",
            self.file, self.line, self.record, self.count
        )
    }
}

/// A network read from an OpenDRIVE file, and what it skipped.
#[derive(Debug, Clone, PartialEq)]
pub struct Imported {
    /// The roads and junctions.
    pub network: RoadNetwork,
    /// The skipped records, in the order first met.
    pub warnings: Vec<OpenDriveWarning>,
}

/// Reads and imports the OpenDRIVE file at `path` (at most [`MAX_FILE_BYTES`]).
pub fn load(path: &Path) -> Result<Imported, OpenDriveError> {
    let file = path.display().to_string();
    let fail = |message: String| OpenDriveError {
        file: file.clone(),
        line: None,
        message,
    };
    let f = std::fs::File::open(path).map_err(|e| fail(e.to_string()))?;
    let mut bytes = Vec::new();
    f.take(MAX_FILE_BYTES + 1)
        .read_to_end(&mut bytes)
        .map_err(|e| fail(e.to_string()))?;
    if bytes.len() as u64 > MAX_FILE_BYTES {
        return Err(fail(format!(
            "it is longer than {} MiB",
            MAX_FILE_BYTES >> 20
        )));
    }
    let text = String::from_utf8(bytes).map_err(|_| fail("it is not UTF-8 text".into()))?;
    parse_str(&file, &text)
}

/// Imports OpenDRIVE text; `file` names it in messages.
pub fn parse_str(file: &str, text: &str) -> Result<Imported, OpenDriveError> {
    let doc = Document::parse(text).map_err(|e| OpenDriveError {
        file: file.to_owned(),
        line: Some(e.pos().row),
        message: format!("not well-formed XML: {e}"),
    })?;
    let mut r = Reader {
        file,
        doc: &doc,
        warnings: Vec::new(),
        geometries: 0,
    };
    let root = doc.root_element();
    if root.tag_name().name() != "OpenDRIVE" {
        return Err(r.error(root, "the root element is not <OpenDRIVE>".into()));
    }
    let mut network = RoadNetwork::default();
    for child in root.children().filter(Node::is_element) {
        match child.tag_name().name() {
            "header" => r.header(child),
            "road" => network.roads.push(r.road(child)?),
            "junction" => network.junctions.push(r.junction(child)?),
            _ => r.skip(child, ""),
        }
    }
    network.validate().map_err(|e| {
        let node = root
            .children()
            .find(|n| n.has_tag_name("road") && n.attribute("id") == Some(e.road.as_str()))
            .unwrap_or(root);
        r.error(node, e.to_string())
    })?;
    Ok(Imported {
        network,
        warnings: r.warnings,
    })
}

/// The import's state: the document, for line numbers, and what it skipped.
struct Reader<'a, 'd> {
    file: &'a str,
    doc: &'d Document<'d>,
    warnings: Vec<OpenDriveWarning>,
    geometries: usize,
}

impl<'d> Reader<'_, 'd> {
    fn line(&self, node: Node<'_, '_>) -> u32 {
        self.doc.text_pos_at(node.range().start).row
    }

    fn error(&self, node: Node<'_, '_>, message: String) -> OpenDriveError {
        OpenDriveError {
            file: self.file.to_owned(),
            line: Some(self.line(node)),
            message,
        }
    }

    /// Notes `node` (in `parent`'s path) as skipped.
    fn skip(&mut self, node: Node<'_, '_>, parent: &str) {
        let record = if parent.is_empty() {
            node.tag_name().name().to_owned()
        } else {
            format!("{parent}/{}", node.tag_name().name())
        };
        match self.warnings.iter_mut().find(|w| w.record == record) {
            Some(w) => w.count += 1,
            None => {
                let line = self.line(node);
                self.warnings.push(OpenDriveWarning {
                    file: self.file.to_owned(),
                    line,
                    record,
                    count: 1,
                });
            }
        }
    }

    /// The number in attribute `name` of `node`; an error if absent or not a finite number.
    fn number(&self, node: Node<'_, '_>, name: &str) -> Result<f64, OpenDriveError> {
        let v = node.attribute(name).ok_or_else(|| {
            self.error(
                node,
                format!("<{}> has no attribute '{name}'", node.tag_name().name()),
            )
        })?;
        match v.trim().parse::<f64>() {
            Ok(x) if x.is_finite() => Ok(x),
            _ => Err(self.error(
                node,
                format!(
                    "<{}> {name}=\"{v}\": not a finite number",
                    node.tag_name().name()
                ),
            )),
        }
    }

    /// The number in attribute `name`, or `default` when absent.
    fn number_or(
        &self,
        node: Node<'_, '_>,
        name: &str,
        default: f64,
    ) -> Result<f64, OpenDriveError> {
        if node.attribute(name).is_some() {
            self.number(node, name)
        } else {
            Ok(default)
        }
    }

    /// The cubic of a record with `s` (or `sOffset`) and a, b, c, d.
    fn cubic(&self, node: Node<'_, '_>, s_name: &str) -> Result<Cubic, OpenDriveError> {
        Ok(Cubic {
            s: self.number(node, s_name)?,
            coefficients: [
                self.number(node, "a")?,
                self.number_or(node, "b", 0.0)?,
                self.number_or(node, "c", 0.0)?,
                self.number_or(node, "d", 0.0)?,
            ],
        })
    }

    fn header(&mut self, node: Node<'_, 'd>) {
        let major = node.attribute("revMajor").unwrap_or("1");
        let minor = node
            .attribute("revMinor")
            .and_then(|m| m.parse::<u32>().ok());
        if major != "1" || !minor.is_some_and(|m| (4..=7).contains(&m)) {
            let version = format!(
                "header revision {major}.{}",
                node.attribute("revMinor").unwrap_or("?")
            );
            let line = self.line(node);
            self.warnings.push(OpenDriveWarning {
                file: self.file.to_owned(),
                line,
                record: format!("{version} (1.4 to 1.7 supported; read as such)"),
                count: 1,
            });
        }
        for child in node.children().filter(Node::is_element) {
            self.skip(child, "header");
        }
    }

    fn road(&mut self, node: Node<'_, 'd>) -> Result<Road, OpenDriveError> {
        let id = node
            .attribute("id")
            .ok_or_else(|| self.error(node, "<road> has no attribute 'id'".into()))?
            .to_owned();
        let junction = node
            .attribute("junction")
            .filter(|j| !j.is_empty() && *j != "-1")
            .map(str::to_owned);
        let mut road = Road {
            id,
            segments: Vec::new(),
            elevation: Profile::default(),
            superelevation: Profile::default(),
            lane_offset: Profile::default(),
            sections: Vec::new(),
            friction: crate::DEFAULT_FRICTION,
            predecessor: None,
            successor: None,
            junction,
        };
        for child in node.children().filter(Node::is_element) {
            match child.tag_name().name() {
                "link" => {
                    for l in child.children().filter(Node::is_element) {
                        match l.tag_name().name() {
                            "predecessor" => road.predecessor = self.link(l)?,
                            "successor" => road.successor = self.link(l)?,
                            _ => self.skip(l, "road/link"),
                        }
                    }
                }
                "planView" => {
                    for g in child.children().filter(Node::is_element) {
                        if g.has_tag_name("geometry") {
                            road.segments.push(self.geometry(g)?);
                        } else {
                            self.skip(g, "road/planView");
                        }
                    }
                }
                "elevationProfile" => {
                    let mut pieces = Vec::new();
                    for e in child.children().filter(Node::is_element) {
                        if e.has_tag_name("elevation") {
                            pieces.push(self.cubic(e, "s")?);
                        } else {
                            self.skip(e, "road/elevationProfile");
                        }
                    }
                    road.elevation = Profile::new(pieces);
                }
                "lateralProfile" => {
                    let mut pieces = Vec::new();
                    for e in child.children().filter(Node::is_element) {
                        if e.has_tag_name("superelevation") {
                            pieces.push(self.cubic(e, "s")?);
                        } else {
                            self.skip(e, "road/lateralProfile");
                        }
                    }
                    road.superelevation = Profile::new(pieces);
                }
                "lanes" => {
                    let mut offsets = Vec::new();
                    for l in child.children().filter(Node::is_element) {
                        match l.tag_name().name() {
                            "laneOffset" => offsets.push(self.cubic(l, "s")?),
                            "laneSection" => road.sections.push(self.section(l)?),
                            _ => self.skip(l, "road/lanes"),
                        }
                    }
                    road.lane_offset = Profile::new(offsets);
                }
                _ => self.skip(child, "road"),
            }
        }
        if road.segments.is_empty() {
            return Err(self.error(
                node,
                format!("road '{}' has no <planView> geometry", road.id),
            ));
        }
        road.sections.sort_by(|a, b| a.s.total_cmp(&b.s));
        Ok(road)
    }

    fn link(&mut self, node: Node<'_, 'd>) -> Result<Option<RoadLink>, OpenDriveError> {
        let Some(id) = node.attribute("elementId") else {
            return Err(self.error(node, "a road link has no attribute 'elementId'".into()));
        };
        Ok(match node.attribute("elementType").unwrap_or("road") {
            "junction" => Some(RoadLink::Junction { id: id.to_owned() }),
            "road" => Some(RoadLink::Road {
                id: id.to_owned(),
                contact: self.contact(node)?,
            }),
            _ => {
                self.skip(node, "road/link");
                None
            }
        })
    }

    fn contact(&self, node: Node<'_, '_>) -> Result<ContactPoint, OpenDriveError> {
        match node.attribute("contactPoint").unwrap_or("start") {
            "start" => Ok(ContactPoint::Start),
            "end" => Ok(ContactPoint::End),
            other => Err(self.error(
                node,
                format!("contactPoint=\"{other}\": must be start or end"),
            )),
        }
    }

    fn junction(&mut self, node: Node<'_, 'd>) -> Result<Junction, OpenDriveError> {
        let id = node
            .attribute("id")
            .ok_or_else(|| self.error(node, "<junction> has no attribute 'id'".into()))?
            .to_owned();
        let mut connections = Vec::new();
        for c in node.children().filter(Node::is_element) {
            if !c.has_tag_name("connection") {
                self.skip(c, "junction");
                continue;
            }
            let (Some(incoming), Some(connecting)) =
                (c.attribute("incomingRoad"), c.attribute("connectingRoad"))
            else {
                self.skip(
                    c,
                    "junction/connection (without incomingRoad and connectingRoad)",
                );
                continue;
            };
            for l in c.children().filter(Node::is_element) {
                self.skip(l, "junction/connection");
            }
            connections.push(JunctionConnection {
                incoming: incoming.to_owned(),
                connecting: connecting.to_owned(),
                contact: self.contact(c)?,
            });
        }
        Ok(Junction { id, connections })
    }
}

mod geometry;
mod lanes;
#[cfg(test)]
mod tests;
