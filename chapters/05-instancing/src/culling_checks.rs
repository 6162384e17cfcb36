//! The chapter's rocks, culled: by chunk on the CPU, the rocks the chapter
//! says it drew against a count made here from the scatter, chapter 03's
//! chunk boxes and the camera's frustum; on the GPU, the compute pass's
//! lists against a recount made here by projecting each rock's sphere,
//! rocks placed by hand against levels worked out by hand, the fall back to
//! the CPU where the device lacks compute shaders, and the triangles the
//! default view draws. On the device the solutions share (`test_gpu`).

use crate::solutions::test_gpu;
use crate::{
    Culling, Grading, InstancingChapter, MarsPlain, Picture, RockCulling, RockInstance, RockSource, SEED, Setup,
    chunk_of, rock_levels, rock_mesh, rocks_on_map, scatter,
};
use common::book_figures::thousands;
use common::glam::{Vec3, Vec4};
use common::headless::{OFFSCREEN_FORMAT, capture};
use common::wgpu::util::DeviceExt as _;
use common::{Camera, Chapter, PassTimer, Target, wgpu};
use terrain::chunks::Aabb;
use terrain::culling::Frustum;
use terrain::heightfield::{CHUNK_QUADS, TerrainSettings};

/// `chapter`'s picture of `view`, the view selected first.
fn picture<C: Chapter>(gpu: &common::Gpu, chapter: &mut C, target: Target, view: &str) -> common::image::RgbaImage {
    let view = common::chapter::view_index::<C>(view).unwrap();
    chapter.select_view(view);
    capture(gpu, chapter, target, (0.0, view), Default::default()).unwrap()
}

#[test]
fn the_cpu_culling_view_draws_the_rocks_of_the_chunks_in_view_and_says_how_many() {
    let gpu = test_gpu();
    let target = Target { format: OFFSCREEN_FORMAT, width: 160, height: 90, samples: 1 };
    let mut chapter: InstancingChapter = common::chapter::create(gpu, target, &Default::default()).unwrap();
    let culled = picture(gpu, &mut chapter, target, "cpu-culling");
    let calls = chapter.draw_calls;
    let drawn = calls.rocks_drawn.expect("the CPU counts as it draws");

    // The count, made here: every rock of the scatter falls in the chunk
    // under it; a chunk's rocks are drawn when its box, grown by the most a
    // rock can reach from where it stands, is in the frustum.
    let field = chapter.plain.terrain.field();
    let bounds = chapter.plain.terrain.chunk_bounds();
    let rocks = scatter(field, rocks_on_map(&field.settings), 5);
    let radius = rock_mesh(5).vertices.iter().map(|v| Vec3::from(v.position).length()).fold(0.0, f32::max);
    let reach = radius * rocks.iter().flat_map(|r| r.scale).fold(0.0, f32::max);
    let frustum = Frustum::from_view_projection(chapter.camera.view_projection());
    let kept: Vec<bool> = bounds
        .iter()
        .map(|b| frustum.intersects(&Aabb { min: b.min - Vec3::splat(reach), max: b.max + Vec3::splat(reach) }))
        .collect();
    let n = field.settings.chunks_per_side as usize;
    let chunk_size = CHUNK_QUADS as f32 * field.settings.spacing;
    let cell = |v: f32| ((v / chunk_size) as usize).min(n - 1);
    let in_view = rocks.iter().filter(|r| kept[cell(r.position[2]) * n + cell(r.position[0])]).count() as u32;
    let chunks_in_view = kept.iter().filter(|&&k| k).count();
    eprintln!(
        "{in_view} of {} rocks in {chunks_in_view} of {} chunks; the chapter drew {} in {} calls",
        rocks.len(),
        kept.len(),
        drawn.rocks,
        calls.rocks
    );
    assert_eq!(rocks.len(), 1_000_000);
    assert_eq!(drawn.rocks, in_view);
    // Every rock drawn is the full rock, 20 triangles.
    assert_eq!((drawn.triangles, drawn.levels), (20 * u64::from(in_view), None));
    assert!(in_view < 400_000, "most of the map is out of view");
    // And the bench's line says so.
    let line = chapter.stats(gpu);
    let said = format!("{} of 1,000,000 rocks drawn", thousands(in_view.into()));
    let triangles = format!("{} rock triangles", thousands(20.0 * f64::from(in_view)));
    assert!(line.contains(&said) && line.contains(&triangles), "`{line}` should say `{said}` and `{triangles}`");

    // The chunk lesson quotes the view's figures.
    let page = common::book_figures::section_text("05-instancing");
    for figure in [
        format!("**{} of the 1,000,000 rocks**", thousands(in_view.into())),
        format!("**in {} calls**", calls.rocks),
        format!("{} of the 4,096\ngroups", thousands(calls.rock_groups.into())),
    ] {
        assert!(page.contains(&figure), "chapter 05's pages should say `{figure}`");
    }

    // The same runs, drawn by one indirect call, are the same picture.
    let indirect = picture(gpu, &mut chapter, target, "multi-draw");
    assert_eq!(chapter.draw_calls.rocks_drawn.map(|d| d.rocks), Some(in_view));
    if gpu.device.features().contains(wgpu::Features::INDIRECT_FIRST_INSTANCE) {
        assert_eq!(chapter.draw_calls.rocks, 1);
    }
    assert_eq!(indirect, culled, "one indirect call draws what the runs drew");
}

