//! Making sure the tests have what they need from the system: a Vulkan
//! driver (lavapipe will do), Mesa's OpenGL for the GL run, and, for the window test, a virtual X server,
//! a window manager and xdotool.

use std::path::Path;
use std::process::Command;

use anyhow::{bail, ensure};

const VULKAN: [&str; 2] = ["mesa-vulkan-drivers", "libvulkan1"];
/// Xvfb, the X libraries winit loads at run time, xdotool to drive the
/// windows, openbox, a small window manager (without one, X has no
/// minimising), and xwd (in x11-apps), which reads a window's pixels.
const WINDOW: [&str; 10] = [
    "xvfb",
    "xauth",
    "libx11-xcb1",
    "libxcursor1",
    "libxrandr2",
    "libxi6",
    "libxkbcommon-x11-0",
    "xdotool",
    "openbox",
    "x11-apps",
];

/// Mesa's OpenGL through EGL, with no display (llvmpipe's GL 4.5): the
/// snapshot test draws every chapter once on wgpu's GL backend too.
const OPENGL: [&str; 4] = ["libegl1", "libegl-mesa0", "libgles2", "libgl1-mesa-dri"];

/// On Linux, wgpu needs the Vulkan loader and at least one driver (ICD);
/// with no GPU, Mesa's lavapipe is that driver.
pub fn ensure_adapter() -> anyhow::Result<()> {
    if !cfg!(target_os = "linux") || std::env::var_os("WGPU_BACKEND").is_some() || vulkan_present() {
        return Ok(());
    }
    apt_install("no Vulkan driver found", &VULKAN)?;
    ensure!(vulkan_present(), "installed {} but still no Vulkan driver", VULKAN.join(" "));
    Ok(())
}

/// The program that lints as it compiles (`cargo xtask test` builds the
/// course through it): clippy's driver, which rustup's default profile
/// installs.
pub fn clippy_driver() -> anyhow::Result<&'static str> {
    let driver = "clippy-driver";
    let runs = Command::new(driver).arg("--version").output().is_ok_and(|out| out.status.success());
    ensure!(runs, "clippy is not installed ({driver} did not run): install it with `rustup component add clippy`");
    Ok(driver)
}

/// [`ensure_adapter`], and Mesa's OpenGL for the snapshot test's GL run
/// where the plan runs it.
pub fn ensure_adapters(plan: &crate::plan::Plan) -> anyhow::Result<()> {
    ensure_adapter()?;
    if plan.opengl == crate::plan::Decision::Install {
        apt_install("the snapshot test draws every chapter on OpenGL too", &OPENGL)?;
    }
    Ok(())
}

/// EGL and Mesa's drivers for it are installed.
pub fn opengl_present() -> bool {
    ["/usr/lib/x86_64-linux-gnu", "/usr/lib/aarch64-linux-gnu", "/usr/lib64", "/usr/lib"].iter().any(|dir| {
        let dir = Path::new(dir);
        dir.join("libEGL.so.1").exists()
            && dir.join("libEGL_mesa.so.0").exists()
            && dir.join("dri/swrast_dri.so").exists()
    })
}

/// Xvfb, openbox, xdotool and xwd (x11-apps) for the window test: true when they are
/// there (installed now if we may), false on systems where we cannot
/// provide them.
pub fn ensure_window_tools() -> anyhow::Result<bool> {
    if !cfg!(target_os = "linux") {
        return Ok(false);
    }
    if !has_window_tools() {
        apt_install("the window test needs Xvfb, openbox, xdotool and xwd", &WINDOW)?;
    }
    Ok(has_window_tools())
}

pub fn has_window_tools() -> bool {
    let command = "command -v Xvfb && command -v openbox && command -v xdotool && command -v xwd";
    Command::new("sh").args(["-c", command]).output().is_ok_and(|o| o.status.success())
}

/// Installs Debian packages when we may (root on Debian or Ubuntu);
/// otherwise fails with the one command to run.
pub fn apt_install(why: &str, packages: &[&str]) -> anyhow::Result<()> {
    let install = format!("apt-get install -y --no-install-recommends {}", packages.join(" "));
    if !Path::new("/etc/debian_version").exists() {
        bail!("{why}: install the equivalent of these Debian packages: {}", packages.join(" "));
    }
    let is_root = Command::new("id").arg("-u").output().is_ok_and(|o| o.stdout.starts_with(b"0\n"));
    if !is_root {
        bail!("{why}. Run: sudo {install}");
    }
    println!("{why}: installing\n$ {install}");
    let quiet = [("DEBIAN_FRONTEND", "noninteractive")];
    let update = Command::new("apt-get").args(["update", "-qq"]).envs(quiet).status()?;
    ensure!(update.success(), "apt-get update failed; run: {install}");
    let status = Command::new("apt-get")
        .args(["install", "-y", "-qq", "--no-install-recommends"])
        .args(packages)
        .envs(quiet)
        .status()?;
    ensure!(status.success(), "installing failed; run: {install}");
    Ok(())
}

/// The Vulkan loader and at least one driver manifest are installed.
fn vulkan_present() -> bool {
    let loader = ["/usr/lib/x86_64-linux-gnu", "/usr/lib/aarch64-linux-gnu", "/usr/lib64", "/usr/lib"]
        .iter()
        .any(|dir| Path::new(dir).join("libvulkan.so.1").exists());
    let driver = ["/usr/share/vulkan/icd.d", "/etc/vulkan/icd.d", "/usr/local/share/vulkan/icd.d"]
        .iter()
        .any(|dir| std::fs::read_dir(dir).is_ok_and(|mut entries| entries.next().is_some()));
    loader && driver
}
