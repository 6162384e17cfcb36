//! The chapter itself: the settings each view applies, the views, the
//! cameras, the lights of a frame, and `impl Chapter`, which composes the
//! city's meshes, the scene's lights, the sky and the post chain into a
//! frame.

use common::chapter::storage_entry;
use common::glam::{Mat4, Vec2, Vec3};
use common::wgpu::util::DeviceExt as _;
use common::{
    Antialiasing, Camera, Chapter, FlyController, Frame, Gpu, Input, Preparation, Reloadable, Target, View, ViewRow,
    anyhow, egui, views_of, wgpu, winit::keyboard::KeyCode,
};

use crate::billboard::Billboard;
use crate::bloom::BloomSettings;
use crate::city::{City, Clocks, Material, Piece, Traffic};
use crate::city_meshes::{CityMeshes, GpuMaterial, Model, Pipelines, build_pipelines, materials};
use crate::city_sky::CitySky;
use crate::clusters::{self, CLUSTERS, ClusterLists};
use crate::countryside::{self, Countryside};
use crate::lights::{self, Daylight, Light, TimeOfDay, daylight};
use crate::material_spheres;
use crate::moving_parts::MovingParts;
use crate::paths;
use crate::post::{HdrTarget, PostChain, PostOutput, PostSettings};
use crate::scene_lights::{Highlight, LoopOptions, MAX_LIGHTS, SceneLights};

