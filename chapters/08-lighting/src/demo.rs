//! The chapter's wiring: `LightingChapter` and `impl Chapter`, which
//! compose the city's meshes, the frame's lights culled into clusters, the
//! sky and the post chain into a frame, apply the views, and draw the
//! overlay's controls. The views are in `views`, the cameras in
//! `camera_presets`, the scene's assembly in `scenery` and `frame_lights`.

use common::{
    Camera, Chapter, FlyController, Frame, Gpu, Input, Preparation, Reloadable, Target, View, anyhow, egui, views_of,
    wgpu, winit::keyboard::KeyCode,
};

use crate::billboard::Billboard;
use crate::camera_presets::{CameraPreset, Riding, aerial_camera};
use crate::city::{City, Clocks, Piece};
use crate::city_meshes::{CityMeshes, Pipelines, build_pipelines};
use crate::city_sky::CitySky;
use crate::clusters::{self, CLUSTERS, ClusterLists};
use crate::countryside::Countryside;
use crate::frame_lights::{LightCount, beacons, frame_lights};
use crate::light_terms::LightTerm;
use crate::lights::{Light, TimeOfDay, daylight};
use crate::lights_per_pixel::lights_per_pixel;
use crate::material_spheres;
use crate::moving_parts::MovingParts;
use crate::post::{HdrTarget, PostChain, PostOutput, PostSettings};
use crate::scene_lights::{Highlight, LoopOptions, MAX_LIGHTS, SceneLights};
use crate::scenery::{MaterialBuffer, Scenery, all_materials, scenery};
use crate::views::{Display, Settings, Shading, VIEW_TABLE};

pub struct LightingChapter {
    pub city: City,
    /// The crown and the sign that move on the city's towers.
    pub moving_parts: MovingParts,
    /// The billboard across the river, and its spot lights.
    pub billboard: Billboard,
    /// The countryside's roads and bridge and the billboard's pieces,
    /// drawn with the city's shapes when the countryside is on.
    countryside_pieces: Vec<Piece>,
    pub settings: Settings,
    pub clocks: Clocks,
    pub camera: Camera,
    pub controller: FlyController,
    /// What the camera rides with (the `follow` and `drone` presets), if anything.
    pub riding: Option<Riding>,
    /// Scene time of the last frame, for pausing and the follow camera.
    last_time: f32,
    beacons: Vec<Light>,
    meshes: CityMeshes,
    scene_lights: SceneLights,
    /// The materials, group 1 of city.wgsl.
    materials: MaterialBuffer,
    sky: CitySky,
    /// Made again when city.wgsl or the lights' module is saved (hot reload).
    pipelines: Reloadable<Pipelines>,
    /// The HDR picture, its bloom and its tone map.
    pub post: PostChain,
    target: Target,
    /// The cluster lists of the last frame, and how many lights it had.
    last_lists: ClusterLists,
    last_light_count: usize,
}

impl Chapter for LightingChapter {
    const NAME: &'static str = env!("CARGO_PKG_NAME");
    // Measured mean FLIP 0.0064; outliers at most 0.1%. Worst 16×16 patch 0.065 (SwiftShader against lavapipe, both with four samples a pixel, 2026-11-28).
    const BROWSER_TOLERANCE: common::Tolerance = common::Tolerance { mean: 0.013, outliers: 0.002, patch: 0.2 };
    const TITLE: &'static str = "08 · Lighting";
    const VIEWS: &'static [View] = &views_of(&VIEW_TABLE);

