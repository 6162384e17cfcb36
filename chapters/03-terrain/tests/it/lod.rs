//! The level of detail, checked on real pictures of the default terrain:
//! no hole opens between levels wherever the camera is, nor where a coarse
//! patch meets a finer one seen through a long lens, moving across a
//! level's boundary changes no pixel by much and moves the ground no more
//! than the morph slides it (nothing pops), and the ground a walker stands
//! on is the ground drawn.

use common::Camera;
use common::glam::Vec3;
use common::headless::{OFFSCREEN_FORMAT, read_floats, read_texture};
use common::{Target, image, wgpu};
use terrain::culling::Frustum;
use terrain::ground::EYE_HEIGHT;
use terrain::heightfield::HeightField;
use terrain::quadtree::PATCH_QUADS;
use terrain::{Detail, LodRanges, Patch, Quadtree, TerrainRenderer};

use crate::{default_terrain, draw_terrain, edited_terrain_shader, pictures, terrain_shader_with};

/// A clear colour no ground has: every ground colour has some red.
const NO_GROUND: wgpu::Color = wgpu::Color { r: 0.0, g: 0.0, b: 1.0, a: 1.0 };

fn shaded() -> common::ShaderFile {
    common::shader!("terrain/terrain.wgsl")
}

/// `terrain.wgsl` with the morph switched off: each level drawn as it is
/// until the quadtree swaps it for the next.
fn unmorphed() -> common::ShaderFile {
    edited_terrain_shader("return clamp((distance - start) / (end - start), 0.0, 1.0);", "return 0.0;")
}

/// A camera over (x, z), `above` metres over the ground there, pitched down
/// by `pitch` degrees, facing `yaw` degrees.
fn looking_down(field: &HeightField, (x, z): (f32, f32), above: f32, yaw: f32, pitch: f32, aspect: f32) -> Camera {
    let mut camera = Camera::looking_at(Vec3::ZERO, Vec3::NEG_Z, aspect);
    camera.position = Vec3::new(x, field.height_at(x, z) + above, z);
    (camera.yaw, camera.pitch) = (yaw.to_radians(), -pitch.to_radians());
    (camera.near, camera.far) = (0.5, 6000.0);
    camera
}

/// Pixels of `picture` in the clear colour: where no ground was drawn.
fn holes(picture: &image::RgbaImage) -> usize {
    picture.pixels().filter(|p| p[0] == 0 && p[1] == 0 && p[2] == 255).count()
}

/// Cameras whose pictures cross one or several levels' boundaries, all
/// looking at ground only (no sky, no edge of the map in view).
fn straddling_cameras(field: &HeightField, aspect: f32) -> Vec<Camera> {
    let mut cameras = Vec::new();
    // The picture's top edge is 30° above its middle: pitched down by more
    // than 40°, it sees no sky.
    for (i, (above, pitch)) in
        [(30.0, 45.0), (120.0, 50.0), (250.0, 60.0), (500.0, 70.0), (900.0, 89.0)].into_iter().enumerate()
    {
        for yaw in [0.0, 70.0, 200.0] {
            let at = (1200.0 + 400.0 * i as f32, 2600.0 - 250.0 * i as f32);
            cameras.push(looking_down(field, at, above, yaw, pitch, aspect));
        }
    }
    cameras
}

#[test]
fn no_hole_opens_between_levels_and_one_does_without_the_morph() {
    let (_, data) = default_terrain();
    let target = Target { format: OFFSCREEN_FORMAT, width: 800, height: 450, samples: 1 };
    let (mut without_morph, mut cameras_with_holes) = (0, 0);
    for camera in straddling_cameras(&data.field, target.aspect()) {
        let detail = Detail::lod(target.height);
        let picture =
            read_texture(default_terrain().0, &draw_terrain(&shaded(), target, NO_GROUND, (&camera, &camera), detail))
                .unwrap();
        assert_eq!(holes(&picture), 0, "a hole seen from {camera:?}");
        let broken = read_texture(
            default_terrain().0,
            &draw_terrain(&unmorphed(), target, NO_GROUND, (&camera, &camera), detail),
        )
        .unwrap();
        without_morph += holes(&broken);
        cameras_with_holes += usize::from(holes(&broken) > 0);
    }
    eprintln!("without the morph: {without_morph} holes, from {cameras_with_holes} of the cameras");
    assert!(without_morph > 0, "the check can fail: cracks open without the morph");
}

