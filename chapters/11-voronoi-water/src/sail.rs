//! The sail and its sailor: two OBJ + MTL models with several materials
//! each, read by chapter 09's loader and drawn by chapter 10's shadowed
//! renderer with the boat's own model matrix, so they ride the waves with
//! it and cast its shadow; and the sail's swell: the cloth bent every
//! frame, on the CPU, by the wind blowing across it.

use std::collections::BTreeSet;
use std::path::Path;

use common::glam::{Vec2, Vec3};
use textures::mesh::{ModelData, TexturedVertex};
use textures::obj::{self, LoadedModel, ModelError, ReadFile};

use crate::{boat, sea};

/// The sail, its boom and sheet, in the boat's frame.
pub const SAIL: &str = "models/sail/sail.obj";
/// The sailor at the helm, in the boat's frame.
pub const SAILOR: &str = "models/sailor/sailor.obj";
/// The sail's material that swells; the boom and the sheet stay put.
pub const CLOTH: &str = "cloth";

/// The sail's and the sailor's files, carried in the binary.
const FILES: &[(&str, &[u8])] = textures::builtin![
    "models/sail/sail.obj",
    "models/sail/sail.mtl",
    "models/sailor/sailor.obj",
    "models/sailor/sailor.mtl",
];

/// A file of the sail's or the sailor's, by its path under `assets/`.
pub fn read_builtin(path: &Path) -> Result<Vec<u8>, common::files::ReadError> {
    textures::builtin::find(FILES, path)
}

/// How far the middle of the sail bellies out with the wind straight
/// across it, metres: a sixth of its 4.3 m foot, a full cruising sail.
pub const SWELL_DEPTH: f32 = 0.7;

/// Where the wind blows to, in the xz plane: the way the longest waves run.
pub fn wind() -> Vec2 {
    Vec2::from_angle(sea::WIND_ANGLE)
}

// ANCHOR: swell
/// The belly's shape over the sail, 0 to 1: `u` runs along the foot from
/// the mast, `v` up the mast from the boom, and the cloth is the triangle
/// u, v ≥ 0, u + v ≤ 1. The product of u, v and 1 − u − v (each in
/// proportion to the distance to one edge) is zero on all three edges
/// (mast, boom and the free trailing edge) and deepest at the middle,
/// (1/3, 1/3), where 27 scales it to 1.
pub fn belly(u: f32, v: f32) -> f32 {
    (27.0 * u * v * (1.0 - u - v)).max(0.0)
}

/// How much of the wind blows across a sail set along the keel of a boat
/// heading `heading`: the wind's component along the boat's starboard
/// side, from −1 (the wind pushes the sail to port) to 1 (to starboard).
/// Along the keel, from ahead or astern, nothing fills it.
pub fn wind_across(heading: f32, wind: Vec2) -> f32 {
    let ahead = boat::forward(heading);
    let starboard = Vec2::new(-ahead.y, ahead.x);
    starboard.dot(wind)
}

/// How far the cloth at (u, v) moves along the boat's x axis (starboard)
/// with `across` of the wind across it: downwind, as deep as the belly.
pub fn swell(u: f32, v: f32, across: f32) -> f32 {
    SWELL_DEPTH * across * belly(u, v)
}
// ANCHOR_END: swell

/// The sail and the sailor as loaded, the sail at rest (flat).
#[derive(Clone, Debug)]
pub struct Rig {
    pub sail: ModelData,
    pub sailor: ModelData,
    /// The sail's vertices that are cloth, and the cloth's triangles.
    cloth: Vec<usize>,
    cloth_triangles: Vec<[usize; 3]>,
    /// What the loader had to make up, one line each.
    pub warnings: Vec<String>,
}