    fn view_settings(view: usize) -> String {
        common::ViewRow::settings_of(&VIEW_TABLE, view)
    }
    const POST_ANTIALIASING: bool = true;
    const SNAPSHOT_TIME: f32 = 6.0;
    const BENCH_FRAMES: u32 = 5;
    const BENCH_BASELINE: Option<&'static str> = Some("lights-1");
    const MAIN_SHADER: Option<&'static str> = Some("lighting/city.wgsl");
    const KEYS: &'static [(&'static str, &'static str)] = &[
        ("W A S D / arrows", "move (leaves the car you follow)"),
        ("E / Space, Q / Shift+Space", "rise, fall"),
        ("left drag, or Tab to lock", "look around"),
        ("[", "pause or resume the drones"),
        ("]", "pause or resume the cars"),
    ];

    fn gpu_needs() -> common::GpuNeeds {
        crate::scene_lights::gpu_needs()
    }

    /// Nothing takes long enough to prepare in steps.
    type Prepared = ();

    fn prepare(_gpu: &Gpu) -> Preparation<()> {
        Preparation::ready(())
    }

    fn new(gpu: &Gpu, target: Target, (): ()) -> anyhow::Result<Self> {
        let device = &gpu.device;
        let city = City::new();
        let Scenery { meshes, billboard, countryside_pieces } = scenery(device, &city)?;
        let scene_lights = SceneLights::new(gpu)?;
        let materials = MaterialBuffer::new(device);
        let layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("city"),
            bind_group_layouts: &[Some(&scene_lights.layout), Some(&materials.layout)],
            immediate_size: 0,
        });
        let post = PostChain::new(gpu, target)?;
        let multisample = post.hdr().multisample();
        let pipelines = Reloadable::new(gpu, move |gpu| build_pipelines(gpu, &layout, multisample))?;
        let sky = CitySky::new(gpu, &scene_lights, multisample)?;
        Ok(Self {
            camera: aerial_camera(target.aspect()),
            controller: FlyController { speed: 20.0, ..Default::default() },
            settings: Settings::DAY,
            clocks: Clocks::default(),
            riding: None,
            last_time: 0.0,
            beacons: beacons(MAX_LIGHTS as usize),
            meshes,
            moving_parts: MovingParts::new(&city),
            billboard,
            countryside_pieces,
            city,
            scene_lights,
            materials,
            sky,
            pipelines,
            post,
            target,
            last_lists: ClusterLists::default(),
            last_light_count: 0,
        })
    }

    fn resize(&mut self, gpu: &Gpu, target: Target) {
        self.target = target;
        self.camera.aspect = target.aspect();
        self.post.resize(gpu, target);
    }

    fn apply_view(&mut self, view: usize) {
        self.settings = VIEW_TABLE[view].settings;
    }

    fn reset_camera(&mut self, view: usize) {
        match VIEW_TABLE[view].camera {
            Some(preset) => self.place_camera(preset),
            None => (self.camera, self.riding) = (aerial_camera(self.target.aspect()), None),
        }
    }

    fn camera_mut(&mut self) -> Option<&mut Camera> {
        Some(&mut self.camera)
    }

    fn before_first_frame(&mut self, camera_placed: bool) {
        // `--camera` on a view that rides a car or a drone: look from
        // there, as when the learner takes the keys.
        if camera_placed {
            self.riding = None;
        }
    }

    fn update(&mut self, input: &Input, dt: f32) {
        let moving = [KeyCode::KeyW, KeyCode::KeyA, KeyCode::KeyS, KeyCode::KeyD, KeyCode::ArrowUp, KeyCode::ArrowDown];
        if moving.iter().any(|&k| input.held(k)) {
            self.riding = None;
        }
        if input.pressed(KeyCode::BracketLeft) {
            self.clocks.drones.set_paused(!self.clocks.drones.is_paused(), self.last_time);
        }
        if input.pressed(KeyCode::BracketRight) {
            self.clocks.cars.set_paused(!self.clocks.cars.is_paused(), self.last_time);
        }
        self.controller.update(&mut self.camera, input, dt);
    }

    // ANCHOR: render
    fn render(&mut self, gpu: &Gpu, frame: &mut Frame) {
        self.last_time = frame.time;
        let s = self.settings;
        let mut day = daylight(s.time_of_day.phase(frame.time, s.day_seconds));
        let traffic = self.city.traffic(self.clocks.cars.time(frame.time), self.clocks.drones.time(frame.time));
        if let Some(riding) = self.riding {
            self.camera = riding.camera(&traffic, self.target.aspect());
        }
        let camera = self.camera;

        // The frame's lights and materials, with only one term of the
        // light in the `ambient`, `diffuse` and `specular` views.
        let mut lights = frame_lights(&self.city, &traffic, &self.beacons, s.lights, day.night);
        if s.lights == LightCount::City && s.countryside {
            lights.extend(self.billboard.lights(day.night));
        }
        let mut materials = all_materials(day.night, s.highlights);
        if let Display::Term(term) = s.display {
            term.isolate(&mut day, &mut lights, &mut materials);
        }

        // The lights, culled into cluster lists on the CPU.
        self.last_lists = if s.culling {
            frame.timer.cpu("light culling", || clusters::cull(&camera, &lights))
        } else {
            ClusterLists::default()
        };
        self.last_light_count = lights.len();
        let options =
            LoopOptions { culling: s.culling, highlight: s.highlight, heat_map: s.display == Display::LightTiles };
        if s.sky_every_frame {
            // Computed again and waited for, so that the bench's CPU clock
            // measures the passes from start to end (a software GPU's
            // timestamps need not cover a compute pass's work).
            self.scene_lights.forget_sky();
            frame.timer.cpu("sky light to the end", || {
                self.scene_lights.update_sky(gpu, &day, frame.timer);
                let _ = gpu.device.poll(wgpu::PollType::wait_indefinitely());
            });
        } else {
            self.scene_lights.update_sky(gpu, &day, frame.timer);
        }
        self.scene_lights.write(gpu, &camera, &day, &lights, &self.last_lists, options);
        let mut pieces = traffic.pieces();
        pieces.extend(self.moving_parts.pieces(frame.time));
        if s.countryside {
            pieces.extend_from_slice(&self.countryside_pieces);
            pieces.push(Countryside::water(frame.time));
        }
        let spheres = if s.material_spheres { material_spheres::instances() } else { Vec::new() };
        self.meshes.write(gpu, &pieces, &spheres);
        gpu.queue.write_buffer(&self.materials.buffer, 0, bytemuck::cast_slice(&materials));
        self.sky.write(gpu, &camera, &day);

        // The scene, in HDR.
        {
            let mut pass = self.post.hdr().pass(frame.encoder, frame.timer, "scene", wgpu::Color::BLACK);
            pass.set_bind_group(0, &self.scene_lights.group, &[]);
            pass.set_bind_group(1, &self.materials.group, &[]);
            let pipelines = self.pipelines.get();
            pass.set_pipeline(match s.shading {
                Shading::Flat => &pipelines.flat,
                Shading::Gouraud => &pipelines.gouraud,
                Shading::Phong => &pipelines.phong,
            });
            let mut drawn = self.meshes.draw(&mut pass, s.shading == Shading::Flat, s.countryside);
            // The sky is a background, not light a surface reflects.
            if !matches!(s.display, Display::Term(_)) {
                drawn += self.sky.draw(&mut pass);
            }
            frame.drawn.add("scene", drawn);
        }

        // Bloom, then tone mapping to the target.
        let output = match s.display {
            Display::Scene | Display::Term(_) => PostOutput::Picture,
            Display::BloomOnly => PostOutput::BloomOnly,
            Display::LightTiles => PostOutput::RawHdr,
        };
        let post = PostSettings { output, exposure: s.exposure, bloom: s.bloom_on.then_some(s.bloom) };
        self.post.finish(gpu, frame, &post);
    }
    // ANCHOR_END: render

    fn ui(&mut self, ui: &mut egui::Ui) {
        let s = &mut self.settings;
        ui.horizontal_wrapped(|ui| {
            ui.label("time of day");
            for time in TimeOfDay::ALL {
                ui.radio_value(&mut s.time_of_day, time, format!("{time:?}").to_lowercase());
            }
        });
        ui.horizontal(|ui| {
            ui.label("shading");
            ui.radio_value(&mut s.shading, Shading::Flat, "flat");
            ui.radio_value(&mut s.shading, Shading::Gouraud, "Gouraud");
            ui.radio_value(&mut s.shading, Shading::Phong, "Phong");
        });
        ui.horizontal(|ui| {
            ui.label("highlight");
            ui.radio_value(&mut s.highlight, Highlight::Phong, "Phong");
            ui.radio_value(&mut s.highlight, Highlight::BlinnPhong, "Blinn-Phong");
            ui.radio_value(&mut s.highlight, Highlight::CookTorrance, "Cook-Torrance");
            ui.checkbox(&mut s.highlights, "on");
        });
        let city_lights = self.city.fixed_lights.len() as u32
            + 2 * self.city.cars.len() as u32
            + self.city.drones.len() as u32
            + if s.countryside { self.billboard.lights(1.0).len() as u32 } else { 0 };
        let mut count = match s.lights {
            LightCount::City => city_lights,
            LightCount::First(n) => n,
        };
        if ui.add(egui::Slider::new(&mut count, 0..=MAX_LIGHTS).text("lights")).changed() {
            s.lights = if count == city_lights { LightCount::City } else { LightCount::First(count) };
        }
        ui.checkbox(&mut s.culling, "cull lights per cluster (off: every fragment visits every light)");
        ui.checkbox(&mut s.countryside, "countryside and billboard");
        ui.checkbox(&mut s.material_spheres, "material spheres (south of the city)");
        ui.checkbox(&mut s.bloom_on, "bloom");
        ui.add(egui::Slider::new(&mut s.bloom.threshold, 0.2..=4.0).text("bloom threshold"));
        ui.add(egui::Slider::new(&mut s.bloom.strength, 0.0..=2.0).text("bloom strength"));
        ui.add(egui::Slider::new(&mut s.bloom.spread, 0.0..=1.0).text("bloom spread"));
        ui.add(egui::Slider::new(&mut s.exposure, 0.1..=4.0).logarithmic(true).text("exposure"));
        ui.horizontal_wrapped(|ui| {
            ui.radio_value(&mut s.display, Display::Scene, "picture");
            ui.radio_value(&mut s.display, Display::Term(LightTerm::Ambient), "ambient");
            ui.radio_value(&mut s.display, Display::Term(LightTerm::Diffuse), "diffuse");
            ui.radio_value(&mut s.display, Display::Term(LightTerm::Specular), "specular");
            ui.radio_value(&mut s.display, Display::BloomOnly, "bloom only");
            ui.radio_value(&mut s.display, Display::LightTiles, "lights per fragment");
        });
        let time = self.last_time;
        ui.horizontal(|ui| {
            let mut cars = self.clocks.cars.is_paused();
            if ui.checkbox(&mut cars, "pause cars (])").changed() {
                self.clocks.cars.set_paused(cars, time);
            }
            let mut drones = self.clocks.drones.is_paused();
            if ui.checkbox(&mut drones, "pause drones ([)").changed() {
                self.clocks.drones.set_paused(drones, time);
            }
        });
        let aspect = self.target.aspect();
        ui.horizontal_wrapped(|ui| {
            ui.label("camera");
            if ui.button("aerial").clicked() {
                (self.camera, self.riding) = (aerial_camera(aspect), None);
            }
            for (label, preset) in CameraPreset::PLACES {
                if ui.button(label).clicked() {
                    self.place_camera(preset);
                }
            }
        });
        let listed = self.last_lists.indices.len();
        ui.label(format!(
            "{} lights; {} cluster entries ({:.1} per cluster); bloom {:?}, {} levels",
            self.last_light_count,
            listed,
            listed as f32 / CLUSTERS as f32,
            self.post.bloom().format,
            self.post.bloom().sizes().len()
        ));
    }

    fn stats(&mut self, gpu: &Gpu) -> String {
        // With several samples a pixel the frame's depth buffer holds no
        // one depth a pixel to count from (a resolved depth is not a
        // depth): the last frame's city is drawn again at one sample.
        let one_sample;
        let hdr = match self.post.hdr().depth_texture() {
            Some(_) => self.post.hdr(),
            None => {
                one_sample = self.redraw_at_one_sample(gpu);
                &one_sample
            }
        };
        let per_pixel =
            lights_per_pixel(gpu, hdr, &self.camera, &self.last_lists, self.last_light_count, self.settings.culling);
        let count = self.last_light_count;
        format!(
            "{count} light{}; lights visited per covered pixel: {}; bloom in {:?}",
            if count == 1 { "" } else { "s" },
            per_pixel.map_or("n/a".into(), |v| format!("{v:.2}")),
            self.post.bloom().format
        )
    }
}

