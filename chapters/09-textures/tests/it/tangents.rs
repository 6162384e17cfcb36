//! Tangents on every primitive of `common` and on the three models this
//! chapter builds in (car, tower, boat; not chapter 10's): unit length, at
//! right angles to the normal, pointing the way u grows, and close to what
//! MikkTSpace (the reference implementation that Blender and glTF use, here
//! as the `bevy_mikktspace` crate) computes.

use std::path::Path;

use bevy_mikktspace::{Geometry, TangentSpace, generate_tangents};
use common::glam::{Vec2, Vec3, Vec4};
use common::{MeshData, primitives};
use textures::mesh::{MaterialDesc, ModelData};
use textures::{builtin, obj, tangents};

fn primitives() -> Vec<(&'static str, MeshData)> {
    vec![
        ("cube", primitives::cube()),
        ("sphere", primitives::uv_sphere(24, 12)),
        ("cylinder", primitives::cylinder(24)),
        ("cone", primitives::cone(24)),
        ("torus", primitives::torus(32, 12, 0.15)),
        ("pyramid", primitives::pyramid()),
        ("plane", primitives::plane(4)),
    ]
}

fn models() -> Vec<(String, ModelData)> {
    let mut all: Vec<(String, ModelData)> = primitives()
        .into_iter()
        .map(|(name, mesh)| {
            (name.to_string(), ModelData::from_mesh(&mesh, MaterialDesc::plain("test", Vec3::ONE, 0.0, 1.0)))
        })
        .collect();
    for name in ["car", "tower", "boat"] {
        let path = format!("models/{name}/{name}.obj");
        all.push((name.to_string(), obj::load(Path::new(&path), &builtin::read).unwrap().model));
    }
    all
}

#[test]
fn tangents_are_unit_length_at_right_angles_to_the_normal_and_along_u() {
    for (name, model) in models() {
        for triangle in model.indices.chunks_exact(3) {
            let v = [0, 1, 2].map(|k| model.vertices[triangle[k] as usize]);
            let Some((du, _)) = tangents::triangle_tangents(v.map(|v| v.position.into()), v.map(|v| v.uv.into()))
            else {
                continue;
            };
            for vertex in v {
                let t = Vec4::from(vertex.tangent);
                let n = Vec3::from(vertex.normal);
                assert!((t.truncate().length() - 1.0).abs() < 1e-5, "{name}: tangent {t} is not unit length");
                assert!(t.truncate().dot(n).abs() < 1e-4, "{name}: tangent {t} is not at right angles to {n}");
                assert!(t.w == 1.0 || t.w == -1.0, "{name}: handedness {}", t.w);
                // Along u: within 90° of this triangle's ∂P/∂u (made orthogonal to n).
                let along = du - n * n.dot(du);
                assert!(along.length() < 1e-6 || t.truncate().dot(along) > 0.0, "{name}: tangent {t} points against u");
            }
        }
    }
}

/// The geometry MikkTSpace reads: our triangles, with texture coordinates
/// turned back to OBJ's way (v up the image), as MikkTSpace expects.
struct Mikk<'a> {
    model: &'a ModelData,
    out: Vec<Option<TangentSpace>>,
}

impl Geometry for Mikk<'_> {
    fn num_faces(&self) -> usize {
        self.model.indices.len() / 3
    }
    fn num_vertices_of_face(&self, _face: usize) -> usize {
        3
    }
    fn position(&self, face: usize, vert: usize) -> [f32; 3] {
        self.model.vertices[self.model.indices[3 * face + vert] as usize].position
    }
    fn normal(&self, face: usize, vert: usize) -> [f32; 3] {
        self.model.vertices[self.model.indices[3 * face + vert] as usize].normal
    }
    fn tex_coord(&self, face: usize, vert: usize) -> [f32; 2] {
        let uv = self.model.vertices[self.model.indices[3 * face + vert] as usize].uv;
        [uv[0], 1.0 - uv[1]]
    }
    fn set_tangent(&mut self, tangent: Option<TangentSpace>, face: usize, vert: usize) {
        self.out[3 * face + vert] = tangent;
    }
}

/// Per model: the largest and the mean angle between our tangent and
/// MikkTSpace's at each triangle corner, and how many corners disagree on
/// handedness. Corners of triangles with no UV area are skipped (neither
/// method defines a tangent there).
fn compare_with_mikktspace(model: &ModelData) -> (f32, f32, usize, usize) {
    let mut mikk = Mikk { model, out: vec![None; model.indices.len()] };
    generate_tangents(&mut mikk).unwrap();
    let (mut worst, mut sum, mut count, mut flipped) = (0.0f32, 0.0f32, 0usize, 0usize);
    for (corner, reference) in mikk.out.iter().enumerate() {
        let triangle = &model.indices[corner / 3 * 3..corner / 3 * 3 + 3];
        let v = [0, 1, 2].map(|k| model.vertices[triangle[k] as usize]);
        if tangents::triangle_tangents(v.map(|v| v.position.into()), v.map(|v| Vec2::from(v.uv))).is_none() {
            continue;
        }
        let Some(reference) = reference else { continue };
        let ours = Vec4::from(model.vertices[model.indices[corner] as usize].tangent);
        let theirs = Vec4::from(reference.tangent_encoded());
        let angle = ours.truncate().angle_between(theirs.truncate()).to_degrees();
        worst = worst.max(angle);
        sum += angle;
        count += 1;
        flipped += usize::from(ours.w != theirs.w);
    }
    (worst, sum / count.max(1) as f32, count, flipped)
}

