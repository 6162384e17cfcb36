//! The endless sea: chapter 07's sum of sine waves, chosen so that the sea
//! repeats exactly in space and in time, drawn on one fixed grid of
//! vertices that follows the boat in whole cells.

use common::chapter::{FILTERABLE, mesh_pipeline, sampler_entry, texture_entry, uniform_entry};
use common::glam::Vec2;
use common::{Drawn, Gpu, Reloadable, ShaderError, shader, wgpu};
use lighting::{HDR_FORMAT, SceneLights};
use shadows::shadow_map::ShadowMap;
use water::waves::Wave;

use crate::atmosphere::Atmosphere;

// ANCHOR: periods
/// The sea repeats every this many metres along x and along z …
pub const PERIOD_METRES: f32 = 4096.0;
/// … and every this many seconds.
pub const PERIOD_SECONDS: f32 = 256.0;
/// Earth's, this time: m/s².
pub const GRAVITY: f32 = 9.81;

/// A deep-water wave of about `wavelength` metres travelling at `angle`
/// (radians from +x towards +z), nudged so that the sea repeats: its
/// wave vector k = 2π (m, n) / L for whole m and n, so it fits the
/// period L a whole number of times along x and along z; and its angular
/// frequency ω, which deep water sets to √(g k), rounded to a whole number
/// of turns per [`PERIOD_SECONDS`].
pub fn periodic_wave(angle: f32, wavelength: f32, amplitude: f32) -> Wave {
    let turns = PERIOD_METRES / wavelength;
    let (m, n) = ((turns * angle.cos()).round(), (turns * angle.sin()).round());
    let cycles = Vec2::new(m, n).length();
    let k = std::f32::consts::TAU * cycles / PERIOD_METRES;
    let omega_turns = ((GRAVITY * k).sqrt() * PERIOD_SECONDS / std::f32::consts::TAU).round();
    let omega = std::f32::consts::TAU * omega_turns / PERIOD_SECONDS;
    Wave { direction: Vec2::new(m, n) / cycles, amplitude, wavelength: PERIOD_METRES / cycles, speed: omega / k }
}

/// The way the wind blows, radians from +x towards +z: the longest wave
/// runs with it, and the sail fills with it.
pub const WIND_ANGLE: f32 = 0.7;

/// The sea's longest wave, metres: it runs with the wind …
pub const LONGEST_WAVE_METRES: f32 = 72.0;
/// … and its shortest, four grid cells, so that the grid can draw it.
pub const SHORTEST_WAVE_METRES: f32 = 17.0;
/// Every wave is as steep as the others: its wavelength is this many times
/// its amplitude.
pub const WAVELENGTHS_PER_AMPLITUDE: f32 = 90.0;

/// The sea's eight waves: wind from the south-west, wavelengths from
/// [`LONGEST_WAVE_METRES`] to [`SHORTEST_WAVE_METRES`], spread about the
/// wind, amplitude 1/[`WAVELENGTHS_PER_AMPLITUDE`] of the wavelength.
pub fn sea_waves() -> [Wave; 8] {
    let wavelengths = [LONGEST_WAVE_METRES, 52.0, 40.0, 31.0, 25.0, 21.0, 18.5, SHORTEST_WAVE_METRES];
    let spread = [0.0, 0.45, -0.4, 0.8, -0.75, 0.25, -0.2, 0.6];
    std::array::from_fn(|i| {
        periodic_wave(WIND_ANGLE + spread[i], wavelengths[i], wavelengths[i] / WAVELENGTHS_PER_AMPLITUDE)
    })
}

/// Scene time as the waves see it: reduced modulo their period, which
/// changes nothing about the sea (it repeats) and keeps the phases small
/// enough for f32 at any scene time.
pub fn sea_time(time: f32) -> f32 {
    time.rem_euclid(PERIOD_SECONDS)
}

/// The sea's height at world point `p` at scene time `time`: chapter 07's
/// sum, at the reduced time.
pub fn height(waves: &[Wave], p: Vec2, time: f32) -> f32 {
    water::waves::height(waves, p.x, p.y, sea_time(time))
}
// ANCHOR_END: periods

