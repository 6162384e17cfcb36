//! Chapter 10's figures: the shadow test, how the sun's box is fitted
//! (computed with the chapter's `fit_light` for its default picture),
//! shadow acne with the slope-scaled bias that ends it, and the lantern's
//! cube shadow map (computed with the chapter's `CubeFace::lookup`).

use common::Chapter;
use common::glam::{Vec2, Vec3};
use std::path::Path;

use common::glam::Mat4;
use shadows::game::{self, Block, Game, Level, PropKind};
use shadows::light_box::{SECTION_AT, SECTION_LIT_AT, through_box};
use shadows::point_shadow::CubeFace;
use shadows::shadow_map::{self, LightBox, fit_light};
use shadows::{CAMERA_DISTANCE, Settings, ShadowsChapter, scene, side_camera, visible_part};
use textures::mesh::ModelInstance;

use crate::kit::{ACCENT, BLUE, INK, MUTED, Svg};

/// Chapter 10: shadow acne. The light looks down; each shadow-map texel
/// stores the depth of the surface at its centre, a flat step. Along a
/// sloped surface, half of every texel lies deeper than its step and
/// shadows itself; a bias of half a texel's depth change moves every step
/// below the surface.
pub fn shadow_acne() -> String {
    let mut svg = Svg::new(640.0, 380.0);
    let (left, top, texel) = (40.0f32, 90.0f32, 60.0f32);
    let slope = 0.45f32;
    let surface = |x: f32| top + 30.0 + slope * (x - left);
    let texels = 8;
    let right = left + texel * texels as f32;
    // Rays from the sun, straight down in light space.
    for i in 0..=texels {
        let x = left + texel * i as f32;
        svg.dashed(Vec2::new(x, top - 10.0), Vec2::new(x, 370.0), MUTED);
    }
    svg.text(
        Vec2::new(left, top - 18.0),
        "shadow-map texels, seen from the sun (rays point down)",
        11.0,
        "start",
        MUTED,
    );
    for i in 0..texels {
        let x0 = left + texel * i as f32;
        let centre = x0 + texel / 2.0;
        let stored = surface(centre);
        // The part of the surface deeper than the stored step: in shadow.
        svg.polygon(
            &[Vec2::new(centre, stored), Vec2::new(x0 + texel, surface(x0 + texel)), Vec2::new(x0 + texel, stored)],
            "#e9b8a6",
            "none",
        );
        svg.line(Vec2::new(x0, stored), Vec2::new(x0 + texel, stored), ACCENT, 2.5);
        svg.circle(Vec2::new(centre, stored), 3.0, ACCENT);
        let biased = stored + slope * texel / 2.0 + 4.0;
        svg.line(Vec2::new(x0, biased), Vec2::new(x0 + texel, biased), BLUE, 1.5);
    }
    svg.line(Vec2::new(left, surface(left)), Vec2::new(right, surface(right)), INK, 2.0);
    let legend = right + 12.0;
    svg.text(Vec2::new(legend, top + 20.0), "depth stored", 11.0, "start", ACCENT);
    svg.text(Vec2::new(legend, top + 34.0), "(one per texel)", 11.0, "start", ACCENT);
    svg.text(Vec2::new(legend, top + 58.0), "the surface", 11.0, "start", INK);
    svg.text(Vec2::new(legend, top + 82.0), "stored + bias", 11.0, "start", BLUE);
    svg.text(Vec2::new(legend, top + 106.0), "shaded: in its", 11.0, "start", ACCENT);
    svg.text(Vec2::new(legend, top + 120.0), "own shadow", 11.0, "start", ACCENT);
    svg.text(
        Vec2::new(20.0, 24.0),
        "Where the surface lies deeper than the step its texel stored (shaded), it shadows itself: stripes.",
        11.0,
        "start",
        INK,
    );
    svg.text(
        Vec2::new(20.0, 40.0),
        "Pushing each step back by the depth the surface gains across half a texel (slope-scaled bias) ends it.",
        11.0,
        "start",
        BLUE,
    );
    svg.finish()
}

/// The chapter's default picture as `ShadowsChapter::render` fits the
/// sun's box for it: the demo at the snapshot time, the game's camera at
/// 16:9, the default sun, a 2048² map.
struct Fitted {
    level: Level,
    game: Game,
    bounds: (Vec3, Vec3),
    towards_sun: Vec3,
    eye: Vec3,
    visible: [Vec3; 8],
    light: LightBox,
}

fn fitted_at(time: f32) -> Fitted {
    let level = game::level();
    let game = game::demo_at(&level, &level.solids(), time);
    let camera = side_camera(game.player.aabb.centre(), CAMERA_DISTANCE, 16.0 / 9.0);
    let bounds = scene::level_bounds(&level);
    let visible = visible_part(&camera, bounds.1.z);
    let towards_sun = scene::sun_at(Settings::DEFAULT.phase).direction;
    let light = fit_light(towards_sun, &visible, bounds, shadow_map::DEFAULT_SIZE);
    Fitted { level, game, bounds, towards_sun, eye: camera.position, visible, light }
}

