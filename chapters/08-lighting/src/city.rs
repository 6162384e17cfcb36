//! The futuristic city as data: where every building, road, lamp, car and
//! drone is, what it is made of, and which lights it carries. Nothing here
//! touches the GPU; the chapter draws it, and chapter 09 textures the same
//! city by composing this module.

use std::f32::consts::{FRAC_PI_2, FRAC_PI_4, TAU};

use common::glam::{Mat4, Quat, Vec2, Vec3};
use common::rng::Rng;
use common::{MeshData, primitives};

use crate::lights::{Light, LightKind};
use crate::paths::{PausableClock, Pose, SegmentedPath};
use crate::pbr::Physical;

/// Roads run every `BLOCK` metres from −`HALF` to `HALF`, both ways.
pub const HALF: f32 = 180.0;
pub const BLOCK: f32 = 60.0;
pub const ROAD_WIDTH: f32 = 12.0;
/// How far a drone bobs up and down about its place, metres, and the
/// seconds one bob takes.
pub const DRONE_BOB_HEIGHT: f32 = 1.2;
pub const DRONE_BOB_PERIOD: f32 = 3.3;

/// The meshes the city is built from: `common`'s primitives and the ground.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Shape {
    Cube,
    Sphere,
    Cylinder,
    Cone,
    Torus,
    Pyramid,
    Ground,
}

impl Shape {
    pub const ALL: [Shape; 7] =
        [Shape::Cube, Shape::Sphere, Shape::Cylinder, Shape::Cone, Shape::Torus, Shape::Pyramid, Shape::Ground];

    /// The mesh, smooth-shaded. The sphere is coarse on purpose (24 × 12):
    /// lit per vertex, its highlight shows every facet.
    pub fn mesh(self) -> MeshData {
        match self {
            Shape::Cube => primitives::cube(),
            Shape::Sphere => primitives::uv_sphere(24, 12),
            Shape::Cylinder => primitives::cylinder(24),
            Shape::Cone => primitives::cone(24),
            Shape::Torus => primitives::torus(32, 12, 0.12),
            Shape::Pyramid => primitives::pyramid(),
            // 4 m squares, so that lit per vertex the lamps still make pools.
            Shape::Ground => primitives::plane(100),
        }
    }
}

// ANCHOR: materials
/// What a surface is made of. Chapter 09 gives some of them textures.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[repr(u32)]
pub enum Material {
    Ground,
    Road,
    Concrete,
    Facade,
    Brick,
    Metal,
    Glass,
    Hill,
    /// Neon: glows in its own colour, day and night.
    Neon,
    /// A street lamp's head: glows at night.
    Lamp,
    Headlight,
    TailLight,
    CarPaint,
    Drone,
    /// The countryside's ground: sand near the water, grass above
    /// (countryside.rs), by the height of each point.
    Countryside,
    /// The river.
    Water,
    /// The trees' trunks and foliage.
    Bark,
    Leaves,
    /// The billboard's panel.
    Billboard,
}

/// The countryside's ground, linear RGB: sand by the water, grass above
/// (countryside.rs blends them by height).
pub const SAND: Vec3 = Vec3::new(0.42, 0.36, 0.22);
pub const GRASS: Vec3 = Vec3::new(0.05, 0.11, 0.03);

/// How a material responds to light.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Surface {
    /// Diffuse colour, linear RGB.
    pub albedo: Vec3,
    /// Strength and sharpness of the highlight.
    pub specular: f32,
    pub shininess: f32,
    /// Light of its own, added unlit (linear RGB, may exceed 1: it blooms).
    pub emissive: Vec3,
    /// Emits only as night falls (lamps, windows), not by day.
    pub at_night: bool,
}

impl Material {
    pub const ALL: [Material; 19] = [
        Material::Ground,
        Material::Road,
        Material::Concrete,
        Material::Facade,
        Material::Brick,
        Material::Metal,
        Material::Glass,
        Material::Hill,
        Material::Neon,
        Material::Lamp,
        Material::Headlight,
        Material::TailLight,
        Material::CarPaint,
        Material::Drone,
        Material::Countryside,
        Material::Water,
        Material::Bark,
        Material::Leaves,
        Material::Billboard,
    ];

