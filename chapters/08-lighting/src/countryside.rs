//! The countryside around the city, as the city project had it: ground
//! from a height function, coloured sand near the water and grass above; a
//! river whose water rises and falls with sine "tides" of scene time;
//! trees (the tree model chapter 10 stands in its level, read from the same
//! OBJ file); and rural roads leaving the city, on a bridge over the river.
//! Nothing here touches the GPU: the chapter draws its meshes and pieces
//! with the city's.

use std::f32::consts::TAU;

use common::glam::{Mat4, Quat, Vec2, Vec3};
use common::noise::Fbm;
use common::rng::Rng;
use common::{MeshData, Vertex};

use crate::city::{GRASS, HALF, Material, Piece, ROAD_WIDTH, SAND, Shape};
use crate::lights::smoothstep;

/// The city's ground ends this far from its middle, both ways (city.rs
/// lays a ground 40 m wider than its roads); the countryside starts there.
pub const CITY_EDGE: f32 = HALF + 20.0;
/// The countryside runs to this far from the middle, both ways.
pub const WORLD_HALF: f32 = 1000.0;
/// The ground mesh's grid spacing, metres.
pub const CELL: f32 = 10.0;

// ANCHOR: tide
/// The river's water level halfway between the tides, metres (the city's
/// ground is at 0).
pub const MEAN_LEVEL: f32 = -3.0;
/// How far the water rises above the mean and falls below it.
pub const TIDE_AMPLITUDE: f32 = 0.8;
/// Seconds from one high tide to the next: a scene's tides are fast.
pub const TIDE_PERIOD: f32 = 40.0;

/// The river's level at scene time `time`: a sine about the mean, so the
/// water climbs the beaches and falls back, the same at the same time.
pub fn water_level(time: f32) -> f32 {
    MEAN_LEVEL + TIDE_AMPLITUDE * (TAU * time / TIDE_PERIOD).sin()
}
// ANCHOR_END: tide

// ANCHOR: colour
/// Sand (city.rs's `SAND`) up to a little above the highest tide, grass
/// (`GRASS`) from a metre and a bit higher, blended between.
pub const SAND_UP_TO: f32 = MEAN_LEVEL + TIDE_AMPLITUDE + 0.6;
pub const GRASS_FROM: f32 = SAND_UP_TO + 1.2;

/// The ground's colour at `height`: a function of height alone, as the
/// city project's was. `city.wgsl` blends the same two colours with the
/// same smoothstep for the countryside's material.
pub fn ground_colour(height: f32) -> Vec3 {
    SAND.lerp(GRASS, smoothstep(SAND_UP_TO, GRASS_FROM, height))
}
// ANCHOR_END: colour

/// The river's half-width at its bed, and how wide each bank is.
const RIVER_BED_HALF: f32 = 18.0;
const BANK: f32 = 70.0;
const RIVER_BED: f32 = -7.0;
/// Hills rise to about this many metres.
const HILL_HEIGHT: f32 = 30.0;
/// The road deck stays this high over the river: 2.5 m above the highest tide.
pub const BRIDGE_DECK: f32 = MEAN_LEVEL + TIDE_AMPLITUDE + 2.5;

/// Where the river runs: north of the city, winding east to west.
pub fn river_z(x: f32) -> f32 {
    -430.0 + 55.0 * (x / 170.0).sin()
}

/// A road from the city's edge straight out to the world's edge.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RuralRoad {
    /// Where it leaves the city, at the end of one of its streets.
    pub from: Vec2,
    /// Unit, along x or z.
    pub direction: Vec2,
}

impl RuralRoad {
    /// Metres from `p` to the road's centre line (to its start, behind it).
    pub fn distance(&self, p: Vec2) -> f32 {
        let along = (p - self.from).dot(self.direction);
        if along < 0.0 { p.distance(self.from) } else { (p - self.from - self.direction * along).length() }
    }

