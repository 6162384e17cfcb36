//! Physically based shading: a microfacet BRDF (Cook and Torrance 1982)
//! with GGX's distribution of facet normals (Walter et al. 2007), Smith's
//! height-correlated masking and shadowing (Heitz 2014), Schlick's Fresnel,
//! and the metallic-roughness description of materials (Burley 2012, Karis
//! 2013). `brdf.wgsl` evaluates the same formulas on the GPU; these copies
//! are what the tests integrate and the book plots. [`BrdfTable`] is the
//! split-sum table, computed by a compute shader, with which a surface
//! reflects the sky.

use std::f32::consts::PI;

use common::glam::Vec3;
use common::{Gpu, ShaderError, shader, wgpu};

// ANCHOR: parameters
/// Below this roughness a highlight would be a point (at α = 0, D is a
/// spike of no width and infinite height): `brdf.wgsl` clamps it too.
pub const MIN_ROUGHNESS: f32 = 0.045;

/// The Fresnel reflectance of non-metals seen head on: 4 % (glass and most
/// plastics have an index of refraction near 1.5, and
/// ((1.5 − 1) / (1.5 + 1))² = 0.04; water, at 1.33, reflects about 2 %,
/// which this chapter rounds to the same 4 %).
pub const DIELECTRIC_F0: f32 = 0.04;

/// How a surface reflects, in the metallic-roughness terms of every modern
/// engine and of glTF.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Physical {
    /// Linear RGB: the diffuse colour of a non-metal, the reflectance of a metal.
    pub base_colour: Vec3,
    /// 0 for a non-metal, 1 for a metal (in between only where the two mix).
    pub metallic: f32,
    /// 0 for a mirror, 1 for chalk.
    pub roughness: f32,
}

/// GGX's width α from the roughness a learner sets: α = roughness²,
/// which makes equal steps of roughness look like equal steps (Burley 2012).
pub fn ggx_alpha(roughness: f32) -> f32 {
    let r = roughness.clamp(MIN_ROUGHNESS, 1.0);
    r * r
}

/// Head-on reflectance: 4 % for non-metals, the base colour for metals.
pub fn fresnel_f0(base_colour: Vec3, metallic: f32) -> Vec3 {
    Vec3::splat(DIELECTRIC_F0).lerp(base_colour, metallic.clamp(0.0, 1.0))
}

/// The roughness for a Phong exponent `shininess`, for models that give no
/// roughness (an MTL file's `Ns`): Walter et al. (2007) match Phong's
/// exponent to Beckmann's width by s = 2/α² − 2, and GGX's α is close to
/// Beckmann's for the narrow lobes shininess describes; roughness = √α.
pub fn roughness_from_shininess(shininess: f32) -> f32 {
    (2.0 / (shininess.max(0.0) + 2.0)).powf(0.25)
}

/// The same rule the other way, s = 2/α² − 2: the Phong exponent for a
/// roughness, for surfaces made with one to be shaded by Phong's models too.
pub fn shininess_from_roughness(roughness: f32) -> f32 {
    let alpha = ggx_alpha(roughness);
    2.0 / (alpha * alpha) - 2.0
}
// ANCHOR_END: parameters

// ANCHOR: terms
/// D: the density of facet normals around h, per steradian, normalised so
/// that the facets' area projected on the surface is the surface's.
pub fn ggx_distribution(n_dot_h: f32, alpha: f32) -> f32 {
    let a2 = alpha * alpha;
    let d = n_dot_h * n_dot_h * (a2 - 1.0) + 1.0;
    a2 / (PI * d * d)
}

/// V = G / (4 n·l n·v): the share of facets both lit and seen (Smith's
/// height-correlated form for GGX, Heitz 2014), divided by the model's
/// 4 n·l n·v.
pub fn smith_visibility(n_dot_v: f32, n_dot_l: f32, alpha: f32) -> f32 {
    let a2 = alpha * alpha;
    let seen = n_dot_l * (n_dot_v * n_dot_v * (1.0 - a2) + a2).sqrt();
    let lit = n_dot_v * (n_dot_l * n_dot_l * (1.0 - a2) + a2).sqrt();
    0.5 / (seen + lit)
}

/// F: how much a facet reflects, by the angle between view and facet
/// (Schlick 1994): f0 head on, rising to 1 at grazing.
pub fn fresnel_schlick(f0: Vec3, v_dot_h: f32) -> Vec3 {
    let grazing = (1.0 - v_dot_h.clamp(0.0, 1.0)).powi(5);
    f0 + (Vec3::ONE - f0) * grazing
}
// ANCHOR_END: terms