    pub fn surface(self) -> Surface {
        let (albedo, specular, shininess, emissive, at_night) = match self {
            Material::Ground => (Vec3::new(0.07, 0.075, 0.07), 0.05, 8.0, Vec3::ZERO, false),
            Material::Road => (Vec3::new(0.03, 0.03, 0.033), 0.2, 24.0, Vec3::ZERO, false),
            Material::Concrete => (Vec3::new(0.20, 0.20, 0.19), 0.1, 12.0, Vec3::ZERO, false),
            Material::Facade => (Vec3::new(0.14, 0.16, 0.20), 0.3, 48.0, Vec3::new(0.012, 0.010, 0.006), true),
            Material::Brick => (Vec3::new(0.28, 0.11, 0.07), 0.08, 10.0, Vec3::ZERO, false),
            Material::Metal => (Vec3::new(0.30, 0.31, 0.34), 0.6, 96.0, Vec3::ZERO, false),
            Material::Glass => (Vec3::new(0.05, 0.13, 0.18), 0.8, 96.0, Vec3::new(0.008, 0.02, 0.035), true),
            Material::Hill => (Vec3::new(0.05, 0.11, 0.035), 0.02, 6.0, Vec3::ZERO, false),
            Material::Neon => (Vec3::new(0.05, 0.2, 0.3), 0.5, 32.0, Vec3::new(0.4, 2.5, 4.0), false),
            Material::Lamp => (Vec3::new(0.8, 0.8, 0.75), 0.3, 16.0, Vec3::new(6.0, 4.4, 2.6), true),
            Material::Headlight => (Vec3::ONE, 0.5, 32.0, Vec3::new(8.0, 7.5, 6.5), false),
            Material::TailLight => (Vec3::new(0.4, 0.02, 0.02), 0.5, 32.0, Vec3::new(5.0, 0.2, 0.1), false),
            Material::CarPaint => (Vec3::new(0.55, 0.08, 0.05), 0.8, 80.0, Vec3::ZERO, false),
            Material::Drone => (Vec3::new(0.12, 0.12, 0.14), 0.7, 64.0, Vec3::ZERO, false),
            // The sand's colour; city_meshes.rs blends it to grass by height.
            Material::Countryside => (SAND, 0.03, 8.0, Vec3::ZERO, false),
            Material::Water => (Vec3::new(0.02, 0.055, 0.08), 0.9, 160.0, Vec3::ZERO, false),
            // Bark as tree.mtl has it; the foliage darker than its 0.12, 0.33, 0.12, as deep as the grass.
            Material::Bark => (Vec3::new(0.30, 0.19, 0.11), 0.05, 8.0, Vec3::ZERO, false),
            Material::Leaves => (Vec3::new(0.06, 0.17, 0.06), 0.04, 12.0, Vec3::ZERO, false),
            Material::Billboard => (Vec3::new(0.75, 0.74, 0.70), 0.15, 16.0, Vec3::ZERO, false),
        };
        Surface { albedo, specular, shininess, emissive, at_night }
    }

    // ANCHOR: physical
    /// The same material for Cook-Torrance: its albedo as base colour, and
    /// how rough and how metallic it is. Glass, water and paint are smooth
    /// non-metals; metal and the drones' shells are metals; stone, asphalt
    /// and plants are rough.
    pub fn physical(self) -> Physical {
        let (roughness, metallic) = match self {
            Material::Ground | Material::Hill | Material::Countryside => (0.9, 0.0),
            Material::Road => (0.75, 0.0),
            Material::Concrete | Material::Brick | Material::Bark => (0.85, 0.0),
            Material::Facade => (0.45, 0.0),
            Material::Metal => (0.35, 1.0),
            Material::Drone => (0.4, 1.0),
            Material::Glass | Material::Water => (0.06, 0.0),
            Material::CarPaint => (0.3, 0.0),
            Material::Neon | Material::Lamp | Material::Headlight | Material::TailLight => (0.3, 0.0),
            Material::Leaves => (0.65, 0.0),
            Material::Billboard => (0.6, 0.0),
        };
        Physical { base_colour: self.surface().albedo, metallic, roughness }
    }
    // ANCHOR_END: physical
}
// ANCHOR_END: materials

/// One object placed in the city: a shape, where it is (its model matrix),
/// and what it is made of.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Piece {
    pub shape: Shape,
    pub model: Mat4,
    pub material: Material,
}

