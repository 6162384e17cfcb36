//! What the chapter draws, as data: chapter 08's city with textures (its
//! pieces baked into one model, texture coordinates scaled so every
//! texture keeps its size in metres), the stage a model stands on, and the
//! sampling lab's endless checkerboard; and which of these sets a camera
//! is in.

use std::path::PathBuf;

use common::glam::{Mat4, Quat, Vec2, Vec3};
use common::{MeshData, primitives};
use lighting::city::{City, Material, Piece, Shape};
use lighting::lights::{Light, LightKind};

use crate::mesh::{MaterialDesc, ModelData};
use crate::tangents::triangle_tangents;

/// Which set the camera is in: each of the sets below is one.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Scene {
    /// Chapter 08's city, textured, with car models and the tower.
    City,
    /// A model on a stage, with a brick wall and a row of primitives.
    Stage,
    /// A checkerboard floor to the horizon, for comparing samplers.
    Lab,
}

// ANCHOR: texel_density
/// The city's textures and how many metres one repeat of each covers: a
/// brick is a quarter of a metre wide whether the wall is 5 m or 50 m.
pub fn city_texture(material: Material) -> Option<(&'static str, f32)> {
    match material {
        Material::Brick => Some(("brick", 1.0)),
        Material::Concrete => Some(("concrete", 4.0)),
        Material::Metal => Some(("metal", 4.0)),
        Material::Road => Some(("road", 12.0)),
        Material::Facade => Some(("facade", 16.0)),
        _ => None,
    }
}

/// Texture coordinates for `mesh` placed by `model`, so that one repeat of
/// the texture covers `tile` metres. Each vertex scales its u and v by how
/// many metres of surface one unit of u and of v spans there (the lengths
/// of ∂P/∂u and ∂P/∂v, from the triangles around it), over `tile`. Around
/// a closed shape (a cylinder's side, a torus), the repeats are rounded to
/// a whole number, or the texture would not meet itself at the seam.
pub fn world_uvs(mesh: &MeshData, model: Mat4, shape: Shape, tile: f32) -> Vec<Vec2> {
    let world: Vec<Vec3> = mesh.vertices.iter().map(|v| model.transform_point3(v.position.into())).collect();
    let uv: Vec<Vec2> = mesh.vertices.iter().map(|v| v.uv.into()).collect();
    let mut metres = vec![Vec2::ZERO; world.len()];
    let mut count = vec![0.0f32; world.len()];
    for t in mesh.indices.chunks_exact(3) {
        let corners = [0, 1, 2].map(|k| t[k] as usize);
        let Some((du, dv)) = triangle_tangents(corners.map(|i| world[i]), corners.map(|i| uv[i])) else { continue };
        for i in corners {
            metres[i] += Vec2::new(du.length(), dv.length());
            count[i] += 1.0;
        }
    }
    let per_vertex: Vec<Vec2> =
        metres.iter().zip(&count).map(|(m, &c)| if c > 0.0 { *m / c } else { Vec2::ONE }).collect();
    let (wraps_u, wraps_v) = match shape {
        Shape::Cylinder | Shape::Cone | Shape::Sphere => (true, false),
        Shape::Torus => (true, true),
        Shape::Cube | Shape::Pyramid | Shape::Ground => (false, false),
    };
    let whole = |widest: f32| (widest / tile).round().max(1.0);
    let widest = per_vertex.iter().fold(Vec2::ZERO, |a, b| a.max(*b));
    uv.iter()
        .zip(&per_vertex)
        .map(|(uv, m)| {
            let u = if wraps_u { uv.x * whole(widest.x) } else { uv.x * m.x / tile };
            let v = if wraps_v { uv.y * whole(widest.y) } else { uv.y * m.y / tile };
            Vec2::new(u, v)
        })
        .collect()
}
// ANCHOR_END: texel_density

/// Where a built-in texture lives, under `assets/`.
fn texture(name: &str, map: &str) -> PathBuf {
    PathBuf::from(format!("textures/{name}/{map}.png"))
}