impl LightingChapter {
    /// The last frame's city (no sky: it writes no depth) drawn again into
    /// an HDR target of one sample a pixel, for its depth.
    fn redraw_at_one_sample(&self, gpu: &Gpu) -> HdrTarget {
        let hdr = HdrTarget::new(gpu, Target { samples: 1, ..self.target });
        let mut encoder = gpu.device.create_command_encoder(&Default::default());
        {
            let timer = common::PassTimer::off();
            let mut pass = hdr.pass(&mut encoder, &timer, "one sample", wgpu::Color::BLACK);
            pass.set_bind_group(0, &self.scene_lights.group, &[]);
            pass.set_bind_group(1, &self.materials.group, &[]);
            pass.set_pipeline(&self.pipelines.get().one_sample);
            let s = self.settings;
            self.meshes.draw(&mut pass, s.shading == Shading::Flat, s.countryside);
        }
        gpu.queue.submit([encoder.finish()]);
        hdr
    }

    /// Puts the camera where `preset` says, for the cars and drones where
    /// the last frame had them (a riding camera follows them from there).
    fn place_camera(&mut self, preset: CameraPreset) {
        let (cars, drones) = (self.clocks.cars.time(self.last_time), self.clocks.drones.time(self.last_time));
        let traffic = self.city.traffic(cars, drones);
        (self.camera, self.riding) = preset.place(&self.city, &traffic, self.target.aspect());
    }
}