    pub fn length(&self) -> f32 {
        WORLD_HALF - self.from.dot(self.direction)
    }
}

/// Four roads, each the continuation of one of the city's streets: north
/// along x = 0 (over the river), south along x = −120, east along
/// z = 60, west along z = 0. City streets end 6 m past the last line.
pub const RURAL_ROADS: [RuralRoad; 4] = {
    let end = HALF + ROAD_WIDTH / 2.0;
    [
        RuralRoad { from: Vec2::new(0.0, -end), direction: Vec2::new(0.0, -1.0) },
        RuralRoad { from: Vec2::new(-120.0, end), direction: Vec2::new(0.0, 1.0) },
        RuralRoad { from: Vec2::new(end, 60.0), direction: Vec2::new(1.0, 0.0) },
        RuralRoad { from: Vec2::new(-end, 0.0), direction: Vec2::new(-1.0, 0.0) },
    ]
};

/// Metres from `p` to the nearest rural road's centre line.
pub fn road_distance(p: Vec2) -> f32 {
    RURAL_ROADS.iter().map(|r| r.distance(p)).fold(f32::INFINITY, f32::min)
}

/// Where the billboard's hill stands, north of the river, facing the city.
pub const BILLBOARD_HILL: Vec2 = Vec2::new(90.0, -600.0);
const BILLBOARD_HILL_HEIGHT: f32 = 22.0;
const BILLBOARD_HILL_RADIUS: f32 = 90.0;

// ANCHOR: height
/// The ground's height at `p` = (x, z): level with the city at its edge,
/// rising into fBm hills (chapter 03's noise) further out, flattened along
/// the roads, and carved down to the river's bed along its course.
pub fn height(p: Vec2) -> f32 {
    const HILLS: Fbm = Fbm { octaves: 4, persistence: 0.5, lacunarity: 2.0 };
    let outside = (p.x.abs().max(p.y.abs()) - CITY_EDGE).max(0.0);
    let rise = smoothstep(0.0, 160.0, outside);
    let across = (p.y - river_z(p.x)).abs();
    let noise = HILLS.sample(f64::from(p.x / 300.0), f64::from(p.y / 300.0), 0.37) as f32;
    let hills = HILL_HEIGHT
        * smoothstep(-0.2, 0.45, noise)
        * smoothstep(ROAD_WIDTH / 2.0 + 4.0, ROAD_WIDTH / 2.0 + 60.0, road_distance(p))
        * smoothstep(RIVER_BED_HALF + BANK, RIVER_BED_HALF + BANK + 150.0, across);
    let bump = (-(p.distance_squared(BILLBOARD_HILL)) / (BILLBOARD_HILL_RADIUS * BILLBOARD_HILL_RADIUS)).exp();
    let land = rise * (1.0 + hills) + BILLBOARD_HILL_HEIGHT * bump;
    let bank = smoothstep(RIVER_BED_HALF, RIVER_BED_HALF + BANK, across);
    RIVER_BED + (land - RIVER_BED) * bank
}
// ANCHOR_END: height

/// The countryside: its ground, its trees and its roads.
pub struct Countryside {
    /// The ground as one mesh in world space, with a hole where the city is.
    pub ground: MeshData,
    /// Each tree's placement (the model stands on y = 0, 4.5 m tall).
    pub trees: Vec<Mat4>,
    /// Rural roads (boxes along the ground, over the river on a deck) and
    /// the bridge's piers.
    pub pieces: Vec<Piece>,
}

impl Countryside {
    /// The same every time.
    pub fn new() -> Self {
        Self { ground: ground_mesh(), trees: trees(), pieces: road_pieces() }
    }