/// The city's materials, one per chapter 08 `Material`, in its order:
/// the five textured ones with their maps, the rest as chapter 08 has them.
pub fn city_materials() -> Vec<MaterialDesc> {
    Material::ALL
        .iter()
        .map(|&m| {
            let s = m.surface();
            let name = format!("{m:?}").to_lowercase();
            match city_texture(m) {
                Some((texture_name, _)) => MaterialDesc {
                    name,
                    diffuse: Vec3::ONE,
                    specular: s.specular,
                    shininess: s.shininess,
                    // Facades: the albedo's alpha marks the lit windows.
                    emissive: if m == Material::Facade { Vec3::new(1.5, 1.1, 0.65) } else { Vec3::ZERO },
                    at_night: s.at_night,
                    vertex_colours: false,
                    albedo_map: Some(texture(texture_name, "albedo")),
                    normal_map: Some(texture(texture_name, "normal")),
                    roughness_map: None,
                    metallic_map: None,
                    texture_folders: Vec::new(),
                    roughness: None,
                    metallic: None,
                },
                None => MaterialDesc {
                    emissive: s.emissive,
                    at_night: s.at_night,
                    ..MaterialDesc::plain(&name, s.albedo, s.specular, s.shininess)
                },
            }
        })
        .collect()
}

// ANCHOR: bake
/// Chapter 08's pieces as one textured model: each piece's mesh placed in
/// the world, its texture coordinates scaled to the texture's size in
/// metres, its tangents computed there; then grouped by material, so the
/// whole city is one vertex buffer and one draw per material.
pub fn bake(pieces: &[Piece]) -> ModelData {
    let mut model = ModelData { materials: city_materials(), ..Default::default() };
    let meshes: Vec<MeshData> = Shape::ALL.iter().map(|s| s.mesh()).collect();
    for piece in pieces {
        let mesh = &meshes[Shape::ALL.iter().position(|s| *s == piece.shape).expect("every shape is in ALL")];
        let uvs = match city_texture(piece.material) {
            Some((_, tile)) => world_uvs(mesh, piece.model, piece.shape, tile),
            None => mesh.vertices.iter().map(|v| v.uv.into()).collect(),
        };
        model.append(mesh, piece.material as usize, piece.model, |_, i| uvs[i]);
    }
    model.group_by_material();
    model
}
// ANCHOR_END: bake

/// The north-west corner block, where the city gets the tower model
/// instead of its own buildings.
pub const TOWER_BLOCK: Vec2 = Vec2::new(-150.0, -150.0);

/// Whether `piece` is one of the buildings on the tower's block (street
/// lamps and the pavement stay).
pub fn on_tower_block(piece: &Piece) -> bool {
    let at = piece.model.w_axis.truncate();
    let inside = (at.x - TOWER_BLOCK.x).abs() < 20.0 && (at.z - TOWER_BLOCK.y).abs() < 20.0;
    inside && at.y > 0.3
}

/// The tower's place: in the middle of the block, on its pavement.
pub fn tower_placement() -> Mat4 {
    Mat4::from_translation(Vec3::new(TOWER_BLOCK.x, 0.2, TOWER_BLOCK.y))
}

/// The city's fixed pieces as the textured city draws them.
pub fn textured_city(city: &City) -> ModelData {
    let pieces: Vec<Piece> = city.pieces.iter().filter(|p| !on_tower_block(p)).copied().collect();
    bake(&pieces)
}

