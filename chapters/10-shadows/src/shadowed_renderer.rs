//! The main pass of a shadowed scene: chapter 09's textured models, lit by
//! chapter 08's lights with the sun's share scaled by what a rendered
//! [`ShadowMap`] says. In: the [`SceneLights`], a [`DrawList`], the shadow
//! map; out: the draws in an HDR pass. Chapter 11 draws its boat with it.

use common::chapter::{mesh_pipeline, sampler_entry};
use common::{Gpu, Reloadable, ShaderError, shader, wgpu};
use lighting::{HDR_FORMAT, SceneLights};
use textures::DrawList;
use textures::materials::{Materials, SamplerMode};
use textures::mesh::{ModelInstance, TexturedVertex};

use crate::shadow_map::ShadowMap;

// ANCHOR: renderer
/// The second pass: the level's models, textured (chapter 09) and lit
/// (chapter 08) with the sun's light scaled by what the shadow map says.
/// Group 0 the [`SceneLights`], group 1 a material, group 2 the surface
/// sampler, group 3 the [`ShadowMap`]. Inputs: a draw list of chapter
/// 09's models and a shadow map already rendered for this frame.
pub struct ShadowedRenderer {
    /// The picture's pipeline and the tests' sunlit-only one, made again
    /// when scene.wgsl or a module it imports is saved (hot reload).
    pipelines: Reloadable<(wgpu::RenderPipeline, wgpu::RenderPipeline)>,
    sampler_group: wgpu::BindGroup,
}
// ANCHOR_END: renderer

impl ShadowedRenderer {
    pub fn new(
        gpu: &Gpu,
        lights: &SceneLights,
        materials: &Materials,
        shadow: &ShadowMap,
    ) -> Result<Self, ShaderError> {
        let device = &gpu.device;
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("surface sampler"),
            entries: &[sampler_entry(0)],
        });
        // Trilinear, as chapter 09's default (never anisotropic, so the
        // adapter's support does not matter).
        let sampler = device.create_sampler(&SamplerMode::Mipmaps.descriptor(false));
        let sampler_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("surface sampler"),
            layout: &layout,
            entries: &[wgpu::BindGroupEntry { binding: 0, resource: wgpu::BindingResource::Sampler(&sampler) }],
        });
        let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("shadowed"),
            bind_group_layouts: &[Some(&lights.layout), Some(&materials.layout), Some(&layout), Some(&shadow.layout)],
            immediate_size: 0,
        });
        let pipelines = Reloadable::new(gpu, move |gpu| Self::pipelines(gpu, &pipeline_layout))?;
        Ok(Self { pipelines, sampler_group })
    }

    fn pipelines(
        gpu: &Gpu,
        layout: &wgpu::PipelineLayout,
    ) -> Result<(wgpu::RenderPipeline, wgpu::RenderPipeline), ShaderError> {
        let module = shader!(
            "shadows/scene.wgsl",
            imports: ["lighting/lights.wgsl", "textures/surface.wgsl", "shadows/shadow.wgsl"]
        )
        .module(gpu)?;
        let buffers = [Some(TexturedVertex::LAYOUT), Some(ModelInstance::LAYOUT)];
        let pipeline =
            |fragment| mesh_pipeline(&gpu.device, layout, &module, ("vs_main", fragment), &buffers, HDR_FORMAT.into());
        gpu.catch_validation(|| (pipeline("fs_main"), pipeline("fs_sunlit"))).map_err(ShaderError)
    }

    // ANCHOR: draw
    /// Draws `list` into `pass`, whose group 0 must be the scene's lights.
    /// `sunlit_only` draws what the tests count instead of the picture.
    pub fn draw(&self, pass: &mut wgpu::RenderPass<'_>, shadow: &ShadowMap, list: &DrawList, sunlit_only: bool) {
        let (lit, sunlit) = self.pipelines.get();
        pass.set_pipeline(if sunlit_only { &sunlit } else { &lit });
        pass.set_bind_group(2, &self.sampler_group, &[]);
        pass.set_bind_group(3, &shadow.group, &[]);
        list.draw(pass, false);
    }
    // ANCHOR_END: draw
}