// ANCHOR: views
/// Every view, once: what it shows, and for a preset where the camera goes.
pub const VIEW_TABLE: [ViewRow<Settings, CameraPreset>; 38] = [
    ViewRow::mode("day", "the city at noon, from above", Settings::DAY),
    ViewRow::mode("night", "the city at night: street lamps, lit buildings, headlights, bloom", Settings::NIGHT),
    ViewRow::preset(
        "flat",
        "the glass sphere in the morning sun, flat shaded: one colour per face",
        Settings { shading: Shading::Flat, ..Settings::SPHERE },
        CameraPreset::Sphere,
    ),
    ViewRow::preset(
        "gouraud",
        "the same, lit per vertex and blended: the highlight smears over the facets",
        Settings { shading: Shading::Gouraud, ..Settings::SPHERE },
        CameraPreset::Sphere,
    ),
    ViewRow::preset(
        "phong",
        "the same, lit per fragment: a round, sharp highlight (Phong's mirror direction)",
        Settings { shading: Shading::Phong, ..Settings::SPHERE },
        CameraPreset::Sphere,
    ),
    ViewRow::preset(
        "blinn-phong",
        "the same with Blinn-Phong's half vector: a wider, softer highlight",
        Settings { shading: Shading::Phong, highlight: Highlight::BlinnPhong, ..Settings::SPHERE },
        CameraPreset::Sphere,
    ),
    ViewRow::preset(
        "cook-torrance",
        "the same, physically based: smooth glass's small, bright highlight and the sky it reflects at the rim",
        Settings { shading: Shading::Phong, highlight: Highlight::CookTorrance, ..Settings::SPHERE },
        CameraPreset::Sphere,
    ),
    ViewRow::preset(
        "spheres",
        "physically based, in the morning: roughness rising from 0 to 1 left to right, red paint above and gold below; the first gold sphere a mirror",
        Settings { highlight: Highlight::CookTorrance, material_spheres: true, ..Settings::SPHERE },
        CameraPreset::MaterialSpheres,
    ),
    ViewRow::mode(
        "pbr-day",
        "the day view, physically based: metal, glass and paint by roughness and metalness, lit by sun and sky",
        Settings { highlight: Highlight::CookTorrance, ..Settings::DAY },
    ),
    ViewRow::mode(
        "pbr-night",
        "the night view, physically based: the same lights through the same clusters",
        Settings { highlight: Highlight::CookTorrance, ..Settings::NIGHT },
    ),
    ViewRow::preset(
        "ambient",
        "the phong view's ambient term alone: albedo times the sky's light, the same on every side",
        Settings { display: Display::Term(LightTerm::Ambient), ..Settings::SPHERE },
        CameraPreset::Sphere,
    ),
    ViewRow::preset(
        "diffuse",
        "its diffuse term alone: Lambert's, brightest where the surface faces the sun",
        Settings { display: Display::Term(LightTerm::Diffuse), ..Settings::SPHERE },
        CameraPreset::Sphere,
    ),
    ViewRow::preset(
        "specular",
        "its specular term alone: the highlights",
        Settings { display: Display::Term(LightTerm::Specular), ..Settings::SPHERE },
        CameraPreset::Sphere,
    ),
    ViewRow::mode(
        "no-bloom",
        "the night city without bloom: lights are bright dots",
        Settings { bloom_on: false, ..Settings::NIGHT },
    ),
    ViewRow::mode(
        "bloom-only",
        "the blurred bright light the bloom adds, alone",
        Settings { display: Display::BloomOnly, ..Settings::NIGHT },
    ),
    ViewRow::mode(
        "light-tiles",
        "lights each fragment visits, as a heat map (black 0, blue few, red 24 or more)",
        Settings { display: Display::LightTiles, ..Settings::NIGHT },
    ),
    ViewRow::preset(
        "follow",
        "at night, behind a car, with its headlights on the road",
        Settings::NIGHT,
        CameraPreset::Follow,
    ),
    ViewRow::preset(
        "street",
        "at eye height in the avenue at evening, looking north: lamps coming on, towers against the sky",
        Settings { time_of_day: TimeOfDay::Evening, ..Settings::DAY },
        CameraPreset::Street,
    ),
    ViewRow::preset(
        "rooftop",
        "on the roof of the tallest tower in the morning, looking over the middle of the city",
        Settings { time_of_day: TimeOfDay::Morning, ..Settings::DAY },
        CameraPreset::Rooftop,
    ),
    ViewRow::preset(
        "lollipop",
        "at night beside the lollipop's glowing ball, 74 m up, looking down on the blocks it lights",
        Settings::NIGHT,
        CameraPreset::Lollipop,
    ),
    ViewRow::preset(
        "hill",
        "on the hill at the city's north-east corner in the morning, looking south along its edge",
        Settings { time_of_day: TimeOfDay::Morning, ..Settings::DAY },
        CameraPreset::Hill,
    ),
    ViewRow::preset(
        "drone",
        "at noon, riding beside a drone as it bobs, looking past it into the city",
        Settings::DAY,
        CameraPreset::Drone,
    ),
    ViewRow::preset(
        "skyline",
        "at night from the south-east edge of the city, at eye height: the skyline",
        Settings::NIGHT,
        CameraPreset::Skyline,
    ),
    ViewRow::preset(
        "landscape",
        "in the morning over the countryside north of the city: the river at its tide, beaches, trees, the road on its bridge",
        Settings { time_of_day: TimeOfDay::Morning, ..Settings::DAY },
        CameraPreset::Landscape,
    ),
    ViewRow::preset(
        "billboard",
        "at night in front of the billboard on the hill across the river, lit by its three spot lights",
        Settings::NIGHT,
        CameraPreset::Billboard,
    ),
    ViewRow::preset(
        "moving-parts",
        "in the evening, the tallest tower from over the avenue: the crown turning on its roof, the neon sign riding up its face",
        Settings { time_of_day: TimeOfDay::Evening, ..Settings::DAY },
        CameraPreset::MovingParts,
    ),
    ViewRow::no_aa("day", Settings::DAY),
    ViewRow::mode(
        "fxaa",
        "the first view with one sample a pixel and FXAA over the finished picture instead of multisampling",
        Settings::DAY,
    )
    .same_picture_as("day")
    .antialiasing(Antialiasing::Post),
    ViewRow::bench(
        "sky-every-frame",
        "bench: pbr-day with the sky's harmonics and prefiltered cube computed again every frame, as when the day turns",
        Settings { highlight: Highlight::CookTorrance, sky_every_frame: true, ..Settings::DAY },
    ),
    ViewRow::bench("lights-1", "bench: the night city with 1 light, culled", Settings::bench(1, true)),
    ViewRow::bench("lights-16", "bench: 16 lights, culled per cluster", Settings::bench(16, true)),
    ViewRow::bench("lights-64", "bench: 64 lights, culled per cluster", Settings::bench(64, true)),
    ViewRow::bench("lights-256", "bench: 256 lights, culled per cluster", Settings::bench(256, true)),
    ViewRow::bench("lights-1024", "bench: 1024 lights, culled per cluster", Settings::bench(1024, true)),
    ViewRow::bench("naive-16", "bench: 16 lights, every fragment visits every light", Settings::bench(16, false)),
    ViewRow::bench("naive-64", "bench: 64 lights, every fragment visits every light", Settings::bench(64, false)),
    ViewRow::bench("naive-256", "bench: 256 lights, every fragment visits every light", Settings::bench(256, false)),
    ViewRow::bench("naive-1024", "bench: 1024 lights, every fragment visits every light", Settings::bench(1024, false)),
];

