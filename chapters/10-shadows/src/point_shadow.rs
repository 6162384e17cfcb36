//! A point light's shadow: the cube shadow map. A lamp shines every way,
//! so one picture from it cannot hold what it sees; six can, one per face
//! of a cube around it, each a 90° square view. This module renders the
//! six faces (the distance from the light to the nearest surface, over the
//! light's range, in every texel), binds the cube for the main pass, and
//! holds the face maths that rendering and looking up must agree on.
//!
//! Why distance, and not each face's own depth: a lookup reads the cube
//! with a direction and the GPU picks the face, so the value a point is
//! compared with must not depend on the face. The distance to the light is
//! the same whichever face holds it, also for a filter's taps that fall
//! across a cube edge onto the next face. The shadow pass writes it as the
//! fragment's depth (`frag_depth`), so the comparison sampler still does
//! the comparing.

use common::chapter::uniform_entry;
use common::glam::{Mat4, Vec2, Vec3, Vec4};
use common::{Drawn, Gpu, PassCount, PassTimer, Reloadable, ShaderError, Target, shader, wgpu};
use lighting::lights::Light;
use textures::DrawList;
use textures::mesh::{ModelInstance, TexturedVertex};

// ANCHOR: faces
/// One face of the cube, in the order of a cube texture's layers.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum CubeFace {
    PosX,
    NegX,
    PosY,
    NegY,
    PosZ,
    NegZ,
}

/// A face's three axes: where it looks (its major axis), which way its
/// texel columns run (s) and which way its rows run (t, downwards).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FaceAxes {
    pub major: Vec3,
    pub s: Vec3,
    pub t: Vec3,
}

impl CubeFace {
    /// The six faces, in layer order.
    pub const ALL: [CubeFace; 6] =
        [CubeFace::PosX, CubeFace::NegX, CubeFace::PosY, CubeFace::NegY, CubeFace::PosZ, CubeFace::NegZ];

    /// The face's axes, from the table every API shares (the Vulkan
    /// specification's "Cube Map Face Selection"; OpenGL's and Direct3D's
    /// are the same): a direction d on this face lands at
    /// s = (d · s_axis / |d · major| + 1) / 2, t likewise.
    pub const fn axes(self) -> FaceAxes {
        let (x, y, z) = (Vec3::X, Vec3::Y, Vec3::Z);
        let (nx, ny, nz) = (Vec3::NEG_X, Vec3::NEG_Y, Vec3::NEG_Z);
        let (major, s, t) = match self {
            CubeFace::PosX => (x, nz, ny),
            CubeFace::NegX => (nx, z, ny),
            CubeFace::PosY => (y, x, z),
            CubeFace::NegY => (ny, x, nz),
            CubeFace::PosZ => (z, x, ny),
            CubeFace::NegZ => (nz, nx, ny),
        };
        FaceAxes { major, s, t }
    }

    /// The layer this face is in a cube texture.
    pub fn layer(self) -> u32 {
        self as u32
    }

    /// The face a lookup along `direction` reads, and where on it: s and t
    /// from 0 to 1, t down the face. The largest component picks the face;
    /// on a tie (a cube edge or corner) x wins over y, and y over z. Either
    /// face would do there: both hold that direction on their border.
    pub fn lookup(direction: Vec3) -> (CubeFace, Vec2) {
        let a = direction.abs();
        let face = if a.x >= a.y && a.x >= a.z {
            if direction.x >= 0.0 { CubeFace::PosX } else { CubeFace::NegX }
        } else if a.y >= a.z {
            if direction.y >= 0.0 { CubeFace::PosY } else { CubeFace::NegY }
        } else if direction.z >= 0.0 {
            CubeFace::PosZ
        } else {
            CubeFace::NegZ
        };
        let axes = face.axes();
        let along = direction.dot(axes.major);
        let st = Vec2::new(direction.dot(axes.s), direction.dot(axes.t)) / along;
        (face, (st + 1.0) / 2.0)
    }

    /// The direction through `st` (0 to 1 across the face, t down): the
    /// inverse of [`CubeFace::lookup`], not normalised.
    pub fn direction(self, st: Vec2) -> Vec3 {
        let axes = self.axes();
        axes.major + axes.s * (st.x * 2.0 - 1.0) + axes.t * (st.y * 2.0 - 1.0)
    }