fn piece(shape: Shape, position: Vec3, scale: Vec3, material: Material) -> Piece {
    Piece { shape, model: Mat4::from_scale_rotation_translation(scale, Quat::IDENTITY, position), material }
}

/// A car: its path through the city and its paint.
#[derive(Clone, Debug, PartialEq)]
pub struct Car {
    pub path: SegmentedPath,
    pub paint: Material,
}

/// A drone hovering over a spot.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Drone {
    pub position: Vec3,
    /// Seconds into its bob at time 0, so that drones do not bob together.
    pub phase: f32,
}

/// The whole city.
pub struct City {
    /// Everything that does not move.
    pub pieces: Vec<Piece>,
    pub cars: Vec<Car>,
    pub drones: Vec<Drone>,
    /// Lights that do not move: street lamps and lit buildings, in a fixed
    /// shuffled order so that any first n of them spread over the city.
    pub fixed_lights: Vec<Light>,
    /// Where the tall glass sphere building stands, for close-ups.
    pub sphere_building: Vec3,
}

// ANCHOR: layout
impl City {
    /// The city, the same every time: a 360 m square on a grid of roads.
    pub fn new() -> Self {
        let mut rng = Rng::new(8);
        let mut pieces = Vec::new();
        let mut lights = Vec::new();
        pieces.push(piece(
            Shape::Ground,
            Vec3::ZERO,
            Vec3::new(2.0 * HALF + 40.0, 1.0, 2.0 * HALF + 40.0),
            Material::Ground,
        ));
        let lines: Vec<f32> = (0..=6).map(|i| -HALF + i as f32 * BLOCK).collect();
        for &line in &lines {
            // Roads both ways; the second set sits 1 cm higher, so crossings
            // do not fight for depth. Each is built along x and the first set
            // turned a quarter, so that a road's length runs along its box's
            // own x (chapter 09's road texture runs that way).
            let length = 2.0 * HALF + ROAD_WIDTH;
            let road = |position, turn: f32| Piece {
                shape: Shape::Cube,
                model: Mat4::from_scale_rotation_translation(
                    Vec3::new(length, 0.08, ROAD_WIDTH),
                    Quat::from_rotation_y(turn),
                    position,
                ),
                material: Material::Road,
            };
            pieces.push(road(Vec3::new(line, 0.04, 0.0), FRAC_PI_2));
            pieces.push(road(Vec3::new(0.0, 0.05, line), 0.0));
        }
        street_lamps(&lines, &mut pieces, &mut lights);
        let sphere_building = Vec3::new(30.0, 0.0, -30.0);
        for bx in 0..6 {
            for bz in 0..6 {
                let centre = Vec2::new(-HALF + BLOCK * (bx as f32 + 0.5), -HALF + BLOCK * (bz as f32 + 0.5));
                let inner = BLOCK - ROAD_WIDTH;
                let pavement = Vec3::new(centre.x, 0.1, centre.y);
                pieces.push(piece(Shape::Cube, pavement, Vec3::new(inner, 0.2, inner), Material::Concrete));
                let at = |x: f32, z: f32| Vec3::new(centre.x + x, 0.2, centre.y + z);
                match (bx, bz) {
                    (3, 2) => sphere_tower(at(0.0, 0.0), &mut pieces, &mut lights),
                    (2, 3) => lollipop(at(0.0, 0.0), &mut pieces, &mut lights),
                    (5, 0) => {
                        pieces.push(piece(Shape::Sphere, at(0.0, -6.0), Vec3::new(70.0, 30.0, 70.0), Material::Hill))
                    }
                    (4, 4) => {
                        pieces.push(piece(Shape::Pyramid, at(0.0, 14.0), Vec3::new(36.0, 28.0, 36.0), Material::Metal));
                        lights.push(point(at(0.0, 30.0), Vec3::new(1.0, 0.3, 0.8) * 120.0, 45.0));
                    }
                    _ => block(centre, &mut rng, &mut pieces, &mut lights),
                }
            }
        }
        // A fixed shuffle (Fisher–Yates with the seeded generator).
        for i in (1..lights.len()).rev() {
            let j = (rng.next_u64() % (i as u64 + 1)) as usize;
            lights.swap(i, j);
        }
        Self {
            pieces,
            cars: cars(),
            drones: drones(),
            fixed_lights: lights,
            sphere_building: sphere_building + Vec3::Y * 0.2,
        }
    }
}
// ANCHOR_END: layout

