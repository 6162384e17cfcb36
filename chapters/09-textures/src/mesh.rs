//! Textured models: the vertex with a tangent, a model as one vertex
//! buffer and one index buffer with a range of indices per material, and
//! models placed as instances.

use std::ops::Range;
use std::path::PathBuf;

use common::glam::{Mat3, Mat4, Vec2, Vec3, Vec4};
use common::wgpu::util::DeviceExt as _;
use common::{MeshData, wgpu};

use crate::tangents::{face_tangents, vertex_tangents};

// ANCHOR: vertex
/// A point on a textured surface: chapter 02's vertex plus a tangent
/// (xyz, at right angles to the normal) and its handedness (w = ±1), and
/// a colour of its own (linear RGB, white unless an OBJ gives one), which
/// multiplies the material's where the material says so. 60 bytes.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct TexturedVertex {
    pub position: [f32; 3],
    pub normal: [f32; 3],
    pub uv: [f32; 2],
    pub tangent: [f32; 4],
    pub colour: [f32; 3],
}
// ANCHOR_END: vertex

impl TexturedVertex {
    // The colour comes after the instance's locations (4 to 11).
    const ATTRIBUTES: [wgpu::VertexAttribute; 5] = wgpu::vertex_attr_array![
        0 => Float32x3, 1 => Float32x3, 2 => Float32x2, 3 => Float32x4, 12 => Float32x3
    ];

    pub const LAYOUT: wgpu::VertexBufferLayout<'static> = wgpu::VertexBufferLayout {
        array_stride: std::mem::size_of::<TexturedVertex>() as wgpu::BufferAddress,
        step_mode: wgpu::VertexStepMode::Vertex,
        attributes: &Self::ATTRIBUTES,
    };
}

/// A material as a file describes it (MTL) or the city assigns it.
#[derive(Clone, Debug, PartialEq)]
pub struct MaterialDesc {
    pub name: String,
    /// Kd: multiplies the albedo map (or is the colour, without one). Linear RGB.
    pub diffuse: Vec3,
    /// Ks, one number (the mean of its three).
    pub specular: f32,
    /// Ns.
    pub shininess: f32,
    /// Pr and Pm, where an MTL written for physically based shading gives
    /// them: roughness and metalness, 0 to 1 (`obj.rs` clamps and warns).
    pub roughness: Option<f32>,
    pub metallic: Option<f32>,
    /// Ke: light of its own. With an albedo map, its alpha says where.
    pub emissive: Vec3,
    /// Whether the emissive light comes on only at night (lamps, windows).
    pub at_night: bool,
    /// Whether the vertices' colours multiply `diffuse` (OBJ's `v x y z r g b`).
    pub vertex_colours: bool,
    /// map_Kd, decoded as sRGB.
    pub albedo_map: Option<PathBuf>,
    /// map_Bump, bump or norm: a tangent-space normal map, read as data.
    pub normal_map: Option<PathBuf>,
    /// map_Pr and map_Pm: roughness and metalness maps, read as data, whose
    /// red channel (a grey image's value) multiplies Pr and Pm.
    pub roughness_map: Option<PathBuf>,
    pub metallic_map: Option<PathBuf>,
    /// Where else to look for a map by its file name alone, in order, when
    /// its path does not lead to it (a file made on another machine).
    pub texture_folders: Vec<PathBuf>,
}

impl MaterialDesc {
    /// Cook-Torrance's roughness and metalness, which the maps multiply:
    /// Pr and Pm where given; else 1 where a map gives the value alone;
    /// else a non-metal with the roughness Walter et al.'s rule gives for
    /// Ns (`lighting::pbr::roughness_from_shininess`).
    pub fn physical(&self) -> (f32, f32) {
        let by_map = |map: &Option<PathBuf>| map.as_ref().map(|_| 1.0);
        let roughness = self
            .roughness
            .or(by_map(&self.roughness_map))
            .unwrap_or_else(|| lighting::pbr::roughness_from_shininess(self.shininess));
        (roughness, self.metallic.or(by_map(&self.metallic_map)).unwrap_or(0.0))
    }

    /// Whether the MTL gave Pr, Pm or their maps: a model made for
    /// physically based shading.
    pub fn is_physical(&self) -> bool {
        self.roughness.is_some()
            || self.metallic.is_some()
            || self.roughness_map.is_some()
            || self.metallic_map.is_some()
    }

