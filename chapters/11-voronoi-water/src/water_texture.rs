//! From the diagram to the water's texture, the seed's way: colour the
//! cells, blur them with a separable box blur run twice, find the edges
//! with Sobel's operator, and lay foam along them. Every step can be
//! switched off, and every picture on the way shown full screen.

use common::chapter::{sampler_entry, texture_entry, uniform_entry};
use common::{Drawn, Gpu, PassCount, PassTimer, Reloadable, ShaderError, fullscreen, shader, wgpu};
use textures::mipmaps::{Averaging, MipMaker, level_count};

/// The pictures' format: sRGB, so they are stored as they are seen and
/// read back as linear colour.
pub const PICTURE_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba8UnormSrgb;

/// How many times a picture of the texture is tiled down the screen when
/// shown full screen: more than once, so that the tile's edges show (they
/// should not), and not a whole number, so that they are not at the
/// screen's own edges.
pub const TILES_SHOWN_DOWN: f32 = 1.5;

/// Which steps run.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Processing {
    /// The sea's shades (on) or a distinct hue per cell (off).
    pub water_colours: bool,
    /// The box blur's radius in texels; 0 switches the blur off.
    pub blur_radius: u32,
    /// Foam along the edges.
    pub edges: bool,
    /// Where foam starts and where it is full, in Sobel's gradient.
    pub foam: (f32, f32),
}

impl Processing {
    /// The sea's shades, blurred, with foam along the edges.
    pub const DEFAULT: Self = Self { water_colours: true, blur_radius: 4, edges: true, foam: (0.04, 0.12) };
}

impl Default for Processing {
    fn default() -> Self {
        Self::DEFAULT
    }
}

/// A picture to show full screen.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Picture {
    /// The coloured cells.
    Colours,
    /// The cells blurred.
    Blurred,
    /// Sobel's edges of the blurred cells.
    Edges,
    /// What the sea is painted with.
    Water,
}

/// `Process` in process.wgsl.
#[repr(C)]
#[derive(Clone, Copy, bytemuck::Pod, bytemuck::Zeroable)]
struct ProcessUniform {
    options: [u32; 4],
    foam: [f32; 4],
}

/// `Show` in process.wgsl.
#[repr(C)]
#[derive(Clone, Copy, bytemuck::Pod, bytemuck::Zeroable)]
struct ShowUniform {
    options: [u32; 4],
    shape: [f32; 4],
}

/// A picture of the chain, with the group that lets a pass read it.
struct Stage {
    texture: wgpu::Texture,
    /// Every mip level, for sampling.
    view: wgpu::TextureView,
    /// Level 0 alone: what a pass draws into and reads.
    level_zero: wgpu::TextureView,
    group: wgpu::BindGroup,
}

// ANCHOR: piece
/// The chain of passes. Inputs: the diagram's id texture and the
/// [`Processing`] settings; output: [`WaterTexture::water`], a tileable
/// sRGB picture with mipmaps, for the sea to repeat.
pub struct WaterTexture {
    uniform: wgpu::Buffer,
    ids_layout: wgpu::BindGroupLayout,
    picture_layout: wgpu::BindGroupLayout,
    /// Colour, blur across, blur down, edges and water, made again when
    /// process.wgsl is saved (hot reload).
    pipelines: Reloadable<[wgpu::RenderPipeline; 5]>,
    ids_group: Option<wgpu::BindGroup>,
    size: u32,
    /// Colours, the two halves of a blur, edges, and the water.
    stages: [Stage; 5],
    /// Which stage the sea's picture was blurred into last.
    blurred: usize,
    mips: MipMaker,
}
// ANCHOR_END: piece

const COLOURS: usize = 0;
const BLUR_A: usize = 1;
const BLUR_B: usize = 2;
const EDGES: usize = 3;
const WATER: usize = 4;

