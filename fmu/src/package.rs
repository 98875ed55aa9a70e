//! The `.fmu` archive: `modelDescription.xml`, the shared library under
//! `binaries/<platform>/`, and the world (with the OpenDRIVE file it names) under
//! `resources/`.

use std::fs::File;
use std::io::Write as _;
use std::path::{Component, Path, PathBuf};

use sim::world_file::{self, WorldDescription};
use toml::de::{DeTable, DeValue};
use vehicle_model::Model;
use zip::write::SimpleFileOptions;

use crate::instance::{Version, WORLD_FILE};
use crate::model_description::{self, Description, MODEL_IDENTIFIER};
use crate::variables::{Causality, VARIABLES, parameter_of};

/// The name of the platform this library was built for (`binaries/<platform>/`) in FMI
/// `version`: FMI 2.0's `linux64` …, FMI 3.0's platform tuple `x86_64-linux` ….
///
/// # Errors
/// A platform the version has no name for.
pub fn platform(version: Version) -> Result<String, String> {
    if version == Version::Fmi3 {
        let arch = match std::env::consts::ARCH {
            "x86_64" => "x86_64",
            "aarch64" => "aarch64",
            "x86" => "x86",
            other => {
                return Err(format!(
                    "FMI 3.0 names no platform tuple for the {other} architecture"
                ));
            }
        };
        let os = match std::env::consts::OS {
            "linux" => "linux",
            "windows" => "windows",
            "macos" => "darwin",
            other => return Err(format!("FMI 3.0 names no platform tuple for {other}")),
        };
        return Ok(format!("{arch}-{os}"));
    }
    platform_fmi2().map(str::to_string)
}

/// FMI 2.0's platform directory name.
fn platform_fmi2() -> Result<&'static str, String> {
    if cfg!(all(target_os = "linux", target_pointer_width = "64")) {
        Ok("linux64")
    } else if cfg!(all(target_os = "windows", target_pointer_width = "64")) {
        Ok("win64")
    } else if cfg!(all(target_os = "macos", target_pointer_width = "64")) {
        Ok("darwin64")
    } else {
        Err("FMI 2.0 names no platform directory for this operating system".to_string())
    }
}

/// The shared library's file name on this platform.
pub fn library_file_name() -> String {
    format!(
        "{}{MODEL_IDENTIFIER}{}",
        std::env::consts::DLL_PREFIX,
        std::env::consts::DLL_SUFFIX
    )
}

/// A world to package: its name, text, and the directory its relative files are in.
#[derive(Debug, Clone, PartialEq)]
pub struct World {
    /// The model name in the FMU.
    pub name: String,
    /// The world file's text.
    pub text: String,
    /// The directory of the world file (`None` for a built-in world).
    pub directory: Option<PathBuf>,
}

impl World {
    /// The world `spec` names as `vehicle-sim --world` takes it: a world file, a vehicle model
    /// (its default world), or empty for the default world.
    ///
    /// # Errors
    /// A file that cannot be read, or a name that is neither a file nor a model.
    pub fn named(spec: &str) -> Result<World, String> {
        if spec.trim().is_empty() {
            return Ok(World {
                name: "BmwX5".to_string(),
                text: world_file::DEFAULT_WORLD.to_string(),
                directory: None,
            });
        }
        let path = Path::new(spec);
        if path.is_file() {
            let text = std::fs::read_to_string(path)
                .map_err(|e| format!("cannot read the world {spec}: {e}"))?;
            let name = path
                .file_stem()
                .map_or_else(|| spec.to_string(), |s| s.to_string_lossy().into_owned());
            let directory = path.parent().map(Path::to_path_buf);
            return Ok(World {
                name,
                text,
                directory,
            });
        }
        match Model::from_name(spec) {
            Some(model) => Ok(World {
                name: model.webots_name().to_string(),
                text: world_file::model_world_text(model),
                directory: None,
            }),
            None => Err(format!(
                "{spec} is neither a world file nor a vehicle model (e.g. BmwX5)"
            )),
        }
    }

