//! Everything the chapter draws, assembled: the built-in models made once
//! per device (the textured city, the stage with its primitives, the lab's
//! floor, the car and the tower), their copies on the GPU, and for each
//! frame the lights, the instances and the draws of the scene the camera
//! is in.

use std::ops::Range;
use std::path::Path;

use common::glam::{Mat4, Quat};
use common::{Gpu, anyhow, wgpu};
use lighting::LightCount;
use lighting::city::{City, Clocks};
use lighting::lights::{Daylight, Light};

use crate::builtin;
use crate::featured::Featured;
use crate::materials::{Materials, Uploader};
use crate::mesh::{GpuModel, ModelData, ModelInstance};
use crate::obj::{self, LoadedModel, ReadFile};
use crate::scenes;
use crate::textured_renderer::upload_model;
use crate::views::Tangents;

/// The CPU side of every built-in model, made once per device and shared
/// by every instance of the chapter (`Gpu::cached`): tangents for a whole
/// city take a while in a debug build.
pub struct BuiltinModels {
    pub city: ModelData,
    pub stage: ModelData,
    pub stage_face_tangents: ModelData,
    pub lab: ModelData,
    pub car: LoadedModel,
    pub tower: LoadedModel,
}

impl BuiltinModels {
    pub(crate) fn load() -> anyhow::Result<Self> {
        let read: ReadFile = &builtin::read;
        let stage = scenes::stage_set();
        Ok(Self {
            city: scenes::textured_city(&City::new()),
            stage_face_tangents: stage.with_face_tangents(),
            stage,
            lab: scenes::lab_floor(),
            car: obj::load(Path::new("models/car/car.obj"), read)?,
            tower: obj::load(Path::new("models/tower/tower.obj"), read)?,
        })
    }
}

/// Everything drawable, on the GPU.
pub(crate) struct Models {
    pub city: GpuModel,
    /// Chapter 08's drones, baked again every frame where they have flown.
    pub drones: GpuModel,
    pub car: GpuModel,
    pub tower: GpuModel,
    pub stage: GpuModel,
    pub stage_face_tangents: GpuModel,
    pub lab: GpuModel,
}

impl Models {
    /// Uploads the built-in models and their materials, in a fixed order
    /// (the city's materials first: the drones draw with them).
    pub(crate) fn upload(
        device: &wgpu::Device,
        up: &mut Uploader,
        materials: &mut Materials,
        builtin: &BuiltinModels,
    ) -> Self {
        let mut model = |data: &ModelData, label| upload_model(up, materials, data, label);
        let city = model(&builtin.city, "city");
        Self {
            drones: GpuModel::upload(device, &ModelData::default(), city.first_material, "drones"),
            car: model(&builtin.car.model, "car"),
            tower: model(&builtin.tower.model, "tower"),
            stage: model(&builtin.stage, "stage"),
            stage_face_tangents: model(&builtin.stage_face_tangents, "stage, face tangents"),
            lab: model(&builtin.lab, "lab"),
            city,
        }
    }

    /// The model a draw names (the featured one is the chapter's, not here).
    pub(crate) fn get<'a>(&'a self, which: Which, featured: &'a Featured) -> &'a GpuModel {
        match which {
            Which::City => &self.city,
            Which::Drones => &self.drones,
            Which::Tower => &self.tower,
            Which::Car => &self.car,
            Which::Featured => &featured.model,
            Which::Stage => &self.stage,
            Which::StageFaceTangents => &self.stage_face_tangents,
            Which::Lab => &self.lab,
        }
    }
}

/// Which model a draw uses.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Which {
    City,
    Drones,
    Tower,
    Car,
    Featured,
    Stage,
    StageFaceTangents,
    Lab,
}

/// One frame of a scene: its lights, every instance (they go into one
/// buffer), and which model draws which range of them.
#[derive(Default)]
pub(crate) struct FrameDraws {
    pub lights: Vec<Light>,
    pub instances: Vec<ModelInstance>,
    pub draws: Vec<(Which, Range<u32>)>,
}

impl FrameDraws {
    /// Draws `which` once for each of `list`.
    fn push(&mut self, which: Which, list: Vec<ModelInstance>) {
        let start = self.instances.len() as u32;
        self.instances.extend(list);
        self.draws.push((which, start..self.instances.len() as u32));
    }
}

/// The city at this moment: lights, and the instances and draws for the
/// textured city, the tower, the car models and the drones.
pub(crate) fn city_draws(
    gpu: &Gpu,
    city: &City,
    clocks: &Clocks,
    drones: &mut GpuModel,
    time: f32,
    day: &Daylight,
) -> FrameDraws {
    let traffic = city.traffic(clocks.cars.time(time), clocks.drones.time(time));
    let lights = lighting::frame_lights(city, &traffic, &[], LightCount::City, day.night);
    drones.update(&gpu.device, &gpu.queue, &scenes::bake(&traffic.drone_parts));
    let mut frame = FrameDraws { lights, ..Default::default() };
    frame.push(Which::City, vec![ModelInstance::new(Mat4::IDENTITY, 1.0)]);
    frame.push(Which::Drones, vec![ModelInstance::new(Mat4::IDENTITY, 1.0)]);
    // The tower's windows light up as night falls.
    frame.push(Which::Tower, vec![ModelInstance::new(scenes::tower_placement(), day.night)]);
    let cars = traffic
        .cars
        .iter()
        .map(|pose| {
            ModelInstance::new(Mat4::from_rotation_translation(Quat::from_rotation_y(pose.heading), pose.position), 1.0)
        })
        .collect();
    frame.push(Which::Car, cars);
    frame
}

/// The stage, with its primitives' tangents as `tangents` says, and the
/// featured model where `placement` puts it; lit by the stage's two lamps.
pub(crate) fn stage_draws(placement: Mat4, tangents: Tangents) -> FrameDraws {
    let set = if tangents == Tangents::PerFace { Which::StageFaceTangents } else { Which::Stage };
    let mut frame = FrameDraws { lights: scenes::stage_lights(), ..Default::default() };
    frame.push(set, vec![ModelInstance::new(Mat4::IDENTITY, 1.0)]);
    frame.push(Which::Featured, vec![ModelInstance::new(placement, 1.0)]);
    frame
}

/// The sampling lab: its floor, and no lights but the sun.
pub(crate) fn lab_draws() -> FrameDraws {
    let mut frame = FrameDraws::default();
    frame.push(Which::Lab, vec![ModelInstance::new(Mat4::IDENTITY, 1.0)]);
    frame
}
