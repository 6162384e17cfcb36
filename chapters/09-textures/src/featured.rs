//! The featured model on the stage: the car, or whatever OBJ a learner
//! brings with `--model`. Loading it reads the file as the loader reads
//! any model (`obj.rs`), refuses one this GPU cannot hold, scales it to
//! fit the stage, and keeps what the overlay's model panel tells: its
//! counts, its materials and where each texture was found, its warnings.

use std::path::Path;

use common::args::UsageError;
use common::glam::Mat4;
use common::{Gpu, anyhow, egui, wgpu};

use crate::materials::{Materials, Uploader};
use crate::mesh::{GpuModel, MaterialDesc, ModelData, TexturedVertex};
use crate::mipmaps::MipMaker;
use crate::obj::{self, LoadedModel, ReadFile};
use crate::scenes;
use crate::textured_renderer::upload_model;

/// The featured model on the stage: the car, or the learner's.
pub struct Featured {
    pub name: String,
    pub model: GpuModel,
    pub placement: Mat4,
    pub triangles: usize,
    pub vertices: usize,
    pub objects: usize,
    /// Its materials: `model.first_material` onwards, this many.
    pub materials: usize,
    /// Whether its vertices carry colours.
    pub vertex_colours: bool,
    /// Whether its MTL gives roughness or metalness (Pr, Pm): a model made
    /// for physically based shading, which the stage then shades with
    /// chapter 08's Cook-Torrance instead of Blinn-Phong.
    pub physical: bool,
    /// The model's own warnings (the chapter's `warnings` hold them too).
    pub warnings: Vec<String>,
    /// Scale applied to fit the stage, and the load time and memory (for
    /// a learner's model).
    pub scale: f32,
    pub load_ms: Option<f64>,
    pub peak_memory: Option<u64>,
}

impl Featured {
    /// The car, featured until a learner's model takes its place: the
    /// car's own buffers again, drawn with the car's materials, which
    /// start at `first_material`.
    pub(crate) fn car(device: &wgpu::Device, car: &LoadedModel, first_material: usize) -> Self {
        let (placement, scale) = scenes::stage_placement(car.model.bounds());
        Self {
            name: "the car (assets/models/car/car.obj)".into(),
            model: GpuModel::upload(device, &car.model, first_material, "featured"),
            placement,
            triangles: car.model.triangle_count(),
            vertices: car.model.vertices.len(),
            objects: car.objects,
            materials: car.model.materials.len(),
            vertex_colours: car.vertex_colours,
            physical: car.model.materials.iter().any(MaterialDesc::is_physical),
            warnings: car.warnings.clone(),
            scale,
            load_ms: None,
            peak_memory: None,
        }
    }

    // ANCHOR: learners_model
    /// The model at `path`, read from the disk with its MTL and textures,
    /// its materials added to `materials`. A file that cannot be read, or
    /// that this GPU cannot hold, is a usage error: one line, exit code 2.
    pub(crate) fn load(gpu: &Gpu, mips: &mut MipMaker, materials: &mut Materials, path: &Path) -> anyhow::Result<Self> {
        let read: ReadFile = &|p: &Path| common::files::read(p);
        let (loaded, load_ms) = common::timing::measure(|| obj::load(path, read));
        let loaded = loaded.map_err(|e| UsageError(format!("--model: {e}")))?;
        check_fits(gpu, path, &loaded.model)?;
        let mut up = Uploader::new(gpu, mips, read);
        let model = upload_model(&mut up, materials, &loaded.model, "model");
        up.finish();
        let (placement, scale) = scenes::stage_placement(loaded.model.bounds());
        let mut warnings = loaded.warnings;
        warnings.append(&mut materials.warnings);
        Ok(Self {
            name: path.display().to_string(),
            model,
            placement,
            triangles: loaded.model.triangle_count(),
            vertices: loaded.model.vertices.len(),
            objects: loaded.objects,
            materials: loaded.model.materials.len(),
            vertex_colours: loaded.vertex_colours,
            physical: loaded.model.materials.iter().any(MaterialDesc::is_physical),
            warnings,
            scale,
            load_ms: Some(load_ms),
            peak_memory: common::memory::peak_process_bytes(),
        })
    }
    // ANCHOR_END: learners_model

    /// The model's facts, as the overlay's model panel gives them.
    pub fn facts(&self) -> String {
        format!(
            "model: {}: {} triangles, {} vertices, {} objects, scaled ×{:.3} to fit{}",
            self.name,
            self.triangles,
            self.vertices,
            self.objects,
            self.scale,
            if self.vertex_colours { "; it has vertex colours" } else { "" },
        ) + if self.physical { "; shaded by Cook-Torrance (its MTL gives Pr, Pm or their maps)" } else { "" }
    }

    /// What the model is made of: counts, materials and where their
    /// textures were found, and what loading it warned about.
    pub(crate) fn panel(&self, ui: &mut egui::Ui, all_materials: &Materials) {
        ui.label(self.facts());
        let first = self.model.first_material;
        let materials = all_materials.list.get(first..first + self.materials).unwrap_or_default();
        egui::CollapsingHeader::new(format!("its {} materials and their textures", materials.len()))
            .id_salt("model materials")
            .show(ui, |ui| {
                for material in materials {
                    let d = &material.desc;
                    ui.label(format!(
                        "{}: colour {:.2} {:.2} {:.2}{}",
                        d.name,
                        d.diffuse.x,
                        d.diffuse.y,
                        d.diffuse.z,
                        if material.maps.is_empty() { ", no textures" } else { "" }
                    ));
                    for (what, source) in &material.maps {
                        ui.small(format!("    {what}: {source}"));
                    }
                }
                for warning in &self.warnings {
                    ui.colored_label(egui::Color32::from_rgb(230, 180, 60), warning);
                }
            });
    }
}

/// Refuses a model whose buffers this GPU cannot hold, before trying to
/// make them (which would end the program).
fn check_fits(gpu: &Gpu, path: &Path, model: &ModelData) -> Result<(), UsageError> {
    let limit = gpu.device.limits().max_buffer_size;
    let vertex_bytes = (model.vertices.len() * std::mem::size_of::<TexturedVertex>()) as u64;
    let index_bytes = (model.indices.len() * 4) as u64;
    if vertex_bytes.max(index_bytes) > limit {
        return Err(UsageError(format!(
            "--model: {}: {} vertices and {} triangles need {} MiB, more than the {} MiB this GPU allows in one buffer",
            path.display(),
            model.vertices.len(),
            model.triangle_count(),
            vertex_bytes.max(index_bytes) >> 20,
            limit >> 20
        )));
    }
    Ok(())
}
