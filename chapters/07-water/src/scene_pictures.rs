//! The lake's scene as pictures: chapter 05's plain and chapter 06's sky,
//! composed and drawn from any camera, keeping only what a clip plane
//! keeps, into one of the water's pictures or into the frame. A frame takes
//! three (the reflection, the refraction and the main picture), each
//! through its own `Eye`, so that all three are recorded before one submit.

use common::book_figures::thousands;
use common::chapter::scene_pass;
use common::glam::Vec4;
use common::{Camera, Drawn, Gpu, PassTimer, SceneTargets, wgpu};
use instancing::{MarsPlain, PlainViewpoint, RocksDrawn, Setup};
use skybox::{Sky, SkyViewpoint, sun_at};
use terrain::SKY;

/// Which of the frame's pictures an `Eye` draws.
pub const REFLECTION: usize = 0;
pub const REFRACTION: usize = 1;
pub const MAIN: usize = 2;

/// The uniforms for drawing the plain and the sky from one camera. The
/// frame draws three pictures, each from its own camera, so it keeps three
/// of these, and all three pictures are recorded before one submit.
pub struct Eye {
    pub plain: PlainViewpoint,
    pub sky: SkyViewpoint,
    /// What the plain drew in this eye's last picture, where it was taken
    /// in the last frame: counted on the CPU, or read back late from the GPU.
    pub drawn: Option<Option<RocksDrawn>>,
}

/// Where `take_picture` draws: one of the water's pictures (its colour
/// and its depth, one sample a pixel: the water reads that depth), or the
/// frame, through the scene's samples.
pub enum DrawnInto<'a> {
    Picture(&'a wgpu::TextureView, &'a wgpu::TextureView),
    Frame(&'a SceneTargets, &'a wgpu::TextureView),
}

impl Eye {
    /// An eye on `plain` and `sky` for a picture of `samples` samples a pixel.
    pub fn new(plain: &MarsPlain, sky: &Sky, device: &wgpu::Device, samples: u32) -> Self {
        Self { plain: plain.viewpoint(device, samples), sky: sky.viewpoint(device, samples), drawn: None }
    }

    // ANCHOR: picture
    /// Records the plain and the sky, seen from `camera` through this eye,
    /// into `into`, keeping only what `clip` keeps, with `rocks`. Each
    /// picture has its own eye, so its uniforms are not overwritten by the
    /// next picture's before the one submit at the end of the frame.
    #[allow(clippy::too_many_arguments)]
    pub fn take_picture(
        &mut self,
        gpu: &Gpu,
        encoder: &mut wgpu::CommandEncoder,
        timer: &PassTimer,
        (plain, sky): (&MarsPlain, &Sky),
        (label, into): (&'static str, DrawnInto<'_>),
        (camera, clip): (&Camera, Vec4),
        phase: f32,
        rocks: Setup,
    ) -> Drawn {
        // The picture's own height: the half-size reflection and refraction
        // see each rock half as many pixels across, and grade it so.
        let height = match into {
            DrawnInto::Picture(colour, _) | DrawnInto::Frame(_, colour) => colour.texture().height(),
        };
        let detail = rocks.detail(height);
        plain.aim(gpu, &mut self.plain, camera, detail, sun_at(phase), clip);
        sky.aim(&gpu.queue, &self.sky, camera, phase);
        // The rocks' compute pass, with this picture's clip plane: rocks
        // wholly on the cut side of the water are never drawn.
        plain.cull(gpu, encoder, timer, &mut self.plain, rocks);
        let mut pass = match into {
            DrawnInto::Picture(colour, depth) => scene_pass(encoder, timer, label, colour, SKY, depth),
            DrawnInto::Frame(scene, frame) => scene.pass(encoder, timer, label, frame, Some(SKY)),
        };
        let calls = plain.draw(&mut pass, &self.plain, rocks);
        self.drawn = Some(calls.rocks_drawn);
        calls.drawn() + sky.draw(&mut pass, &self.sky)
    }
    // ANCHOR_END: picture
}

/// "rocks drawn: reflection 1,200 (5,000 triangles), …", for each of the
/// frame's pictures that was drawn and counted.
pub fn rocks_per_picture(drawn: [Option<RocksDrawn>; 3]) -> String {
    let names = [(REFLECTION, "reflection"), (REFRACTION, "refraction"), (MAIN, "plain and sky")];
    let pictures: Vec<String> = (names.iter())
        .filter_map(|&(eye, name)| {
            let drawn = drawn[eye]?;
            Some(format!("{name} {} ({} triangles)", thousands(drawn.rocks.into()), thousands(drawn.triangles as f64)))
        })
        .collect();
    format!("rocks drawn: {}", if pictures.is_empty() { "counting…".to_string() } else { pictures.join(", ") })
}