// ANCHOR: stage
/// The stage a model is shown on: a concrete floor, a brick wall behind,
/// and a row of `common`'s primitives on each side, each textured, so that
/// every primitive's texture coordinates and tangents are on show.
pub fn stage_set() -> ModelData {
    let concrete = MaterialDesc {
        albedo_map: Some(texture("concrete", "albedo")),
        normal_map: Some(texture("concrete", "normal")),
        ..MaterialDesc::plain("stage floor", Vec3::ONE, 0.1, 12.0)
    };
    let textured = |name: &str, specular, shininess| MaterialDesc {
        albedo_map: Some(texture(name, "albedo")),
        normal_map: Some(texture(name, "normal")),
        ..MaterialDesc::plain(name, Vec3::ONE, specular, shininess)
    };
    let mut model = ModelData {
        materials: vec![
            concrete,
            textured("brick", 0.08, 10.0),
            textured("metal", 0.6, 64.0),
            textured("facade", 0.3, 48.0),
        ],
        ..Default::default()
    };
    let place = |x: f32, y: f32, z: f32, size: Vec3| {
        Mat4::from_scale_rotation_translation(size, Quat::IDENTITY, Vec3::new(x, y, z))
    };
    // Floor 40 m square, a 4 m tile: 10 repeats each way.
    let floor = primitives::plane(8);
    model.append(&floor, 0, place(0.0, 0.0, 0.0, Vec3::new(40.0, 1.0, 40.0)), |uv, _| uv * 10.0);
    // The wall, 20 × 6 m, bricks at their real size.
    let wall = primitives::cube();
    let wall_at = place(0.0, 3.0, -5.0, Vec3::new(20.0, 6.0, 0.6));
    let uvs = world_uvs(&wall, wall_at, Shape::Cube, 1.0);
    model.append(&wall, 1, wall_at, |_, i| uvs[i]);
    // The primitives, 1.6 m each, the texture once or twice round each.
    // Coarse on purpose: the fewer the faces, the plainer the difference
    // between per-face and per-vertex tangents.
    let size = Vec3::splat(1.6);
    let row: [(MeshData, f32, usize, f32); 6] = [
        (primitives::uv_sphere(16, 8), -3.8, 1, 2.0),
        (primitives::torus(24, 10, 0.15), -6.3, 2, 2.0),
        (primitives::cone(16), -8.8, 1, 1.0),
        (primitives::cylinder(16), 3.8, 2, 1.0),
        (primitives::cube(), 6.3, 3, 1.0),
        (primitives::pyramid(), 8.8, 1, 1.0),
    ];
    for (mesh, x, material, repeats) in row {
        model.append(&mesh, material, place(x, 0.8, -3.2, size), |uv, _| uv * repeats);
    }
    model.group_by_material();
    model
}
// ANCHOR_END: stage

/// The stage's own lights besides the sun: a warm lamp on the left and a
/// cool one on the right, so that normal maps answer more than one light.
pub fn stage_lights() -> Vec<Light> {
    let point = |position: Vec3, colour: Vec3| Light { position, colour, range: 14.0, kind: LightKind::Point };
    vec![
        point(Vec3::new(-4.5, 3.0, 1.5), Vec3::new(1.0, 0.75, 0.45) * 25.0),
        point(Vec3::new(4.5, 2.5, -1.0), Vec3::new(0.45, 0.65, 1.0) * 25.0),
    ]
}

/// Where the featured model stands: scaled so that its bounding box's
/// diagonal is 5 m (whatever units its file used), centred on the stage,
/// its lowest point on the floor, and turned 120° so that the stage camera
/// sees its −z end (the car's front) from three quarters. Returns the
/// placement and the scale.
pub fn stage_placement(bounds: (Vec3, Vec3)) -> (Mat4, f32) {
    let (low, high) = bounds;
    let diagonal = (high - low).length();
    let scale = if diagonal > 1e-6 && diagonal.is_finite() { 5.0 / diagonal } else { 1.0 };
    let centre = (low + high) / 2.0;
    let fit = Mat4::from_scale(Vec3::splat(scale)) * Mat4::from_translation(Vec3::new(-centre.x, -low.y, -centre.z));
    (Mat4::from_rotation_y(120f32.to_radians()) * fit, scale)
}

/// The path of the lab's checkerboard texture (made in code, not a file).
pub const CHECKER: &str = "generated/checkerboard";

