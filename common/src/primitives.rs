//! Unit-sized primitives with normals and texture coordinates: the building
//! blocks of the camera chapter's scene and of the city later on.
//!
//! Every shape is centred on the origin and fits in a 1×1×1 box, so a model
//! matrix alone places and sizes it. Triangles wind counter-clockwise seen
//! from outside.

use std::f32::consts::{PI, TAU};

use glam::{Vec2, Vec3};

use crate::{MeshData, Vertex};

fn vertex(position: Vec3, normal: Vec3, uv: Vec2) -> Vertex {
    Vertex { position: position.into(), normal: normal.into(), uv: uv.into() }
}

// ANCHOR: surface
/// Samples a parametric surface on a `columns × rows` grid of quads.
///
/// `point(u, v)` returns a position and normal for u, v in 0..=1. The
/// orientation rule: ∂P/∂v × ∂P/∂u must point outward (v runs "down" the
/// surface while u runs "around" it), so the two triangles of each quad
/// come out counter-clockwise seen from outside. Quads that collapse to a
/// point (a sphere's poles, a cone's tip) lose their zero-area triangle.
pub fn surface(columns: u32, rows: u32, point: impl Fn(f32, f32) -> (Vec3, Vec3)) -> MeshData {
    let mut mesh = MeshData::default();
    for row in 0..=rows {
        for column in 0..=columns {
            let uv = Vec2::new(column as f32 / columns as f32, row as f32 / rows as f32);
            let (position, normal) = point(uv.x, uv.y);
            mesh.vertices.push(vertex(position, normal, uv));
        }
    }
    let index = |column: u32, row: u32| row * (columns + 1) + column;
    for row in 0..rows {
        for column in 0..columns {
            let a = index(column, row);
            let b = index(column + 1, row);
            let c = index(column, row + 1);
            let d = index(column + 1, row + 1);
            for triangle in [[a, c, b], [b, c, d]] {
                let [p, q, r] = triangle.map(|i| Vec3::from(mesh.vertices[i as usize].position));
                if (q - p).cross(r - p).length_squared() > 1e-12 {
                    mesh.indices.extend(triangle);
                }
            }
        }
    }
    mesh
}
// ANCHOR_END: surface

/// Appends `other`, renumbering its indices.
fn append(mesh: &mut MeshData, other: MeshData) {
    let base = mesh.vertices.len() as u32;
    mesh.vertices.extend(other.vertices);
    mesh.indices.extend(other.indices.iter().map(|i| i + base));
}

/// A flat disc at height `y` facing up (`up = true`) or down.
fn disc(segments: u32, radius: f32, y: f32, up: bool) -> MeshData {
    let normal = if up { Vec3::Y } else { Vec3::NEG_Y };
    let mut mesh = MeshData::default();
    mesh.vertices.push(vertex(Vec3::new(0.0, y, 0.0), normal, Vec2::splat(0.5)));
    for i in 0..=segments {
        let (s, c) = (TAU * i as f32 / segments as f32).sin_cos();
        let uv = Vec2::new(0.5 + 0.5 * s, 0.5 - 0.5 * c);
        mesh.vertices.push(vertex(Vec3::new(radius * s, y, radius * c), normal, uv));
    }
    for i in 1..=segments {
        mesh.indices.extend(if up { [0, i, i + 1] } else { [0, i + 1, i] });
    }
    mesh
}

/// A cube from -0.5 to 0.5: six faces with their own normals (24 vertices),
/// each face mapped to the whole texture.
pub fn cube() -> MeshData {
    // (normal, u axis, v axis) with u × v = normal, so corners listed
    // (-u -v), (+u -v), (+u +v), (-u +v) run counter-clockwise.
    let faces = [
        (Vec3::X, Vec3::NEG_Z, Vec3::Y),
        (Vec3::NEG_X, Vec3::Z, Vec3::Y),
        (Vec3::Y, Vec3::X, Vec3::NEG_Z),
        (Vec3::NEG_Y, Vec3::X, Vec3::Z),
        (Vec3::Z, Vec3::X, Vec3::Y),
        (Vec3::NEG_Z, Vec3::NEG_X, Vec3::Y),
    ];
    let mut mesh = MeshData::default();
    for (normal, u, v) in faces {
        let base = mesh.vertices.len() as u32;
        for (s, t) in [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)] {
            let position = 0.5 * (normal + s * u + t * v);
            let uv = Vec2::new((s + 1.0) / 2.0, (1.0 - t) / 2.0);
            mesh.vertices.push(vertex(position, normal, uv));
        }
        mesh.indices.extend([base, base + 1, base + 2, base, base + 2, base + 3]);
    }
    mesh
}

