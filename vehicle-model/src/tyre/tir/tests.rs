extern crate std;
use std::string::ToString;
use std::vec::Vec;

use super::*;
use crate::tyre::{Direction, TyreClass};

/// A minimal MF 5.2 file with every required key, in mm and kN.
const SMALL: &str = "[MDI_HEADER]\nFILE_TYPE = 'tir'\n[UNITS]\nLENGTH = 'mm' $ millimetres\n\
FORCE = 'kN'\n[MODEL]\nFITTYP = 6\n[DIMENSION]\nUNLOADED_RADIUS = 300\n[VERTICAL]\n\
FNOMIN = 4 ! kN\n[SCALING_COEFFICIENTS]\nLMUY = 0.9\n[LONGITUDINAL_COEFFICIENTS]\n\
PCX1 = 1.6\nPDX1 = 1.0\nPDX2 = -0.1\nPKX1 = 20\nPKX2 = 1.5\n[LATERAL_COEFFICIENTS]\n\
PCY1 = 1.3\nPDY1 = 0.9\nPDY2 = -0.09\nPEY1 = -0.5\nPKY1 = -18\nPKY2 = 2\nPTY1 = 2\n\
PTY2 = 2\nRBY1 = 7\n[SHAPE]\n{radial width}\n1.0 0.0\n0.9 1.0\n";

#[test]
fn reads_units_comments_and_tables() {
    let tir = TirFile::read(SMALL).unwrap();
    // 300 mm and 4 kN in SI.
    assert_eq!(tir.value("UNLOADED_RADIUS"), Some(0.3));
    assert_eq!(tir.value("FNOMIN"), Some(4000.0));
    assert_eq!(tir.value("PKY1"), Some(-18.0));
    assert_eq!(tir.line("PKY1"), 25);
    assert_eq!(tir.value("PTX1"), None);
    // FILE_TYPE is the header's; the table rows are skipped; RBY1 is a combined-slip term.
    assert_eq!(tir.ignored().collect::<Vec<_>>(), [(29, "RBY1")]);
    // PKX2 is a load dependence the model cannot follow; PDX2/PDX1 = PDY2/PDY1.
    assert_eq!(tir.approximated().collect::<Vec<_>>(), [(19, "PKX2")]);
}

#[test]
fn maps_by_the_formulas() {
    let tir = TirFile::read(SMALL).unwrap();
    let mut p = TyreClass::PassengerCar.params(0.3, 4000.0);
    tir.apply(&mut p).unwrap();
    let close = |a: f64, b: f64| (a - b).abs() < 1e-12 * b.abs().max(1.0);
    assert!(close(p.nominal_load, 4000.0));
    // D_y = PDY1·LMUY; K_y/F_z at F_z0 = |PKY1|·sin(2·atan(1/PKY2)) = 18·0.8 (sin(2·atan ½) = 0.8).
    assert!(close(p.lateral.peak_friction, 0.81));
    assert!(close(p.lateral.stiffness, 18.0 * 0.8));
    assert!(close(p.longitudinal.stiffness, 20.0));
    assert!(close(p.load_sensitivity, 0.1));
    assert!(close(p.cornering_saturation, 2.0));
    // σ_α = PTY1·sin(2·atan(1/PTY2))·R₀ = 2·0.8·0.3 m; no PTX1: the class's stays.
    assert!(close(p.lateral.relaxation_length, 0.48));
    let class = TyreClass::PassengerCar.params(0.3, 4000.0);
    assert_eq!(
        p.longitudinal.relaxation_length,
        class.longitudinal.relaxation_length
    );
    assert_eq!(p.rolling_resistance, class.rolling_resistance);
}

#[test]
fn errors_name_line_and_key() {
    let err = |text: &'static str| TirFile::read(text).unwrap_err();
    let e = err("[VERTICAL]\nFNOMIN = 4000\nFNOMIN = 5000\n");
    assert_eq!(
        (e.line, e.key, e.kind),
        (3, "FNOMIN", TirErrorKind::Duplicate(2))
    );
    let e = err("[LATERAL_COEFFICIENTS]\nPKY1 = fast\n");
    assert_eq!(
        (e.line, e.key, e.kind),
        (2, "PKY1", TirErrorKind::NotANumber)
    );
    assert_eq!(e.to_string(), "line 2: PKY1: not a finite number");
    let e = err("[UNITS]\nLENGTH = 'furlong'\n");
    assert_eq!(
        (e.line, e.key, e.kind),
        (2, "LENGTH", TirErrorKind::UnknownUnit)
    );
    let e = err("[MODEL]\nFITTYP = 62\n");
    assert_eq!(e.kind, TirErrorKind::UnsupportedFittyp);
    let e = err("[MODEL]\nthis is not a key\n");
    assert_eq!((e.line, e.kind), (2, TirErrorKind::Syntax));
    // A required key absent; a coefficient out of the model's range, at its line.
    let tir = TirFile::read("[VERTICAL]\nFNOMIN = 4000\n").unwrap();
    let e = tir.mapped().unwrap_err();
    assert_eq!(
        (e.line, e.key, e.kind),
        (0, "UNLOADED_RADIUS", TirErrorKind::Missing)
    );
    let bad = SMALL.replace("PCY1 = 1.3", "PCY1 = 2.4");
    let tir = TirFile::read(&bad).unwrap();
    let e = tir
        .apply(&mut TyreClass::PassengerCar.params(0.3, 4000.0))
        .unwrap_err();
    assert_eq!((e.line, e.key), (21, "PCY1"));
    assert_eq!(
        e.kind,
        TirErrorKind::OutOfRange {
            field: TyreField::Shape(Direction::Lateral),
            value: 2.4
        }
    );
    assert_eq!(
        e.to_string(),
        "line 21: PCY1: gives tyre.lateral.shape = 2.4, which must be in (1, 2)"
    );
}
