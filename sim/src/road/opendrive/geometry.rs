//! The plan view's records (`<geometry>`: line, arc, spiral, poly3, paramPoly3) as road
//! segments.

use proto_geom::nalgebra::Point2;
use roxmltree::Node;

use super::{MAX_GEOMETRIES, OpenDriveError, Reader};
use crate::road::{Curve, ParamRange, Segment, cubic_length};

impl<'d> Reader<'_, 'd> {
    pub(super) fn geometry(&mut self, node: Node<'_, 'd>) -> Result<Segment, OpenDriveError> {
        self.geometries += 1;
        if self.geometries > MAX_GEOMETRIES {
            return Err(self.error(
                node,
                format!("more than {MAX_GEOMETRIES} <geometry> records"),
            ));
        }
        let length = self.number(node, "length")?;
        if length <= 0.0 {
            return Err(self.error(node, format!("<geometry> length=\"{length}\": must be > 0")));
        }
        let Some(shape) = node.children().find(Node::is_element) else {
            return Err(self.error(
                node,
                "<geometry> has no shape (line, arc, spiral, poly3, paramPoly3)".into(),
            ));
        };
        let curve =
            match shape.tag_name().name() {
                "line" => Curve::Line,
                "arc" => Curve::Arc {
                    curvature: self.number(shape, "curvature")?,
                },
                "spiral" => Curve::Spiral {
                    curvature_start: self.number(shape, "curvStart")?,
                    curvature_end: self.number(shape, "curvEnd")?,
                },
                "paramPoly3" => {
                    let mut c = [0.0; 8];
                    for (v, name) in c
                        .iter_mut()
                        .zip(["aU", "bU", "cU", "dU", "aV", "bV", "cV", "dV"])
                    {
                        *v = self.number_or(shape, name, 0.0)?;
                    }
                    let range = match shape.attribute("pRange").unwrap_or("normalized") {
                        "normalized" => ParamRange::Normalized,
                        "arcLength" => ParamRange::ArcLength,
                        other => {
                            return Err(self.error(
                                shape,
                                format!("pRange=\"{other}\": must be arcLength or normalized"),
                            ));
                        }
                    };
                    Curve::ParamPoly3 {
                        u: [c[0], c[1], c[2], c[3]],
                        v: [c[4], c[5], c[6], c[7]],
                        range,
                    }
                }
                "poly3" => {
                    let v = [
                        self.number(shape, "a")?,
                        self.number(shape, "b")?,
                        self.number(shape, "c")?,
                        self.number(shape, "d")?,
                    ];
                    poly3(v, length).ok_or_else(|| {
                        self.error(shape, "<poly3> whose length cannot be reached".into())
                    })?
                }
                other => return Err(self.error(
                    shape,
                    format!(
                        "unknown geometry <{other}>: must be line, arc, spiral, poly3 or paramPoly3"
                    ),
                )),
            };
        Ok(Segment {
            s: self.number(node, "s")?,
            start: Point2::new(self.number(node, "x")?, self.number(node, "y")?),
            heading: self.number(node, "hdg")?,
            length,
            curve,
        })
    }
}

/// OpenDRIVE's `poly3` v(u) = a + b·u + c·u² + d·u³ (u along the start heading) of arc length
/// `length` (m), as a normalized parametric cubic u(p) = U·p: U by Newton's method on the
/// arc length (L'(U) = √(1 + v'(U)²) ≥ 1, so it converges from U = length).
fn poly3(v: [f64; 4], length: f64) -> Option<Curve> {
    let mut u_end = length;
    for _ in 0..50 {
        let vv = [
            v[0],
            v[1] * u_end,
            v[2] * u_end * u_end,
            v[3] * u_end * u_end * u_end,
        ];
        let l = cubic_length(&[0.0, u_end, 0.0, 0.0], &vv, 1.0);
        let slope = v[1] + 2.0 * v[2] * u_end + 3.0 * v[3] * u_end * u_end;
        let step = (l - length) / (1.0 + slope * slope).sqrt();
        u_end -= step;
        if !(u_end.is_finite() && u_end > 0.0) {
            return None;
        }
        if step.abs() < 1e-10 * length {
            let u = [0.0, u_end, 0.0, 0.0];
            let vv = [
                v[0],
                v[1] * u_end,
                v[2] * u_end * u_end,
                v[3] * u_end * u_end * u_end,
            ];
            return Some(Curve::ParamPoly3 {
                u,
                v: vv,
                range: ParamRange::Normalized,
            });
        }
    }
    None
}
