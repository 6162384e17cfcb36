//! Reading Wavefront OBJ models and their MTL materials through tobj, and
//! making whatever a learner brings drawable: files in the wild lack
//! normals or texture coordinates, use quads and n-gons, count indices
//! backwards, name textures that are not there, or are simply broken.
//! Missing pieces are made up, with a warning; broken files are an error
//! that names the file and, where it can be found, the line.

use std::cell::RefCell;
use std::collections::HashMap;
use std::path::{Component, Path, PathBuf};

use common::files::ReadError;
use common::glam::Vec3;
use common::{MeshData, Vertex};

use crate::mesh::{MaterialDesc, ModelData};

/// Where files come from: the disk, or the chapter's built-in copies.
pub type ReadFile<'a> = &'a dyn Fn(&Path) -> Result<Vec<u8>, ReadError>;

/// A model as loaded, with what had to be made up on the way.
#[derive(Clone, Debug, Default)]
pub struct LoadedModel {
    pub model: ModelData,
    /// One line each, naming the file: a missing MTL, meshes without
    /// normals or texture coordinates.
    pub warnings: Vec<String>,
    /// The objects and groups the file had (tobj's models).
    pub objects: usize,
}

/// A file that cannot be used at all, as one line.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ModelError(pub String);

impl std::fmt::Display for ModelError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for ModelError {}

/// Normals are smoothed across edges whose faces meet at less than this;
/// sharper edges stay creased.
pub const SMOOTHING_ANGLE_DEGREES: f32 = 60.0;

/// The material of meshes whose file has none: light grey, a soft highlight.
pub fn default_material() -> MaterialDesc {
    MaterialDesc::plain("default", Vec3::splat(0.6), 0.2, 32.0)
}

