//! Roughness and metalness, one at a time: two rows of spheres south of the
//! city, rougher from left to right, red paint (a non-metal) above and gold
//! (a metal) below. The first gold sphere is a mirror: the prefiltered
//! sky's sharpest level. Materials of their own, after the city's in the
//! material buffer, so that the city's own stay as they are.

use common::glam::{Mat4, Vec3};

use crate::city::Material;
use crate::city_meshes::{GpuInstance, GpuMaterial};
use crate::pbr::shininess_from_roughness;

// ANCHOR: spheres
/// The rows' roughness, left to right.
pub const ROUGHNESS: [f32; 6] = [0.0, 0.2, 0.4, 0.6, 0.8, 1.0];
/// Linear RGB: a red paint's albedo, and a gold's reflectance head on.
pub const PAINT: Vec3 = Vec3::new(0.6, 0.05, 0.04);
pub const GOLD: Vec3 = Vec3::new(1.0, 0.71, 0.29);
/// The middle of the two rows, and the spheres' radius and spacing, metres.
pub const CENTRE: Vec3 = Vec3::new(0.0, 7.0, 215.0);
pub const RADIUS: f32 = 2.0;
pub const SPACING: f32 = 5.0;

/// The spheres' materials, with or without Phong's highlights: paint at
/// each roughness, then gold.
pub fn materials(highlights: bool) -> Vec<GpuMaterial> {
    let sphere = |base: Vec3, metallic: f32, roughness: f32| {
        GpuMaterial {
            albedo: base.into(),
            specular: if highlights { 0.5 } else { 0.0 },
            emissive: [0.0; 3],
            // For Phong's highlights.
            shininess: shininess_from_roughness(roughness),
            albedo_high: base.into(),
            high_from: 0.0,
            high_to: 1.0,
            roughness,
            metallic,
            _padding: 0.0,
        }
    };
    let paint = ROUGHNESS.map(|r| sphere(PAINT, 0.0, r));
    let gold = ROUGHNESS.map(|r| sphere(GOLD, 1.0, r));
    paint.into_iter().chain(gold).collect()
}

/// The spheres as instances of the city's sphere, each with its material's
/// index (after the city's `Material::ALL`).
pub fn instances() -> Vec<GpuInstance> {
    let first = Material::ALL.len() as u32;
    let left = CENTRE.x - SPACING * (ROUGHNESS.len() - 1) as f32 / 2.0;
    let mut instances = Vec::new();
    for (row, height) in [CENTRE.y + SPACING / 2.0, CENTRE.y - SPACING / 2.0].into_iter().enumerate() {
        for column in 0..ROUGHNESS.len() {
            let at = Vec3::new(left + SPACING * column as f32, height, CENTRE.z);
            // The city's sphere is one across: scale it to the diameter.
            let model = Mat4::from_scale_rotation_translation(Vec3::splat(2.0 * RADIUS), Default::default(), at);
            instances.push(GpuInstance::with_material_index(model, first + (row * ROUGHNESS.len() + column) as u32));
        }
    }
    instances
}
// ANCHOR_END: spheres