    /// The river's water at scene time `time`: one flat sheet over the
    /// whole world at the tide's level; the ground hides it everywhere but
    /// the river (and the city's ground, 2 m above the highest tide).
    pub fn water(time: f32) -> Piece {
        let size = 2.0 * WORLD_HALF;
        Piece {
            shape: Shape::Ground,
            model: Mat4::from_translation(Vec3::Y * water_level(time)) * Mat4::from_scale(Vec3::new(size, 1.0, size)),
            material: Material::Water,
        }
    }
}

impl Default for Countryside {
    fn default() -> Self {
        Self::new()
    }
}

// ANCHOR: ground
/// A grid of `CELL`-metre squares over the world, heights from [`height`],
/// normals from the differences of neighbouring heights, leaving out the
/// squares under the city's own ground.
fn ground_mesh() -> MeshData {
    let n = (2.0 * WORLD_HALF / CELL) as usize;
    let at = |i: usize| -WORLD_HALF + i as f32 * CELL;
    let heights: Vec<f32> =
        (0..=n).flat_map(|row| (0..=n).map(move |col| height(Vec2::new(at(col), at(row))))).collect();
    let h = |col: usize, row: usize| heights[row * (n + 1) + col];
    let mut mesh = MeshData::default();
    for row in 0..=n {
        for col in 0..=n {
            // Central differences (one-sided at the world's edge).
            let (l, r) = (col.saturating_sub(1), (col + 1).min(n));
            let (u, d) = (row.saturating_sub(1), (row + 1).min(n));
            let dx = (h(r, row) - h(l, row)) / ((r - l) as f32 * CELL);
            let dz = (h(col, d) - h(col, u)) / ((d - u) as f32 * CELL);
            mesh.vertices.push(Vertex {
                position: [at(col), h(col, row), at(row)],
                normal: Vec3::new(-dx, 1.0, -dz).normalize().into(),
                uv: [col as f32, row as f32],
            });
        }
    }
    let index = |col: usize, row: usize| (row * (n + 1) + col) as u32;
    let inside = |x: f32| x >= -CITY_EDGE && x + CELL <= CITY_EDGE;
    for row in 0..n {
        for col in 0..n {
            if inside(at(col)) && inside(at(row)) {
                continue;
            }
            let [a, b, c, d] = [index(col, row), index(col + 1, row), index(col, row + 1), index(col + 1, row + 1)];
            mesh.indices.extend([a, c, b, b, c, d]);
        }
    }
    mesh
}
// ANCHOR_END: ground

/// Half a road's width plus this margin is kept clear of trees.
pub const TREE_ROAD_CLEARANCE: f32 = ROAD_WIDTH / 2.0 + 6.0;

// ANCHOR: trees
/// Trees on a jittered 45 m grid, as a planner would lay them out and
/// nature would spoil it: only on grass (so never in the river or on its
/// beaches), never on a road or within 6 m of one, never in the city or on
/// the billboard's hilltop; each turned and sized at random (fixed seed).
fn trees() -> Vec<Mat4> {
    let mut rng = Rng::new(2002);
    let mut trees = Vec::new();
    let step = 45.0;
    let mut z = -WORLD_HALF + step / 2.0;
    while z < WORLD_HALF {
        let mut x = -WORLD_HALF + step / 2.0;
        while x < WORLD_HALF {
            let p = Vec2::new(x + rng.range(-18.0, 18.0), z + rng.range(-18.0, 18.0));
            let (turn, scale, keep) = (rng.range(0.0, TAU), rng.range(1.8, 2.8), rng.unit() < 0.6);
            let ground = height(p);
            let clear = p.x.abs().max(p.y.abs()) > CITY_EDGE + 15.0
                && p.x.abs().max(p.y.abs()) < WORLD_HALF - 10.0
                && ground > GRASS_FROM + 0.5
                && road_distance(p) > TREE_ROAD_CLEARANCE
                && p.distance(BILLBOARD_HILL) > 50.0;
            if keep && clear {
                // Sunk half a metre, so that a slope shows no gap under the trunk.
                let base = Vec3::new(p.x, ground - 0.5, p.y);
                trees.push(Mat4::from_scale_rotation_translation(
                    Vec3::splat(scale),
                    Quat::from_rotation_y(turn),
                    base,
                ));
            }
            x += step;
        }
        z += step;
    }
    trees
}
// ANCHOR_END: trees