// ANCHOR: load
/// Loads `path` and the MTL files it names, reading through `read`.
pub fn load(path: &Path, read: ReadFile) -> Result<LoadedModel, ModelError> {
    let bytes = read(path).map_err(|e| ModelError(e.to_string()))?;
    if let Some((line, what)) = bad_face_index(&bytes) {
        return Err(ModelError(format!("{}: line {line}: {what}", path.display())));
    }
    let folder = path.parent().unwrap_or(Path::new(""));
    let options = tobj::LoadOptions {
        // Quads and n-gons become triangle fans; one index per vertex, so
        // that a corner's position, normal and uv travel together.
        triangulate: true,
        single_index: true,
        ignore_points: true,
        ignore_lines: true,
    };
    // tobj's material loader is a `Fn`: what it learns goes through cells.
    let warnings = RefCell::new(Vec::new());
    let mtl_error = RefCell::new(None);
    // Texture paths in an MTL are relative to that MTL: remember, for each
    // material, the folder of the file it came from.
    let folders: RefCell<HashMap<String, PathBuf>> = RefCell::new(HashMap::new());
    let (models, materials) = tobj::load_obj_buf(&mut bytes.as_slice(), &options, |mtl: &Path| {
        let mtl_path = folder.join(mtl);
        match read(&mtl_path) {
            Ok(text) => {
                // tobj panics on some malformed colour lines: check first.
                if let Some((line, what)) = check_mtl(&text) {
                    *mtl_error.borrow_mut() = Some(format!("{}: line {line}: {what}", mtl_path.display()));
                    return Err(tobj::LoadError::MaterialParseError);
                }
                let loaded = tobj::load_mtl_buf(&mut text.as_slice());
                match &loaded {
                    Ok((materials, _)) => {
                        let mtl_folder = mtl_path.parent().unwrap_or(Path::new("")).to_path_buf();
                        for m in materials {
                            folders.borrow_mut().insert(m.name.clone(), mtl_folder.clone());
                        }
                    }
                    Err(kind) => *mtl_error.borrow_mut() = Some(format!("{}: {kind}", mtl_path.display())),
                }
                loaded
            }
            Err(error) => {
                warnings.borrow_mut().push(format!("{error}; using a default material"));
                Err(tobj::LoadError::OpenFileFailed)
            }
        }
    })
    .map_err(|kind| {
        let text = String::from_utf8_lossy(&bytes);
        let line = locate_obj_error(kind, &text).map_or(String::new(), |n| format!("line {n}: "));
        ModelError(format!("{}: {line}{kind}", path.display()))
    })?;
    if let Some(message) = mtl_error.into_inner() {
        return Err(ModelError(message));
    }
    let mut warnings = warnings.into_inner();
    let folders = folders.into_inner();
    let materials: Vec<MaterialDesc> = materials
        .unwrap_or_default()
        .iter()
        .map(|m| {
            let here = folders.get(&m.name).map_or(folder, PathBuf::as_path);
            let mut material = material_of(m);
            material.albedo_map = material.albedo_map.map(|p| normalise(&here.join(p)));
            material.normal_map = material.normal_map.map(|p| normalise(&here.join(p)));
            material
        })
        .collect();
    let mut model = ModelData { materials, ..Default::default() };
    let (mut without_normals, mut without_uvs) = (0, 0);
    for object in &models {
        let mesh = &object.mesh;
        if mesh.indices.is_empty() {
            continue;
        }
        // Faces that give normals (or uvs) mixed with faces that don't
        // leave tobj's lists short: then the mesh counts as having none.
        let vertex_count = mesh.positions.len() / 3;
        let has_normals = mesh.normals.len() == 3 * vertex_count;
        let has_uvs = mesh.texcoords.len() == 2 * vertex_count;
        without_normals += usize::from(!has_normals);
        without_uvs += usize::from(!has_uvs);
        let mut data = MeshData {
            vertices: (0..mesh.positions.len() / 3)
                .map(|i| Vertex {
                    position: [mesh.positions[3 * i], mesh.positions[3 * i + 1], mesh.positions[3 * i + 2]],
                    normal: if has_normals {
                        [mesh.normals[3 * i], mesh.normals[3 * i + 1], mesh.normals[3 * i + 2]]
                    } else {
                        [0.0; 3]
                    },
                    // OBJ's v runs up the image; wgpu's runs down.
                    uv: if has_uvs { [mesh.texcoords[2 * i], 1.0 - mesh.texcoords[2 * i + 1]] } else { [0.0; 2] },
                })
                .collect(),
            indices: mesh.indices.clone(),
        };
        if !has_normals {
            data = smooth_normals(&data, SMOOTHING_ANGLE_DEGREES);
        }
        let material = match mesh.material_id.filter(|&m| m < model.materials.len()) {
            Some(m) if has_uvs => m,
            // Without texture coordinates there is nothing to map a texture
            // with: the same material, its maps left off.
            Some(m) => untextured(&mut model.materials, m),
            None => default_index(&mut model.materials),
        };
        model.append(&data, material, common::glam::Mat4::IDENTITY, |uv, _| uv);
    }
    let name = path.display();
    if without_normals > 0 {
        warnings.push(format!(
            "{name}: {without_normals} mesh(es) without normals; computed, smooth up to {SMOOTHING_ANGLE_DEGREES}°"
        ));
    }
    if without_uvs > 0 {
        warnings.push(format!("{name}: {without_uvs} mesh(es) without texture coordinates; drawn untextured"));
    }
    if model.indices.is_empty() {
        return Err(ModelError(format!("{name}: no faces to draw")));
    }
    model.group_by_material();
    Ok(LoadedModel { model, warnings, objects: models.len() })
}
// ANCHOR_END: load

fn default_index(materials: &mut Vec<MaterialDesc>) -> usize {
    if let Some(i) = materials.iter().position(|m| *m == default_material()) {
        return i;
    }
    materials.push(default_material());
    materials.len() - 1
}

fn untextured(materials: &mut Vec<MaterialDesc>, index: usize) -> usize {
    let plain = MaterialDesc {
        name: format!("{} (no texture coordinates)", materials[index].name),
        albedo_map: None,
        normal_map: None,
        ..materials[index].clone()
    };
    if let Some(i) = materials.iter().position(|m| *m == plain) {
        return i;
    }
    materials.push(plain);
    materials.len() - 1
}