impl City {
    /// The tallest square tower (a box of facade or brick): the rooftop
    /// camera stands on it. Round towers have cone roofs, no place to stand.
    pub fn tallest_tower(&self) -> &Piece {
        let top = |piece: &Piece| piece.model.transform_point3(Vec3::Y * 0.5).y;
        self.pieces
            .iter()
            .filter(|p| p.shape == Shape::Cube && matches!(p.material, Material::Facade | Material::Brick))
            .max_by(|a, b| top(a).total_cmp(&top(b)))
            .expect("the city has square towers")
    }
}

impl Default for City {
    fn default() -> Self {
        Self::new()
    }
}

fn point(position: Vec3, colour: Vec3, range: f32) -> Light {
    Light { position, colour, range, kind: LightKind::Point }
}

/// Lamps along both sides of every road, every 24 m, clear of crossings.
/// Each is a spot light looking straight down, as street lamps are: a pool
/// on the road, and only grazing light on the walls beside it.
fn street_lamps(lines: &[f32], pieces: &mut Vec<Piece>, lights: &mut Vec<Light>) {
    let warm = Vec3::new(1.0, 0.72, 0.42) * 45.0;
    let down = LightKind::Spot { direction: Vec3::NEG_Y, inner: 45f32.to_radians(), outer: 70f32.to_radians() };
    for &line in lines {
        for side in [-1.0, 1.0] {
            let across = line + side * (ROAD_WIDTH / 2.0 + 1.2);
            let mut along = -HALF + 12.0;
            while along < HALF - 6.0 {
                let near_crossing = lines.iter().any(|&l| (l - along).abs() < ROAD_WIDTH);
                if !near_crossing && across.abs() < HALF + 1.0 {
                    for (x, z) in [(across, along), (along, across)] {
                        pieces.push(piece(
                            Shape::Cylinder,
                            Vec3::new(x, 3.5, z),
                            Vec3::new(0.25, 7.0, 0.25),
                            Material::Metal,
                        ));
                        pieces.push(piece(Shape::Sphere, Vec3::new(x, 7.1, z), Vec3::splat(0.8), Material::Lamp));
                        lights.push(Light { position: Vec3::new(x, 6.6, z), colour: warm, range: 18.0, kind: down });
                    }
                }
                along += 24.0;
            }
        }
    }
}

/// The glass sphere on a pedestal, with a light at its foot.
fn sphere_tower(base: Vec3, pieces: &mut Vec<Piece>, lights: &mut Vec<Light>) {
    pieces.push(piece(Shape::Cylinder, base + Vec3::Y * 6.0, Vec3::new(9.0, 12.0, 9.0), Material::Concrete));
    pieces.push(piece(Shape::Sphere, base + Vec3::Y * 24.0, Vec3::splat(28.0), Material::Glass));
    pieces.push(piece(Shape::Torus, base + Vec3::Y * 12.5, Vec3::new(18.0, 6.0, 18.0), Material::Neon));
    lights.push(point(base + Vec3::new(0.0, 13.0, 0.0), Vec3::new(0.3, 0.7, 1.0) * 150.0, 40.0));
}

/// The "lollipop": a thin tower with a glowing ball on top, the light inside it.
fn lollipop(base: Vec3, pieces: &mut Vec<Piece>, lights: &mut Vec<Light>) {
    pieces.push(piece(Shape::Cylinder, base + Vec3::Y * 35.0, Vec3::new(2.4, 70.0, 2.4), Material::Metal));
    pieces.push(piece(Shape::Sphere, base + Vec3::Y * 74.0, Vec3::splat(12.0), Material::Neon));
    lights.push(point(base + Vec3::Y * 74.0, Vec3::new(0.4, 0.9, 1.0) * 400.0, 70.0));
}

