use super::*;
use crate::road::{Curve, LaneKind, LineStyle, cubic_length};
use core::f64::consts::PI;

/// A two-road network as the common writers (scenariogeneration, RoadRunner) lay it out: a
/// line, a spiral, an arc and a paramPoly3 on road 1, lane sections with cubic widths, a
/// crest and a bank, marks and a material; road 2 a poly3 continuing it through a junction.
const NETWORK: &str = r#"<?xml version="1.0" encoding="UTF-8"?>
<OpenDRIVE>
  <header revMajor="1" revMinor="6" name="test" date="2026-11-28"/>
  <road id="1" length="150" junction="-1">
    <link><successor elementType="junction" elementId="100"/></link>
    <type s="0" type="town"/>
    <planView>
      <geometry s="0" x="0" y="0" hdg="0" length="50"><line/></geometry>
      <geometry s="50" x="50" y="0" hdg="0" length="20"><spiral curvStart="0" curvEnd="0.02"/></geometry>
      <geometry s="70" x="69.99466768" y="1.33315523" hdg="0.2" length="30"><arc curvature="0.02"/></geometry>
      <geometry s="100" x="98.2279" y="10.6296" hdg="0.8" length="50">
        <paramPoly3 aU="0" bU="50" cU="0" dU="0" aV="0" bV="0" cV="0" dV="0" pRange="normalized"/>
      </geometry>
    </planView>
    <elevationProfile>
      <elevation s="0" a="1" b="0.02" c="0" d="0"/>
      <elevation s="100" a="3" b="0.02" c="-0.0002" d="0"/>
    </elevationProfile>
    <lateralProfile>
      <superelevation s="0" a="0" b="0.001" c="0" d="0"/>
      <shape s="0" t="0" a="0" b="0" c="0" d="0"/>
    </lateralProfile>
    <lanes>
      <laneOffset s="0" a="0.5" b="0" c="0" d="0"/>
      <laneSection s="0">
        <left>
          <lane id="1" type="driving" level="false">
            <width sOffset="0" a="3.5" b="0" c="0" d="0"/>
            <roadMark sOffset="0" type="solid" color="standard" width="0.15"/>
          </lane>
        </left>
        <center>
          <lane id="0" type="none"><roadMark sOffset="0" type="broken" color="yellow" width="0.12"/></lane>
        </center>
        <right>
          <lane id="-1" type="driving">
            <link><successor id="-1"/></link>
            <width sOffset="0" a="3.0" b="0.01" c="0" d="0"/>
            <material sOffset="0" surface="asphalt" friction="0.8" roughness="0"/>
          </lane>
          <lane id="-2" type="shoulder"><width sOffset="0" a="1" b="0" c="0" d="0"/></lane>
        </right>
      </laneSection>
      <laneSection s="70">
        <right>
          <lane id="-1" type="driving"><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane>
        </right>
      </laneSection>
    </lanes>
    <objects><object id="o1" s="10" t="5" type="pole"/></objects>
  </road>
  <road id="2" length="20" junction="100">
    <planView>
      <geometry s="0" x="0" y="-30" hdg="0" length="20"><poly3 a="0" b="0" c="0.01" d="0"/></geometry>
    </planView>
    <lanes><laneSection s="0"><right><lane id="-1" type="driving"><width sOffset="0" a="3" b="0" c="0" d="0"/></lane></right></laneSection></lanes>
  </road>
  <junction id="100" name="j">
    <connection id="0" incomingRoad="1" connectingRoad="2" contactPoint="start">
      <laneLink from="-1" to="-1"/>
    </connection>
  </junction>
</OpenDRIVE>
"#;

#[test]
fn a_network_loads_with_its_geometry_lanes_and_profiles() {
    let imported = parse_str("n.xodr", NETWORK).unwrap();
    let net = &imported.network;
    assert_eq!(net.roads.len(), 2);
    let road = net.road("1").unwrap();
    assert_eq!(road.segments.len(), 4);
    assert!((road.length() - 150.0).abs() < 1e-12);
    // The line: a lane centre at s = 20 m, lane −1 (3 + 0.01·20 = 3.2 m wide) right of the
    // 0.5 m lane offset: t = 0.5 − 1.6.
    let (t0, edges) = road.lane_edges(20.0);
    assert_eq!(t0, 0.5);
    let (_, a, b) = edges.iter().find(|e| e.0.id == -1).copied().unwrap();
    assert!((a - 0.5).abs() < 1e-12 && (b - (0.5 - 3.2)).abs() < 1e-12);
    // Elevation and superelevation as written.
    let p = road.surface_point(20.0, 0.5 - 1.6);
    let phi: f64 = 0.02;
    assert!((p.z - (1.0 + 0.4 + (0.5 - 1.6) * phi.sin())).abs() < 1e-12);
    assert!((road.elevation.value(110.0) - (3.0 + 0.2 - 0.02)).abs() < 1e-12);
    // The spiral from the line's end: its curvature 0.01 1/m halfway.
    assert!((road.plan_at(60.0).curvature - 0.01).abs() < 1e-15);
    // Friction and marks.
    assert_eq!(road.friction_at(10.0, -1.0), 0.8);
    assert_eq!(road.friction_at(10.0, 2.0), 1.0);
    assert_eq!(road.sections[0].centre_marks[0].colour, [1.0, 0.8, 0.0]);
    assert_eq!(road.sections[0].centre_marks[0].style, LineStyle::Dashed);
    assert_eq!(road.sections[0].right[1].kind, LaneKind::Shoulder);
    // The second section: one lane.
    assert_eq!(road.section_at(80.0).unwrap().right.len(), 1);
    // The junction and its connecting road.
    assert_eq!(net.junctions[0].connections[0].connecting, "2");
    assert_eq!(net.road("2").unwrap().junction.as_deref(), Some("100"));
    // Skipped records, once each, with their lines.
    let records: Vec<(&str, u32)> = imported
        .warnings
        .iter()
        .map(|w| (w.record.as_str(), w.line))
        .collect();
    assert!(records.contains(&("road/type", 6)), "{records:?}");
    assert!(
        records.contains(&("road/lateralProfile/shape", 21)),
        "{records:?}"
    );
    assert!(records.contains(&("road/objects", 50)), "{records:?}");
    assert!(
        imported.warnings[0]
            .to_string()
            .starts_with("n.xodr:6: unsupported OpenDRIVE record <road/type>")
    );
}

