//! Rendering with no window: into an offscreen texture, read back to the
//! CPU as an image. Screenshots, snapshots and benches all go through here.

// `std::time::Instant` panics in the browser; this one reads `performance.now()` there.
use web_time::Instant;

use anyhow::{Context as _, bail};

use crate::chapter::{About, FlagValues, Runnable};
use crate::fingerprint::Fingerprint;
use crate::memory::{Growth, MemoryUse};
use crate::{Antialiasing, CameraPlace, Chapter, DrawCounts, Frame, Gpu, PassCount, PassTimer, Stats, Target, View};

/// Offscreen pictures are 8-bit RGBA with sRGB encoding, like a PNG.
pub const OFFSCREEN_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba8UnormSrgb;

/// What to render: size, scene time, view, and where to look from.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RenderRequest {
    pub width: u32,
    pub height: u32,
    pub time: f32,
    pub view: usize,
    /// `--camera`: a place that replaces the view's camera; `None` keeps it.
    pub camera: Option<CameraPlace>,
    /// `--antialiasing`: how the scene's edges are smoothed.
    pub antialiasing: Antialiasing,
}

impl RenderRequest {
    /// The offscreen target for this request: its size, and the samples a
    /// pixel its view is drawn with (its own, or `antialiasing`'s).
    pub fn target<C: Chapter>(&self) -> Target {
        self.target_in(C::VIEWS)
    }

    /// [`RenderRequest::target`] for a chapter with `views`.
    pub fn target_in(&self, views: &[View]) -> Target {
        let samples = smoothing(views, self.view, self.antialiasing).samples();
        Target { format: OFFSCREEN_FORMAT, width: self.width, height: self.height, samples }
    }
}

/// A texture to render into instead of a window.
pub struct Offscreen {
    pub texture: wgpu::Texture,
    pub view: wgpu::TextureView,
}

impl Offscreen {
    pub fn new(device: &wgpu::Device, target: Target) -> Self {
        let texture = device.create_texture(&wgpu::TextureDescriptor {
            label: Some("offscreen target"),
            size: wgpu::Extent3d { width: target.width, height: target.height, depth_or_array_layers: 1 },
            mip_level_count: 1,
            sample_count: 1,
            dimension: wgpu::TextureDimension::D2,
            format: target.format,
            usage: wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::COPY_SRC,
            view_formats: &[],
        });
        let view = texture.create_view(&Default::default());
        Self { texture, view }
    }
}

// ANCHOR: readback
/// Copies a texture's bytes to the CPU, rows unpadded, `bytes_per_texel`
/// bytes a texel (depth textures: the depth aspect).
pub fn read_bytes(gpu: &Gpu, texture: &wgpu::Texture, bytes_per_texel: u32) -> anyhow::Result<Vec<u8>> {
    read_level_bytes(gpu, texture, 0, bytes_per_texel)
}

/// [`read_bytes`] for one mip level (`level` 0 is the full-size picture).
///
/// GPUs copy textures to buffers in rows padded to 256 bytes
/// (`COPY_BYTES_PER_ROW_ALIGNMENT`), so a 37-pixel-wide RGBA8 image arrives
/// as rows of 256 bytes, of which 148 are pixels. The padding is cut here.
pub fn read_level_bytes(
    gpu: &Gpu,
    texture: &wgpu::Texture,
    level: u32,
    bytes_per_texel: u32,
) -> anyhow::Result<Vec<u8>> {
    let (width, height) = ((texture.width() >> level).max(1), (texture.height() >> level).max(1));
    let row_bytes = bytes_per_texel * width;
    let padded_row_bytes = row_bytes.next_multiple_of(wgpu::COPY_BYTES_PER_ROW_ALIGNMENT);
    let buffer = gpu.device.create_buffer(&wgpu::BufferDescriptor {
        label: Some("readback"),
        size: u64::from(padded_row_bytes) * u64::from(height),
        usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
        mapped_at_creation: false,
    });
    let aspect = if texture.format().is_depth_stencil_format() {
        wgpu::TextureAspect::DepthOnly
    } else {
        wgpu::TextureAspect::All
    };
    let mut encoder = gpu.device.create_command_encoder(&Default::default());
    encoder.copy_texture_to_buffer(
        wgpu::TexelCopyTextureInfo { texture, mip_level: level, origin: wgpu::Origin3d::ZERO, aspect },
        wgpu::TexelCopyBufferInfo {
            buffer: &buffer,
            layout: wgpu::TexelCopyBufferLayout {
                offset: 0,
                bytes_per_row: Some(padded_row_bytes),
                rows_per_image: Some(height),
            },
        },
        wgpu::Extent3d { width, height, depth_or_array_layers: 1 },
    );
    gpu.queue.submit([encoder.finish()]);
    let slice = buffer.slice(..);
    slice.map_async(wgpu::MapMode::Read, |_| {});
    gpu.device.poll(wgpu::PollType::wait_indefinitely()).context("waiting for the readback")?;
    let padded = slice.get_mapped_range().context("mapping the readback buffer")?;
    let mut bytes = Vec::with_capacity((row_bytes * height) as usize);
    for row in padded.chunks_exact(padded_row_bytes as usize) {
        bytes.extend_from_slice(&row[..row_bytes as usize]);
    }
    Ok(bytes)
}