// ANCHOR: load
/// Loads the sail and the sailor through `read`, as the boat is loaded.
/// The chapter carries both files of each model, so a missing MTL is an
/// error here (naming it), where a learner's model would get grey.
pub fn load(read: ReadFile) -> Result<Rig, ModelError> {
    let sail = load_with_materials(SAIL, read)?;
    let sailor = load_with_materials(SAILOR, read)?;
    let model = &sail.model;
    let material = model
        .materials
        .iter()
        .position(|m| m.name == CLOTH)
        .ok_or_else(|| ModelError(format!("{SAIL}: no material named `{CLOTH}` to swell")))?;
    let cloth_triangles: Vec<[usize; 3]> = model
        .parts
        .iter()
        .filter(|part| part.material == material)
        .flat_map(|part| model.indices[part.indices.start as usize..part.indices.end as usize].chunks_exact(3))
        .map(|t| [t[0] as usize, t[1] as usize, t[2] as usize])
        .collect();
    let cloth: BTreeSet<usize> = cloth_triangles.iter().flatten().copied().collect();
    let warnings = sail.warnings.iter().chain(&sailor.warnings).cloned().collect();
    Ok(Rig { sail: sail.model, sailor: sailor.model, cloth: cloth.into_iter().collect(), cloth_triangles, warnings })
}

fn load_with_materials(path: &str, read: ReadFile) -> Result<LoadedModel, ModelError> {
    let loaded = obj::load(Path::new(path), read)?;
    if loaded.material_files.is_empty() {
        let why = loaded.warnings.first().cloned().unwrap_or_else(|| "it names no MTL file".into());
        return Err(ModelError(format!("{path}: its materials could not be read: {why}")));
    }
    Ok(loaded)
}
// ANCHOR_END: load

// ANCHOR: bend
impl Rig {
    /// The sail's vertices with `across` of the wind across it: each cloth
    /// vertex moved along the boat's x by [`swell`] at its texture
    /// coordinates (the cloth's own u and v, as the model writes them),
    /// then its normal made again from the bent triangles around it, each
    /// side of the cloth from its own.
    pub fn bent_sail(&self, across: f32) -> Vec<TexturedVertex> {
        let mut vertices = self.sail.vertices.clone();
        for &i in &self.cloth {
            let (u, v) = cloth_coordinates(&vertices[i]);
            vertices[i].position[0] += swell(u, v, across);
        }
        let mut normals = vec![Vec3::ZERO; vertices.len()];
        for &[a, b, c] in &self.cloth_triangles {
            let at = |i: usize| Vec3::from(vertices[i].position);
            // The cross product's length is twice the triangle's area:
            // bigger triangles weigh more.
            let face = (at(b) - at(a)).cross(at(c) - at(a));
            for i in [a, b, c] {
                normals[i] += face;
            }
        }
        for &i in &self.cloth {
            let rest = Vec3::from(self.sail.vertices[i].normal);
            vertices[i].normal = normals[i].try_normalize().unwrap_or(rest).into();
        }
        vertices
    }

    /// The sail's cloth vertices, how many.
    pub fn cloth_vertices(&self) -> usize {
        self.cloth.len()
    }
}

