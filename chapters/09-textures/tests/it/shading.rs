//! Flat, Gouraud and Phong shading in the textured renderer: chapter 08's
//! switch, with the texture still read per pixel. On a coarse sphere whose
//! texture is one colour, brought in with `--model` and shown on the stage,
//! the three give different pictures, and flat shading gives each face one
//! colour: the light is the face's, and the texture adds no change of its own.

use std::path::{Path, PathBuf};

use common::glam::{Mat4, Vec2, Vec3};
use common::headless::{OFFSCREEN_FORMAT, capture};
use common::{Camera, Chapter, FlagValues, Gpu, Target, image};
use lighting::Shading;
use textures::{TexturesChapter, obj};

const SIZE: (u32, u32) = (480, 270);

/// A unit sphere of `columns` × `rows` quads as OBJ text, with smooth
/// normals and texture coordinates, all in the material `paint`.
fn sphere_obj(columns: u32, rows: u32) -> String {
    let mut text = String::from("mtllib paint.mtl\nusemtl paint\n");
    for row in 0..=rows {
        for column in 0..=columns {
            let (u, v) = (column as f32 / columns as f32, row as f32 / rows as f32);
            let (s, c) = (std::f32::consts::TAU * u).sin_cos();
            let (sl, cl) = (std::f32::consts::PI * v).sin_cos();
            let (x, y, z) = (sl * s, cl, sl * c);
            text += &format!("v {x} {y} {z}\nvt {u} {}\nvn {x} {y} {z}\n", 1.0 - v);
        }
    }
    for row in 0..rows {
        for column in 0..columns {
            let i = |c: u32, r: u32| r * (columns + 1) + c + 1;
            let quad = [i(column, row), i(column, row + 1), i(column + 1, row + 1), i(column + 1, row)];
            text += &format!("f {}\n", quad.map(|k| format!("{k}/{k}/{k}")).join(" "));
        }
    }
    text
}

