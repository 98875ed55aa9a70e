//! `[vehicle.tyre] file = "….tir"`: the shipped Magic Formula 5.2 property files, read through
//! a world file into the car's tyre, give the pure-slip forces of MF 5.2's formulas written
//! out here by hand; the warnings list the keys ignored; errors name file, line and key.

// Helpers outside #[test] functions unwrap too: a failure is a test failure.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use sim::VehicleSpec;
use sim::world_file::{WorldFileErrorKind, parse_str, shipped};
use vehicle_model::{MagicFormula, TirFile, TyreModel};

/// A world file next to the shipped ones, whose car rolls on `tir`.
fn world(tir: &str) -> String {
    format!("[vehicle]\nmodel = \"BmwX5\"\n[vehicle.tyre]\nfile = \"{tir}\"\n")
}

/// The source name of a world in the shipped directory, so that its includes resolve there.
fn source() -> String {
    format!("{}/manoeuvre-test.toml", shipped::SHIPPED_DIR)
}

/// The text of a file of `sim/worlds`.
fn shipped_text(name: &str) -> String {
    std::fs::read_to_string(format!("{}/worlds/{name}", env!("CARGO_MANIFEST_DIR"))).unwrap()
}

/// The front tyre of the car of a world rolling on `tir`.
fn built(tir: &str) -> MagicFormula<f64> {
    let w = parse_str(&source(), &world(tir)).unwrap_or_else(|e| panic!("{e}"));
    let car = w.car().unwrap();
    let spec = VehicleSpec::from_car_with(&car.params, &car.tyre).unwrap();
    match spec.tyres.front {
        TyreModel::MagicFormula(m) => m,
        TyreModel::Webots(_) => panic!("expected the slip-based tyre"),
    }
}

/// MF 5.2's pure-slip forces (Pacejka, *Tire and Vehicle Dynamics*, 2nd ed., §4.3.2, the
/// PAC2002 equations) at zero camber, from the file's coefficients (0 when absent, the
/// scaling factors 1).
struct Mf52<'a>(TirFile<'a>);

impl Mf52<'_> {
    fn c(&self, key: &str) -> f64 {
        self.0.value(key).unwrap_or(0.0)
    }
    fn scale(&self, key: &str) -> f64 {
        self.0.value(key).unwrap_or(1.0)
    }
    /// `F'_z0` and `df_z` at load `fz` (N).
    fn load(&self, fz: f64) -> (f64, f64) {
        let fz0 = self.c("FNOMIN") * self.scale("LFZO");
        (fz0, (fz - fz0) / fz0)
    }
    /// `D·sin(C·atan(B·x − E·(B·x − atan(B·x))))`.
    fn curve(b: f64, c: f64, d: f64, e: f64, x: f64) -> f64 {
        let bx = b * x;
        d * (c * (bx - e * (bx - bx.atan())).atan()).sin()
    }
    /// `F_x0` (N) at slip ratio `kappa` under `fz` (N) (shifts zero).
    fn fx(&self, fz: f64, kappa: f64) -> f64 {
        let (_, dfz) = self.load(fz);
        let cx = self.c("PCX1") * self.scale("LCX");
        let dx = (self.c("PDX1") + self.c("PDX2") * dfz) * self.scale("LMUX") * fz;
        let ex = (self.c("PEX1") + self.c("PEX2") * dfz + self.c("PEX3") * dfz * dfz)
            * (1.0 - self.c("PEX4") * kappa.signum())
            * self.scale("LEX");
        let kx = fz
            * (self.c("PKX1") + self.c("PKX2") * dfz)
            * (self.c("PKX3") * dfz).exp()
            * self.scale("LKX");
        Self::curve(kx / (cx * dx), cx, dx, ex, kappa)
    }
    /// `F_y0` (N) at slip angle `alpha` (rad) under `fz` (N), in the file's sign convention
    /// (`α* = tan α`; shifts zero).
    fn fy(&self, fz: f64, alpha: f64) -> f64 {
        let (fz0, dfz) = self.load(fz);
        let a = alpha.tan();
        let cy = self.c("PCY1") * self.scale("LCY");
        let dy = (self.c("PDY1") + self.c("PDY2") * dfz) * self.scale("LMUY") * fz;
        let ey = (self.c("PEY1") + self.c("PEY2") * dfz)
            * (1.0 - self.c("PEY3") * a.signum())
            * self.scale("LEY");
        let ky = self.c("PKY1")
            * fz0
            * (2.0 * (fz / (self.c("PKY2") * fz0)).atan()).sin()
            * self.scale("LKY");
        Self::curve(ky / (cy * dy), cy, dy, ey, a)
    }
}

