//! Models as they come: the project's own, and the messy files learners
//! bring. Each case writes its files into a fresh folder and loads them the
//! way `--model` does.

use std::path::{Path, PathBuf};
use std::process::Command;

use common::glam::Vec3;
use common::headless::{OFFSCREEN_FORMAT, capture};
use common::{Chapter, FlagValues, Gpu, Target};
use textures::{TexturesChapter, builtin, obj};

/// A fresh folder holding `files` (name, contents).
fn folder(case: &str, files: &[(&str, &str)]) -> PathBuf {
    let files: Vec<(&str, &[u8])> = files.iter().map(|(name, text)| (*name, text.as_bytes())).collect();
    folder_of_bytes(case, &files)
}

/// A fresh folder holding `files` (name, which may have folders in it, and bytes).
/// Each `case` names one folder: tests run side by side, and two sharing a
/// folder would delete each other's files (it happened, once in a cold run).
fn folder_of_bytes(case: &str, files: &[(&str, &[u8])]) -> PathBuf {
    static TAKEN: std::sync::Mutex<Vec<String>> = std::sync::Mutex::new(Vec::new());
    let mut taken = TAKEN.lock().unwrap_or_else(|e| e.into_inner());
    assert!(!taken.iter().any(|t| t == case), "two tests use the folder for case `{case}`");
    taken.push(case.to_string());
    drop(taken);
    let dir = std::env::temp_dir().join(format!("textures-{case}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    for (name, bytes) in files {
        let path = dir.join(name);
        std::fs::create_dir_all(path.parent().unwrap()).unwrap();
        std::fs::write(path, bytes).unwrap();
    }
    dir
}

fn load(path: &Path) -> Result<obj::LoadedModel, obj::ModelError> {
    obj::load(path, &|p: &Path| common::files::read(p))
}

#[test]
fn the_projects_models_load_cleanly_and_wind_with_their_normals() {
    for name in ["car", "tower", "boat"] {
        let loaded = obj::load(Path::new(&format!("models/{name}/{name}.obj")), &builtin::read).unwrap();
        assert!(loaded.warnings.is_empty(), "{name}: {:?}", loaded.warnings);
        let model = &loaded.model;
        for t in model.indices.chunks_exact(3) {
            let v = [0, 1, 2].map(|k| model.vertices[t[k] as usize]);
            let p = v.map(|v| Vec3::from(v.position));
            let face = (p[1] - p[0]).cross(p[2] - p[0]);
            if face.length() < 1e-9 {
                continue;
            }
            for vertex in v {
                assert!(face.dot(vertex.normal.into()) > 0.0, "{name}: a triangle winds against its normals at {p:?}");
            }
        }
    }
    let car = obj::load(Path::new("models/car/car.obj"), &builtin::read).unwrap();
    let names: Vec<&str> = car.model.materials.iter().map(|m| m.name.as_str()).collect();
    for wanted in ["body", "glass", "tyre", "headlight", "taillight"] {
        assert!(names.contains(&wanted), "the car has a {wanted} material: {names:?}");
    }
    assert_eq!(car.model.parts.len(), 5, "one draw per material");
}

// ANCHOR: messy
#[test]
fn quads_ngons_relative_indices_objects_and_groups_without_normals() {
    let dir = folder(
        "messy",
        &[(
            "messy.obj",
            "# a cube of quads, written with relative indices, no normals\n\
             o cube\n\
             v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n\
             vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n\
             f -8/-4 -5/-3 -6/-2 -7/-1\n\
             f -4/-4 -3/-3 -2/-2 -1/-1\n\
             g sides\n\
             f 1/1 2/2 6/3 5/4\nf 2/1 3/2 7/3 6/4\nf 3/1 4/2 8/3 7/4\nf 4/1 1/2 5/3 8/4\n\
             o pentagon\n\
             v 3 0 0\nv 4 0 0\nv 4.3 1 0\nv 3.5 1.6 0\nv 2.7 1 0\n\
             f 9 10 11 12 13\n",
        )],
    );
    let loaded = load(&dir.join("messy.obj")).unwrap();
    // Six quads make 12 triangles; the pentagon 3.
    assert_eq!(loaded.model.triangle_count(), 15);
    assert!(loaded.objects >= 2, "objects and groups are read: {}", loaded.objects);
    let says = |words: &str| loaded.warnings.iter().any(|w| w.contains(words));
    assert!(says("without normals; computed"), "{:?}", loaded.warnings);
    assert!(says("without texture coordinates; drawn untextured"), "{:?}", loaded.warnings);
    // The cube's edges are 90°: above the smoothing angle, so its faces stay flat.
    for v in &loaded.model.vertices[..24.min(loaded.model.vertices.len())] {
        let n = Vec3::from(v.normal);
        assert!((n.abs().max_element() - 1.0).abs() < 1e-5, "a cube face's normal is an axis: {n}");
    }
}
// ANCHOR_END: messy

#[test]
fn a_missing_mtl_is_one_warning_and_a_default_material() {
    let dir = folder(
        "no-mtl",
        &[("lonely.obj", "mtllib nowhere.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nusemtl red\nf 1//1 2//1 3//1\n")],
    );
    let loaded = load(&dir.join("lonely.obj")).unwrap();
    let about: Vec<&String> = loaded.warnings.iter().filter(|w| w.contains("nowhere.mtl")).collect();
    assert_eq!(about.len(), 1, "{:?}", loaded.warnings);
    assert!(about[0].contains("no such file") && about[0].contains("default material"), "{}", about[0]);
    assert_eq!(loaded.model.materials[loaded.model.parts[0].material].name, "default");
}

#[test]
fn broken_files_name_the_file_and_the_line() {
    let cases = [
        ("position", "v 0 0 0\nv 1 0 0\nv 1 oops 0\nf 1 2 3\n", "line 3: position parse error"),
        // Positions out of range stay an error (texture coordinates and
        // normals are left out: see `out_of_range_texture_coordinates_and_normals_are_left_out`).
        ("face", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n", "line 4: index out of range: position 9, the file has 3"),
        ("normal", "v 0 0 0\nvn 0 1\nf 1 1 1\n", "line 2: normal parse error"),
        // Indices tobj would turn into huge numbers and overflow on.
        ("huge", "v 0 0 0\nf -9223372036854775808 1 1\n", "line 2: index out of range"),
        ("bare-face", "v 0 0 0\nf\n", "line 2: a face without corners"),
        ("not-a-corner", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2/x 3\n", "line 4: `2/x` is not a corner"),
        ("zero", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/0 3/1\n", "line 5: index 0"),
        (
            "before-first",
            "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//-1 2//-2 3//-1\n",
            "line 5: relative index -2 reaches before the first normal",
        ),
    ];
    for (case, text, expected) in cases {
        let dir = folder(&format!("broken-{case}"), &[("broken.obj", text)]);
        let error = load(&dir.join("broken.obj")).unwrap_err().to_string();
        assert!(error.contains("broken.obj") && error.contains(expected), "{case}: {error}");
        assert!(!error.contains('\n'), "one line: {error}");
    }
    let dir = folder(
        "broken-mtl",
        &[
            ("m.obj", "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl a\nf 1 2 3\n"),
            ("m.mtl", "newmtl a\nKd 0.5 0.5\n"),
        ],
    );
    let error = load(&dir.join("m.obj")).unwrap_err().to_string();
    assert!(error.contains("m.mtl: line 2: Kd needs 3 numbers"), "{error}");
}

/// The chapter binary with `--model`: a broken model is a one-line error
/// and exit code 2, never a panic; and the `--screenshot` file that was
/// not there before is not left behind empty (one that was is kept).
#[test]
fn the_binary_exits_2_on_a_broken_or_missing_model() {
    let dir = folder("binary", &[("broken.obj", "v 0 0 0\nv 1 x 0\n"), ("kept.png", "an older picture")]);
    for (model, picture) in [(dir.join("broken.obj"), "out.png"), (dir.join("absent.obj"), "kept.png")] {
        let out = Command::new(env!("CARGO_BIN_EXE_textures"))
            .args(["--screenshot", dir.join(picture).to_str().unwrap(), "--size", "64x36", "--model"])
            .arg(&model)
            .output()
            .unwrap();
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{stderr}");
        let errors: Vec<&str> = stderr.lines().filter(|l| l.starts_with("error:")).collect();
        assert_eq!(errors.len(), 1, "{stderr}");
        assert!(
            errors[0].contains("--model") && errors[0].contains(model.file_name().unwrap().to_str().unwrap()),
            "{stderr}"
        );
        assert!(!stderr.contains("panicked"), "{stderr}");
    }
    assert!(!dir.join("out.png").exists(), "a failed run leaves no empty screenshot behind");
    assert_eq!(std::fs::read_to_string(dir.join("kept.png")).unwrap(), "an older picture");
}

fn gpu() -> Gpu {
    Gpu::headless(TexturesChapter::gpu_needs()).unwrap()
}

fn chapter_with_model(gpu: &Gpu, path: &Path, size: (u32, u32)) -> TexturesChapter {
    let target = Target { format: OFFSCREEN_FORMAT, width: size.0, height: size.1, samples: 1 };
    let flags = FlagValues(vec![("model", path.display().to_string())]);
    common::chapter::create::<TexturesChapter>(gpu, target, &flags).unwrap()
}

/// A texture the MTL names but the folder lacks: one warning naming it,
/// a magenta checker where it would be, and the model still drawn. One
/// named by another machine's path is found by its name, with a warning
/// that says where (issue 25, kind 4), and the model's panel lists both.
#[test]
fn a_missing_texture_is_one_warning_and_a_visible_checker() {
    let png = picture([90, 160, 220, 255], 2, common::image::ImageFormat::Png);
    let dir = folder_of_bytes(
        "no-texture",
        &[
            (
                "panel.obj",
                // Facing −z, the side the stage turns towards its camera.
                b"mtllib panel.mtl\nv 1 0 0\nv -1 0 0\nv -1 2 0\nv 1 2 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvn 0 0 -1\n\
                 usemtl a\nf 1/1/1 2/2/1 3/3/1\nusemtl b\nf 1/1/1 3/3/1 4/4/1\n",
            ),
            (
                "panel.mtl",
                b"newmtl a\nKd 1 1 1\nmap_Kd gone.png\nnewmtl b\nKd 1 1 1\nmap_Kd gone.png\n\
                  newmtl c\nmap_Kd C:\\\\Users\\\\Ann\\\\here.png\n",
            ),
            ("here.png", &png),
        ],
    );
    let gpu = gpu();
    let mut chapter = chapter_with_model(&gpu, &dir.join("panel.obj"), (320, 180));
    let about: Vec<&String> = chapter.warnings.iter().filter(|w| w.contains("gone.png")).collect();
    assert_eq!(about.len(), 1, "one warning for the file, however many materials use it: {:?}", chapter.warnings);
    assert!(about[0].contains("checker"), "{}", about[0]);
    let elsewhere: Vec<&String> = chapter.warnings.iter().filter(|w| w.contains("here.png")).collect();
    assert_eq!(elsewhere.len(), 1, "{:?}", chapter.warnings);
    assert!(elsewhere[0].contains("material c: ") && elsewhere[0].contains("not found; using"), "{}", elsewhere[0]);
    assert_eq!(chapter.featured.materials, 3);
    let view = common::chapter::view_index::<TexturesChapter>("car").unwrap();
    chapter.select_view(view);
    let target = Target { format: OFFSCREEN_FORMAT, width: 320, height: 180, samples: 1 };
    let picture =
        capture(&gpu, &mut chapter, target, (TexturesChapter::SNAPSHOT_TIME, view), Default::default()).unwrap();
    let magenta = picture.pixels().filter(|p| p[0] > 120 && p[2] > 120 && p[1] < 90).count();
    assert!(magenta > 200, "the checker shows: {magenta} magenta pixels");
}

/// A sphere of 708 × 708 quads, about a million triangles, as OBJ text
/// with normals and texture coordinates.
fn million_triangle_sphere() -> String {
    use std::fmt::Write as _;
    let (columns, rows) = (708u32, 708u32);
    let mut text = String::with_capacity(80 << 20);
    for row in 0..=rows {
        for column in 0..=columns {
            let (u, v) = (column as f32 / columns as f32, row as f32 / rows as f32);
            let (s, c) = (std::f32::consts::TAU * u).sin_cos();
            let (sl, cl) = (std::f32::consts::PI * v).sin_cos();
            let _ = writeln!(
                text,
                "v {:.6} {:.6} {:.6}\nvt {u:.6} {:.6}\nvn {:.6} {:.6} {:.6}",
                sl * s,
                cl,
                sl * c,
                1.0 - v,
                sl * s,
                cl,
                sl * c
            );
        }
    }
    for row in 0..rows {
        for column in 0..columns {
            let i = |c: u32, r: u32| r * (columns + 1) + c + 1;
            let quad = [i(column, row), i(column, row + 1), i(column + 1, row + 1), i(column + 1, row)];
            let _ = writeln!(text, "f {}", quad.map(|k| format!("{k}/{k}/{k}")).join(" "));
        }
    }
    text
}

// ANCHOR: million
/// A model of a million triangles loads and renders.
#[test]
fn a_million_triangles_load_and_render() {
    let dir = folder("million", &[("sphere.obj", &million_triangle_sphere())]);
    let gpu = gpu();
    let mut chapter = chapter_with_model(&gpu, &dir.join("sphere.obj"), (160, 90));
    assert!(chapter.featured.triangles >= 1_000_000, "{} triangles", chapter.featured.triangles);
    let view = common::chapter::view_index::<TexturesChapter>("car").unwrap();
    chapter.select_view(view);
    let target = Target { format: OFFSCREEN_FORMAT, width: 160, height: 90, samples: 1 };
    let with = capture(&gpu, &mut chapter, target, (TexturesChapter::SNAPSHOT_TIME, view), Default::default()).unwrap();
    // The same picture with the model taken off the stage: the middle changes.
    chapter.featured.placement = common::glam::Mat4::from_translation(Vec3::new(0.0, -1000.0, 0.0));
    let without =
        capture(&gpu, &mut chapter, target, (TexturesChapter::SNAPSHOT_TIME, view), Default::default()).unwrap();
    let changed = with.pixels().zip(without.pixels()).filter(|(a, b)| a.0 != b.0).count();
    assert!(changed > 160 * 90 / 10, "the sphere covers the middle of the picture: {changed} pixels changed");
    let _ = std::fs::remove_dir_all(dir);
}
// ANCHOR_END: million

/// Faces with normals and texture coordinates mixed with faces without, in
/// one mesh: tobj's lists come out shorter than its positions. The mesh
/// is drawn as one without them (normals computed, untextured), not read
/// past the end.
#[test]
fn faces_with_and_without_normals_in_one_mesh_load() {
    let text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvt 0 0\nvn 0 0 1\nf 1/1/1 2/1/1 3/1/1\nf 2 4 3\n";
    let dir = folder("mixed", &[("mixed.obj", text)]);
    let loaded = load(&dir.join("mixed.obj")).unwrap();
    assert_eq!(loaded.model.triangle_count(), 2);
    for w in ["without normals", "without texture coordinates"] {
        assert!(loaded.warnings.iter().any(|x| x.contains(w)), "no warning '{w}': {:?}", loaded.warnings);
    }
}

/// The bytes of a picture `size` texels square, all `colour`, in `format`.
fn picture(colour: [u8; 4], size: u32, format: common::image::ImageFormat) -> Vec<u8> {
    let image = common::image::RgbaImage::from_pixel(size, size, common::image::Rgba(colour));
    let mut bytes = std::io::Cursor::new(Vec::new());
    common::image::DynamicImage::ImageRgba8(image).write_to(&mut bytes, format).unwrap();
    bytes.into_inner()
}

/// The material of the model's first part.
fn first_material(loaded: &obj::LoadedModel) -> &textures::mesh::MaterialDesc {
    &loaded.model.materials[loaded.model.parts[0].material]
}

// Issue 25, kind 1: text as Windows writes it.
#[test]
fn utf16_latin1_crlf_and_names_with_trailing_spaces_load() {
    let utf16 = |text: &str, big_endian: bool| -> Vec<u8> {
        let bom: [u8; 2] = if big_endian { [0xFE, 0xFF] } else { [0xFF, 0xFE] };
        let units = text.encode_utf16().flat_map(|u| if big_endian { u.to_be_bytes() } else { u.to_le_bytes() });
        bom.into_iter().chain(units).collect()
    };
    // UTF-16 little-endian with CRLF; its MTL big-endian, names padded.
    let obj = "# exported\r\nmtllib wide.mtl\r\nv 0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\nvt 0 0\r\nvn 0 0 1\r\n\
               usemtl red \t\r\nf 1/1/1 2/1/1 3/1/1\r\n";
    let mtl = "newmtl red   \r\nKd 1 0 0\r\n";
    let dir = folder_of_bytes("utf16", &[("wide.obj", &utf16(obj, false)), ("wide.mtl", &utf16(mtl, true))]);
    let loaded = load(&dir.join("wide.obj")).unwrap();
    assert!(loaded.warnings.is_empty(), "{:?}", loaded.warnings);
    assert_eq!(first_material(&loaded).name, "red");
    assert_eq!(first_material(&loaded).diffuse, Vec3::new(1.0, 0.0, 0.0));

    // Latin-1 (3ds Max on a French Windows) in a comment and in names.
    let obj = b"# mod\xe8le\nmtllib mat.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nusemtl Mat\xe9riau 01\nf 1/1 2/1 3/1\n";
    let mtl = b"newmtl Mat\xe9riau 01  \nKd 0 1 0\n";
    let dir = folder_of_bytes("latin1", &[("old.obj", obj), ("mat.mtl", mtl)]);
    let loaded = load(&dir.join("old.obj")).unwrap();
    assert_eq!(first_material(&loaded).name, "Matériau 01");
    assert_eq!(first_material(&loaded).diffuse, Vec3::new(0.0, 1.0, 0.0));
    let latin1: Vec<&String> = loaded.warnings.iter().filter(|w| w.contains("Latin-1")).collect();
    assert_eq!(latin1.len(), 2, "one warning per file: {:?}", loaded.warnings);
    assert!(latin1[0].contains("old.obj: line 1 and 1 more"), "{}", latin1[0]);
    assert!(latin1[1].contains("mat.mtl: line 1 is not UTF-8"), "{}", latin1[1]);

    // What cannot be read at all says where and why, never just "read error".
    let long_line = format!("v 0 0 0\n# {}\n", "x".repeat(2000));
    let limits = obj::Limits { line_bytes: 1000, ..obj::Limits::DEFAULT };
    for (case, bytes, expected) in [
        ("binary", &b"v 0 0 0\nv 1\x00 0 0\n"[..], "binary.obj: line 2: a zero byte"),
        ("long", long_line.as_bytes(), "long.obj: line 2: 2002 bytes on one line"),
    ] {
        let dir = folder_of_bytes(&format!("unreadable-{case}"), &[(&format!("{case}.obj"), bytes)]);
        let path = dir.join(format!("{case}.obj"));
        let error = obj::load_within(&path, &|p: &Path| common::files::read(p), limits).unwrap_err().to_string();
        assert!(error.contains(expected) && !error.contains("read error"), "{error}");
    }
}

// Issue 25, kind 2: vertex colours, read in linear light.
#[test]
fn vertex_colours_are_read_in_linear_light() {
    let text = "v 0 0 0 1 0 0\nv 1 0 0 0 1 0\nv 0 1 0 0.5 0.5 0.5\nv 1 1 0\nf 1 2 3\nf 2 4 3\n";
    let dir = folder("colours", &[("coloured.obj", text), ("plain.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")]);
    let loaded = load(&dir.join("coloured.obj")).unwrap();
    assert!(loaded.vertex_colours);
    assert!(loaded.model.materials.iter().all(|m| m.vertex_colours));
    let colour_at = |position: [f32; 3]| loaded.model.vertices.iter().find(|v| v.position == position).unwrap().colour;
    assert_eq!(colour_at([0.0, 0.0, 0.0]), [1.0, 0.0, 0.0]);
    assert_eq!(colour_at([1.0, 0.0, 0.0]), [0.0, 1.0, 0.0]);
    // sRGB 0.5 is 21 % of the light of white.
    assert!((colour_at([0.0, 1.0, 0.0])[0] - 0.2140).abs() < 1e-3, "{:?}", colour_at([0.0, 1.0, 0.0]));
    // A vertex without a colour, in a file with colours, is white.
    assert_eq!(colour_at([1.0, 1.0, 0.0]), [1.0; 3]);
    let plain = load(&dir.join("plain.obj")).unwrap();
    assert!(!plain.vertex_colours && plain.model.materials.iter().all(|m| !m.vertex_colours));
    assert!(plain.model.vertices.iter().all(|v| v.colour == [1.0; 3]));
}

/// A cube whose corners are all `colour` (an OBJ colour, 0 to 1).
fn coloured_cube(colour: &str) -> String {
    let mut text = String::new();
    for corner in 0..8 {
        let [x, y, z] = [corner & 1, (corner >> 1) & 1, (corner >> 2) & 1];
        text += &format!("v {x} {y} {z} {colour}\n");
    }
    text + "f 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\n"
}

// Issue 25, kind 2: vertex colours are drawn, and the model's facts say so.
#[test]
fn vertex_colours_are_drawn() {
    let dir = folder("colours-drawn", &[("red.obj", &coloured_cube("1 0 0")), ("white.obj", &coloured_cube("1 1 1"))]);
    let gpu = gpu();
    let view = common::chapter::view_index::<TexturesChapter>("car").unwrap();
    let target = Target { format: OFFSCREEN_FORMAT, width: 64, height: 64, samples: 1 };
    let mut reddish = Vec::new();
    for name in ["red.obj", "white.obj"] {
        let mut chapter = chapter_with_model(&gpu, &dir.join(name), (64, 64));
        let facts = chapter.featured.facts();
        assert!(facts.contains("it has vertex colours"), "{name}: the model's facts say so: {facts}");
        chapter.select_view(view);
        let picture =
            capture(&gpu, &mut chapter, target, (TexturesChapter::SNAPSHOT_TIME, view), Default::default()).unwrap();
        reddish.push(picture.pixels().filter(|p| i32::from(p[0]) > 2 * i32::from(p[1]) + 20).count());
    }
    assert!(reddish[0] > reddish[1] + 100, "the red cube is red: {reddish:?} reddish pixels (red, white)");
}

// Issue 25, kind 3: BMP and TGA textures on the desktop.
#[test]
fn bmp_and_tga_textures_are_read() {
    use common::image::ImageFormat;
    for (name, format) in [("wood.bmp", ImageFormat::Bmp), ("wood.tga", ImageFormat::Tga)] {
        let bytes = picture([200, 120, 40, 255], 4, format);
        let image = common::texture::decode_named(name, &bytes).unwrap_or_else(|e| panic!("{name}: {e:#}"));
        assert_eq!((image.width(), image.get_pixel(3, 3).0), (4, [200, 120, 40, 255]), "{name}");
    }
    let error = common::texture::decode_named("wood.tga", b"not a picture").unwrap_err();
    assert!(format!("{error:#}").contains("wood.tga is not a readable"), "{error:#}");
}

// Issue 25, kind 4: texture paths written on another machine.
#[test]
fn texture_paths_from_other_machines_are_found_by_their_name() {
    let png = picture([255; 4], 2, common::image::ImageFormat::Png);
    let mtl = "newmtl wood\nmap_Kd C:\\\\Users\\\\Ann Lee\\\\My Textures\\\\dungeon_texture.png\n\
               newmtl stone\nmap_Kd /home/bob/textures/stone.png\n\
               newmtl lost\nmap_Kd D:\\\\lost\\\\nowhere.png\n";
    let obj = "mtllib materials/scene.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nusemtl wood\nf 1/1 2/1 3/1\n";
    let dir = folder_of_bytes(
        "elsewhere",
        &[
            ("scene.obj", obj.as_bytes()),
            ("materials/scene.mtl", mtl.as_bytes()),
            ("materials/dungeon_texture.png", &png),
            ("stone.png", &png),
        ],
    );
    let loaded = load(&dir.join("scene.obj")).unwrap();
    let read = |p: &Path| common::files::read(p);
    let found = |name: &str| {
        let material = loaded.model.materials.iter().find(|m| m.name == name).unwrap();
        assert_eq!(material.texture_folders, [dir.join("materials"), dir.clone()], "beside the MTL, then the OBJ");
        let folders: Vec<&Path> = material.texture_folders.iter().map(PathBuf::as_path).collect();
        obj::find_file(material.albedo_map.as_ref().unwrap(), Path::new(""), &folders, &read)
    };
    match found("wood") {
        obj::Found::Elsewhere { path, .. } => assert_eq!(path, dir.join("materials/dungeon_texture.png")),
        _ => panic!("the wood texture is beside the MTL"),
    }
    match found("stone") {
        obj::Found::Elsewhere { path, .. } => assert_eq!(path, dir.join("stone.png")),
        _ => panic!("the stone texture is beside the OBJ"),
    }
    match found("lost") {
        obj::Found::Nowhere { error, tried } => {
            assert!(error.to_string().contains("no such file"), "{error}");
            let expected =
                [dir.join("materials/D:/lost/nowhere.png"), dir.join("materials/nowhere.png"), dir.join("nowhere.png")];
            assert_eq!(tried, expected, "every place tried");
        }
        _ => panic!("the lost texture is nowhere"),
    }
}

// Issue 25, kind 5: `mtllib` with several files, or one with spaces.
#[test]
fn mtllib_may_name_several_files_or_one_whose_name_has_spaces() {
    let faces =
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvn 0 0 1\nusemtl a\nf 1/1/1 2/1/1 3/1/1\nusemtl b\nf 3/1/1 2/1/1 1/1/1\n";
    let dir = folder(
        "mtllib",
        &[
            ("list.obj", &format!("mtllib first.mtl missing.mtl second.mtl\n{faces}")),
            ("spaces.obj", &format!("mtllib my materials.mtl\n{faces}")),
            ("windows.obj", &format!("mtllib C:\\\\Work\\\\first.mtl\n{faces}")),
            ("first.mtl", "newmtl a\nKd 1 0 0\n"),
            ("second.mtl", "newmtl b\nKd 0 0 1\n"),
            ("my materials.mtl", "newmtl a\nKd 1 0 0\nnewmtl b\nKd 0 0 1\n"),
        ],
    );
    let names = |loaded: &obj::LoadedModel| -> Vec<String> {
        loaded.model.parts.iter().map(|p| loaded.model.materials[p.material].name.clone()).collect()
    };
    let list = load(&dir.join("list.obj")).unwrap();
    assert_eq!(names(&list), ["a", "b"]);
    assert_eq!(list.material_files, [dir.join("first.mtl"), dir.join("second.mtl")]);
    assert_eq!(list.warnings.len(), 1, "{:?}", list.warnings);
    assert!(list.warnings[0].contains("missing.mtl: no such file"), "{}", list.warnings[0]);
    let spaces = load(&dir.join("spaces.obj")).unwrap();
    assert_eq!((names(&spaces), spaces.warnings.len()), (vec!["a".to_string(), "b".to_string()], 0));
    let windows = load(&dir.join("windows.obj")).unwrap();
    assert_eq!(windows.material_files, [dir.join("first.mtl")]);
    assert!(windows.warnings.iter().any(|w| w.contains("not found as written; using")), "{:?}", windows.warnings);
}

// Issue 25, kind 6: texture coordinate and normal indices past the end.
#[test]
fn out_of_range_texture_coordinates_and_normals_are_left_out() {
    let text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nvn 0 0 1\n\
                f 1/1/1 2/2/1 3/9/1\n\
                f 2/2/7 4/3/1 3/3/1\n\
                f 2/2/1 4/3/9000000000000000000 3/3/1\n";
    let dir = folder("out-of-range", &[("range.obj", text)]);
    let loaded = load(&dir.join("range.obj")).unwrap();
    assert_eq!(loaded.model.triangle_count(), 3);
    let says = |words: &[&str]| loaded.warnings.iter().filter(|w| words.iter().all(|x| w.contains(x))).count();
    assert_eq!(says(&["range.obj: line 9: texture coordinate index", "(1 in all)"]), 1, "{:?}", loaded.warnings);
    assert_eq!(says(&["range.obj: line 10: normal index", "(2 in all)"]), 1, "{:?}", loaded.warnings);
    assert_eq!(says(&["without normals; computed"]), 1, "{:?}", loaded.warnings);
    assert_eq!(says(&["without texture coordinates; drawn untextured"]), 1, "{:?}", loaded.warnings);
    assert!(loaded.model.vertices.iter().all(|v| (Vec3::from(v.normal) - Vec3::Z).length() < 1e-6));
}

// Issue 25, kind 7: coordinates that are not finite numbers.
#[test]
fn non_finite_coordinates_are_left_out_with_their_faces() {
    let text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv nan 0 0\nv 1 1.#IND 0\nv inf 0 1\nv -1.#QNAN0 2 2\nv 1e39 0 0\n\
                vn 0 0 1\nvn -nan(ind) 0 1\n\
                f 1//1 2//1 3//1\nf 1 2 4\nf 2 5 3\nf 1 6 7 8\nf 1//2 3//1 2//1\n";
    let dir = folder("not-finite", &[("nan.obj", text)]);
    let loaded = load(&dir.join("nan.obj")).unwrap();
    assert_eq!(loaded.model.triangle_count(), 2, "the faces on finite positions stay");
    assert!(loaded.model.vertices.iter().all(|v| Vec3::from(v.position).is_finite()));
    let about: Vec<&String> = loaded.warnings.iter().filter(|w| w.contains("not finite")).collect();
    assert_eq!(about.len(), 2, "{:?}", loaded.warnings);
    assert!(about[0].contains("nan.obj: line 4: 5 position(s)") && about[0].contains("left out, with the faces"));
    assert!(about[1].contains("nan.obj: line 10: 1 normal(s)") && about[1].contains("computed instead"));
}

/// The area of the triangles of `model`, each counted as positive.
fn area(model: &textures::mesh::ModelData) -> f32 {
    let p = |i: u32| Vec3::from(model.vertices[i as usize].position);
    model.indices.chunks_exact(3).map(|t| (p(t[1]) - p(t[0])).cross(p(t[2]) - p(t[0])).length() / 2.0).sum()
}

// Issue 25, kind 8: concave faces are cut into ears, in their own plane.
#[test]
fn concave_faces_are_cut_into_ears() {
    // A star of 33 points (66 corners), tilted out of every axis plane; and
    // a comb. Fans from the first corner would cover more than the face.
    let tilt = common::glam::Quat::from_euler(common::glam::EulerRot::XYZ, 0.4, 0.7, 0.2);
    let face = |corners: &[(f32, f32)]| {
        let mut text = String::new();
        for &(x, y) in corners {
            let p = tilt * Vec3::new(x, y, 0.0) + Vec3::new(3.0, 1.0, -2.0);
            text += &format!("v {} {} {}\n", p.x, p.y, p.z);
        }
        let numbers: Vec<String> = (1..=corners.len()).map(|i| format!("{i}/1/1")).collect();
        text + "vt 0 0\nvn 0 0 1\nf " + &numbers.join(" ") + "\n"
    };
    let star: Vec<(f32, f32)> = (0..66)
        .map(|i| {
            let (s, c) = (i as f32 * std::f32::consts::TAU / 66.0).sin_cos();
            let r = if i % 2 == 0 { 1.0 } else { 0.4 };
            (r * c, r * s)
        })
        .collect();
    // Shoelace: the star's own area.
    let star_area: f32 =
        (0..66).map(|i| star[i].0 * star[(i + 1) % 66].1 - star[(i + 1) % 66].0 * star[i].1).sum::<f32>() / 2.0;
    let comb = [(0.0, 0.0), (7.0, 0.0), (7.0, 3.0), (6.0, 3.0), (6.0, 1.0), (5.0, 1.0), (5.0, 3.0), (4.0, 3.0)]
        .into_iter()
        .chain([(4.0, 1.0), (3.0, 1.0), (3.0, 3.0), (2.0, 3.0), (2.0, 1.0), (1.0, 1.0), (1.0, 3.0), (0.0, 3.0)])
        .collect::<Vec<(f32, f32)>>();
    let comb_area: f32 = (0..comb.len())
        .map(|i| comb[i].0 * comb[(i + 1) % comb.len()].1 - comb[(i + 1) % comb.len()].0 * comb[i].1)
        .sum::<f32>()
        / 2.0;
    let dir = folder("ears", &[("star.obj", &face(&star)), ("comb.obj", &face(&comb))]);
    let normal = tilt * Vec3::Z;
    for (name, corners, expected) in [("star.obj", 66, star_area), ("comb.obj", comb.len(), comb_area)] {
        let loaded = load(&dir.join(name)).unwrap();
        let model = &loaded.model;
        assert_eq!(model.triangle_count(), corners - 2, "{name}");
        assert!((area(model) - expected).abs() < 1e-3 * expected, "{name}: {} against {expected}", area(model));
        let p = |i: u32| Vec3::from(model.vertices[i as usize].position);
        for t in model.indices.chunks_exact(3) {
            let winding = (p(t[1]) - p(t[0])).cross(p(t[2]) - p(t[0])).dot(normal);
            assert!(winding > -1e-6, "{name}: every triangle winds as the face does");
        }
        assert!(loaded.warnings.is_empty(), "{name}: {:?}", loaded.warnings);
    }
}

// Issue 25, "also": files too large are refused with a message, quickly.
#[test]
fn too_many_triangles_or_elements_are_refused_with_the_line() {
    let limits = obj::Limits { line_bytes: 1 << 20, elements: 100, triangles: 50 };
    let mut text = String::from("v 0 0 0\nv 1 0 0\nv 0 1 0\n");
    for _ in 0..60 {
        text += "f 1 2 3\n";
    }
    let many_positions = "v 0 0 0\n".repeat(101);
    let dir = folder("limits", &[("faces.obj", &text), ("positions.obj", &many_positions)]);
    let read = |p: &Path| common::files::read(p);
    let error = obj::load_within(&dir.join("faces.obj"), &read, limits).unwrap_err().to_string();
    assert!(error.contains("faces.obj: line 54: more than 50 triangles"), "{error}");
    let error = obj::load_within(&dir.join("positions.obj"), &read, limits).unwrap_err().to_string();
    assert!(error.contains("positions.obj: line 101: more than 100 positions"), "{error}");
}

#[test]
fn pr_and_pm_are_read_clamped_with_the_line_named_or_derived_from_ns() {
    let mtl = "newmtl metal\nKd 0.9 0.6 0.2\nPr 0.25\nPm 1\n\
               newmtl wild\nKd 0.5 0.5 0.5\nPr 1.7\nPm -0.5\n\
               newmtl garbled\nKd 0.5 0.5 0.5\nPr rough\n\
               newmtl classic\nKd 0.5 0.5 0.5\nNs 96\n";
    let obj = "mtllib pbr.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\n\
               usemtl metal\nf 1//1 2//1 3//1\nusemtl wild\nf 1//1 2//1 3//1\n\
               usemtl garbled\nf 1//1 2//1 3//1\nusemtl classic\nf 1//1 2//1 3//1\n";
    let dir = folder("pbr-keys", &[("pbr.obj", obj), ("pbr.mtl", mtl)]);
    let loaded = load(&dir.join("pbr.obj")).unwrap();
    let material = |name: &str| loaded.model.materials.iter().find(|m| m.name == name).unwrap().clone();
    assert_eq!((material("metal").roughness, material("metal").metallic), (Some(0.25), Some(1.0)));
    assert_eq!((material("wild").roughness, material("wild").metallic), (Some(1.0), Some(0.0)));
    assert_eq!((material("garbled").roughness, material("garbled").metallic), (None, None));
    // No Pr or Pm: a non-metal whose roughness comes from Ns by the stated rule.
    let classic = material("classic");
    assert!(!classic.is_physical());
    assert_eq!(classic.physical(), (lighting::pbr::roughness_from_shininess(96.0), 0.0));
    let about = |line: usize| loaded.warnings.iter().filter(|w| w.contains(&format!("pbr.mtl: line {line}:"))).count();
    assert_eq!((about(7), about(8), about(11)), (1, 1, 1), "{:#?}", loaded.warnings);
    assert!(loaded.warnings.iter().any(|w| w.contains("line 7: Pr 1.7 is outside 0 to 1; roughness 1 used")));
    assert!(loaded.warnings.iter().any(|w| w.contains("line 11: Pr `rough` is not a number")));
    assert_eq!(about(3) + about(4), 0, "in-range values are not warned about");
}

#[test]
fn map_pr_and_map_pm_are_read_beside_the_mtl_and_alone_give_the_value() {
    let mtl = "newmtl mapped\nKd 1 1 1\nmap_Pr -imfchan l maps/rough.png\nmap_Pm metal.png\nPm 0.5\n";
    let obj = "mtllib pbr.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nusemtl mapped\nf 1/1 2/2 3/3\n";
    let dir = folder("pbr-maps", &[("pbr.obj", obj), ("pbr.mtl", mtl)]);
    let loaded = load(&dir.join("pbr.obj")).unwrap();
    let material = first_material(&loaded);
    assert_eq!(material.roughness_map.as_deref(), Some(dir.join("maps/rough.png").as_path()));
    assert_eq!(material.metallic_map.as_deref(), Some(dir.join("metal.png").as_path()));
    // The map alone gives the roughness (times 1); Pm scales its map.
    assert!(material.is_physical());
    assert_eq!(material.physical(), (1.0, 0.5));
}

#[test]
fn a_model_with_pr_or_pm_is_shaded_by_cook_torrance() {
    // A gold pyramid, facing the stage's camera, with and without Pr and Pm.
    let obj = "mtllib gold.mtl\nv -1 0 -1\nv 1 0 -1\nv 1 0 1\nv -1 0 1\nv 0 1.5 0\nusemtl gold\n\
               f 1 2 5\nf 2 3 5\nf 3 4 5\nf 4 1 5\n";
    let classic = "newmtl gold\nKd 1.0 0.77 0.34\nKs 0.5 0.5 0.5\nNs 40\n";
    let physical = format!("{classic}Pr 0.3\nPm 1\n");
    let gpu = gpu();
    let view = common::chapter::view_index::<TexturesChapter>("car").unwrap();
    let target = Target { format: OFFSCREEN_FORMAT, width: 160, height: 90, samples: 1 };
    let mut pictures = Vec::new();
    for (case, mtl) in [("gold-classic", classic.to_string()), ("gold-physical", physical)] {
        let dir = folder(case, &[("gold.obj", obj), ("gold.mtl", &mtl)]);
        let mut chapter = chapter_with_model(&gpu, &dir.join("gold.obj"), (160, 90));
        let shaded = chapter.featured.facts().contains("Cook-Torrance");
        assert_eq!((chapter.featured.physical, shaded), (case == "gold-physical", case == "gold-physical"));
        chapter.select_view(view);
        pictures.push(
            capture(&gpu, &mut chapter, target, (TexturesChapter::SNAPSHOT_TIME, view), Default::default()).unwrap(),
        );
    }
    let differ = pictures[0].pixels().zip(pictures[1].pixels()).filter(|(a, b)| a != b).count();
    assert!(differ > 100, "Cook-Torrance and Blinn-Phong draw the same gold pyramid ({differ} pixels differ)");
}

/// Where a cell of `ROUGHNESS_CELLS` is white: a 4 × 4 pattern that no
/// mirror (of u, of v, or both) or quarter turn maps onto itself, so that a
/// map read at the wrong texel shows the wrong value somewhere.
const ROUGHNESS_CELLS: [[bool; 4]; 4] =
    [[true, false, false, false], [true, true, false, false], [false, true, false, true], [false, false, true, true]];

/// A roughness or metalness map shades each texel as the same material with
/// that texel's value as Pr or Pm does, at that texel. The map is
/// `ROUGHNESS_CELLS`, black and white cells of 16 texels; the same picture
/// as an albedo map, drawn beside a white and a black panel, says which
/// texel each screen pixel shows (the pixels that draw as the white panel
/// show a white texel, those that draw as the black one a black texel;
/// the seams, where the sampler blends two cells, are left out). Then,
/// pixel for pixel, the panel with the map must draw as the panel with the
/// low value where its texel is black and as the one with the high value
/// where it is white. Made to fail by reading the maps at the mirrored
/// texel (1 − u in `physical_at`: 8,273 of the 9,781 pixels where Pr 0 and
/// Pr 1 differ drew the other value), by reading the roughness from the
/// metalness map (white where the material has none), and by leaving the
/// maps out of `physical_at` (every pixel then draws the high value).
#[test]
fn roughness_and_metalness_maps_shade_each_texel_as_its_value_would() {
    let cells = common::image::RgbaImage::from_fn(64, 64, |x, y| {
        let white = ROUGHNESS_CELLS[(y / 16) as usize][(x / 16) as usize];
        common::image::Rgba(if white { [255, 255, 255, 255] } else { [0, 0, 0, 255] })
    });
    let mut png = std::io::Cursor::new(Vec::new());
    common::image::DynamicImage::ImageRgba8(cells).write_to(&mut png, common::image::ImageFormat::Png).unwrap();
    let png = png.into_inner();
    // A panel facing the stage's camera, its texture across it.
    let obj = b"mtllib panel.mtl\nv 1 0 0\nv -1 0 0\nv -1 2 0\nv 1 2 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvn 0 0 -1\n\
                usemtl m\nf 1/1/1 2/2/1 3/3/1\nf 1/1/1 3/3/1 4/4/1\n";
    let gpu = gpu();
    let view = common::chapter::view_index::<TexturesChapter>("car").unwrap();
    let target = Target { format: OFFSCREEN_FORMAT, width: 320, height: 180, samples: 1 };
    let draw = |case: &str, mtl: String| {
        let dir = folder_of_bytes(case, &[("panel.obj", obj), ("panel.mtl", mtl.as_bytes()), ("cells.png", &png)]);
        let mut chapter = chapter_with_model(&gpu, &dir.join("panel.obj"), (320, 180));
        assert!(chapter.warnings.is_empty(), "{case}: {:?}", chapter.warnings);
        assert!(chapter.featured.physical, "{case} is shaded by Cook-Torrance");
        chapter.select_view(view);
        // Bloom spreads a highlight over its neighbours: off, so that each
        // pixel shows its own texel's light alone.
        chapter.settings.bloom = false;
        capture(&gpu, &mut chapter, target, (TexturesChapter::SNAPSHOT_TIME, view), Default::default()).unwrap()
    };
    let close = |a: &[u8], b: &[u8]| a.iter().zip(b).all(|(x, y)| x.abs_diff(*y) <= 1);
    // Which texel each pixel shows: the cells as albedo, against all white and all black.
    let rough = "Pr 0.6\nPm 0\n";
    let as_albedo = draw("cells-albedo", format!("newmtl m\nKd 1 1 1\n{rough}map_Kd cells.png\n"));
    let white = draw("cells-white", format!("newmtl m\nKd 1 1 1\n{rough}"));
    let black = draw("cells-black", format!("newmtl m\nKd 0 0 0\n{rough}"));
    let texels: Vec<Option<bool>> = as_albedo
        .pixels()
        .zip(white.pixels())
        .zip(black.pixels())
        .map(|((a, w), b)| match (close(&w.0, &b.0), close(&a.0, &w.0), close(&a.0, &b.0)) {
            (true, _, _) => None, // the background: no texel
            (_, true, false) => Some(true),
            (_, false, true) => Some(false),
            _ => None, // a seam between cells
        })
        .collect();
    let (white_texels, black_texels) =
        (texels.iter().filter(|t| **t == Some(true)).count(), texels.iter().filter(|t| **t == Some(false)).count());
    assert!(white_texels > 2000 && black_texels > 2000, "{white_texels} pixels show white cells, {black_texels} black");

    let gold = "newmtl m\nKd 1.0 0.77 0.34\n";
    for (key, other) in [("Pr", "Pm 1"), ("Pm", "Pr 0.3")] {
        let mapped = draw(&format!("{key}-map"), format!("{gold}{other}\nmap_{key} cells.png\n"));
        let low = draw(&format!("{key}-0"), format!("{gold}{other}\n{key} 0\n"));
        let high = draw(&format!("{key}-1"), format!("{gold}{other}\n{key} 1\n"));
        let (mut right, mut wrong, mut neither, mut differ) = (0, 0, 0, 0);
        for (((m, l), h), texel) in mapped.pixels().zip(low.pixels()).zip(high.pixels()).zip(&texels) {
            let Some(white) = texel else { continue };
            if close(&l.0, &h.0) {
                continue; // wherever the value makes no difference
            }
            differ += 1;
            let (expected, other) = if *white { (h, l) } else { (l, h) };
            match (close(&m.0, &expected.0), close(&m.0, &other.0)) {
                (true, _) => right += 1,
                (_, true) => wrong += 1,
                _ => neither += 1,
            }
        }
        let says = format!(
            "map_{key}: of {differ} pixels where {key} 0 and {key} 1 differ, {right} draw their texel's value, \
             {wrong} the other value, {neither} neither"
        );
        eprintln!("{says}");
        assert!(differ > 2000, "{says}");
        assert!(wrong == 0 && neither < differ / 50, "{says}");
    }
}
