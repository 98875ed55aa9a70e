//! Helpers of the C API tests: staging the libraries once per test binary, compiling C and
//! C++ programs against them, running them with a `VEHICLE_WORLD`.

// Test helpers report failures by panicking; each test binary uses a part of them.
#![allow(dead_code, clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::io::Read;
use std::path::{Path, PathBuf};
use std::process::{Command, ExitStatus, Stdio};
use std::sync::OnceLock;

/// `capi/`.
pub fn capi_dir() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// `capi/tests/`.
pub fn tests_dir() -> PathBuf {
    capi_dir().join("tests")
}

/// Scratch space of this test binary.
pub fn scratch() -> PathBuf {
    let dir =
        Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("capi-{}", env!("CARGO_CRATE_NAME")));
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// The staged prefix (built once per test process with `stage.sh`).
pub fn prefix() -> &'static Path {
    static PREFIX: OnceLock<PathBuf> = OnceLock::new();
    PREFIX.get_or_init(|| {
        let prefix = scratch().join("prefix");
        let cargo = std::env::var("CARGO").unwrap_or_else(|_| "cargo".to_string());
        // The libraries are built with this test's own profile, so the build is shared.
        let profile = if cfg!(debug_assertions) {
            "--debug"
        } else {
            "--release"
        };
        let out = Command::new("bash")
            .arg(capi_dir().join("stage.sh"))
            .arg(profile)
            .arg(&prefix)
            .env("CARGO", cargo)
            .output()
            .expect("running capi/stage.sh");
        assert!(
            out.status.success(),
            "capi/stage.sh {profile} failed:\n{}{}",
            String::from_utf8_lossy(&out.stdout),
            String::from_utf8_lossy(&out.stderr)
        );
        prefix
    })
}

pub fn include_dir() -> PathBuf {
    prefix().join("include")
}

pub fn lib_dir() -> PathBuf {
    prefix().join("lib/controller")
}

/// The usual link flags (shared libraries, rpath to the staged tree).
pub fn shared_link_flags() -> Vec<String> {
    let lib = lib_dir().display().to_string();
    vec![
        format!("-L{lib}"),
        "-ldriver".into(),
        "-lcar".into(),
        format!("-Wl,-rpath,{lib}"),
        // The C maths library, for the programs that compute their expected values.
        "-lm".into(),
    ]
}

/// Compiles `source` with `compiler` (`cc` or `c++`) and `std`, warnings as errors, into
/// `scratch/<name>`; `link` are the library flags. Panics with the compiler output on failure.
pub fn compile(compiler: &str, std: &str, source: &Path, name: &str, link: &[String]) -> PathBuf {
    let exe = scratch().join(name);
    let out = Command::new(compiler)
        .arg(format!("-std={std}"))
        .args(["-Wall", "-Wextra", "-Werror", "-I"])
        .arg(include_dir())
        .arg(source)
        .arg("-o")
        .arg(&exe)
        .args(link)
        .output()
        .unwrap_or_else(|e| panic!("running {compiler}: {e}"));
    assert!(
        out.status.success(),
        "{compiler} {} failed:\n{}",
        source.display(),
        String::from_utf8_lossy(&out.stderr)
    );
    exe
}

/// Writes a C source into the scratch directory and returns its path.
pub fn write_source(name: &str, text: &str) -> PathBuf {
    let path = scratch().join(name);
    std::fs::write(&path, text).unwrap();
    path
}

/// A finished program run.
pub struct Run {
    /// Exit status.
    pub status: ExitStatus,
    /// Standard output.
    pub stdout: String,
    /// Standard error.
    pub stderr: String,
}

/// Runs `exe` with `VEHICLE_WORLD` set to `world` (or unset), stdout and stderr apart.
pub fn run(exe: &Path, world: Option<&str>) -> Run {
    run_command(Command::new(exe), world)
}

/// Runs `cmd` with `VEHICLE_WORLD` set to `world` (or unset), stdout and stderr apart.
pub fn run_command(mut cmd: Command, world: Option<&str>) -> Run {
    match world {
        Some(w) => cmd.env("VEHICLE_WORLD", w),
        None => cmd.env_remove("VEHICLE_WORLD"),
    };
    let out = cmd.output().unwrap();
    Run {
        status: out.status,
        stdout: String::from_utf8_lossy(&out.stdout).into_owned(),
        stderr: String::from_utf8_lossy(&out.stderr).into_owned(),
    }
}

