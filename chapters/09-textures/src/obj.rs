//! Reading Wavefront OBJ models and their MTL materials, and making
//! whatever a learner brings drawable: files in the wild come in UTF-16 or
//! Latin-1, lack normals or texture coordinates, carry vertex colours, use
//! concave n-gons, count indices backwards, point past their own lists,
//! name textures on another person's disk, or are simply broken. Missing
//! or damaged pieces are made up or left out, with a warning; broken files
//! are an error that names the file and, where it can be found, the line.
//!
//! The OBJ text is read here, in two passes (the elements, then the faces
//! that use them); MTL files go through the `tobj` crate once their text
//! has been decoded and checked.

use std::borrow::Cow;
use std::collections::HashMap;
use std::path::{Component, Path, PathBuf};

use common::files::ReadError;
use common::glam::{DVec2, DVec3, Vec2, Vec3};
use common::{MeshData, Vertex};

use crate::mesh::{MaterialDesc, ModelData};

/// Where files come from: the disk, or the chapter's built-in copies.
pub type ReadFile<'a> = &'a dyn Fn(&Path) -> Result<Vec<u8>, ReadError>;

/// A model as loaded, with what had to be made up on the way.
#[derive(Clone, Debug, Default)]
pub struct LoadedModel {
    pub model: ModelData,
    /// One line each, naming the file: a missing MTL, meshes without
    /// normals or texture coordinates, indices and numbers left out.
    pub warnings: Vec<String>,
    /// The meshes the file's objects, groups and material changes made.
    pub objects: usize,
    /// Whether its vertices carry colours (`v x y z r g b`).
    pub vertex_colours: bool,
    /// The MTL files read, where they were found.
    pub material_files: Vec<PathBuf>,
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

/// How much a model may hold, so that a huge or damaged file is refused
/// with a message instead of filling the memory or taking minutes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Limits {
    /// A longer line is not OBJ text (a face of 50 000 corners is shorter).
    pub line_bytes: usize,
    /// Positions, texture coordinates or normals, each.
    pub elements: usize,
    pub triangles: usize,
}

impl Limits {
    /// Ten times the million-triangle sphere the bench loads: about 2 GB
    /// on the way through the loader.
    pub const DEFAULT: Self = Self { line_bytes: 1 << 20, elements: 30_000_000, triangles: 10_000_000 };
}

/// The material of meshes whose file has none: light grey, a soft highlight.
pub fn default_material() -> MaterialDesc {
    MaterialDesc::plain("default", Vec3::splat(0.6), 0.2, 32.0)
}

// ANCHOR: load
/// Loads `path` and the MTL files it names, reading through `read`.
pub fn load(path: &Path, read: ReadFile) -> Result<LoadedModel, ModelError> {
    load_within(path, read, Limits::DEFAULT)
}

/// [`load`], refusing files that pass `limits`.
pub fn load_within(path: &Path, read: ReadFile, limits: Limits) -> Result<LoadedModel, ModelError> {
    let name = path.display();
    let bytes = read(path).map_err(|e| ModelError(e.to_string()))?;
    let text = Text::decode(&bytes, limits.line_bytes);
    let mut warnings = Vec::new();
    // Pass 1: positions (and their colours), texture coordinates, normals
    // and the MTL files named, so that faces may use elements listed after
    // them and every material is known before the first `usemtl`.
    let elements =
        read_elements(&text, limits).map_err(|(line, why)| ModelError(format!("{name}: line {line}: {why}")))?;
    warnings.extend(text.warning(&name.to_string()));
    let folder = path.parent().unwrap_or(Path::new(""));
    let libraries = read_material_libraries(folder, &elements.libraries, read, limits, &mut warnings)?;
    // Pass 2: faces, cut into triangles, with one index per vertex, in
    // meshes split where the object, group or material changes.
    let mut face_warnings = Vec::new();
    let meshes = read_faces(&text, &elements, &libraries.index, limits.triangles, &mut face_warnings)
        .map_err(|(line, why)| ModelError(format!("{name}: line {line}: {why}")))?;
    warnings.extend(face_warnings.iter().map(|w| format!("{name}: {w}")));
    warnings.extend(elements.not_finite_warnings(&name.to_string()));
    let mut model = ModelData { materials: libraries.materials, ..Default::default() };
    let (mut without_normals, mut without_uvs) = (0, 0);
    for mesh in &meshes {
        let (data, colours, has_uvs) = mesh.data(&elements);
        without_normals += usize::from(!mesh.has_normals());
        without_uvs += usize::from(!has_uvs);
        let material = match mesh.material.filter(|&m| m < model.materials.len()) {
            Some(m) if has_uvs => m,
            // Without texture coordinates there is nothing to map a texture
            // with: the same material, its maps left off.
            Some(m) => untextured(&mut model.materials, m),
            None => default_index(&mut model.materials),
        };
        let colours = (!elements.colours.is_empty()).then_some(colours.as_slice());
        model.append_coloured(&data, colours, material, common::glam::Mat4::IDENTITY, |uv, _| uv);
    }
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
    let vertex_colours = !elements.colours.is_empty();
    for material in &mut model.materials {
        material.vertex_colours = vertex_colours;
    }
    model.group_by_material();
    Ok(LoadedModel { model, warnings, objects: meshes.len(), vertex_colours, material_files: libraries.files })
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
        roughness_map: None,
        metallic_map: None,
        ..materials[index].clone()
    };
    if let Some(i) = materials.iter().position(|m| *m == plain) {
        return i;
    }
    materials.push(plain);
    materials.len() - 1
}