/// Where a preset puts the camera; a mode leaves it, and the "reset
/// camera" button takes it back to the aerial view. The seed's city had
/// camera buttons for places worth seeing; these are this city's.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CameraPreset {
    /// Close to the glass sphere ([`sphere_camera`]).
    Sphere,
    /// In front of the material spheres ([`material_spheres_camera`]).
    MaterialSpheres,
    /// Riding behind the first car ([`follow_camera`]) until the learner moves.
    Follow,
    /// At eye height in the avenue along x = 0 ([`street_camera`]).
    Street,
    /// On the roof of the tallest tower ([`rooftop_camera`]).
    Rooftop,
    /// Beside the lollipop tower's ball ([`lollipop_camera`]).
    Lollipop,
    /// On the hill in the north-east corner ([`hill_camera`]).
    Hill,
    /// Riding beside the drone over the hill ([`drone_camera`]) until the learner moves.
    Drone,
    /// Outside the south-east corner, at eye height ([`skyline_camera`]).
    Skyline,
    /// Over the countryside north of the city ([`landscape_camera`]).
    Landscape,
    /// In front of the billboard on its hill ([`billboard_camera`]).
    Billboard,
    /// Facing the tallest tower's crown and sign ([`moving_parts_camera`]).
    MovingParts,
}
// ANCHOR_END: views

impl CameraPreset {
    /// The overlay's camera buttons: every place but the sphere's close-up,
    /// which the shading views use.
    pub const PLACES: [(&'static str, CameraPreset); 10] = [
        ("street", CameraPreset::Street),
        ("rooftop", CameraPreset::Rooftop),
        ("lollipop", CameraPreset::Lollipop),
        ("hill", CameraPreset::Hill),
        ("skyline", CameraPreset::Skyline),
        ("landscape", CameraPreset::Landscape),
        ("billboard", CameraPreset::Billboard),
        ("moving parts", CameraPreset::MovingParts),
        ("follow a car", CameraPreset::Follow),
        ("ride a drone", CameraPreset::Drone),
    ];

    /// The camera this preset places in `city` with its `traffic` now, and
    /// what it then rides with, if anything.
    pub fn place(self, city: &City, traffic: &Traffic, aspect: f32) -> (Camera, Option<Riding>) {
        let still = |camera| (camera, None);
        match self {
            Self::Sphere => still(sphere_camera(city, aspect)),
            Self::MaterialSpheres => still(material_spheres_camera(aspect)),
            Self::Street => still(street_camera(aspect)),
            Self::Rooftop => still(rooftop_camera(city, aspect)),
            Self::Lollipop => still(lollipop_camera(aspect)),
            Self::Hill => still(hill_camera(aspect)),
            Self::Skyline => still(skyline_camera(aspect)),
            Self::Landscape => still(landscape_camera(aspect)),
            Self::Billboard => still(billboard_camera(&billboard(), aspect)),
            Self::MovingParts => still(moving_parts_camera(&MovingParts::new(city), aspect)),
            Self::Follow | Self::Drone => {
                // The drone over the hill: nothing stands between it and the city.
                let riding = if self == Self::Follow { Riding::Car(0) } else { Riding::Drone(3) };
                (riding.camera(traffic, aspect), Some(riding))
            }
        }
    }
}

/// Something moving that the camera rides with, placed anew every frame
/// from where it is then, until the learner moves the camera.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Riding {
    /// Behind this car ([`follow_camera`]).
    Car(usize),
    /// Beside this drone ([`drone_camera`]).
    Drone(usize),
}