/// The boxes around the props and the player, from their models' own
/// vertices placed as the chapter places them.
fn model_boxes(f: &Fitted) -> Vec<(Vec3, Vec3)> {
    let read: textures::obj::ReadFile = &scene::read;
    let placed = |path: &str, instances: Vec<ModelInstance>| {
        let model = textures::obj::load(Path::new(path), read).expect("the chapter's models load").model;
        instances
            .into_iter()
            .map(|instance| {
                let at = Mat4::from_cols_array_2d(&instance.model);
                model.vertices.iter().fold((Vec3::MAX, Vec3::MIN), |(lo, hi), v| {
                    let p = at.transform_point3(Vec3::from(v.position));
                    (lo.min(p), hi.max(p))
                })
            })
            .collect::<Vec<_>>()
    };
    let kinds = [PropKind::Tree, PropKind::Rock, PropKind::Crate];
    let mut boxes: Vec<(Vec3, Vec3)> =
        kinds.iter().flat_map(|&k| placed(scene::prop_model(k), scene::prop_instances(&f.level, k))).collect();
    boxes.extend(placed(scene::PLAYER_MODEL, vec![scene::player_instance(&f.game)]));
    boxes
}

/// A block of the level as a box in the world.
fn block_box(block: &Block) -> (Vec3, Vec3) {
    (block.aabb.min.extend(-block.depth), block.aabb.max.extend(block.depth))
}

fn box_corners((low, high): (Vec3, Vec3)) -> [Vec3; 8] {
    std::array::from_fn(|i| {
        Vec3::new(
            if i & 1 == 0 { low.x } else { high.x },
            if i & 2 == 0 { low.y } else { high.y },
            if i & 4 == 0 { low.z } else { high.z },
        )
    })
}

/// The sun's box's own axes, read back from the corners of the box
/// `fit_light` returned: across the map (x, y; y is up on the map) and
/// away from the sun (depth). A point's coordinates are metres from the
/// corner where the map's x and y are smallest, on the face nearest the sun.
struct BoxFrame {
    origin: Vec3,
    axes: [Vec3; 3],
}

impl BoxFrame {
    fn of(light: &LightBox) -> Self {
        let c = light.corners();
        Self { origin: c[0], axes: [1, 2, 4].map(|i| (c[i] - c[0]).normalize()) }
    }

    fn at(&self, p: Vec3) -> Vec3 {
        let d = p - self.origin;
        Vec3::new(d.dot(self.axes[0]), d.dot(self.axes[1]), d.dot(self.axes[2]))
    }
}

/// The convex hull of `points` (Andrew's monotone chain): a box's outline
/// seen along any direction.
fn hull(points: &[Vec2]) -> Vec<Vec2> {
    let mut sorted = points.to_vec();
    sorted.sort_by(|a, b| a.x.total_cmp(&b.x).then(a.y.total_cmp(&b.y)));
    let half = |points: &mut dyn Iterator<Item = Vec2>| {
        let mut chain: Vec<Vec2> = Vec::new();
        for q in points {
            while chain.len() >= 2
                && (chain[chain.len() - 1] - chain[chain.len() - 2]).perp_dot(q - chain[chain.len() - 2]) <= 0.0
            {
                chain.pop();
            }
            chain.push(q);
        }
        chain.pop();
        chain
    };
    let mut outline = half(&mut sorted.iter().copied());
    outline.extend(half(&mut sorted.iter().rev().copied()));
    outline
}

/// A plane's region (y up) drawn into a rectangle of the picture (y
/// down), the same scale on both axes, centred.
struct Panel {
    centre: Vec2,
    scale: f32,
    middle: Vec2,
}

impl Panel {
    fn new((low, high): (Vec2, Vec2), origin: Vec2, size: Vec2) -> Self {
        let span = high - low;
        Self { centre: (low + high) / 2.0, scale: (size.x / span.x).min(size.y / span.y), middle: origin + size / 2.0 }
    }

    fn at(&self, p: Vec2) -> Vec2 {
        self.middle + Vec2::new(p.x - self.centre.x, self.centre.y - p.y) * self.scale
    }
}

/// The demo's script runs for 21 s (`game::script`); a second later the
/// player has stopped, and the view with it.
const DEMO_SECONDS: u32 = 22;

