//! `<laneSection>`, its `<lane>`s (type, polynomial width, friction) and their road marks.

use roxmltree::Node;

use super::{OpenDriveError, Reader};
use crate::road::{Lane, LaneKind, LaneSection, LineStyle, Profile, RoadMark};

impl<'d> Reader<'_, 'd> {
    pub(super) fn section(&mut self, node: Node<'_, 'd>) -> Result<LaneSection, OpenDriveError> {
        let mut section = LaneSection {
            s: self.number(node, "s")?,
            left: Vec::new(),
            centre_marks: Vec::new(),
            right: Vec::new(),
        };
        for side in node.children().filter(Node::is_element) {
            let name = side.tag_name().name();
            if !matches!(name, "left" | "center" | "right") {
                self.skip(side, "laneSection");
                continue;
            }
            for lane in side.children().filter(Node::is_element) {
                if !lane.has_tag_name("lane") {
                    self.skip(lane, "laneSection/side");
                    continue;
                }
                let l = self.lane(lane)?;
                match name {
                    "left" if l.id > 0 => section.left.push(l),
                    "right" if l.id < 0 => section.right.push(l),
                    "center" => section.centre_marks = l.marks,
                    _ => {
                        return Err(
                            self.error(lane, format!("lane id {} on the {name} side", l.id))
                        );
                    }
                }
            }
        }
        section.left.sort_by_key(|l| l.id);
        section.right.sort_by_key(|l| -l.id);
        for (side, sign) in [(&section.left, 1), (&section.right, -1)] {
            for (k, l) in side.iter().enumerate() {
                if l.id != sign * (k as i32 + 1) {
                    return Err(self.error(node, format!("lane ids must run 1, 2, … (−1, −2, …) from the centre: lane {} is out of order", l.id)));
                }
            }
        }
        Ok(section)
    }

    pub(super) fn lane(&mut self, node: Node<'_, 'd>) -> Result<Lane, OpenDriveError> {
        let id = node
            .attribute("id")
            .and_then(|v| v.trim().parse::<i32>().ok())
            .ok_or_else(|| self.error(node, "<lane> has no integer id".into()))?;
        let kind = match node.attribute("type").unwrap_or("driving") {
            "driving" | "entry" | "exit" | "onRamp" | "offRamp" | "connectingRamp"
            | "bidirectional" => LaneKind::Driving,
            "shoulder" => LaneKind::Shoulder,
            "border" | "curb" => LaneKind::Border,
            "sidewalk" | "walking" => LaneKind::Sidewalk,
            _ => LaneKind::Other,
        };
        let (mut widths, mut marks, mut friction) = (Vec::new(), Vec::new(), None);
        for c in node.children().filter(Node::is_element) {
            match c.tag_name().name() {
                "width" => widths.push(self.cubic(c, "sOffset")?),
                "roadMark" => {
                    if let Some(m) = self.mark(c)? {
                        marks.push(m);
                    }
                }
                "material" => {
                    if friction.is_none() {
                        friction = Some(self.number(c, "friction")?);
                    } else {
                        self.skip(c, "lane/material (after the first)");
                    }
                }
                _ => self.skip(c, "lane"),
            }
        }
        marks.sort_by(|a: &RoadMark, b| a.s_offset.total_cmp(&b.s_offset));
        Ok(Lane {
            id,
            kind,
            width: Profile::new(widths),
            friction,
            marks,
        })
    }

    pub(super) fn mark(&mut self, node: Node<'_, 'd>) -> Result<Option<RoadMark>, OpenDriveError> {
        let style = match node.attribute("type").unwrap_or("none") {
            "none" => return Ok(None),
            "solid" | "curb" | "edge" => LineStyle::Solid,
            "broken" | "botts dots" => LineStyle::Dashed,
            "solid solid" | "solid broken" | "broken solid" => LineStyle::DoubleSolid,
            "broken broken" => LineStyle::DoubleDashed,
            _ => {
                self.skip(node, "roadMark type");
                return Ok(None);
            }
        };
        let colour = match node.attribute("color").unwrap_or("standard") {
            "yellow" | "orange" => [1.0, 0.8, 0.0],
            "red" => [0.9, 0.1, 0.1],
            "blue" => [0.1, 0.2, 0.9],
            "green" => [0.1, 0.7, 0.2],
            _ => [1.0, 1.0, 1.0],
        };
        let width = self.number_or(node, "width", 0.12)?;
        if !(width > 0.0 && width <= crate::road::MAX_MARK_WIDTH) {
            return Err(self.error(
                node,
                format!(
                    "<roadMark> width=\"{width}\": must be > 0 and at most {} m",
                    crate::road::MAX_MARK_WIDTH
                ),
            ));
        }
        for c in node.children().filter(Node::is_element) {
            self.skip(c, "roadMark");
        }
        Ok(Some(RoadMark {
            s_offset: self.number_or(node, "sOffset", 0.0)?,
            style,
            colour,
            width,
        }))
    }
}
