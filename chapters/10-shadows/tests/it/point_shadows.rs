//! The lantern's cube shadow map: the six faces cover every direction
//! exactly once and are rendered as the GPU's lookup reads them; boxes
//! between a point light and a plane cast the shadows that rays towards
//! the light say they must, on every face that sees the plane; without
//! bias the plane shadows itself; and the figures the page gives for the
//! level's lantern.

use std::collections::HashMap;

use common::glam::{Mat4, Vec2, Vec3};
use common::headless::{OFFSCREEN_FORMAT, Offscreen, capture, read_floats};
use common::{Camera, Chapter, Gpu, Target, primitives, wgpu};
use lighting::lights::{Light, LightKind, daylight};
use lighting::{HDR_FORMAT, Highlight, LoopOptions, SceneLights};
use shadows::point_shadow::{self, CubeFace, PointBias, PointFilter, PointShadow, PointShadowSettings, caster_winding};
use shadows::shadow_map::{Filter, ShadowMap, ShadowSettings, fit_light};
use shadows::{ShadowedRenderer, ShadowsChapter, game, scene};
use textures::materials::{Materials, Uploader};
use textures::mesh::{MaterialDesc, ModelData, ModelInstance};
use textures::mipmaps::MipMaker;
use textures::{Draw, DrawList, upload_model};

// ANCHOR: faces_test
/// Every face's square of directions, on a grid whose lines include the
/// face's borders: inside a face, a direction belongs to that face alone;
/// on an edge, to the two faces that meet there; at a corner, to three.
/// The faces' matrices must agree: each face's frustum holds exactly the
/// directions of its own grid, so the six pictures leave no gap and
/// overlap only along shared borders. The lookup gives each direction one
/// face, whose matrix puts it where the lookup reads it.
#[test]
fn the_six_faces_cover_every_direction_exactly_once() {
    let light = Vec3::new(3.0, -1.0, 2.0);
    let range = 10.0;
    let steps = 16;
    // Which faces' grids hold each direction (rounded, so that an edge's
    // direction from two faces is one key).
    let mut grids: HashMap<[i32; 3], Vec<CubeFace>> = HashMap::new();
    for face in CubeFace::ALL {
        for i in 0..=steps {
            for j in 0..=steps {
                let st = Vec2::new(i as f32, j as f32) / steps as f32;
                let d = face.direction(st);
                grids.entry(d.to_array().map(|c| (c * 1024.0).round() as i32)).or_default().push(face);
            }
        }
    }
    // 6 × 15² inside the faces, 12 edges × 15, 8 corners.
    assert_eq!(grids.len(), 6 * 15 * 15 + 12 * 15 + 8);
    let mut by_count = [0; 4];
    for (key, faces) in &grids {
        let d = Vec3::from_array(key.map(|c| c as f32 / 1024.0));
        let p = light + d * 2.5;
        let holders: Vec<CubeFace> = CubeFace::ALL
            .into_iter()
            .filter(|f| {
                let clip = f.view_proj(light, range) * p.extend(1.0);
                let (x, y) = (clip.x / clip.w, clip.y / clip.w);
                clip.w > 0.0 && x.abs() <= 1.0 + 1e-5 && y.abs() <= 1.0 + 1e-5
            })
            .collect();
        let mut expected = faces.clone();
        expected.sort_by_key(|f| f.layer());
        assert_eq!(holders, expected, "direction {d}: held by {holders:?}, on the grids of {faces:?}");
        by_count[faces.len()] += 1;
        let (face, st) = CubeFace::lookup(d);
        assert!(faces.contains(&face), "{d} looked up on {face:?}, not one of {faces:?}");
        let ndc = face.view_proj(light, range).project_point3(p);
        let rendered_at = Vec2::new(ndc.x + 1.0, 1.0 - ndc.y) / 2.0;
        assert!((rendered_at - st).abs().max_element() < 1e-5, "{d}: rendered at {rendered_at}, read at {st}");
        assert!((0.0..=1.0).contains(&ndc.z), "{d}: depth {} outside 0 to 1", ndc.z);
    }
    assert_eq!(by_count, [0, 1350, 180, 8], "inside a face, on an edge, at a corner");
}
// ANCHOR_END: faces_test