/// Where a rock lies against the picture, worked out on the CPU by
/// projecting its sphere with the camera's matrices.
struct Projected {
    /// What the test expects: the level the rock is drawn at, or `None`.
    level: Option<usize>,
    /// Whether a rock right at a threshold could have gone either way
    /// (see `project`).
    borderline: bool,
}

/// How near, in pixels, a sphere's outline may come to the picture's edge
/// before the recount calls its answer borderline: a pixel, the least any
/// picture can show.
const EDGE_TOLERANCE_PIXELS: f32 = 1.0;

/// How near, as a fraction, a rock's size may come to a threshold before
/// the recount calls its level borderline (float rounding).
const SIZE_TOLERANCE: f32 = 0.0001;

/// Grades the sphere (`centre`, `radius`) seen by `camera` in a picture
/// `size` pixels wide and high, by projecting its outline, without the
/// compute shader's plane test or its formula for the size.
///
/// In view: across and up, the outline's innermost point, projected, lies
/// within the picture, and the sphere reaches between the near and far
/// planes. Seen from the eye in the plane through the view axis and one
/// axis of the picture, the centre lies at an angle α off the view axis,
/// at a distance ρ, and the outline reaches β = asin(r / ρ) nearer the
/// axis: its innermost point is at α − β, and falls tan(α − β) / tan(half
/// the field of view) of the way from the picture's middle to its edge. A
/// rock whose outline comes within `EDGE_TOLERANCE_PIXELS` of the edge is
/// borderline.
///
/// Size: the pixels between the projections of two points at the rock's
/// distance straight ahead, one a radius above the other, twice over.
/// A rock within `SIZE_TOLERANCE` of a threshold is borderline (rounding).
fn project(camera: &Camera, (width, height): (f32, f32), centre: Vec3, radius: f32, grading: Grading) -> Projected {
    let view_projection = camera.view_projection();
    let seen = camera.view().transform_point3(centre);
    let depth = -seen.z;
    let half_fov_y = camera.fov_y / 2.0;
    let half_fov_x = (camera.aspect * half_fov_y.tan()).atan();
    // Past the edge by this many pixels (negative: inside), along one axis
    // of the picture `pixels` long, whose half field of view is `half_fov`.
    let past_edge = |along: f32, half_fov: f32, pixels: f32| {
        let innermost = (along.abs() / depth).atan() - (radius / along.hypot(depth)).asin();
        (innermost.tan() / half_fov.tan() - 1.0) * pixels / 2.0
    };
    // A centre level with the eye or behind it has no outline ahead to
    // project: such a rock is out, or so near the eye that it is borderline.
    let ahead_of_the_eye = depth > radius;
    let beside_the_eye = centre.distance(camera.position) < 3.0 * radius + camera.near;
    let (across, up) = (past_edge(seen.x, half_fov_x, width), past_edge(seen.y, half_fov_y, height));
    let between_planes = depth + radius >= camera.near && depth - radius <= camera.far;
    let in_view = ahead_of_the_eye && between_planes && across <= 0.0 && up <= 0.0;

    let ahead = camera.position + camera.forward() * centre.distance(camera.position);
    let up_axis = camera.right().cross(camera.forward());
    let (a, b) = (view_projection.project_point3(ahead), view_projection.project_point3(ahead + up_axis * radius));
    let pixels = (b.y - a.y).abs() * height;
    let level = |pixels: f32| [grading.full, grading.coarse, grading.drawn].iter().position(|&from| pixels >= from);
    // Only a rock big enough to be drawn can be borderline at an edge or a plane.
    let drawn = level(pixels * (1.0 + SIZE_TOLERANCE)).is_some();
    let at_an_edge = |past: f32| drawn && ahead_of_the_eye && past.abs() < EDGE_TOLERANCE_PIXELS;
    let at_a_plane =
        drawn && ((depth + radius - camera.near).abs() < 0.01 || (depth - radius - camera.far).abs() < 0.01);
    let borderline = beside_the_eye
        || at_a_plane
        || (at_an_edge(across) && up <= EDGE_TOLERANCE_PIXELS)
        || (at_an_edge(up) && across <= EDGE_TOLERANCE_PIXELS)
        || level(pixels * (1.0 - SIZE_TOLERANCE)) != level(pixels * (1.0 + SIZE_TOLERANCE));

    Projected { level: if in_view { level(pixels) } else { None }, borderline }
}