impl Riding {
    pub fn camera(self, traffic: &Traffic, aspect: f32) -> Camera {
        match self {
            Riding::Car(car) => follow_camera(&traffic.cars[car], aspect),
            Riding::Drone(drone) => drone_camera(traffic.drones[drone], aspect),
        }
    }
}

/// How surfaces are lit.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Shading {
    /// Once per face: one normal and one colour per triangle.
    Flat,
    /// Once per vertex; colours interpolated.
    Gouraud,
    /// Once per fragment; normals interpolated.
    Phong,
}

/// What reaches the screen.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Display {
    Scene,
    /// One term of the light that surfaces reflect, alone: without the
    /// other two, the glow of emissive materials, or the sky.
    Term(LightTerm),
    BloomOnly,
    LightTiles,
}

// ANCHOR: terms
/// The three terms `light_surface` in lights.wgsl adds up for a surface.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LightTerm {
    /// albedo × the sky's light: the same whichever way the surface faces.
    Ambient,
    /// albedo × radiance × n · l, from the sun and every light: Lambert's.
    Diffuse,
    /// specular × the highlight's lobe × radiance × n · l: the highlights.
    Specular,
}

impl LightTerm {
    /// Switches off the glow and the inputs of the other two terms. The
    /// shader adds up three products: zeroing the sun and the lamps leaves
    /// the ambient term; zeroing the sky's light and the specular strength
    /// leaves the diffuse; zeroing the sky's light and the albedo leaves the
    /// highlights. Exactly one term is drawn, with no branch in any shader.
    pub fn isolate(self, day: &mut Daylight, lights: &mut Vec<Light>, materials: &mut [GpuMaterial]) {
        for material in materials.iter_mut() {
            material.emissive = [0.0; 3];
            match self {
                Self::Ambient => {}
                Self::Diffuse => material.specular = 0.0,
                Self::Specular => (material.albedo, material.albedo_high) = ([0.0; 3], [0.0; 3]),
            }
        }
        match self {
            // No light arrives from a direction: no diffuse light, no highlight.
            Self::Ambient => {
                day.sun = Vec3::ZERO;
                lights.clear();
            }
            // The sky's light: the ambient colour, and for Cook-Torrance the
            // sky itself (these views do not draw it).
            Self::Diffuse | Self::Specular => {
                (day.ambient, day.horizon, day.zenith) = (Vec3::ZERO, Vec3::ZERO, Vec3::ZERO)
            }
        }
    }
}
// ANCHOR_END: terms

/// How many lights shine.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LightCount {
    /// The city's own: lamps, buildings, cars and drones.
    City,
    /// The first n of the city's lights and then of extra beacons: the bench's counts.
    First(u32),
}

/// Everything a view decides.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Settings {
    pub time_of_day: TimeOfDay,
    /// Seconds in a day when the time of day is `Auto`.
    pub day_seconds: f32,
    pub shading: Shading,
    pub highlight: Highlight,
    /// Highlights at all (off: diffuse light only).
    pub highlights: bool,
    /// Cluster lists (true) or every light for every fragment (false).
    pub culling: bool,
    pub lights: LightCount,
    pub bloom_on: bool,
    pub bloom: BloomSettings,
    pub display: Display,
    pub exposure: f32,
    /// The countryside, the billboard and its spots around the city (off:
    /// the city alone, as the bench measures its lights).
    pub countryside: bool,
    /// The two rows of material spheres south of the city (`material_spheres`).
    pub material_spheres: bool,
    /// The sky's light computed again every frame, as if the day turned:
    /// the bench's measure of what that costs.
    pub sky_every_frame: bool,
}

impl Settings {
    /// The night city, as `night` shows it; the other views change a few
    /// of these.
    pub const NIGHT: Self = Self {
        time_of_day: TimeOfDay::Night,
        day_seconds: 120.0,
        shading: Shading::Phong,
        highlight: Highlight::BlinnPhong,
        highlights: true,
        culling: true,
        lights: LightCount::City,
        bloom_on: true,
        bloom: BloomSettings::DEFAULT,
        display: Display::Scene,
        exposure: 1.0,
        countryside: true,
        material_spheres: false,
        sky_every_frame: false,
    };

    /// The city at noon: what the chapter starts with.
    pub const DAY: Self = Self { time_of_day: TimeOfDay::Noon, ..Self::NIGHT };