// ANCHOR: material
/// An MTL material as this chapter draws it.
fn material_of(m: &tobj::Material) -> MaterialDesc {
    let colour = |c: Option<[f32; 3]>, default: f32| c.map_or(Vec3::splat(default), Vec3::from);
    let normal_map = m.normal_texture.clone().or_else(|| m.unknown_param.get("norm").cloned());
    MaterialDesc {
        name: m.name.clone(),
        diffuse: colour(m.diffuse, 0.8),
        specular: colour(m.specular, 0.0).element_sum() / 3.0,
        shininess: m.shininess.unwrap_or(1.0).max(1.0),
        emissive: colour(m.emissive, 0.0),
        at_night: false,
        albedo_map: m.diffuse_texture.as_deref().and_then(texture_file),
        normal_map: normal_map.as_deref().and_then(texture_file),
    }
}
// ANCHOR_END: material

/// The file name in an MTL texture statement, without its options
/// (`map_Bump -bm 0.5 bricks normal.png` names "bricks normal.png"), with
/// Windows separators turned round.
pub fn texture_file(statement: &str) -> Option<PathBuf> {
    let mut words = statement.split_whitespace().peekable();
    while let Some(&word) = words.peek() {
        let arguments = match word {
            "-blendu" | "-blendv" | "-bm" | "-boost" | "-cc" | "-clamp" | "-imfchan" | "-texres" | "-type" => 1,
            "-mm" => 2,
            "-o" | "-s" | "-t" => 3,
            _ => break,
        };
        words.next();
        for _ in 0..arguments {
            // -o, -s and -t take one to three numbers.
            if words.peek().is_some_and(|w| w.parse::<f32>().is_ok() || arguments < 3) {
                words.next();
            }
        }
    }
    let name = words.collect::<Vec<_>>().join(" ").replace('\\', "/");
    (!name.is_empty()).then(|| PathBuf::from(name))
}

/// `a/b/../c` as `a/c`, so that paths print plainly and built-in files are found.
pub fn normalise(path: &Path) -> PathBuf {
    let mut out = PathBuf::new();
    for part in path.components() {
        match part {
            Component::ParentDir if out.file_name().is_some() => {
                out.pop();
            }
            Component::CurDir => {}
            other => out.push(other),
        }
    }
    out
}

// ANCHOR: smooth
/// Normals for a mesh that has none. Each corner gets the average of the
/// faces around its position that meet its own face at less than
/// `max_angle_degrees`, each face weighted by its angle at that position
/// (Thürmer and Wüthrich 1998: a face split in two then counts the same),
/// so curved surfaces come out smooth and sharp edges stay sharp. Corners
/// that end up with the same normal share a vertex.
pub fn smooth_normals(mesh: &MeshData, max_angle_degrees: f32) -> MeshData {
    let position = |i: u32| Vec3::from(mesh.vertices[i as usize].position);
    let faces: Vec<Vec3> = mesh
        .indices
        .chunks_exact(3)
        .map(|t| (position(t[1]) - position(t[0])).cross(position(t[2]) - position(t[0])).normalize_or_zero())
        .collect();
    // Each corner's angle, and which corners share a position (by value:
    // texture seams split vertices that should still be smoothed together).
    let angle = |corner: usize| {
        let (t, k) = (corner / 3 * 3, corner % 3);
        let p = |j: usize| position(mesh.indices[t + (k + j) % 3]);
        let a = (p(1) - p(0)).angle_between(p(2) - p(0));
        if a.is_finite() { a } else { 0.0 }
    };
    // Positions as keys, rounded to a millionth of the model's size: points
    // meant to be one (at a texture seam, say) may differ in the last bits.
    let (low, high) = mesh
        .vertices
        .iter()
        .fold((Vec3::MAX, Vec3::MIN), |(lo, hi), v| (lo.min(v.position.into()), hi.max(v.position.into())));
    let step = ((high - low).max_element() * 1e-6).max(f32::MIN_POSITIVE);
    let key = |p: Vec3| ((p - low) / step).round().to_array().map(|c| c as i64);
    let mut around: HashMap<[i64; 3], Vec<usize>> = HashMap::new();
    for (corner, &i) in mesh.indices.iter().enumerate() {
        around.entry(key(position(i))).or_default().push(corner);
    }
    let threshold = max_angle_degrees.to_radians().cos();
    let mut out = MeshData::default();
    let mut welded: HashMap<(u32, [u32; 3]), u32> = HashMap::new();
    for (corner, &i) in mesh.indices.iter().enumerate() {
        let own = faces[corner / 3];
        let sum: Vec3 = around[&key(position(i))]
            .iter()
            .filter(|&&other| faces[other / 3].dot(own) >= threshold)
            .map(|&other| faces[other / 3] * angle(other))
            .sum();
        let normal = sum.try_normalize().unwrap_or(own);
        let index = *welded.entry((i, normal.to_array().map(f32::to_bits))).or_insert_with(|| {
            out.vertices.push(Vertex { normal: normal.into(), ..mesh.vertices[i as usize] });
            out.vertices.len() as u32 - 1
        });
        out.indices.push(index);
    }
    out
}
// ANCHOR_END: smooth