#[test]
fn a_large_picture_has_no_hole_either() {
    let (_, data) = default_terrain();
    let target = Target { format: OFFSCREEN_FORMAT, width: 1920, height: 1080, samples: 1 };
    let camera = looking_down(&data.field, (2000.0, 2200.0), 250.0, 30.0, 50.0, target.aspect());
    let picture = read_texture(
        default_terrain().0,
        &draw_terrain(&shaded(), target, NO_GROUND, (&camera, &camera), Detail::lod(1080)),
    )
    .unwrap();
    assert_eq!(holes(&picture), 0);
}

/// A coarse patch's vertex that a finer patch shares an edge with, at one
/// of the coarse level's odd places: a vertex the coarse patch would slide
/// along that edge if it morphed, which the finer patch does not have.
struct SharedEdgeVertex {
    /// Where it stands, unmorphed.
    world: Vec3,
    /// Its distance from the eye over where its level's morph starts: under
    /// 1, it must not have begun to morph (`morph_start` is chosen so).
    towards_morph: f32,
    /// How far its height stands off the straight line between its
    /// neighbours along the edge, which the finer patch draws: the crack a
    /// morph there would open at its full extent, metres.
    stands_off: f32,
}

/// Every coarse patch's odd vertex on an edge it shares with a patch one
/// level finer, among `patches` chosen for an eye at `eye` with `ranges`.
fn shared_edge_vertices(
    field: &HeightField,
    patches: &[Patch],
    eye: Vec3,
    ranges: &LodRanges,
) -> Vec<SharedEdgeVertex> {
    // The level drawn over each cell of one sample, 255 where none is.
    let size = (field.size - 1) as usize;
    let mut level = vec![255u8; size * size];
    for p in patches {
        let side = (PATCH_QUADS << p.level) as usize;
        for z in p.origin[1] as usize..p.origin[1] as usize + side {
            let row = z * size + p.origin[0] as usize;
            level[row..row + side].fill(p.level as u8);
        }
    }
    let level_at = |x: i64, z: i64| {
        let inside = (0..size as i64).contains(&x) && (0..size as i64).contains(&z);
        if inside { level[z as usize * size + x as usize] } else { 255 }
    };
    let spacing = field.settings.spacing;
    let mut found = Vec::new();
    for p in patches.iter().filter(|p| p.level > 0) {
        let (step, side) = (1i64 << p.level, i64::from(PATCH_QUADS << p.level));
        let (x0, z0) = (i64::from(p.origin[0]), i64::from(p.origin[1]));
        // Each edge: where it starts, which way it runs, and a cell just outside.
        let edges = [
            ((x0, z0), (1, 0), (0, -1)),
            ((x0, z0 + side), (1, 0), (0, 0)),
            ((x0, z0), (0, 1), (-1, 0)),
            ((x0 + side, z0), (0, 1), (0, 0)),
        ];
        for ((sx, sz), (dx, dz), (ox, oz)) in edges {
            for k in (step..side).step_by(2 * step as usize) {
                let (x, z) = (sx + dx * k, sz + dz * k);
                if u32::from(level_at(x + ox, z + oz)) + 1 != p.level {
                    continue;
                }
                let height = field.height(x, z);
                let world = Vec3::new(x as f32 * spacing, height, z as f32 * spacing);
                let start = ranges.morph_start * ranges.range(p.level);
                let straight =
                    0.5 * (field.height(x - dx * step, z - dz * step) + field.height(x + dx * step, z + dz * step));
                let stands_off = (height - straight).abs();
                found.push(SharedEdgeVertex { world, towards_morph: world.distance(eye) / start, stands_off });
            }
        }
    }
    found
}