/// How long each road box is, metres.
const ROAD_STEP: f32 = 10.0;

/// Each rural road as boxes 10 m long laid on the ground (or on the deck
/// over the river), each tilted to the slope between its ends, with a
/// concrete pier under every other box of the bridge.
fn road_pieces() -> Vec<Piece> {
    let mut pieces = Vec::new();
    for road in RURAL_ROADS {
        // The highest ground across the road, so that a bank sloping
        // across it does not cover one edge.
        let side = road.direction.perp() * ROAD_WIDTH / 2.0;
        let top = |p: Vec2| height(p).max(height(p + side)).max(height(p - side)).max(BRIDGE_DECK) + 0.12;
        let mut along = 0.0;
        let mut box_index = 0;
        while along + ROAD_STEP <= road.length() {
            let (a, b) = (road.from + road.direction * along, road.from + road.direction * (along + ROAD_STEP));
            let (a3, b3) = (Vec3::new(a.x, top(a), a.y), Vec3::new(b.x, top(b), b.y));
            let forward = (b3 - a3).normalize();
            let right = Vec3::Y.cross(forward).normalize();
            let up = forward.cross(right);
            // 0.3 m thick, its top on the line, 0.4 m longer to close the joints.
            let centre = (a3 + b3) / 2.0 - up * 0.15;
            let length = a3.distance(b3) + 0.4;
            let model = Mat4::from_cols(
                (right * ROAD_WIDTH).extend(0.0),
                (up * 0.3).extend(0.0),
                (forward * length).extend(0.0),
                centre.extend(1.0),
            );
            pieces.push(Piece { shape: Shape::Cube, model, material: Material::Road });
            let middle = (a + b) / 2.0;
            let ground = height(middle);
            if ground < BRIDGE_DECK - 0.5 && box_index % 2 == 0 {
                let pier = Vec3::new(middle.x, (ground + BRIDGE_DECK) / 2.0, middle.y);
                pieces.push(Piece {
                    shape: Shape::Cylinder,
                    model: Mat4::from_scale_rotation_translation(
                        Vec3::new(1.6, BRIDGE_DECK - ground, 1.6),
                        Quat::IDENTITY,
                        pier,
                    ),
                    material: Material::Concrete,
                });
            }
            along += ROAD_STEP;
            box_index += 1;
        }
    }
    pieces
}

// ANCHOR: tree_model
/// Chapter 10's tree, read from the OBJ file `cargo xtask assets` writes
/// (`assets/models/tree/tree.obj`), embedded in the binary. Chapter 09
/// explains OBJ files; here tobj reads the two objects, the trunk and the
/// foliage, into a mesh each, and the city's own materials colour them.
pub const TREE_OBJ: &[u8] = include_bytes!(concat!(env!("CARGO_MANIFEST_DIR"), "/../../assets/models/tree/tree.obj"));

