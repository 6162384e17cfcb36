//! Chapter 03's integration tests, one binary: the terrain made in steps,
//! the `--walk` switch, the level of detail (no holes, no pops, the ground
//! walked on is the ground drawn), and the worked solutions to the
//! lessons' exercises.
//!
//! One test binary per crate: each links wgpu, naga, egui and winit, so
//! every extra file in `tests/` would be another link of all of them.

mod lod;
mod prepare;
mod solutions;
mod walk;

use std::sync::{Arc, OnceLock};

use common::headless::Offscreen;
use common::{Camera, Gpu, PassTimer, ShaderFile, Target, wgpu};
use terrain::heightfield::TerrainSettings;
use terrain::{Detail, KEEP_ALL, Sun, TerrainData, TerrainRenderer};

/// One device for these tests, so that the default terrain (4097² samples,
/// two seconds to make) is made once, whichever test asks first.
fn default_terrain() -> (&'static Gpu, Arc<TerrainData>) {
    static GPU: OnceLock<Gpu> = OnceLock::new();
    let gpu = GPU.get_or_init(|| Gpu::headless(terrain::gpu_needs()).expect("an adapter (lavapipe will do)"));
    (gpu, TerrainData::get(gpu, TerrainSettings::default()))
}

/// The default terrain drawn with `shader` into a new texture of `target`'s
/// size and format, cleared to `clear`: the patches chosen, and morphed,
/// for `eye`, the picture taken from `camera`.
fn draw_terrain(
    shader: &ShaderFile,
    target: Target,
    clear: wgpu::Color,
    (camera, eye): (&Camera, &Camera),
    detail: Detail,
) -> wgpu::Texture {
    let views = [(*camera, *eye)];
    pictures(shader, target, clear, &views, detail, |_, texture| texture.clone()).remove(0)
}

/// [`draw_terrain`] once for each of `views` (the camera the picture is
/// taken from, and the eye the patches are chosen and morphed for), each
/// picture read back by `read`. One renderer, pipeline and target for them
/// all: a pipeline is the dear part of a small picture.
fn pictures<T>(
    shader: &ShaderFile,
    target: Target,
    clear: wgpu::Color,
    views: &[(Camera, Camera)],
    detail: Detail,
    read: impl Fn(&Gpu, &wgpu::Texture) -> T,
) -> Vec<T> {
    let (gpu, data) = default_terrain();
    let renderer = TerrainRenderer::new(gpu, data);
    let layout = gpu.device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
        label: None,
        bind_group_layouts: &[Some(&renderer.bind_group_layout)],
        immediate_size: 0,
    });
    let pipeline = TerrainRenderer::pipeline(gpu, shader, &layout, (target.format, 1)).unwrap();
    let mut viewpoint = renderer.viewpoint(&gpu.device);
    let offscreen = Offscreen::new(&gpu.device, target);
    let depth = common::texture::depth_view(&gpu.device, target.width, target.height);
    views
        .iter()
        .map(|(camera, eye)| {
            renderer.aim_seen_from(gpu, &mut viewpoint, eye, detail, Sun::AFTERNOON, KEEP_ALL, camera);
            let mut encoder = gpu.device.create_command_encoder(&Default::default());
            {
                let mut pass = common::pipeline::scene_pass(
                    &mut encoder,
                    &PassTimer::off(),
                    "test",
                    &offscreen.view,
                    clear,
                    &depth,
                );
                pass.set_pipeline(&pipeline);
                renderer.draw(&mut pass, &viewpoint);
            }
            gpu.queue.submit([encoder.finish()]);
            read(gpu, &offscreen.texture)
        })
        .collect()
}

/// `terrain.wgsl` with `replace` in place of `find` (which must be there).
fn edited_terrain_shader(find: &str, replace: &str) -> ShaderFile {
    terrain_shader_with(&[(find, replace)])
}

/// `terrain.wgsl` with each edit's `replace` in place of its `find` (which
/// must be there), in turn.
fn terrain_shader_with(edits: &[(&str, &str)]) -> ShaderFile {
    let original = common::shader!("terrain/terrain.wgsl");
    let mut edited = original.embedded.to_string();
    for (find, replace) in edits {
        assert!(edited.contains(find), "terrain.wgsl changed: update the test's edit of {find:?}");
        edited = edited.replacen(find, replace, 1);
    }
    ShaderFile { embedded: Box::leak(edited.into_boxed_str()), ..original }
}