// ANCHOR: grid
/// Vertices along each side of the grid.
pub const GRID_VERTICES: u32 = 200;
/// Metres between neighbouring vertices: the grid is 796 m across.
pub const CELL: f32 = 4.0;
/// Cells along each side of the seed's "magic carpet": 24 m, three boat
/// lengths.
pub const SMALL_GRID_CELLS: u32 = 6;
/// Metres the water texture covers before it repeats (a whole fraction of
/// the sea's period, so it repeats with the sea).
pub const TILE_METRES: f32 = 32.0;

/// Where the grid's first vertex is, in cells from the world's origin,
/// for a boat at `boat`: the grid's middle on the cell the boat is in.
/// With `snap` off, the grid moves with the boat by fractions of a cell,
/// and its vertices sample the waves at new places every frame: the waves
/// swim.
pub fn grid_origin(boat: Vec2, snap: bool) -> Vec2 {
    grid_origin_for(boat / CELL, GRID_VERTICES, snap)
}

/// [`grid_origin`] for a grid of `vertices` vertices a side and a boat
/// `cells` cells from the world's origin (the book's diagram draws one of
/// 8 vertices).
pub fn grid_origin_for(cells: Vec2, vertices: u32, snap: bool) -> Vec2 {
    let half = (vertices / 2 - 1) as f32;
    if snap { cells.floor() - half } else { cells - half }
}
// ANCHOR_END: grid

/// Indices of the grid's triangles, for the `side` × `side` block of
/// vertices whose first is (`first`, `first`).
fn triangles(first: u32, side: u32) -> Vec<u32> {
    let n = GRID_VERTICES;
    let mut indices = Vec::with_capacity(((side - 1) * (side - 1) * 6) as usize);
    for j in first..first + side - 1 {
        for i in first..first + side - 1 {
            let (a, b, c, d) = (j * n + i, j * n + i + 1, (j + 1) * n + i, (j + 1) * n + i + 1);
            // Counter-clockwise seen from above (+y), with z towards the viewer.
            indices.extend_from_slice(&[a, c, b, b, c, d]);
        }
    }
    indices
}

/// Indices of the grid's edges, as lines.
fn edges() -> Vec<u32> {
    let n = GRID_VERTICES;
    let mut indices = Vec::new();
    for j in 0..n {
        for i in 0..n - 1 {
            indices.extend_from_slice(&[j * n + i, j * n + i + 1, i * n + j, (i + 1) * n + j]);
        }
    }
    indices
}

/// `Sea` in sea.wgsl.
#[repr(C)]
#[derive(Clone, Copy, bytemuck::Pod, bytemuck::Zeroable)]
struct SeaUniform {
    waves: [[f32; 4]; 8],
    speeds: [[f32; 4]; 2],
    grid: [f32; 4],
    look: [f32; 4],
}

/// What the sea looks like this frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SeaSettings {
    /// The grid's first vertex, from [`grid_origin`].
    pub origin: Vec2,
    /// Scene time, seconds.
    pub time: f32,
    /// Paint the water texture (off: one flat colour).
    pub textured: bool,
}

// ANCHOR: piece
/// Draws the sea. Inputs: the waves, the grid's origin and time, the water
/// texture, the lights (group 0), the atmosphere (group 1) and the shadow
/// map (group 3); output: the sea drawn into an HDR scene pass.
pub struct SeaRenderer {
    waves: [Wave; 8],
    uniform: wgpu::Buffer,
    group_layout: wgpu::BindGroupLayout,
    group: Option<wgpu::BindGroup>,
    sampler: wgpu::Sampler,
    /// The lit sea and its edges, and the tests' probe where the adapter
    /// can draw into 32-bit floats (OpenGL cannot), made again when
    /// sea.wgsl or a module it imports is saved (hot reload).
    pipelines: Reloadable<([wgpu::RenderPipeline; 2], Option<wgpu::RenderPipeline>)>,
    whole: (wgpu::Buffer, u32),
    small: (wgpu::Buffer, u32),
    lines: (wgpu::Buffer, u32),
}
// ANCHOR_END: piece