#[test]
fn a_poly3_has_its_length_and_follows_its_cubic() {
    let imported = parse_str("n.xodr", NETWORK).unwrap();
    let road = imported.network.road("2").unwrap();
    let Curve::ParamPoly3 { u, v, .. } = road.segments[0].curve else {
        panic!()
    };
    // Its arc length is the geometry's 20 m, and every point is on v = 0.01·u².
    assert!((cubic_length(&u, &v, 1.0) - 20.0).abs() < 1e-9);
    for s in [0.0, 7.0, 20.0] {
        let p = road.plan_at(s).point;
        assert!((p.y + 30.0 - 0.01 * p.x * p.x).abs() < 1e-12);
    }
}

#[test]
fn bad_files_are_errors_not_panics() {
    let cases: Vec<(String, &str)> = vec![
        (
            NETWORK[..NETWORK.len() / 2].to_owned(),
            "not well-formed XML",
        ),
        (
            NETWORK.replace("<line/>", "<clothoid/>"),
            "unknown geometry <clothoid>",
        ),
        (
            NETWORK.replace(r#"a="3.5" b="0""#, r#"a="-3.5" b="0""#),
            "lane 1 width",
        ),
        (
            NETWORK.replace(r#"length="30"><arc"#, r#"length="-30"><arc"#),
            "must be > 0",
        ),
        (
            NETWORK.replace(r#"curvature="0.02""#, r#"curvature="nan""#),
            "not a finite number",
        ),
        ("<html/>".to_owned(), "not <OpenDRIVE>"),
        (String::new(), "not well-formed XML"),
    ];
    for (text, expected) in cases {
        let e = parse_str("bad.xodr", &text).unwrap_err();
        assert!(e.to_string().contains(expected), "{expected}: {e}");
        assert!(e.to_string().starts_with("bad.xodr:"), "{e}");
    }
    // 10⁶ geometries: refused past the limit, quickly, without building them.
    let mut text = String::from("<OpenDRIVE><road id=\"r\"><planView>");
    for i in 0..1_000_000 {
        text.push_str(&format!(
            "<geometry s=\"{i}\" x=\"{i}\" y=\"0\" hdg=\"0\" length=\"1\"><line/></geometry>"
        ));
    }
    text.push_str("</planView></road></OpenDRIVE>");
    let e = parse_str("big.xodr", &text).unwrap_err();
    assert!(e.message.contains("more than 200000 <geometry>"), "{e}");
}

#[test]
fn linked_roads_must_meet() {
    let text = r#"<OpenDRIVE><header revMajor="1" revMinor="4"/>
<road id="a" length="10"><link><successor elementType="road" elementId="b" contactPoint="start"/></link>
<planView><geometry s="0" x="0" y="0" hdg="0" length="10"><line/></geometry></planView>
<lanes><laneSection s="0"><right><lane id="-1"><width sOffset="0" a="3"/></lane></right></laneSection></lanes></road>
<road id="b" length="10"><planView><geometry s="0" x="10" y="0" hdg="0" length="10"><arc curvature="0.1"/></geometry></planView>
<lanes><laneSection s="0"><right><lane id="-1"><width sOffset="0" a="3"/></lane></right></laneSection></lanes></road>
</OpenDRIVE>"#;
    let ok = parse_str("l.xodr", text).unwrap();
    assert!(ok.warnings.is_empty(), "{:?}", ok.warnings);
    let end = ok.network.road("b").unwrap().plan_at(10.0);
    // An arc of 10 m at 0.1 1/m turns by 1 rad.
    assert!((end.heading - 1.0).abs() < 1e-15);
    assert!((end.point.x - (10.0 + 1.0_f64.sin() * 10.0)).abs() < 1e-12);
    let gap = text.replace(r#"x="10" y="0""#, r#"x="10.5" y="0""#);
    let e = parse_str("l.xodr", &gap).unwrap_err();
    assert_eq!(e.line, Some(2));
    assert!(
        e.message.contains("0.500 m from the start of road 'b'"),
        "{e}"
    );
    let _ = PI;
}
