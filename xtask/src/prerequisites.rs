//! Making sure the tests can find a GPU adapter, or lavapipe in its place.

use std::path::Path;
use std::process::Command;

use anyhow::{bail, ensure};

const PACKAGES: [&str; 2] = ["mesa-vulkan-drivers", "libvulkan1"];

/// On Linux, wgpu needs the Vulkan loader and at least one driver (ICD);
/// with no GPU, Mesa's lavapipe is that driver. Install it when we may
/// (root on Debian or Ubuntu), otherwise say the one command to run.
pub fn ensure_adapter() -> anyhow::Result<()> {
    if !cfg!(target_os = "linux") || std::env::var_os("WGPU_BACKEND").is_some() || vulkan_present() {
        return Ok(());
    }
    let install = format!("apt-get install -y --no-install-recommends {}", PACKAGES.join(" "));
    let is_root = Command::new("id").arg("-u").output().is_ok_and(|o| o.stdout.starts_with(b"0\n"));
    if !Path::new("/etc/debian_version").exists() {
        bail!("no Vulkan driver found. Install your GPU's Vulkan driver, or Mesa's software one (lavapipe, package mesa-vulkan-drivers or mesa-vulkan-swrast)");
    }
    if !is_root {
        bail!("no Vulkan driver found. Run: sudo {install}");
    }
    println!("no Vulkan driver found: installing Mesa's software rasteriser (lavapipe)\n$ {install}");
    let quiet = [("DEBIAN_FRONTEND", "noninteractive")];
    let update = Command::new("apt-get").args(["update", "-qq"]).envs(quiet).status()?;
    ensure!(update.success(), "apt-get update failed; run: {install}");
    let status = Command::new("apt-get")
        .args(["install", "-y", "-qq", "--no-install-recommends"])
        .args(PACKAGES)
        .envs(quiet)
        .status()?;
    ensure!(status.success() && vulkan_present(), "installing lavapipe failed; run: {install}");
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