#[test]
fn no_hole_opens_where_a_coarse_patch_meets_a_finer_one() {
    // A crack between levels is a sliver a few centimetres wide: a whole
    // picture finds it only where it happens to cover a pixel's centre (a
    // morph started a tenth of a range early left the fifteen cameras above
    // at 800 × 450 without a hole, and showed one pixel of sky in a
    // 1920 × 1080 picture). Where cracks can open is known: along the edges
    // where a coarse patch meets a finer one, at the coarse patch's odd
    // vertices, and first where such a vertex is nearest its own morph's
    // start. So look there, through a long lens from the eye the patches
    // were chosen for: 64 × 64 pixels 0.1° across, about a centimetre a
    // pixel where the levels meet.
    let (gpu, data) = default_terrain();
    let field = &data.field;
    let renderer = TerrainRenderer::new(gpu, data.clone());
    // The large picture's eye and the fifteen cameras', with the ranges of a
    // 1920 × 1080 window and of an 800 × 450 one (the floor under r_0).
    let mut eyes = straddling_cameras(field, 16.0 / 9.0);
    eyes.push(looking_down(field, (2000.0, 2200.0), 250.0, 30.0, 50.0, 16.0 / 9.0));
    let target = Target { format: OFFSCREEN_FORMAT, width: 64, height: 64, samples: 1 };
    let (mut nearest, mut looked_at, mut holes_early) = (0.0f32, 0, Vec::new());
    for detail in [Detail::lod(1080), Detail::lod(450)] {
        let mut views = Vec::new();
        for eye in &eyes {
            let ranges = renderer.ranges(eye, detail);
            let mut patches = Vec::new();
            let frustum = Frustum::from_view_projection(eye.view_projection());
            data.quadtree.select(&frustum, eye.position, &ranges, &mut patches);
            let mut vertices = shared_edge_vertices(field, &patches, eye.position, &ranges);
            // The argument of `morph_start`, on the CPU: no such vertex has
            // begun to morph.
            nearest = vertices.iter().map(|v| v.towards_morph).fold(nearest, f32::max);
            // Those that would open a crack worth seeing, well inside the
            // eye's picture (a long lens aimed near its edge would see
            // patches culled), nearest their morph's start first.
            vertices.retain(|v| {
                let on_picture = eye.view_projection().project_point3(v.world);
                v.stands_off >= 0.3 && on_picture.x.abs() < 0.9 && on_picture.y.abs() < 0.9
            });
            vertices.sort_by(|a, b| b.towards_morph.total_cmp(&a.towards_morph));
            views.extend(vertices.iter().take(2).map(|v| {
                let mut lens = Camera::looking_at(eye.position, v.world, 1.0);
                (lens.fov_y, lens.near, lens.far) = (0.1f32.to_radians(), eye.near, eye.far);
                (lens, *eye)
            }));
        }
        let holes_seen = |shader: &common::ShaderFile| -> Vec<usize> {
            pictures(shader, target, NO_GROUND, &views, detail, |gpu, texture| {
                holes(&read_texture(gpu, texture).unwrap())
            })
        };
        let morphed = holes_seen(&shaded());
        assert!(morphed.iter().all(|&h| h == 0), "holes where levels meet: {morphed:?}");
        looked_at += views.len();
        // The check can fail: the same places with the morph started a
        // tenth of a range early.
        holes_early
            .extend(holes_seen(&edited_terrain_shader(MORPH_START, "    let start = (globals.lod.y - 0.1) * end;")));
    }
    eprintln!(
        "the coarse vertex beside a finer patch nearest its morph's start is at {nearest:.3} of it; {looked_at} \
         looked at, no hole; with the morph started a tenth of a range early, holes {holes_early:?}"
    );
    assert!(nearest < 1.0, "a coarse vertex beside a finer patch morphs ({nearest} of its start)");
    assert!(holes_early.iter().sum::<usize>() > 0, "the check can fail: a morph started early opens cracks");
}

/// The line of `terrain.wgsl` that places the start of a level's morph.
const MORPH_START: &str = "    let start = globals.lod.y * end;";

/// The largest change of any colour channel of any pixel between two pictures.
fn largest_change(a: &image::RgbaImage, b: &image::RgbaImage) -> u8 {
    a.as_raw().iter().zip(b.as_raw()).map(|(x, y)| x.abs_diff(*y)).max().unwrap_or(0)
}