/// One ordinary block: towers, a round tower, or low buildings; taller
/// towards the middle of the city. Some towers wear a neon ring and a light.
fn block(centre: Vec2, rng: &mut Rng, pieces: &mut Vec<Piece>, lights: &mut Vec<Light>) {
    let central = 1.0 - (centre.length() / (HALF * 1.3)).min(1.0);
    let kind = rng.unit();
    let spots: &[Vec2] = if kind < 0.5 {
        &[Vec2::new(-11.0, -11.0), Vec2::new(11.0, -11.0), Vec2::new(-11.0, 11.0), Vec2::new(11.0, 11.0)]
    } else {
        &[Vec2::new(0.0, 0.0)]
    };
    for &spot in spots {
        let position = Vec3::new(centre.x + spot.x, 0.2, centre.y + spot.y);
        let size = if spots.len() == 1 { rng.range(20.0, 30.0) } else { rng.range(9.0, 16.0) };
        let height = rng.range(10.0, 30.0) + central * rng.range(20.0, 80.0);
        if rng.unit() < 0.3 {
            // A round tower with a cone roof.
            let radius = size * 0.9;
            pieces.push(piece(
                Shape::Cylinder,
                position + Vec3::Y * height / 2.0,
                Vec3::new(radius, height, radius),
                Material::Facade,
            ));
            pieces.push(piece(
                Shape::Cone,
                position + Vec3::Y * (height + 4.0),
                Vec3::new(radius, 8.0, radius),
                Material::Metal,
            ));
        } else {
            let material = if height < 22.0 { Material::Brick } else { Material::Facade };
            pieces.push(piece(Shape::Cube, position + Vec3::Y * height / 2.0, Vec3::new(size, height, size), material));
            pieces.push(piece(
                Shape::Cube,
                position + Vec3::Y * (height + 1.0),
                Vec3::new(size * 0.5, 2.0, size * 0.5),
                Material::Concrete,
            ));
        }
        if height > 35.0 && rng.unit() < 0.6 {
            let ring = position + Vec3::Y * (height * 0.7);
            pieces.push(piece(Shape::Torus, ring, Vec3::new(size * 1.3, 2.0, size * 1.3), Material::Neon));
            let hue = rng.unit();
            let colour = Vec3::new(0.2 + 0.8 * hue, 0.4, 1.0 - 0.7 * hue) * 90.0;
            lights.push(point(ring + Vec3::new(size * 0.8, 0.0, 0.0), colour, 32.0));
        }
    }
}

/// Ten cars, each on its own loop around blocks of the city, at its own
/// height and speed.
fn cars() -> Vec<Car> {
    // (corner x, corner z, blocks ahead, blocks across, turn left, height, speed, lane)
    let loops = [
        (-120.0, 120.0, 2, 2, true, 4.0, 14.0, 3.0),
        (0.0, 60.0, 3, 2, true, 6.0, 11.0, -3.0),
        (60.0, 180.0, 4, 1, false, 5.0, 16.0, 3.0),
        (-60.0, 0.0, 1, 3, true, 9.0, 12.0, 3.0),
        (120.0, 120.0, 5, 2, true, 12.0, 18.0, -3.0),
        (-180.0, 180.0, 6, 6, false, 16.0, 20.0, 3.0),
        (0.0, 0.0, 2, 1, false, 3.5, 9.0, 3.0),
        (-120.0, -60.0, 1, 1, true, 7.0, 10.0, -3.0),
        (60.0, 60.0, 2, 2, false, 20.0, 15.0, -3.0),
        (-60.0, 180.0, 3, 2, false, 25.0, 13.0, 3.0),
    ];
    let paints = [Material::CarPaint, Material::Metal, Material::Drone];
    loops
        .iter()
        .enumerate()
        .map(|(i, &(x, z, ahead, across, left, height, speed, lane))| {
            let radius = 9.0;
            let (depth, width) = (ahead as f32 * BLOCK, across as f32 * BLOCK);
            let segments = SegmentedPath::rounded_rectangle(depth, width, radius, left);
            // Start at the corner, facing −z, where the first straight begins,
            // in a lane beside the road's centre line.
            let start = Vec2::new(x + lane, z - radius);
            Car {
                path: SegmentedPath { start, height, heading: 0.0, segments, speed },
                paint: paints[i % paints.len()],
            }
        })
        .collect()
}

fn drones() -> Vec<Drone> {
    [(-90.0, 32.0, -90.0), (90.0, 40.0, 30.0), (-30.0, 28.0, 90.0), (150.0, 36.0, -150.0)]
        .iter()
        .enumerate()
        .map(|(i, &(x, y, z))| Drone { position: Vec3::new(x, y, z), phase: i as f32 * 0.9 })
        .collect()
}

