//! Tangents for normal mapping. A normal map stores directions in the
//! surface's own frame: along the texture's u, up its v, and out of the
//! surface. Using one needs that frame at every vertex: the normal the
//! vertex already has, a tangent (the direction in which u grows), and which
//! side of the normal and tangent "up the image" lies on. All of it comes
//! from the positions and texture coordinates (Lengyel 2001).
//!
//! This project's texture coordinates run as wgpu's do, v down the image
//! (OBJ files are flipped on load), while normal maps, as Blender and glTF
//! make them, store "up the image" in green. So the bitangent that matters
//! is −∂P/∂v.

use common::glam::{Vec2, Vec3, Vec4};

// ANCHOR: triangle
/// How position changes with texture coordinates across one triangle: the
/// T = ∂P/∂u and B = ∂P/∂v for which
/// p₁ − p₀ = Δu₁ T + Δv₁ B and p₂ − p₀ = Δu₂ T + Δv₂ B.
/// Two equations in two unknown vectors, solved by inverting the 2 × 2
/// matrix of UV differences. `None` when the triangle covers no area of the
/// texture (its UVs are in a line), so T and B are not defined.
pub fn triangle_tangents(p: [Vec3; 3], uv: [Vec2; 3]) -> Option<(Vec3, Vec3)> {
    let (e1, e2) = (p[1] - p[0], p[2] - p[0]);
    let (d1, d2) = (uv[1] - uv[0], uv[2] - uv[0]);
    let determinant = d1.x * d2.y - d2.x * d1.y;
    if determinant.abs() < 1e-12 {
        return None;
    }
    let t = (e1 * d2.y - e2 * d1.y) / determinant;
    let b = (e2 * d1.x - e1 * d2.x) / determinant;
    (t.is_finite() && b.is_finite()).then_some((t, b))
}
// ANCHOR_END: triangle

// ANCHOR: per_vertex
/// One tangent per vertex, for indexed triangles: xyz a unit tangent at
/// right angles to the vertex's normal, and w = ±1, the handedness: "up
/// the image" is w · (N × T). w is −1 where the texture is mirrored.
///
/// Each triangle adds its tangent at each of its corners, first made
/// orthogonal to that corner's normal (Gram–Schmidt: subtract the part
/// along N) and weighted by the corner's angle, so that a vertex where one
/// wide triangle meets many thin ones is not ruled by the thin ones. The
/// sums are normalised at the end. The bitangents are summed the same way,
/// only to read the handedness.
pub fn vertex_tangents(positions: &[Vec3], normals: &[Vec3], uvs: &[Vec2], indices: &[u32]) -> Vec<Vec4> {
    let mut tangents = vec![Vec3::ZERO; positions.len()];
    let mut bitangents = vec![Vec3::ZERO; positions.len()];
    for triangle in indices.chunks_exact(3) {
        let corners = [0, 1, 2].map(|k| triangle[k] as usize);
        let p = corners.map(|i| positions[i]);
        let Some((t, b)) = triangle_tangents(p, corners.map(|i| uvs[i])) else { continue };
        for (k, &i) in corners.iter().enumerate() {
            let angle = (p[(k + 1) % 3] - p[k]).angle_between(p[(k + 2) % 3] - p[k]);
            if !angle.is_finite() {
                continue;
            }
            let n = normals[i];
            tangents[i] += (t - n * n.dot(t)).normalize_or_zero() * angle;
            bitangents[i] += (b - n * n.dot(b)).normalize_or_zero() * angle;
        }
    }
    tangents
        .iter()
        .zip(&bitangents)
        .zip(normals)
        .map(|((&t, &b), &n)| {
            // Gram–Schmidt once more: the sum of tangents each orthogonal
            // to the normal is too, up to rounding.
            let t = (t - n * n.dot(t)).try_normalize().unwrap_or_else(|| n.any_orthonormal_vector());
            let up = -b;
            let handedness = if n.cross(t).dot(up) < 0.0 { -1.0 } else { 1.0 };
            t.extend(handedness)
        })
        .collect()
}
// ANCHOR_END: per_vertex

