//! `modelDescription.xml` for FMI 2.0 or 3.0 co-simulation, written from the variable table
//! ([`crate::variables::VARIABLES`]) and the world's parameter values.
//!
//! Why by hand rather than with an XML crate: the document is a fixed shape of a few element
//! kinds with attribute values that are numbers or our own names; the one thing a writer must
//! get right, escaping, is [`escape`], tested below.

use core::fmt::Write as _;

use crate::devices::DeviceOutput;
use crate::instance::Version;
use crate::variables::{Causality, Kind, UNITS, VARIABLES, Variable};

/// The `modelIdentifier`: the shared library's file name without its extension.
pub const MODEL_IDENTIFIER: &str = "vehicle_fmu";

/// What the model description says about one packaged world.
#[derive(Debug, Clone, PartialEq)]
pub struct Description {
    /// `modelName`: the world's name.
    pub model_name: String,
    /// The world's `basicTimeStep` (s): the default communication step.
    pub step: f64,
    /// The world's `duration` (s), the default stop time, if it has one.
    pub stop_time: Option<f64>,
    /// The start value of each parameter, in [`VARIABLES`] order (those of the world).
    pub parameters: Vec<(u32, f64)>,
    /// The outputs of the car's devices, listed after [`VARIABLES`].
    pub devices: Vec<DeviceOutput>,
}

/// The GUID of this build of the FMU: a hash of the crate version and the variable table,
/// so an FMU whose binary serves other variables than its description lists is refused at
/// `fmi2Instantiate`.
pub fn guid() -> String {
    // FNV-1a (64-bit) twice, with two offsets, for 128 bits: a fingerprint, not a secret.
    let mut text = String::from(env!("CARGO_PKG_VERSION"));
    for v in &VARIABLES {
        let _ = write!(
            text,
            "|{}:{}:{:?}:{:?}",
            v.name, v.reference, v.kind, v.causality
        );
    }
    let fnv = |offset: u64| {
        text.bytes().fold(offset, |h, b| {
            (h ^ u64::from(b)).wrapping_mul(0x0000_0100_0000_01b3)
        })
    };
    let (a, b) = (fnv(0xcbf2_9ce4_8422_2325), fnv(0x6c62_272e_07bb_0142));
    format!(
        "{{{:08x}-{:04x}-{:04x}-{:04x}-{:012x}}}",
        a >> 32,
        (a >> 16) & 0xffff,
        a & 0xffff,
        b >> 48,
        b & 0xffff_ffff_ffff
    )
}

/// `text` with the five XML special characters escaped, for an attribute value.
pub fn escape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&apos;"),
            c => out.push(c),
        }
    }
    out
}

/// The variability FMI 2.0 requires of `v`: parameters are fixed, reals continuous,
/// integers discrete.
fn variability(v: &Variable) -> &'static str {
    match (v.causality, v.kind) {
        (Causality::Parameter, _) => "fixed",
        (Causality::Independent, _) => "continuous",
        (_, Kind::Real) => "continuous",
        (_, Kind::Integer) => "discrete",
    }
}

