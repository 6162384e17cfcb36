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
    let dir = std::env::temp_dir().join(format!("textures-{case}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    for (name, text) in files {
        std::fs::write(dir.join(name), text).unwrap();
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
        ("face", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n", "line 4:"),
        ("normal", "v 0 0 0\nvn 0 1\nf 1 1 1\n", "line 2: normal parse error"),
        // Indices tobj would turn into huge numbers and overflow on.
        ("huge", "v 0 0 0\nf -9223372036854775808 1 1\n", "line 2: index out of range"),
        ("huge-normal", "v 0 0 0\nvn 0 1 0\nf 1//9000000000000000000 1//1 1//1\n", "line 3: index out of range"),
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
/// and exit code 2, never a panic.
#[test]
fn the_binary_exits_2_on_a_broken_or_missing_model() {
    let dir = folder("binary", &[("broken.obj", "v 0 0 0\nv 1 x 0\n")]);
    for model in [dir.join("broken.obj"), dir.join("absent.obj")] {
        let out = Command::new(env!("CARGO_BIN_EXE_textures"))
            .args(["--screenshot", dir.join("out.png").to_str().unwrap(), "--size", "64x36", "--model"])
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
}

fn gpu() -> Gpu {
    Gpu::headless(TexturesChapter::gpu_needs()).unwrap()
}

fn chapter_with_model(gpu: &Gpu, path: &Path, size: (u32, u32)) -> TexturesChapter {
    let target = Target { format: OFFSCREEN_FORMAT, width: size.0, height: size.1 };
    let flags = FlagValues(vec![("model", path.display().to_string())]);
    common::chapter::create::<TexturesChapter>(gpu, target, &flags).unwrap()
}

/// A texture the MTL names but the folder lacks: one warning naming it,
/// a magenta checker where it would be, and the model still drawn.
#[test]
fn a_missing_texture_is_one_warning_and_a_visible_checker() {
    let dir = folder(
        "no-texture",
        &[
            (
                "panel.obj",
                // Facing −z, the side the stage turns towards its camera.
                "mtllib panel.mtl\nv 1 0 0\nv -1 0 0\nv -1 2 0\nv 1 2 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvn 0 0 -1\n\
                 usemtl a\nf 1/1/1 2/2/1 3/3/1\nusemtl b\nf 1/1/1 3/3/1 4/4/1\n",
            ),
            ("panel.mtl", "newmtl a\nKd 1 1 1\nmap_Kd gone.png\nnewmtl b\nKd 1 1 1\nmap_Kd gone.png\n"),
        ],
    );
    let gpu = gpu();
    let mut chapter = chapter_with_model(&gpu, &dir.join("panel.obj"), (320, 180));
    let about: Vec<&String> = chapter.warnings.iter().filter(|w| w.contains("gone.png")).collect();
    assert_eq!(about.len(), 1, "one warning for the file, however many materials use it: {:?}", chapter.warnings);
    assert!(about[0].contains("checker"), "{}", about[0]);
    let view = common::chapter::view_index::<TexturesChapter>("car").unwrap();
    chapter.select_view(view);
    let target = Target { format: OFFSCREEN_FORMAT, width: 320, height: 180 };
    let picture = capture(&gpu, &mut chapter, target, TexturesChapter::SNAPSHOT_TIME, view).unwrap();
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
    let target = Target { format: OFFSCREEN_FORMAT, width: 160, height: 90 };
    let with = capture(&gpu, &mut chapter, target, TexturesChapter::SNAPSHOT_TIME, view).unwrap();
    // The same picture with the model taken off the stage: the middle changes.
    chapter.featured.placement = common::glam::Mat4::from_translation(Vec3::new(0.0, -1000.0, 0.0));
    let without = capture(&gpu, &mut chapter, target, TexturesChapter::SNAPSHOT_TIME, view).unwrap();
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