/// Copies a floating-point colour texture (`Rgba16Float`, `Rgba32Float`,
/// `Rg11b10Ufloat`) or a `Depth32Float` texture to the CPU as RGBA floats
/// (depth in the first channel), row by row. For tests that check numbers,
/// not pictures.
pub fn read_floats(gpu: &Gpu, texture: &wgpu::Texture) -> anyhow::Result<Vec<[f32; 4]>> {
    use wgpu::TextureFormat as F;
    let format = texture.format();
    let size = match format {
        F::Rgba16Float => 8,
        F::Rgba32Float => 16,
        F::Rg11b10Ufloat | F::Depth32Float | F::R32Float => 4,
        other => bail!("cannot read back {other:?} textures as floats"),
    };
    let bytes = read_bytes(gpu, texture, size)?;
    Ok(bytes
        .chunks_exact(size as usize)
        .map(|texel| match format {
            F::Rgba16Float => {
                std::array::from_fn(|i| half::f16::from_le_bytes([texel[2 * i], texel[2 * i + 1]]).to_f32())
            }
            F::Rgba32Float => std::array::from_fn(|i| f32::from_le_bytes(texel[4 * i..4 * i + 4].try_into().unwrap())),
            F::Rg11b10Ufloat => {
                let bits = u32::from_le_bytes(texel.try_into().unwrap());
                [small_float(bits & 0x7ff, 6), small_float((bits >> 11) & 0x7ff, 6), small_float(bits >> 22, 5), 1.0]
            }
            _ => [f32::from_le_bytes(texel.try_into().unwrap()), 0.0, 0.0, 1.0],
        })
        .collect())
}

/// An unsigned float of 5 exponent bits and `mantissa` bits (the 11- and
/// 10-bit channels of `Rg11b10Ufloat`), bias 15 like half floats.
fn small_float(bits: u32, mantissa: u32) -> f32 {
    let exponent = (bits >> mantissa) as i32;
    let fraction = (bits & ((1 << mantissa) - 1)) as f32 / (1 << mantissa) as f32;
    match exponent {
        0 => fraction * 2f32.powi(-14),
        31 => f32::INFINITY,
        e => (1.0 + fraction) * 2f32.powi(e - 15),
    }
}

/// Copies an RGBA8 or BGRA8 texture to the CPU as an RGBA image.
pub fn read_texture(gpu: &Gpu, texture: &wgpu::Texture) -> anyhow::Result<image::RgbaImage> {
    use wgpu::TextureFormat as F;
    let bgra = match texture.format() {
        F::Rgba8Unorm | F::Rgba8UnormSrgb => false,
        F::Bgra8Unorm | F::Bgra8UnormSrgb => true,
        other => bail!("cannot read back {other:?} textures"),
    };
    let mut pixels = read_bytes(gpu, texture, 4)?;
    if bgra {
        pixels.chunks_exact_mut(4).for_each(|p| p.swap(0, 2));
    }
    image::RgbaImage::from_raw(texture.width(), texture.height(), pixels).context("readback size mismatch")
}
// ANCHOR_END: readback