// ANCHOR: per_face
/// The seed project's way: one tangent per triangle, straight from
/// [`triangle_tangents`], shared by its three corners and not adjusted to
/// their normals. On a flat face it is the same as per-vertex; on a curved
/// surface the frame jumps at every edge.
pub fn face_tangents(positions: &[Vec3], normals: &[Vec3], uvs: &[Vec2], indices: &[u32]) -> Vec<Vec4> {
    indices
        .chunks_exact(3)
        .map(|triangle| {
            let corners = [0, 1, 2].map(|k| triangle[k] as usize);
            let p = corners.map(|i| positions[i]);
            let n = (p[1] - p[0]).cross(p[2] - p[0]).try_normalize().unwrap_or(normals[corners[0]]);
            match triangle_tangents(p, corners.map(|i| uvs[i])) {
                Some((t, b)) => {
                    let t = t.try_normalize().unwrap_or_else(|| n.any_orthonormal_vector());
                    t.extend(if n.cross(t).dot(-b) < 0.0 { -1.0 } else { 1.0 })
                }
                None => n.any_orthonormal_vector().extend(1.0),
            }
        })
        .collect()
}
// ANCHOR_END: per_face

#[cfg(test)]
mod tests {
    use super::*;

    /// A square in the xy plane facing +z, textured the usual way: u to
    /// the right, v down the image (so up the image is +y).
    fn square(mirrored: bool) -> (Vec<Vec3>, Vec<Vec3>, Vec<Vec2>, Vec<u32>) {
        let positions = vec![
            Vec3::new(0.0, 0.0, 0.0),
            Vec3::new(1.0, 0.0, 0.0),
            Vec3::new(1.0, 1.0, 0.0),
            Vec3::new(0.0, 1.0, 0.0),
        ];
        let uv = |p: Vec3| Vec2::new(if mirrored { 1.0 - p.x } else { p.x }, 1.0 - p.y);
        let uvs = positions.iter().map(|&p| uv(p)).collect();
        (positions, vec![Vec3::Z; 4], uvs, vec![0, 1, 2, 0, 2, 3])
    }

    #[test]
    fn a_square_textured_the_usual_way_has_tangent_x_and_handedness_plus_one() {
        let (p, n, uv, i) = square(false);
        for t in vertex_tangents(&p, &n, &uv, &i) {
            assert!(t.truncate().abs_diff_eq(Vec3::X, 1e-6) && t.w == 1.0, "{t}");
        }
    }

    #[test]
    fn a_mirrored_texture_flips_the_tangent_and_the_handedness() {
        let (p, n, uv, i) = square(true);
        for t in vertex_tangents(&p, &n, &uv, &i) {
            assert!(t.truncate().abs_diff_eq(Vec3::NEG_X, 1e-6) && t.w == -1.0, "{t}");
        }
    }

    #[test]
    fn the_triangle_solution_reproduces_the_edges() {
        let p = [Vec3::new(0.2, -1.0, 3.0), Vec3::new(2.0, 0.5, 1.0), Vec3::new(-1.0, 2.0, 0.0)];
        let uv = [Vec2::new(0.1, 0.9), Vec2::new(0.7, 0.6), Vec2::new(0.3, 0.1)];
        let (t, b) = triangle_tangents(p, uv).unwrap();
        for k in [1, 2] {
            let d = uv[k] - uv[0];
            assert!((d.x * t + d.y * b).abs_diff_eq(p[k] - p[0], 1e-5));
        }
    }

    #[test]
    fn uvs_in_a_line_give_no_tangent_and_a_fallback_frame() {
        let p = [Vec3::ZERO, Vec3::X, Vec3::Y];
        let uv = [Vec2::ZERO, Vec2::new(0.5, 0.5), Vec2::new(1.0, 1.0)];
        assert!(triangle_tangents(p, uv).is_none());
        let t = vertex_tangents(&p, &[Vec3::Z; 3], &uv, &[0, 1, 2]);
        for t in t {
            assert!((t.truncate().length() - 1.0).abs() < 1e-6 && t.truncate().dot(Vec3::Z).abs() < 1e-6);
        }
    }
}
