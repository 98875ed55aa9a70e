//! Wavefront OBJ / MTL writer.

use std::io::{self, Write};
use std::string::{String, ToString};
use std::vec::Vec;

use nalgebra::{Point3, Vector3};

use super::{Geometry, Scene};

impl Scene {
    /// Writes the scene as Wavefront OBJ (ASCII, m, z up as in the vehicle frame), at rest (OBJ
    /// has no animation).
    ///
    /// Each mesh instance becomes an object (`o`) named by its node path below the root (a
    /// wheel scene gives `tyre`, `rim`, `hub`; a vehicle `front_right_wheel.tyre`, …) with
    /// `usemtl <material>`; positions and normals are baked into the vehicle frame. If
    /// `mtl_file` is given, a `mtllib` line refers to it (write it with [`Scene::write_mtl`]).
    ///
    /// # Errors
    /// Any error of `w`.
    pub fn write_obj<W: Write>(&self, w: &mut W, mtl_file: Option<&str>) -> io::Result<()> {
        writeln!(
            w,
            "# Webots VehicleWheel geometry exported by proto-geom (m, z up)"
        )?;
        if let Some(mtl) = mtl_file {
            writeln!(w, "mtllib {mtl}")?;
        }
        let mut base = 1usize;
        let mut result = Ok(());
        self.for_each_instance(|name, world, part| {
            if result.is_err() {
                return;
            }
            result = (|| {
                writeln!(w, "o {name}")?;
                if let Some(mat) = self.materials.get(part.material) {
                    writeln!(w, "usemtl {}", mat.name)?;
                }
                let point = |p: [f32; 3]| {
                    let [x, y, z] = p.map(f64::from);
                    world.transform_point(&Point3::new(x, y, z))
                };
                match &part.geometry {
                    Geometry::Triangles(m) => {
                        for v in &m.vertices {
                            let p = point(v.position);
                            writeln!(w, "v {} {} {}", p.x as f32, p.y as f32, p.z as f32)?;
                        }
                        for v in &m.vertices {
                            writeln!(w, "vt {} {}", v.tex_coord[0], v.tex_coord[1])?;
                        }
                        for v in &m.vertices {
                            let [x, y, z] = v.normal.map(f64::from);
                            let n = world.transform_vector(&Vector3::new(x, y, z));
                            writeln!(w, "vn {} {} {}", n.x as f32, n.y as f32, n.z as f32)?;
                        }
                        for t in m.indices.chunks_exact(3) {
                            let [a, b, c] = [t[0], t[1], t[2]].map(|i| i as usize + base);
                            writeln!(w, "f {a}/{a}/{a} {b}/{b}/{b} {c}/{c}/{c}")?;
                        }
                        base += m.vertices.len();
                    }
                    Geometry::Segments(points)
                    | Geometry::Polyline(points)
                    | Geometry::Points(points) => {
                        for &v in points {
                            let p = point(v);
                            writeln!(w, "v {} {} {}", p.x as f32, p.y as f32, p.z as f32)?;
                        }
                        if let Geometry::Segments(_) = part.geometry {
                            for i in (0..points.len() / 2).map(|k| base + 2 * k) {
                                writeln!(w, "l {i} {}", i + 1)?;
                            }
                        } else if let Geometry::Points(_) = part.geometry {
                            for i in base..base + points.len() {
                                writeln!(w, "p {i}")?;
                            }
                        } else if points.len() >= 2 {
                            let all: Vec<String> =
                                (base..base + points.len()).map(|i| i.to_string()).collect();
                            writeln!(w, "l {}", all.join(" "))?;
                        }
                        base += points.len();
                    }
                }
                Ok(())
            })();
        });
        result
    }

    /// Writes the materials as a Wavefront MTL file: diffuse `Kd` = base colour, a specular
    /// colour and exponent approximating metalness and roughness, and the PBR extension
    /// statements `Pr` (roughness) and `Pm` (metalness), and the emission `Ke`.
    ///
    /// # Errors
    /// Any error of `w`.
    pub fn write_mtl<W: Write>(&self, w: &mut W) -> io::Result<()> {
        writeln!(w, "# Materials exported by proto-geom")?;
        for m in &self.materials {
            let [r, g, b] = m.base_color;
            // Dielectrics reflect about 4 %, metals their base colour.
            let ks = |c: f32| 0.04 + (c - 0.04) * m.metalness;
            // Blinn-Phong exponent of a GGX roughness α = r²: 2/α² − 2.
            let alpha = (m.roughness * m.roughness).max(0.03);
            let ns = (2.0 / (alpha * alpha) - 2.0).clamp(0.0, 1000.0);
            writeln!(w, "\nnewmtl {}", m.name)?;
            writeln!(w, "Ka 0 0 0")?;
            writeln!(w, "Kd {r} {g} {b}")?;
            writeln!(w, "Ks {} {} {}", ks(r), ks(g), ks(b))?;
            writeln!(w, "Ns {ns}")?;
            writeln!(w, "Pr {}", m.roughness)?;
            writeln!(w, "Pm {}", m.metalness)?;
            let [er, eg, eb] = m.emissive;
            writeln!(w, "Ke {er} {eg} {eb}")?;
            writeln!(w, "illum 2")?;
        }
        Ok(())
    }
}
