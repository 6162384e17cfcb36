//! Worked solutions to the exercises of chapter 01's lessons, compiled and
//! checked with the chapter's other tests: the lessons include them by
//! anchor, and each test asserts the figure its solution states. A test's
//! name starts with its lesson's page (`vertices`, `pipeline`,
//! `interpolation`) and the exercise's number there.

use common::headless::{OFFSCREEN_FORMAT, Offscreen, capture, read_texture};
use common::wgpu::util::DeviceExt as _;
use common::{Chapter, Gpu, GpuNeeds, PassTimer, Target, image, shader, wgpu};
use triangle::{ColoredVertex, TRIANGLE, Triangle, build_pipeline};

/// Draws `vertices` (through `indices`, when given) with the chapter's own
/// smooth pipeline into a `size` × `size` picture cleared to black.
fn draw(gpu: &Gpu, size: u32, vertices: &[ColoredVertex], indices: Option<&[u16]>) -> image::RgbaImage {
    draw_with(gpu, SMOOTH, (size, size), vertices, indices)
}

/// The chapter's two pairs of entry points: blended, and flat.
const SMOOTH: (&str, &str) = ("vs_main", "fs_main");
const FLAT: (&str, &str) = ("vs_flat", "fs_flat");

/// [`draw`] with the pipeline of the `entry_points` given, into a picture
/// of `(width, height)`.
fn draw_with(
    gpu: &Gpu,
    (vertex_entry, fragment_entry): (&str, &str),
    (width, height): (u32, u32),
    vertices: &[ColoredVertex],
    indices: Option<&[u16]>,
) -> image::RgbaImage {
    let target = Target { format: OFFSCREEN_FORMAT, width, height, samples: 1 };
    let module = shader!("triangle/triangle.wgsl").module(gpu).unwrap();
    let pipeline =
        build_pipeline(&gpu.device, &module, target.format, vertex_entry, fragment_entry, Default::default());
    let buffer = |contents: &[u8], usage| {
        gpu.device.create_buffer_init(&wgpu::util::BufferInitDescriptor { label: None, contents, usage })
    };
    let vertex_buffer = buffer(bytemuck::cast_slice(vertices), wgpu::BufferUsages::VERTEX);
    let index_buffer = indices.map(|i| buffer(bytemuck::cast_slice(i), wgpu::BufferUsages::INDEX));
    let offscreen = Offscreen::new(&gpu.device, target);
    let mut encoder = gpu.device.create_command_encoder(&Default::default());
    {
        let black = Some(wgpu::Color::BLACK);
        let mut pass = common::fullscreen::pass(&mut encoder, &PassTimer::off(), "exercise", &offscreen.view, black);
        pass.set_pipeline(&pipeline);
        pass.set_vertex_buffer(0, vertex_buffer.slice(..));
        match (&index_buffer, indices) {
            (Some(index_buffer), Some(indices)) => {
                pass.set_index_buffer(index_buffer.slice(..), wgpu::IndexFormat::Uint16);
                pass.draw_indexed(0..indices.len() as u32, 0, 0..1);
            }
            _ => pass.draw(0..vertices.len() as u32, 0..1),
        }
    }
    gpu.queue.submit([encoder.finish()]);
    read_texture(gpu, &offscreen.texture).unwrap()
}

/// Pixels that are not the black background.
fn covered(image: &image::RgbaImage) -> usize {
    image.pixels().filter(|p| p.0 != [0, 0, 0, 255]).count()
}

// ANCHOR: clipped
/// Vertices and shaders, exercise 1: the top corner made yellow, and moved from y = 0.7 up to
/// y = 1.5, out of clip space (which ends at 1).
const CLIPPED: [ColoredVertex; 3] =
    [ColoredVertex { position: [0.0, 1.5], color: [1.0, 1.0, 0.0] }, TRIANGLE[1], TRIANGLE[2]];
// ANCHOR_END: clipped

