//! The city's pieces on the GPU: one instanced draw per shape, each piece
//! an instance with its model matrix, normal matrix and material; meshes
//! smooth for Gouraud and Phong shading and faceted for flat shading; the
//! materials as `city.wgsl` reads them, and its three pipelines.

use common::chapter::mesh_pipeline;
use common::glam::{Mat3, Mat4, Vec3};
use common::{Drawn, Gpu, Mesh, MeshData, ShaderError, ShaderFile, Vertex, shader, wgpu};

use crate::city::{GRASS, Material, Piece, Shape};
use crate::countryside;
use crate::post::HDR_FORMAT;

// ANCHOR: instance
/// One piece as the GPU reads it (`Instance` in city.wgsl): its model
/// matrix, the inverse transpose of its upper 3 × 3 for normals (one
/// column per 16 bytes), and its material. 128 bytes.
#[repr(C)]
#[derive(Clone, Copy, Debug, bytemuck::Pod, bytemuck::Zeroable)]
pub struct GpuInstance {
    pub model: [[f32; 4]; 4],
    pub normal: [[f32; 4]; 3],
    pub material: u32,
    pub _padding: [u32; 3],
}

impl GpuInstance {
    pub fn of(piece: &Piece) -> Self {
        Self::new(piece.model, piece.material)
    }

    pub fn new(model: Mat4, material: Material) -> Self {
        Self::with_material_index(model, material as u32)
    }

    /// With the index of its material in the material buffer, which may
    /// be one after the city's own (`material_spheres`).
    pub fn with_material_index(model: Mat4, material: u32) -> Self {
        let normal = Mat3::from_mat4(model).inverse().transpose();
        Self {
            model: model.to_cols_array_2d(),
            normal: [
                normal.x_axis.extend(0.0).into(),
                normal.y_axis.extend(0.0).into(),
                normal.z_axis.extend(0.0).into(),
            ],
            material,
            _padding: [0; 3],
        }
    }

    const ATTRIBUTES: [wgpu::VertexAttribute; 8] = [
        wgpu::VertexAttribute { format: wgpu::VertexFormat::Float32x4, offset: 0, shader_location: 3 },
        wgpu::VertexAttribute { format: wgpu::VertexFormat::Float32x4, offset: 16, shader_location: 4 },
        wgpu::VertexAttribute { format: wgpu::VertexFormat::Float32x4, offset: 32, shader_location: 5 },
        wgpu::VertexAttribute { format: wgpu::VertexFormat::Float32x4, offset: 48, shader_location: 6 },
        wgpu::VertexAttribute { format: wgpu::VertexFormat::Float32x3, offset: 64, shader_location: 7 },
        wgpu::VertexAttribute { format: wgpu::VertexFormat::Float32x3, offset: 80, shader_location: 8 },
        wgpu::VertexAttribute { format: wgpu::VertexFormat::Float32x3, offset: 96, shader_location: 9 },
        wgpu::VertexAttribute { format: wgpu::VertexFormat::Uint32, offset: 112, shader_location: 10 },
    ];

    pub const LAYOUT: wgpu::VertexBufferLayout<'static> = wgpu::VertexBufferLayout {
        array_stride: std::mem::size_of::<GpuInstance>() as wgpu::BufferAddress,
        step_mode: wgpu::VertexStepMode::Instance,
        attributes: &Self::ATTRIBUTES,
    };
}
// ANCHOR_END: instance

// ANCHOR: faceted
/// The same triangles, each with three vertices of its own carrying the
/// face's normal: what flat shading needs, since a shared vertex can only
/// have one normal.
pub fn faceted(mesh: &MeshData) -> MeshData {
    let mut flat = MeshData::default();
    for triangle in mesh.indices.chunks_exact(3) {
        let [a, b, c] = [0, 1, 2].map(|k| mesh.vertices[triangle[k] as usize]);
        let [pa, pb, pc] = [a, b, c].map(|v| Vec3::from(v.position));
        let normal = (pb - pa).cross(pc - pa).normalize_or_zero();
        for v in [a, b, c] {
            flat.indices.push(flat.vertices.len() as u32);
            flat.vertices.push(Vertex { normal: normal.into(), ..v });
        }
    }
    flat
}
// ANCHOR_END: faceted