/// The table itself, against the lookup of every API: the major axis
/// picks the face, and s and t are the other two components over it.
#[test]
fn the_lookup_follows_the_cube_map_table() {
    let cases = [
        (Vec3::new(1.0, 0.5, -0.25), CubeFace::PosX, Vec2::new(0.625, 0.25)),
        (Vec3::new(-1.0, 0.5, -0.25), CubeFace::NegX, Vec2::new(0.375, 0.25)),
        (Vec3::new(0.5, 1.0, -0.25), CubeFace::PosY, Vec2::new(0.75, 0.375)),
        (Vec3::new(0.5, -1.0, -0.25), CubeFace::NegY, Vec2::new(0.75, 0.625)),
        (Vec3::new(0.5, -0.25, 1.0), CubeFace::PosZ, Vec2::new(0.75, 0.625)),
        (Vec3::new(0.5, -0.25, -1.0), CubeFace::NegZ, Vec2::new(0.25, 0.625)),
    ];
    for (direction, face, st) in cases {
        assert_eq!(CubeFace::lookup(direction * 3.0), (face, st), "{direction}");
        assert!((face.direction(st) - direction).length() < 1e-6);
    }
}

/// The faces are mirror images of a camera's picture: a triangle facing
/// the light winds the way `caster_winding` says on every face, and the
/// shadow pass culls back faces with it.
#[test]
fn triangles_facing_the_light_wind_clockwise_on_every_face() {
    let light = Vec3::new(1.0, 2.0, 3.0);
    for face in CubeFace::ALL {
        let axes = face.axes();
        // A small triangle a metre along the face's axis, turned to face the light.
        let centre = light + axes.major;
        let (a, b) = (axes.s * 0.1, axes.t * 0.1);
        let corners = [centre, centre + a, centre + b];
        let normal = (corners[1] - corners[0]).cross(corners[2] - corners[0]);
        let corners = if normal.dot(light - centre) > 0.0 { corners } else { [corners[0], corners[2], corners[1]] };
        let m = face.view_proj(light, 10.0);
        let screen: Vec<Vec2> = corners.iter().map(|c| m.project_point3(*c).truncate()).collect();
        let signed_area = (screen[1] - screen[0]).perp_dot(screen[2] - screen[0]);
        let winding = if signed_area > 0.0 { wgpu::FrontFace::Ccw } else { wgpu::FrontFace::Cw };
        assert_eq!(winding, caster_winding(), "{face:?}");
    }
}

const WIDTH: u32 = 320;
const HEIGHT: u32 = 240;
/// The plane: y = 0, 12 m square.
const PLANE_HALF: f32 = 6.0;
/// The light, 2 m above the middle of the plane.
const LIGHT: Vec3 = Vec3::new(0.0, 2.0, 0.0);
/// Two boxes between the light and the plane: one off to +x, one off to −z.
const BOXES: [(Vec3, Vec3); 2] =
    [(Vec3::new(1.5, 0.6, -0.5), Vec3::new(2.5, 1.4, 0.5)), (Vec3::new(-0.4, 0.8, -2.4), Vec3::new(0.4, 1.2, -1.6))];

/// Whether the segment from `p` to the light passes through a box (the
/// slab test, between the two ends).
fn blocked(p: Vec3) -> bool {
    let direction = LIGHT - p;
    BOXES.iter().any(|(low, high)| {
        let inverse = direction.recip();
        let t0 = (*low - p) * inverse;
        let t1 = (*high - p) * inverse;
        let near = t0.min(t1).max_element().max(0.0);
        let far = t0.max(t1).min_element().min(1.0);
        far >= near
    })
}

/// The tiny scene: a plane, two boxes and a point light, seen from above;
/// `look(settings)` renders it with the lantern's lookups and returns, per
/// pixel, how much of the light arrives (the blue of `fs_lantern_sunlit`).
struct TinyScene {
    gpu: Gpu,
    camera: Camera,
}

impl TinyScene {
    fn new() -> Self {
        let gpu = Gpu::headless(ShadowsChapter::gpu_needs()).unwrap();
        let camera =
            Camera::looking_at(Vec3::new(0.0, 9.0, 5.0), Vec3::new(0.0, 0.0, -0.3), WIDTH as f32 / HEIGHT as f32);
        Self { gpu, camera }
    }