    /// One light, the morning sun, so that shading is all there is to see:
    /// the glass sphere's views, with Phong's highlight unless they say otherwise.
    pub const SPHERE: Self = Self {
        time_of_day: TimeOfDay::Morning,
        lights: LightCount::First(0),
        highlight: Highlight::Phong,
        ..Self::NIGHT
    };

    /// The bench's night city with the first `lights` lights, culled per
    /// cluster or (`culling` false) visited by every fragment; the city
    /// alone, so that every covered pixel is one the lights are meant for.
    pub const fn bench(lights: u32, culling: bool) -> Self {
        Self { lights: LightCount::First(lights), culling, countryside: false, ..Self::NIGHT }
    }
}

// ANCHOR: cameras
/// High over the south-west corner, looking at the middle of the city.
pub fn aerial_camera(aspect: f32) -> Camera {
    Camera {
        near: 0.5,
        far: 900.0,
        ..Camera::looking_at(Vec3::new(-190.0, 120.0, 230.0), Vec3::new(0.0, 10.0, 0.0), aspect)
    }
}

/// Standing in the road along x = 0, at the southern edge, looking north.
pub fn street_camera(aspect: f32) -> Camera {
    Camera {
        near: 0.3,
        far: 900.0,
        ..Camera::looking_at(Vec3::new(-3.0, 1.8, 185.0), Vec3::new(-3.0, 8.0, 0.0), aspect)
    }
}

/// Close to the glass sphere, from the south-west, with the morning sun on it.
pub fn sphere_camera(city: &City, aspect: f32) -> Camera {
    let centre = city.sphere_building + Vec3::Y * 24.0;
    Camera { near: 0.3, far: 900.0, ..Camera::looking_at(centre + Vec3::new(-18.0, 6.0, 34.0), centre, aspect) }
}

/// South of the material spheres, looking north at them with the city
/// behind, just far enough back to see both rows whole.
pub fn material_spheres_camera(aspect: f32) -> Camera {
    let centre = material_spheres::CENTRE;
    Camera { near: 0.3, far: 900.0, ..Camera::looking_at(centre + Vec3::Z * 19.0, centre, aspect) }
}

/// Behind and above a car, looking where it goes.
pub fn follow_camera(car: &paths::Pose, aspect: f32) -> Camera {
    let ahead = car.forward();
    let eye = car.position - ahead * 12.0 + Vec3::Y * 4.5;
    Camera { near: 0.3, far: 900.0, ..Camera::looking_at(eye, car.position + ahead * 12.0, aspect) }
}
// ANCHOR_END: cameras

// ANCHOR: places
/// A camera at `eye` looking at `target`, seeing as far as the city needs.
fn city_camera(eye: Vec3, target: Vec3, aspect: f32) -> Camera {
    Camera { near: 0.3, far: 900.0, ..Camera::looking_at(eye, target, aspect) }
}

/// On the roof of the tallest square tower, near the edge that faces the
/// glass sphere (the roof's cap behind), looking down past the sphere
/// across the city.
pub fn rooftop_camera(city: &City, aspect: f32) -> Camera {
    let tower = city.tallest_tower().model;
    let roof = tower.transform_point3(Vec3::Y * 0.5);
    let towards = (city.sphere_building - roof).with_y(0.0).normalize();
    let eye = roof + towards * 0.4 * tower.x_axis.length() + Vec3::Y * 1.7;
    city_camera(eye, roof.with_y(0.0) + towards * 170.0, aspect)
}

/// Beside the lollipop's glowing ball (at 74 m, block (−30, 30)), a little
/// above it, looking down past it at the blocks to the south-east.
pub fn lollipop_camera(aspect: f32) -> Camera {
    let ball = Vec3::new(-30.0, 74.2, 30.0);
    city_camera(ball + Vec3::new(-20.0, 4.0, -15.0), ball + Vec3::new(40.0, -60.0, 50.0), aspect)
}

/// Standing on the east slope of the hill that fills the north-east
/// corner block, at the city's edge, looking south along it: the towers on
/// the right, the ground ending on the left.
pub fn hill_camera(aspect: f32) -> Camera {
    city_camera(Vec3::new(172.0, 13.3, -150.0), Vec3::new(176.0, 6.0, 150.0), aspect)
}