#[test]
fn walking_across_a_boundary_changes_no_pixel_much() {
    // The picture is taken from one fixed camera; only the eye the patches
    // are chosen and morphed for moves, a metre a step, along the camera's
    // line of sight up to it (so its frustum always holds the camera's),
    // and every change between steps is the level of detail's, none the
    // camera's.
    let (_, data) = default_terrain();
    let target = Target { format: OFFSCREEN_FORMAT, width: 400, height: 225, samples: 1 };
    let camera = looking_down(&data.field, (2000.0, 2200.0), 120.0, 0.0, 60.0, target.aspect());
    let detail = Detail::lod(target.height);
    let walk = |shader: &common::ShaderFile| {
        let mut pictures = Vec::new();
        for step in 0..80 {
            let mut eye = camera;
            eye.position -= camera.forward() * (80 - step) as f32;
            pictures.push(
                read_texture(default_terrain().0, &draw_terrain(shader, target, NO_GROUND, (&camera, &eye), detail))
                    .unwrap(),
            );
        }
        pictures.windows(2).map(|pair| largest_change(&pair[0], &pair[1])).max().unwrap_or(0)
    };
    let (smooth, popping) = (walk(&shaded()), walk(&unmorphed()));
    eprintln!("the largest change of a pixel between two steps: {smooth} with the morph, {popping} without");
    // Measured on lavapipe: 1 level with the morph, 204 without (a crack
    // opening onto the clear colour). The bound leaves other rasterisers
    // room for a rounding or two.
    assert!(smooth <= 4, "{smooth}");
    assert!(popping > 10 * smooth.max(1), "{popping}");
}

/// A control for the pop test below: the slide of `terrain.wgsl` with its
/// morph factor snapped to 0 or 1, so that vertices jump half-way through
/// their morph instead of sliding. Both sides of an edge jump together, so
/// nothing cracks: it pops. (The edits leave the morph factor's own line
/// alone, wherever a fault may be.)
const SLIDE: [&str; 2] =
    ["        sample -= odd * f32(step) * k;", "        y = mix(height, height_at(vec2<u32>(neighbour)), k);"];
const SNAPPED_SLIDE: [&str; 2] = [
    "        sample -= odd * f32(step) * round(k);",
    "        y = mix(height, height_at(vec2<u32>(neighbour)), round(k));",
];

/// The fragment shader's shaded return, and a probe of the geometry in its
/// place: the world position of the ground each pixel shows.
const SHADED_RETURN: &str = "            return vec4<f32>(shaded, 1.0);";
const WORLD_POSITION_RETURN: &str = "            return vec4<f32>(in.world_position, 1.0);";

#[test]
fn walking_across_a_boundary_moves_the_ground_only_as_far_as_the_morph_slides() {
    // Colour cannot see a pop: the ground is shaded from the height and
    // normal maps, so a vertex that jumps changes almost no pixel's colour.
    // Geometry can. The same fixed camera and moving eye as the walk above,
    // at 160 × 90, each pixel holding the world position of the ground it
    // shows; between two steps, how far along its ray that ground moved.
    let (gpu, data) = default_terrain();
    let target = Target { format: wgpu::TextureFormat::Rgba32Float, width: 160, height: 90, samples: 1 };
    let camera = looking_down(&data.field, (2000.0, 2200.0), 120.0, 0.0, 60.0, target.aspect());
    let (steps, step_length) = (80, 1.0f32);
    let views: Vec<(Camera, Camera)> = (0..steps)
        .map(|step| {
            let mut eye = camera;
            eye.position -= camera.forward() * (steps - step) as f32 * step_length;
            (camera, eye)
        })
        .collect();
    let largest_move = |slide: [&str; 2]| {
        let probe =
            terrain_shader_with(&[(SLIDE[0], slide[0]), (SLIDE[1], slide[1]), (SHADED_RETURN, WORLD_POSITION_RETURN)]);
        let along_rays: Vec<Vec<f32>> =
            pictures(&probe, target, NO_GROUND, &views, Detail::lod(target.height), |gpu, texture| {
                read_floats(gpu, texture).unwrap()
            })
            .iter()
            .map(|picture| picture.iter().map(|p| Vec3::new(p[0], p[1], p[2]).distance(camera.position)).collect())
            .collect();
        along_rays
            .windows(2)
            .map(|pair| pair[0].iter().zip(&pair[1]).map(|(a, b)| (a - b).abs()).fold(0.0, f32::max))
            .fold(0.0, f32::max)
    };
    let (sliding, jumping) = (largest_move(SLIDE), largest_move(SNAPPED_SLIDE));
    // The second way of knowing, from the CPU's ranges: a step moves the
    // eye `step_length`, so no vertex's distance from it changes by more,
    // and its morph factor by no more than `step_length` over its level's
    // morph zone, the last (1 − morph_start) of its range; level 0's zone
    // is the shortest. A sliding vertex moves by that share of its whole
    // slide in a step, where a snapped one moves its whole slide at once:
    // the largest move of the ground with the morph is at most that share
    // of the largest jump without it (twice that, for the rays' angles
    // against the ground and the rasteriser's rounding).
    let ranges = TerrainRenderer::new(gpu, data.clone()).ranges(&camera, Detail::lod(target.height));
    let shortest_zone = (1.0 - ranges.morph_start) * ranges.range(0);
    let allowed = 2.0 * jumping * step_length / shortest_zone;
    eprintln!(
        "the ground along a pixel's ray moved at most {sliding:.3} m in a step with the morph (allowed \
         {allowed:.3} m: the shortest morph zone is {shortest_zone:.1} m), {jumping:.3} m with it snapped"
    );
    assert!(jumping > 0.1, "the walk crosses morphing ground: snapped, a vertex jumps ({jumping} m)");
    assert!(sliding <= allowed, "the ground jumps {sliding} m in a step: it pops (allowed {allowed} m)");
}