/// The BRDF times π for light from `l` leaving towards `v` over normal `n`
/// (unit vectors): what `cook_torrance` in brdf.wgsl returns. The course's
/// lights are scaled so that Lambert's diffuse is albedo × light × n·l,
/// which is π × albedo/π.
pub fn cook_torrance(n: Vec3, v: Vec3, l: Vec3, surface: Physical) -> Vec3 {
    let h = (l + v).normalize();
    let n_dot_v = n.dot(v).max(1e-4);
    let n_dot_l = n.dot(l).max(0.0);
    let alpha = ggx_alpha(surface.roughness);
    let f = fresnel_schlick(fresnel_f0(surface.base_colour, surface.metallic), v.dot(h));
    let specular = f * (ggx_distribution(n.dot(h).max(0.0), alpha) * smith_visibility(n_dot_v, n_dot_l, alpha) * PI);
    // What Fresnel lets in at the light's angle and out at the eye's.
    let f0 = fresnel_f0(surface.base_colour, surface.metallic);
    let through = (Vec3::ONE - fresnel_schlick(f0, n_dot_l)) * (Vec3::ONE - fresnel_schlick(f0, n_dot_v));
    let diffuse = through * (1.0 - surface.metallic.clamp(0.0, 1.0)) * surface.base_colour;
    diffuse + specular
}

// ANCHOR: table
/// The split-sum table (Karis 2013): texel (x, y) holds A and B for a view
/// at n·v = (x + ½)/SIZE over a roughness (y + ½)/SIZE, so that a surface
/// under an even sky of light L reflects L × (f0 × A + B). Computed on the
/// GPU when made, by `brdf_table.wgsl`.
pub struct BrdfTable {
    pub texture: wgpu::Texture,
    pub view: wgpu::TextureView,
    pub sampler: wgpu::Sampler,
}

impl BrdfTable {
    pub const SIZE: u32 = 32;
    pub const FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba16Float;

    pub fn new(gpu: &Gpu) -> Result<Self, ShaderError> {
        let device = &gpu.device;
        let texture = device.create_texture(&wgpu::TextureDescriptor {
            label: Some("brdf table"),
            size: wgpu::Extent3d { width: Self::SIZE, height: Self::SIZE, depth_or_array_layers: 1 },
            mip_level_count: 1,
            sample_count: 1,
            dimension: wgpu::TextureDimension::D2,
            format: Self::FORMAT,
            usage: wgpu::TextureUsages::STORAGE_BINDING
                | wgpu::TextureUsages::TEXTURE_BINDING
                | wgpu::TextureUsages::COPY_SRC,
            view_formats: &[],
        });
        let view = texture.create_view(&Default::default());
        let module = shader!("lighting/brdf_table.wgsl", imports: ["lighting/brdf.wgsl"]).module(gpu)?;
        let pipeline = gpu
            .catch_validation(|| {
                device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
                    label: Some("brdf table"),
                    layout: None,
                    module: &module,
                    entry_point: Some("cs_brdf_table"),
                    compilation_options: Default::default(),
                    cache: None,
                })
            })
            .map_err(ShaderError)?;
        let group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("brdf table"),
            layout: &pipeline.get_bind_group_layout(0),
            entries: &[wgpu::BindGroupEntry { binding: 0, resource: wgpu::BindingResource::TextureView(&view) }],
        });
        let mut encoder = device.create_command_encoder(&Default::default());
        {
            let mut pass = encoder.begin_compute_pass(&Default::default());
            pass.set_pipeline(&pipeline);
            pass.set_bind_group(0, &group, &[]);
            let groups = Self::SIZE.div_ceil(8);
            pass.dispatch_workgroups(groups, groups, 1);
        }
        gpu.queue.submit([encoder.finish()]);
        // Clamped at the edges: roughness MIN_ROUGHNESS and n·v near 0 lie
        // outside the first texel's centre.
        let sampler = device.create_sampler(&wgpu::SamplerDescriptor {
            label: Some("brdf table"),
            mag_filter: wgpu::FilterMode::Linear,
            min_filter: wgpu::FilterMode::Linear,
            ..Default::default()
        });
        Ok(Self { view, sampler, texture })
    }
}
// ANCHOR_END: table