/// Runs `exe` with stdout and stderr on one pipe (`2>&1`), so that the order of the
/// program's announcements and the libraries' messages is kept.
pub fn run_merged(exe: &Path, world: Option<&str>) -> (ExitStatus, String) {
    let (mut reader, writer) = std::io::pipe().unwrap();
    let mut cmd = Command::new(exe);
    cmd.stdin(Stdio::null())
        .stdout(writer.try_clone().unwrap())
        .stderr(writer);
    match world {
        Some(w) => cmd.env("VEHICLE_WORLD", w),
        None => cmd.env_remove("VEHICLE_WORLD"),
    };
    let mut child = cmd.spawn().unwrap();
    // The command's copies of the pipe's write end must be closed for read_to_end to finish.
    drop(cmd);
    let mut text = Vec::new();
    reader.read_to_end(&mut text).unwrap();
    let status = child.wait().unwrap();
    (status, String::from_utf8_lossy(&text).into_owned())
}

/// Asserts that a test program passed: exit status 0 and its `PASS` line.
pub fn assert_passed(program: &str, status: ExitStatus, stdout: &str) {
    let failures: Vec<&str> = stdout
        .lines()
        .filter(|l| l.contains(": FAIL") || l.contains(": FATAL"))
        .collect();
    assert!(
        status.success() && stdout.contains(&format!("{program}: PASS")),
        "{program} did not pass (status {status}):\n{}\n--- full output:\n{stdout}",
        failures.join("\n")
    );
}

/// Checks the merged output of a program that announces each misuse on stdout as
/// `<program>: call: <what> -> stderr: <text>` (README.md, "Expected stderr"): `<text>` must
/// follow at once (with or without a newline: Webots prints some texts without one). A `call:`
/// line without `-> stderr:` may be followed by the library's own lines. Any other line that
/// is not the program's own is an unexpected message.
pub fn check_announced_stderr(program: &str, merged: &str) -> Result<usize, String> {
    let own = format!("{program}: ");
    let mut rest = merged;
    let mut free = false;
    let mut matched = 0;
    while !rest.is_empty() {
        let (line, next) = rest.split_once('\n').unwrap_or((rest, ""));
        match line.strip_prefix(&own) {
            Some(body) => {
                free = false;
                if let Some(call) = body.strip_prefix("call: ") {
                    match call.split_once(" -> stderr: ") {
                        Some((what, text)) => {
                            // A message of several lines is announced with `\n` between them.
                            let text = text.replace("\\n", "\n");
                            let after = next.strip_prefix(text.as_str()).ok_or_else(|| {
                                format!(
                                    "after `{what}` expected stderr `{text}`, got `{}`",
                                    next.lines().next().unwrap_or("")
                                )
                            })?;
                            matched += 1;
                            rest = after.strip_prefix('\n').unwrap_or(after);
                            continue;
                        }
                        None => free = true,
                    }
                }
            }
            None if free => {}
            None => return Err(format!("unexpected stderr line `{line}`")),
        }
        rest = next;
    }
    Ok(matched)
}

/// Compiles and runs a program that announces its misuses, and checks both streams.
pub fn run_announcing(program: &str, world: Option<&str>, announced: usize) {
    let exe = compile(
        "cc",
        "c99",
        &tests_dir().join(format!("{program}.c")),
        program,
        &shared_link_flags(),
    );
    let (status, merged) = run_merged(&exe, world);
    assert_passed(program, status, &merged);
    match check_announced_stderr(program, &merged) {
        Ok(n) => assert_eq!(n, announced, "{program}: announced stderr texts matched"),
        Err(e) => panic!("{program}: {e}\n--- full output:\n{merged}"),
    }
}

/// Compiles and runs a program whose stderr must be exactly `expected_stderr`.
pub fn run_exact(program: &str, world: Option<&str>, link: &[String], expected_stderr: &[&str]) {
    let exe = compile(
        "cc",
        "c99",
        &tests_dir().join(format!("{program}.c")),
        program,
        link,
    );
    let r = run(&exe, world);
    assert_passed(program, r.status, &r.stdout);
    let lines: Vec<&str> = r.stderr.lines().collect();
    assert_eq!(lines, expected_stderr, "{program}: stderr");
}

/// The path of `worlds/sensors.toml`.
pub fn sensors_world() -> String {
    tests_dir()
        .join("worlds/sensors.toml")
        .display()
        .to_string()
}

/// The path of `worlds/<name>`.
pub fn world_path(name: &str) -> String {
    tests_dir().join("worlds").join(name).display().to_string()
}

/// The path of `worlds/rays.toml`.
pub fn rays_world() -> String {
    tests_dir().join("worlds/rays.toml").display().to_string()
}

/// The path of `worlds/differential_wheels.toml`.
pub fn differential_wheels_world() -> String {
    tests_dir()
        .join("worlds/differential_wheels.toml")
        .display()
        .to_string()
}