#[test]
fn the_gpu_keeps_and_grades_the_rocks_a_projection_of_their_spheres_keeps_and_grades() {
    let gpu = test_gpu();
    let target = Target { format: OFFSCREEN_FORMAT, width: 640, height: 360, samples: 1 };
    let mut chapter: InstancingChapter = common::chapter::create(gpu, target, &Default::default()).unwrap();
    picture(gpu, &mut chapter, target, "default");
    let lists = chapter.plain.rock_lists(chapter.viewpoint()).expect("lavapipe culls on the GPU");
    let kept = lists.lists_now(gpu);
    let draws = lists.draws_now(gpu);

    // The rocks as the buffer holds them: the scatter, each chunk's rocks
    // in the order it made them, the chunks in the plain's group order
    // (`group_by_chunk`'s promise, which its own test checks).
    let field = chapter.plain.terrain.field();
    let scattered = scatter(field, rocks_on_map(&field.settings), SEED);
    let mut by_chunk = vec![Vec::new(); chapter.plain.terrain.chunk_bounds().len()];
    for rock in &scattered {
        by_chunk[chunk_of(&field.settings, rock.position[0], rock.position[2]) as usize].push(*rock);
    }
    let rocks: Vec<RockInstance> =
        chapter.plain.rock_field().groups.iter().flat_map(|g| by_chunk[g.chunk as usize].clone()).collect();
    assert_eq!(rocks.len(), 1_000_000);

    // Each rock's sphere: around all three of its meshes, centred on the
    // middle of the full mesh's box, turned and stretched with the rock.
    let levels = rock_levels(SEED);
    let corners = levels[0].vertices.iter().map(|v| Vec3::from(v.position));
    let (low, high) = corners.fold((Vec3::MAX, Vec3::MIN), |(l, h), p| (l.min(p), h.max(p)));
    let own_centre = (low + high) / 2.0;
    let own_radius = (levels.iter().flat_map(|l| &l.vertices))
        .map(|v| Vec3::from(v.position).distance(own_centre))
        .fold(0.0, f32::max);

    // Which list the GPU put each rock in: each rock in one list at most.
    let mut gpu_level = vec![None; rocks.len()];
    for (level, list) in kept.iter().enumerate() {
        for &index in list {
            assert!(gpu_level[index as usize].is_none(), "rock {index} is in two lists");
            gpu_level[index as usize] = Some(level);
        }
    }
    let camera = chapter.camera;
    let (mut expected, mut borderline, mut disagree) = ([0u32; 3], 0, 0);
    for (index, rock) in rocks.iter().enumerate() {
        let turn = common::glam::Quat::from_rotation_y(rock.yaw);
        let scale = Vec3::from(rock.scale);
        let centre = Vec3::from(rock.position) + turn * (own_centre * scale);
        let size = (target.width as f32, target.height as f32);
        let cpu = project(&camera, size, centre, own_radius * scale.max_element(), Grading::LOD);
        if let Some(level) = cpu.level {
            expected[level] += 1;
        }
        borderline += u32::from(cpu.borderline);
        if cpu.level != gpu_level[index] {
            disagree += 1;

            assert!(
                cpu.borderline,
                "rock {index} at {centre}: the GPU says {:?}, the projection {:?}",
                gpu_level[index], cpu.level
            );
        }
    }
    let counts = kept.each_ref().map(|list| list.len() as u32);
    eprintln!(
        "GPU kept {counts:?}, the projection {expected:?}; {disagree} rocks disagree, all of {borderline} borderline"
    );
    // Every level is used, and the tolerance is a thin band at the edges.
    assert!(expected.iter().all(|&count| count > 10), "{expected:?}");
    assert!(borderline * 50 < expected.iter().sum(), "{borderline} borderline rocks is too loose a tolerance");
    // The indirect draws: each level's mesh, as many instances as the
    // projection counts (within the borderline rocks), from instance 0.
    for (level, mesh) in levels.iter().enumerate() {
        let draw = &draws[level * 5..level * 5 + 5];
        assert_eq!(draw[0] as usize, mesh.indices.len());
        assert!(draw[1].abs_diff(expected[level]) <= borderline, "level {level}: {} against {expected:?}", draw[1]);
        assert_eq!(draw[1], counts[level]);
        assert_eq!(&draw[2..], &[0, 0, 0], "first index, base vertex and first instance are 0");
    }
}