/// How view `view` of a chapter with `views` smooths edges where the run
/// asks for `asked` (its own setting, if it has one); `asked` for an index
/// past the views.
fn smoothing(views: &[View], view: usize, asked: Antialiasing) -> Antialiasing {
    views.get(view).map_or(asked, |v| v.smoothing(asked))
}

/// Records and submits one frame of `chapter` into `target`, its edges
/// smoothed as the view says or else as `asked`; returns what each pass
/// drew, as the chapter counted it.
pub fn draw_frame(
    gpu: &Gpu,
    chapter: &mut dyn Runnable,
    target: &wgpu::TextureView,
    (time, view): (f32, usize),
    asked: Antialiasing,
    timer: &PassTimer,
) -> Vec<PassCount> {
    let about = chapter.about();
    let mut encoder = gpu.device.create_command_encoder(&wgpu::CommandEncoderDescriptor { label: Some(about.name) });
    let drawn = DrawCounts::new();
    let antialiasing = smoothing(about.views, view, asked);
    chapter.render(gpu, &mut Frame { encoder: &mut encoder, target, time, view, timer, drawn: &drawn, antialiasing });
    timer.resolve(&mut encoder);
    gpu.queue.submit([encoder.finish()]);
    drawn.take()
}

/// Renders one picture of an existing chapter instance at its target size.
pub fn capture(
    gpu: &Gpu,
    chapter: &mut dyn Runnable,
    target: Target,
    (time, view): (f32, usize),
    asked: Antialiasing,
) -> anyhow::Result<image::RgbaImage> {
    let offscreen = Offscreen::new(&gpu.device, target);
    draw_frame(gpu, chapter, &offscreen.view, (time, view), asked, &PassTimer::off());
    read_texture(gpu, &offscreen.texture)
}

/// Makes chapter `C` for `request`'s size with `flags`, and starts it as
/// every runner does ([`crate::chapter::start`]: the view, the camera).
pub fn started<C: Chapter>(gpu: &Gpu, request: &RenderRequest, flags: &FlagValues) -> anyhow::Result<C> {
    let target = request.target::<C>();
    let mut chapter = crate::chapter::create::<C>(gpu, target, flags)?;
    crate::chapter::start(&mut chapter, request.view, request.camera)?;
    Ok(chapter)
}

/// [`started`], whatever the chapter's type.
pub fn started_of(
    about: &About,
    gpu: &Gpu,
    request: &RenderRequest,
    flags: &FlagValues,
) -> anyhow::Result<Box<dyn Runnable>> {
    let mut chapter = about.create(gpu, request.target_in(about.views), flags)?;
    crate::chapter::start(chapter.as_mut(), request.view, request.camera)?;
    Ok(chapter)
}

/// Creates the chapter offscreen and renders one picture.
pub fn render_image<C: Chapter>(gpu: &Gpu, request: &RenderRequest) -> anyhow::Result<image::RgbaImage> {
    render_image_with::<C>(gpu, request, &FlagValues::default())
}

/// [`render_image`] with values for the chapter's own flags.
pub fn render_image_with<C: Chapter>(
    gpu: &Gpu,
    request: &RenderRequest,
    flags: &FlagValues,
) -> anyhow::Result<image::RgbaImage> {
    render_image_of(&About::of::<C>(), gpu, request, flags)
}

/// [`render_image_with`], whatever the chapter's type.
pub fn render_image_of(
    about: &About,
    gpu: &Gpu,
    request: &RenderRequest,
    flags: &FlagValues,
) -> anyhow::Result<image::RgbaImage> {
    let mut chapter = started_of(about, gpu, request, flags)?;
    let target = request.target_in(about.views);
    capture(gpu, chapter.as_mut(), target, (request.time, request.view), request.antialiasing)
}

