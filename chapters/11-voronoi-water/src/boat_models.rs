//! The boat, its sail and its sailor on the GPU: three models read by
//! chapter 09's loader with their materials, placed by one instance (the
//! boat's model matrix, which rides the waves), and drawn as one draw list
//! by chapter 10's shadowed renderer, into the shadow map and the picture
//! alike. The sail is bent by the wind every frame (`sail`).

use std::path::Path;

use common::{Gpu, anyhow, wgpu};
use textures::materials::{Materials, Uploader};
use textures::mesh::{GpuModel, ModelInstance};
use textures::mipmaps::MipMaker;
use textures::{Draw, DrawList, obj, upload_model};

use crate::boat::Pose;
use crate::sail::{self, Rig};

/// The boat and its textures: the only files of chapter 09's this chapter
/// embeds, so that the browser downloads no more than it draws.
const BOAT_FILES: &[(&str, &[u8])] = textures::builtin![
    "models/boat/boat.obj",
    "models/boat/boat.mtl",
    "textures/metal/albedo.png",
    "textures/metal/normal.png",
];

/// A file the chapter carries (the boat's, or the sail's and the
/// sailor's), by its path under `assets/`.
fn read_builtin(path: &Path) -> Result<Vec<u8>, common::files::ReadError> {
    textures::builtin::find(BOAT_FILES, path).or_else(|_| sail::read_builtin(path))
}

/// The three models and the instance that places them.
pub struct BoatModels {
    pub materials: Materials,
    boat: GpuModel,
    /// The sail as made (flat) and the sailor, on the CPU: the sail is
    /// bent from it every frame.
    pub rig: Rig,
    sail: GpuModel,
    sailor: GpuModel,
    instance: wgpu::Buffer,
}

impl BoatModels {
    /// Loads the boat, the sail and the sailor with their materials and
    /// uploads them (a missing file is an error naming it).
    pub fn load(gpu: &Gpu) -> anyhow::Result<Self> {
        // The boat: chapter 09's model, materials and loader.
        let loaded = obj::load(Path::new("models/boat/boat.obj"), &read_builtin)?;
        // Its sail and sailor: two more models, through the same loader.
        let rig = sail::load(&sail::read_builtin)?;
        for warning in loaded.warnings.iter().chain(&rig.warnings) {
            eprintln!("warning: {warning}");
        }
        let mut mips = MipMaker::new(gpu)?;
        let mut up = Uploader::new(gpu, &mut mips, &read_builtin);
        let mut materials = Materials::new(&mut up);
        let boat = upload_model(&mut up, &mut materials, &loaded.model, "boat");
        let sail = upload_model(&mut up, &mut materials, &rig.sail, "sail");
        let sailor = upload_model(&mut up, &mut materials, &rig.sailor, "sailor");
        up.finish();
        let instance = gpu.device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("boat"),
            size: std::mem::size_of::<ModelInstance>() as u64,
            usage: wgpu::BufferUsages::VERTEX | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        Ok(Self { materials, boat, rig, sail, sailor, instance })
    }

    // ANCHOR: rig_draw
    /// This frame's boat: the sail filled by the wind across it; the boat,
    /// the sail and the sailor all placed by the boat's one instance, its
    /// model matrix.
    pub fn place(&self, gpu: &Gpu, pose: &Pose) {
        let across = sail::wind_across(pose.helm.heading, sail::wind());
        gpu.queue.write_buffer(&self.sail.vertices, 0, bytemuck::cast_slice(&self.rig.bent_sail(across)));
        gpu.queue.write_buffer(&self.instance, 0, bytemuck::bytes_of(&ModelInstance::new(pose.model(), 0.0)));
    }

    /// The three models as one draw list, for the shadow pass and the
    /// scene pass alike.
    pub fn draw_list(&self) -> DrawList<'_> {
        DrawList {
            materials: &self.materials,
            instances: &self.instance,
            draws: [&self.boat, &self.sail, &self.sailor]
                .into_iter()
                .map(|model| Draw { model, instances: 0..1 })
                .collect(),
        }
    }
    // ANCHOR_END: rig_draw
}