    /// A plain material: a colour and a highlight, no maps.
    pub fn plain(name: &str, diffuse: Vec3, specular: f32, shininess: f32) -> Self {
        Self {
            name: name.into(),
            diffuse,
            specular,
            shininess,
            roughness: None,
            metallic: None,
            emissive: Vec3::ZERO,
            at_night: false,
            vertex_colours: false,
            albedo_map: None,
            normal_map: None,
            roughness_map: None,
            metallic_map: None,
            texture_folders: Vec::new(),
        }
    }
}

/// A range of a model's indices drawn with one material.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Part {
    pub indices: Range<u32>,
    pub material: usize,
}

// ANCHOR: model
/// A model on the CPU: every mesh of it in one vertex list and one index
/// list, grouped into parts by material, so that drawing it takes one
/// vertex buffer and one draw per part.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct ModelData {
    pub vertices: Vec<TexturedVertex>,
    pub indices: Vec<u32>,
    pub parts: Vec<Part>,
    pub materials: Vec<MaterialDesc>,
}
// ANCHOR_END: model

impl ModelData {
    /// One of `common`'s primitives with tangents, all in `material`.
    pub fn from_mesh(mesh: &MeshData, material: MaterialDesc) -> Self {
        let mut model = Self { materials: vec![material], ..Default::default() };
        model.append(mesh, 0, Mat4::IDENTITY, |uv, _| uv);
        model
    }

    /// Adds `mesh` placed by `transform` to the model's last part if that
    /// part uses `material`, or as a new part; `uv_of(uv, vertex index)`
    /// may rescale the texture coordinates. Tangents are computed after
    /// placing, from the final positions and texture coordinates.
    pub fn append(&mut self, mesh: &MeshData, material: usize, transform: Mat4, uv_of: impl Fn(Vec2, usize) -> Vec2) {
        self.append_coloured(mesh, None, material, transform, uv_of);
    }

    /// [`append`](Self::append), with a colour for each vertex of `mesh`
    /// (white without).
    pub fn append_coloured(
        &mut self,
        mesh: &MeshData,
        colours: Option<&[Vec3]>,
        material: usize,
        transform: Mat4,
        uv_of: impl Fn(Vec2, usize) -> Vec2,
    ) {
        let normal_matrix = Mat3::from_mat4(transform).inverse().transpose();
        let positions: Vec<Vec3> =
            mesh.vertices.iter().map(|v| transform.transform_point3(v.position.into())).collect();
        let normals: Vec<Vec3> =
            mesh.vertices.iter().map(|v| (normal_matrix * Vec3::from(v.normal)).normalize_or_zero()).collect();
        let uvs: Vec<Vec2> = mesh.vertices.iter().enumerate().map(|(i, v)| uv_of(v.uv.into(), i)).collect();
        let tangents = vertex_tangents(&positions, &normals, &uvs, &mesh.indices);
        let base = self.vertices.len() as u32;
        self.vertices.extend((0..positions.len()).map(|i| TexturedVertex {
            position: positions[i].into(),
            normal: normals[i].into(),
            uv: uvs[i].into(),
            tangent: tangents[i].into(),
            colour: colours.map_or([1.0; 3], |c| c[i].into()),
        }));
        let start = self.indices.len() as u32;
        self.indices.extend(mesh.indices.iter().map(|i| i + base));
        let end = self.indices.len() as u32;
        match self.parts.last_mut() {
            Some(part) if part.material == material && part.indices.end == start => part.indices.end = end,
            _ => self.parts.push(Part { indices: start..end, material }),
        }
    }

    /// Sorts the parts by material and merges neighbours with the same one,
    /// so that each material is drawn once.
    pub fn group_by_material(&mut self) {
        let mut parts = std::mem::take(&mut self.parts);
        parts.sort_by_key(|p| p.material);
        let mut indices = Vec::with_capacity(self.indices.len());
        for part in parts {
            let start = indices.len() as u32;
            indices.extend_from_slice(&self.indices[part.indices.start as usize..part.indices.end as usize]);
            let end = indices.len() as u32;
            match self.parts.last_mut() {
                Some(last) if last.material == part.material => last.indices.end = end,
                _ => self.parts.push(Part { indices: start..end, material: part.material }),
            }
        }
        self.indices = indices;
    }

    pub fn triangle_count(&self) -> usize {
        self.indices.len() / 3
    }

    /// The smallest box around every vertex, as (min, max).
    pub fn bounds(&self) -> (Vec3, Vec3) {
        self.vertices.iter().fold((Vec3::splat(f32::MAX), Vec3::splat(f32::MIN)), |(lo, hi), v| {
            (lo.min(v.position.into()), hi.max(v.position.into()))
        })
    }