/// Chapter 10: the shadow test, in the chapter's default picture. A
/// vertical section through the level along the sun's rays, through two
/// points of the ground; for each, what the map stored along its ray (the
/// first surface of the level's blocks the ray meets, coming from the sun)
/// and the point's own depth, both from `fit_light`'s box.
pub fn shadow_test() -> String {
    let f = fitted_at(ShadowsChapter::SNAPSHOT_TIME);
    let sun = f.towards_sun;
    let light = f.light;
    // The section: the vertical plane along the sun's rays through the
    // ground at x = 25.6 m, under the third platform (23–26 m); u metres along
    // the ground towards the sun, y up. Every ray towards the sun from a
    // point of the plane stays in the plane.
    let towards = Vec3::new(sun.x, 0.0, sun.z).normalize();
    let shadowed = Vec3::new(SECTION_AT, 0.0, 0.0);
    let lit = shadowed + towards * SECTION_LIT_AT;
    let (u_range, y_range) = ((-1.5f32, 8.0f32), (-1.2f32, 3.6f32));
    let blocks: Vec<(Vec3, Vec3)> = f.level.blocks.iter().map(block_box).collect();
    // The props and the player touch neither ray, nor the part of the
    // section drawn: the blocks alone decide, and all of them are drawn.
    for b in model_boxes(&f) {
        for p in [shadowed, lit] {
            assert!(through_box(p, sun, b).is_none_or(|(_, out)| out < 0.0), "a model stands on a ray");
        }
        let cut = through_box(shadowed, towards, (b.0.with_y(-1.0), b.1.with_y(1.0)));
        let in_window = cut.is_some_and(|(u0, u1)| u1 > u_range.0 && u0 < u_range.1 && b.1.y > y_range.0);
        assert!(!in_window, "a model stands in the section drawn: {b:?}");
    }
    let first_surface = |p: Vec3| {
        let t = blocks.iter().filter_map(|b| through_box(p, sun, *b)).map(|(_, out)| out).fold(0.0, f32::max);
        p + sun * t
    };
    let depth = |p: Vec3| light.view_proj.project_point3(p).z;
    let texel = |p: Vec3| {
        let clip = light.view_proj.project_point3(p);
        let size = shadow_map::DEFAULT_SIZE as f32;
        (((clip.x * 0.5 + 0.5) * size) as u32, ((0.5 - clip.y * 0.5) * size) as u32)
    };

    let mut svg = Svg::new(640.0, 420.0);
    let panel = Panel::new(
        (Vec2::new(-u_range.1, y_range.0), Vec2::new(-u_range.0, y_range.1)),
        Vec2::new(20.0, 40.0),
        Vec2::new(600.0, 260.0),
    );
    // Picture x grows away from the sun: the sun is on the left.
    let at = |p: Vec3| panel.at(Vec2::new(-(p - shadowed).dot(towards), p.y));
    let in_plane = |u: f32, y: f32| shadowed + towards * u + Vec3::Y * y;
    let (corner_a, corner_b) = (at(in_plane(u_range.1, y_range.1)), at(in_plane(u_range.0, y_range.0)));
    svg.clip(corner_a.x, corner_a.y, corner_b.x - corner_a.x, corner_b.y - corner_a.y);
    for &(low, high) in &blocks {
        // The block cut by the plane: the part of the line where it runs
        // inside the block's footprint, from its bottom to its top.
        let Some((u0, u1)) = through_box(shadowed, towards, (low.with_y(-1.0), high.with_y(1.0))) else { continue };
        let rect = [in_plane(u0, low.y), in_plane(u1, low.y), in_plane(u1, high.y), in_plane(u0, high.y)];
        svg.polygon(&rect.map(at), "#d9d3c7", "#a9a190");
    }
    for (p, colour, name) in [(lit, BLUE, "A"), (shadowed, ACCENT, "B")] {
        // From the sun to the first surface, then on (dashed) behind it.
        let hit = first_surface(p);
        svg.line(at(hit), at(hit + sun * 40.0), colour, 1.6);
        if hit.distance(p) > 0.01 {
            svg.dashed(at(hit), at(p), colour);
            svg.circle(at(hit), 5.0, colour);
        }
        svg.circle(at(p), 5.0, colour);
        svg.text(at(p) + Vec2::new(8.0, -8.0), name, 13.0, "start", colour);
    }
    svg.unclip();
    svg.rect(corner_a.x, corner_a.y, corner_b.x - corner_a.x, corner_b.y - corner_a.y, "none", MUTED);

    // Labels: what the map stored along each ray, and each point's depth.
    let metres = |d: f32| d * light.depth;
    let stored_s = depth(first_surface(shadowed));
    let (own_s, own_l, stored_l) = (depth(shadowed), depth(lit), depth(first_surface(lit)));
    let hit_s = at(first_surface(shadowed));
    svg.text(hit_s + Vec2::new(18.0, -34.0), "first on B's ray: the platform's top,", 11.0, "start", ACCENT);
    svg.text(
        hit_s + Vec2::new(18.0, -20.0),
        &format!("stored in B's texel: {:.4} ({:.2} m)", stored_s, metres(stored_s)),
        11.0,
        "start",
        ACCENT,
    );
    let (tl, ts) = (texel(lit), texel(shadowed));
    svg.text(
        at(shadowed) + Vec2::new(-10.0, 22.0),
        &format!("B: depth {own_s:.4} ({:.2} m)", metres(own_s)),
        11.0,
        "end",
        ACCENT,
    );
    svg.text(
        at(lit) + Vec2::new(-10.0, 22.0),
        &format!("A: depth {own_l:.4} ({:.2} m)", metres(own_l)),
        11.0,
        "end",
        BLUE,
    );
    let towards_sun_label = at(in_plane(u_range.1 - 0.3, y_range.1 - 0.5));
    let away = format!("← towards the sun: the box's near face is {:.0} m from A along its ray", metres(own_l));
    svg.text(towards_sun_label, &away, 11.0, "start", MUTED);
    svg.text(at(in_plane(u_range.0 + 0.2, -0.9)), "the ground", 11.0, "end", MUTED);
    assert!(own_l <= stored_l && own_s > stored_s, "the figure's points are no longer lit and shadowed");
    let lines = [
        (
            format!(
                "A, texel {tl:?}: the ray's first surface is A itself; stored {stored_l:.4} ≥ A's {own_l:.4}: lit (1)"
            ),
            BLUE,
        ),
        (
            format!(
                "B, texel {ts:?}: stored {stored_s:.4} < B's {own_s:.4}; B is {:.2} m behind: shadowed (0)",
                metres(own_s - stored_s)
            ),
            ACCENT,
        ),
        (
            format!(
                "Depths are fractions of the sun's box, {:.1} m from its face nearest the sun to its far face;",
                light.depth
            ),
            INK,
        ),
        ("the comparison is the sampler's LessEqual: lit where the point's depth ≤ the stored one.".to_string(), INK),
    ];
    for (i, (line, colour)) in lines.iter().enumerate() {
        svg.text(Vec2::new(20.0, 336.0 + 18.0 * i as f32), line, 11.0, "start", colour);
    }
    let title = format!(
        "A section through the level along the sun's rays, default view at {} s, sun at {:.0}°: no bias",
        ShadowsChapter::SNAPSHOT_TIME,
        sun.y.asin().to_degrees()
    );
    svg.text(Vec2::new(20.0, 24.0), &title, 11.0, "start", INK);
    svg.finish()
}

