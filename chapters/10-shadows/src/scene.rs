//! The level as things to draw: its blocks baked into one textured model
//! (chapter 09's textures at their size in metres), its props and the
//! player as chapter 09's OBJ models, its lantern and the lantern's light,
//! and the sun's path over the day.

use std::path::Path;

use common::files::ReadError;
use common::glam::{Mat4, Quat, Vec2, Vec3};
use common::{MeshData, primitives};
use lighting::city::Shape;
use lighting::lights::{Daylight, Light, LightKind, daylight};
use textures::mesh::{MaterialDesc, ModelData, ModelInstance};
use textures::scenes::world_uvs;

use crate::game::{Game, Level, PropKind, Surface};

/// The files this chapter carries: the models it dresses the level with,
/// the textures of the level and the models, and the background layers.
/// Only these, not all of chapter 09's, so that the browser downloads less.
const FILES: &[(&str, &[u8])] = textures::builtin![
    "textures/concrete/albedo.png",
    "textures/concrete/normal.png",
    "textures/brick/albedo.png",
    "textures/brick/normal.png",
    "textures/metal/albedo.png",
    "textures/metal/normal.png",
    "models/tree/tree.obj",
    "models/tree/tree.mtl",
    "models/rock/rock.obj",
    "models/rock/rock.mtl",
    "models/crate/crate.obj",
    "models/crate/crate.mtl",
    "models/robot/robot.obj",
    "models/robot/robot.mtl",
    "models/island/island.obj",
    "models/island/island.mtl",
    "models/sphere/sphere.obj",
    "models/sphere/sphere.mtl",
    "textures/wood/albedo.png",
    "textures/wood/normal.png",
    "layers/far.png",
    "layers/middle.png",
    "layers/near.png",
];

/// A built-in file by its path under `assets/`.
pub fn read(path: &Path) -> Result<Vec<u8>, ReadError> {
    textures::builtin::find(FILES, path)
}

// ANCHOR: blocks
/// A surface's texture and how many metres one repeat covers.
fn surface_texture(surface: Surface) -> (&'static str, f32, f32, f32) {
    // (name, metres per repeat, specular, shininess)
    match surface {
        Surface::Concrete => ("concrete", 4.0, 0.1, 12.0),
        Surface::Brick => ("brick", 1.0, 0.08, 10.0),
        Surface::Metal => ("metal", 2.0, 0.6, 64.0),
    }
}

/// Every block of the level as one model: a box per block, textured at
/// the texture's size in metres, one part per surface.
pub fn level_model(level: &Level) -> ModelData {
    let surfaces = [Surface::Concrete, Surface::Brick, Surface::Metal];
    let materials = surfaces
        .iter()
        .map(|&s| {
            let (name, _, specular, shininess) = surface_texture(s);
            MaterialDesc {
                albedo_map: Some(format!("textures/{name}/albedo.png").into()),
                normal_map: Some(format!("textures/{name}/normal.png").into()),
                ..MaterialDesc::plain(name, Vec3::ONE, specular, shininess)
            }
        })
        .collect();
    let mut model = ModelData { materials, ..Default::default() };
    let cube: MeshData = primitives::cube();
    for block in &level.blocks {
        let size = block.aabb.size().extend(2.0 * block.depth);
        let at = Mat4::from_scale_rotation_translation(size, Quat::IDENTITY, block.aabb.centre().extend(0.0));
        let material = surfaces.iter().position(|s| *s == block.surface).unwrap_or(0);
        let uvs = world_uvs(&cube, at, Shape::Cube, surface_texture(block.surface).1);
        model.append(&cube, material, at, |_, i| uvs[i]);
    }
    model.group_by_material();
    model
}
// ANCHOR_END: blocks

/// Where each prop kind's model is, under `assets/`.
pub fn prop_model(kind: PropKind) -> &'static str {
    match kind {
        PropKind::Tree => "models/tree/tree.obj",
        PropKind::Rock => "models/rock/rock.obj",
        PropKind::Crate => "models/crate/crate.obj",
        PropKind::Island => "models/island/island.obj",
        PropKind::Sphere => "models/sphere/sphere.obj",
    }
}

pub const PLAYER_MODEL: &str = "models/robot/robot.obj";

/// The instances of `kind` in the level.
pub fn prop_instances(level: &Level, kind: PropKind) -> Vec<ModelInstance> {
    level
        .props
        .iter()
        .filter(|p| p.kind == kind)
        .map(|p| {
            let at = Mat4::from_scale_rotation_translation(Vec3::splat(p.scale), Quat::from_rotation_y(p.turn), p.base);
            ModelInstance::new(at, 1.0)
        })
        .collect()
}