/// A file's text as UTF-8 bytes, whatever it came as: UTF-8 (a byte-order
/// mark skipped), UTF-16 with a byte-order mark (decoded), with `\n`,
/// `\r\n` or old Macs' `\r` line ends. A line that is not UTF-8 is read as
/// Latin-1, the usual 8-bit encoding of older Windows exporters: names
/// may come out wrong, numbers never do, and one warning says so.
struct Text<'a> {
    bytes: Cow<'a, [u8]>,
    /// The longest line allowed.
    line_bytes: usize,
    /// `\n`, or `\r` for a file that has no `\n` at all.
    line_end: u8,
    /// Lines read as Latin-1: how many, and the first.
    latin1: std::cell::Cell<(usize, usize)>,
}

impl<'a> Text<'a> {
    fn decode(bytes: &'a [u8], line_bytes: usize) -> Self {
        let utf16 = |big_endian: bool| {
            let units = bytes[2..].chunks_exact(2).map(|pair| {
                let pair = [pair[0], pair[1]];
                if big_endian { u16::from_be_bytes(pair) } else { u16::from_le_bytes(pair) }
            });
            let text: String = char::decode_utf16(units).map(|c| c.unwrap_or(char::REPLACEMENT_CHARACTER)).collect();
            Cow::Owned(text.into_bytes())
        };
        let bytes = match bytes {
            [0xFF, 0xFE, ..] => utf16(false),
            [0xFE, 0xFF, ..] => utf16(true),
            [0xEF, 0xBB, 0xBF, rest @ ..] => Cow::Borrowed(rest),
            _ => Cow::Borrowed(bytes),
        };
        let line_end = if !bytes.contains(&b'\n') && bytes.contains(&b'\r') { b'\r' } else { b'\n' };
        Self { bytes, line_bytes, line_end, latin1: std::cell::Cell::new((0, 0)) }
    }

    /// Each line with its number (from 1), without its line end, or the
    /// first line that cannot be text.
    fn lines(&self) -> impl Iterator<Item = Result<(usize, Cow<'_, str>), (usize, String)>> {
        // Text that is all UTF-8 (the usual case) is split by the standard
        // library's `str::split`, which finds line ends much faster than a
        // byte-by-byte search in a debug build.
        let raw: Box<dyn Iterator<Item = &[u8]>> = match std::str::from_utf8(&self.bytes) {
            Ok(text) => Box::new(text.split(char::from(self.line_end)).map(str::as_bytes)),
            Err(_) => Box::new(self.bytes.split(move |&b| b == self.line_end)),
        };
        raw.enumerate().map(|(i, raw)| {
            let n = i + 1;
            let raw = raw.strip_suffix(b"\r").unwrap_or(raw);
            if raw.len() > self.line_bytes {
                let size = if raw.len() >= 1 << 20 {
                    format!("{} MiB", raw.len() >> 20)
                } else {
                    format!("{} bytes", raw.len())
                };
                return Err((n, format!("{size} on one line, more than OBJ or MTL text has")));
            }
            if raw.contains(&0) {
                return Err((n, "a zero byte: a binary file, not OBJ or MTL text".into()));
            }
            Ok((n, self.line(n, raw)))
        })
    }

    fn line<'b>(&self, n: usize, raw: &'b [u8]) -> Cow<'b, str> {
        match std::str::from_utf8(raw) {
            Ok(line) => Cow::Borrowed(line),
            Err(_) => {
                let (count, first) = self.latin1.get();
                self.latin1.set((count + 1, if count == 0 { n } else { first }));
                Cow::Owned(raw.iter().map(|&b| char::from(b)).collect())
            }
        }
    }

    /// The one warning for lines read as Latin-1, if there were any.
    fn warning(&self, name: &str) -> Option<String> {
        match self.latin1.get() {
            (0, _) => None,
            (1, first) => Some(format!("{name}: line {first} is not UTF-8; read as Latin-1")),
            (count, first) => {
                Some(format!("{name}: line {first} and {} more are not UTF-8; read as Latin-1", count - 1))
            }
        }
    }
}

/// `line` without its first word and the space around the rest: names
/// with spaces inside (`usemtl Material 01 `) stay whole.
fn rest_of_line(line: &str) -> &str {
    let line = line.trim_start();
    line.find(char::is_whitespace).map_or("", |end| line[end..].trim())
}

/// The words of a line, split at spaces and tabs. (`str::split_whitespace`
/// does the same for all of Unicode's spaces, several times slower.)
struct Words<'a>(&'a str);

impl<'a> Iterator for Words<'a> {
    type Item = &'a str;

    fn next(&mut self) -> Option<&'a str> {
        let bytes = self.0.as_bytes();
        let mut start = 0;
        while start < bytes.len() && bytes[start].is_ascii_whitespace() {
            start += 1;
        }
        let mut end = start;
        while end < bytes.len() && !bytes[end].is_ascii_whitespace() {
            end += 1;
        }
        let word = &self.0[start..end];
        self.0 = &self.0[end..];
        (!word.is_empty()).then_some(word)
    }
}

/// A number as an OBJ or MTL file writes it.
enum Number {
    Finite(f32),
    /// `nan`, `inf`, a number too large for an f32, or what Microsoft's C
    /// library prints for those (`1.#IND`, `-1.#INF`, `1.#QNAN`, `-nan(ind)`).
    NotFinite,
}

fn number(word: &str) -> Option<Number> {
    match word.parse::<f32>() {
        Ok(x) if x.is_finite() => Some(Number::Finite(x)),
        Ok(_) => Some(Number::NotFinite),
        Err(_) => {
            let lower = word.to_ascii_lowercase();
            ["#ind", "#inf", "#qnan", "#snan", "nan("].iter().any(|k| lower.contains(k)).then_some(Number::NotFinite)
        }
    }
}