// ANCHOR: sphere
/// A UV sphere of radius 0.5: `segments` around, `rings` from pole to pole.
pub fn uv_sphere(segments: u32, rings: u32) -> MeshData {
    surface(segments, rings, |u, v| {
        let (sin_lon, cos_lon) = (TAU * u).sin_cos();
        let (sin_lat, cos_lat) = (PI * v).sin_cos(); // v = 0 at the north pole
        let normal = Vec3::new(sin_lat * sin_lon, cos_lat, sin_lat * cos_lon);
        (0.5 * normal, normal)
    })
}
// ANCHOR_END: sphere

/// A closed cylinder of radius 0.5 and height 1 along y.
pub fn cylinder(segments: u32) -> MeshData {
    let mut mesh = surface(segments, 1, |u, v| {
        let (s, c) = (TAU * u).sin_cos();
        let normal = Vec3::new(s, 0.0, c);
        (Vec3::new(0.5 * s, 0.5 - v, 0.5 * c), normal)
    });
    append(&mut mesh, disc(segments, 0.5, 0.5, true));
    append(&mut mesh, disc(segments, 0.5, -0.5, false));
    mesh
}

/// A closed cone with its tip at y = 0.5 and a base of radius 0.5 at y = -0.5.
pub fn cone(segments: u32) -> MeshData {
    let (radius, height) = (0.5, 1.0);
    let mut mesh = surface(segments, 1, |u, v| {
        let (s, c) = (TAU * u).sin_cos();
        // The side leans back by radius/height: its normal tilts up by as much.
        let normal = Vec3::new(height * s, radius, height * c).normalize();
        (Vec3::new(radius * v * s, 0.5 - v, radius * v * c), normal)
    });
    append(&mut mesh, disc(segments, radius, -0.5, false));
    mesh
}

/// A torus lying in the xz plane: the tube's centre circle has radius
/// `0.5 - tube`, so the whole ring spans -0.5..0.5.
pub fn torus(segments: u32, sides: u32, tube: f32) -> MeshData {
    let ring = 0.5 - tube;
    surface(segments, sides, |u, v| {
        let (s, c) = (TAU * u).sin_cos();
        // Walk the tube the other way round so ∂P/∂v × ∂P/∂u points out.
        let (sin_tube, cos_tube) = (-TAU * v).sin_cos();
        let normal = Vec3::new(cos_tube * s, sin_tube, cos_tube * c);
        (Vec3::new(ring * s, 0.0, ring * c) + tube * normal, normal)
    })
}

/// A square pyramid: base -0.5..0.5 at y = -0.5, tip at y = 0.5. Flat
/// shaded, so every face has its own three or four vertices.
pub fn pyramid() -> MeshData {
    let apex = Vec3::new(0.0, 0.5, 0.0);
    let corners = [
        Vec3::new(-0.5, -0.5, 0.5),
        Vec3::new(0.5, -0.5, 0.5),
        Vec3::new(0.5, -0.5, -0.5),
        Vec3::new(-0.5, -0.5, -0.5),
    ];
    let mut mesh = MeshData::default();
    for i in 0..4 {
        let (a, b) = (corners[i], corners[(i + 1) % 4]);
        let normal = (b - a).cross(apex - a).normalize();
        let base = mesh.vertices.len() as u32;
        mesh.vertices.push(vertex(a, normal, Vec2::new(0.0, 1.0)));
        mesh.vertices.push(vertex(b, normal, Vec2::new(1.0, 1.0)));
        mesh.vertices.push(vertex(apex, normal, Vec2::new(0.5, 0.0)));
        mesh.indices.extend([base, base + 1, base + 2]);
    }
    let base = mesh.vertices.len() as u32;
    for c in corners {
        // Seen from below, +x is to the right and +z up the image.
        mesh.vertices.push(vertex(c, Vec3::NEG_Y, Vec2::new(c.x + 0.5, 0.5 - c.z)));
    }
    mesh.indices.extend([base, base + 3, base + 2, base, base + 2, base + 1]);
    mesh
}