#[test]
fn the_walker_stands_on_the_ground_drawn() {
    let (gpu, data) = default_terrain();
    let field = &data.field;
    let renderer = TerrainRenderer::new(gpu, data.clone());
    // The drawn ground's height under the eye, from a picture looking
    // straight down, each pixel showing its world position's height.
    let world_height = edited_terrain_shader(
        "            return vec4<f32>(shaded, 1.0);",
        "            return vec4<f32>(in.world_position, 1.0);",
    );
    let target = Target { format: wgpu::TextureFormat::Rgba32Float, width: 9, height: 9, samples: 1 };
    let mut worst = 0.0f32;
    for (x, z) in [(1900.0, 2300.0), (1925.3, 2317.8), (812.6, 3120.1), (3010.0, 1544.4), (2222.2, 600.9)] {
        let mut eye = looking_down(field, (x, z), EYE_HEIGHT, 0.0, 89.99, 1.0);
        eye.near = 0.1;
        // A 1920 × 1080 picture's ranges, the nearest any window uses.
        let ranges = renderer.ranges(&eye, Detail::lod(1080));
        assert_eq!(Quadtree::level_at(&ranges, EYE_HEIGHT * 2.0), 0);
        assert_eq!(ranges.morph(0, EYE_HEIGHT * 2.0), 0.0, "the ground at the walker's feet never morphs");
        let texture = draw_terrain(&world_height, target, NO_GROUND, (&eye, &eye), Detail::lod(1080));
        let centre = read_floats(gpu, &texture).unwrap()[4 * 9 + 4];
        let drawn = centre[1];
        // Walking puts the eye over the field's bilinear height; the mesh
        // draws two flat triangles per cell, which differ from the bilinear
        // surface by at most a quarter of the cell's twist.
        let (gx, gz) = (centre[0].floor() as i64, centre[2].floor() as i64);
        let twist = (field.height(gx, gz) - field.height(gx + 1, gz) - field.height(gx, gz + 1)
            + field.height(gx + 1, gz + 1))
        .abs();
        let off = (drawn - field.height_at(centre[0], centre[2])).abs();
        eprintln!(
            "({x}, {z}): drawn {drawn:.3} m, walked {:.3} m, twist {twist:.3} m",
            field.height_at(centre[0], centre[2])
        );
        assert!(off <= twist / 4.0 + 1e-3, "{off} m off at ({x}, {z}), twist {twist}");
        worst = worst.max(off);
    }
    eprintln!("the walker is at most {worst:.3} m off the drawn ground");
}