    /// World to this face's clip space, for a light at `light` whose range
    /// is `range`: x and y land where [`CubeFace::lookup`] says (y up the
    /// picture, as t runs down it), w is the distance along the face's
    /// axis, and the near and far planes are [`NEAR`] and `range`. The
    /// depth the shadow pass stores is not this z but the distance (see
    /// `point_caster.wgsl`); z only clips.
    ///
    /// No camera turned to face the axis gives this: (s, −t, major) is a
    /// left-handed frame, because a cube map's faces are laid out as seen
    /// from outside the cube. The picture is a mirror image of a camera's,
    /// so triangles facing the light wind clockwise (see [`caster_winding`]).
    pub fn view_proj(self, light: Vec3, range: f32) -> Mat4 {
        let axes = self.axes();
        let row = |axis: Vec3| Vec4::new(axis.x, axis.y, axis.z, -axis.dot(light));
        let (x, y, w) = (row(axes.s), row(-axes.t), row(axes.major));
        // z = 0 at the near plane and w at the far one, so z / w runs 0 to 1.
        let scale = range / (range - NEAR);
        let z = w * scale - Vec4::new(0.0, 0.0, 0.0, NEAR * scale);
        Mat4::from_cols(x, y, z, w).transpose()
    }
}

/// Metres from the light to the near plane of every face.
pub const NEAR: f32 = 0.05;

/// Which way triangles that face the light wind in a face's picture: the
/// faces are mirror images (see [`CubeFace::view_proj`]), so clockwise.
pub const fn caster_winding() -> wgpu::FrontFace {
    wgpu::FrontFace::Cw
}
// ANCHOR_END: faces

// ANCHOR: settings
/// The cube's format: one distance per texel, compared by the sampler.
pub const CUBE_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Depth32Float;
/// Texels along each side of each face.
pub const DEFAULT_FACE_SIZE: u32 = 512;

/// How a fragment turns the cube into light.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PointFilter {
    /// No lookup: the light passes through everything, as chapter 08's
    /// lamps do (the bench's baseline, and the "light through walls" picture).
    Off,
    /// One comparison along the direction from the light: one texel's answer.
    Hard,
    /// Nine comparisons along directions a texel apart around it, each
    /// blending the answers of the four texels around its direction.
    Pcf3x3,
}

impl PointFilter {
    pub const ALL: [PointFilter; 3] = [PointFilter::Off, PointFilter::Hard, PointFilter::Pcf3x3];

    pub fn label(self) -> &'static str {
        match self {
            PointFilter::Off => "off (light through walls)",
            PointFilter::Hard => "hard (1 tap)",
            PointFilter::Pcf3x3 => "3×3 PCF",
        }
    }
}

/// Keeping a surface from shadowing itself, both in texels of the cube at
/// the point's distance from the light (a texel covers 2 × distance / size
/// metres, so a far point needs more metres of bias than a near one).
/// The shadow pass writes its depth from the shader, which the pipeline's
/// depth-bias state does not touch: both biases are the lookup's.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PointBias {
    /// How far the point looked up is moved off its surface, along its normal.
    pub normal_offset: f32,
    /// How much nearer the light the point is taken to be.
    pub depth: f32,
}

impl PointBias {
    pub const NONE: PointBias = PointBias { normal_offset: 0.0, depth: 0.0 };
    /// Enough for the level's surfaces, and no more.
    pub const DEFAULT: PointBias = PointBias { normal_offset: 1.0, depth: 1.5 };
}

/// Everything the cube's lookups depend on.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PointShadowSettings {
    pub filter: PointFilter,
    pub bias: PointBias,
    /// How far apart the PCF taps are, in texels.
    pub spacing: f32,
}

impl PointShadowSettings {
    pub const DEFAULT: Self = Self { filter: PointFilter::Pcf3x3, bias: PointBias::DEFAULT, spacing: 1.0 };
    /// The light without its shadow.
    pub const OFF: Self = Self { filter: PointFilter::Off, ..Self::DEFAULT };
}

impl Default for PointShadowSettings {
    fn default() -> Self {
        Self::DEFAULT
    }
}
// ANCHOR_END: settings

/// What one frame's cube cost, counted as it was recorded.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct CubeCost {
    /// Render passes: one per face.
    pub passes: u32,
    /// `draw_indexed` calls, over all six passes.
    pub draw_calls: u32,
    /// Triangles submitted, over all six passes (instances counted).
    pub triangles: u64,
}