    fn look(&self, settings: &PointShadowSettings) -> Vec<f32> {
        let gpu = &self.gpu;
        let device = &gpu.device;
        let grey = MaterialDesc::plain("grey", Vec3::splat(0.5), 0.0, 1.0);
        let mut plane = ModelData::from_mesh(&primitives::plane(1), grey.clone());
        plane.vertices.iter_mut().for_each(|v| v.position = (Vec3::from(v.position) * 2.0 * PLANE_HALF).into());
        let mut boxes = ModelData { materials: vec![grey], ..Default::default() };
        for (low, high) in BOXES {
            let at = Mat4::from_scale_rotation_translation(high - low, Default::default(), (low + high) / 2.0);
            boxes.append(&primitives::cube(), 0, at, |uv, _| uv);
        }
        let mut mips = MipMaker::new(gpu).unwrap();
        let mut up = Uploader::new(gpu, &mut mips, &scene::read);
        let mut materials = Materials::new(&mut up);
        let plane = upload_model(&mut up, &mut materials, &plane, "plane");
        let boxes = upload_model(&mut up, &mut materials, &boxes, "boxes");
        up.finish();
        let instances = wgpu::util::DeviceExt::create_buffer_init(
            device,
            &wgpu::util::BufferInitDescriptor {
                label: Some("instances"),
                contents: bytemuck::cast_slice(&[ModelInstance::new(Mat4::IDENTITY, 1.0)]),
                usage: wgpu::BufferUsages::VERTEX,
            },
        );
        let list = DrawList {
            materials: &materials,
            instances: &instances,
            draws: vec![Draw { model: &plane, instances: 0..1 }, Draw { model: &boxes, instances: 0..1 }],
        };
        let day = daylight(0.5);
        let mut lights = SceneLights::new(gpu).unwrap();
        let options = LoopOptions { culling: false, highlight: Highlight::BlinnPhong, heat_map: false };
        lights.write(gpu, &self.camera, &day, &[], &Default::default(), options);
        // The sun's map is not looked up: its filter is off.
        let sun = ShadowMap::new(gpu, 512).unwrap();
        let sun_settings = ShadowSettings { filter: Filter::Off, ..Default::default() };
        let bounds = (Vec3::splat(-PLANE_HALF), Vec3::splat(PLANE_HALF));
        sun.write(gpu, &fit_light(day.direction, &[Vec3::ZERO], bounds, 512), &sun_settings);
        let point = PointShadow::new(gpu, point_shadow::DEFAULT_FACE_SIZE).unwrap();
        let light = Light { position: LIGHT, colour: Vec3::ONE, range: 12.0, kind: LightKind::Point };
        point.write(gpu, &light, settings);
        let renderer =
            ShadowedRenderer::with_point_light(gpu, &lights, &materials, &sun, &point, Default::default()).unwrap();
        let Offscreen { texture: target, view } =
            Offscreen::new(device, Target { format: HDR_FORMAT, width: WIDTH, height: HEIGHT, samples: 1 });
        let depth = common::texture::depth_view(device, WIDTH, HEIGHT);
        let mut encoder = device.create_command_encoder(&Default::default());
        let timer = common::PassTimer::off();
        let cost = point.render(&mut encoder, &timer, &list);
        assert_eq!(cost.passes, 6);
        {
            let mut pass =
                common::chapter::scene_pass(&mut encoder, &timer, "lantern lit", &view, wgpu::Color::BLACK, &depth);
            pass.set_bind_group(0, &lights.group, &[]);
            renderer.draw(&mut pass, &sun, &list, true);
        }
        gpu.queue.submit([encoder.finish()]);
        read_floats(gpu, &target).unwrap().iter().map(|p| p[2]).collect()
    }

    /// The point of the plane pixel (x, y) shows, if it shows the plane.
    fn plane_point(&self, x: u32, y: u32) -> Option<Vec3> {
        let inverse = self.camera.view_projection().inverse();
        let ndc = Vec2::new((x as f32 + 0.5) / WIDTH as f32 * 2.0 - 1.0, 1.0 - (y as f32 + 0.5) / HEIGHT as f32 * 2.0);
        let near = inverse.project_point3(ndc.extend(0.0));
        let far = inverse.project_point3(ndc.extend(1.0));
        let direction = (far - near).normalize();
        let t = -near.y / direction.y;
        let p = near + direction * t;
        let hidden = BOXES.iter().any(|(low, high)| {
            let inverse = direction.recip();
            let (t0, t1) = ((*low - near) * inverse, (*high - near) * inverse);
            let (enter, leave) = (t0.min(t1).max_element(), t0.max(t1).min_element());
            leave >= enter.max(0.0) && enter < t
        });
        (p.x.abs() < PLANE_HALF - 0.1 && p.z.abs() < PLANE_HALF - 0.1 && !hidden).then_some(p)
    }

    /// The pixel that shows the world point `p`.
    fn pixel_of(&self, p: Vec3) -> (u32, u32) {
        let ndc = self.camera.view_projection().project_point3(p);
        (((ndc.x + 1.0) / 2.0 * WIDTH as f32) as u32, ((1.0 - ndc.y) / 2.0 * HEIGHT as f32) as u32)
    }
}