/// The sampling lab: a checkerboard floor 2 km square, 1 m squares.
pub fn lab_floor() -> ModelData {
    let material = MaterialDesc {
        albedo_map: Some(PathBuf::from(CHECKER)),
        ..MaterialDesc::plain("checkerboard", Vec3::ONE, 0.0, 1.0)
    };
    let mut model = ModelData { materials: vec![material], ..Default::default() };
    // 2000 m with the 8 m tile (8 × 8 squares): 250 repeats.
    let floor = primitives::plane(1);
    model.append(&floor, 0, Mat4::from_scale(Vec3::new(2000.0, 1.0, 2000.0)), |uv, _| uv * 250.0);
    model
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The span of u and v over the vertices whose normal is `normal`.
    fn spans(mesh: &MeshData, uvs: &[Vec2], model: Mat4, normal: Vec3) -> Vec2 {
        let n_matrix = common::glam::Mat3::from_mat4(model).inverse().transpose();
        let (lo, hi) = mesh
            .vertices
            .iter()
            .zip(uvs)
            .filter(|(v, _)| (n_matrix * Vec3::from(v.normal)).normalize().dot(normal) > 0.99)
            .fold((Vec2::splat(f32::MAX), Vec2::splat(f32::MIN)), |(lo, hi), (_, uv)| (lo.min(*uv), hi.max(*uv)));
        hi - lo
    }

    #[test]
    fn a_textures_size_in_metres_is_the_same_on_any_box() {
        let cube = primitives::cube();
        let model = Mat4::from_scale(Vec3::new(20.0, 6.0, 0.6));
        let uvs = world_uvs(&cube, model, Shape::Cube, 1.0);
        assert!(spans(&cube, &uvs, model, Vec3::Z).abs_diff_eq(Vec2::new(20.0, 6.0), 1e-4));
        assert!(spans(&cube, &uvs, model, Vec3::X).abs_diff_eq(Vec2::new(0.6, 6.0), 1e-4));
        assert!(spans(&cube, &uvs, model, Vec3::Y).abs_diff_eq(Vec2::new(20.0, 0.6), 1e-4));
    }

    #[test]
    fn roads_run_along_u_both_ways() {
        let city = City::new();
        let roads: Vec<&Piece> = city.pieces.iter().filter(|p| p.material == Material::Road).collect();
        assert_eq!(roads.len(), 14);
        let cube = primitives::cube();
        for road in roads {
            let uvs = world_uvs(&cube, road.model, Shape::Cube, 12.0);
            let top = spans(&cube, &uvs, road.model, Vec3::Y);
            // 372 m long, 12 m wide: 31 tiles along u, one across v.
            assert!(top.abs_diff_eq(Vec2::new(31.0, 1.0), 1e-3), "{top}");
        }
    }

    #[test]
    fn round_shapes_repeat_a_whole_number_of_times_around() {
        let cylinder = primitives::cylinder(24);
        let model = Mat4::from_scale(Vec3::new(9.0, 12.0, 9.0));
        let uvs = world_uvs(&cylinder, model, Shape::Cylinder, 4.0);
        let around: f32 = cylinder
            .vertices
            .iter()
            .zip(&uvs)
            .filter(|(v, _)| v.normal[1] == 0.0)
            .map(|(_, uv)| uv.x)
            .fold(0.0, f32::max);
        // A circumference of about 28 m, in 4 m tiles: 7 whole repeats.
        assert_eq!(around, 7.0);
    }

    #[test]
    fn the_tower_replaces_the_buildings_of_one_block_only() {
        let city = City::new();
        let removed: Vec<&Piece> = city.pieces.iter().filter(|p| on_tower_block(p)).collect();
        assert!(!removed.is_empty());
        assert!(
            removed.iter().all(|p| matches!(
                p.material,
                Material::Facade | Material::Brick | Material::Concrete | Material::Metal
            ))
        );
        let lamps_kept = city.pieces.iter().filter(|p| p.material == Material::Lamp).count();
        assert_eq!(lamps_kept, 288, "every street lamp stays");
    }
}