/// A flat square in the xz plane, facing up, split into
/// `subdivisions × subdivisions` quads: the ground of many scenes.
pub fn plane(subdivisions: u32) -> MeshData {
    surface(subdivisions, subdivisions, |u, v| (Vec3::new(u - 0.5, 0.0, v - 0.5), Vec3::Y))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Signed volume by the divergence theorem: positive only when every
    /// triangle winds counter-clockwise seen from outside.
    fn signed_volume(mesh: &MeshData) -> f32 {
        mesh.triangles().map(|[a, b, c]| a.dot(b.cross(c)) / 6.0).sum()
    }

    fn check_well_formed(name: &str, mesh: &MeshData) {
        assert_eq!(mesh.indices.len() % 3, 0, "{name}: index count");
        assert!(mesh.indices.iter().all(|&i| (i as usize) < mesh.vertices.len()), "{name}: index range");
        for v in &mesh.vertices {
            let n = Vec3::from(v.normal);
            assert!((n.length() - 1.0).abs() < 1e-5, "{name}: normal {n} is not unit length");
            assert!(Vec3::from(v.position).abs().max_element() <= 0.5 + 1e-6, "{name}: outside the unit box");
            assert!(v.uv.iter().all(|t| (0.0..=1.0).contains(t)), "{name}: uv {:?}", v.uv);
        }
        // Each triangle's winding agrees with the normals of its corners.
        for t in mesh.indices.chunks_exact(3) {
            let [a, b, c] = [0, 1, 2].map(|k| Vec3::from(mesh.vertices[t[k] as usize].position));
            let face = (b - a).cross(c - a);
            assert!(face.length() > 0.0, "{name}: degenerate triangle {t:?}");
            for &i in t {
                let n = Vec3::from(mesh.vertices[i as usize].normal);
                assert!(face.dot(n) > 0.0, "{name}: triangle {t:?} winds against its normals");
            }
        }
    }

    fn check_outward(name: &str, mesh: &MeshData, centre_of: impl Fn(Vec3) -> Vec3) {
        for v in &mesh.vertices {
            let p = Vec3::from(v.position);
            let n = Vec3::from(v.normal);
            assert!(n.dot(p - centre_of(p)) > 0.0, "{name}: normal {n} at {p} points inward");
        }
    }

    #[test]
    fn cube_is_24_vertices_12_triangles_of_volume_1() {
        let mesh = cube();
        assert_eq!((mesh.vertices.len(), mesh.indices.len()), (24, 36));
        check_well_formed("cube", &mesh);
        check_outward("cube", &mesh, |_| Vec3::ZERO);
        assert!((signed_volume(&mesh) - 1.0).abs() < 1e-5);
    }

    #[test]
    fn sphere_counts_and_volume() {
        let mesh = uv_sphere(32, 16);
        assert_eq!(mesh.vertices.len(), 33 * 17);
        // Two triangles per quad, less one at each pole quad.
        assert_eq!(mesh.indices.len() / 3, 2 * 32 * 16 - 2 * 32);
        check_well_formed("sphere", &mesh);
        check_outward("sphere", &mesh, |_| Vec3::ZERO);
        let exact = 4.0 / 3.0 * PI * 0.125;
        let volume = signed_volume(&mesh);
        assert!(volume > 0.97 * exact && volume < exact, "{volume} vs {exact}");
    }

    #[test]
    fn cylinder_and_cone_are_closed_and_outward() {
        let cyl = cylinder(48);
        check_well_formed("cylinder", &cyl);
        check_outward("cylinder", &cyl, |_| Vec3::ZERO);
        let exact = PI * 0.25;
        assert!((signed_volume(&cyl) - exact).abs() < 0.01 * exact);

        let cone = cone(48);
        check_well_formed("cone", &cone);
        check_outward("cone", &cone, |_| Vec3::new(0.0, -0.25, 0.0));
        let exact = PI * 0.25 / 3.0;
        assert!((signed_volume(&cone) - exact).abs() < 0.01 * exact);
    }

    #[test]
    fn torus_normals_point_away_from_the_tube_centre() {
        let tube = 0.15;
        let mesh = torus(48, 24, tube);
        assert_eq!(mesh.vertices.len(), 49 * 25);
        assert_eq!(mesh.indices.len(), 48 * 24 * 6);
        check_well_formed("torus", &mesh);
        check_outward("torus", &mesh, |p| Vec3::new(p.x, 0.0, p.z).normalize() * (0.5 - tube));
        let exact = 2.0 * PI * PI * (0.5 - tube) * tube * tube;
        assert!((signed_volume(&mesh) - exact).abs() < 0.02 * exact);
    }

    #[test]
    fn pyramid_has_volume_one_third() {
        let mesh = pyramid();
        assert_eq!((mesh.vertices.len(), mesh.indices.len()), (16, 18));
        check_well_formed("pyramid", &mesh);
        check_outward("pyramid", &mesh, |_| Vec3::new(0.0, -0.25, 0.0));
        assert!((signed_volume(&mesh) - 1.0 / 3.0).abs() < 1e-5);
    }

    /// Every vertex sits where its texture coordinates say: `expected`
    /// gives the position for (u, v) and the vertex's normal.
    fn check_uv_mapping(name: &str, mesh: &MeshData, expected: impl Fn(Vec2, Vec3) -> Vec3) {
        for v in &mesh.vertices {
            let want = expected(Vec2::from(v.uv), Vec3::from(v.normal));
            let got = Vec3::from(v.position);
            assert!(got.abs_diff_eq(want, 1e-5), "{name}: uv {:?} is at {got}, not {want}", v.uv);
        }
    }

    // ANCHOR: uv_tests
    #[test]
    fn texels_map_where_they_should() {
        let lon = |u: f32| (TAU * u).sin_cos();
        check_uv_mapping("sphere", &uv_sphere(24, 12), |uv, _| {
            let ((s, c), (sin_lat, cos_lat)) = (lon(uv.x), (PI * uv.y).sin_cos());
            0.5 * Vec3::new(sin_lat * s, cos_lat, sin_lat * c)
        });
        // Sides: u around from +z towards +x, v down from the top. Caps: the
        // texture laid flat, u along +x, v along −z.
        let cap = |uv: Vec2, y: f32| Vec3::new(uv.x - 0.5, y, 0.5 - uv.y);
        check_uv_mapping("cylinder", &cylinder(24), |uv, n| match n.y {
            y if y > 0.5 => cap(uv, 0.5),
            y if y < -0.5 => cap(uv, -0.5),
            _ => Vec3::new(0.5 * lon(uv.x).0, 0.5 - uv.y, 0.5 * lon(uv.x).1),
        });
        check_uv_mapping("cone", &cone(24), |uv, n| {
            if n.y < -0.5 {
                cap(uv, -0.5)
            } else {
                Vec3::new(0.5 * uv.y * lon(uv.x).0, 0.5 - uv.y, 0.5 * uv.y * lon(uv.x).1)
            }
        });
        check_uv_mapping("torus", &torus(32, 12, 0.15), |uv, _| {
            let (s, c) = lon(uv.x);
            let (sin_tube, cos_tube) = (-TAU * uv.y).sin_cos();
            Vec3::new(0.35 * s, 0.0, 0.35 * c) + 0.15 * Vec3::new(cos_tube * s, sin_tube, cos_tube * c)
        });
        check_uv_mapping("plane", &plane(4), |uv, _| Vec3::new(uv.x - 0.5, 0.0, uv.y - 0.5));
        check_uv_mapping(
            "pyramid base",
            &MeshData { vertices: pyramid().vertices[12..].to_vec(), indices: vec![] },
            |uv, _| Vec3::new(uv.x - 0.5, -0.5, 0.5 - uv.y),
        );
    }

    /// Each face of the cube and each side of the pyramid shows the whole
    /// texture the right way round: seen from outside, u runs to the right
    /// and v down (so ∂P/∂u × ∂P/∂v points into the face), and on the
    /// upright faces "up the image" is up.
    #[test]
    fn flat_faces_show_the_texture_upright_and_unmirrored() {
        for (name, mesh) in [("cube", cube()), ("pyramid", pyramid())] {
            for t in mesh.indices.chunks_exact(3) {
                let [a, b, c] = [0, 1, 2].map(|k| mesh.vertices[t[k] as usize]);
                let (p, uv) = ([a, b, c].map(|v| Vec3::from(v.position)), [a, b, c].map(|v| Vec2::from(v.uv)));
                let (e1, e2, d1, d2) = (p[1] - p[0], p[2] - p[0], uv[1] - uv[0], uv[2] - uv[0]);
                let det = d1.x * d2.y - d2.x * d1.y;
                let du = (e1 * d2.y - e2 * d1.y) / det;
                let dv = (e2 * d1.x - e1 * d2.x) / det;
                let n = Vec3::from(a.normal);
                assert!(du.cross(dv).dot(n) < 0.0, "{name}: triangle {t:?} shows its texture mirrored");
                if n.y.abs() < 0.9 {
                    assert!(dv.y < 0.0, "{name}: triangle {t:?} shows its texture upside down");
                }
            }
        }
    }
    // ANCHOR_END: uv_tests

    #[test]
    fn plane_faces_up() {
        let mesh = plane(4);
        assert_eq!((mesh.vertices.len(), mesh.indices.len()), (25, 96));
        check_well_formed("plane", &mesh);
        assert!(mesh.vertices.iter().all(|v| v.normal == [0.0, 1.0, 0.0]));
    }
}