/// The player's model placed on its box, turned the way it runs (the
/// model looks along +x).
pub fn player_instance(game: &Game) -> ModelInstance {
    let base = Vec2::new(game.player.aabb.centre().x, game.player.aabb.min.y).extend(0.0);
    let turn = if game.facing < 0.0 { std::f32::consts::PI } else { 0.0 };
    ModelInstance::new(Mat4::from_rotation_translation(Quat::from_rotation_y(turn), base), 1.0)
}

// ANCHOR: lantern
/// How far the lantern's light reaches, metres: chapter 08's falloff is
/// exactly zero there, and its cube shadow map holds nothing farther.
pub const LANTERN_RANGE: f32 = 9.0;

/// The lantern's light: one of chapter 08's point lights, warm, at the
/// middle of its glass.
pub fn lantern_light(level: &Level) -> Light {
    Light {
        position: level.lantern,
        colour: Vec3::new(1.0, 0.72, 0.4) * 5.0,
        range: LANTERN_RANGE,
        kind: LightKind::Point,
    }
}

/// The lantern as a model around its light (the origin): glowing glass
/// between a metal base and cap, and a rod up to the ceiling above it.
/// The light is inside the glass, so the lantern itself must not cast
/// shadows into its own cube; the chapter leaves it out of those passes.
pub fn lantern_model(level: &Level) -> ModelData {
    let light = level.lantern;
    let ceiling = level
        .blocks
        .iter()
        .filter(|b| b.aabb.min.x <= light.x && light.x <= b.aabb.max.x && b.aabb.min.y > light.y)
        .map(|b| b.aabb.min.y)
        .fold(light.y + 0.5, f32::min);
    let glass = MaterialDesc {
        emissive: Vec3::new(1.0, 0.72, 0.4) * 3.0,
        ..MaterialDesc::plain("lantern glass", Vec3::new(1.0, 0.85, 0.6), 0.3, 24.0)
    };
    let metal = MaterialDesc::plain("lantern metal", Vec3::new(0.12, 0.11, 0.1), 0.5, 32.0);
    let mut model = ModelData { materials: vec![glass, metal], ..Default::default() };
    let cube: MeshData = primitives::cube();
    let mut add = |size: Vec3, centre_y: f32, material: usize| {
        let at = Mat4::from_scale_rotation_translation(size, Quat::IDENTITY, Vec3::new(0.0, centre_y, 0.0));
        model.append(&cube, material, at, |uv, _| uv);
    };
    add(Vec3::new(0.2, 0.26, 0.2), 0.0, 0);
    add(Vec3::new(0.26, 0.05, 0.26), 0.155, 1);
    add(Vec3::new(0.24, 0.04, 0.24), -0.15, 1);
    let rod_bottom = 0.18;
    let rod = (ceiling - light.y - rod_bottom).max(0.01);
    add(Vec3::new(0.025, rod, 0.025), rod_bottom + rod / 2.0, 1);
    model.group_by_material();
    model
}

/// The lantern's instance: its model moved to its light.
pub fn lantern_instance(level: &Level) -> ModelInstance {
    ModelInstance::new(Mat4::from_translation(level.lantern), 1.0)
}
// ANCHOR_END: lantern

/// The box around everything that can cast a shadow.
pub fn level_bounds(level: &Level) -> (Vec3, Vec3) {
    let mut low = Vec3::MAX;
    let mut high = Vec3::MIN;
    for block in &level.blocks {
        low = low.min(block.aabb.min.extend(-block.depth));
        high = high.max(block.aabb.max.extend(block.depth));
    }
    // Trees are the tallest props standing on something: 4.5 m at scale
    // 1. An island's base is its grassy top, at most 6.7 m across, with
    // 4.4 m of stone under it; the level's box grows to take in the
    // islands behind it.
    for p in &level.props {
        let (below, above, half) = match p.kind {
            PropKind::Island => (4.4, 0.0, 3.35),
            _ => (0.0, 4.5, 1.0),
        };
        low = low.min(p.base - Vec3::new(half, below, half) * p.scale);
        high = high.max(p.base + Vec3::new(half, above, half) * p.scale);
    }
    (low, high)
}

// ANCHOR: sun
/// The sun over the level at `phase` of the day (0.25 sunrise, 0.5 noon,
/// 0.75 sunset): it rises on the left, passes overhead and sets on the
/// right, on an arc tilted 35° towards the camera, so shadows fall back
/// onto the ground behind what casts them where the camera can see them.
/// Colours come from chapter 08's daylight at the same phase.
pub fn sun_at(phase: f32) -> Daylight {
    let angle = (phase - 0.25) * std::f32::consts::TAU;
    let tilt = 35f32.to_radians();
    let direction = Vec3::new(-angle.cos(), angle.sin() * tilt.cos(), angle.sin() * tilt.sin());
    Daylight { direction, ..daylight(phase) }
}
// ANCHOR_END: sun