/// The first `N` numbers of `words` (more may follow), `None` where one
/// is not finite; or why they are not numbers.
fn numbers<const N: usize>(words: &[&str], what: &str) -> Result<Option<[f32; N]>, String> {
    if words.len() < N {
        return Err(format!("{what} parse error: {N} numbers needed, the line has {}", words.len()));
    }
    let mut out = [0.0; N];
    let mut finite = true;
    for (k, word) in words[..N].iter().enumerate() {
        match number(word) {
            Some(Number::Finite(x)) => out[k] = x,
            Some(Number::NotFinite) => finite = false,
            None => return Err(format!("{what} parse error: `{word}` is not a number")),
        }
    }
    Ok(finite.then_some(out))
}

/// An sRGB component (as vertex colours are written) to linear light.
fn srgb_to_linear(c: f32) -> f32 {
    common::texture::srgb_to_linear(c.clamp(0.0, 1.0))
}

/// What pass 1 reads: every element, in file order. Elements that are not
/// finite numbers stay in the lists (so that indices still count right) as
/// NaN, and faces leave them out.
#[derive(Default)]
struct Elements {
    positions: Vec<Vec3>,
    /// Linear RGB, one per position: empty when no vertex has a colour;
    /// white for those that do not, once one does.
    colours: Vec<Vec3>,
    uvs: Vec<Vec2>,
    normals: Vec<Vec3>,
    /// `mtllib` lines: the line number and what follows the keyword.
    libraries: Vec<(usize, String)>,
    /// Positions, texture coordinates and normals that were not finite:
    /// how many, and the first line.
    not_finite: [(usize, usize); 3],
}

impl Elements {
    /// One warning each for the positions, texture coordinates and
    /// normals that were not finite numbers.
    fn not_finite_warnings(&self, name: &str) -> Vec<String> {
        let what = [
            ("position(s)", "left out, with the faces that use them"),
            ("texture coordinate(s)", "left out of the faces that use them"),
            ("normal(s)", "left out, and computed instead"),
        ];
        let nan = "are not finite numbers (nan, inf, 1.#IND)";
        self.not_finite
            .iter()
            .zip(what)
            .filter(|((count, _), _)| *count > 0)
            .map(|((count, first), (kind, fix))| format!("{name}: line {first}: {count} {kind} {nan}: {fix}"))
            .collect()
    }

    fn note_not_finite(&mut self, kind: usize, line: usize) {
        let (count, first) = self.not_finite[kind];
        self.not_finite[kind] = (count + 1, if count == 0 { line } else { first });
    }
}

/// Pass 1: every `v`, `vt` and `vn` line, and the `mtllib` lines.
fn read_elements(text: &Text, limits: Limits) -> Result<Elements, (usize, String)> {
    let mut e = Elements::default();
    // Every face is at least one triangle: a file of far too many faces
    // is refused here, before its faces are read.
    let mut faces = 0;
    for line in text.lines() {
        let (n, line) = line?;
        let mut words = Words(&line);
        let keyword = words.next();
        if keyword == Some("f") {
            faces += 1;
            if faces > limits.triangles {
                return Err((n, too_many_triangles(limits.triangles)));
            }
        }
        if !matches!(keyword, Some("v" | "vt" | "vn" | "mtllib")) {
            continue;
        }
        // The first few words are all any element has.
        let mut list = [""; 8];
        let mut count = 0;
        for word in words {
            if count < list.len() {
                list[count] = word;
            }
            count += 1;
        }
        let words = &list[..count.min(list.len())];
        let full = |list_len: usize, what: &str| {
            if list_len >= limits.elements {
                Err((n, format!("more than {} {what}: more than this chapter draws", limits.elements)))
            } else {
                Ok(())
            }
        };
        match keyword {
            Some("v") => {
                full(e.positions.len(), "positions")?;
                let nan = Vec3::NAN;
                let mut position = match numbers::<3>(words, "position").map_err(|why| (n, why))? {
                    Some(p) => Vec3::from(p),
                    None => {
                        e.note_not_finite(0, n);
                        nan
                    }
                };
                match count {
                    // x y z w: a weight, dividing the rest (rational curves).
                    4 => {
                        if let Some(Number::Finite(w)) = number(words[3])
                            && w != 0.0
                        {
                            position /= w;
                        }
                    }
                    // x y z r g b: a colour (MeshLab, photogrammetry, ZBrush).
                    6.. => {
                        let colour = match numbers::<3>(&words[3..], "vertex colour").map_err(|why| (n, why))? {
                            Some(c) => Vec3::from(c.map(srgb_to_linear)),
                            None => Vec3::ONE,
                        };
                        if e.colours.is_empty() {
                            e.colours = vec![Vec3::ONE; e.positions.len()];
                        }
                        e.colours.push(colour);
                    }
                    _ => {}
                }
                e.positions.push(position);
                if !e.colours.is_empty() && e.colours.len() < e.positions.len() {
                    e.colours.push(Vec3::ONE);
                }
            }
            Some("vt") => {
                full(e.uvs.len(), "texture coordinates")?;
                // u, and v if given (1D textures write only u).
                let (u, v) = match words {
                    [] => return Err((n, "texture coordinate parse error: no numbers".into())),
                    [u] => (*u, "0"),
                    [u, v, ..] => (*u, *v),
                };
                let uv = match numbers::<2>(&[u, v], "texture coordinate").map_err(|why| (n, why))? {
                    Some(uv) => Vec2::from(uv),
                    None => {
                        e.note_not_finite(1, n);
                        Vec2::NAN
                    }
                };
                e.uvs.push(uv);
            }
            Some("vn") => {
                full(e.normals.len(), "normals")?;
                let normal = match numbers::<3>(words, "normal").map_err(|why| (n, why))? {
                    Some(normal) => Vec3::from(normal),
                    None => {
                        e.note_not_finite(2, n);
                        Vec3::NAN
                    }
                };
                e.normals.push(normal);
            }
            _ => {
                let rest = rest_of_line(&line);
                if rest.is_empty() {
                    return Err((n, "mtllib needs a file name".into()));
                }
                e.libraries.push((n, rest.to_string()));
            }
        }
    }
    Ok(e)
}