// ANCHOR: by_hand
/// A camera at the origin looking down −z, 60° high, a square picture 600
/// pixels high: 600 / (2 tan 30°) = 519.6 pixels per radian, so a sphere of
/// radius 1 at distance d is 2 / d × 519.6 = 1,039.2 / d pixels across.
/// With `Grading::LOD`: full rock from 12 px (d ≤ 86.6), octahedron from
/// 4 px (d ≤ 259.8), tetrahedron from 1 px (d ≤ 1,039.2). The far plane is
/// at 600 m; the clip plane keeps y ≥ −5.
const BY_HAND: [(&str, [f32; 3], f32, Option<usize>); 24] = [
    ("86 m ahead: 12.08 px", [0.0, 0.0, -86.0], 1.0, Some(0)),
    ("88 m ahead: 11.81 px", [0.0, 0.0, -88.0], 1.0, Some(1)),
    ("250 m ahead: 4.16 px", [0.0, 0.0, -250.0], 1.0, Some(1)),
    ("270 m ahead: 3.85 px", [0.0, 0.0, -270.0], 1.0, Some(2)),
    ("599 m ahead: 1.73 px, before the far plane", [0.0, 0.0, -599.0], 1.0, Some(2)),
    ("601.5 m ahead: wholly past the far plane", [0.0, 0.0, -601.5], 1.0, None),
    ("radius 0.5 at 500 m: 1.04 px", [0.0, 0.0, -500.0], 0.5, Some(2)),
    ("radius 0.5 at 550 m: 0.94 px, too small", [0.0, 0.0, -550.0], 0.5, None),
    ("50 m behind", [0.0, 0.0, 50.0], 1.0, None),
    ("0.5 m behind, holding the near plane", [0.0, 0.0, 0.5], 1.0, Some(0)),
    ("1.2 m behind, short of the near plane", [0.0, 0.0, 1.2], 1.0, None),
    // At 100 m the right plane is at x = 100 tan 30° = 57.735; a centre δ
    // past it is δ cos 30° = 0.866 δ from the plane: kept while δ ≤ 1.155.
    ("1 m past the right edge: 0.87 m from its plane", [58.735, 0.0, -100.0], 1.0, Some(1)),
    // Past δ = 1 the centre is beyond the edge by more than the radius, yet
    // the sphere still reaches over the plane: kept, up to δ = 1.155.
    ("1.1 m past the right edge: 0.95 m from its plane", [58.835, 0.0, -100.0], 1.0, Some(1)),
    ("1.15 m past the right edge: 0.996 m from its plane", [58.885, 0.0, -100.0], 1.0, Some(1)),
    ("1.1 m past the left edge", [-58.835, 0.0, -100.0], 1.0, Some(1)),
    ("1.15 m over the top edge", [0.0, 58.885, -100.0], 1.0, Some(1)),
    ("1.3 m past the right edge: 1.13 m from its plane", [59.035, 0.0, -100.0], 1.0, None),
    ("1 m past the left edge", [-58.735, 0.0, -100.0], 1.0, Some(1)),
    ("1 m over the top edge", [0.0, 58.735, -100.0], 1.0, Some(1)),
    ("1.3 m over the top edge", [0.0, 59.035, -100.0], 1.0, None),
    ("1.3 m past the left edge", [-59.035, 0.0, -100.0], 1.0, None),
    ("wholly under the clip plane: y −7, its top at −6", [0.0, -7.0, -100.0], 1.0, None),
    ("reaching above the clip plane: y −5.5, its top at −4.5", [0.0, -5.5, -100.0], 1.0, Some(1)),
    ("far to the side, 63° off the axis", [100.0, 0.0, -50.0], 1.0, None),
];
// ANCHOR_END: by_hand

