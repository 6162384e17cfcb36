//! The rock every instance draws, at three levels of detail: a low-poly
//! icosahedron pushed in and out at random and shaded flat, and two coarser
//! copies of the same rock (an octahedron and a tetrahedron) for rocks a few
//! pixels across.

use common::glam::Vec3;
use common::{MeshData, Vertex};

use crate::rng::Rng;

// ANCHOR: rock_mesh
/// A low-poly rock: an icosahedron whose twelve corners are pushed in or
/// out at random, squashed, and shaded flat, so each of its 20 faces
/// catches the light on its own. 60 vertices.
pub fn rock_mesh(seed: u64) -> MeshData {
    let t = (1.0 + 5f32.sqrt()) / 2.0;
    let corners = [
        [-1.0, t, 0.0],
        [1.0, t, 0.0],
        [-1.0, -t, 0.0],
        [1.0, -t, 0.0],
        [0.0, -1.0, t],
        [0.0, 1.0, t],
        [0.0, -1.0, -t],
        [0.0, 1.0, -t],
        [t, 0.0, -1.0],
        [t, 0.0, 1.0],
        [-t, 0.0, -1.0],
        [-t, 0.0, 1.0],
    ];
    const FACES: [[usize; 3]; 20] = [
        [0, 11, 5],
        [0, 5, 1],
        [0, 1, 7],
        [0, 7, 10],
        [0, 10, 11],
        [1, 5, 9],
        [5, 11, 4],
        [11, 10, 2],
        [10, 7, 6],
        [7, 1, 8],
        [3, 9, 4],
        [3, 4, 2],
        [3, 2, 6],
        [3, 6, 8],
        [3, 8, 9],
        [4, 9, 5],
        [2, 4, 11],
        [6, 2, 10],
        [8, 6, 7],
        [9, 8, 1],
    ];
    let mut rng = Rng::new(seed);
    let points: Vec<Vec3> = corners
        .iter()
        .map(|&c| {
            let p = Vec3::from(c).normalize() * rng.range(0.75, 1.15) * 0.5;
            // Flatter than tall, and sitting on its base.
            Vec3::new(p.x, p.y * 0.8 + 0.1, p.z)
        })
        .collect();
    flat_shaded(&points, &FACES)
}
// ANCHOR_END: rock_mesh

/// Triangles `faces` (corners counter-clockwise seen from outside) over
/// `points`, each face with its own three vertices and its own normal.
fn flat_shaded(points: &[Vec3], faces: &[[usize; 3]]) -> MeshData {
    let mut mesh = MeshData::default();
    for face in faces {
        let [a, b, c] = face.map(|i| points[i]);
        let normal = (b - a).cross(c - a).normalize();
        for p in [a, b, c] {
            mesh.indices.push(mesh.vertices.len() as u32);
            mesh.vertices.push(Vertex { position: p.into(), normal: normal.into(), uv: [0.0; 2] });
        }
    }
    mesh
}

// ANCHOR: rock_levels
/// How many meshes a rock has: one per level of detail.
pub const LEVELS: usize = 3;

/// The rock of `seed` at its three levels of detail, finest first: the
/// icosahedron of `rock_mesh` (20 triangles), an octahedron (8) and a
/// tetrahedron (4). The coarse ones are cut from the same rock: each corner
/// lies where a ray from the rock's centre, along the corner's direction,
/// meets the full rock's surface, so they keep its squashed, lopsided
/// shape. Then each is scaled about the centre until its surface area is
/// the full rock's: by Cauchy's formula a convex body's shadow, averaged
/// over every direction, is a quarter of its surface area, so the coarse
/// rock covers about as many pixels as the rock it stands in for.
pub fn rock_levels(seed: u64) -> [MeshData; LEVELS] {
    let full = rock_mesh(seed);
    let centre = box_centre(&full);
    let coarse = |directions: &[Vec3], faces: &[[usize; 3]]| {
        let corners: Vec<Vec3> = directions.iter().map(|&d| centre + d * reach_along(&full, centre, d)).collect();
        let grow = (surface_area(&full) / surface_area(&flat_shaded(&corners, faces))).sqrt();
        let grown: Vec<Vec3> = corners.iter().map(|&p| centre + (p - centre) * grow).collect();
        flat_shaded(&grown, faces)
    };
    let octahedron = [Vec3::X, Vec3::NEG_X, Vec3::Y, Vec3::NEG_Y, Vec3::Z, Vec3::NEG_Z];
    const OCTAHEDRON_FACES: [[usize; 3]; 8] =
        [[2, 4, 0], [2, 1, 4], [2, 5, 1], [2, 0, 5], [3, 0, 4], [3, 4, 1], [3, 1, 5], [3, 5, 0]];
    // A corner straight up and three around below it: a pyramid on a
    // triangular base, the way a rock sits on the ground.
    let below = |k: f32| {
        let angle = k * std::f32::consts::TAU / 3.0;
        Vec3::new(angle.cos() * 8f32.sqrt() / 3.0, -1.0 / 3.0, angle.sin() * 8f32.sqrt() / 3.0)
    };
    let tetrahedron = [Vec3::Y, below(0.0), below(1.0), below(2.0)];
    const TETRAHEDRON_FACES: [[usize; 3]; 4] = [[0, 2, 1], [0, 3, 2], [0, 1, 3], [1, 2, 3]];
    let octahedron = coarse(&octahedron, &OCTAHEDRON_FACES);
    let tetrahedron = coarse(&tetrahedron, &TETRAHEDRON_FACES);
    [full, octahedron, tetrahedron]
}
// ANCHOR_END: rock_levels