// ANCHOR: moving
/// The moving parts at one moment: cars at their clock's time on their
/// paths, drones bobbing with spinning propellers at theirs. A pure
/// function of the two clocks' times.
pub struct Traffic {
    /// Each car's body, glass and lamps (chapter 09 draws a model instead).
    pub car_parts: Vec<Piece>,
    /// Each drone's body, arms and spinning propellers.
    pub drone_parts: Vec<Piece>,
    pub lights: Vec<Light>,
    /// Where each car is, for a camera that follows one.
    pub cars: Vec<Pose>,
    /// Where each drone's body is, for a camera that rides with one.
    pub drones: Vec<Vec3>,
}

impl Traffic {
    /// Every moving piece: the cars' parts, then the drones'.
    pub fn pieces(&self) -> Vec<Piece> {
        self.car_parts.iter().chain(&self.drone_parts).copied().collect()
    }
}

impl City {
    pub fn traffic(&self, car_time: f32, drone_time: f32) -> Traffic {
        let mut pieces = Vec::new();
        let mut drone_parts = Vec::new();
        let mut lights = Vec::new();
        let mut poses = Vec::new();
        let mut drones = Vec::new();
        for car in &self.cars {
            // ANCHOR: car_pose
            let pose = car.path.at(car_time);
            let place = Mat4::from_rotation_translation(Quat::from_rotation_y(pose.heading), pose.position);
            // ANCHOR_END: car_pose
            let part = |shape, offset: Vec3, scale: Vec3, material| Piece {
                shape,
                model: place * Mat4::from_scale_rotation_translation(scale, Quat::IDENTITY, offset),
                material,
            };
            pieces.push(part(Shape::Cube, Vec3::new(0.0, 0.45, 0.0), Vec3::new(2.0, 0.9, 4.4), car.paint));
            pieces.push(part(Shape::Cube, Vec3::new(0.0, 1.2, 0.3), Vec3::new(1.6, 0.7, 2.2), Material::Glass));
            for side in [-0.6, 0.6] {
                pieces.push(part(
                    Shape::Cube,
                    Vec3::new(side, 0.5, -2.22),
                    Vec3::new(0.4, 0.2, 0.1),
                    Material::Headlight,
                ));
                pieces.push(part(
                    Shape::Cube,
                    Vec3::new(side, 0.55, 2.22),
                    Vec3::new(0.4, 0.15, 0.1),
                    Material::TailLight,
                ));
            }
            // ANCHOR: car_lights
            // The headlight: a spot riding with the car, looking ahead and a little down.
            let ahead = pose.forward();
            let down = (ahead - Vec3::Y * 0.22).normalize();
            let inner = 16f32.to_radians();
            lights.push(Light {
                position: place.transform_point3(Vec3::new(0.0, 0.5, -2.4)),
                colour: Vec3::new(1.0, 0.92, 0.8) * 500.0,
                range: 70.0,
                kind: LightKind::Spot { direction: down, inner, outer: 28f32.to_radians() },
            });
            lights.push(point(
                place.transform_point3(Vec3::new(0.0, 0.55, 2.6)),
                Vec3::new(1.0, 0.05, 0.02) * 10.0,
                7.0,
            ));
            // ANCHOR_END: car_lights
            poses.push(pose);
        }
        for drone in &self.drones {
            // ANCHOR: drone_bob
            let t = drone_time + drone.phase;
            let centre = drone.position + Vec3::Y * DRONE_BOB_HEIGHT * (TAU * t / DRONE_BOB_PERIOD).sin();
            // ANCHOR_END: drone_bob
            let place = Mat4::from_rotation_translation(Quat::from_rotation_y(0.1 * t), centre);
            let part = |shape, offset: Vec3, rotation: Quat, scale: Vec3, material| Piece {
                shape,
                model: place * Mat4::from_scale_rotation_translation(scale, rotation, offset),
                material,
            };
            drone_parts.push(part(
                Shape::Sphere,
                Vec3::ZERO,
                Quat::IDENTITY,
                Vec3::new(2.2, 0.7, 2.2),
                Material::Drone,
            ));
            drone_parts.push(part(Shape::Sphere, Vec3::Y * -0.4, Quat::IDENTITY, Vec3::splat(0.45), Material::Neon));
            for arm in 0..4 {
                let angle = FRAC_PI_4 + FRAC_PI_2 * arm as f32;
                let (s, c) = angle.sin_cos();
                let turn = Quat::from_rotation_y(-angle);
                drone_parts.push(part(
                    Shape::Cube,
                    Vec3::new(c, 0.0, s) * 1.6,
                    turn,
                    Vec3::new(2.2, 0.15, 0.2),
                    Material::Metal,
                ));
                // Propellers spin fast, alternate ones the other way.
                let spin = Quat::from_rotation_y(if arm % 2 == 0 { 40.0 } else { -40.0 } * t);
                let tip = Vec3::new(c, 0.0, s) * 2.7 + Vec3::Y * 0.3;
                drone_parts.push(part(Shape::Cube, tip, spin, Vec3::new(1.6, 0.04, 0.16), Material::Metal));
                drone_parts.push(part(
                    Shape::Cylinder,
                    tip - Vec3::Y * 0.15,
                    Quat::IDENTITY,
                    Vec3::new(0.2, 0.3, 0.2),
                    Material::Drone,
                ));
            }
            lights.push(point(centre - Vec3::Y * 0.8, Vec3::new(0.3, 0.8, 1.0) * 25.0, 12.0));
            drones.push(centre);
        }
        Traffic { car_parts: pieces, drone_parts, lights, cars: poses, drones }
    }
}
// ANCHOR_END: moving