#[test]
fn vertices_exercise_1_a_corner_out_of_clip_space_is_cut_off() {
    let gpu = Gpu::headless(GpuNeeds::default()).expect("an adapter (lavapipe will do)");
    let picture = draw(&gpu, 64, &CLIPPED, None);
    // In clip units the triangle is 1.4 wide and 2.1 tall: 1.47 square
    // units. Above y = 1 a similar triangle 0.5 tall and 1/3 wide is cut
    // off (0.083), leaving 1.387 of the 4 square units the picture spans:
    // 1,420 of its 4,096 pixels. The rasteriser covers the pixels whose
    // centres are inside: 1,394 of them. What is left is a quadrilateral
    // whose top edge, a third of a unit wide, is the picture's top row:
    // 10.7 pixels.
    let (area, top_row) = (covered(&picture), (0..64).filter(|&x| picture.get_pixel(x, 0).0 != [0, 0, 0, 255]).count());
    assert!((area as f32 - 1394.0).abs() <= 14.0 && (area as f32 / 1420.0 - 1.0).abs() < 0.025, "{area} pixels");
    assert!((10..=12).contains(&top_row), "{top_row} pixels of the top row covered");
    // The yellow corner is off the picture, but its colour still reaches
    // the cut: three quarters of it (w₀ = 1.6 / 2.1) at the top edge.
    let top = picture.get_pixel(32, 0).0;
    assert!(top[0] > 200 && top[1] > 200 && top[2] < 120, "{top:?}");
}

// ANCHOR: square
/// The pipeline and the draw, exercise 1, first way: two triangles, six vertices, the two corners on
/// the diagonal listed twice. Both triangles wind counter-clockwise.
const SQUARE_SIX: [ColoredVertex; 6] = [
    ColoredVertex { position: [-0.5, -0.5], color: [1.0, 0.0, 0.0] },
    ColoredVertex { position: [0.5, -0.5], color: [0.0, 1.0, 0.0] },
    ColoredVertex { position: [0.5, 0.5], color: [0.0, 0.0, 1.0] },
    ColoredVertex { position: [-0.5, -0.5], color: [1.0, 0.0, 0.0] },
    ColoredVertex { position: [0.5, 0.5], color: [0.0, 0.0, 1.0] },
    ColoredVertex { position: [-0.5, 0.5], color: [1.0, 1.0, 1.0] },
];

/// The pipeline and the draw, exercise 1, second way: the four corners once each, and an index buffer
/// (`wgpu::BufferUsages::INDEX`) that lists each triangle's corners.
/// Drawn with `set_index_buffer(…, IndexFormat::Uint16)` and
/// `draw_indexed(0..6, 0, 0..1)` instead of `draw(0..6, 0..1)`.
const SQUARE_CORNERS: [ColoredVertex; 4] = [SQUARE_SIX[0], SQUARE_SIX[1], SQUARE_SIX[2], SQUARE_SIX[5]];
const SQUARE_INDICES: [u16; 6] = [0, 1, 2, 0, 2, 3];
// ANCHOR_END: square

#[test]
fn pipeline_exercise_1_six_vertices_and_four_with_indices_draw_the_same_square() {
    let gpu = Gpu::headless(GpuNeeds::default()).expect("an adapter (lavapipe will do)");
    let six = draw(&gpu, 64, &SQUARE_SIX, None);
    let indexed = draw(&gpu, 64, &SQUARE_CORNERS, Some(&SQUARE_INDICES));
    // From −0.5 to 0.5 is half of the picture each way: 32 × 32 pixels,
    // each covered once (the shared diagonal leaves no gap and no overlap).
    assert_eq!(covered(&six), 32 * 32);
    assert_eq!(six, indexed, "the same square, byte for byte");
    // What the index buffer saves: 6 × 20 = 120 bytes against 4 × 20 + 6 × 2 = 92.
    let bytes = |vertices: usize, indices: usize| vertices * size_of::<ColoredVertex>() + indices * size_of::<u16>();
    assert_eq!((bytes(6, 0), bytes(4, 6)), (120, 92));
}

/// `triangle.wgsl` copied into a folder of its own, for a device to read
/// its shaders from (`Gpu::read_shaders_from`), as the window reads the
/// source tree: the tests edit the copy, never the file in `shaders/`.
fn scratch_shaders(name: &str) -> (std::path::PathBuf, String) {
    let root = std::env::temp_dir().join(format!("triangle-exercise-{name}-{}", std::process::id()));
    std::fs::create_dir_all(root.join("triangle")).unwrap();
    let original = shader!("triangle/triangle.wgsl").embedded.to_string();
    std::fs::write(root.join("triangle/triangle.wgsl"), &original).unwrap();
    (root, original)
}

/// `fs_main` as the chapter writes it: what both shader exercises replace.
const FS_MAIN: &str = "    return vec4<f32>(in.color, 1.0);";

/// Vertices and shaders, exercise 2: `fs_main`'s body, colouring each pixel by where it is.
const BY_POSITION: &str = "
// ANCHOR: by_position
    // In the fragment shader the position is in pixels, from (0, 0) at
    // the top-left corner of the picture: x to the right, y downwards.
    let size = vec2<f32>(1280.0, 720.0);
    return vec4<f32>(in.clip_position.xy / size, 0.0, 1.0);