impl SeaRenderer {
    /// The sea for an HDR pass of `multisample`'s samples a pixel
    /// ([`lighting::HdrTarget::multisample`]); the tests' probe draws at one.
    pub fn new(
        gpu: &Gpu,
        lights: &SceneLights,
        atmosphere: &Atmosphere,
        shadow: &ShadowMap,
        waves: [Wave; 8],
        multisample: wgpu::MultisampleState,
    ) -> Result<Self, ShaderError> {
        let device = &gpu.device;
        let group_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("sea"),
            entries: &[
                uniform_entry(0, wgpu::ShaderStages::VERTEX_FRAGMENT, std::mem::size_of::<SeaUniform>()),
                texture_entry(1, FILTERABLE),
                sampler_entry(2),
            ],
        });
        let layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("sea"),
            bind_group_layouts: &[
                Some(&lights.layout),
                Some(&atmosphere.layout),
                Some(&group_layout),
                Some(&shadow.layout),
            ],
            immediate_size: 0,
        });
        let uniform = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("sea"),
            size: std::mem::size_of::<SeaUniform>() as u64,
            usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let sampler = device.create_sampler(&wgpu::SamplerDescriptor {
            label: Some("water texture"),
            address_mode_u: wgpu::AddressMode::Repeat,
            address_mode_v: wgpu::AddressMode::Repeat,
            mag_filter: wgpu::FilterMode::Linear,
            min_filter: wgpu::FilterMode::Linear,
            mipmap_filter: wgpu::MipmapFilterMode::Linear,
            ..Default::default()
        });
        let indices = |label, data: Vec<u32>| {
            let buffer = wgpu::util::DeviceExt::create_buffer_init(
                device,
                &wgpu::util::BufferInitDescriptor {
                    label: Some(label),
                    contents: bytemuck::cast_slice(&data),
                    usage: wgpu::BufferUsages::INDEX,
                },
            );
            (buffer, data.len() as u32)
        };
        let middle = GRID_VERTICES / 2 - 1 - SMALL_GRID_CELLS / 2;
        let pipelines = Reloadable::new(gpu, move |gpu| Self::pipelines(gpu, &layout, multisample))?;
        Ok(Self {
            waves,
            uniform,
            group_layout,
            group: None,
            sampler,
            pipelines,
            whole: indices("sea", triangles(0, GRID_VERTICES)),
            small: indices("small sea", triangles(middle, SMALL_GRID_CELLS + 1)),
            lines: indices("sea edges", edges()),
        })
    }

    fn pipelines(
        gpu: &Gpu,
        layout: &wgpu::PipelineLayout,
        multisample: wgpu::MultisampleState,
    ) -> Result<([wgpu::RenderPipeline; 2], Option<wgpu::RenderPipeline>), ShaderError> {
        let device = &gpu.device;
        let module = shader!(
            "voronoi-water/sea.wgsl",
            imports: [
                "lighting/brdf.wgsl",
                "lighting/sky_light.wgsl",
                "lighting/lights.wgsl",
                "shadows/shadow.wgsl",
                "water/waves.wgsl",
                "voronoi-water/atmosphere.wgsl"
            ]
        )
        .module(gpu)?;
        let lit = || mesh_pipeline(device, layout, &module, ("vs_sea", "fs_sea"), &[], HDR_FORMAT.into(), multisample);
        let wire = || {
            device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
                label: Some("sea edges"),
                layout: Some(layout),
                vertex: wgpu::VertexState {
                    module: &module,
                    entry_point: Some("vs_sea"),
                    buffers: &[],
                    compilation_options: Default::default(),
                },
                primitive: wgpu::PrimitiveState { topology: wgpu::PrimitiveTopology::LineList, ..Default::default() },
                // Over the sea it outlines: lines tie with its surface, so
                // they pass where they are no farther.
                depth_stencil: Some(wgpu::DepthStencilState {
                    depth_write_enabled: Some(false),
                    depth_compare: Some(wgpu::CompareFunction::LessEqual),
                    ..common::texture::depth_test().expect("a depth test")
                }),
                multisample,
                fragment: Some(wgpu::FragmentState {
                    module: &module,
                    entry_point: Some("fs_wire"),
                    targets: &[Some(HDR_FORMAT.into())],
                    compilation_options: Default::default(),
                }),
                multiview_mask: None,
                cache: None,
            })
        };
        let probe = || {
            device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
                label: Some("sea probe"),
                layout: Some(layout),
                vertex: wgpu::VertexState {
                    module: &module,
                    entry_point: Some("vs_probe"),
                    buffers: &[],
                    compilation_options: Default::default(),
                },
                primitive: wgpu::PrimitiveState { topology: wgpu::PrimitiveTopology::PointList, ..Default::default() },
                depth_stencil: None,
                multisample: Default::default(),
                fragment: Some(wgpu::FragmentState {
                    module: &module,
                    entry_point: Some("fs_probe"),
                    targets: &[Some(wgpu::TextureFormat::Rgba32Float.into())],
                    compilation_options: Default::default(),
                }),
                multiview_mask: None,
                cache: None,
            })
        };
        let probe_drawable = gpu
            .adapter
            .get_texture_format_features(wgpu::TextureFormat::Rgba32Float)
            .allowed_usages
            .contains(wgpu::TextureUsages::RENDER_ATTACHMENT);
        gpu.catch_validation(|| ([lit(), wire()], probe_drawable.then(probe))).map_err(ShaderError)
    }

    pub fn waves(&self) -> &[Wave; 8] {
        &self.waves
    }

    /// Writes the frame's grid and time, and points the sea at `water`.
    pub fn write(&mut self, gpu: &Gpu, water: &wgpu::TextureView, settings: &SeaSettings) {
        let mut speeds = [[0.0; 4]; 2];
        for (i, w) in self.waves.iter().enumerate() {
            speeds[i / 4][i % 4] = w.speed;
        }
        let uniform = SeaUniform {
            waves: self.waves.map(|w| [w.direction.x, w.direction.y, w.amplitude, w.wavelength]),
            speeds,
            grid: [settings.origin.x, settings.origin.y, CELL, sea_time(settings.time)],
            look: [TILE_METRES, if settings.textured { 1.0 } else { 0.0 }, GRID_VERTICES as f32, 0.0],
        };
        gpu.queue.write_buffer(&self.uniform, 0, bytemuck::bytes_of(&uniform));
        self.group = Some(gpu.device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("sea"),
            layout: &self.group_layout,
            entries: &[
                wgpu::BindGroupEntry { binding: 0, resource: self.uniform.as_entire_binding() },
                wgpu::BindGroupEntry { binding: 1, resource: wgpu::BindingResource::TextureView(water) },
                wgpu::BindGroupEntry { binding: 2, resource: wgpu::BindingResource::Sampler(&self.sampler) },
            ],
        }));
    }

    // ANCHOR: draw
    /// Draws the sea into `pass`, whose groups 0, 1 and 3 must be the
    /// lights, the atmosphere and the shadow map; `wires` draws the grid's
    /// edges over it. Returns what it drew.
    pub fn draw(&self, pass: &mut wgpu::RenderPass<'_>, small: bool, wires: bool) -> Drawn {
        pass.set_bind_group(2, self.group.as_ref(), &[]);
        let (indices, count) = if small { &self.small } else { &self.whole };
        let ([lit, wire], _) = self.pipelines.get();
        pass.set_pipeline(&lit);
        pass.set_index_buffer(indices.slice(..), wgpu::IndexFormat::Uint32);
        pass.draw_indexed(0..*count, 0, 0..1);
        let mut drawn = Drawn::triangle_list(0..*count, 0..1);
        if wires {
            pass.set_pipeline(&wire);
            pass.set_index_buffer(self.lines.0.slice(..), wgpu::IndexFormat::Uint32);
            pass.draw_indexed(0..self.lines.1, 0, 0..1);
            drawn += Drawn::POINTS_OR_LINES;
        }
        drawn
    }
    // ANCHOR_END: draw

    /// For the tests: where the vertex shader puts every vertex of the
    /// grid, as (x, height, z), vertex i at index i. Needs the groups of a
    /// frame written first ([`SeaRenderer::write`] and the others').
    pub fn probe(
        &self,
        gpu: &Gpu,
        lights: &SceneLights,
        atmosphere: &Atmosphere,
        shadow: &ShadowMap,
    ) -> common::anyhow::Result<Vec<[f32; 4]>> {
        let Some(pipeline) = self.pipelines.get().1 else {
            common::anyhow::bail!("this adapter cannot draw into Rgba32Float, which the sea's probe reads back");
        };
        let texture = gpu.device.create_texture(&wgpu::TextureDescriptor {
            label: Some("sea probe"),
            size: wgpu::Extent3d { width: GRID_VERTICES, height: GRID_VERTICES, depth_or_array_layers: 1 },
            mip_level_count: 1,
            sample_count: 1,
            dimension: wgpu::TextureDimension::D2,
            format: wgpu::TextureFormat::Rgba32Float,
            usage: wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::COPY_SRC,
            view_formats: &[],
        });
        let view = texture.create_view(&Default::default());
        let mut encoder = gpu.device.create_command_encoder(&Default::default());
        {
            let mut pass = common::fullscreen::pass(
                &mut encoder,
                &common::PassTimer::off(),
                "sea probe",
                &view,
                Some(wgpu::Color::TRANSPARENT),
            );
            pass.set_pipeline(&pipeline);
            pass.set_bind_group(0, &lights.group, &[]);
            pass.set_bind_group(1, &atmosphere.group, &[]);
            pass.set_bind_group(2, self.group.as_ref(), &[]);
            pass.set_bind_group(3, &shadow.group, &[]);
            pass.draw(0..GRID_VERTICES * GRID_VERTICES, 0..1);
        }
        gpu.queue.submit([encoder.finish()]);
        common::headless::read_floats(gpu, &texture)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_sea_repeats_in_space_and_time() {
        let waves = sea_waves();
        for i in 0..50 {
            let p = Vec2::new(i as f32 * 37.3, i as f32 * 11.9);
            let t = i as f32 * 1.7;
            let here = height(&waves, p, t);
            let moved = water::waves::height(&waves, p.x + PERIOD_METRES, p.y, t);
            let later = water::waves::height(&waves, p.x, p.y, t + PERIOD_SECONDS);
            assert!((here - moved).abs() < 2e-3, "a period along x changed {here} to {moved}");
            assert!((here - later).abs() < 2e-3, "a period later {here} became {later}");
        }
    }

    /// The most that rounding ω to whole turns a period may move a wave's
    /// speed from deep water's, as a share of it.
    const MOST_SPEED_MOVED: f32 = 0.02;

    #[test]
    fn nudged_waves_keep_their_shape() {
        for w in sea_waves() {
            // Deep water: c = √(g λ / 2π), within what rounding ω allows.
            let ideal = (GRAVITY * w.wavelength / std::f32::consts::TAU).sqrt();
            assert!(
                (w.speed - ideal).abs() / ideal < MOST_SPEED_MOVED,
                "{} m: {} m/s, not {ideal}",
                w.wavelength,
                w.speed
            );
            assert!(w.wavelength >= 4.0 * CELL, "a {} m wave is too short for {CELL} m cells", w.wavelength);
        }
    }

    #[test]
    fn the_grid_snaps_to_whole_cells() {
        let a = grid_origin(Vec2::new(1000.3, 52.0), true);
        let b = grid_origin(Vec2::new(1001.9, 53.5), true);
        assert_eq!(a, b, "within a cell the grid stays put");
        assert_eq!(a.fract(), Vec2::ZERO);
        let c = grid_origin(Vec2::new(1004.1, 52.0), true);
        assert_eq!(c - a, Vec2::new(1.0, 0.0), "into the next cell: one cell over");
        assert_ne!(grid_origin(Vec2::new(1000.3, 52.0), false), grid_origin(Vec2::new(1001.9, 52.0), false));
    }
}
