//! The scene assembled for the GPU: the city's shapes with its still
//! pieces, the countryside's ground and trees as models of their own, the
//! billboard on its hill, and the material buffer (the city's materials,
//! then the material spheres').

use common::anyhow;
use common::chapter::storage_entry;
use common::glam::{Mat4, Vec2};
use common::wgpu;
use common::wgpu::util::DeviceExt as _;

use crate::billboard::Billboard;
use crate::city::{City, Material, Piece};
use crate::city_meshes::{CityMeshes, GpuMaterial, Model, materials};
use crate::countryside::{self, Countryside};
use crate::material_spheres;

/// The billboard on its hill across the river, facing the city.
pub fn billboard() -> Billboard {
    Billboard::new(countryside::BILLBOARD_HILL, Vec2::ZERO, countryside::height)
}

/// The material buffer: the city's materials, then the material spheres'
/// (whose instances index past the city's).
pub fn all_materials(night: f32, highlights: bool) -> Vec<GpuMaterial> {
    let mut all = materials(night, highlights);
    all.extend(material_spheres::materials(highlights));
    all
}

/// The material buffer and its bind group, group 1 of city.wgsl: written
/// every frame with [`all_materials`], since the lamps' glow follows the night.
pub(crate) struct MaterialBuffer {
    pub(crate) buffer: wgpu::Buffer,
    pub(crate) layout: wgpu::BindGroupLayout,
    pub(crate) group: wgpu::BindGroup,
}

impl MaterialBuffer {
    pub(crate) fn new(device: &wgpu::Device) -> Self {
        let buffer = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("materials"),
            contents: bytemuck::cast_slice(&all_materials(0.0, true)),
            usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_DST,
        });
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("city"),
            entries: &[storage_entry(0, wgpu::ShaderStages::VERTEX_FRAGMENT)],
        });
        let group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("city"),
            layout: &layout,
            entries: &[wgpu::BindGroupEntry { binding: 0, resource: buffer.as_entire_binding() }],
        });
        Self { buffer, layout, group }
    }
}

/// What [`scenery`] makes.
pub(crate) struct Scenery {
    pub(crate) meshes: CityMeshes,
    pub(crate) billboard: Billboard,
    pub(crate) countryside_pieces: Vec<Piece>,
}

// ANCHOR: scenery
/// The meshes on the GPU: the city's shapes with the city's still pieces,
/// and the countryside's ground and trees as models of their own; with
/// the billboard, and the pieces the countryside adds to the city's shapes
/// (its roads and bridge, the billboard's panel, posts and digits).
pub(crate) fn scenery(device: &wgpu::Device, city: &City) -> anyhow::Result<Scenery> {
    let countryside = Countryside::new();
    let billboard = billboard();
    let (trunk, foliage) = countryside::tree_meshes().map_err(anyhow::Error::msg)?;
    let models = [
        Model { name: "countryside", mesh: countryside.ground, placed: vec![(Mat4::IDENTITY, Material::Countryside)] },
        Model {
            name: "tree trunk",
            mesh: trunk,
            placed: countryside.trees.iter().map(|&t| (t, Material::Bark)).collect(),
        },
        Model {
            name: "tree foliage",
            mesh: foliage,
            placed: countryside.trees.iter().map(|&t| (t, Material::Leaves)).collect(),
        },
    ];
    let countryside_pieces = countryside.pieces.iter().chain(&billboard.pieces).copied().collect();
    Ok(Scenery { meshes: CityMeshes::new(device, &city.pieces, &models), billboard, countryside_pieces })
}
// ANCHOR_END: scenery