/// Every pixel showing the plane, checked against the segment from its
/// point to the light: (pixels checked, of them in shadow, those that
/// disagree, pixels checked per face). Within three texels of a shadow's
/// edge (measured at the point's distance) either answer is fair.
fn check(scene: &TinyScene, arriving: &[f32]) -> (usize, usize, Vec<(Vec3, f32)>, [usize; 6]) {
    let (mut checked, mut shadowed, mut wrong, mut per_face) = (0, 0, Vec::new(), [0; 6]);
    for y in 0..HEIGHT {
        for x in 0..WIDTH {
            let Some(p) = scene.plane_point(x, y) else { continue };
            let margin = 3.0 * 2.0 * p.distance(LIGHT) / point_shadow::DEFAULT_FACE_SIZE as f32;
            let expected = blocked(p);
            let near_edge =
                [Vec3::X, Vec3::NEG_X, Vec3::Z, Vec3::NEG_Z].iter().any(|d| blocked(p + *d * margin) != expected);
            if near_edge {
                continue;
            }
            let value = arriving[(y * WIDTH + x) as usize];
            checked += 1;
            shadowed += usize::from(expected);
            per_face[CubeFace::lookup(p - LIGHT).0.layer() as usize] += 1;
            if (value < 0.5) != expected {
                wrong.push((p, value));
            }
        }
    }
    (checked, shadowed, wrong, per_face)
}

// ANCHOR: tiny_scene_test
#[test]
fn boxes_between_a_point_light_and_a_plane_cast_the_shadows_rays_predict() {
    let scene = TinyScene::new();
    let hard = PointShadowSettings { filter: PointFilter::Hard, ..PointShadowSettings::DEFAULT };
    let arriving = scene.look(&hard);

    // Two points by name: one behind the first box as the light sees it,
    // one in the open.
    let behind = Vec3::new(4.0, 0.0, 0.0);
    let open = Vec3::new(-3.0, 0.0, 2.0);
    assert!(blocked(behind) && !blocked(open));
    let at = |p: Vec3| {
        let (x, y) = scene.pixel_of(p);
        arriving[(y * WIDTH + x) as usize]
    };
    assert!(at(behind) < 0.01, "behind the box: {} of the light arrives", at(behind));
    assert!(at(open) > 0.99, "in the open: {} of the light arrives", at(open));

    // Every pixel of the plane, read from five faces of the cube (+y sees
    // only sky).
    let (checked, shadowed, wrong, per_face) = check(&scene, &arriving);
    eprintln!("{checked} plane pixels checked, {shadowed} in shadow, per face {per_face:?}");
    assert_eq!((checked, shadowed), (47_312, 4_073));
    for face in [CubeFace::PosX, CubeFace::NegX, CubeFace::NegY, CubeFace::PosZ, CubeFace::NegZ] {
        assert!(per_face[face.layer() as usize] > 5_000, "only {per_face:?} pixels per face");
    }
    assert!(wrong.is_empty(), "{} pixels disagree with the rays, e.g. {:?}", wrong.len(), &wrong[..wrong.len().min(5)]);

    // With nine taps, the same, a few texels further from the edges.
    let pcf = scene.look(&PointShadowSettings::DEFAULT);
    let (_, _, wrong, _) = check(&scene, &pcf);
    assert!(wrong.len() * 200 < checked, "3×3 PCF: {} of {checked} pixels disagree", wrong.len());

    // Without the lookup the light passes through the boxes: chapter 08's
    // lamps, "light through walls".
    let off = scene.look(&PointShadowSettings::OFF);
    let plane_pixels = (0..HEIGHT).flat_map(|y| (0..WIDTH).map(move |x| (x, y)));
    let dimmed =
        plane_pixels.filter(|&(x, y)| scene.plane_point(x, y).is_some() && off[(y * WIDTH + x) as usize] != 1.0);
    assert_eq!(dimmed.count(), 0, "with the filter off, every pixel of the plane gets all the light");
}
// ANCHOR_END: tiny_scene_test