#[test]
fn shipped_files_give_mf52_forces_at_three_loads() {
    for name in ["passenger-car.tir", "van.tir"] {
        let text = shipped_text(name);
        let mf = Mf52(TirFile::read(&text).unwrap());
        // The file's shifts and load-dependent terms are zero: the regime where the mapping
        // is exact (vehicle_model::tyre::tir::mapping).
        for k in [
            "PKX2", "PKX3", "PEX2", "PEX3", "PEX4", "PEY2", "PEY3", "PHX1", "PVX1",
        ] {
            assert_eq!(mf.c(k), 0.0, "{name} {k}");
        }
        let tyre = built(name);
        let fz0 = mf.load(0.0).0;
        // The lateral force's sign: ISO files have PKY1 < 0 (a positive slip angle pushes to
        // the right); the model's positive tan α pushes left.
        let side = mf.c("PKY1").signum();
        for fz in [0.5 * fz0, fz0, 1.6 * fz0] {
            for kappa in [0.01, 0.05, 0.12, 0.3, -0.08, -1.0] {
                let [fx, _] = tyre.force([kappa, 0.0], fz, 1.0);
                let expected = mf.fx(fz, kappa);
                // 0.1 %: the brief's bound; the two evaluations differ by their arc tangent
                // and sine kernels (≤ 1e-15 of the peak) and the load law's roundings.
                assert!(
                    (fx - expected).abs() <= 1e-3 * expected.abs(),
                    "{name} Fz {fz} κ {kappa}: {fx} vs MF {expected}"
                );
            }
            for alpha_deg in [0.5_f64, 2.0, 5.0, 10.0, -4.0] {
                let alpha = alpha_deg.to_radians();
                let [_, fy] = tyre.force([0.0, alpha.tan()], fz, 1.0);
                let expected = side * mf.fy(fz, alpha);
                assert!(
                    (fy - expected).abs() <= 1e-3 * expected.abs(),
                    "{name} Fz {fz} α {alpha_deg}°: {fy} vs MF {expected}"
                );
            }
        }
    }
}

#[test]
fn the_van_file_is_read_in_its_units_and_scaled() {
    let tyre = built("van.tir");
    let p = tyre.params();
    // FNOMIN = 6.5 kN; R₀ = 350 mm; K_y/F_z0 = |PKY1|·sin(2·atan(1/PKY2))·LKY.
    assert!((p.nominal_load - 6500.0).abs() < 1e-9);
    let ky = 13.0 * (2.0 * (1.0_f64 / 2.2).atan()).sin() * 1.05;
    assert!((p.lateral.stiffness - ky).abs() < 1e-12);
    assert!((p.lateral.peak_friction - 0.85 * 0.95).abs() < 1e-12);
    // σ_κ = PTX1·R₀; rolling resistance QSY1.
    assert!((p.longitudinal.relaxation_length - 0.35).abs() < 1e-12);
    assert!((p.rolling_resistance - 0.008).abs() < 1e-15);
}

#[test]
fn ignored_keys_are_listed_by_name() {
    let w = parse_str(&source(), &world("passenger-car.tir")).unwrap();
    let ignored = w
        .warnings
        .iter()
        .find(|w| w.message.contains("ignored"))
        .expect("a warning listing the ignored keys");
    assert_eq!(ignored.key.as_deref(), Some("vehicle.tyre.file"));
    for key in [
        "RBX1",
        "PHY1",
        "QBZ1",
        "VERTICAL_STIFFNESS",
        "PDY3",
        "TYRESIDE",
    ] {
        assert!(ignored.message.contains(key), "{key}: {}", ignored.message);
    }
    for key in ["PKY1", "FNOMIN", "LFZO", "FILE_TYPE", "LENGTH"] {
        assert!(
            !ignored.message.contains(&format!(" {key},")),
            "{key}: {}",
            ignored.message
        );
    }
}

#[test]
fn errors_name_file_line_and_key() {
    let dir = std::env::temp_dir().join(format!("tir-import-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let text = shipped_text("passenger-car.tir");
    std::fs::write(dir.join("bad.tir"), text.replace("= 1.35", "= 2.35")).unwrap();
    let world_path = dir.join("w.toml");
    let e = parse_str(&world_path.display().to_string(), &world("bad.tir")).unwrap_err();
    assert_eq!(e.key.as_deref(), Some("vehicle.tyre.file"));
    let WorldFileErrorKind::InvalidValue(m) = &e.kind else {
        panic!("{e}")
    };
    let line = text.lines().position(|l| l.contains("= 1.35")).unwrap() + 1;
    assert!(
        m.contains("bad.tir") && m.contains(&format!("line {line}: PCY1")),
        "{m}"
    );
    let e = parse_str(&world_path.display().to_string(), &world("none.tir")).unwrap_err();
    assert!(e.to_string().contains("none.tir"), "{e}");
    std::fs::remove_dir_all(&dir).unwrap();
}