/// Frame-time figures for one chapter view.
#[derive(Clone, Debug)]
pub struct BenchReport {
    pub view: &'static str,
    pub width: u32,
    pub height: u32,
    /// Wall time from recording the frame to the GPU finishing it.
    pub frame: Stats,
    /// GPU time per timed pass, when the adapter has timestamp queries.
    pub passes: Vec<(&'static str, Stats)>,
    /// CPU time of the work timed with `PassTimer::cpu`.
    pub cpu: Vec<(&'static str, Stats)>,
    /// Time to create the chapter (`Chapter::new`), in milliseconds.
    pub setup_ms: f64,
    /// The chapter's own figures ([`Chapter::stats`]).
    pub stats: String,
    /// What each pass drew in the last measured frame, as the chapter
    /// counted it (empty for a chapter that counts nothing).
    pub drawn: Vec<PassCount>,
    /// Memory at the end of the first and second thirds of the measured
    /// frames and after the last.
    pub memory: Growth,
}

/// Renders `frames` frames offscreen (after a few warm-up frames) and
/// measures each. The scene time stays fixed so every frame does the same work.
pub fn bench<C: Chapter>(
    gpu: &Gpu,
    request: &RenderRequest,
    frames: u32,
    flags: &FlagValues,
) -> anyhow::Result<BenchReport> {
    bench_of(&About::of::<C>(), gpu, request, frames, flags)
}

/// [`bench`], whatever the chapter's type.
pub fn bench_of(
    about: &About,
    gpu: &Gpu,
    request: &RenderRequest,
    frames: u32,
    flags: &FlagValues,
) -> anyhow::Result<BenchReport> {
    let target = request.target_in(about.views);
    let setup = Instant::now();
    let mut chapter = about.create(gpu, target, flags)?;
    let setup_ms = setup.elapsed().as_secs_f64() * 1e3;
    crate::chapter::start(chapter.as_mut(), request.view, request.camera)?;
    let offscreen = Offscreen::new(&gpu.device, target);
    let timer = PassTimer::new(&gpu.device, 16);

    let mut wall = Vec::new();
    let mut passes: Vec<(&'static str, Vec<f64>)> = Vec::new();
    let mut cpu: Vec<(&'static str, Vec<f64>)> = Vec::new();
    // Memory is read before frames `reading_at`: a third of the measured
    // frames apart, from the end of the first third, since the first frames
    // still settle (allocator arenas, driver caches).
    let third = frames / 3;
    let reading_at = [3 + third, 3 + 2 * third, 3 + 3 * third];
    let mut memory = [MemoryUse::default(); 3];
    let mut drawn = Vec::new();
    for i in 0..frames + 3 {
        if let Some(k) = reading_at.iter().position(|&at| at == i) {
            memory[k] = MemoryUse::now(&gpu.device);
        }
        let start = Instant::now();
        drawn = draw_frame(
            gpu,
            chapter.as_mut(),
            &offscreen.view,
            (request.time, request.view),
            request.antialiasing,
            &timer,
        );
        gpu.device.poll(wgpu::PollType::wait_indefinitely()).context("waiting for the frame")?;
        let elapsed = start.elapsed().as_secs_f64() * 1e3;
        let timed = timer.read(gpu);
        let cpu_timed = timer.take_cpu();
        if i < 3 {
            continue; // warm-up: pipeline caches, first-touch allocations
        }
        wall.push(elapsed);
        for (series, samples) in [(&mut passes, timed), (&mut cpu, cpu_timed)] {
            for (label, ms) in samples {
                match series.iter_mut().find(|(l, _)| *l == label) {
                    Some((_, samples)) => samples.push(ms),
                    None => series.push((label, vec![ms])),
                }
            }
        }
    }
    if reading_at[2] == frames + 3 {
        memory[2] = MemoryUse::now(&gpu.device);
    }
    let memory = Growth { readings: memory, frames: [u64::from(third); 2] };
    let summarise = |series: Vec<(&'static str, Vec<f64>)>| {
        series.into_iter().filter_map(|(l, s)| Some((l, Stats::of(&s)?))).collect()
    };
    Ok(BenchReport {
        view: about.views[request.view].name,
        width: request.width,
        height: request.height,
        frame: Stats::of(&wall).context("no frames measured")?,
        passes: summarise(passes),
        cpu: summarise(cpu),
        setup_ms,
        stats: chapter.stats(gpu),
        drawn,
        memory,
    })
}

/// The fingerprint of `view`'s frame ([`crate::fingerprint`]): a snapshot
/// view drawn once by a fresh chapter at the snapshot size and time, as
/// the snapshot test draws it, and its passes counted; a bench view's
/// from its settings and samples alone.
pub fn fingerprint<C: Chapter>(gpu: &Gpu, view: usize, flags: &FlagValues) -> anyhow::Result<Fingerprint> {
    fingerprint_of(&About::of::<C>(), gpu, view, flags)
}

/// [`fingerprint`], whatever the chapter's type.
pub fn fingerprint_of(about: &About, gpu: &Gpu, view: usize, flags: &FlagValues) -> anyhow::Result<Fingerprint> {
    let shown = &about.views[view];
    let samples = shown.samples(Antialiasing::default());
    let settings = (about.view_settings)(view);
    if !shown.snapshot {
        return Ok(Fingerprint::new(settings, samples, &[]));
    }
    let (width, height) = crate::fingerprint::SIZE;
    let target = Target { format: OFFSCREEN_FORMAT, width, height, samples };
    let mut chapter = about.create(gpu, target, flags)?;
    crate::chapter::start(chapter.as_mut(), view, None)?;
    let offscreen = Offscreen::new(&gpu.device, target);
    let timer = PassTimer::off();
    let counted = draw_frame(
        gpu,
        chapter.as_mut(),
        &offscreen.view,
        (about.snapshot_time, view),
        Antialiasing::default(),
        &timer,
    );
    gpu.device.poll(wgpu::PollType::wait_indefinitely()).context("waiting for the frame")?;
    Ok(Fingerprint::new(settings, samples, &counted))
}

// ANCHOR: edit_to_frame
/// How long a shader edit takes to reach the picture: the chapter's main
/// file (the one its shader panel opens on) is edited `edits` times
/// through the panel's own entry points, each built at once (Ctrl+Enter),
/// and each time from the key to the GPU finishing the next frame is
/// measured. The edit appends a comment: the picture stays the same, and
/// the whole path runs (compose, validate, create the pipelines).
pub fn edit_to_frame<C: Chapter>(
    gpu: &Gpu,
    request: &RenderRequest,
    edits: usize,
    flags: &FlagValues,
) -> anyhow::Result<(&'static str, Stats)> {
    edit_to_frame_of(&About::of::<C>(), gpu, request, edits, flags)
}

/// [`edit_to_frame`], whatever the chapter's type.
pub fn edit_to_frame_of(
    about: &About,
    gpu: &Gpu,
    request: &RenderRequest,
    edits: usize,
    flags: &FlagValues,
) -> anyhow::Result<(&'static str, Stats)> {
    let target = request.target_in(about.views);
    let mut chapter = started_of(about, gpu, request, flags)?;
    let offscreen = Offscreen::new(&gpu.device, target);
    let file = crate::editor::main_file_of(about, gpu).context("the chapter builds no pipeline from WGSL")?;
    let mut editor = crate::editor::ShaderEditor::new();
    editor.open_on(gpu, file, None)?;
    let original = editor.text().unwrap_or_default().to_string();
    let mut samples = Vec::new();
    for i in 0..edits {
        editor.type_text(&format!("{original}\n// edit {i}\n"));
        editor.build_now();
        let start = Instant::now();
        editor.update(gpu);
        if let Some(error) = editor.error() {
            bail!("editing {file} failed: {}", error.message);
        }
        draw_frame(
            gpu,
            chapter.as_mut(),
            &offscreen.view,
            (request.time, request.view),
            request.antialiasing,
            &PassTimer::off(),
        );
        gpu.device.poll(wgpu::PollType::wait_indefinitely()).context("waiting for the frame")?;
        samples.push(start.elapsed().as_secs_f64() * 1e3);
    }
    editor.revert(gpu);
    Ok((file, Stats::of(&samples).context("no edits measured")?))
}
// ANCHOR_END: edit_to_frame