// ANCHOR_END: by_position
";

/// The linear value an sRGB-encoded byte stands for.
fn decode(byte: u8) -> f32 {
    let c = f32::from(byte) / 255.0;
    if c <= 0.04045 { c / 12.92 } else { ((c + 0.055) / 1.055).powf(2.4) }
}

#[test]
fn vertices_exercise_2_clip_position_holds_pixel_coordinates() {
    let (root, original) = scratch_shaders("position");
    let gpu = Gpu::headless(GpuNeeds::default()).expect("an adapter (lavapipe will do)");
    gpu.read_shaders_from(Some(root.clone()));
    let target = Target { format: OFFSCREEN_FORMAT, width: 1280, height: 720, samples: 1 };
    let mut chapter = Triangle::new(&gpu, target, ()).unwrap();

    // Saving the edit while the window is open: the pipeline is rebuilt.
    assert!(original.contains(FS_MAIN), "triangle.wgsl changed: update FS_MAIN");
    std::fs::write(root.join("triangle/triangle.wgsl"), original.replacen(FS_MAIN, BY_POSITION, 1)).unwrap();
    assert_eq!(gpu.reload_shaders(&["triangle/triangle.wgsl"]), Ok(1));
    let picture = capture(&gpu, &mut chapter, target, (0.0, 0), Default::default()).unwrap();

    // Red is x / 1280 and green y / 720: read the pixel position back from
    // the colour near each corner. Clip (0, 0.7) is pixel (640, 108);
    // clip (−0.7, −0.6) is pixel (192, 576), since y turns over.
    let position = |x: u32, y: u32| {
        let p = picture.get_pixel(x, y).0;
        (decode(p[0]) * 1280.0, decode(p[1]) * 720.0)
    };
    for (x, y) in [(640, 112), (196, 574), (1084, 574), (640, 360)] {
        let (px, py) = position(x, y);
        // One step of an 8-bit sRGB byte is up to 11 pixels near the right edge.
        assert!(
            (px - x as f32 - 0.5).abs() < 8.0 && (py - y as f32 - 0.5).abs() < 8.0,
            "({x}, {y}) reads ({px}, {py})"
        );
    }
    // Green grows downwards: the bottom corners are greener than the top one.
    assert!(picture.get_pixel(640, 112)[1] < picture.get_pixel(196, 574)[1]);
    std::fs::remove_dir_all(root).unwrap();
}

// ANCHOR: typo
/// The pipeline and the draw, exercise 2: the typo, `retrun` for `return` in `fs_main`.
const TYPO: &str = "    retrun vec4<f32>(in.color, 1.0);";
// ANCHOR_END: typo