    /// The same model with the seed's tangents: every triangle gets three
    /// vertices of its own carrying the triangle's tangent (normals stay
    /// smooth). For comparing the two ways in the `face-tangents` view.
    pub fn with_face_tangents(&self) -> Self {
        let positions: Vec<Vec3> = self.vertices.iter().map(|v| v.position.into()).collect();
        let normals: Vec<Vec3> = self.vertices.iter().map(|v| v.normal.into()).collect();
        let uvs: Vec<Vec2> = self.vertices.iter().map(|v| v.uv.into()).collect();
        let faces = face_tangents(&positions, &normals, &uvs, &self.indices);
        let mut model = Self { materials: self.materials.clone(), parts: self.parts.clone(), ..Default::default() };
        for (triangle, tangent) in self.indices.chunks_exact(3).zip(faces) {
            for &i in triangle {
                model.indices.push(model.vertices.len() as u32);
                model.vertices.push(TexturedVertex { tangent: tangent.into(), ..self.vertices[i as usize] });
            }
        }
        model
    }
}

// ANCHOR: instance
/// One placed copy of a model, as the vertex shader reads it: the model
/// matrix, the inverse transpose of its 3 × 3 for normals, and how much
/// of the materials' emissive light shows (1, or the night's strength for
/// windows). 128 bytes.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct ModelInstance {
    pub model: [[f32; 4]; 4],
    pub normal: [[f32; 4]; 3],
    pub glow: f32,
    pub _padding: [f32; 3],
}

impl ModelInstance {
    pub fn new(model: Mat4, glow: f32) -> Self {
        let n = Mat3::from_mat4(model).inverse().transpose();
        Self {
            model: model.to_cols_array_2d(),
            normal: [n.x_axis, n.y_axis, n.z_axis].map(|c| Vec4::from((c, 0.0)).into()),
            glow,
            _padding: [0.0; 3],
        }
    }

    const ATTRIBUTES: [wgpu::VertexAttribute; 8] = wgpu::vertex_attr_array![
        4 => Float32x4, 5 => Float32x4, 6 => Float32x4, 7 => Float32x4,
        8 => Float32x4, 9 => Float32x4, 10 => Float32x4, 11 => Float32
    ];

    pub const LAYOUT: wgpu::VertexBufferLayout<'static> = wgpu::VertexBufferLayout {
        array_stride: std::mem::size_of::<ModelInstance>() as wgpu::BufferAddress,
        step_mode: wgpu::VertexStepMode::Instance,
        attributes: &Self::ATTRIBUTES,
    };
}
// ANCHOR_END: instance

/// A model in GPU buffers: its parts, and the first material of this model
/// in the renderer's material list.
pub struct GpuModel {
    pub vertices: wgpu::Buffer,
    pub indices: wgpu::Buffer,
    pub parts: Vec<Part>,
    pub first_material: usize,
}

impl GpuModel {
    pub fn upload(device: &wgpu::Device, model: &ModelData, first_material: usize, label: &str) -> Self {
        let buffer = |contents: &[u8], usage| {
            device.create_buffer_init(&wgpu::util::BufferInitDescriptor { label: Some(label), contents, usage })
        };
        // An empty buffer cannot be bound; keep one zero vertex and index.
        let zero = [0; std::mem::size_of::<TexturedVertex>()];
        let vertices: &[u8] = if model.vertices.is_empty() { &zero } else { bytemuck::cast_slice(&model.vertices) };
        let indices: &[u8] = if model.indices.is_empty() { &[0; 4] } else { bytemuck::cast_slice(&model.indices) };
        Self {
            vertices: buffer(vertices, wgpu::BufferUsages::VERTEX | wgpu::BufferUsages::COPY_DST),
            indices: buffer(indices, wgpu::BufferUsages::INDEX | wgpu::BufferUsages::COPY_DST),
            parts: model.parts.clone(),
            first_material,
        }
    }

    /// Replaces the contents with `model` (the drones, every frame),
    /// growing the buffers when it no longer fits.
    pub fn update(&mut self, device: &wgpu::Device, queue: &wgpu::Queue, model: &ModelData) {
        let vertex_bytes: &[u8] = bytemuck::cast_slice(&model.vertices);
        let index_bytes: &[u8] = bytemuck::cast_slice(&model.indices);
        if vertex_bytes.len() as u64 > self.vertices.size() || index_bytes.len() as u64 > self.indices.size() {
            *self = Self::upload(device, model, self.first_material, "model");
            return;
        }
        queue.write_buffer(&self.vertices, 0, vertex_bytes);
        queue.write_buffer(&self.indices, 0, index_bytes);
        self.parts = model.parts.clone();
    }
}