fn too_many_triangles(limit: usize) -> String {
    format!("more than {limit} triangles: more than this chapter draws")
}

/// What the MTL files gave: the materials as this chapter draws them, the
/// index of each name, and the files found.
struct Libraries {
    materials: Vec<MaterialDesc>,
    index: HashMap<String, usize>,
    files: Vec<PathBuf>,
}

/// Reads every MTL file the `mtllib` lines name. A line may name several
/// files (`mtllib a.mtl b.mtl`), or one whose name has spaces: the whole
/// line is tried as one file first. A missing file is a warning, and the
/// meshes that use its materials get a default one.
fn read_material_libraries(
    folder: &Path,
    lines: &[(usize, String)],
    read: ReadFile,
    limits: Limits,
    warnings: &mut Vec<String>,
) -> Result<Libraries, ModelError> {
    let mut out = Libraries { materials: Vec::new(), index: HashMap::new(), files: Vec::new() };
    for (_, rest) in lines {
        let whole = find_file(Path::new(rest), folder, &[folder], read);
        let found = match whole {
            Found::Nowhere { .. } if rest.split_whitespace().count() > 1 => {
                let each: Vec<Found> =
                    rest.split_whitespace().map(|word| find_file(Path::new(word), folder, &[folder], read)).collect();
                // None of them either: one name with spaces, missing.
                let none = each.iter().all(|f| matches!(f, Found::Nowhere { .. }));
                if none { vec![whole] } else { each }
            }
            other => vec![other],
        };
        for file in found {
            let (mtl_path, bytes) = match file {
                Found::AsWritten(path, bytes) => (path, bytes),
                Found::Elsewhere { written, path, bytes } => {
                    warnings.push(format!(
                        "{}: not found as written; using {} (same name, beside the OBJ)",
                        written.display(),
                        path.display()
                    ));
                    (path, bytes)
                }
                Found::Nowhere { error, tried } => {
                    warnings.push(format!("{error}{}; using a default material", also_tried(&tried[1..])));
                    continue;
                }
            };
            if out.files.contains(&mtl_path) {
                continue;
            }
            let here = mtl_path.parent().unwrap_or(Path::new("")).to_path_buf();
            let (materials, mtl_warnings) = read_mtl(&mtl_path, &bytes, limits.line_bytes)?;
            warnings.extend(mtl_warnings);
            for m in &materials {
                let mut material = material_of(m);
                let texture_path = |p: PathBuf| normalise(&here.join(p));
                material.albedo_map = material.albedo_map.map(texture_path);
                material.normal_map = material.normal_map.map(texture_path);
                material.roughness_map = material.roughness_map.map(texture_path);
                material.metallic_map = material.metallic_map.map(texture_path);
                // Where else to look for a texture by its name alone: beside
                // the MTL, then beside the OBJ.
                material.texture_folders = vec![here.clone()];
                if here != folder {
                    material.texture_folders.push(folder.to_path_buf());
                }
                // Later files win, as they would in tobj.
                out.index.insert(m.name.clone(), out.materials.len());
                out.materials.push(material);
            }
            out.files.push(mtl_path);
        }
    }
    Ok(out)
}

/// The materials of one MTL file through tobj, once its text is decoded
/// and checked; and its warnings: Latin-1, and Pr or Pm out of range.
fn read_mtl(path: &Path, bytes: &[u8], line_bytes: usize) -> Result<(Vec<tobj::Material>, Vec<String>), ModelError> {
    let name = path.display();
    let text = Text::decode(bytes, line_bytes);
    let mut clean = String::with_capacity(text.bytes.len());
    for line in text.lines() {
        let (_, line) = line.map_err(|(n, why)| ModelError(format!("{name}: line {n}: {why}")))?;
        clean.push_str(&line);
        clean.push('\n');
    }
    // tobj panics on some malformed colour lines: check first.
    if let Some((line, what)) = check_mtl(clean.as_bytes()) {
        return Err(ModelError(format!("{name}: line {line}: {what}")));
    }
    let (mut materials, _) =
        tobj::load_mtl_buf(&mut clean.as_bytes()).map_err(|kind| ModelError(format!("{name}: {kind}")))?;
    let mut warnings: Vec<String> = text.warning(&name.to_string()).into_iter().collect();
    physical_keys(&name.to_string(), &clean, &mut materials, &mut warnings);
    Ok((materials, warnings))
}

// ANCHOR: physical_keys
/// Pr and Pm, the roughness and metalness that exporters for physically
/// based shading write (tobj keeps them as unknown keys): a value outside
/// 0 to 1 is clamped, and one that is not a number is left out, each with a
/// warning naming the file and the line.
fn physical_keys(name: &str, text: &str, materials: &mut [tobj::Material], warnings: &mut Vec<String>) {
    let mut current = None;
    for (index, line) in text.lines().enumerate() {
        let mut words = line.split_whitespace();
        let (Some(key), rest) = (words.next(), words.collect::<Vec<_>>().join(" ")) else { continue };
        if key == "newmtl" {
            current = materials.iter().position(|m| m.name == rest);
            continue;
        }
        let (Some(at), "Pr" | "Pm") = (current, key) else { continue };
        let what = if key == "Pr" { "roughness" } else { "metalness" };
        let line = index + 1;
        match rest.parse::<f32>() {
            Ok(value) if value.is_finite() && !(0.0..=1.0).contains(&value) => {
                let clamped = value.clamp(0.0, 1.0);
                warnings.push(format!("{name}: line {line}: {key} {rest} is outside 0 to 1; {what} {clamped} used"));
                materials[at].unknown_param.insert(key.into(), clamped.to_string());
            }
            Ok(value) if value.is_finite() => {}
            _ => {
                warnings.push(format!("{name}: line {line}: {key} `{rest}` is not a number; left out"));
                materials[at].unknown_param.remove(key);
            }
        }
    }
}
// ANCHOR_END: physical_keys