/// The centre of the box around `mesh`: the point the coarse rocks are
/// cut from, and the centre of the sphere the culling tests.
pub fn box_centre(mesh: &MeshData) -> Vec3 {
    let points = mesh.vertices.iter().map(|v| Vec3::from(v.position));
    let (min, max) = points.fold((Vec3::MAX, Vec3::MIN), |(lo, hi), p| (lo.min(p), hi.max(p)));
    (min + max) * 0.5
}

/// How far from `centre`, along the unit vector `direction`, the surface
/// of `mesh` is: the nearest face the ray meets (a rock is star-shaped
/// about its centre, so there is one).
fn reach_along(mesh: &MeshData, centre: Vec3, direction: Vec3) -> f32 {
    mesh.triangles()
        .filter_map(|[a, b, c]| {
            // Where the ray meets the face's plane, then whether that point
            // is inside all three of its edges.
            let normal = (b - a).cross(c - a);
            let along = normal.dot(direction);
            if along <= 0.0 {
                return None;
            }
            let t = normal.dot(a - centre) / along;
            let p = centre + direction * t;
            let inside = [(a, b), (b, c), (c, a)].iter().all(|&(u, v)| (v - u).cross(p - u).dot(normal) >= -1e-6);
            inside.then_some(t)
        })
        .fold(f32::INFINITY, f32::min)
}

/// The total area of `mesh`'s triangles.
pub fn surface_area(mesh: &MeshData) -> f32 {
    mesh.triangles().map(|[a, b, c]| (b - a).cross(c - a).length() / 2.0).sum()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rock_scatter::SEED;

    #[test]
    fn the_rock_is_closed_flat_shaded_and_sixty_vertices() {
        let rock = rock_mesh(SEED);
        assert_eq!((rock.vertices.len(), rock.indices.len()), (60, 60));
        let volume: f32 = rock.triangles().map(|[a, b, c]| a.dot(b.cross(c)) / 6.0).sum();
        assert!(volume > 0.05, "faces must wind outward: volume {volume}");
        for face in rock.vertices.chunks_exact(3) {
            assert!(face.iter().all(|v| v.normal == face[0].normal), "flat shading");
        }
        assert_ne!(rock_mesh(SEED).vertices, rock_mesh(SEED + 1).vertices);
    }

    #[test]
    fn the_coarse_rocks_are_the_same_rock_with_fewer_faces() {
        let levels = rock_levels(SEED);
        let triangles = levels.each_ref().map(|mesh| mesh.indices.len() / 3);
        assert_eq!(triangles, [20, 8, 4]);
        assert_eq!(levels[0], rock_mesh(SEED));
        let full_area = surface_area(&levels[0]);
        let centre = box_centre(&levels[0]);
        let reach =
            |m: &MeshData| m.vertices.iter().map(|v| (Vec3::from(v.position) - centre).length()).fold(0.0, f32::max);
        for (level, mesh) in levels.iter().enumerate() {
            // Closed and wound outward: a positive volume seen from the centre.
            let volume: f32 =
                mesh.triangles().map(|[a, b, c]| (a - centre).dot((b - centre).cross(c - centre)) / 6.0).sum();
            assert!(volume > 0.02, "level {level}: volume {volume}");
            // The same surface area, so the same average shadow, to rounding.
            let area = surface_area(mesh);
            assert!((area / full_area - 1.0).abs() < 1e-4, "level {level}: area {area} against {full_area}");
            // About the same size: no corner half as far out again as the full rock's.
            assert!(
                reach(mesh) < 1.5 * reach(&levels[0]),
                "level {level}: {} against {}",
                reach(mesh),
                reach(&levels[0])
            );
        }
        // Squashed like the full rock: each coarse rock is wider than tall.
        for mesh in &levels[1..] {
            let extent = |axis: usize| {
                let values = mesh.vertices.iter().map(|v| v.position[axis]);
                values.clone().fold(f32::MIN, f32::max) - values.fold(f32::MAX, f32::min)
            };
            assert!(extent(1) < extent(0).max(extent(2)), "{} {} {}", extent(0), extent(1), extent(2));
        }
    }
}