/// Beside a drone, a little above it and further out from the middle of
/// the city, looking past it at the towers.
pub fn drone_camera(drone: Vec3, aspect: f32) -> Camera {
    let outwards = Vec3::new(drone.x, 0.0, drone.z).normalize_or(Vec3::Z);
    let aside = Vec3::Y.cross(outwards);
    let eye = drone + outwards * 7.0 + aside * 3.0 + Vec3::Y * 1.5;
    city_camera(eye, drone - outwards * 40.0 + aside * 8.0 - Vec3::Y * 12.0, aspect)
}

/// Far out past the south-east corner, 20 m up, looking at the middle of
/// the city: its skyline.
pub fn skyline_camera(aspect: f32) -> Camera {
    city_camera(Vec3::new(235.0, 16.0, 235.0), Vec3::new(0.0, 30.0, 0.0), aspect)
}

/// A camera at `eye` looking at `target`, seeing past the countryside's
/// far edge (1 km out from the middle of the city, both ways).
fn countryside_camera(eye: Vec3, target: Vec3, aspect: f32) -> Camera {
    Camera { near: 0.3, far: 2500.0, ..Camera::looking_at(eye, target, aspect) }
}

/// 24 m over the river's south bank, east of the road north, looking
/// north-west across the river, its beaches and the bridge, to the
/// billboard's hill.
pub fn landscape_camera(aspect: f32) -> Camera {
    countryside_camera(Vec3::new(170.0, 24.0, -300.0), Vec3::new(10.0, 0.0, -480.0), aspect)
}

/// In front of the billboard, a little below its middle and 45 m out,
/// looking up at it.
pub fn billboard_camera(billboard: &Billboard, aspect: f32) -> Camera {
    let eye = billboard.centre + billboard.facing * 45.0 + billboard.across * 8.0 - Vec3::Y * 6.0;
    countryside_camera(eye, billboard.centre, aspect)
}

/// East of the tallest tower, over the avenue, looking at the face the
/// sign rides up, the crown on the roof above it.
pub fn moving_parts_camera(parts: &MovingParts, aspect: f32) -> Camera {
    let target = parts.sign_face.with_y((parts.sign_low + parts.crown_base.y) / 2.0);
    city_camera(target + Vec3::new(75.0, -5.0, 40.0), target, aspect)
}
// ANCHOR_END: places

/// The billboard on its hill across the river, facing the city.
pub fn billboard() -> Billboard {
    Billboard::new(countryside::BILLBOARD_HILL, Vec2::ZERO, countryside::height)
}

// ANCHOR: frame_lights
/// The lights of this frame: the moving ones (cars, drones), then the
/// still ones (street lamps and lit buildings, which come on as night falls,
/// `night` from 0 by day to 1), then beacons, up to the view's count. A
/// light that is off is not in the list at all: it would cost the loop
/// without adding anything.
pub fn frame_lights(city: &City, traffic: &Traffic, beacons: &[Light], count: LightCount, night: f32) -> Vec<Light> {
    let dimmed = |light: &Light| Light { colour: light.colour * night, ..*light };
    let fixed = city.fixed_lights.iter().filter(|_| night > 0.0).map(dimmed);
    let all = traffic.lights.iter().copied().chain(fixed);
    match count {
        LightCount::City => all.collect(),
        LightCount::First(n) => all.chain(beacons.iter().copied()).take(n.min(MAX_LIGHTS) as usize).collect(),
    }
}
// ANCHOR_END: frame_lights