#[test]
fn rocks_placed_by_hand_land_in_the_lists_worked_out_by_hand() {
    let gpu = test_gpu();
    let device = &gpu.device;
    let culling = RockCulling::new(gpu, [60, 24, 12]).unwrap();
    // Each rock's own sphere is the unit sphere about where it stands, so
    // its radius in the world is its scale.
    let rocks: Vec<RockInstance> = BY_HAND
        .iter()
        .map(|&(_, position, radius, _)| RockInstance { position, yaw: 0.7, scale: [radius; 3], shade: 0.5 })
        .collect();
    let buffer = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
        label: Some("rocks placed by hand"),
        contents: bytemuck::cast_slice(&rocks),
        usage: wgpu::BufferUsages::STORAGE,
    });
    let group = culling.rocks_group(device, &buffer);
    let mut lists = culling.lists(device, rocks.len() as u32);
    let camera = Camera {
        position: Vec3::ZERO,
        yaw: 0.0,
        pitch: 0.0,
        fov_y: 60f32.to_radians(),
        aspect: 1.0,
        near: 0.1,
        far: 600.0,
    };
    let picture = Picture { camera, height: 600, clip: Vec4::new(0.0, 1.0, 0.0, 5.0) };
    assert!((picture.pixels_per_radian() - 519.6).abs() < 0.05);
    let source = RockSource { group: &group, sphere: Vec4::new(0.0, 0.0, 0.0, 1.0), count: rocks.len() as u32 };
    culling.aim(&gpu.queue, &lists, &picture, &source, Grading::LOD);
    let mut encoder = device.create_command_encoder(&Default::default());
    culling.cull(gpu, &mut encoder, &PassTimer::off(), &mut lists, &source);
    gpu.queue.submit([encoder.finish()]);

    let kept = lists.lists_now(gpu);
    let level_of = |index: u32| kept.iter().position(|list| list.contains(&index));
    let mut wrong = Vec::new();
    for (index, &(what, _, _, expected)) in BY_HAND.iter().enumerate() {
        let level = level_of(index as u32);
        if level != expected {
            wrong.push(format!("{what}: level {level:?}, worked out {expected:?}"));
        }
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
    let expected_counts: [u32; 3] = std::array::from_fn(|level| {
        BY_HAND.iter().filter(|(_, _, _, expected)| *expected == Some(level)).count() as u32
    });
    assert_eq!(lists.counts_now(gpu), expected_counts);
    assert_eq!(expected_counts, [2, 10, 3]);
}