/// A folder with the sphere, its material and its texture: 4 × 4 texels
/// of one orange, and a highlight, so that every term of the light shows.
fn sphere_folder() -> PathBuf {
    let dir = std::env::temp_dir().join(format!("textures-shading-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join("sphere.obj"), sphere_obj(12, 6)).unwrap();
    std::fs::write(dir.join("paint.mtl"), "newmtl paint\nKd 1 1 1\nKs 0.5 0.5 0.5\nNs 24\nmap_Kd paint.png\n").unwrap();
    image::RgbaImage::from_pixel(4, 4, image::Rgba([200, 120, 60, 255])).save(dir.join("paint.png")).unwrap();
    dir
}

/// The stage with the sphere on it, seen by the `car` view's camera, with
/// `shading` and no bloom (which would spread light from face to face).
fn render(gpu: &Gpu, chapter: &mut TexturesChapter, shading: Shading) -> image::RgbaImage {
    let target = Target { format: OFFSCREEN_FORMAT, width: SIZE.0, height: SIZE.1, samples: 1 };
    let view = common::chapter::view_index::<TexturesChapter>("car").unwrap();
    chapter.select_view(view);
    chapter.settings.shading = shading;
    chapter.settings.bloom = false;
    capture(gpu, chapter, target, (TexturesChapter::SNAPSHOT_TIME, view), Default::default()).unwrap()
}

/// For every face of `model` placed by `placement` that faces `camera`, the
/// pixels whose centres lie inside it, at least 1.5 pixels from its edges:
/// the pixels that face alone covers, whatever the rasteriser's rules.
fn faces_pixels(model: &textures::mesh::ModelData, placement: Mat4, camera: &Camera) -> Vec<Vec<(u32, u32)>> {
    let (w, h) = (SIZE.0 as f32, SIZE.1 as f32);
    let to_screen = |world: Vec3| {
        let clip = camera.view_projection() * world.extend(1.0);
        Vec2::new((clip.x / clip.w + 1.0) * 0.5 * w, (1.0 - clip.y / clip.w) * 0.5 * h)
    };
    let mut faces = Vec::new();
    for t in model.indices.chunks_exact(3) {
        let world = [0, 1, 2].map(|k| placement.transform_point3(model.vertices[t[k] as usize].position.into()));
        let normal = (world[1] - world[0]).cross(world[2] - world[0]);
        if normal.dot(camera.position - world[0]) <= 0.0 {
            continue;
        }
        let screen = world.map(to_screen);
        let (low, high) = (screen[0].min(screen[1]).min(screen[2]), screen[0].max(screen[1]).max(screen[2]));
        let mut inside = Vec::new();
        for y in low.y.floor().max(0.0) as u32..(high.y.ceil() as u32).min(SIZE.1) {
            for x in low.x.floor().max(0.0) as u32..(high.x.ceil() as u32).min(SIZE.0) {
                let p = Vec2::new(x as f32 + 0.5, y as f32 + 0.5);
                // Signed distances to the three edges: all past 1.5 on one side.
                let distances = [0, 1, 2].map(|e| {
                    let (a, b) = (screen[e], screen[(e + 1) % 3]);
                    (b - a).perp_dot(p - a) / (b - a).length().max(1e-6)
                });
                if distances.iter().all(|d| *d >= 1.5) || distances.iter().all(|d| *d <= -1.5) {
                    inside.push((x, y));
                }
            }
        }
        if inside.len() >= 6 {
            faces.push(inside);
        }
    }
    faces
}

/// The largest difference, over the three channels, between two pixels of `pixels`.
fn spread(picture: &image::RgbaImage, pixels: &[(u32, u32)]) -> u8 {
    (0..3)
        .map(|c| {
            let values = pixels.iter().map(|&(x, y)| picture.get_pixel(x, y)[c]);
            values.clone().max().unwrap_or(0) - values.min().unwrap_or(0)
        })
        .max()
        .unwrap_or(0)
}

fn mean_difference(a: &image::RgbaImage, b: &image::RgbaImage, pixels: &[(u32, u32)]) -> f32 {
    let sum: f32 = pixels
        .iter()
        .map(|&(x, y)| (0..3).map(|c| f32::from(a.get_pixel(x, y)[c].abs_diff(b.get_pixel(x, y)[c]))).sum::<f32>())
        .sum();
    sum / (3 * pixels.len()) as f32
}

#[test]
fn flat_gouraud_and_phong_differ_and_flat_gives_each_face_one_colour() {
    let dir = sphere_folder();
    let path: &Path = &dir.join("sphere.obj");
    let gpu = Gpu::headless(TexturesChapter::gpu_needs()).unwrap();
    let target = Target { format: OFFSCREEN_FORMAT, width: SIZE.0, height: SIZE.1, samples: 1 };
    let flags = FlagValues(vec![("model", path.display().to_string())]);
    let mut chapter = common::chapter::create::<TexturesChapter>(&gpu, target, &flags).unwrap();
    let [flat, gouraud, phong] =
        [Shading::Flat, Shading::Gouraud, Shading::Phong].map(|s| render(&gpu, &mut chapter, s));

    let model = obj::load(path, &|p: &Path| common::files::read(p)).unwrap().model;
    let faces = faces_pixels(&model, chapter.featured.placement, &chapter.camera);
    let all: Vec<(u32, u32)> = faces.concat();
    // Page 09 says 32: where the camera and the model's placement put them.
    assert_eq!(faces.len(), 32, "faces big enough to look inside");

    // One colour per face in flat shading; Phong's light changes across most.
    let flat_spreads: Vec<u8> = faces.iter().map(|f| spread(&flat, f)).collect();
    let varied = faces.iter().filter(|f| spread(&phong, f) > 2).count();
    eprintln!(
        "{} faces, {} pixels: largest spread inside a face, flat {}; faces varying by more than 2 in Phong {varied}",
        faces.len(),
        all.len(),
        flat_spreads.iter().max().unwrap()
    );
    // Measured on lavapipe: not one level anywhere. The face's normal comes
    // from derivatives, which another GPU may round differently: one level.
    assert!(flat_spreads.iter().all(|s| *s <= 1), "flat shading varies inside a face: {flat_spreads:?}");
    assert!(varied * 2 > faces.len(), "Phong's light should change across most faces: {varied} of {}", faces.len());

    // Three ways of lighting, three pictures.
    let pairs = [
        ("flat", &flat, "gouraud", &gouraud),
        ("flat", &flat, "phong", &phong),
        ("gouraud", &gouraud, "phong", &phong),
    ];
    for (a_name, a, b_name, b) in pairs {
        let mean = mean_difference(a, b, &all);
        eprintln!("{a_name} against {b_name}: mean difference {mean:.2} of 255 over the sphere");
        // Measured on lavapipe: 21 to 32 levels of 255.
        assert!(mean > 5.0, "{a_name} and {b_name} draw the sphere alike: mean difference {mean:.2}");
    }
    let _ = std::fs::remove_dir_all(dir);
}