/// The 1-based line of the first statement tobj would have failed on, for
/// the error kinds where that can be told.
pub fn locate_obj_error(kind: tobj::LoadError, text: &str) -> Option<usize> {
    use tobj::LoadError as E;
    let floats = |words: &[&str], counts: &[usize]| {
        counts.contains(&words.len()) && words.iter().all(|w| w.parse::<f32>().is_ok())
    };
    let (mut positions, mut uvs, mut normals) = (0i64, 0i64, 0i64);
    for (n, line) in text.lines().enumerate() {
        let words: Vec<&str> = line.split_whitespace().collect();
        let Some((&keyword, rest)) = words.split_first() else { continue };
        let bad = match keyword {
            "v" => {
                positions += 1;
                kind == E::PositionParseError && !floats(rest, &[3, 4, 6, 7])
            }
            "vt" => {
                uvs += 1;
                kind == E::TexcoordParseError && !floats(rest, &[1, 2, 3])
            }
            "vn" => {
                normals += 1;
                kind == E::NormalParseError && !floats(rest, &[3])
            }
            "f" => match kind {
                E::InvalidPolygon => rest.len() < 3,
                E::FaceParseError
                | E::FaceVertexOutOfBounds
                | E::FaceTexCoordOutOfBounds
                | E::FaceNormalOutOfBounds => rest.iter().any(|corner| {
                    let mut fields = corner.split('/');
                    let check = |field: Option<&str>, count: i64, required: bool| match field {
                        None | Some("") => required,
                        Some(text) => match text.parse::<i64>() {
                            Ok(i) => i == 0 || i > count || -i > count,
                            Err(_) => true,
                        },
                    };
                    check(fields.next(), positions, true)
                        || check(fields.next(), uvs, false)
                        || check(fields.next(), normals, false)
                }),
                _ => false,
            },
            _ => kind == E::UnrecognizedCharacter && !keyword.starts_with('#') && !KNOWN.contains(&keyword),
        };
        if bad {
            return Some(n + 1);
        }
    }
    None
}

/// OBJ statements tobj reads or skips without complaint.
const KNOWN: [&str; 12] = ["v", "vt", "vn", "f", "l", "p", "o", "g", "s", "mtllib", "usemtl", "vp"];