impl CubeCost {
    /// The six passes as the frame's counts know them: one pass, as they are timed.
    pub fn pass_count(&self) -> PassCount {
        PassCount { pass: "lantern shadow", drawn: Drawn::counted(self.draw_calls, self.triangles) }
    }
}

/// `PointShadow` in point_shadow.wgsl: 64 bytes.
#[repr(C)]
#[derive(Clone, Copy, bytemuck::Pod, bytemuck::Zeroable)]
struct PointShadowUniform {
    light: [f32; 4],
    colour: [f32; 4],
    options: [u32; 4],
    params: [f32; 4],
}

/// `Face` in point_caster.wgsl: 80 bytes, each face's copy at its own
/// aligned offset of one buffer.
#[repr(C)]
#[derive(Clone, Copy, bytemuck::Pod, bytemuck::Zeroable)]
struct FaceUniform {
    view_proj: [[f32; 4]; 4],
    light: [f32; 4],
}

// ANCHOR: point_shadow
/// A point light's cube shadow map, the six passes that render it, and
/// what the main pass needs to read it. Inputs: the light (chapter 08's
/// [`Light`], a point light) and the settings, each frame; what casts
/// shadows, as a draw list. Output: five bindings, 1 to 5, that a
/// renderer adds to a bind group of its own ([`PointShadow::layout_entries`],
/// [`PointShadow::group_entries`]): WebGPU promises only four bind groups
/// a pipeline, and the shadowed main pass already uses all four.
///
/// One cube, not a cube array: a cube texture is core in WebGPU and in
/// WebGL 2 (OpenGL ES 3.0), where a cube array needs
/// `DownlevelFlags::CUBE_ARRAY_TEXTURES`, which WebGL 2 lacks. Each more
/// light would be one more `PointShadow`.
pub struct PointShadow {
    /// Texels along each side of each face, after clamping to the adapter.
    pub size: u32,
    /// The six faces as one cube, for lookups.
    pub cube: wgpu::TextureView,
    /// Each face alone, to render into.
    faces: [wgpu::TextureView; 6],
    compare_nearest: wgpu::Sampler,
    compare_linear: wgpu::Sampler,
    uniform: wgpu::Buffer,
    face_uniforms: wgpu::Buffer,
    /// Bytes between two faces' uniforms: the adapter's alignment for
    /// dynamic offsets.
    face_stride: u32,
    caster_group: wgpu::BindGroup,
    /// Made again when point_caster.wgsl is saved (hot reload).
    caster: Reloadable<wgpu::RenderPipeline>,
}
// ANCHOR_END: point_shadow