/// A file looked for by [`find_file`].
pub enum Found {
    /// Where its path says.
    AsWritten(PathBuf, Vec<u8>),
    /// Not there, but a file of the same name is in one of the folders.
    Elsewhere { written: PathBuf, path: PathBuf, bytes: Vec<u8> },
    /// Nowhere: the error for the path as written, and every place tried.
    Nowhere { error: ReadError, tried: Vec<PathBuf> },
}

/// A file an OBJ or MTL names, `written` relative to `base`. Files from
/// other machines name places that do not exist here
/// (`C:\\Users\\Ann\\My Textures\\wood.png`, `/home/bob/wood.png`): then
/// the file's name alone is tried in each of `folders`, in order.
pub fn find_file(written: &Path, base: &Path, folders: &[&Path], read: ReadFile) -> Found {
    let written = PathBuf::from(written.to_string_lossy().replace('\\', "/"));
    let as_written = normalise(&base.join(&written));
    let error = match read(&as_written) {
        Ok(bytes) => return Found::AsWritten(as_written, bytes),
        Err(error) => error,
    };
    let mut tried = vec![as_written];
    if let Some(file_name) = written.file_name() {
        for folder in folders {
            let path = normalise(&folder.join(file_name));
            if tried.contains(&path) {
                continue;
            }
            if let Ok(bytes) = read(&path) {
                return Found::Elsewhere { written, path, bytes };
            }
            tried.push(path);
        }
    }
    Found::Nowhere { error, tried }
}

/// ", nor X, nor Y" for the other places a file was looked for.
pub fn also_tried(places: &[PathBuf]) -> String {
    places.iter().map(|p| format!(", nor {}", p.display())).collect()
}

// ANCHOR: material
/// An MTL material as this chapter draws it.
fn material_of(m: &tobj::Material) -> MaterialDesc {
    let colour = |c: Option<[f32; 3]>, default: f32| c.map_or(Vec3::splat(default), Vec3::from);
    let normal_map = m.normal_texture.clone().or_else(|| m.unknown_param.get("norm").cloned());
    // Some exporters write the keyword in lower case.
    let albedo_map = m.diffuse_texture.clone().or_else(|| m.unknown_param.get("map_kd").cloned());
    MaterialDesc {
        name: m.name.clone(),
        diffuse: colour(m.diffuse, 0.8),
        specular: colour(m.specular, 0.0).element_sum() / 3.0,
        shininess: m.shininess.unwrap_or(1.0).max(1.0),
        // Checked and clamped to 0..1 by `physical_keys` as the MTL was read.
        roughness: m.unknown_param.get("Pr").and_then(|v| v.trim().parse().ok()),
        metallic: m.unknown_param.get("Pm").and_then(|v| v.trim().parse().ok()),
        emissive: colour(m.emissive, 0.0),
        at_night: false,
        vertex_colours: false,
        albedo_map: albedo_map.as_deref().and_then(texture_file),
        normal_map: normal_map.as_deref().and_then(texture_file),
        roughness_map: m.unknown_param.get("map_Pr").and_then(|s| texture_file(s)),
        metallic_map: m.unknown_param.get("map_Pm").and_then(|s| texture_file(s)),
        texture_folders: Vec::new(),
    }
}
// ANCHOR_END: material

/// The file name in an MTL texture statement, without its options
/// (`map_Bump -bm 0.5 bricks normal.png` names "bricks normal.png"), with
/// Windows separators turned round (doubled ones too).
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
    (!name.is_empty()).then(|| normalise(Path::new(&name)))
}

/// `a/b/../c` as `a/c`, `a//b` as `a/b`, so that paths print plainly and
/// built-in files are found.
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

/// A corner's index that says "none" (`f 1//3` has no texture coordinate).
const NONE: u32 = u32::MAX;

/// A mesh as pass 2 builds it: one vertex per distinct corner
/// (position, texture coordinate, normal), and triangles of them.
struct MeshBuilder {
    /// Each vertex's corner: indices into the element lists, or `NONE`.
    keys: Vec<[u32; 3]>,
    /// The next vertex of this mesh with the same position, or `NONE`.
    next: Vec<u32>,
    indices: Vec<u32>,
    material: Option<usize>,
}

/// For each position, the first vertex made from it in the mesh being
/// built (and that mesh's number): with [`MeshBuilder::next`], how a
/// corner finds the vertex it shares, faster than a hash map.
struct FirstVertex {
    mesh: u32,
    of_position: Vec<(u32, u32)>,
}

impl MeshBuilder {
    fn new(material: Option<usize>) -> Self {
        Self { keys: Vec::new(), next: Vec::new(), indices: Vec::new(), material }
    }

    /// The vertex for `key`, made if this mesh has none yet.
    fn vertex(&mut self, key: [u32; 3], first: &mut FirstVertex) -> u32 {
        let new = self.keys.len() as u32;
        let slot = &mut first.of_position[key[0] as usize];
        if slot.0 != first.mesh {
            *slot = (first.mesh, new);
        } else {
            let mut v = slot.1;
            loop {
                if self.keys[v as usize] == key {
                    return v;
                }
                if self.next[v as usize] == NONE {
                    break;
                }
                v = self.next[v as usize];
            }
            self.next[v as usize] = new;
        }
        self.keys.push(key);
        self.next.push(NONE);
        new
    }

    /// Faces that give normals mixed with faces that do not: the mesh
    /// counts as having none (and gets computed ones).
    fn has_normals(&self) -> bool {
        self.keys.iter().all(|k| k[2] != NONE)
    }