/// The first line of an MTL file tobj cannot read, and why: a colour
/// with fewer than three numbers (on which tobj panics), a number that is
/// not one, a texture statement without a file.
pub fn check_mtl(text: &[u8]) -> Option<(usize, String)> {
    let text = String::from_utf8_lossy(text);
    for (n, line) in text.lines().enumerate() {
        let words: Vec<&str> = line.split_whitespace().collect();
        let Some((&keyword, rest)) = words.split_first() else { continue };
        let number = |w: &&str| w.parse::<f32>().is_ok();
        let problem = match keyword {
            "Ka" | "Kd" | "Ks" | "Ke" | "Tf" if !(rest.len() >= 3 && rest[..3].iter().all(number)) => {
                Some(format!("{keyword} needs 3 numbers"))
            }
            "Ns" | "Ni" | "d" | "Tr" if !rest.first().is_some_and(number) => Some(format!("{keyword} needs a number")),
            "illum" if rest.first().is_none_or(|w| w.parse::<u8>().is_err()) => {
                Some("illum needs a whole number".into())
            }
            k if (k.starts_with("map_") || k == "bump" || k == "norm") && rest.is_empty() => {
                Some(format!("{keyword} needs a file name"))
            }
            "newmtl" if rest.is_empty() => Some("newmtl needs a name".into()),
            _ => None,
        };
        if let Some(problem) = problem {
            return Some((n + 1, problem));
        }
    }
    None
}

/// The first face line with an index tobj cannot take, and why. tobj
/// turns an index of 0, or a relative one reaching before the first
/// element, into a huge number, and its arithmetic on a texture coordinate
/// or normal index that large overflows (a panic in debug builds); no file
/// has a billion vertices, so longer indices are refused too.
fn bad_face_index(bytes: &[u8]) -> Option<(usize, String)> {
    // Positions, texture coordinates and normals read so far.
    let mut counts = [0i64; 3];
    for (n, line) in bytes.split(|&b| b == b'\n').enumerate() {
        let line = String::from_utf8_lossy(line);
        let mut words = line.split_whitespace();
        match words.next() {
            Some("v") => counts[0] += 1,
            Some("vt") => counts[1] += 1,
            Some("vn") => counts[2] += 1,
            Some("f") => {
                for corner in words {
                    for (kind, index) in corner.split('/').enumerate().take(3) {
                        if index.chars().filter(char::is_ascii_digit).count() > 9 {
                            return Some((n + 1, "index out of range".into()));
                        }
                        let Ok(index) = index.parse::<i64>() else { continue };
                        if index == 0 {
                            return Some((n + 1, "index 0 (OBJ counts from 1)".into()));
                        }
                        if index < 0 && -index > counts[kind] {
                            let what = ["position", "texture coordinate", "normal"][kind];
                            return Some((n + 1, format!("relative index {index} reaches before the first {what}")));
                        }
                    }
                }
            }
            _ => {}
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn texture_statements_lose_their_options() {
        assert_eq!(texture_file("bricks.png"), Some("bricks.png".into()));
        assert_eq!(texture_file("-bm 0.5 bricks normal.png"), Some("bricks normal.png".into()));
        assert_eq!(texture_file("-o 0.1 0.2 -s 2 2 1 tex\\wall.jpg"), Some("tex/wall.jpg".into()));
        assert_eq!(texture_file("-clamp on"), None);
    }

    #[test]
    fn paths_are_normalised() {
        assert_eq!(
            normalise(Path::new("models/car/../../textures/./metal/albedo.png")),
            Path::new("textures/metal/albedo.png")
        );
    }

    #[test]
    fn a_cube_without_normals_keeps_its_edges_and_a_sphere_comes_out_smooth() {
        let strip = |mesh: &MeshData| MeshData {
            vertices: mesh.vertices.iter().map(|v| Vertex { normal: [0.0; 3], ..*v }).collect(),
            indices: mesh.indices.clone(),
        };
        let cube = common::primitives::cube();
        let smoothed = smooth_normals(&strip(&cube), 60.0);
        for (a, b) in smoothed.vertices.iter().zip(&cube.vertices) {
            assert!(Vec3::from(a.normal).abs_diff_eq(b.normal.into(), 1e-6), "a cube's faces stay flat");
        }
        let sphere = common::primitives::uv_sphere(24, 12);
        let smoothed = smooth_normals(&strip(&sphere), 60.0);
        let worst = smoothed
            .indices
            .iter()
            .map(|&i| {
                let v = smoothed.vertices[i as usize];
                Vec3::from(v.normal).angle_between(Vec3::from(v.position).normalize()).to_degrees()
            })
            .fold(0.0f32, f32::max);
        assert!(worst < 1.0, "sphere normals point out from the centre to within {worst}°");
    }
}