// ANCHOR: material
/// `Material` in city.wgsl: 64 bytes. The albedo turns into `albedo_high`
/// between the heights `high_from` and `high_to` (a smoothstep of the
/// point's y): the countryside's sand and grass. Every other material has
/// the same colour both ways.
#[repr(C)]
#[derive(Clone, Copy, Debug, bytemuck::Pod, bytemuck::Zeroable)]
pub struct GpuMaterial {
    pub albedo: [f32; 3],
    pub specular: f32,
    pub emissive: [f32; 3],
    pub shininess: f32,
    pub albedo_high: [f32; 3],
    pub high_from: f32,
    pub high_to: f32,
    /// Cook-Torrance's (`pbr::Physical`): 0 a mirror to 1 chalk; 0 a non-metal, 1 a metal.
    pub roughness: f32,
    pub metallic: f32,
    pub _padding: f32,
}
// ANCHOR_END: material

/// The city's materials as they look at this time of day (lamps and
/// windows glow only as night falls), with or without highlights.
pub(crate) fn materials(night: f32, highlights: bool) -> Vec<GpuMaterial> {
    Material::ALL
        .iter()
        .map(|m| {
            let s = m.surface();
            let physical = m.physical();
            let glow = if s.at_night { night } else { 1.0 };
            let (albedo_high, high_from, high_to) = match m {
                Material::Countryside => (GRASS, countryside::SAND_UP_TO, countryside::GRASS_FROM),
                _ => (s.albedo, 0.0, 1.0),
            };
            GpuMaterial {
                albedo: s.albedo.into(),
                specular: if highlights { s.specular } else { 0.0 },
                emissive: (s.emissive * glow).into(),
                shininess: s.shininess,
                albedo_high: albedo_high.into(),
                high_from,
                high_to,
                roughness: physical.roughness,
                metallic: physical.metallic,
                _padding: 0.0,
            }
        })
        .collect()
}

fn city_shader() -> ShaderFile {
    shader!("lighting/city.wgsl", imports: ["lighting/brdf.wgsl", "lighting/sky_light.wgsl", "lighting/lights.wgsl"])
}

/// The city's three shadings, and Phong's at one sample a pixel for the
/// bench's count of lights per pixel (which needs one depth a pixel).
/// Clone (handles): a `Reloadable` hands out copies.
#[derive(Clone)]
pub(crate) struct Pipelines {
    pub(crate) flat: wgpu::RenderPipeline,
    pub(crate) gouraud: wgpu::RenderPipeline,
    pub(crate) phong: wgpu::RenderPipeline,
    pub(crate) one_sample: wgpu::RenderPipeline,
}

/// The three shadings, for an HDR pass of `multisample`'s samples a pixel
/// ([`crate::HdrTarget::multisample`]), and Phong's at one.
pub(crate) fn build_pipelines(
    gpu: &Gpu,
    layout: &wgpu::PipelineLayout,
    multisample: wgpu::MultisampleState,
) -> Result<Pipelines, ShaderError> {
    let module = city_shader().module(gpu)?;
    let buffers = [Some(Vertex::LAYOUT), Some(GpuInstance::LAYOUT)];
    let mesh = |entries, multisample| {
        mesh_pipeline(&gpu.device, layout, &module, entries, &buffers, HDR_FORMAT.into(), multisample)
    };
    gpu.catch_validation(|| Pipelines {
        flat: mesh(("vs_flat", "fs_flat"), multisample),
        gouraud: mesh(("vs_gouraud", "fs_gouraud"), multisample),
        phong: mesh(("vs_phong", "fs_phong"), multisample),
        one_sample: mesh(("vs_phong", "fs_phong"), Default::default()),
    })
    .map_err(ShaderError)
}

/// A mesh of its own, not one of the city's shapes, and its copies, none
/// of which move: the countryside's ground, a tree's trunk, its foliage.
pub struct Model {
    pub name: &'static str,
    pub mesh: MeshData,
    pub placed: Vec<(Mat4, Material)>,
}

/// The city's meshes, smooth and faceted, and the instance buffer.
pub(crate) struct CityMeshes {
    /// The shapes' meshes in `Shape::ALL`'s order, then the models'.
    smooth: Vec<Mesh>,
    faceted: Vec<Mesh>,
    instances: wgpu::Buffer,
    /// Per mesh, which instances it draws this frame.
    ranges: Vec<std::ops::Range<u32>>,
    /// The copies that never move, per mesh, ready to copy.
    still: Vec<Vec<GpuInstance>>,
}