/// The document for `d` in FMI `version`.
pub fn write(d: &Description, version: Version) -> String {
    let fmi3 = version == Version::Fmi3;
    let mut x = String::new();
    let _ = writeln!(x, r#"<?xml version="1.0" encoding="UTF-8"?>"#);
    let _ = writeln!(
        x,
        r#"<fmiModelDescription fmiVersion="{}" modelName="{}" {}="{}" description="A car of a vehicle-sim world (the Webots automobile stack in Rust)" generationTool="vehicle-fmu {}" variableNamingConvention="flat"{}>"#,
        if fmi3 { "3.0" } else { "2.0" },
        escape(&d.model_name),
        if fmi3 { "instantiationToken" } else { "guid" },
        guid(),
        env!("CARGO_PKG_VERSION"),
        if fmi3 {
            ""
        } else {
            r#" numberOfEventIndicators="0""#
        }
    );
    if fmi3 {
        let _ = writeln!(
            x,
            r#"  <CoSimulation modelIdentifier="{MODEL_IDENTIFIER}" canHandleVariableCommunicationStepSize="true" canGetAndSetFMUState="true" canSerializeFMUState="true" fixedInternalStepSize="{:?}" hasEventMode="false" providesIntermediateUpdate="false"/>"#,
            d.step
        );
    } else {
        let _ = writeln!(
            x,
            r#"  <CoSimulation modelIdentifier="{MODEL_IDENTIFIER}" canHandleVariableCommunicationStepSize="true" canNotUseMemoryManagementFunctions="true" canGetAndSetFMUstate="true" canSerializeFMUstate="true"/>"#
        );
    }
    x.push_str("  <UnitDefinitions>\n");
    for (name, [kg, m, s, rad], factor) in UNITS {
        let mut base = String::new();
        for (symbol, e) in [("kg", kg), ("m", m), ("s", s), ("rad", rad)] {
            if e != 0 {
                let _ = write!(base, r#" {symbol}="{e}""#);
            }
        }
        if factor != 1.0 {
            let _ = write!(base, r#" factor="{factor:?}""#);
        }
        let _ = writeln!(
            x,
            r#"    <Unit name="{}"><BaseUnit{base}/></Unit>"#,
            escape(name)
        );
    }
    x.push_str("  </UnitDefinitions>\n");
    x.push_str("  <LogCategories>\n");
    for category in crate::instance::LOG_CATEGORIES {
        let _ = writeln!(x, r#"    <Category name="{category}"/>"#);
    }
    x.push_str("  </LogCategories>\n");
    let _ = write!(x, r#"  <DefaultExperiment startTime="0""#);
    if let Some(stop) = d.stop_time {
        let _ = write!(x, r#" stopTime="{stop:?}""#);
    }
    let _ = writeln!(x, r#" stepSize="{:?}"/>"#, d.step);
    x.push_str("  <ModelVariables>\n");
    // A parameter the world has no value for (a magic-formula coefficient of a car on Webots'
    // contact) is left out: FMI requires a parameter's start value.
    let listed: Vec<&Variable> = VARIABLES
        .iter()
        .filter(|v| {
            v.causality != Causality::Parameter
                || d.parameters.iter().any(|(r, _)| *r == v.reference)
        })
        .collect();
    for v in &listed {
        let mut attributes = format!(
            r#"name="{}" valueReference="{}" causality="{}" variability="{}" description="{}""#,
            escape(v.name),
            v.reference,
            match v.causality {
                Causality::Parameter => "parameter",
                Causality::Input => "input",
                Causality::Output => "output",
                Causality::Independent => "independent",
            },
            variability(v),
            escape(v.description)
        );
        let mut typed = String::new();
        if let Some(unit) = v.unit {
            let _ = write!(typed, r#" unit="{}""#, escape(unit));
        }
        let start = match v.causality {
            Causality::Input => Some(crate::variables::input_start(v.reference)),
            Causality::Parameter => d
                .parameters
                .iter()
                .find(|(r, _)| *r == v.reference)
                .map(|(_, value)| *value),
            Causality::Output | Causality::Independent => None,
        };
        match (start, v.kind) {
            (Some(s), Kind::Real) => {
                let _ = write!(typed, r#" start="{s:?}""#);
            }
            (Some(s), Kind::Integer) => {
                let _ = write!(typed, r#" start="{}""#, s as i32);
            }
            (None, _) => {}
        }
        if fmi3 {
            // FMI 3.0: one element per type, its attributes on it.
            attributes.push_str(&typed);
            let element = match v.kind {
                Kind::Real => "Float64",
                Kind::Integer => "Int32",
            };
            let _ = writeln!(x, "    <{element} {attributes}/>");
        } else {
            let element = match v.kind {
                Kind::Real => "Real",
                Kind::Integer => "Integer",
            };
            let _ = writeln!(
                x,
                "    <ScalarVariable {attributes}><{element}{typed}/></ScalarVariable>"
            );
        }
    }
    for o in &d.devices {
        let unit = o
            .unit
            .map(|u| format!(r#" unit="{}""#, escape(u)))
            .unwrap_or_default();
        let attributes = format!(
            r#"name="{}" valueReference="{}" causality="output" variability="continuous" description="{}""#,
            escape(&o.name),
            o.reference,
            escape(&o.description)
        );
        if fmi3 {
            let _ = writeln!(x, "    <Float64 {attributes}{unit}/>");
        } else {
            let _ = writeln!(
                x,
                "    <ScalarVariable {attributes}><Real{unit}/></ScalarVariable>"
            );
        }
    }
    x.push_str("  </ModelVariables>\n");
    // Every output as (1-based index in ModelVariables, value reference).
    let outputs = || {
        listed
            .iter()
            .enumerate()
            .filter(|(_, v)| v.causality == Causality::Output)
            .map(|(i, v)| (i + 1, v.reference))
            .chain(
                d.devices
                    .iter()
                    .enumerate()
                    .map(|(k, o)| (listed.len() + k + 1, o.reference)),
            )
    };
    if fmi3 {
        // FMI 3.0 names the unknowns by value reference.
        x.push_str("  <ModelStructure>\n");
        for (_, reference) in outputs() {
            let _ = writeln!(x, r#"    <Output valueReference="{reference}"/>"#);
        }
        for (_, reference) in outputs() {
            let _ = writeln!(x, r#"    <InitialUnknown valueReference="{reference}"/>"#);
        }
        x.push_str("  </ModelStructure>\n</fmiModelDescription>\n");
    } else {
        // FMI 2.0 by 1-based index in ModelVariables.
        x.push_str("  <ModelStructure>\n    <Outputs>\n");
        for (index, _) in outputs() {
            let _ = writeln!(x, r#"      <Unknown index="{index}"/>"#);
        }
        x.push_str("    </Outputs>\n    <InitialUnknowns>\n");
        for (index, _) in outputs() {
            let _ = writeln!(x, r#"      <Unknown index="{index}"/>"#);
        }
        x.push_str("    </InitialUnknowns>\n  </ModelStructure>\n</fmiModelDescription>\n");
    }
    x
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn escaping_covers_the_five_special_characters() {
        assert_eq!(escape(r#"a<b>&"c'"#), "a&lt;b&gt;&amp;&quot;c&apos;");
    }

    #[test]
    fn the_guid_is_stable_and_shaped_as_a_guid() {
        let g = guid();
        assert_eq!(g, guid());
        assert_eq!(g.len(), 38);
        assert!(g.starts_with('{') && g.ends_with('}'));
    }

    #[test]
    fn every_variable_and_output_index_is_written() {
        let d = Description {
            model_name: "w & <x>".to_string(),
            step: 0.01,
            stop_time: Some(10.0),
            parameters: vec![(1000, 1500.0)],
            devices: Vec::new(),
        };
        let outputs = VARIABLES
            .iter()
            .filter(|v| v.causality == Causality::Output)
            .count();
        // Only the parameter the world has a value for is listed.
        let listed = VARIABLES
            .iter()
            .filter(|v| v.causality != Causality::Parameter || v.reference == 1000)
            .count();
        let xml = write(&d, Version::Fmi2);
        assert!(xml.contains(r#"fmiVersion="2.0""#));
        assert!(xml.contains(r#"modelName="w &amp; &lt;x&gt;""#));
        assert_eq!(xml.matches("<ScalarVariable ").count(), listed);
        assert!(xml.contains(r#"<Real unit="kg" start="1500.0"/>"#));
        assert!(xml.contains(r#"stopTime="10.0" stepSize="0.01""#));
        assert_eq!(xml.matches("<Unknown ").count(), 2 * outputs);
        let xml = write(&d, Version::Fmi3);
        assert!(xml.contains(r#"fmiVersion="3.0""#));
        assert!(xml.contains(&format!(r#"instantiationToken="{}""#, guid())));
        assert_eq!(
            xml.matches("<Float64 ").count() + xml.matches("<Int32 ").count(),
            listed
        );
        assert!(xml.contains(r#"causality="independent""#));
        assert!(xml.contains(r#"unit="kg" start="1500.0"/>"#));
        assert_eq!(xml.matches("<Output ").count(), outputs);
        assert_eq!(xml.matches("<InitialUnknown ").count(), outputs);
    }
}