impl WaterTexture {
    pub fn new(gpu: &Gpu, size: u32) -> Result<Self, ShaderError> {
        let device = &gpu.device;
        let ids_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("processing"),
            entries: &[
                uniform_entry(0, wgpu::ShaderStages::FRAGMENT, std::mem::size_of::<ProcessUniform>()),
                texture_entry(1, wgpu::TextureSampleType::Uint),
            ],
        });
        let picture_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("picture"),
            entries: &[texture_entry(0, common::chapter::FILTERABLE)],
        });
        let layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("processing"),
            bind_group_layouts: &[Some(&ids_layout), Some(&picture_layout)],
            immediate_size: 0,
        });
        let uniform = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("processing"),
            size: std::mem::size_of::<ProcessUniform>() as u64,
            usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let pipelines = Reloadable::new(gpu, move |gpu| Self::pipelines(gpu, &layout))?;
        let stages = Self::stages(device, &picture_layout, size);
        Ok(Self {
            uniform,
            ids_layout,
            picture_layout,
            pipelines,
            ids_group: None,
            size,
            stages,
            blurred: COLOURS,
            mips: MipMaker::new(gpu)?,
        })
    }

    fn pipelines(gpu: &Gpu, layout: &wgpu::PipelineLayout) -> Result<[wgpu::RenderPipeline; 5], ShaderError> {
        let module = shader!("voronoi-water/process.wgsl", imports: ["common/fullscreen.wgsl"]).module(gpu)?;
        let pipeline =
            |entry| fullscreen::pipeline(&gpu.device, entry, layout, &module, entry, PICTURE_FORMAT.into(), None);
        gpu.catch_validation(|| {
            [
                pipeline("fs_colour"),
                pipeline("fs_blur_across"),
                pipeline("fs_blur_down"),
                pipeline("fs_edges"),
                pipeline("fs_water"),
            ]
        })
        .map_err(ShaderError)
    }

    fn stages(device: &wgpu::Device, layout: &wgpu::BindGroupLayout, size: u32) -> [Stage; 5] {
        ["colours", "blur (across)", "blur (down)", "edges", "water"].map(|label| {
            // Only the water, which the sea repeats into the distance, needs mipmaps.
            let mip_level_count = if label == "water" { level_count(size, size) } else { 1 };
            let texture = device.create_texture(&wgpu::TextureDescriptor {
                label: Some(label),
                size: wgpu::Extent3d { width: size, height: size, depth_or_array_layers: 1 },
                mip_level_count,
                sample_count: 1,
                dimension: wgpu::TextureDimension::D2,
                format: PICTURE_FORMAT,
                usage: wgpu::TextureUsages::RENDER_ATTACHMENT
                    | wgpu::TextureUsages::TEXTURE_BINDING
                    | wgpu::TextureUsages::COPY_SRC,
                view_formats: &[],
            });
            let view = texture.create_view(&Default::default());
            let level_zero = texture.create_view(&wgpu::TextureViewDescriptor {
                base_mip_level: 0,
                mip_level_count: Some(1),
                ..Default::default()
            });
            let group = device.create_bind_group(&wgpu::BindGroupDescriptor {
                label: Some(label),
                layout,
                entries: &[wgpu::BindGroupEntry {
                    binding: 0,
                    resource: wgpu::BindingResource::TextureView(&level_zero),
                }],
            });
            Stage { texture, view, level_zero, group }
        })
    }

    /// The picture the sea is painted with (all its mip levels).
    pub fn water(&self) -> &wgpu::TextureView {
        &self.stages[WATER].view
    }

    /// The group that reads `picture`, for showing it.
    fn group_of(&self, picture: Picture) -> &wgpu::BindGroup {
        let stage = match picture {
            Picture::Colours => COLOURS,
            Picture::Blurred => self.blurred,
            Picture::Edges => EDGES,
            Picture::Water => WATER,
        };
        &self.stages[stage].group
    }

    // ANCHOR: render
    /// Runs the chain on `ids`, a diagram of `size` × `size` pixels;
    /// returns what each of its passes drew (the water picture's mipmaps,
    /// untimed, counted with it).
    pub fn render(
        &mut self,
        gpu: &Gpu,
        encoder: &mut wgpu::CommandEncoder,
        timer: &PassTimer,
        ids: &wgpu::TextureView,
        size: u32,
        settings: &Processing,
    ) -> Vec<PassCount> {
        let device = &gpu.device;
        if size != self.size {
            self.size = size;
            self.stages = Self::stages(device, &self.picture_layout, size);
        }
        // The id texture may have been made again (a new size): always
        // point the group at this frame's.
        self.ids_group = Some(device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("processing"),
            layout: &self.ids_layout,
            entries: &[
                wgpu::BindGroupEntry { binding: 0, resource: self.uniform.as_entire_binding() },
                wgpu::BindGroupEntry { binding: 1, resource: wgpu::BindingResource::TextureView(ids) },
            ],
        }));
        let uniform = ProcessUniform {
            options: [u32::from(settings.water_colours), settings.blur_radius, u32::from(settings.edges), 0],
            foam: [settings.foam.0, settings.foam.1, 0.0, 0.0],
        };
        gpu.queue.write_buffer(&self.uniform, 0, bytemuck::bytes_of(&uniform));

        let [colour, blur_across, blur_down, edges, water] = self.pipelines.get();
        let mut drawn = vec![self.run(encoder, timer, "colour cells", &colour, None, COLOURS)];
        // Box blur across then down, twice: four passes, timed as one.
        self.blurred = COLOURS;
        if settings.blur_radius > 0 {
            let passes = [(&blur_across, COLOURS, BLUR_A), (&blur_down, BLUR_A, BLUR_B)];
            let mut blur = Drawn::NOTHING;
            for round in 0..2 {
                for (i, (pipeline, from, to)) in passes.iter().enumerate() {
                    let from = if round == 1 && *from == COLOURS { BLUR_B } else { *from };
                    let timing = timer.chain("blur", round * 2 + i, 4);
                    self.run_timed(encoder, timing, pipeline, Some(from), *to);
                    blur += Drawn::FULL_SCREEN;
                }
            }
            drawn.push(PassCount { pass: "blur", drawn: blur });
            self.blurred = BLUR_B;
        }
        drawn.push(self.run(encoder, timer, "edges", &edges, Some(self.blurred), EDGES));
        let mut water = self.run(encoder, timer, "water", &water, Some(self.blurred), WATER);
        water.drawn += self.mips.generate(device, encoder, &self.stages[WATER].texture, Averaging::Colour);
        drawn.push(water);
        drawn
    }
    // ANCHOR_END: render

    fn run(
        &self,
        encoder: &mut wgpu::CommandEncoder,
        timer: &PassTimer,
        label: &'static str,
        pipeline: &wgpu::RenderPipeline,
        from: Option<usize>,
        to: usize,
    ) -> PassCount {
        self.run_timed(encoder, timer.pass(label), pipeline, from, to);
        PassCount { pass: label, drawn: Drawn::FULL_SCREEN }
    }

    fn run_timed(
        &self,
        encoder: &mut wgpu::CommandEncoder,
        timestamp_writes: Option<wgpu::RenderPassTimestampWrites<'_>>,
        pipeline: &wgpu::RenderPipeline,
        from: Option<usize>,
        to: usize,
    ) {
        let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: Some("water texture"),
            color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                view: &self.stages[to].level_zero,
                depth_slice: None,
                resolve_target: None,
                ops: wgpu::Operations { load: wgpu::LoadOp::Clear(wgpu::Color::BLACK), store: wgpu::StoreOp::Store },
            })],
            timestamp_writes,
            ..Default::default()
        });
        pass.set_pipeline(pipeline);
        pass.set_bind_group(0, self.ids_group.as_ref(), &[]);
        // Passes that read no picture still need group 1 bound: any will do.
        pass.set_bind_group(1, &self.stages[from.unwrap_or(EDGES)].group, &[]);
        pass.draw(0..3, 0..1);
    }
}