impl CityMeshes {
    /// The shapes, with the `pieces` that never move, and the `models`.
    pub(crate) fn new(device: &wgpu::Device, pieces: &[Piece], models: &[Model]) -> Self {
        let meshes: Vec<(String, MeshData)> = Shape::ALL
            .iter()
            .map(|s| (format!("{s:?}"), s.mesh()))
            .chain(models.iter().map(|m| (m.name.to_string(), m.mesh.clone())))
            .collect();
        let smooth = meshes.iter().map(|(name, mesh)| mesh.upload(device, name)).collect();
        let faceted =
            meshes.iter().map(|(name, mesh)| faceted(mesh).upload(device, &format!("{name} faceted"))).collect();
        let still: Vec<Vec<GpuInstance>> = Shape::ALL
            .iter()
            .map(|shape| pieces.iter().filter(|p| p.shape == *shape).map(GpuInstance::of).collect())
            .chain(
                models.iter().map(|m| m.placed.iter().map(|&(at, material)| GpuInstance::new(at, material)).collect()),
            )
            .collect();
        let count: usize = still.iter().map(Vec::len).sum();
        let instances = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("city instances"),
            size: (count as u64 + 1024) * std::mem::size_of::<GpuInstance>() as u64,
            usage: wgpu::BufferUsages::VERTEX | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        Self { smooth, faceted, instances, ranges: Vec::new(), still }
    }

    /// Writes this frame's instances: the still pieces and this frame's
    /// others (the moving ones, the countryside's, and `spheres` drawn
    /// with the city's sphere), grouped by shape, then the models', so
    /// that each mesh is one instanced draw.
    pub(crate) fn write(&mut self, gpu: &Gpu, moving: &[Piece], spheres: &[GpuInstance]) {
        let mut all = Vec::new();
        self.ranges.clear();
        for (i, still) in self.still.iter().enumerate() {
            let start = all.len() as u32;
            all.extend_from_slice(still);
            if let Some(shape) = Shape::ALL.get(i) {
                all.extend(moving.iter().filter(|p| p.shape == *shape).map(GpuInstance::of));
                if *shape == Shape::Sphere {
                    all.extend_from_slice(spheres);
                }
            }
            self.ranges.push(start..all.len() as u32);
        }
        let bytes = (all.len() * std::mem::size_of::<GpuInstance>()) as u64;
        if bytes > self.instances.size() {
            self.instances = gpu.device.create_buffer(&wgpu::BufferDescriptor {
                label: Some("city instances"),
                size: bytes.next_power_of_two(),
                usage: wgpu::BufferUsages::VERTEX | wgpu::BufferUsages::COPY_DST,
                mapped_at_creation: false,
            });
        }
        gpu.queue.write_buffer(&self.instances, 0, bytemuck::cast_slice(&all));
    }

    /// One instanced draw per mesh: the shapes', then (`models`) the
    /// models'. Returns what the draws drew.
    pub(crate) fn draw(&self, pass: &mut wgpu::RenderPass<'_>, faceted: bool, models: bool) -> Drawn {
        pass.set_vertex_buffer(1, self.instances.slice(..));
        let meshes = if faceted { &self.faceted } else { &self.smooth };
        let count = if models { meshes.len() } else { Shape::ALL.len() };
        let mut drawn = Drawn::NOTHING;
        for (mesh, range) in meshes.iter().zip(&self.ranges).take(count) {
            if !range.is_empty() {
                drawn += mesh.draw(pass, range.clone());
            }
        }
        drawn
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_countryside_material_blends_the_ground_colours_over_the_same_heights() {
        let gpu = materials(0.0, true)[Material::Countryside as usize];
        assert_eq!((Vec3::from(gpu.albedo), Vec3::from(gpu.albedo_high)), (crate::city::SAND, GRASS));
        assert_eq!((gpu.high_from, gpu.high_to), (countryside::SAND_UP_TO, countryside::GRASS_FROM));
        // At each end of the blend it is countryside.rs's ground colour.
        assert_eq!(countryside::ground_colour(gpu.high_from), Vec3::from(gpu.albedo));
        assert_eq!(countryside::ground_colour(gpu.high_to), Vec3::from(gpu.albedo_high));
    }
}