    /// The OpenDRIVE file the world names with its top-level `road` key, relative to it.
    ///
    /// # Errors
    /// A `road` that is absolute or leads out of the world's directory: the FMU carries the
    /// file beside the world, at the same relative path.
    fn road_file(&self) -> Result<Option<PathBuf>, String> {
        let Ok(doc) = DeTable::parse(&self.text) else {
            return Ok(None);
        };
        let Some(DeValue::String(road)) = doc.get_ref().get("road").map(|v| v.get_ref()) else {
            return Ok(None);
        };
        let relative = PathBuf::from(road.as_ref());
        if relative
            .components()
            .any(|c| !matches!(c, Component::Normal(_) | Component::CurDir))
        {
            return Err(format!(
                "road = \"{road}\": the FMU carries the road file beside the world, so it \
                 must be a relative path inside the world's directory"
            ));
        }
        Ok(Some(relative))
    }
}

/// The model description of `world`, read as the FMU will read it.
///
/// # Errors
/// What is wrong with the world (as its reader says), or a world the FMU cannot drive (a
/// robot, or several cars of which not exactly one has no programme).
pub fn describe(world: &World) -> Result<(WorldDescription, Description), String> {
    let file = world
        .directory
        .as_ref()
        .map_or_else(|| PathBuf::from(WORLD_FILE), |d| d.join(WORLD_FILE));
    let description = world_file::parse_str(&file.display().to_string(), &world.text)
        .map_err(|e| e.to_string())?;
    // The driven car and its device outputs come from the built world, as the instance
    // derives them.
    let built = crate::world::build(description.clone())?;
    let devices = crate::instance::device_outputs(&built)?;
    let driven = built.driven;
    let parameters = VARIABLES
        .iter()
        .filter(|v| v.causality == Causality::Parameter)
        .filter_map(|v| parameter_of(&description, driven, v.reference).map(|x| (v.reference, x)))
        .collect();
    let d = Description {
        model_name: world.name.clone(),
        step: description.config.dt(),
        stop_time: description.duration,
        parameters,
        devices,
    };
    Ok((description, d))
}

/// Writes the FMU of `world` for FMI `version` to `out`, with the shared library `library`
/// (built by `cargo build -p vehicle-fmu`; the same library serves both versions).
///
/// # Errors
/// What is wrong with the world, the library or writing the archive, as a sentence.
pub fn write_fmu(
    world: &World,
    library: &Path,
    out: &Path,
    version: Version,
) -> Result<(), String> {
    let (_, description) = describe(world)?;
    let binary = std::fs::read(library).map_err(|e| {
        format!(
            "cannot read the FMU's shared library {}: {e} (build it with cargo build \
             -p vehicle-fmu --lib in the profile of this vehicle-fmu, e.g. with --release)",
            library.display()
        )
    })?;
    let road = match world.road_file()? {
        Some(relative) => {
            let directory = world.directory.as_deref().unwrap_or(Path::new("."));
            let bytes = std::fs::read(directory.join(&relative)).map_err(|e| {
                format!(
                    "cannot read the world's road file {}: {e}",
                    relative.display()
                )
            })?;
            Some((relative, bytes))
        }
        None => None,
    };
    let fail = |e: &dyn std::fmt::Display| format!("cannot write {}: {e}", out.display());
    let file = File::create(out).map_err(|e| fail(&e))?;
    let mut zip = zip::ZipWriter::new(file);
    let stored = SimpleFileOptions::default().compression_method(zip::CompressionMethod::Stored);
    let mut entries: Vec<(String, Vec<u8>, u32)> = vec![
        (
            "modelDescription.xml".to_string(),
            model_description::write(&description, version).into_bytes(),
            0o644,
        ),
        (
            format!(
                "binaries/{}/{MODEL_IDENTIFIER}{}",
                platform(version)?,
                std::env::consts::DLL_SUFFIX
            ),
            binary,
            0o755,
        ),
        (
            format!("resources/{WORLD_FILE}"),
            world.text.clone().into_bytes(),
            0o644,
        ),
    ];
    if let Some((relative, bytes)) = road {
        let name = relative
            .components()
            .filter_map(|c| match c {
                Component::Normal(part) => Some(part.to_string_lossy().into_owned()),
                _ => None,
            })
            .collect::<Vec<_>>()
            .join("/");
        entries.push((format!("resources/{name}"), bytes, 0o644));
    }
    for (name, bytes, mode) in entries {
        zip.start_file(name, stored.unix_permissions(mode))
            .map_err(|e| fail(&e))?;
        zip.write_all(&bytes).map_err(|e| fail(&e))?;
    }
    zip.finish().map_err(|e| fail(&e))?;
    Ok(())
}