// ANCHOR: mikktspace
/// Our tangents against MikkTSpace's on every model of `models()`, corner
/// by corner: the same handedness at every one; within 0.02° everywhere
/// but on the boat and on `common`'s cone. On the cone MikkTSpace, which
/// averages only triangles joined by edges around a vertex, keeps one
/// tangent per triangle along the base: the tip's zero-area triangles were
/// dropped, so each base vertex's two triangles share no edge. A cone of
/// two rows, or one without a tip, agrees within 0.03°.
#[test]
fn tangents_agree_with_mikktspace() {
    // (model, corners compared, worst angle, mean angle). 0.0198° is the
    // smallest angle f32 can tell from none (acos of the float below 1):
    // there the two agree to rounding. The others are measured, and the
    // tangents are computed on the CPU, the same on every machine up to a
    // last bit of sin or acos: 0.01° and 0.001° allow for that.
    const EXPECTED: [(&str, usize, f32, f32); 10] = [
        ("cube", 36, 0.0, 0.0),
        ("sphere", 1584, 0.0198, 0.0004),
        ("cylinder", 288, 0.0, 0.0),
        ("cone", 144, 3.3696, 1.0764),
        ("torus", 2304, 0.0198, 0.0),
        ("pyramid", 18, 0.0, 0.0),
        ("plane", 96, 0.0, 0.0),
        ("car", 996, 0.0198, 0.0001),
        ("tower", 126, 0.0, 0.0),
        ("boat", 1749, 0.9409, 0.0490),
    ];
    let models = models();
    assert_eq!(models.len(), EXPECTED.len());
    for ((name, model), (expected_name, expected_corners, expected_worst, expected_mean)) in models.iter().zip(EXPECTED)
    {
        assert_eq!(name, expected_name);
        let (worst, mean, corners, flipped) = compare_with_mikktspace(model);
        eprintln!("{name}: {corners} corners, worst {worst:.4}°, mean {mean:.5}°, handedness differs at {flipped}");
        // Every corner of a triangle with UV area is compared: none skipped.
        assert_eq!(corners, expected_corners, "{name}: {corners} corners compared");
        assert_eq!(flipped, 0, "{name}: handedness disagrees at {flipped} corners");
        assert!((worst - expected_worst).abs() <= 0.01, "{name}: worst difference {worst}°, not {expected_worst}°");
        assert!(expected_worst > 0.02 || worst < 0.02, "{name}: worst difference {worst}°, over 0.02°");
        assert!((mean - expected_mean).abs() <= 0.001, "{name}: mean difference {mean}°, not {expected_mean}°");
    }
}
// ANCHOR_END: mikktspace

/// The seed's per-face tangents, once made orthogonal to each vertex's
/// normal as the fragment shader does, against per-vertex tangents: the
/// same on meshes made of flat faces, degrees apart on curved ones (the
/// book quotes these numbers).
#[test]
fn per_face_tangents_match_per_vertex_on_flat_faces_only() {
    for (name, model) in models() {
        let faced = model.with_face_tangents();
        let (mut worst, mut sum) = (0.0f32, 0.0f32);
        for (corner, &i) in model.indices.iter().enumerate() {
            let vertex = model.vertices[i as usize];
            let n = Vec3::from(vertex.normal);
            let face = Vec4::from(faced.vertices[corner].tangent).truncate();
            let projected = (face - n * n.dot(face)).normalize_or_zero();
            let angle = projected.angle_between(Vec4::from(vertex.tangent).truncate()).to_degrees();
            if angle.is_finite() {
                worst = worst.max(angle);
                sum += angle;
            }
        }
        let mean = sum / model.indices.len() as f32;
        eprintln!("{name}: per-face after Gram–Schmidt against per-vertex: worst {worst:.2}°, mean {mean:.3}°");
        match name.as_str() {
            "cube" | "pyramid" | "plane" | "tower" => assert!(worst < 0.05, "{name}: flat faces, yet {worst}° apart"),
            "sphere" | "torus" => assert!(mean > 2.0, "{name}: curved, yet only {mean}° apart on average"),
            _ => {}
        }
    }
}