/// The tree's trunk and foliage meshes, or why the embedded file could not be read.
pub fn tree_meshes() -> Result<(MeshData, MeshData), String> {
    let options = tobj::LoadOptions { single_index: true, triangulate: true, ..Default::default() };
    // The materials come from the city's table, not from tree.mtl.
    let (models, _) = tobj::load_obj_buf(&mut &TREE_OBJ[..], &options, |_| Ok(Default::default()))
        .map_err(|e| format!("assets/models/tree/tree.obj: {e}"))?;
    let mesh = |name: &str| -> Result<MeshData, String> {
        let model = models
            .iter()
            .find(|m| m.name == name)
            .ok_or_else(|| format!("assets/models/tree/tree.obj: no object named {name}"))?;
        let m = &model.mesh;
        if m.normals.len() != m.positions.len() {
            return Err(format!("assets/models/tree/tree.obj: {name} has no normal for every vertex"));
        }
        let vertices = (0..m.positions.len() / 3)
            .map(|i| Vertex {
                position: [m.positions[3 * i], m.positions[3 * i + 1], m.positions[3 * i + 2]],
                normal: [m.normals[3 * i], m.normals[3 * i + 1], m.normals[3 * i + 2]],
                uv: m.texcoords.get(2 * i..2 * i + 2).map_or([0.0; 2], |t| [t[0], t[1]]),
            })
            .collect();
        Ok(MeshData { vertices, indices: m.indices.clone() })
    };
    Ok((mesh("trunk")?, mesh("foliage")?))
}
// ANCHOR_END: tree_model

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_tide_is_a_sine_of_time_within_its_bounds() {
        // The formula at the quarter periods, written out.
        assert_eq!(water_level(0.0), MEAN_LEVEL);
        assert!((water_level(TIDE_PERIOD / 4.0) - (MEAN_LEVEL + TIDE_AMPLITUDE)).abs() < 1e-5);
        assert!((water_level(TIDE_PERIOD / 2.0) - MEAN_LEVEL).abs() < 1e-5);
        assert!((water_level(0.75 * TIDE_PERIOD) - (MEAN_LEVEL - TIDE_AMPLITUDE)).abs() < 1e-5);
        // At the snapshots' time, 6 s: −3 + 0.8 sin(2π · 6 / 40) = −2.353 m.
        assert!((water_level(6.0) - (-2.3528)).abs() < 1e-3, "{}", water_level(6.0));
        let (low, high) = (MEAN_LEVEL - TIDE_AMPLITUDE, MEAN_LEVEL + TIDE_AMPLITUDE);
        for i in 0..2000 {
            let t = i as f32 * 0.173;
            let level = water_level(t);
            assert!((low - 1e-5..=high + 1e-5).contains(&level), "{level} at {t} s");
            assert!((water_level(t + TIDE_PERIOD) - level).abs() < 1e-3, "not periodic at {t} s");
            assert_eq!(Countryside::water(t).model.w_axis.y, level, "the water sheet is at the tide's level");
        }
        // And it stays under the city's ground, which is at 0.
        assert!(high < -1.0);
    }

    #[test]
    fn the_ground_is_sand_by_the_water_and_grass_above() {
        let high_tide = MEAN_LEVEL + TIDE_AMPLITUDE;
        for h in [RIVER_BED, MEAN_LEVEL - TIDE_AMPLITUDE, MEAN_LEVEL, high_tide, SAND_UP_TO] {
            assert_eq!(ground_colour(h), SAND, "at {h} m, at or under the highest tide's reach");
        }
        for h in [GRASS_FROM, 0.0, 1.0, 30.0] {
            assert_eq!(ground_colour(h), GRASS, "at {h} m");
        }
        // Between, a blend that only ever turns greener going up.
        let mut last = 0.0;
        for i in 0..=100 {
            let h = SAND_UP_TO + (GRASS_FROM - SAND_UP_TO) * i as f32 / 100.0;
            let green = (ground_colour(h) - SAND).length() / (GRASS - SAND).length();
            assert!(green >= last - 1e-6, "at {h} m");
            last = green;
        }
    }

    #[test]
    fn the_river_keeps_water_at_low_tide_and_has_beaches_on_both_banks() {
        let low_tide = MEAN_LEVEL - TIDE_AMPLITUDE;
        let mut x = -WORLD_HALF;
        while x <= WORLD_HALF {
            let centre = Vec2::new(x, river_z(x));
            assert!(height(centre) < low_tide - 1.0, "the river runs dry at x = {x}");
            for side in [-1.0, 1.0] {
                // Walking out from the middle: sand first, then grass.
                let heights: Vec<f32> = (0..300).map(|d| height(centre + Vec2::Y * side * d as f32)).collect();
                let sand = heights.iter().position(|&h| h > MEAN_LEVEL + TIDE_AMPLITUDE && h < SAND_UP_TO);
                let grass = heights.iter().position(|&h| h > GRASS_FROM);
                assert!(matches!((sand, grass), (Some(s), Some(g)) if s < g), "no beach at x = {x}, side {side}");
            }
            x += 25.0;
        }
        // Nowhere near the city: its ground would flood.
        assert!((-1000..=1000).step_by(5).all(|x| river_z(x as f32) + RIVER_BED_HALF + BANK < -CITY_EDGE));
    }

    #[test]
    fn the_ground_is_a_10_m_grid_with_a_hole_for_the_city() {
        let ground = ground_mesh();
        // 200 × 200 squares over the 2 km world, less the 40 × 40 under the
        // city's 400 m ground: 38,400 squares, two triangles each.
        assert_eq!(ground.indices.len() / 3, 76_800);
        assert_eq!(ground.vertices.len(), 201 * 201);
        for v in &ground.vertices {
            let p = Vec2::new(v.position[0], v.position[2]);
            assert!((v.position[1] - height(p)).abs() < 1e-5 && v.normal[1] > 0.0);
        }
    }

    #[test]
    fn trees_stand_on_grass_off_the_roads_and_out_of_the_city() {
        let trees = trees();
        // The number the book quotes.
        assert_eq!(trees.len(), 996, "{} trees", trees.len());
        for tree in &trees {
            let (scale, _, base) = tree.to_scale_rotation_translation();
            let p = Vec2::new(base.x, base.z);
            // The foliage is 1.5 m wide at the model's scale.
            let reach = 1.5 * scale.x;
            assert!(height(p) >= GRASS_FROM, "a tree at {p} stands on sand or in the river");
            assert!((0..8).all(|k| {
                let edge = p + Vec2::from_angle(k as f32 * TAU / 8.0) * reach;
                height(edge) > MEAN_LEVEL + TIDE_AMPLITUDE
            }));
            assert!(road_distance(p) - reach > ROAD_WIDTH / 2.0, "a tree at {p} stands on a road");
            assert!(p.x.abs().max(p.y.abs()) - reach > CITY_EDGE, "a tree at {p} stands in the city");
        }
    }

    #[test]
    fn roads_stay_above_the_ground_and_the_highest_tide() {
        let pieces = road_pieces();
        let roads: Vec<&Piece> = pieces.iter().filter(|p| p.material == Material::Road).collect();
        assert!(pieces.len() > roads.len(), "the bridge has piers");
        for road in roads {
            let top = road.model.transform_point3(Vec3::new(0.0, 0.5, 0.0));
            for corner in [Vec3::new(-0.5, 0.5, -0.5), Vec3::new(0.5, 0.5, 0.5)] {
                let at = road.model.transform_point3(corner);
                let ground = height(Vec2::new(at.x, at.z));
                assert!(at.y + 0.05 >= ground, "a road sinks under the ground at {at}, {} m", ground - at.y);
            }
            assert!(top.y > MEAN_LEVEL + TIDE_AMPLITUDE + 2.0, "a road floods at {top}");
        }
    }

    #[test]
    fn the_tree_model_reads_from_chapter_10s_obj() {
        let (trunk, foliage) = tree_meshes().unwrap();
        let top = |m: &MeshData| m.vertices.iter().map(|v| v.position[1]).fold(f32::MIN, f32::max);
        assert!(!trunk.indices.is_empty() && !foliage.indices.is_empty());
        assert!(trunk.indices.len() % 3 == 0 && foliage.indices.len() % 3 == 0);
        assert_eq!((top(&trunk), top(&foliage)), (2.4, 4.5), "the trunk is 2.4 m tall, the tree 4.5 m");
    }
}