/// Where a cloth vertex is on the sail, (u, v): its texture coordinates,
/// with v turned back up the mast (the loader turns OBJ's v, up the image,
/// into wgpu's, down it).
fn cloth_coordinates(vertex: &TexturedVertex) -> (f32, f32) {
    (vertex.uv[0], 1.0 - vertex.uv[1])
}
// ANCHOR_END: bend

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_belly_is_flat_at_the_edges_and_deepest_in_the_middle() {
        for k in 0..=20 {
            let t = k as f32 / 20.0;
            // The mast (u = 0), the boom (v = 0), the trailing edge (u + v = 1).
            for (u, v) in [(0.0, t), (t, 0.0), (t, 1.0 - t)] {
                assert!(belly(u, v).abs() < 1e-6, "belly({u}, {v}) = {}", belly(u, v));
            }
        }
        let middle = belly(1.0 / 3.0, 1.0 / 3.0);
        assert!((middle - 1.0).abs() < 1e-5, "the middle bellies {middle}");
        for i in 0..=30 {
            for j in 0..=30 - i {
                let (u, v) = (i as f32 / 30.0, j as f32 / 30.0);
                assert!(belly(u, v) <= middle + 1e-6, "({u}, {v}) bellies deeper than the middle");
            }
        }
    }

    /// A pose at `heading`, somewhere on the sea, tilted by `pitch` and
    /// `roll`, and its model matrix: the one the renderer draws the boat,
    /// the sail and the sailor with.
    fn model_at(heading: f32, pitch: f32, roll: f32) -> common::glam::Mat4 {
        let helm = boat::Helm { position: Vec2::new(700.0, 1300.0), heading, speed: 5.0 };
        boat::Pose { helm, heave: 0.4, pitch, roll }.model()
    }

    /// The boat's right side and its bow in the world's xz plane, as its
    /// model matrix places the model's +x and −z: not from the expression
    /// `wind_across` turns the heading into.
    fn sides(model: common::glam::Mat4) -> (Vec2, Vec2) {
        let flat = |v: Vec3| Vec2::new(v.x, v.z).normalize();
        (flat(model.transform_vector3(Vec3::X)), flat(model.transform_vector3(Vec3::NEG_Z)))
    }

    #[test]
    fn the_wind_across_is_the_winds_part_along_the_boats_right_side() {
        for heading in [0.0, 0.9, 2.5, 4.0, 5.9] {
            let (starboard, bow) = sides(model_at(heading, 0.0, 0.0));
            // From the beam: all of it, and from the other beam, all of it
            // the other way; along the keel, from ahead or astern, none.
            assert!((wind_across(heading, starboard) - 1.0).abs() < 1e-5, "heading {heading}");
            assert!((wind_across(heading, -starboard) + 1.0).abs() < 1e-5, "heading {heading}");
            for along in [bow, -bow] {
                assert!(wind_across(heading, along).abs() < 1e-5, "heading {heading}");
                assert!(swell(0.3, 0.3, wind_across(heading, along)).abs() < 1e-5);
            }
            // Halfway between: as the cosine says.
            let quarter = (bow + starboard).normalize();
            assert!((wind_across(heading, quarter) - std::f32::consts::FRAC_1_SQRT_2).abs() < 1e-5);
        }
    }

    /// The cloth fills downwind, measured where it is drawn: the bent sail
    /// and the flat one placed by the boat's model matrix (on a level sea
    /// and rolled and pitched on a wave), each cloth vertex's move in the
    /// world compared with the wind. None moves against it, and the belly
    /// moves with it by its depth times the wind across.
    #[test]
    fn the_cloth_moves_downwind_in_the_world() {
        let rig = load(&read_builtin).unwrap();
        let wind = wind();
        let downwind = Vec3::new(wind.x, 0.0, wind.y);
        for heading in [0.0, 0.9, 2.5, 4.0, 5.9] {
            for (pitch, roll) in [(0.0, 0.0), (0.08, -0.12)] {
                let model = model_at(heading, pitch, roll);
                let across = wind_across(heading, wind);
                let bent = rig.bent_sail(across);
                let mut deepest = 0.0f32;
                for &i in &rig.cloth {
                    let at = |p: [f32; 3]| model.transform_point3(Vec3::from(p));
                    let moved = at(bent[i].position) - at(rig.sail.vertices[i].position);
                    let with_the_wind = moved.dot(downwind);
                    assert!(with_the_wind >= -1e-4, "heading {heading}: vertex {i} moves {with_the_wind} m upwind");
                    deepest = deepest.max(with_the_wind);
                }
                // The wind's part across the boat's right side, as its
                // model matrix has it, times the belly's depth: the middle
                // moves that far downwind (less the roll's tilt of the mast).
                let (starboard, _) = sides(model);
                let expected = SWELL_DEPTH * starboard.dot(wind).powi(2);
                assert!(
                    (deepest - expected).abs() < 0.02 * SWELL_DEPTH + 1e-4,
                    "heading {heading}, pitch {pitch}, roll {roll}: the belly moved {deepest} m downwind, not {expected}"
                );
            }
        }
    }

    // ANCHOR: rig_test
    #[test]
    fn the_rig_loads_with_its_materials() {
        let rig = load(&read_builtin).unwrap();
        assert!(rig.warnings.is_empty(), "{:?}", rig.warnings);
        let names = |m: &ModelData| m.materials.iter().map(|m| m.name.clone()).collect::<Vec<_>>();
        assert_eq!(names(&rig.sail), ["cloth", "spar", "rope"]);
        assert_eq!(names(&rig.sailor), ["skin", "tunic", "trousers", "hat", "boots"]);
        // Every material is drawn: one part each.
        assert_eq!(rig.sail.parts.len(), 3);
        assert_eq!(rig.sailor.parts.len(), 5);
        // Low-poly: 6² cloth triangles a side and two boxes; ten boxes
        // and a six-sided cap.
        assert_eq!(rig.sail.triangle_count(), 2 * 36 + 2 * 12);
        assert_eq!(rig.sailor.triangle_count(), 10 * 12 + 6 + 4);
        // 28 corners of the cloth's grid, on each side.
        assert_eq!(rig.cloth_vertices(), 2 * 28);
    }

    #[test]
    fn a_missing_model_file_is_an_error_naming_it() {
        for missing in [SAIL, "models/sail/sail.mtl", SAILOR, "models/sailor/sailor.mtl"] {
            let without = |path: &Path| {
                if obj::normalise(path) == Path::new(missing) {
                    Err(common::files::ReadError { path: path.to_path_buf(), reason: "no such file".into() })
                } else {
                    read_builtin(path)
                }
            };
            let error = load(&without).unwrap_err().to_string();
            assert!(error.contains(missing), "without {missing}: {error}");
        }
    }
    // ANCHOR_END: rig_test

    #[test]
    fn only_the_cloth_bends_and_it_stays_inside_the_boats_box() {
        let rig = load(&read_builtin).unwrap();
        // No wind across: the sail as it was made.
        for (rest, now) in rig.sail.vertices.iter().zip(rig.bent_sail(0.0)) {
            assert_eq!(now.position, rest.position);
            assert!(Vec3::from(now.normal).distance(rest.normal.into()) < 1e-6);
        }
        for across in [-1.0, 1.0] {
            let bent = rig.bent_sail(across);
            let mut deepest = 0.0f32;
            for (i, (rest, now)) in rig.sail.vertices.iter().zip(&bent).enumerate() {
                if !rig.cloth.contains(&i) {
                    assert_eq!(now, rest, "the boom and the sheet stay put");
                    continue;
                }
                let moved = now.position[0] - rest.position[0];
                assert_eq!(now.position[1..], rest.position[1..], "only x moves");
                let (u, v) = cloth_coordinates(rest);
                assert!((moved - swell(u, v, across)).abs() < 1e-6);
                deepest = deepest.max(moved * across);
                // Unit normals, each side's still facing its own side.
                assert!((Vec3::from(now.normal).length() - 1.0).abs() < 1e-5);
                assert!(now.normal[0] * rest.normal[0] > 0.0);
            }
            // The cloth's grid has a corner at the middle, (2/6, 2/6).
            assert!((deepest - SWELL_DEPTH).abs() < 1e-4, "deepest {deepest}");
            // The normals follow the bent surface x(y, z): they lean as its
            // slopes say, d·a·∂belly/∂u / foot along z and ∂belly/∂v / luff
            // along y (the cloth's u runs along z, its v along y).
            let span = |axis: usize| {
                let along = rig.cloth.iter().map(|&i| rig.sail.vertices[i].position[axis]);
                along.clone().fold(f32::MIN, f32::max) - along.fold(f32::MAX, f32::min)
            };
            let (foot, luff) = (span(2), span(1));
            let mut worst = 0.0f32;
            for &i in &rig.cloth {
                let (u, v) = cloth_coordinates(&rig.sail.vertices[i]);
                // Inside the cloth, where triangles lie on every side.
                if u < 1e-3 || v < 1e-3 || u + v > 1.0 - 1e-3 {
                    continue;
                }
                let slope_z = SWELL_DEPTH * across * 27.0 * v * (1.0 - 2.0 * u - v) / foot;
                let slope_y = SWELL_DEPTH * across * 27.0 * u * (1.0 - u - 2.0 * v) / luff;
                let side = rig.sail.vertices[i].normal[0].signum();
                let exact = Vec3::new(side, -side * slope_y, -side * slope_z).normalize();
                worst = worst.max(Vec3::from(bent[i].normal).angle_between(exact).to_degrees());
            }
            assert!(worst < 1.0, "a normal is {worst}° off the bent surface's");
        }
        // The sail, bent either way, and the sailor stay inside the box the
        // sun's shadow map is fitted to.
        let inside = |p: [f32; 3]| {
            p[0].abs() <= boat::BEAM / 2.0 && (0.0..=boat::MAST_TOP).contains(&p[1]) && p[2].abs() <= boat::LENGTH / 2.0
        };
        for bent in [rig.bent_sail(-1.0), rig.bent_sail(1.0), rig.sailor.vertices.clone()] {
            assert!(bent.iter().all(|v| inside(v.position)));
        }
    }
}