/// Small coloured lights scattered over the city: not part of its design,
/// there to fill the bench's larger light counts.
pub fn beacons(count: usize) -> Vec<Light> {
    let mut rng = common::rng::Rng::new(21);
    (0..count)
        .map(|_| {
            let hue = rng.unit();
            Light {
                position: Vec3::new(rng.range(-170.0, 170.0), rng.range(1.0, 50.0), rng.range(-170.0, 170.0)),
                colour: Vec3::new(0.3 + 0.7 * hue, 0.5, 1.0 - 0.6 * hue) * rng.range(20.0, 60.0),
                range: rng.range(6.0, 22.0),
                kind: lights::LightKind::Point,
            }
        })
        .collect()
}

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
    materials: wgpu::Buffer,
    sky: CitySky,
    city_group: wgpu::BindGroup,
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
        common::GpuNeeds {
            required: wgpu::Features::empty(),
            optional: PostChain::OPTIONAL_FEATURES,
            downlevel: crate::scene_lights::DOWNLEVEL,
        }
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
        let materials = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("materials"),
            contents: bytemuck::cast_slice(&all_materials(0.0, true)),
            usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_DST,
        });
        let city_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("city"),
            entries: &[storage_entry(0, wgpu::ShaderStages::VERTEX_FRAGMENT)],
        });
        let city_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("city"),
            layout: &city_layout,
            entries: &[wgpu::BindGroupEntry { binding: 0, resource: materials.as_entire_binding() }],
        });
        let layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("city"),
            bind_group_layouts: &[Some(&scene_lights.layout), Some(&city_layout)],
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
            city_group,
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
        gpu.queue.write_buffer(&self.materials, 0, bytemuck::cast_slice(&materials));
        self.sky.write(gpu, &camera, &day);

        // The scene, in HDR.
        {
            let mut pass = self.post.hdr().pass(frame.encoder, frame.timer, "scene", wgpu::Color::BLACK);
            pass.set_bind_group(0, &self.scene_lights.group, &[]);
            pass.set_bind_group(1, &self.city_group, &[]);
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

/// The material buffer: the city's materials, then the material spheres'
/// (whose instances index past the city's).
fn all_materials(night: f32, highlights: bool) -> Vec<GpuMaterial> {
    let mut all = materials(night, highlights);
    all.extend(material_spheres::materials(highlights));
    all
}

/// What [`scenery`] makes.
struct Scenery {
    meshes: CityMeshes,
    billboard: Billboard,
    countryside_pieces: Vec<Piece>,
}

// ANCHOR: scenery
/// The meshes on the GPU: the city's shapes with the city's still pieces,
/// and the countryside's ground and trees as models of their own; with
/// the billboard, and the pieces the countryside adds to the city's shapes
/// (its roads and bridge, the billboard's panel, posts and digits).
fn scenery(device: &wgpu::Device, city: &City) -> anyhow::Result<Scenery> {
    let countryside = Countryside::new();
    let billboard = billboard();
    let (trunk, foliage) = countryside::tree_meshes().map_err(anyhow::Error::msg)?;
    let models = [
        Model { name: "countryside", mesh: countryside.ground, placed: vec![(Mat4::IDENTITY, Material::Countryside)] },
        Model {
            name: "tree trunk",
            mesh: trunk,
            placed: countryside.trees.iter().map(|&t| (t, Material::Bark)).collect(),
        },
        Model {
            name: "tree foliage",
            mesh: foliage,
            placed: countryside.trees.iter().map(|&t| (t, Material::Leaves)).collect(),
        },
    ];
    let countryside_pieces = countryside.pieces.iter().chain(&billboard.pieces).copied().collect();
    Ok(Scenery { meshes: CityMeshes::new(device, &city.pieces, &models), billboard, countryside_pieces })
}
// ANCHOR_END: scenery

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
            pass.set_bind_group(1, &self.city_group, &[]);
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

/// The average number of lights the loop visits per pixel that shows the
/// city (not the sky) in the last frame: from its depth buffer (of one
/// sample a pixel), each pixel's cluster, and that cluster's list.
fn lights_per_pixel(
    gpu: &Gpu,
    hdr: &HdrTarget,
    camera: &Camera,
    lists: &ClusterLists,
    light_count: usize,
    culling: bool,
) -> Option<f64> {
    // Copying a depth texture out is optional on downlevel backends (GL):
    // without it the figure is "n/a" rather than a wgpu validation panic.
    let copies = wgpu::DownlevelFlags::DEPTH_TEXTURE_AND_BUFFER_COPIES;
    if !gpu.adapter.get_downlevel_capabilities().flags.contains(copies) {
        return None;
    }
    // One depth a pixel: `hdr` is of one sample (see `stats`).
    let depth = hdr.depth_texture()?;
    let depths = common::headless::read_floats(gpu, depth).ok()?;
    let (width, height) = (depth.width(), depth.height());
    let (near, far) = (camera.near, camera.far);
    let (mut visited, mut pixels) = (0u64, 0u64);
    for (i, depth) in depths.iter().map(|d| d[0]).enumerate() {
        if depth >= 1.0 {
            continue;
        }
        pixels += 1;
        if !culling {
            visited += light_count as u64;
            continue;
        }
        // Back from stored depth to distance (chapter 02), and to the pixel's cluster.
        let distance = near * far / (far - depth * (far - near));
        let (x, y) = ((i as u32 % width) * clusters::GRID[0] / width, (i as u32 / width) * clusters::GRID[1] / height);
        let z = clusters::slice(distance, near, far).clamp(0, clusters::GRID[2] as i32 - 1) as u32;
        let cluster = ((z * clusters::GRID[1] + y) * clusters::GRID[0] + x) as usize;
        visited += u64::from(lists.ranges.get(cluster).map_or(0, |r| r[1]));
    }
    (pixels > 0).then(|| visited as f64 / pixels as f64)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::city::{Material, Shape};

    #[test]
    fn the_drone_camera_keeps_its_drone_in_view_as_it_bobs() {
        let city = City::new();
        let mut heights = Vec::new();
        for drone_time in [0.0, 0.8, 1.7, 6.0] {
            let traffic = city.traffic(0.0, drone_time);
            let (camera, riding) = CameraPreset::Drone.place(&city, &traffic, 16.0 / 9.0);
            assert_eq!(riding, Some(Riding::Drone(3)));
            let clip = camera.view_projection() * traffic.drones[3].extend(1.0);
            let (x, y) = (clip.x / clip.w, clip.y / clip.w);
            assert!(clip.w > 0.0 && x.abs() < 0.8 && y.abs() < 0.8, "the drone is at ({x}, {y}) in the picture");
            heights.push(camera.position.y);
        }
        assert!(heights.windows(2).all(|h| h[0] != h[1]), "the camera bobs with the drone: {heights:?}");
    }

    /// The page's count: the city's 339 lights and the billboard's 3 spots.
    #[test]
    fn the_night_has_342_lights_with_the_billboards_spots() {
        let city = City::new();
        let traffic = city.traffic(6.0, 6.0);
        let lights = frame_lights(&city, &traffic, &[], LightCount::City, 1.0);
        assert_eq!(lights.len() + billboard().lights(1.0).len(), 342);
    }

    #[test]
    fn the_preset_views_keep_their_subjects_in_the_picture() {
        let city = City::new();
        let traffic = city.traffic(6.0, 6.0);
        let parts = MovingParts::new(&city);
        let board = billboard();
        let in_view = |preset: CameraPreset, point: Vec3| {
            let camera = preset.place(&city, &traffic, 16.0 / 9.0).0;
            let clip = camera.view_projection() * point.extend(1.0);
            clip.w > 0.0 && (clip.x / clip.w).abs() < 0.95 && (clip.y / clip.w).abs() < 0.95
        };
        for corner in board.corners() {
            assert!(in_view(CameraPreset::Billboard, corner), "the billboard's corner {corner}");
        }
        assert!(in_view(CameraPreset::Landscape, board.centre), "the billboard from the landscape view");
        let bridge = Vec3::new(0.0, countryside::BRIDGE_DECK, countryside::river_z(0.0));
        assert!(in_view(CameraPreset::Landscape, bridge), "the bridge");
        let crown = parts.crown_base + Vec3::Y * 6.0;
        let sign = parts.sign_face.with_y(parts.sign_height(6.0));
        assert!(in_view(CameraPreset::MovingParts, crown) && in_view(CameraPreset::MovingParts, sign));
    }

    #[test]
    fn the_rooftop_camera_stands_over_every_other_square_tower() {
        let city = City::new();
        let camera = rooftop_camera(&city, 16.0 / 9.0);
        let roofs = city
            .pieces
            .iter()
            .filter(|p| p.shape == Shape::Cube && matches!(p.material, Material::Facade | Material::Brick))
            .map(|p| p.model.transform_point3(Vec3::Y * 0.5).y);
        let highest = roofs.fold(0.0, f32::max);
        assert!((camera.position.y - (highest + 1.7)).abs() < 1e-3, "{} over a roof at {highest}", camera.position.y);
    }
}