/// The cars' and the drones' clocks, each pausable on its own.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Clocks {
    pub cars: PausableClock,
    pub drones: PausableClock,
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_city_has_what_the_chapter_promises() {
        let city = City::new();
        assert!(city.cars.len() >= 8, "at least 8 cars");
        assert_eq!(city.drones.len(), 4);
        let traffic = city.traffic(3.0, 3.0);
        let lights = city.fixed_lights.len() + traffic.lights.len();
        assert!(lights >= 256, "the night city has {lights} lights");
        assert!(city.pieces.len() > 200, "dense enough to fly through: {} pieces", city.pieces.len());
        for shape in [Shape::Sphere, Shape::Cylinder, Shape::Cone, Shape::Torus, Shape::Pyramid] {
            assert!(city.pieces.iter().any(|p| p.shape == shape), "{shape:?} is used");
        }
    }

    /// The numbers the book quotes: change the layout, and this test says
    /// which page to change too.
    #[test]
    fn the_night_has_339_lights_as_book_page_08_says() {
        let city = City::new();
        let lamps = city.fixed_lights.iter().filter(|l| matches!(l.kind, LightKind::Spot { .. })).count();
        let buildings = city.fixed_lights.len() - lamps;
        let traffic = city.traffic(0.0, 0.0);
        assert_eq!((lamps, buildings, city.cars.len(), city.drones.len()), (288, 27, 10, 4));
        assert_eq!(traffic.lights.len(), 2 * 10 + 4);
        assert_eq!(city.fixed_lights.len() + traffic.lights.len(), 339);
    }

    #[test]
    fn every_car_path_is_closed_and_the_same_every_time() {
        let (a, b) = (City::new(), City::new());
        assert_eq!(a.cars, b.cars);
        assert_eq!(a.fixed_lights, b.fixed_lights);
        for car in &a.cars {
            let (start, lap) = (car.path.at(0.0).position, car.path.at(car.path.period() * 0.999_999).position);
            assert!(start.distance(lap) < 0.05, "{start} vs {lap}");
            assert!(car.path.speed > 0.0);
        }
        let speeds: std::collections::BTreeSet<u32> = a.cars.iter().map(|c| c.path.speed as u32).collect();
        assert!(speeds.len() >= 8, "cars have speeds of their own");
    }

    #[test]
    fn headlights_ride_with_their_cars() {
        let city = City::new();
        for t in [0.0, 4.0, 17.5] {
            let traffic = city.traffic(t, 0.0);
            for (car, pose) in traffic.cars.iter().enumerate() {
                let spot = traffic.lights[2 * car];
                let LightKind::Spot { direction, .. } = spot.kind else {
                    panic!("the first light of a car is its headlight")
                };
                assert!(spot.position.distance(pose.position) < 3.0);
                assert!(direction.dot(pose.forward()) > 0.95, "the headlight looks where the car goes");
            }
        }
    }
}
