//! How many lights the loop visits per pixel, on average over the pixels
//! that show the city: read back from a depth buffer of one sample a pixel,
//! each pixel's cluster found from its depth, and that cluster's list
//! counted. The overlay's and the bench's measure of what culling saves.

use common::{Camera, Gpu, wgpu};

use crate::clusters::{self, ClusterLists};
use crate::post::HdrTarget;

// ANCHOR: lights_per_pixel
/// The average number of lights the loop visits per pixel that shows the
/// city (not the sky) in the last frame: from its depth buffer (of one
/// sample a pixel), each pixel's cluster, and that cluster's list.
pub fn lights_per_pixel(
    gpu: &Gpu,
    hdr: &HdrTarget,
    camera: &Camera,
    lists: &ClusterLists,
    light_count: usize,
    culling: bool,
) -> Option<f64> {
    // Copying a depth texture out is optional on downlevel backends (GL):
    // without it the figure is "n/a" rather than a wgpu validation panic.
    let copies = wgpu::DownlevelFlags::DEPTH_TEXTURE_AND_BUFFER_COPIES;
    if !gpu.downlevel().flags.contains(copies) {
        return None;
    }
    // One depth a pixel: `hdr` is of one sample (see `stats`).
    let depth = hdr.depth_texture()?;
    let depths = common::headless::read_floats(gpu, depth).ok()?;
    let (width, height) = (depth.width(), depth.height());
    let (near, far) = (camera.near, camera.far);
    let (mut visited, mut pixels) = (0u64, 0u64);
    for (i, depth) in depths.iter().map(|d| d[0]).enumerate() {
        if depth >= 1.0 {
            continue;
        }
        pixels += 1;
        if !culling {
            visited += light_count as u64;
            continue;
        }
        // Back from stored depth to distance (chapter 02), and to the pixel's cluster.
        let distance = near * far / (far - depth * (far - near));
        let (x, y) = ((i as u32 % width) * clusters::GRID[0] / width, (i as u32 / width) * clusters::GRID[1] / height);
        let z = clusters::slice(distance, near, far).clamp(0, clusters::GRID[2] as i32 - 1) as u32;
        let cluster = ((z * clusters::GRID[1] + y) * clusters::GRID[0] + x) as usize;
        visited += u64::from(lists.ranges.get(cluster).map_or(0, |r| r[1]));
    }
    (pixels > 0).then(|| visited as f64 / pixels as f64)
}
// ANCHOR_END: lights_per_pixel