#[test]
fn without_compute_shaders_the_plain_culls_by_chunk_and_says_which_capability_is_missing() {
    let gpu = test_gpu();
    let target = Target { format: OFFSCREEN_FORMAT, width: 160, height: 90, samples: 1 };
    let mut chapter: InstancingChapter = common::chapter::create(gpu, target, &Default::default()).unwrap();
    let by_chunk = picture(gpu, &mut chapter, target, "cpu-culling");
    let chunk_calls = chapter.draw_calls;
    let on_the_gpu = picture(gpu, &mut chapter, target, "default");
    assert_eq!(chapter.draw_calls.rocks, 3, "one indirect draw per level");
    assert!(!chapter.stats(gpu).contains("culled by chunk"));

    // The same plain on a device that lacks compute shaders.
    let mut lacking = gpu.downlevel();
    lacking.flags -= wgpu::DownlevelFlags::COMPUTE_SHADERS;
    let terrain = terrain::TerrainData::get(gpu, TerrainSettings::default());
    chapter.plain = MarsPlain::with_capabilities(gpu, (OFFSCREEN_FORMAT, &[1]), terrain, &lacking).unwrap();
    let fallen_back = picture(gpu, &mut chapter, target, "default");
    assert_eq!(chapter.draw_calls, chunk_calls, "the default view draws the chunk groups, as cpu-culling does");
    assert_eq!(fallen_back, by_chunk);
    assert_ne!(fallen_back, on_the_gpu, "the GPU's picture differs, so the comparison above means something");
    let line = chapter.stats(gpu);
    let said = "rocks culled by chunk on the CPU: this GPU has no compute shaders (DownlevelFlags::COMPUTE_SHADERS)";
    assert!(line.contains(said), "`{line}` should say `{said}`");
    assert_eq!(line.lines().count(), 1);
}

/// The number before " rock triangles" in a stats line.
fn rock_triangles(line: &str) -> u64 {
    let before = &line[..line.find(" rock triangles").unwrap_or_else(|| panic!("no rock triangles in `{line}`"))];
    let number = before.rsplit(' ').next().unwrap_or_default();
    number.replace(',', "").parse().unwrap_or_else(|_| panic!("`{number}` in `{line}`"))
}

/// The graded rocks' triangles at 1920 × 1080, per cent of those culling
/// by chunk draws: the page's figure, which the test below computes.
const GRADED_TRIANGLES_PERCENT: f64 = 8.8;

#[test]
fn the_default_view_draws_a_tenth_of_the_rock_triangles_culling_by_chunk_drew() {
    // The budget's picture size: the lent GPU's figures are at 1920 × 1080.
    let gpu = test_gpu();
    let target = Target { format: OFFSCREEN_FORMAT, width: 1920, height: 1080, samples: 1 };
    let mut chapter: InstancingChapter = common::chapter::create(gpu, target, &Default::default()).unwrap();
    let mut drawn = |view: &str| {
        let view = common::chapter::view_index::<InstancingChapter>(view).unwrap();
        chapter.select_view(view);
        // The rocks alone: the terrain changes no count and costs lavapipe seconds.
        chapter.setup.terrain = false;
        capture(gpu, &mut chapter, target, (0.0, view), Default::default()).unwrap();
        let line = chapter.stats(gpu);
        let drawn = chapter.plain.rocks_drawn_now(gpu, chapter.viewpoint(), chapter.setup);
        assert_eq!(rock_triangles(&line), drawn.triangles, "the stats line gives the count: `{line}`");
        drawn
    };
    let (by_chunk, graded) = (drawn("cpu-culling"), drawn("default"));
    eprintln!("at 1920 × 1080: by chunk {by_chunk:?}, graded on the GPU {graded:?}");
    assert_eq!(by_chunk.triangles, 20 * 276_571, "the chunk groups' rocks, 20 triangles each (the lessons)");
    assert!(graded.triangles * 10 <= by_chunk.triangles, "{graded:?} against {by_chunk:?}");
    assert_eq!(Setup::DEFAULT.culling, Culling::PerRock);

    // The lessons quote the counts.
    let [full, octahedra, tetrahedra] = graded.levels.expect("graded on the GPU").map(|n| thousands(n.into()));
    let share = 100.0 * graded.triangles as f64 / by_chunk.triangles as f64;
    assert!((share - GRADED_TRIANGLES_PERCENT).abs() < 0.05, "{share:.2} %");
    let page = common::book_figures::section_text("05-instancing");
    for figure in [
        format!("**{} rock triangles** a frame", thousands(by_chunk.triangles as f64)),
        format!("**{} rocks**", thousands(graded.rocks.into())),
        format!("({full} full, {octahedra} octahedra, {tetrahedra} tetrahedra)"),
        format!("**{} rock triangles**, {{{{#figure", thousands(graded.triangles as f64)),
    ] {
        assert!(page.contains(&figure), "chapter 05's pages should say `{figure}`");
    }
}