impl PointShadow {
    /// A cube of `requested` texels a side (clamped to what the adapter allows).
    pub fn new(gpu: &Gpu, requested: u32) -> Result<Self, ShaderError> {
        let device = &gpu.device;
        let size = requested.clamp(16, device.limits().max_texture_dimension_2d);
        // ANCHOR: texture
        // Six layers of one square texture: the GPU treats them as a cube
        // through a `Cube` view (the lookups), and each as a picture of
        // its own through a 2D view of one layer (the shadow passes).
        let texture = device.create_texture(&wgpu::TextureDescriptor {
            label: Some("lantern cube shadow map"),
            size: wgpu::Extent3d { width: size, height: size, depth_or_array_layers: 6 },
            mip_level_count: 1,
            sample_count: 1,
            dimension: wgpu::TextureDimension::D2,
            format: CUBE_FORMAT,
            usage: wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::TEXTURE_BINDING,
            view_formats: &[],
        });
        let cube = texture.create_view(&wgpu::TextureViewDescriptor {
            label: Some("lantern cube"),
            dimension: Some(wgpu::TextureViewDimension::Cube),
            ..Default::default()
        });
        let faces = CubeFace::ALL.map(|face| {
            texture.create_view(&wgpu::TextureViewDescriptor {
                label: Some("lantern cube face"),
                dimension: Some(wgpu::TextureViewDimension::D2),
                base_array_layer: face.layer(),
                array_layer_count: Some(1),
                ..Default::default()
            })
        });
        // ANCHOR_END: texture
        // Comparison samplers, as the sun's: one texel's answer, or the
        // answers of the four around the direction, blended. Across a cube
        // edge the four come from two faces (cube filtering is seamless in
        // WebGPU and in OpenGL ES 3.0).
        let comparison = |filter| {
            device.create_sampler(&wgpu::SamplerDescriptor {
                label: Some("lantern comparison"),
                mag_filter: filter,
                min_filter: filter,
                compare: Some(wgpu::CompareFunction::LessEqual),
                ..Default::default()
            })
        };
        let (compare_nearest, compare_linear) =
            (comparison(wgpu::FilterMode::Nearest), comparison(wgpu::FilterMode::Linear));
        let uniform = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("lantern shadow"),
            size: std::mem::size_of::<PointShadowUniform>() as u64,
            usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let face_size = std::mem::size_of::<FaceUniform>() as u32;
        let face_stride = face_size.next_multiple_of(device.limits().min_uniform_buffer_offset_alignment);
        let face_uniforms = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("lantern cube faces"),
            size: u64::from(face_stride) * 6,
            usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let caster_group_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("lantern caster"),
            entries: &[wgpu::BindGroupLayoutEntry {
                binding: 0,
                visibility: wgpu::ShaderStages::VERTEX_FRAGMENT,
                ty: wgpu::BindingType::Buffer {
                    ty: wgpu::BufferBindingType::Uniform,
                    has_dynamic_offset: true,
                    min_binding_size: wgpu::BufferSize::new(u64::from(face_size)),
                },
                count: None,
            }],
        });
        let caster_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("lantern caster"),
            layout: &caster_group_layout,
            entries: &[wgpu::BindGroupEntry {
                binding: 0,
                resource: wgpu::BindingResource::Buffer(wgpu::BufferBinding {
                    buffer: &face_uniforms,
                    offset: 0,
                    size: wgpu::BufferSize::new(u64::from(face_size)),
                }),
            }],
        });
        let caster_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("lantern caster"),
            bind_group_layouts: &[Some(&caster_group_layout)],
            immediate_size: 0,
        });
        let caster = Reloadable::new(gpu, move |gpu| Self::caster_pipeline(gpu, &caster_layout))?;
        Ok(Self {
            size,
            cube,
            faces,
            compare_nearest,
            compare_linear,
            uniform,
            face_uniforms,
            face_stride,
            caster_group,
            caster,
        })
    }

    // ANCHOR: caster_pipeline
    /// The shadow passes' pipeline: the fragment shader writes the
    /// distance as the depth, the depth test keeps the nearest, and
    /// back faces are culled with the mirrored faces' winding.
    fn caster_pipeline(gpu: &Gpu, layout: &wgpu::PipelineLayout) -> Result<wgpu::RenderPipeline, ShaderError> {
        let module = shader!("shadows/point_caster.wgsl", imports: ["textures/surface.wgsl"]).module(gpu)?;
        gpu.catch_validation(|| {
            gpu.device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
                label: Some("lantern caster"),
                layout: Some(layout),
                vertex: wgpu::VertexState {
                    module: &module,
                    entry_point: Some("vs_point_caster"),
                    buffers: &[Some(TexturedVertex::LAYOUT), Some(ModelInstance::LAYOUT)],
                    compilation_options: Default::default(),
                },
                primitive: wgpu::PrimitiveState {
                    front_face: caster_winding(),
                    cull_mode: Some(wgpu::Face::Back),
                    ..Default::default()
                },
                depth_stencil: Some(wgpu::DepthStencilState {
                    format: CUBE_FORMAT,
                    depth_write_enabled: Some(true),
                    depth_compare: Some(wgpu::CompareFunction::Less),
                    stencil: Default::default(),
                    bias: Default::default(),
                }),
                multisample: Default::default(),
                fragment: Some(wgpu::FragmentState {
                    module: &module,
                    entry_point: Some("fs_point_caster"),
                    targets: &[],
                    compilation_options: Default::default(),
                }),
                multiview_mask: None,
                cache: None,
            })
        })
        .map_err(ShaderError)
    }
    // ANCHOR_END: caster_pipeline

    /// Bindings 1 to 5 of the group a renderer shares with the cube: the
    /// cube, its two comparison samplers, the light with its settings, and
    /// the cube again for the second sampler (OpenGL's GLSL reads a texture
    /// through one sampler only). `point_shadow.wgsl` declares them in
    /// group 2.
    pub fn layout_entries() -> [wgpu::BindGroupLayoutEntry; 5] {
        let fragment = wgpu::ShaderStages::FRAGMENT;
        let comparison = |binding| wgpu::BindGroupLayoutEntry {
            binding,
            visibility: fragment,
            ty: wgpu::BindingType::Sampler(wgpu::SamplerBindingType::Comparison),
            count: None,
        };
        let cube = |binding| wgpu::BindGroupLayoutEntry {
            binding,
            visibility: fragment,
            ty: wgpu::BindingType::Texture {
                sample_type: wgpu::TextureSampleType::Depth,
                view_dimension: wgpu::TextureViewDimension::Cube,
                multisampled: false,
            },
            count: None,
        };
        [
            cube(1),
            comparison(2),
            comparison(3),
            // Storage, not uniform: `point_lit` switches on the filter
            // (lights.wgsl's `frame` says why).
            common::chapter::storage_entry(4, fragment),
            cube(5),
        ]
    }

    /// The resources for [`PointShadow::layout_entries`]. The cube and the
    /// buffer are made once and never replaced, so a group made from these
    /// stays valid.
    pub fn group_entries(&self) -> [wgpu::BindGroupEntry<'_>; 5] {
        [
            wgpu::BindGroupEntry { binding: 1, resource: wgpu::BindingResource::TextureView(&self.cube) },
            wgpu::BindGroupEntry { binding: 2, resource: wgpu::BindingResource::Sampler(&self.compare_nearest) },
            wgpu::BindGroupEntry { binding: 3, resource: wgpu::BindingResource::Sampler(&self.compare_linear) },
            wgpu::BindGroupEntry { binding: 4, resource: self.uniform.as_entire_binding() },
            wgpu::BindGroupEntry { binding: 5, resource: wgpu::BindingResource::TextureView(&self.cube) },
        ]
    }

    /// Writes this frame's light and settings, for the passes and the lookups.
    pub fn write(&self, gpu: &Gpu, light: &Light, settings: &PointShadowSettings) {
        let filter = PointFilter::ALL.iter().position(|f| *f == settings.filter).unwrap_or(0) as u32;
        let place = light.position.extend(light.range).to_array();
        let uniform = PointShadowUniform {
            light: place,
            colour: light.colour.extend(0.0).to_array(),
            options: [filter, self.size, 0, 0],
            params: [settings.bias.normal_offset, settings.bias.depth, settings.spacing, 0.0],
        };
        gpu.queue.write_buffer(&self.uniform, 0, bytemuck::bytes_of(&uniform));
        for face in CubeFace::ALL {
            let face_uniform =
                FaceUniform { view_proj: face.view_proj(light.position, light.range).to_cols_array_2d(), light: place };
            let offset = u64::from(face.layer() * self.face_stride);
            gpu.queue.write_buffer(&self.face_uniforms, offset, bytemuck::bytes_of(&face_uniform));
        }
    }

    // ANCHOR: render
    /// The six shadow passes: every model in `casters`, once per face, as
    /// the light sees it. Returns what they cost.
    pub fn render(&self, encoder: &mut wgpu::CommandEncoder, timer: &PassTimer, casters: &DrawList) -> CubeCost {
        let pipeline = self.caster.get();
        let mut cost = CubeCost::default();
        for face in CubeFace::ALL {
            let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
                label: Some("lantern shadow"),
                color_attachments: &[],
                depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
                    view: &self.faces[face.layer() as usize],
                    depth_ops: Some(wgpu::Operations { load: wgpu::LoadOp::Clear(1.0), store: wgpu::StoreOp::Store }),
                    stencil_ops: None,
                }),
                // The six passes are timed as one.
                timestamp_writes: timer.chain("lantern shadow", face.layer() as usize, 6),
                ..Default::default()
            });
            cost.passes += 1;
            pass.set_pipeline(&pipeline);
            pass.set_bind_group(0, &self.caster_group, &[face.layer() * self.face_stride]);
            pass.set_vertex_buffer(1, casters.instances.slice(..));
            for draw in casters.draws.iter().filter(|d| !d.instances.is_empty()) {
                pass.set_vertex_buffer(0, draw.model.vertices.slice(..));
                pass.set_index_buffer(draw.model.indices.slice(..), wgpu::IndexFormat::Uint32);
                for part in &draw.model.parts {
                    pass.draw_indexed(part.indices.clone(), 0, draw.instances.clone());
                    cost.draw_calls += 1;
                    cost.triangles += u64::from(part.indices.len() as u32 / 3) * draw.instances.len() as u64;
                }
            }
        }
        cost
    }
    // ANCHOR_END: render
}

