//! Vertex and triangle counts of every wheel mesh, from the formulas of spec §4.4.
// Test helpers outside #[test] functions unwrap too: a failed lookup is a failed test.
#![allow(clippy::unwrap_used, clippy::expect_used)]

mod common;

use proto_geom::{
    BufferTooSmall, RimCentreMesh, RimContourMesh, TriMesh, TyreMesh, WheelParams, WheelPreset,
};

/// (preset, S, E, N, tyre vertices, tyre triangles, rim vertices, rim triangles, hub vertices,
/// hub triangles), each count worked out by hand:
/// tyre (2E+4)(S+1) / 2S(2E+3), rim contour 4(S+1) / 6S, rim centre 10N+12 / 17N.
const EXPECTED: [(WheelPreset, u32, u32, u32, [usize; 6]); 10] = [
    // S 36, E 3, N 5: 10·37 = 370, 2·36·9 = 648; 4·37 = 148, 216; 62, 85.
    (
        WheelPreset::VehicleWheel,
        36,
        3,
        5,
        [370, 648, 148, 216, 62, 85],
    ),
    // S 24, E 1, N 5: 6·25 = 150, 2·24·5 = 240; 100, 144; 62, 85.
    (
        WheelPreset::AutomobileWheel,
        24,
        1,
        5,
        [150, 240, 100, 144, 62, 85],
    ),
    (
        WheelPreset::BmwX5Wheel,
        36,
        3,
        5,
        [370, 648, 148, 216, 62, 85],
    ),
    // E 2, N 6: 8·37 = 296, 2·36·7 = 504; hub 72, 102.
    (
        WheelPreset::ToyotaPriusWheel,
        36,
        2,
        6,
        [296, 504, 148, 216, 72, 102],
    ),
    // E 2, N 7: hub 82, 119.
    (
        WheelPreset::CitroenCZeroFrontWheel,
        36,
        2,
        7,
        [296, 504, 148, 216, 82, 119],
    ),
    (
        WheelPreset::CitroenCZeroRearWheel,
        36,
        2,
        7,
        [296, 504, 148, 216, 82, 119],
    ),
    (
        WheelPreset::BusWheel,
        36,
        3,
        7,
        [370, 648, 148, 216, 82, 119],
    ),
    (
        WheelPreset::TruckWheel,
        36,
        3,
        6,
        [370, 648, 148, 216, 72, 102],
    ),
    (
        WheelPreset::LincolnMKZWheel,
        36,
        3,
        5,
        [370, 648, 148, 216, 62, 85],
    ),
    (
        WheelPreset::RangeRoverSportSVRWheel,
        36,
        3,
        5,
        [370, 648, 148, 216, 62, 85],
    ),
];

#[test]
fn counts_match_formulas_for_default_and_shipped_wheels() {
    for (preset, s, e, n, expected) in EXPECTED {
        let (w, warnings) = preset.params::<f64>().validate();
        assert!(warnings.is_empty(), "{preset:?}");
        assert_eq!(
            (w.subdivision(), w.edge_subdivision(), w.rim_beam_number()),
            (s, e, n),
            "{preset:?}"
        );
        let (tyre, rim, hub) = (w.tyre(), w.rim_contour(), w.rim_centre());
        let got = [
            tyre.vertex_count(),
            tyre.triangle_count(),
            rim.vertex_count(),
            rim.triangle_count(),
            hub.vertex_count(),
            hub.triangle_count(),
        ];
        assert_eq!(got, expected, "{preset:?}");
        let formulas = [
            TyreMesh::<f64>::vertex_count_for(s, e),
            TyreMesh::<f64>::triangle_count_for(s, e),
            RimContourMesh::<f64>::vertex_count_for(s),
            RimContourMesh::<f64>::triangle_count_for(s),
            RimCentreMesh::<f64>::vertex_count_for(n),
            RimCentreMesh::<f64>::triangle_count_for(n),
        ];
        assert_eq!(formulas, expected, "{preset:?}");
        // The iterators yield exactly the counts, and every index is in range.
        assert_eq!(tyre.positions().count(), expected[0]);
        assert_eq!(hub.triangles().count(), expected[5]);
        for m in [&tyre as &dyn TriMesh<f64>, &rim, &hub] {
            for t in 0..m.triangle_count() {
                let tri = m.triangle(t).unwrap();
                assert!(tri.iter().all(|&v| (v as usize) < m.vertex_count()));
                let nor = m.triangle_normals(t).unwrap();
                assert!(nor.iter().all(|&v| (v as usize) < m.normal_count()));
            }
            assert!(m.triangle(m.triangle_count()).is_none());
            assert!(m.position(m.vertex_count()).is_none());
            assert!(m.normal(m.normal_count()).is_none());
        }
    }
}