// ANCHOR: show
/// Shows a picture of the chain, or the id buffer, over a whole target.
pub struct Show {
    uniform: wgpu::Buffer,
    group: wgpu::BindGroup,
    /// A picture and the cells, made again when process.wgsl is saved (hot reload).
    pipelines: Reloadable<(wgpu::RenderPipeline, wgpu::RenderPipeline)>,
    format: wgpu::TextureFormat,
}
// ANCHOR_END: show

impl Show {
    pub fn new(gpu: &Gpu, water: &WaterTexture, format: wgpu::TextureFormat) -> Result<Self, ShaderError> {
        let device = &gpu.device;
        let show_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("show"),
            entries: &[
                uniform_entry(0, wgpu::ShaderStages::FRAGMENT, std::mem::size_of::<ShowUniform>()),
                sampler_entry(1),
            ],
        });
        let layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("show"),
            bind_group_layouts: &[Some(&water.ids_layout), Some(&water.picture_layout), Some(&show_layout)],
            immediate_size: 0,
        });
        let uniform = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("show"),
            size: std::mem::size_of::<ShowUniform>() as u64,
            usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        // Repeats, so a tiled picture shows its seams if it has any;
        // nearest, so each texel shows as it is.
        let sampler = device.create_sampler(&wgpu::SamplerDescriptor {
            label: Some("show"),
            address_mode_u: wgpu::AddressMode::Repeat,
            address_mode_v: wgpu::AddressMode::Repeat,
            ..Default::default()
        });
        let group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("show"),
            layout: &show_layout,
            entries: &[
                wgpu::BindGroupEntry { binding: 0, resource: uniform.as_entire_binding() },
                wgpu::BindGroupEntry { binding: 1, resource: wgpu::BindingResource::Sampler(&sampler) },
            ],
        });
        let pipelines = Reloadable::new(gpu, move |gpu| Self::pipelines(gpu, &layout, format))?;
        Ok(Self { uniform, group, pipelines, format })
    }

    fn pipelines(
        gpu: &Gpu,
        layout: &wgpu::PipelineLayout,
        format: wgpu::TextureFormat,
    ) -> Result<(wgpu::RenderPipeline, wgpu::RenderPipeline), ShaderError> {
        let module = shader!("voronoi-water/process.wgsl", imports: ["common/fullscreen.wgsl"]).module(gpu)?;
        let pipeline = |entry| fullscreen::pipeline(&gpu.device, entry, layout, &module, entry, format.into(), None);
        gpu.catch_validation(|| (pipeline("fs_show"), pipeline("fs_show_cells"))).map_err(ShaderError)
    }

    /// Draws `picture` over `target`, tiled at square texels, `tiles` down
    /// the target ([`TILES_SHOWN_DOWN`] shows where the tile meets itself).
    pub fn picture(
        &self,
        gpu: &Gpu,
        frame: &mut common::Frame,
        water: &WaterTexture,
        picture: Picture,
        aspect: f32,
        tiles: f32,
    ) {
        self.write(gpu, true, aspect, tiles);
        let mut pass = fullscreen::pass(frame.encoder, frame.timer, "show picture", frame.target, None);
        pass.set_pipeline(&self.pipelines.get().0);
        pass.set_bind_group(0, water.ids_group.as_ref(), &[]);
        pass.set_bind_group(1, water.group_of(picture), &[]);
        pass.set_bind_group(2, &self.group, &[]);
        pass.draw(0..3, 0..1);
        frame.drawn.add("show picture", Drawn::FULL_SCREEN);
    }

    /// Draws the id buffer `ids` (the target's size) as the `cells` view's
    /// exact colours.
    pub fn cells(&self, gpu: &Gpu, frame: &mut common::Frame, water: &WaterTexture, ids: &wgpu::TextureView) {
        self.write(gpu, false, 1.0, 1.0);
        let ids_group = gpu.device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("cells"),
            layout: &water.ids_layout,
            entries: &[
                wgpu::BindGroupEntry { binding: 0, resource: water.uniform.as_entire_binding() },
                wgpu::BindGroupEntry { binding: 1, resource: wgpu::BindingResource::TextureView(ids) },
            ],
        });
        let mut pass = fullscreen::pass(frame.encoder, frame.timer, "show cells", frame.target, None);
        pass.set_pipeline(&self.pipelines.get().1);
        pass.set_bind_group(0, &ids_group, &[]);
        pass.set_bind_group(1, &water.stages[EDGES].group, &[]);
        pass.set_bind_group(2, &self.group, &[]);
        pass.draw(0..3, 0..1);
        frame.drawn.add("show cells", Drawn::FULL_SCREEN);
    }

    fn write(&self, gpu: &Gpu, tiled: bool, aspect: f32, tiles: f32) {
        let uniform = ShowUniform {
            options: [u32::from(self.format.is_srgb()), u32::from(tiled), 0, 0],
            shape: [aspect, tiles, 0.0, 0.0],
        };
        gpu.queue.write_buffer(&self.uniform, 0, bytemuck::bytes_of(&uniform));
    }
}