#[test]
fn at_the_edge_under_the_ground_and_at_one_pixel_nothing_breaks() {
    let (gpu, data) = default_terrain();
    let field = &data.field;
    // Straight down over the map's west edge, facing north: the edge runs
    // down the middle of the picture, the map to its right (east, +x).
    let target = Target { format: OFFSCREEN_FORMAT, width: 400, height: 400, samples: 1 };
    let mut camera = looking_down(field, (0.0, 2000.0), 300.0, 0.0, 89.99, 1.0);
    camera.position.x = 0.0;
    let picture =
        read_texture(gpu, &draw_terrain(&shaded(), target, NO_GROUND, (&camera, &camera), Detail::lod(400))).unwrap();
    let east_holes =
        picture.enumerate_pixels().filter(|(x, _, p)| *x > 202 && p[0] == 0 && p[1] == 0 && p[2] == 255).count();
    let west_ground = picture.enumerate_pixels().filter(|(x, _, p)| *x < 198 && p[2] != 255).count();
    assert_eq!((east_holes, west_ground), (0, 0), "the map is drawn east of its edge, and only there");
    // Under the ground, looking up: the ground's underside is culled, so
    // nothing but the clear colour, and no panic.
    let mut under = looking_down(field, (2000.0, 2000.0), -50.0, 0.0, -60.0, 1.0);
    under.far = 3000.0;
    let picture =
        read_texture(gpu, &draw_terrain(&shaded(), target, NO_GROUND, (&under, &under), Detail::lod(400))).unwrap();
    assert_eq!(holes(&picture), 400 * 400);
    // One pixel.
    let one = Target { format: OFFSCREEN_FORMAT, width: 1, height: 1, samples: 1 };
    let camera = looking_down(field, (2000.0, 2000.0), 100.0, 0.0, 60.0, 1.0);
    let picture =
        read_texture(gpu, &draw_terrain(&shaded(), one, NO_GROUND, (&camera, &camera), Detail::lod(1))).unwrap();
    assert_eq!(holes(&picture), 0);
}

#[test]
fn the_page_quotes_the_levels_as_they_are() {
    let (gpu, data) = default_terrain();
    let page = common::book_figures::section_text("03-terrain");
    // Compared with lines joined: a figure may fall across a line break.
    let flat = |text: &str| text.split_whitespace().collect::<Vec<_>>().join(" ");
    let page = flat(&page);
    let says = |text: &str| assert!(page.contains(&flat(text)), "page 03 should say `{text}`");
    let renderer = TerrainRenderer::new(gpu, data.clone());
    let reach = data.quadtree.node_reach();
    says(&format!("On the default map D is {reach:.0} m"));
    says(&format!("r_0 is never less than {:.0} m", terrain::LodRanges::nearest_first(reach)));
    let camera = terrain::start_camera(&data.field, 16.0 / 9.0);
    let from_pixels = |height: u32| height as f32 / (Detail::CELL_PIXELS * 2.0 * (camera.fov_y / 2.0).tan());
    says(&format!(
        "at 1280 × 720 the 4-pixel rule alone would give {:.0} m, at 800 × 450 only {:.0} m",
        from_pixels(720),
        from_pixels(450)
    ));
    says(&format!("r_0: {:.0} m at 1920 × 1080", from_pixels(1080)));
    // Figures the page reads from the bench table, which must hold what
    // the code gives.
    let bench = flat(
        &std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../../book/src/bench/terrain.md"))
            .expect("the terrain's bench table"),
    );
    let table_says = |text: &str| assert!(bench.contains(&flat(text)), "bench/terrain.md should say `{text}`");
    // The maps, and the vertex buffer they replace.
    let maps_mb = data.maps.gpu_bytes() as f64 / 1e6 - 0.0125;
    table_says(&format!("{maps_mb:.1} MB of maps"));
    says("{{#figure [../bench/terrain.md | - default: setup * # MB of maps]}} MB for the whole world");
    let chunks = data.chunk_bounds.len() as u64;
    let thousands = |n: u64| common::book_figures::thousands(n as f64);
    says(&format!(
        "took {} chunks × 4,225 vertices × 8 bytes = {} bytes",
        thousands(chunks),
        thousands(chunks * 65 * 65 * 8)
    ));
    // The default view at 1280 × 720, with levels and at full detail.
    let mut viewpoint = renderer.viewpoint(&gpu.device);
    let aim = |viewpoint: &mut terrain::Viewpoint, detail| {
        renderer.aim(gpu, viewpoint, &camera, detail, terrain::Sun::AFTERNOON, terrain::KEEP_ALL);
        viewpoint.triangles()
    };
    let (lod, full) = (aim(&mut viewpoint, Detail::lod(720)), aim(&mut viewpoint, Detail::full(720)));
    says(&format!("{} patches, {} triangles in the default view at 1280 × 720", lod / 2048, thousands(lod)));
    says(&format!("At full detail the same view draws {} chunks,", thousands(full / 8192)));
    // The triangles at full detail and their ratio the page reads from the
    // bench's count of the draws.
    table_says(&format!("| default | terrain | 1 | {} |", thousands(lod)));
    table_says(&format!("| full-detail | terrain | 1 | {} |", thousands(full)));
}