    /// The mesh's vertices and triangles, with normals computed where it
    /// has none; each vertex's colour; and whether it has texture coordinates.
    fn data(&self, e: &Elements) -> (MeshData, Vec<Vec3>, bool) {
        let has_uvs = self.keys.iter().all(|k| k[1] != NONE);
        let has_normals = self.has_normals();
        let vertices = self
            .keys
            .iter()
            .map(|&[p, t, n]| Vertex {
                position: e.positions[p as usize].into(),
                normal: if has_normals { e.normals[n as usize].into() } else { [0.0; 3] },
                // OBJ's v runs up the image; wgpu's runs down.
                uv: if has_uvs {
                    let uv = e.uvs[t as usize];
                    [uv.x, 1.0 - uv.y]
                } else {
                    [0.0; 2]
                },
            })
            .collect();
        let colour = |k: &[u32; 3]| e.colours.get(k[0] as usize).copied().unwrap_or(Vec3::ONE);
        let mut colours: Vec<Vec3> = self.keys.iter().map(colour).collect();
        let mut data = MeshData { vertices, indices: self.indices.clone() };
        if !has_normals {
            let (smoothed, sources) = smooth_normals(&data, SMOOTHING_ANGLE_DEGREES);
            colours = sources.iter().map(|&s| colours[s as usize]).collect();
            data = smoothed;
        }
        (data, colours, has_uvs)
    }
}

/// What pass 2 left out, for one warning each: how many, and the first line.
#[derive(Default)]
struct LeftOut {
    uv_indices: (usize, usize),
    normal_indices: (usize, usize),
    short_faces: (usize, usize),
    ears_given_up: (usize, usize),
    unknown_materials: (usize, usize),
    unknown_material: String,
}

fn note(counter: &mut (usize, usize), line: usize) {
    if counter.0 == 0 {
        counter.1 = line;
    }
    counter.0 += 1;
}

/// A texture coordinate or normal index past the end of its list: left
/// out of the corner, with a warning.
const OUT_OF_RANGE: u32 = NONE - 1;

/// One corner of a face (`7`, `7/3`, `7//2`, `7/3/2`, or counting back
/// from the last element read so far, `-1/-1/-1`) as indices from 0 into
/// the element lists. `counts` are the elements read so far, `totals` those
/// in the whole file. Index 0, an index reaching back before the first
/// element, and a position past the end are errors; a texture coordinate
/// or normal past the end is `OUT_OF_RANGE`.
fn corner(word: &str, counts: [usize; 3], totals: [usize; 3]) -> Result<[u32; 3], String> {
    const KINDS: [&str; 3] = ["position", "texture coordinate", "normal"];
    let not_a_corner = || format!("`{word}` is not a corner (v, v/vt, v//vn or v/vt/vn)");
    let mut key = [NONE; 3];
    // The fields by hand, a byte at a time: faces are most of a big file,
    // and this is several times faster than `split` and `parse` in a debug
    // build.
    let bytes = word.as_bytes();
    let (mut kind, mut at) = (0, 0);
    loop {
        let field_start = at;
        let negative = bytes.get(at) == Some(&b'-');
        at += usize::from(negative || bytes.get(at) == Some(&b'+'));
        let (digits_start, mut value) = (at, 0i64);
        while let Some(&digit) = bytes.get(at).filter(|b| b.is_ascii_digit()) {
            if at - digits_start < 10 {
                value = value * 10 + i64::from(digit - b'0');
            }
            at += 1;
        }
        let digits = at - digits_start;
        let ends_well = matches!(bytes.get(at), None | Some(b'/'));
        if !ends_well || (digits == 0 && (kind == 0 || at > field_start)) {
            return Err(not_a_corner());
        }
        if digits > 0 {
            let index = if negative { -value } else { value };
            // No file has a billion of anything: longer numbers are out of range.
            let resolved = match index {
                _ if digits > 9 => None,
                0 => return Err("index 0 (OBJ counts from 1)".into()),
                i if i < 0 && -i > counts[kind] as i64 => {
                    return Err(format!("relative index {i} reaches before the first {}", KINDS[kind]));
                }
                i if i < 0 => Some(counts[kind] as i64 + i),
                i if i <= totals[kind] as i64 => Some(i - 1),
                _ => None,
            };
            key[kind] = match resolved {
                Some(i) => i as u32,
                None if kind == 0 => {
                    let field = &word[field_start..at];
                    return Err(format!("index out of range: position {field}, the file has {}", totals[0]));
                }
                None => OUT_OF_RANGE,
            };
        }
        if at == bytes.len() {
            return Ok(key);
        }
        // Past a '/', to the next field.
        at += 1;
        kind += 1;
        if kind > 2 {
            return Err(not_a_corner());
        }
    }
}

