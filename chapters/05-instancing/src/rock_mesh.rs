//! The one rock every instance draws: a low-poly icosahedron, pushed in and
//! out at random and shaded flat.

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
    let mut mesh = MeshData::default();
    for face in FACES {
        let [a, b, c] = face.map(|i| points[i]);
        let normal = (b - a).cross(c - a).normalize();
        for p in [a, b, c] {
            mesh.indices.push(mesh.vertices.len() as u32);
            mesh.vertices.push(Vertex { position: p.into(), normal: normal.into(), uv: [0.0; 2] });
        }
    }
    mesh
}
// ANCHOR_END: rock_mesh

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rock_field::SEED;

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
}