// ANCHOR: bias_test
#[test]
fn without_bias_the_plane_shadows_itself() {
    let scene = TinyScene::new();
    let count = |bias: PointBias| {
        let settings = PointShadowSettings { filter: PointFilter::Hard, bias, ..PointShadowSettings::DEFAULT };
        let (checked, _, wrong, _) = check(&scene, &scene.look(&settings));
        (wrong.len(), checked)
    };
    let (acne, checked) = count(PointBias::NONE);
    let (biased, _) = count(PointBias::DEFAULT);
    eprintln!("plane pixels whose shadow disagrees with the rays: {acne} of {checked} without bias, {biased} with");
    assert_eq!(biased, 0);
    // Which pixels stripe is the rasteriser's business: 5 % either way.
    assert!(acne.abs_diff(22_682) <= 1_134, "without bias {acne} of {checked} pixels, not 22,682");
    // The light grazes the plane's corners at 76.7° from its normal.
    let corner = Vec3::new(PLANE_HALF, 0.0, PLANE_HALF);
    let grazing = (LIGHT.y / corner.distance(LIGHT)).acos().to_degrees();
    assert!((grazing - 76.7).abs() < 0.05, "{grazing}°");
}
// ANCHOR_END: bias_test

// ANCHOR: level_figures
/// What the page says of the level's lantern.
#[test]
fn the_lantern_hangs_in_the_tunnel_and_its_cube_costs_what_the_page_says() {
    let level = game::level();
    let lantern = scene::lantern_light(&level);
    // Under the tunnel's ceiling (the metal block from 40 to 52 m, 2.3 m
    // up), above the player's head.
    let ceiling = level.blocks.iter().find(|b| b.aabb.min.y == 2.3).unwrap();
    assert!((ceiling.aabb.min.x..=ceiling.aabb.max.x).contains(&lantern.position.x));
    assert!(lantern.position.y < 2.3 && lantern.position.y - 0.15 > game::PLAYER_SIZE.y);
    assert_eq!((lantern.range, point_shadow::DEFAULT_FACE_SIZE), (9.0, 512));
    // A texel on the ground under it: 2 × 1.95 m / 512; at its range, 2 × 9 m / 512.
    let texel_cm = |metres: f32| 2.0 * metres / point_shadow::DEFAULT_FACE_SIZE as f32 * 100.0;
    assert!((texel_cm(lantern.position.y) - 0.76).abs() < 0.005, "{} cm", texel_cm(lantern.position.y));
    assert!((texel_cm(lantern.range) - 3.5).abs() < 0.05, "{} cm", texel_cm(lantern.range));
    // The figure's Q, halfway up the inner face of the pillar on the
    // ceiling's left end: the ray to it meets the ceiling's underside
    // 0.75 m from the light, where Q is 3.96 m away.
    let pillar = level.blocks.iter().find(|b| b.aabb.min.y == ceiling.aabb.max.y && b.aabb.max.x < lantern.position.x);
    let pillar = pillar.unwrap().aabb;
    let q = Vec3::new(pillar.max.x, (pillar.min.y + pillar.max.y) / 2.0, lantern.position.z);
    let to_q = q - lantern.position;
    let stored = to_q.length() * (ceiling.aabb.min.y - lantern.position.y) / to_q.y;
    assert!((stored - 0.75).abs() < 0.005 && (to_q.length() - 3.96).abs() < 0.005, "{stored} m, {} m", to_q.length());
    assert_eq!(CubeFace::lookup(to_q).0, CubeFace::NegX);

    // One frame's six passes, counted as they were recorded.
    let gpu = Gpu::headless(ShadowsChapter::gpu_needs()).unwrap();
    let target = Target { format: OFFSCREEN_FORMAT, width: 160, height: 90, samples: 1 };
    let mut chapter = ShadowsChapter::new(&gpu, target, ()).unwrap();
    let view = common::chapter::view_index::<ShadowsChapter>("lantern").unwrap();
    chapter.select_view(view);
    capture(&gpu, &mut chapter, target, (ShadowsChapter::SNAPSHOT_TIME, view), Default::default()).unwrap();
    let cost = chapter.cube_cost;
    eprintln!("the lantern's cube: {cost:?}");
    assert_eq!((cost.passes, cost.draw_calls, cost.triangles), (6, CUBE_DRAW_CALLS, CUBE_TRIANGLES));
    // Without its shadow, no passes at all.
    chapter.settings.lantern.filter = PointFilter::Off;
    capture(&gpu, &mut chapter, target, (ShadowsChapter::SNAPSHOT_TIME, view), Default::default()).unwrap();
    assert_eq!(chapter.cube_cost.passes, 0);
}

/// Draw calls and triangles of the six passes, per frame.
const CUBE_DRAW_CALLS: u32 = 78;
const CUBE_TRIANGLES: u64 = 24_468;
// ANCHOR_END: level_figures