/// Pass 2: the faces, into meshes, triangulated. Warnings come back
/// without the file's name, which the caller adds.
fn read_faces(
    text: &Text,
    e: &Elements,
    materials: &HashMap<String, usize>,
    max_triangles: usize,
    warnings: &mut Vec<String>,
) -> Result<Vec<MeshBuilder>, (usize, String)> {
    let totals = [e.positions.len(), e.uvs.len(), e.normals.len()];
    let mut counts = [0usize; 3];
    let mut meshes = Vec::new();
    let mut mesh = MeshBuilder::new(None);
    let mut first = FirstVertex { mesh: 0, of_position: vec![(NONE, 0); e.positions.len()] };
    let mut left_out = LeftOut::default();
    let mut triangles = 0usize;
    let (mut corners, mut vertices, mut points) = (Vec::new(), Vec::new(), Vec::new());
    for line in text.lines() {
        let (n, line) = line?;
        let mut words = Words(&line);
        match words.next() {
            Some("v") => counts[0] += 1,
            Some("vt") => counts[1] += 1,
            Some("vn") => counts[2] += 1,
            // A new object or group starts a new mesh, in the same material.
            Some("o" | "g") if !mesh.indices.is_empty() => {
                let material = mesh.material;
                meshes.push(std::mem::replace(&mut mesh, MeshBuilder::new(material)));
                first.mesh += 1;
            }
            Some("usemtl") => {
                let name = rest_of_line(&line);
                let material = materials.get(name).copied();
                if material.is_none() && !name.is_empty() {
                    if left_out.unknown_materials.0 == 0 {
                        left_out.unknown_material = name.to_string();
                    }
                    note(&mut left_out.unknown_materials, n);
                }
                if material != mesh.material && !mesh.indices.is_empty() {
                    meshes.push(std::mem::replace(&mut mesh, MeshBuilder::new(material)));
                    first.mesh += 1;
                }
                mesh.material = material;
            }
            Some("f") => {
                corners.clear();
                for word in words {
                    corners.push(corner(word, counts, totals).map_err(|why| (n, why))?);
                }
                match corners.len() {
                    0 => return Err((n, "a face without corners".into())),
                    1 | 2 => {
                        note(&mut left_out.short_faces, n);
                        continue;
                    }
                    _ => {}
                }
                // A position that was not a finite number takes its faces with it.
                if corners.iter().any(|k| !e.positions[k[0] as usize].is_finite()) {
                    continue;
                }
                for key in &mut corners {
                    if key[1] == OUT_OF_RANGE {
                        note(&mut left_out.uv_indices, n);
                    }
                    if key[1] != NONE && !e.uvs.get(key[1] as usize).is_some_and(|uv| uv.is_finite()) {
                        key[1] = NONE;
                    }
                    if key[2] == OUT_OF_RANGE {
                        note(&mut left_out.normal_indices, n);
                    }
                    if key[2] != NONE && !e.normals.get(key[2] as usize).is_some_and(|v| v.is_finite()) {
                        key[2] = NONE;
                    }
                }
                triangles += corners.len() - 2;
                if triangles > max_triangles {
                    return Err((n, too_many_triangles(max_triangles)));
                }
                vertices.clear();
                vertices.extend(corners.iter().map(|&key| mesh.vertex(key, &mut first)));
                let position = |k: usize| e.positions[corners[k][0] as usize];
                if vertices.len() == 3 {
                    mesh.indices.extend_from_slice(&vertices);
                } else if vertices.len() == 4 {
                    let v = &vertices;
                    mesh.indices.extend(match quad_diagonal([0, 1, 2, 3].map(position)) {
                        0 => [v[0], v[1], v[2], v[0], v[2], v[3]],
                        _ => [v[0], v[1], v[3], v[1], v[2], v[3]],
                    });
                } else {
                    points.clear();
                    points.extend(corners.iter().map(|k| e.positions[k[0] as usize]));
                    let (cut, gave_up) = triangulate(&points);
                    if gave_up {
                        note(&mut left_out.ears_given_up, n);
                    }
                    mesh.indices.extend(cut.iter().flatten().map(|&i| vertices[i]));
                }
            }
            _ => {}
        }
    }
    if !mesh.indices.is_empty() {
        meshes.push(mesh);
    }
    let l = &left_out;
    let unknown =
        format!("usemtl {}: no such material in the MTL files; drawn with a default material", l.unknown_material);
    let counted = [
        (l.uv_indices, "texture coordinate index(es) past the end of the list left out; drawn untextured".into()),
        (l.normal_indices, "normal index(es) past the end of the list left out; normals computed".into()),
        (l.short_faces, "face(s) of one or two corners (points, lines) left out".into()),
        (l.ears_given_up, "concave face(s) that cross themselves: cut as well as they go".into()),
        // Without any MTL there is nothing to look names up in: no news.
        (if materials.is_empty() { (0, 0) } else { l.unknown_materials }, unknown),
    ];
    for ((count, line), what) in counted {
        if count > 0 {
            warnings.push(format!("line {line}: {what} ({count} in all)"));
        }
    }
    Ok(meshes)
}

// ANCHOR: triangulate
/// Which diagonal cuts a quad into two triangles: 0 (corners 0 and 2, the
/// fan tools expect) unless the two triangles it makes face opposite ways,
/// which happens when corner 1 or 3 points inwards; then 1.
fn quad_diagonal(p: [Vec3; 4]) -> usize {
    let first = (p[1] - p[0]).cross(p[2] - p[0]);
    let second = (p[2] - p[0]).cross(p[3] - p[0]);
    usize::from(first.dot(second) < 0.0)
}

