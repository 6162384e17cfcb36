//! The main pass of a shadowed scene: chapter 09's textured models, lit by
//! chapter 08's lights with the sun's share scaled by what a rendered
//! [`ShadowMap`] says, and, if it is given one, a point light shadowed by
//! its [`PointShadow`]. In: the [`SceneLights`], a [`DrawList`], the
//! shadow map (and the point light's cube); out: the draws in an HDR pass.
//! Chapter 11 draws its boat with it, without a point light.

use common::chapter::{mesh_pipeline, sampler_entry};
use common::{Drawn, Gpu, Reloadable, ShaderError, shader, wgpu};
use lighting::{HDR_FORMAT, SceneLights};
use textures::DrawList;
use textures::materials::{Materials, SamplerMode};
use textures::mesh::{ModelInstance, TexturedVertex};

use crate::point_shadow::PointShadow;
use crate::shadow_map::ShadowMap;

// ANCHOR: renderer
/// The second pass: the level's models, textured (chapter 09) and lit
/// (chapter 08) with the sun's light scaled by what the shadow map says.
/// Group 0 the [`SceneLights`], group 1 a material, group 2 the surface
/// sampler (and the [`PointShadow`]'s bindings, with a point light),
/// group 3 the [`ShadowMap`]. Inputs: a draw list of chapter 09's models
/// and the shadow maps, already rendered for this frame.
pub struct ShadowedRenderer {
    /// The picture's pipeline and the tests' sunlit-only one, made again
    /// when scene.wgsl or a module it imports is saved (hot reload).
    pipelines: Reloadable<(wgpu::RenderPipeline, wgpu::RenderPipeline)>,
    sampler_group: wgpu::BindGroup,
}
// ANCHOR_END: renderer

impl ShadowedRenderer {
    /// The scene lit by the sun, shadowed, and by `lights`' other lights,
    /// unshadowed; for an HDR pass of `multisample`'s samples a pixel
    /// ([`lighting::HdrTarget::multisample`]).
    pub fn new(
        gpu: &Gpu,
        lights: &SceneLights,
        materials: &Materials,
        shadow: &ShadowMap,
        multisample: wgpu::MultisampleState,
    ) -> Result<Self, ShaderError> {
        Self::build(gpu, lights, materials, shadow, None, multisample)
    }

    /// [`ShadowedRenderer::new`], with one more point light shadowed by
    /// `point` (which says where the light is and what colour). The cube's
    /// bindings go into group 2 once: it never replaces its texture.
    pub fn with_point_light(
        gpu: &Gpu,
        lights: &SceneLights,
        materials: &Materials,
        shadow: &ShadowMap,
        point: &PointShadow,
        multisample: wgpu::MultisampleState,
    ) -> Result<Self, ShaderError> {
        Self::build(gpu, lights, materials, shadow, Some(point), multisample)
    }

    fn build(
        gpu: &Gpu,
        lights: &SceneLights,
        materials: &Materials,
        shadow: &ShadowMap,
        point: Option<&PointShadow>,
        multisample: wgpu::MultisampleState,
    ) -> Result<Self, ShaderError> {
        let device = &gpu.device;
        let mut layout_entries = vec![sampler_entry(0)];
        if point.is_some() {
            layout_entries.extend(PointShadow::layout_entries());
        }
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("surface sampler"),
            entries: &layout_entries,
        });
        // Trilinear, as chapter 09's default (never anisotropic, so the
        // adapter's support does not matter).
        let sampler = device.create_sampler(&SamplerMode::Mipmaps.descriptor(false));
        let mut entries = vec![wgpu::BindGroupEntry { binding: 0, resource: wgpu::BindingResource::Sampler(&sampler) }];
        if let Some(point) = point {
            entries.extend(point.group_entries());
        }
        let sampler_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("surface sampler"),
            layout: &layout,
            entries: &entries,
        });
        let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("shadowed"),
            bind_group_layouts: &[Some(&lights.layout), Some(&materials.layout), Some(&layout), Some(&shadow.layout)],
            immediate_size: 0,
        });
        // Without a point light, entry points that never touch the cube's
        // bindings, which this layout does not have.
        let entries = if point.is_some() { ("fs_lantern", "fs_lantern_sunlit") } else { ("fs_main", "fs_sunlit") };
        let pipelines = Reloadable::new(gpu, move |gpu| Self::pipelines(gpu, &pipeline_layout, entries, multisample))?;
        Ok(Self { pipelines, sampler_group })
    }

    fn pipelines(
        gpu: &Gpu,
        layout: &wgpu::PipelineLayout,
        (picture, sunlit): (&str, &str),
        multisample: wgpu::MultisampleState,
    ) -> Result<(wgpu::RenderPipeline, wgpu::RenderPipeline), ShaderError> {
        let module = shader!(
            "shadows/scene.wgsl",
            imports: ["lighting/brdf.wgsl", "lighting/sky_light.wgsl", "lighting/lights.wgsl", "textures/surface.wgsl", "shadows/shadow.wgsl", "shadows/point_shadow.wgsl"]
        )
        .module(gpu)?;
        let buffers = [Some(TexturedVertex::LAYOUT), Some(ModelInstance::LAYOUT)];
        let pipeline = |fragment| {
            mesh_pipeline(&gpu.device, layout, &module, ("vs_main", fragment), &buffers, HDR_FORMAT.into(), multisample)
        };
        gpu.catch_validation(|| (pipeline(picture), pipeline(sunlit))).map_err(ShaderError)
    }

    // ANCHOR: draw
    /// Draws `list` into `pass`, whose group 0 must be the scene's lights.
    /// `sunlit_only` draws what the tests count instead of the picture:
    /// red the sun that arrives, green whether the surface faces the sun,
    /// and blue, with a point light, how much of its light arrives.
    /// Returns what it drew.
    pub fn draw(
        &self,
        pass: &mut wgpu::RenderPass<'_>,
        shadow: &ShadowMap,
        list: &DrawList,
        sunlit_only: bool,
    ) -> Drawn {
        let (lit, sunlit) = self.pipelines.get();
        pass.set_pipeline(if sunlit_only { &sunlit } else { &lit });
        pass.set_bind_group(2, &self.sampler_group, &[]);
        pass.set_bind_group(3, &shadow.group, &[]);
        list.draw(pass, false)
    }
    // ANCHOR_END: draw
}