#[test]
fn pipeline_exercise_2_a_typo_is_reported_at_its_line_and_the_last_good_pipeline_draws_on() {
    let (root, original) = scratch_shaders("typo");
    let gpu = Gpu::headless(GpuNeeds::default()).expect("an adapter (lavapipe will do)");
    gpu.read_shaders_from(Some(root.clone()));
    let target = Target { format: OFFSCREEN_FORMAT, width: 64, height: 64, samples: 1 };
    let mut chapter = Triangle::new(&gpu, target, ()).unwrap();
    let good = capture(&gpu, &mut chapter, target, (0.0, 0), Default::default()).unwrap();

    let broken = original.replacen(FS_MAIN, TYPO, 1);
    std::fs::write(root.join("triangle/triangle.wgsl"), &broken).unwrap();
    let error = gpu.reload_shaders(&["triangle/triangle.wgsl"]).unwrap_err().0;
    eprintln!("{error}");
    // The overlay shows naga's message, with the file, line and column.
    // `retrun` could be a variable's name, about to be assigned to, so naga
    // stumbles one word later, at `vec4`: column 12.
    let line = broken.lines().position(|l| l == TYPO).unwrap() + 1;
    assert!(error.contains(&format!("triangle/triangle.wgsl:{line}:12")), "{error}");
    assert!(error.contains(r#"expected assignment or increment/decrement, found "vec4""#), "{error}");
    // The lesson quotes the message at that line and column.
    let page = common::book_figures::section_text("01-triangle");
    for quoted in
        [format!("triangle/triangle.wgsl:{line}:12"), format!("{line} │     retrun"), format!("Line {line}, but")]
    {
        assert!(page.contains(&quoted), "chapter 01's pages should quote `{quoted}`, as naga reports it");
    }
    // Meanwhile the window draws with the last pipeline that built.
    assert_eq!(capture(&gpu, &mut chapter, target, (0.0, 0), Default::default()).unwrap(), good);

    // The fix reloads.
    std::fs::write(root.join("triangle/triangle.wgsl"), &original).unwrap();
    assert_eq!(gpu.reload_shaders(&["triangle/triangle.wgsl"]), Ok(1));
    std::fs::remove_dir_all(root).unwrap();
}

// ANCHOR: centroid
/// Interpolation, exercise 1: the centroid, the mean of the three corners,
/// where each corner's weight is a third. A 97 × 102 picture puts the
/// centre of pixel (48, 59) exactly there: x = (48.5 / 97) · 2 − 1 = 0 and
/// y = 1 − (59.5 / 102) · 2 = −1/6.
const CENTROID_PICTURE: (u32, u32) = (97, 102);
const CENTROID_PIXEL: (u32, u32) = (48, 59);
/// Linear 1/3 in each channel, encoded as sRGB: 1.055 · (1/3)^(1/2.4) −
/// 0.055 = 0.6125 of 255. Averaging the corners' bytes would give 85.
const CENTROID_BYTE: u8 = 156;
// ANCHOR_END: centroid

#[test]
fn interpolation_exercise_1_the_centroid_is_a_third_of_each_corner_in_linear_light() {
    // The pixel's centre is the mean of the corners, in clip space.
    let (width, height) = CENTROID_PICTURE;
    let (x, y) = CENTROID_PIXEL;
    let centre = [(x as f32 + 0.5) / width as f32 * 2.0 - 1.0, 1.0 - (y as f32 + 0.5) / height as f32 * 2.0];
    let mean = |axis: usize| TRIANGLE.iter().map(|v| v.position[axis]).sum::<f32>() / 3.0;
    assert!((centre[0] - mean(0)).abs() < 1e-6 && (centre[1] - mean(1)).abs() < 1e-6, "{centre:?}");

    let gpu = Gpu::headless(GpuNeeds::default()).expect("an adapter (lavapipe will do)");
    let picture = draw_with(&gpu, SMOOTH, CENTROID_PICTURE, &TRIANGLE, None);
    let [r, g, b, _] = picture.get_pixel(x, y).0;
    eprintln!("the centroid's pixel: ({r}, {g}, {b})");
    assert!([r, g, b].iter().all(|&c| c.abs_diff(CENTROID_BYTE) <= 1), "({r}, {g}, {b})");
    // Averaging the corners' sRGB bytes is another, darker grey.
    let averaged = TRIANGLE.iter().map(|v| (v.color[0] * 255.0) as u32).sum::<u32>() / 3;
    assert_eq!(averaged, 85);
}

// ANCHOR: green_first
/// Interpolation, exercise 2: the same corners, the list rotated to start
/// with the green one. Still counter-clockwise; now the provoking vertex.
const GREEN_FIRST: [ColoredVertex; 3] = [TRIANGLE[1], TRIANGLE[2], TRIANGLE[0]];
// ANCHOR_END: green_first

#[test]
fn interpolation_exercise_2_the_first_vertex_gives_the_flat_colour() {
    let gpu = Gpu::headless(GpuNeeds::default()).expect("an adapter (lavapipe will do)");
    let draw = |entry_points, corners: &[ColoredVertex]| draw_with(&gpu, entry_points, (64, 64), corners, None);
    // Blended, the order of the list changes nothing but the rounding of
    // the weights' arithmetic: at most one step of a byte.
    let smooth = draw(SMOOTH, &TRIANGLE);
    let rotated = draw(SMOOTH, &GREEN_FIRST);
    let steps: Vec<u8> = smooth.as_raw().iter().zip(rotated.as_raw()).map(|(a, b)| a.abs_diff(*b)).collect();
    let differing = steps.iter().filter(|&&s| s > 0).count();
    eprintln!("blended, rotated: {differing} of {} bytes differ, by at most {:?}", steps.len(), steps.iter().max());
    assert!(steps.iter().all(|&s| s <= 1), "the blend depends on the corners, not their order");
    // Flat, every covered pixel takes the first vertex's colour: green now.
    let flat = draw(FLAT, &GREEN_FIRST);
    assert_eq!(covered(&flat), covered(&smooth), "still counter-clockwise, so still drawn");
    let colours: std::collections::BTreeSet<[u8; 4]> =
        flat.pixels().map(|p| p.0).filter(|&p| p != [0, 0, 0, 255]).collect();
    assert_eq!(colours.into_iter().collect::<Vec<_>>(), [[0, 255, 0, 255]]);
}