/// Chapter 10: how `fit_light` builds the sun's box for the chapter's
/// default picture, in four panels: what the camera sees (the eight
/// points), the same seen from the sun with the sphere and the square
/// around it, the box's depth from the side, and the snap to whole texels
/// (this frame and the next). The box is the one `fit_light` returned;
/// the sphere's centre and reach, recomputed here, are checked against it.
pub fn light_box_fit() -> String {
    let time = ShadowsChapter::SNAPSHOT_TIME;
    let f = fitted_at(time);
    let light = f.light;
    let frame = BoxFrame::of(&light);
    let size = shadow_map::DEFAULT_SIZE as f32;
    let radius = light.texel * size / 2.0;
    // The sphere: around the middle of the points' bounding box, reaching
    // the farthest point; its radius rounded up to half a metre.
    let (low, high) = f.visible.iter().fold((Vec3::MAX, Vec3::MIN), |(lo, hi), p| (lo.min(*p), hi.max(*p)));
    let centre = (low + high) / 2.0;
    let reach = f.visible.iter().map(|p| p.distance(centre)).fold(0.0, f32::max);
    assert_eq!((reach * 2.0).ceil() / 2.0, radius, "fit_light's radius is not the sphere's");
    // The box's depth: from the caster nearest the sun to the point
    // farthest from it, a metre more at each end.
    let casters = box_corners(f.bounds);
    let depths = casters.iter().chain(&f.visible).map(|p| frame.at(*p).z);
    let (nearest, farthest) = depths.fold((f32::MAX, f32::MIN), |(n, x), d| (n.min(d), x.max(d)));
    assert!((nearest - 1.0).abs() < 0.01 && (light.depth - farthest - 1.0).abs() < 0.01, "margins changed");

    let mut svg = Svg::new(640.0, 700.0);
    let size_of = Vec2::new(300.0, 220.0);
    let origins = [Vec2::new(15.0, 44.0), Vec2::new(325.0, 44.0), Vec2::new(15.0, 390.0), Vec2::new(325.0, 390.0)];
    let titles = [
        "1 · What the camera sees",
        "2 · Seen from the sun: a sphere, a square",
        "3 · Depth: every caster, a metre to spare",
        "4 · The centre snapped to whole texels",
    ];
    for (origin, title) in origins.iter().zip(titles) {
        svg.rect(origin.x, origin.y, size_of.x, size_of.y, "#ffffff", "#d8d2c6");
        svg.text(*origin - Vec2::new(0.0, 8.0), title, 12.0, "start", INK);
    }
    let quad = [0, 1, 3, 2];
    let caption = |svg: &mut Svg, origin: Vec2, lines: &[String]| {
        for (i, line) in lines.iter().enumerate() {
            svg.text(origin + Vec2::new(0.0, size_of.y + 18.0 + 15.0 * i as f32), line, 11.0, "start", INK);
        }
    };

    // 1: the world from the side, z to the right (the camera), y up. The
    // eight points: where the view's corner rays cross the level's front
    // face (z = +4) and back face (z = −4); from the side, its left and
    // right corners fall on one another.
    {
        let o = origins[0];
        let side = |p: Vec3| Vec2::new(p.z, p.y);
        let (lo, hi) = f
            .visible
            .iter()
            .chain([&f.eye])
            .fold((Vec2::MAX, Vec2::MIN), |(lo, hi), p| (lo.min(side(*p)), hi.max(side(*p))));
        let panel = Panel::new((lo - Vec2::splat(1.5), hi + Vec2::splat(1.5)), o, size_of);
        let at = |p: Vec3| panel.at(side(p));
        svg.clip(o.x, o.y, size_of.x, size_of.y);
        for block in &f.level.blocks {
            let (l, h) = block_box(block);
            let profile = [l, Vec3::new(l.x, l.y, h.z), h, Vec3::new(l.x, h.y, l.z)];
            svg.polygon(&profile.map(at), "#e6e0d4", "#d3cbbb");
        }
        let eye = at(f.eye);
        for i in 4..8 {
            svg.dashed(eye, at(f.visible[i]), MUTED);
        }
        for (face, colour) in [(0, ACCENT), (4, BLUE)] {
            svg.line(at(f.visible[face]), at(f.visible[face + 2]), colour, 2.0);
            for i in [face, face + 2] {
                svg.circle(at(f.visible[i]), 3.5, colour);
            }
        }
        svg.circle(eye, 4.0, INK);
        svg.text(eye + Vec2::new(-8.0, -8.0), "camera", 11.0, "end", INK);
        svg.text(at(f.visible[2]) + Vec2::new(5.0, -8.0), "z = +4", 11.0, "start", ACCENT);
        svg.text(at(f.visible[6]) + Vec2::new(-5.0, -8.0), "z = −4", 11.0, "end", BLUE);
        let base = o + Vec2::new(size_of.x - 60.0, size_of.y - 12.0);
        let to_sun = (at(f.towards_sun) - at(Vec3::ZERO)).normalize();
        svg.arrow(base, base + to_sun * 36.0, "#b38b14");
        svg.text(base + Vec2::new(-6.0, -4.0), "to the sun", 11.0, "end", "#b38b14");
        svg.unclip();
        let widths = [0, 2, 4, 6].map(|i| f.visible[i + 1].x - f.visible[i].x);
        let (narrowest, widest) = widths.iter().fold((f32::MAX, f32::MIN), |(lo, hi), w| (lo.min(*w), hi.max(*w)));
        caption(
            &mut svg,
            o,
            &[
                "the view's corner rays cross the level's front".to_string(),
                format!("(z = +{} m, red) and back (z = −{} m, blue) faces:", f.bounds.1.z, f.bounds.1.z),
                format!("eight points, in pairs {narrowest:.1} to {widest:.1} m apart across"),
            ],
        );
    }

    // 2: the map's plane, as the sun sees it.
    {
        let o = origins[1];
        let flat = |p: Vec3| frame.at(p).truncate();
        let margin = Vec2::splat(0.12 * radius);
        let panel = Panel::new((-margin, Vec2::splat(2.0 * radius) + margin), o, size_of);
        svg.clip(o.x, o.y, size_of.x, size_of.y);
        for block in &f.level.blocks {
            let outline: Vec<Vec2> =
                hull(&box_corners(block_box(block)).map(flat)).into_iter().map(|p| panel.at(p)).collect();
            svg.polygon(&outline, "#e6e0d4", "#d3cbbb");
        }
        let c = panel.at(flat(centre));
        svg.dashed_ring(c, reach * panel.scale, MUTED);
        let square =
            [Vec2::ZERO, Vec2::new(2.0 * radius, 0.0), Vec2::splat(2.0 * radius), Vec2::new(0.0, 2.0 * radius)];
        svg.polygon(&square.map(|p| panel.at(p)), "none", "#b38b14");
        let front: Vec<Vec2> = quad.iter().map(|&i| panel.at(flat(f.visible[i]))).collect();
        let back: Vec<Vec2> = quad.iter().map(|&i| panel.at(flat(f.visible[i + 4]))).collect();
        svg.polygon(&back, "none", BLUE);
        svg.polygon(&front, "none", ACCENT);
        svg.circle(c, 3.0, INK);
        svg.line(c, c + Vec2::new(reach * panel.scale, 0.0), MUTED, 1.0);
        svg.text(c + Vec2::new(reach * panel.scale / 2.0, 14.0), &format!("{reach:.2} m"), 11.0, "middle", INK);
        svg.unclip();
        let axes = o + Vec2::new(size_of.x - 44.0, size_of.y - 12.0);
        svg.arrow(axes, axes + Vec2::new(28.0, 0.0), INK);
        svg.arrow(axes, axes - Vec2::new(0.0, 28.0), INK);
        svg.text(axes + Vec2::new(30.0, -4.0), "x", 11.0, "start", INK);
        svg.text(axes + Vec2::new(-4.0, -26.0), "y", 11.0, "end", INK);
        caption(
            &mut svg,
            o,
            &[
                format!("the farthest point is {reach:.2} m from the points' middle;"),
                format!("rounded up to {radius} m: a square {} m wide,", 2.0 * radius),
                format!("{} texels of {:.2} cm (the level's blocks in grey);", size as u32, light.texel * 100.0),
                "the map's x is level, its y as near to up as it can be".to_string(),
            ],
        );
    }

    // The box's depth over the whole demo, frame by frame at 60 Hz.
    assert_eq!(fitted_at(DEMO_SECONDS as f32).game.player.velocity, Vec2::ZERO, "the demo runs longer");
    let demo_depths = (0..=DEMO_SECONDS * 60)
        .map(|frame| fitted_at(frame as f32 / 60.0).light.depth)
        .fold((f32::MAX, f32::MIN), |(lo, hi), d| (lo.min(d), hi.max(d)));

    // 3: the box from its side: depth from the sun to the right, the map's
    // x up. Its depth spans the whole level, its width only the view.
    {
        let o = origins[2];
        let side = |p: Vec3| Vec2::new(frame.at(p).z, frame.at(p).x);
        let level_outline: Vec<Vec2> = hull(&casters.map(side));
        let (lo, hi) = level_outline
            .iter()
            .fold((Vec2::new(-6.0, 0.0), Vec2::new(light.depth, 2.0 * radius)), |(lo, hi), p| (lo.min(*p), hi.max(*p)));
        let panel = Panel::new((lo - Vec2::splat(3.0), hi + Vec2::splat(3.0)), o, size_of);
        svg.polygon(&level_outline.iter().map(|p| panel.at(*p)).collect::<Vec<_>>(), "#e6e0d4", "#a9a190");
        let view: Vec<Vec2> = hull(&f.visible.map(side)).into_iter().map(|p| panel.at(p)).collect();
        svg.polygon(&view, "#f1d9cd", ACCENT);
        let corners = [
            Vec2::ZERO,
            Vec2::new(light.depth, 0.0),
            Vec2::new(light.depth, 2.0 * radius),
            Vec2::new(0.0, 2.0 * radius),
        ];
        svg.polygon(&corners.map(|p| panel.at(p)), "none", "#b38b14");
        for d in [0.0, light.depth] {
            svg.dashed(panel.at(Vec2::new(d, lo.y)), panel.at(Vec2::new(d, hi.y)), "#b38b14");
        }
        svg.text(panel.at(Vec2::new(0.0, hi.y)) + Vec2::new(4.0, 2.0), "near", 11.0, "start", "#b38b14");
        svg.text(panel.at(Vec2::new(light.depth, hi.y)) + Vec2::new(-4.0, 2.0), "far", 11.0, "end", "#b38b14");
        let mid = panel.at(Vec2::new(-2.0, lo.y + 4.0));
        svg.arrow(mid, mid + Vec2::new(36.0, 0.0), "#b38b14");
        svg.text(mid + Vec2::new(0.0, -8.0), "sunlight", 11.0, "start", "#b38b14");
        caption(
            &mut svg,
            o,
            &[
                "every caster: the level's bounds (grey); the view (red);".to_string(),
                format!("near and far 1 m beyond them: {:.1} m deep here,", light.depth),
                format!("{:.1} to {:.1} m over the demo", demo_depths.0, demo_depths.1),
            ],
        );
    }

    // 4: the box's centre, this frame and 1/60 s later, before and after
    // snapping, on the grid of texel edges (this frame's box).
    {
        let o = origins[3];
        let next = fitted_at(time + 1.0 / 60.0);
        let next_centre = {
            let (lo, hi) = next.visible.iter().fold((Vec3::MAX, Vec3::MIN), |(lo, hi), p| (lo.min(*p), hi.max(*p)));
            (lo + hi) / 2.0
        };
        let box_centre = |l: &LightBox| {
            let c = l.corners();
            (c[0] + c[7]) / 2.0
        };
        // In texels, on this frame's grid.
        let texels = |p: Vec3| frame.at(p).truncate() / light.texel;
        let points =
            [(texels(centre), texels(box_centre(&light))), (texels(next_centre), texels(box_centre(&next.light)))];
        let moved = points[1].1 - points[0].1;
        assert!((moved - moved.round()).abs().max_element() < 0.05, "the box moved {moved} texels");
        let (lo, hi) =
            points.iter().fold((Vec2::MAX, Vec2::MIN), |(lo, hi), (a, b)| (lo.min(*a).min(*b), hi.max(*a).max(*b)));
        let (lo, hi) = ((lo - Vec2::splat(1.0)).floor(), (hi + Vec2::splat(1.0)).ceil());
        let panel = Panel::new((lo, hi), o + Vec2::new(10.0, 10.0), size_of - Vec2::new(20.0, 20.0));
        for x in lo.x as i32..=hi.x as i32 {
            svg.line(panel.at(Vec2::new(x as f32, lo.y)), panel.at(Vec2::new(x as f32, hi.y)), "#e3dccf", 1.0);
        }
        for y in lo.y as i32..=hi.y as i32 {
            svg.line(panel.at(Vec2::new(lo.x, y as f32)), panel.at(Vec2::new(hi.x, y as f32)), "#e3dccf", 1.0);
        }
        for ((smooth, snapped), colour) in points.iter().zip([ACCENT, BLUE]) {
            svg.arrow(panel.at(*smooth), panel.at(*snapped), colour);
            svg.ring(panel.at(*smooth), 4.0, colour, 1.5);
            svg.circle(panel.at(*snapped), 4.0, colour);
        }
        let offset = (points[0].0 - points[0].1) * light.texel * 100.0;
        let slid = points[1].0 - points[0].0;
        caption(
            &mut svg,
            o,
            &[
                format!("grid: texels of {:.2} cm; ring: the sphere's centre;", light.texel * 100.0),
                format!("dot: the box's, snapped {:.2}, {:.2} cm to a corner.", offset.x.abs(), offset.y.abs()),
                format!(
                    "1/60 s on (blue): ring +{:.2}, +{:.2}; box +{}, +{} texels",
                    slid.x,
                    slid.y,
                    moved.x.round(),
                    moved.y.round()
                ),
            ],
        );
    }
    svg.text(
        Vec2::new(20.0, 18.0),
        &format!("fit_light, step by step, for the default view at {time} s (map {}²)", size as u32),
        11.0,
        "start",
        MUTED,
    );
    svg.finish()
}