/// `Unfolded` in show_cube.wgsl.
#[repr(C)]
#[derive(Clone, Copy, bytemuck::Pod, bytemuck::Zeroable)]
struct UnfoldedUniform {
    axes: [[f32; 4]; 18],
    shape: [f32; 4],
}

/// The `cube-shadow-map` view: the six faces unfolded in a cross, full
/// screen, each pixel read from the cube along the direction its face and
/// place on the face give, as a lookup would. Faces whose rendering and
/// lookup disagreed would show as seams along the cross's edges.
pub struct CubeView {
    group: wgpu::BindGroup,
    uniform: wgpu::Buffer,
    /// Made again when show_cube.wgsl is saved (hot reload).
    pipeline: Reloadable<wgpu::RenderPipeline>,
}

impl CubeView {
    pub fn new(gpu: &Gpu, format: wgpu::TextureFormat, cube: &PointShadow) -> Result<Self, ShaderError> {
        let device = &gpu.device;
        let fragment = wgpu::ShaderStages::FRAGMENT;
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("cube view"),
            entries: &[
                wgpu::BindGroupLayoutEntry {
                    binding: 0,
                    visibility: fragment,
                    // Depths read as plain floats (show_cube.wgsl says why).
                    ty: wgpu::BindingType::Texture {
                        sample_type: wgpu::TextureSampleType::Float { filterable: false },
                        view_dimension: wgpu::TextureViewDimension::Cube,
                        multisampled: false,
                    },
                    count: None,
                },
                // Depth read as a value: a sampler that does not filter
                // (a depth texture cannot be filtered, only compared).
                wgpu::BindGroupLayoutEntry {
                    binding: 1,
                    visibility: fragment,
                    ty: wgpu::BindingType::Sampler(wgpu::SamplerBindingType::NonFiltering),
                    count: None,
                },
                uniform_entry(2, fragment, std::mem::size_of::<UnfoldedUniform>()),
            ],
        });
        let nearest =
            device.create_sampler(&wgpu::SamplerDescriptor { label: Some("cube view"), ..Default::default() });
        let uniform = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("cube view"),
            size: std::mem::size_of::<UnfoldedUniform>() as u64,
            usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("cube view"),
            layout: &layout,
            entries: &[
                wgpu::BindGroupEntry { binding: 0, resource: wgpu::BindingResource::TextureView(&cube.cube) },
                wgpu::BindGroupEntry { binding: 1, resource: wgpu::BindingResource::Sampler(&nearest) },
                wgpu::BindGroupEntry { binding: 2, resource: uniform.as_entire_binding() },
            ],
        });
        let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("cube view"),
            bind_group_layouts: &[Some(&layout)],
            immediate_size: 0,
        });
        let pipeline = Reloadable::new(gpu, move |gpu| {
            let module = shader!("shadows/show_cube.wgsl", imports: ["common/fullscreen.wgsl"]).module(gpu)?;
            gpu.catch_validation(|| {
                common::fullscreen::pipeline(
                    &gpu.device,
                    "cube view",
                    &pipeline_layout,
                    &module,
                    "fs_unfolded",
                    format.into(),
                    None,
                )
            })
            .map_err(ShaderError)
        })?;
        Ok(Self { group, uniform, pipeline })
    }

    /// Draws the cube over the frame's target, which is `target`'s shape.
    pub fn draw(&self, gpu: &Gpu, frame: &mut common::Frame, target: Target) {
        let mut axes = [[0.0; 4]; 18];
        for face in CubeFace::ALL {
            let a = face.axes();
            for (i, axis) in [a.major, a.s, a.t].into_iter().enumerate() {
                axes[face.layer() as usize * 3 + i] = axis.extend(0.0).to_array();
            }
        }
        // The cross is three faces high and fills the height of a wide target.
        let face_pixels = (target.height as f32 / 3.0).min(target.width as f32 / 4.0);
        let uniform = UnfoldedUniform { axes, shape: [target.aspect(), face_pixels, 0.0, 0.0] };
        gpu.queue.write_buffer(&self.uniform, 0, bytemuck::bytes_of(&uniform));
        let mut pass =
            common::fullscreen::pass(frame.encoder, frame.timer, "cube view", frame.target, Some(wgpu::Color::BLACK));
        pass.set_pipeline(&self.pipeline.get());
        pass.set_bind_group(0, &self.group, &[]);
        pass.draw(0..3, 0..1);
        frame.drawn.add("cube view", Drawn::FULL_SCREEN);
    }
}