/// Triangles covering a polygon, as indices into `points`, wound as the
/// polygon is; and whether ear clipping had to give up. A convex polygon
/// becomes a fan from its first corner, as tools expect of quads. A
/// concave one is cut by ear clipping (Meisters 1975) in its own plane:
/// a corner whose triangle with its two neighbours turns the polygon's way
/// and holds no other corner is an "ear"; cutting it off leaves a polygon
/// with one corner fewer, and every simple polygon has an ear to cut.
pub fn triangulate(points: &[Vec3]) -> (Vec<[usize; 3]>, bool) {
    let count = points.len();
    let fan = |corners: &[usize]| -> Vec<[usize; 3]> {
        (1..corners.len().saturating_sub(1)).map(|i| [corners[0], corners[i], corners[i + 1]]).collect()
    };
    let all: Vec<usize> = (0..count).collect();
    // The polygon's plane, by Newell's method: the sum of the cross
    // products around it points along its normal, however it bends.
    let origin = points[0].as_dvec3();
    let p = |i: usize| points[i].as_dvec3() - origin;
    let normal: DVec3 = (0..count).map(|i| p(i).cross(p((i + 1) % count))).sum();
    let Some(normal) = normal.try_normalize() else { return (fan(&all), false) };
    // Flat 2D points, counter-clockwise when seen from the normal's side.
    let u = normal.any_orthonormal_vector();
    let v = normal.cross(u);
    let flat: Vec<DVec2> = (0..count).map(|i| DVec2::new(p(i).dot(u), p(i).dot(v))).collect();
    let size = flat.iter().fold(0.0f64, |m, q| m.max(q.length_squared()));
    let tolerance = 1e-12 * size;
    // How much the boundary turns left at b, coming from a, going to c.
    let turn = |a: usize, b: usize, c: usize| (flat[b] - flat[a]).perp_dot(flat[c] - flat[b]);
    let convex = (0..count).all(|i| turn((i + count - 1) % count, i, (i + 1) % count) >= -tolerance);
    if convex {
        return (fan(&all), false);
    }
    let inside = |q: DVec2, a: usize, b: usize, c: usize| {
        let side = |from: usize, to: usize| (flat[to] - flat[from]).perp_dot(q - flat[from]);
        side(a, b) >= 0.0 && side(b, c) >= 0.0 && side(c, a) >= 0.0
    };
    let mut left = all;
    let mut triangles = Vec::with_capacity(count - 2);
    let (mut at, mut misses, mut gave_up) = (0, 0, false);
    // Every test costs a look at each corner left: a budget keeps a
    // pathological face of many thousand corners from taking minutes.
    let mut budget: u64 = 50_000_000;
    while left.len() > 3 {
        let m = left.len();
        at %= m;
        let (a, b, c) = (left[(at + m - 1) % m], left[at], left[(at + 1) % m]);
        budget = budget.saturating_sub(m as u64);
        let ear = turn(a, b, c) > tolerance
            && left.iter().all(|&k| {
                let q = flat[k];
                k == a || k == b || k == c || q == flat[a] || q == flat[b] || q == flat[c] || !inside(q, a, b, c)
            });
        if ear || misses >= m {
            // No ear all the way round: the face crosses itself or is
            // degenerate; cut here anyway so that the loop ends.
            gave_up |= !ear;
            triangles.push([a, b, c]);
            left.remove(at);
            misses = 0;
        } else {
            at += 1;
            misses += 1;
        }
        if budget == 0 {
            triangles.extend(fan(&left));
            return (triangles, true);
        }
    }
    triangles.push([left[0], left[1], left[2]]);
    (triangles, gave_up)
}
// ANCHOR_END: triangulate

// ANCHOR: smooth
/// Normals for a mesh that has none. Each corner gets the average of the
/// faces around its position that meet its own face at less than
/// `max_angle_degrees`, each face weighted by its angle at that position
/// (Thürmer and Wüthrich 1998: a face split in two then counts the same),
/// so curved surfaces come out smooth and sharp edges stay sharp. Corners
/// that end up with the same normal share a vertex. Also returns, for each
/// new vertex, the vertex of `mesh` it was made from (to carry colours).
pub fn smooth_normals(mesh: &MeshData, max_angle_degrees: f32) -> (MeshData, Vec<u32>) {
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
    let mut sources = Vec::new();
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
            sources.push(i);
            out.vertices.len() as u32 - 1
        });
        out.indices.push(index);
    }
    (out, sources)
}
// ANCHOR_END: smooth

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
    fn convex_faces_are_fans_and_concave_quads_take_the_other_diagonal() {
        let pentagon = [(0.0, 0.0), (2.0, 0.0), (2.5, 1.5), (1.0, 2.5), (-0.5, 1.5)].map(|(x, y)| Vec3::new(x, y, 0.0));
        assert_eq!(triangulate(&pentagon), (vec![[0, 1, 2], [0, 2, 3], [0, 3, 4]], false));
        // Corner 1 points inwards: the fan's diagonal 0–2 would lie outside.
        let dart = [(0.0, 0.0), (1.0, 0.8), (2.0, 0.0), (1.0, 3.0)].map(|(x, y)| Vec3::new(x, y, 0.0));
        assert_eq!(quad_diagonal(dart), 1);
        assert_eq!(quad_diagonal([dart[1], dart[2], dart[3], dart[0]]), 0, "corner 0 inwards: 0–2 is right");
    }

    #[test]
    fn a_face_of_a_thousand_corners_is_cut_quickly() {
        // A comb of 250 teeth, 1000 corners, half of them pointing inwards.
        let mut corners = vec![Vec3::ZERO, Vec3::new(499.0, 0.0, 0.0)];
        for tooth in (0..250).rev() {
            let x = 2.0 * tooth as f32;
            corners.extend([Vec3::new(x + 1.0, 3.0, 0.0), Vec3::new(x, 3.0, 0.0)]);
            if tooth > 0 {
                corners.extend([Vec3::new(x, 1.0, 0.0), Vec3::new(x - 1.0, 1.0, 0.0)]);
            }
        }
        let started = std::time::Instant::now();
        let (triangles, gave_up) = triangulate(&corners);
        assert!(!gave_up && triangles.len() == 998);
        let p = |i: usize| corners[i];
        let area: f32 = triangles.iter().map(|t| (p(t[1]) - p(t[0])).cross(p(t[2]) - p(t[0])).z / 2.0).sum();
        assert!((area - (499.0 + 2.0 * 250.0)).abs() < 1e-2, "the triangles cover the comb once: {area}");
        assert!(started.elapsed().as_secs_f32() < 10.0, "{:?}", started.elapsed());
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
        let (smoothed, _) = smooth_normals(&strip(&cube), 60.0);
        for (a, b) in smoothed.vertices.iter().zip(&cube.vertices) {
            assert!(Vec3::from(a.normal).abs_diff_eq(b.normal.into(), 1e-6), "a cube's faces stay flat");
        }
        let sphere = common::primitives::uv_sphere(24, 12);
        let (smoothed, sources) = smooth_normals(&strip(&sphere), 60.0);
        assert_eq!(sources.len(), smoothed.vertices.len());
        for (v, &s) in smoothed.vertices.iter().zip(&sources) {
            assert_eq!(v.position, sphere.vertices[s as usize].position, "each vertex knows where it came from");
        }
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