#[test]
fn every_shipped_vehicle_wheel_is_in_the_table() {
    let listed: Vec<_> = EXPECTED.iter().map(|e| e.0).collect();
    for p in WheelPreset::ALL {
        assert_eq!(listed.contains(&p), p.is_vehicle_wheel(), "{p:?}");
    }
}

#[test]
fn fill_buffers_without_allocation() {
    let (w, _) = WheelParams::<f32>::default().validate();
    let tyre = w.tyre();
    let mut pos = [[0.0_f32; 3]; 370];
    let mut tri = [[0_u32; 3]; 648];
    let mut uv = [[0.0_f32; 2]; 370];
    assert_eq!(tyre.fill_positions(&mut pos), Ok(370));
    assert_eq!(tyre.fill_triangles(&mut tri), Ok(648));
    assert_eq!(tyre.fill_tex_coords(&mut uv), Ok(370));
    // Vertex 0: ring A (x = T/2 = 0.15 m), angle 0: (0.15, −ρrim, 0) = (0.15, −0.28, 0).
    assert_eq!(pos[0], [0.15, -0.28, 0.0]);
    // First triangle (o0, o0+1, o1+1) = (0, 1, 38).
    assert_eq!(tri[0], [0, 1, 38]);
    // Second triangle (o1+1, o1, o0) = (38, 37, 0).
    assert_eq!(tri[1], [38, 37, 0]);
    // Last vertex: ring D, i = S: u = 1, v = 10.
    assert_eq!(uv[369], [1.0, 10.0]);
    let mut short = [[0.0_f32; 3]; 10];
    assert_eq!(
        tyre.fill_positions(&mut short),
        Err(BufferTooSmall {
            needed: 370,
            given: 10
        })
    );
    // The rim centre has no texture coordinates: nothing to write.
    assert_eq!(w.rim_centre().fill_tex_coords(&mut []), Ok(0));
}

#[test]
fn rim_centre_keeps_webots_vertices_and_drops_the_broken_triangles() {
    let (w, _) = WheelParams::<f64>::default().validate();
    let hub = w.rim_centre();
    // Webots: 17N + 7 = 92 triangles for N = 5; the corrected mesh has 17N = 85.
    assert_eq!(hub.triangle_count() + 7, 92);
    // Front hub fan, first triangle: (hub centre 0, block 0 point 1, block 0 point 0) = (0, 2, 1)
    // (Webots' first triangle is the degenerate (0, 1, 0)).
    assert_eq!(hub.triangle(0), Some([0, 2, 1]));
    // Back hub centre index 1 + 10·6 = 61, the last vertex.
    assert_eq!(hub.position(61).unwrap().x, 0.2 / 2.0 - 0.03 / 2.0);
    // Every vertex but the 7 unreferenced seam duplicates is used.
    let mut used = vec![false; hub.vertex_count()];
    for t in hub.triangles() {
        for v in t {
            used[v as usize] = true;
        }
    }
    assert_eq!(used.iter().filter(|u| !**u).count(), 7);
}