/// Chapter 10: the lantern's cube shadow map, in a section of the level
/// through the lantern (the plane z = the lantern's z): the four faces
/// whose frustums this plane cuts (the 90° wedges between the diagonals;
/// +z and −z look out of the page and into it), and two lookups, each
/// along the direction from the light. Q, on the inner face of the
/// tunnel's left pillar, is what chapter 08's lamps lit through the
/// ceiling: the texel its direction reads holds the ceiling's distance,
/// far less than Q's. P, on the ground in the open, reads its own. The
/// faces and places on them come from `CubeFace::lookup`; the distances
/// from the level's blocks. On the right, the six faces unfolded as the
/// `cube-shadow-map` view draws them, with the two texels marked.
pub fn cube_shadow_map() -> String {
    let level = game::level();
    let lantern = scene::lantern_light(&level);
    let light = lantern.position;
    // The blocks this section cuts, as rectangles in x and y.
    let section: Vec<(Vec2, Vec2)> = level
        .blocks
        .iter()
        .filter(|b| (-b.depth..=b.depth).contains(&light.z))
        .map(|b| (b.aabb.min, b.aabb.max))
        .collect();
    // How far along the ray from the light towards `p` the first block is, in metres.
    let first_hit = |p: Vec3| -> f32 {
        let d = (p - light).truncate();
        let origin = light.truncate();
        let inverse = d.recip();
        section
            .iter()
            .filter_map(|(low, high)| {
                let t0 = (*low - origin) * inverse;
                let t1 = (*high - origin) * inverse;
                let (near, far) = (t0.min(t1).max_element(), t0.max(t1).min_element());
                (far >= near && near > 0.0).then_some(near)
            })
            .fold(1.0f32, f32::min)
            * d.length()
    };
    let ceiling = section
        .iter()
        .find(|(low, high)| low.x <= light.x && light.x <= high.x && low.y > light.y)
        .expect("the tunnel's ceiling above the lantern");
    let pillar = section
        .iter()
        .find(|(low, high)| low.y == ceiling.1.y && high.x <= light.x)
        .expect("the pillar on the ceiling's left end");
    let q = Vec3::new(pillar.1.x, (pillar.0.y + pillar.1.y) / 2.0, light.z);
    let p = Vec3::new(light.x + 3.0, 0.0, light.z);
    let (q_stored, p_stored) = (first_hit(q), first_hit(p));
    let (q_own, p_own) = (q.distance(light), p.distance(light));
    assert!(q_stored < q_own - 1.0, "the ceiling stands between the lantern and Q");
    assert!((p_stored - p_own).abs() < 1e-3, "nothing stands between the lantern and P");
    let (q_face, q_st) = CubeFace::lookup(q - light);
    let (p_face, p_st) = CubeFace::lookup(p - light);

    let mut svg = Svg::new(780.0, 330.0);
    // The section: x from 38 to 52 m, y from −0.6 to 5 m, 30 px a metre.
    let (left, top, scale) = (24.0f32, 70.0f32, 30.0f32);
    let (x0, x1, y0, y1) = (38.0f32, 52.5f32, -0.6f32, 5.0f32);
    let at = |x: f32, y: f32| Vec2::new(left + (x - x0) * scale, top + (y1 - y) * scale);
    let (w, h) = ((x1 - x0) * scale, (y1 - y0) * scale);
    svg.clip(left, top, w, h);
    for (low, high) in &section {
        let (a, b) = (at(low.x, high.y), at(high.x, low.y));
        svg.rect(a.x, a.y, b.x - a.x, b.y - a.y, "#d9d4cb", MUTED);
    }
    // The four wedges: the diagonals through the light bound them.
    let centre = at(light.x, light.y);
    for (dx, dy) in [(1.0, 1.0), (1.0, -1.0)] {
        let d = Vec2::new(dx, -dy) * 600.0;
        svg.dashed(centre - d, centre + d, BLUE);
    }
    // The cube itself, small, around the light.
    svg.rect(centre.x - 9.0, centre.y - 9.0, 18.0, 18.0, "none", BLUE);
    // Q: stored distance solid, the rest dashed; P: all solid.
    let q_hit = light + (q - light) * (q_stored / q_own);
    svg.line(centre, at(q_hit.x, q_hit.y), ACCENT, 2.0);
    svg.dashed(at(q_hit.x, q_hit.y), at(q.x, q.y), ACCENT);
    svg.line(centre, at(p.x, p.y), INK, 2.0);
    svg.unclip();
    svg.rect(left, top, w, h, "none", MUTED);
    svg.circle(centre, 4.5, "#e0a030");
    svg.circle(at(q.x, q.y), 4.0, ACCENT);
    svg.circle(at(q_hit.x, q_hit.y), 3.0, ACCENT);
    svg.circle(at(p.x, p.y), 4.0, INK);
    svg.text(at(q.x, q.y) + Vec2::new(-8.0, -6.0), "Q", 13.0, "end", ACCENT);
    svg.text(at(p.x, p.y) + Vec2::new(6.0, -8.0), "P", 13.0, "start", INK);
    let label = |svg: &mut Svg, face: CubeFace, offset: Vec2| {
        svg.text(centre + offset, &format!("{} face", face_name(face)), 11.0, "middle", BLUE);
    };
    label(&mut svg, CubeFace::PosX, Vec2::new(150.0, 4.0));
    label(&mut svg, CubeFace::NegX, Vec2::new(-150.0, 40.0));
    label(&mut svg, CubeFace::PosY, Vec2::new(0.0, -70.0));
    label(&mut svg, CubeFace::NegY, Vec2::new(40.0, 52.0));
    svg.text(
        Vec2::new(left, top - 24.0),
        &format!("The level cut through the lantern (orange; z = {} m, range {} m)", light.z, lantern.range),
        11.0,
        "start",
        INK,
    );
    svg.text(Vec2::new(left, top - 10.0), "+z and −z face out of the page and into it", 11.0, "start", MUTED);
    let lines = [
        (
            format!(
                "Q, on the pillar: {} face at s {:.2}, t {:.2}; stored {:.2} m, Q is {:.2} m away: shadowed",
                face_name(q_face),
                q_st.x,
                q_st.y,
                q_stored,
                q_own
            ),
            ACCENT,
        ),
        (
            format!(
                "P, on the ground: {} face at s {:.2}, t {:.2}; stored {:.2} m, P is {:.2} m away: lit",
                face_name(p_face),
                p_st.x,
                p_st.y,
                p_stored,
                p_own
            ),
            INK,
        ),
    ];
    for (i, (text, colour)) in lines.iter().enumerate() {
        svg.text(Vec2::new(left, top + h + 24.0 + 16.0 * i as f32), text, 11.0, "start", colour);
    }

    // The cross: +y above +z, −y below it, −x +z +x −z across the middle.
    let (cx, cy, side) = (500.0f32, 90.0f32, 62.0f32);
    let cells = [
        (CubeFace::PosY, 1.0, 0.0),
        (CubeFace::NegX, 0.0, 1.0),
        (CubeFace::PosZ, 1.0, 1.0),
        (CubeFace::PosX, 2.0, 1.0),
        (CubeFace::NegZ, 3.0, 1.0),
        (CubeFace::NegY, 1.0, 2.0),
    ];
    let corner = |face: CubeFace| {
        let (_, column, row) = cells.iter().find(|(f, _, _)| *f == face).expect("every face has a cell");
        Vec2::new(cx + column * side, cy + row * side)
    };
    for (face, _, _) in cells {
        let c = corner(face);
        svg.rect(c.x, c.y, side, side, "#eef1f6", BLUE);
        svg.text(c + Vec2::new(side / 2.0, side / 2.0 + 4.0), face_name(face), 12.0, "middle", BLUE);
    }
    for (face, st, colour, name) in [(q_face, q_st, ACCENT, "Q"), (p_face, p_st, INK, "P")] {
        let mark = corner(face) + st * side;
        svg.circle(mark, 4.0, colour);
        svg.text(mark + Vec2::new(6.0, -5.0), name, 12.0, "start", colour);
    }
    svg.text(Vec2::new(cx, cy - 20.0), "the six faces, unfolded (s right, t down)", 11.0, "start", INK);
    svg.text(Vec2::new(cx, cy + 3.0 * side + 22.0), "each face as seen from outside the cube:", 11.0, "start", MUTED);
    svg.text(Vec2::new(cx, cy + 3.0 * side + 38.0), "a mirror image of a camera's view", 11.0, "start", MUTED);
    svg.finish()
}

/// A face's name as the page writes it: +x, −x, …
fn face_name(face: CubeFace) -> &'static str {
    match face {
        CubeFace::PosX => "+x",
        CubeFace::NegX => "−x",
        CubeFace::PosY => "+y",
        CubeFace::NegY => "−y",
        CubeFace::PosZ => "+z",
        CubeFace::NegZ => "−z",
    }
}
