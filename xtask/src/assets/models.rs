//! Models for chapters 09 to 11, written as Wavefront OBJ with MTL
//! materials: a car with body, glass, tyres and lights; a stepped office
//! tower; the boat that chapter 11 sails, with its sail and sailor;
//! chapter 10's tree, rock, crate, player, floating island and low-poly
//! sphere. Built from code like everything
//! under `assets/`, and written the way exporters write them: several
//! objects, quads and n-gons, some faces with relative (negative) indices.
//!
//! Conventions: metres, y up, the car's and the boat's front towards −z,
//! standing on y = 0; the sail and the sailor are in the boat's frame. Texture coordinates follow OBJ (v up the image).

use std::fmt::Write as _;
use std::path::Path;

use glam::{Vec2, Vec3};

/// An OBJ file and its MTL being written. Indices are 1-based, as OBJ's are.
#[derive(Default)]
pub struct ObjWriter {
    obj: String,
    current_material: String,
    positions: usize,
    uvs: usize,
    normals: usize,
}

/// One corner of a face: indices of its position, uv and normal.
#[derive(Clone, Copy)]
pub struct Corner {
    pub position: usize,
    pub uv: Option<usize>,
    pub normal: Option<usize>,
}

impl ObjWriter {
    pub fn new(header: &str, mtl: Option<&str>) -> Self {
        let mut writer = Self::default();
        for line in header.lines() {
            let _ = writeln!(writer.obj, "# {line}");
        }
        if let Some(mtl) = mtl {
            let _ = writeln!(writer.obj, "mtllib {mtl}");
        }
        writer
    }

    pub fn object(&mut self, name: &str) {
        let _ = writeln!(self.obj, "o {name}");
        self.current_material.clear();
    }

    /// Switches material (written only when it changes).
    pub fn material(&mut self, name: &str) {
        if self.current_material != name {
            let _ = writeln!(self.obj, "usemtl {name}");
            self.current_material = name.to_string();
        }
    }

    pub fn position(&mut self, p: Vec3) -> usize {
        let _ = writeln!(self.obj, "v {} {} {}", f(p.x), f(p.y), f(p.z));
        self.positions += 1;
        self.positions
    }

    pub fn uv(&mut self, t: Vec2) -> usize {
        let _ = writeln!(self.obj, "vt {} {}", f(t.x), f(t.y));
        self.uvs += 1;
        self.uvs
    }

    pub fn normal(&mut self, n: Vec3) -> usize {
        let n = n.normalize();
        let _ = writeln!(self.obj, "vn {} {} {}", f(n.x), f(n.y), f(n.z));
        self.normals += 1;
        self.normals
    }

    /// A face, counter-clockwise seen from outside. With `relative`, its
    /// indices are written counting back from the latest of each kind.
    pub fn face(&mut self, corners: &[Corner], relative: bool) {
        let index =
            |i: usize, count: usize| if relative { format!("{}", i as i64 - count as i64 - 1) } else { i.to_string() };
        let words: Vec<String> = corners
            .iter()
            .map(|c| {
                let p = index(c.position, self.positions);
                match (c.uv, c.normal) {
                    (Some(t), Some(n)) => format!("{p}/{}/{}", index(t, self.uvs), index(n, self.normals)),
                    (Some(t), None) => format!("{p}/{}", index(t, self.uvs)),
                    (None, Some(n)) => format!("{p}//{}", index(n, self.normals)),
                    (None, None) => p,
                }
            })
            .collect();
        let _ = writeln!(self.obj, "f {}", words.join(" "));
    }

    /// A flat polygon (any number of sides) with one normal and uvs from a
    /// planar projection: `uv_of(point)`.
    pub fn flat_polygon(&mut self, points: &[Vec3], uv_of: impl Fn(Vec3) -> Vec2) {
        let normal = polygon_normal(points);
        let n = self.normal(normal);
        let corners: Vec<Corner> = points
            .iter()
            .map(|&p| {
                let position = self.position(p);
                let uv = self.uv(uv_of(p));
                Corner { position, uv: Some(uv), normal: Some(n) }
            })
            .collect();
        self.face(&corners, false);
    }

    /// A box from `low` to `high` as six quads, uvs in metres / `tile`.
    pub fn cuboid(&mut self, low: Vec3, high: Vec3, tile: f32) {
        let c = |x: f32, y: f32, z: f32| Vec3::new(x, y, z);
        let (a, b) = (low, high);
        let faces = [
            [c(b.x, a.y, b.z), c(b.x, a.y, a.z), c(b.x, b.y, a.z), c(b.x, b.y, b.z)],
            [c(a.x, a.y, a.z), c(a.x, a.y, b.z), c(a.x, b.y, b.z), c(a.x, b.y, a.z)],
            [c(a.x, b.y, b.z), c(b.x, b.y, b.z), c(b.x, b.y, a.z), c(a.x, b.y, a.z)],
            [c(a.x, a.y, a.z), c(b.x, a.y, a.z), c(b.x, a.y, b.z), c(a.x, a.y, b.z)],
            [c(a.x, a.y, b.z), c(b.x, a.y, b.z), c(b.x, b.y, b.z), c(a.x, b.y, b.z)],
            [c(b.x, a.y, a.z), c(a.x, a.y, a.z), c(a.x, b.y, a.z), c(b.x, b.y, a.z)],
        ];
        for quad in faces {
            // u along the quad's first edge, v along its last, in metres.
            let (origin, u_axis, v_axis) = (quad[0], (quad[1] - quad[0]).normalize(), (quad[3] - quad[0]).normalize());
            self.flat_polygon(&quad, |p| Vec2::new((p - origin).dot(u_axis), (p - origin).dot(v_axis)) / tile);
        }
    }

    pub fn write(self, path: &Path) -> anyhow::Result<()> {
        std::fs::write(path, self.obj).map_err(|e| anyhow::anyhow!("cannot write {}: {e}", path.display()))
    }
}

/// Numbers as exporters write them: six decimals, no "-0".
fn f(x: f32) -> String {
    let text = format!("{x:.6}");
    if text.trim_start_matches('-').trim_start_matches(['0', '.']).is_empty() { "0.000000".into() } else { text }
}

/// Newell's method: the normal of a planar polygon, counter-clockwise.
fn polygon_normal(points: &[Vec3]) -> Vec3 {
    let mut n = Vec3::ZERO;
    for (i, p) in points.iter().enumerate() {
        let q = points[(i + 1) % points.len()];
        n += Vec3::new((p.y - q.y) * (p.z + q.z), (p.z - q.z) * (p.x + q.x), (p.x - q.x) * (p.y + q.y));
    }
    n.normalize()
}

/// A prism: the polygon `profile` in the (z, y) plane, swept across x from
/// `x0` to `x1`. Its two ends are n-gons; its sides are quads, smooth where
/// the profile turns less than 30°, creased where it turns more.
fn extrude_profile(obj: &mut ObjWriter, profile: &[Vec2], x0: f32, x1: f32, tile: f32) {
    let at = |p: Vec2, x: f32| Vec3::new(x, p.y, p.x);
    // The profile runs clockwise in (z, y) seen from +x, so the +x end reads
    // counter-clockwise from outside after reversing.
    let right: Vec<Vec3> = profile.iter().rev().map(|&p| at(p, x1)).collect();
    obj.flat_polygon(&right, |p| Vec2::new(-p.z, p.y) / tile);
    let left: Vec<Vec3> = profile.iter().map(|&p| at(p, x0)).collect();
    obj.flat_polygon(&left, |p| Vec2::new(p.z, p.y) / tile);
    let count = profile.len();
    let edge_normal = |i: usize| {
        let d = profile[(i + 1) % count] - profile[i];
        // Outward in (z, y) for a clockwise profile seen from +x.
        Vec3::new(0.0, -d.x, d.y).normalize()
    };
    let mut along = 0.0;
    for i in 0..count {
        let j = (i + 1) % count;
        let here = edge_normal(i);
        let smooth = |k: usize| {
            let other = edge_normal(k);
            if here.dot(other) > 30f32.to_radians().cos() { (here + other).normalize() } else { here }
        };
        let (n_i, n_j) = (smooth((i + count - 1) % count), smooth(j));
        let length = (profile[j] - profile[i]).length();
        let quad = [
            (profile[i], x1, n_i, along),
            (profile[j], x1, n_j, along + length),
            (profile[j], x0, n_j, along + length),
            (profile[i], x0, n_i, along),
        ];
        let corners: Vec<Corner> = quad
            .iter()
            .map(|&(p, x, n, s)| {
                let position = obj.position(at(p, x));
                let uv = obj.uv(Vec2::new(s, x - x0) / tile);
                let normal = obj.normal(n);
                Corner { position, uv: Some(uv), normal: Some(normal) }
            })
            .collect();
        obj.face(&corners, false);
        along += length;
    }
}

/// A cylinder along x (a wheel), centred at `centre`, written with relative
/// indices as some exporters do.
fn wheel(obj: &mut ObjWriter, centre: Vec3, radius: f32, width: f32, segments: usize) {
    let ring = |i: usize| {
        let angle = std::f32::consts::TAU * i as f32 / segments as f32;
        Vec2::new(angle.cos(), angle.sin())
    };
    // The tread: quads, smooth normals, written with negative indices.
    for i in 0..segments {
        let (a, b) = (ring(i), ring(i + 1));
        let mut corners = Vec::new();
        for (r, x, u) in [(a, -1.0, i), (a, 1.0, i), (b, 1.0, i + 1), (b, -1.0, i + 1)] {
            let position = obj.position(centre + Vec3::new(x * width / 2.0, r.y * radius, r.x * radius));
            let uv = obj.uv(Vec2::new(u as f32 / segments as f32, (x + 1.0) / 2.0));
            let normal = obj.normal(Vec3::new(0.0, r.y, r.x));
            corners.push(Corner { position, uv: Some(uv), normal: Some(normal) });
        }
        obj.face(&corners, true);
    }
    // The two hubs: n-gons.
    for side in [-1.0f32, 1.0] {
        let mut points: Vec<Vec3> = (0..segments)
            .map(|i| centre + Vec3::new(side * width / 2.0, ring(i).y * radius, ring(i).x * radius))
            .collect();
        if side > 0.0 {
            points.reverse();
        }
        obj.flat_polygon(&points, |p| Vec2::new(p.z - centre.z, p.y - centre.y) / (2.0 * radius) + 0.5);
    }
}

const CAR_MTL: &str = "\
# The car's materials (chapter 09). Kd, Ks, Ns as usual; Ke is light of the
# material's own. Texture paths are relative to this file.
newmtl body
Kd 0.550 0.080 0.050
Ks 0.800 0.800 0.800
Ns 80
map_Kd ../../textures/metal/albedo.png
map_Bump ../../textures/metal/normal.png

newmtl glass
Kd 0.050 0.130 0.180
Ks 0.900 0.900 0.900
Ns 96

newmtl tyre
Kd 0.020 0.020 0.020
Ks 0.100 0.100 0.100
Ns 8

newmtl headlight
Kd 1.000 1.000 1.000
Ks 0.500 0.500 0.500
Ns 32
Ke 8.000 7.500 6.500

newmtl taillight
Kd 0.400 0.020 0.020
Ks 0.500 0.500 0.500
Ns 32
Ke 5.000 0.200 0.100
";

/// The car: 4.4 m long, 1.9 m wide, its front towards −z.
fn car() -> String {
    let mut obj = ObjWriter::new("A car for chapter 09, written by `cargo xtask assets`.", Some("car.mtl"));
    obj.object("body");
    obj.material("body");
    // Side profile (z, y), clockwise seen from +x: rear bumper, boot, roof
    // line under the glass, bonnet, nose, and back along the sill.
    let body = [
        (2.20, 0.30),
        (2.25, 0.70),
        (2.05, 0.95),
        (1.20, 0.98),
        (-0.70, 0.98),
        (-1.80, 0.85),
        (-2.20, 0.72),
        (-2.25, 0.45),
        (-2.10, 0.30),
    ]
    .map(|(z, y)| Vec2::new(z, y));
    extrude_profile(&mut obj, &body, -0.95, 0.95, 4.0);
    obj.object("cabin");
    obj.material("glass");
    let cabin = [(1.30, 0.98), (0.85, 1.45), (-0.15, 1.45), (-0.75, 0.98)].map(|(z, y)| Vec2::new(z, y));
    extrude_profile(&mut obj, &cabin, -0.82, 0.82, 4.0);
    obj.object("wheels");
    obj.material("tyre");
    for (x, z) in [(-0.93, -1.40), (0.93, -1.40), (-0.93, 1.40), (0.93, 1.40)] {
        wheel(&mut obj, Vec3::new(x, 0.33, z), 0.33, 0.26, 16);
    }
    obj.object("lights");
    obj.material("headlight");
    for side in [-1.0, 1.0] {
        obj.cuboid(Vec3::new(side * 0.55 - 0.15, 0.58, -2.27), Vec3::new(side * 0.55 + 0.15, 0.70, -2.20), 1.0);
    }
    obj.material("taillight");
    for side in [-1.0, 1.0] {
        obj.cuboid(Vec3::new(side * 0.60 - 0.18, 0.62, 2.20), Vec3::new(side * 0.60 + 0.18, 0.72, 2.28), 1.0);
    }
    obj.obj
}

const TOWER_MTL: &str = "\
# The tower's materials (chapter 09). The facade's albedo alpha marks lit
# windows: chapter 09 reads it as where Ke glows.
newmtl facade
Kd 1.000 1.000 1.000
Ks 0.300 0.300 0.300
Ns 48
Ke 3.000 2.300 1.400
map_Kd ../../textures/facade/albedo.png
map_Bump ../../textures/facade/normal.png

newmtl roof
Kd 1.000 1.000 1.000
Ks 0.100 0.100 0.100
Ns 12
map_Kd ../../textures/concrete/albedo.png
bump ../../textures/concrete/normal.png

newmtl antenna
Kd 1.000 1.000 1.000
Ks 0.600 0.600 0.600
Ns 96
map_Kd ../../textures/metal/albedo.png
norm ../../textures/metal/normal.png
";

/// A tower in three setbacks, 100 m tall with its antenna, on y = 0.
fn tower() -> String {
    let mut obj = ObjWriter::new("An office tower for chapter 09, written by `cargo xtask assets`.", Some("tower.mtl"));
    let stages = [(24.0, 0.0, 48.0), (18.0, 48.0, 72.0), (12.0, 72.0, 88.0)];
    for (i, &(width, bottom, top)) in stages.iter().enumerate() {
        let half = width / 2.0;
        obj.object(&format!("stage{}", i + 1));
        obj.material("facade");
        // The walls, one 16 m facade tile per 16 m, starting at the ground.
        let corners = [Vec2::new(half, half), Vec2::new(half, -half), Vec2::new(-half, -half), Vec2::new(-half, half)];
        for k in 0..4 {
            let (a, b) = (corners[k], corners[(k + 1) % 4]);
            let quad = [
                Vec3::new(a.x, bottom, a.y),
                Vec3::new(b.x, bottom, b.y),
                Vec3::new(b.x, top, b.y),
                Vec3::new(a.x, top, a.y),
            ];
            let start = quad[0];
            let along = (quad[1] - quad[0]).normalize();
            obj.flat_polygon(&quad, |p| Vec2::new((p - start).dot(along), p.y) / 16.0);
        }
        obj.material("roof");
        let roof: Vec<Vec3> = corners.iter().map(|c| Vec3::new(c.x, top, c.y)).collect();
        obj.flat_polygon(&roof, |p| Vec2::new(p.x, -p.z) / 4.0);
    }
    obj.object("antenna");
    obj.material("antenna");
    obj.cuboid(Vec3::new(-0.4, 88.0, -0.4), Vec3::new(0.4, 100.0, 0.4), 4.0);
    obj.obj
}

const BOAT_MTL: &str = "\
# The boat's materials (chapters 09 and 11).
newmtl hull
Kd 0.800 0.780 0.740
Ks 0.400 0.400 0.400
Ns 40

newmtl stripe
Kd 0.060 0.160 0.420
Ks 0.400 0.400 0.400
Ns 40

newmtl deck
Kd 0.420 0.270 0.150
Ks 0.100 0.100 0.100
Ns 10

newmtl cabin
Kd 1.000 1.000 1.000
Ks 0.200 0.200 0.200
Ns 24
map_Kd ../../textures/metal/albedo.png
map_Bump ../../textures/metal/normal.png

newmtl mast
Kd 0.700 0.700 0.720
Ks 0.700 0.700 0.700
Ns 80
";

/// The boat: 8 m long, 2.6 m in the beam, its keel at y = 0 and its bow
/// towards −z. The hull is lofted through cross-sections, smooth-shaded.
fn boat() -> String {
    let mut obj = ObjWriter::new("A boat for chapters 09 and 11, written by `cargo xtask assets`.", Some("boat.mtl"));
    const STATIONS: usize = 16;
    const AROUND: usize = 8;
    let (length, beam, depth) = (8.0f32, 2.6f32, 1.2f32);
    // At t in 0..1 from bow to stern: half the beam and how far the keel
    // falls below the gunwale. Pointed at the bow, full at the stern.
    let section = |t: f32| {
        let width = (beam / 2.0) * (1.0 - (1.0 - t).powi(2)).sqrt().max(0.02) * (1.0 - 0.15 * t * t);
        let keel = depth * (0.35 + 0.65 * (std::f32::consts::PI * t.min(0.85) / 0.85 / 2.0).sin()).min(1.0);
        (width, keel)
    };
    // Point k of a section: round the bilge from the keel (k = 0) up the side
    // to the gunwale (k = AROUND), on the side given by `side`.
    let point = |t: f32, k: usize, side: f32| {
        let (width, keel) = section(t);
        let angle = std::f32::consts::FRAC_PI_2 * k as f32 / AROUND as f32;
        let z = -length / 2.0 + length * t;
        Vec3::new(side * width * angle.sin(), depth - keel * angle.cos(), z)
    };
    // Normals by differences along the hull and around the section.
    let normal = |t: f32, k: usize, side: f32| {
        let dt = 1e-3;
        let along = point((t + dt).min(1.0), k, side) - point((t - dt).max(0.0), k, side);
        let around = point(t, (k + 1).min(AROUND), side) - point(t, k.saturating_sub(1), side);
        let n = if side > 0.0 { around.cross(along) } else { along.cross(around) };
        if n.length() > 1e-6 { n.normalize() } else { Vec3::new(side, 0.0, 0.0) }
    };
    obj.object("hull");
    // Each side is a grid of points written once, its quads sharing them,
    // as exporters write smooth surfaces.
    for side in [-1.0f32, 1.0] {
        let mut grid = Vec::new();
        for s in 0..=STATIONS {
            for k in 0..=AROUND {
                let t = s as f32 / STATIONS as f32;
                let position = obj.position(point(t, k, side));
                let uv = obj.uv(Vec2::new(t, k as f32 / AROUND as f32));
                let n = obj.normal(normal(t, k, side));
                grid.push(Corner { position, uv: Some(uv), normal: Some(n) });
            }
        }
        let at = |s: usize, k: usize| grid[s * (AROUND + 1) + k];
        for k in 0..AROUND {
            // The top band is the stripe.
            obj.material(if k == AROUND - 1 { "stripe" } else { "hull" });
            for s in 0..STATIONS {
                let mut corners = vec![at(s, k), at(s + 1, k), at(s + 1, k + 1), at(s, k + 1)];
                if side > 0.0 {
                    corners.reverse();
                }
                obj.face(&corners, false);
            }
        }
    }
    // The transom: the flat stern, an n-gon.
    let mut transom: Vec<Vec3> = (0..=AROUND).map(|k| point(1.0, AROUND - k, -1.0)).collect();
    transom.extend((1..=AROUND).map(|k| point(1.0, k, 1.0)));
    transom.dedup_by(|a, b| a.distance(*b) < 1e-4);
    obj.material("hull");
    obj.flat_polygon(&transom, |p| Vec2::new(p.x, p.y) / 4.0);
    obj.object("deck");
    obj.material("deck");
    // The deck: one n-gon along the gunwale, down the port side from bow to
    // stern and back up the starboard side (counter-clockwise from above).
    let mut deck: Vec<Vec3> = (0..=STATIONS).map(|s| point(s as f32 / STATIONS as f32, AROUND, -1.0)).collect();
    deck.extend((0..=STATIONS).rev().map(|s| point(s as f32 / STATIONS as f32, AROUND, 1.0)));
    deck.dedup_by(|a, b| a.distance(*b) < 1e-4);
    obj.flat_polygon(&deck, |p| Vec2::new(p.x, -p.z) / 2.0);
    obj.object("cabin");
    obj.material("cabin");
    obj.cuboid(Vec3::new(-0.8, depth, 0.4), Vec3::new(0.8, depth + 1.1, 2.6), 4.0);
    obj.object("mast");
    obj.material("mast");
    obj.cuboid(Vec3::new(-0.06, depth, -1.06), Vec3::new(0.06, depth + 7.0, -0.94), 4.0);
    obj.obj
}

const SAIL_MTL: &str = "\
# The sail's materials (chapter 11): canvas, a wooden boom, a rope sheet.
newmtl cloth
Kd 0.920 0.880 0.780
Ks 0.050 0.050 0.050
Ns 8

newmtl spar
Kd 0.450 0.270 0.130
Ks 0.150 0.150 0.150
Ns 16

newmtl rope
Kd 0.680 0.580 0.400
Ks 0.050 0.050 0.050
Ns 8
";

/// Rows of the sail's cloth from the boom to the head: 6² = 36 triangles
/// a side.
const SAIL_ROWS: usize = 6;

/// The boat's mainsail, a boom under it and the sheet that holds the boom,
/// in the boat's own frame (so the boat's model matrix places them): the
/// mast is the boat's, its aft face at z = −0.94. The cloth is a triangle
/// in the plane x = 0, from the tack (at the mast, on the boom) up the
/// luff to the head and aft along the foot to the clew; its texture
/// coordinates are its own coordinates, u along the foot and v up the luff,
/// each 0 to 1, which chapter 11 reads to swell it. Both sides are
/// written, since a sail is seen (and casts its shadow) from either.
fn sail() -> String {
    let mut obj = ObjWriter::new(
        "The boat's sail, boom and sheet for chapter 11, in the boat's frame, written by `cargo xtask assets`.",
        Some("sail.mtl"),
    );
    let (tack, head, clew) = (Vec3::new(0.0, 3.32, -0.92), Vec3::new(0.0, 7.9, -0.92), Vec3::new(0.0, 3.32, 3.4));
    obj.object("sail");
    obj.material("cloth");
    // The triangular grid: corner (i, j) at u = i / rows, v = j / rows,
    // i + j ≤ rows. Positions and uvs are shared by both sides.
    let mut corner = std::collections::HashMap::new();
    for j in 0..=SAIL_ROWS {
        for i in 0..=SAIL_ROWS - j {
            let (u, v) = (i as f32 / SAIL_ROWS as f32, j as f32 / SAIL_ROWS as f32);
            let position = obj.position(tack + (clew - tack) * u + (head - tack) * v);
            let uv = obj.uv(Vec2::new(u, v));
            corner.insert((i, j), (position, uv));
        }
    }
    let mut triangles = Vec::new();
    for j in 0..SAIL_ROWS {
        for i in 0..SAIL_ROWS - j {
            triangles.push([(i, j), (i + 1, j), (i, j + 1)]);
            if i + j + 1 < SAIL_ROWS {
                triangles.push([(i + 1, j), (i + 1, j + 1), (i, j + 1)]);
            }
        }
    }
    // (tack, clew, head) turns counter-clockwise seen from −x (port).
    for side in [Vec3::X, Vec3::NEG_X] {
        let normal = obj.normal(side);
        for triangle in &triangles {
            let mut corners: Vec<Corner> = triangle
                .iter()
                .map(|at| Corner { position: corner[at].0, uv: Some(corner[at].1), normal: Some(normal) })
                .collect();
            if side == Vec3::X {
                corners.reverse();
            }
            obj.face(&corners, false);
        }
    }
    obj.object("boom");
    obj.material("spar");
    obj.cuboid(Vec3::new(-0.05, 3.2, -0.94), Vec3::new(0.05, 3.32, 3.5), 1.0);
    obj.object("sheet");
    obj.material("rope");
    obj.cuboid(Vec3::new(-0.015, 1.2, 3.42), Vec3::new(0.015, 3.2, 3.45), 1.0);
    obj.obj
}

const SAILOR_MTL: &str = "\
# The sailor's materials (chapter 11).
newmtl skin
Kd 0.900 0.620 0.460
Ks 0.100 0.100 0.100
Ns 12

newmtl tunic
Kd 0.180 0.520 0.160
Ks 0.080 0.080 0.080
Ns 10

newmtl trousers
Kd 0.880 0.840 0.700
Ks 0.060 0.060 0.060
Ns 10

newmtl hat
Kd 0.140 0.440 0.130
Ks 0.080 0.080 0.080
Ns 10

newmtl boots
Kd 0.300 0.170 0.080
Ks 0.200 0.200 0.200
Ns 24
";

/// An object of boxes from (low, high) corners, all in one material.
fn boxes(obj: &mut ObjWriter, object: &str, material: &str, boxes: &[(Vec3, Vec3)]) {
    obj.object(object);
    obj.material(material);
    for &(low, high) in boxes {
        obj.cuboid(low, high, 0.5);
    }
}

/// A sailor 1.6 m tall at the helm, between the cabin and the sheet, in
/// the boat's frame (feet on the deck, y = 1.2), facing the bow (−z):
/// boxes for boots, legs, body, arms, hands and head, and a pointed cap
/// whose tip droops aft. Faceted, in the seed's toon manner.
fn sailor() -> String {
    let mut obj = ObjWriter::new(
        "A sailor for chapter 11's boat, in the boat's frame, written by `cargo xtask assets`.",
        Some("sailor.mtl"),
    );
    let b = |x0: f32, y0: f32, z0: f32, x1: f32, y1: f32, z1: f32| (Vec3::new(x0, y0, z0), Vec3::new(x1, y1, z1));
    boxes(&mut obj, "boots", "boots", &[b(-0.17, 1.2, 2.84, -0.03, 1.32, 3.08), b(0.03, 1.2, 2.84, 0.17, 1.32, 3.08)]);
    boxes(
        &mut obj,
        "legs",
        "trousers",
        &[b(-0.16, 1.32, 2.89, -0.04, 1.93, 3.03), b(0.04, 1.32, 2.89, 0.16, 1.93, 3.03)],
    );
    // The body and the arms; the head and the hands.
    let body = [
        b(-0.2, 1.88, 2.85, 0.2, 2.46, 3.07),
        b(-0.3, 1.98, 2.9, -0.2, 2.44, 3.02),
        b(0.2, 1.98, 2.9, 0.3, 2.44, 3.02),
    ];
    boxes(&mut obj, "body", "tunic", &body);
    let skin = [
        b(-0.13, 2.47, 2.83, 0.13, 2.75, 3.09),
        b(-0.29, 1.88, 2.91, -0.21, 1.98, 3.01),
        b(0.21, 1.88, 2.91, 0.29, 1.98, 3.01),
    ];
    boxes(&mut obj, "head", "skin", &skin);
    obj.object("cap");
    obj.material("hat");
    // The cap: a six-sided cone on the head, its tip drooping aft.
    const AROUND: usize = 6;
    let (centre, radius, tip) = (Vec3::new(0.0, 2.72, 2.96), 0.17, Vec3::new(0.0, 2.98, 3.3));
    let rim: Vec<Vec3> = (0..AROUND)
        .map(|k| {
            let (sin, cos) = (std::f32::consts::TAU * k as f32 / AROUND as f32).sin_cos();
            centre + Vec3::new(radius * cos, 0.0, -radius * sin)
        })
        .collect();
    for k in 0..AROUND {
        facet(&mut obj, &[rim[k], rim[(k + 1) % AROUND], tip], 0.5);
    }
    let underside: Vec<Vec3> = rim.iter().rev().copied().collect();
    facet(&mut obj, &underside, 0.5);
    obj.obj
}

/// A surface of revolution about the vertical line through `centre`:
/// `profile` is (radius, height) from bottom to top. Smooth normals from the
/// profile's slope; u around, v up, one repeat around.
fn lathe(obj: &mut ObjWriter, centre: Vec3, profile: &[Vec2], segments: usize) {
    let count = profile.len();
    let slope_normal = |i: usize| {
        let before = profile[i.saturating_sub(1)];
        let after = profile[(i + 1).min(count - 1)];
        let d = after - before;
        Vec2::new(d.y, -d.x).normalize() // outward: (dr, dy) turned clockwise
    };
    let mut grid = Vec::new();
    for k in 0..=segments {
        let angle = std::f32::consts::TAU * k as f32 / segments as f32;
        let (sin, cos) = angle.sin_cos();
        for (i, p) in profile.iter().enumerate() {
            let n = slope_normal(i);
            let position = obj.position(centre + Vec3::new(p.x * cos, p.y, -p.x * sin));
            let uv = obj.uv(Vec2::new(k as f32 / segments as f32, i as f32 / (count - 1) as f32));
            let normal = obj.normal(Vec3::new(n.x * cos, n.y, -n.x * sin));
            grid.push(Corner { position, uv: Some(uv), normal: Some(normal) });
        }
    }
    grid_quads(obj, &grid, count);
}

/// Quads between neighbouring corners of a grid written column by column,
/// `column` corners to a column: corner (k, i) is `grid[k * column + i]`.
fn grid_quads(obj: &mut ObjWriter, grid: &[Corner], column: usize) {
    let at = |k: usize, i: usize| grid[k * column + i];
    for k in 0..grid.len() / column - 1 {
        for i in 0..column - 1 {
            obj.face(&[at(k, i), at(k + 1, i), at(k + 1, i + 1), at(k, i + 1)], false);
        }
    }
}

const TREE_MTL: &str = "\
# A tree's materials (chapter 10).
newmtl bark
Kd 0.300 0.190 0.110
Ks 0.050 0.050 0.050
Ns 8

newmtl leaves
Kd 0.120 0.330 0.120
Ks 0.080 0.080 0.080
Ns 12
";

/// A conifer 4.5 m tall: a trunk and three tiers of foliage, each a
/// surface of revolution.
fn tree() -> String {
    let mut obj = ObjWriter::new("A tree for chapter 10, written by `cargo xtask assets`.", Some("tree.mtl"));
    obj.object("trunk");
    obj.material("bark");
    let trunk = [Vec2::new(0.2, 0.0), Vec2::new(0.16, 1.2), Vec2::new(0.12, 2.4)];
    lathe(&mut obj, Vec3::ZERO, &trunk, 10);
    obj.object("foliage");
    obj.material("leaves");
    for (base, width, height) in [(0.9, 1.5, 1.8), (1.9, 1.2, 1.6), (2.8, 0.85, 1.7)] {
        // A cone with a turned-under rim, so that it has a lower side.
        let tier = [
            Vec2::new(0.05, base + 0.2),
            Vec2::new(width, base),
            Vec2::new(width * 0.55, base + height * 0.45),
            Vec2::new(0.02, base + height),
        ];
        lathe(&mut obj, Vec3::ZERO, &tier, 12);
    }
    obj.obj
}

const ROCK_MTL: &str = "\
# A rock's material (chapter 10): concrete's texture, tinted.
newmtl stone
Kd 0.640 0.610 0.570
Ks 0.050 0.050 0.050
Ns 8
map_Kd ../../textures/concrete/albedo.png
map_Bump ../../textures/concrete/normal.png
";

/// A boulder about 1.6 m across: a sphere pushed in and out by noise,
/// flattened underneath, normals averaged from its faces.
fn rock() -> String {
    let mut obj = ObjWriter::new("A rock for chapter 10, written by `cargo xtask assets`.", Some("rock.mtl"));
    const AROUND: usize = 14;
    const UP: usize = 8;
    let point = |k: usize, j: usize| {
        let (theta, phi) =
            (std::f32::consts::TAU * (k % AROUND) as f32 / AROUND as f32, std::f32::consts::PI * j as f32 / UP as f32);
        let d = Vec3::new(phi.sin() * theta.cos(), -phi.cos(), -phi.sin() * theta.sin());
        let bump = super::value_noise([d.x * 1.7 + 3.0, d.y * 1.7, d.z * 1.7]) * 0.35
            + super::value_noise([d.x * 4.0, d.y * 4.0 + 7.0, d.z * 4.0]) * 0.12;
        let p = d * Vec3::new(0.95, 0.6, 0.75) * (0.8 + bump);
        Vec3::new(p.x, p.y.max(-0.3) + 0.3, p.z)
    };
    // Normals: each vertex averages the normals of the quads around it.
    let quad_normal = |k: usize, j: usize| {
        let (a, b, c, d) = (point(k, j), point(k + 1, j), point(k + 1, j + 1), point(k, j + 1));
        (c - a).cross(d - b)
    };
    obj.object("rock");
    obj.material("stone");
    let mut grid = Vec::new();
    for k in 0..=AROUND {
        for j in 0..=UP {
            // The quads left and right (wrapping round), below and above.
            let mut n = Vec3::ZERO;
            for qk in [(k + AROUND - 1) % AROUND, k % AROUND] {
                for qj in [j.checked_sub(1), (j < UP).then_some(j)].into_iter().flatten() {
                    n += quad_normal(qk, qj);
                }
            }
            let position = obj.position(point(k, j));
            let uv = obj.uv(Vec2::new(k as f32 / AROUND as f32 * 2.0, j as f32 / UP as f32));
            let normal =
                obj.normal(if n.length() > 1e-6 { n } else { Vec3::new(0.0, if j == 0 { -1.0 } else { 1.0 }, 0.0) });
            grid.push(Corner { position, uv: Some(uv), normal: Some(normal) });
        }
    }
    grid_quads(&mut obj, &grid, UP + 1);
    obj.obj
}

const CRATE_MTL: &str = "\
# A crate's material (chapter 10).
newmtl wood
Kd 1.000 1.000 1.000
Ks 0.100 0.100 0.100
Ns 10
map_Kd ../../textures/wood/albedo.png
map_Bump ../../textures/wood/normal.png
";

/// A wooden crate, 1 m on a side, standing on y = 0.
fn crate_model() -> String {
    let mut obj = ObjWriter::new("A crate for chapter 10, written by `cargo xtask assets`.", Some("crate.mtl"));
    obj.object("crate");
    obj.material("wood");
    obj.cuboid(Vec3::new(-0.5, 0.0, -0.5), Vec3::new(0.5, 1.0, 0.5), 1.0);
    obj.obj
}

const ROBOT_MTL: &str = "\
# The player's materials (chapter 10).
newmtl suit
Kd 0.900 0.420 0.120
Ks 0.300 0.300 0.300
Ns 32
map_Kd ../../textures/metal/albedo.png
map_Bump ../../textures/metal/normal.png

newmtl joints
Kd 0.060 0.060 0.070
Ks 0.120 0.120 0.120
Ns 16

newmtl visor
Kd 0.020 0.060 0.080
Ks 0.900 0.900 0.900
Ns 96
Ke 0.300 2.400 3.000
";

/// The player: a small robot 1.7 m tall, facing +x, feet on y = 0.
fn robot() -> String {
    let mut obj = ObjWriter::new("The player for chapter 10, written by `cargo xtask assets`.", Some("robot.mtl"));
    let b = |x0: f32, y0: f32, z0: f32, x1: f32, y1: f32, z1: f32| (Vec3::new(x0, y0, z0), Vec3::new(x1, y1, z1));
    obj.object("legs");
    obj.material("joints");
    for z in [-0.16f32, 0.16] {
        let (low, high) = b(-0.1, 0.0, z - 0.08, 0.1, 0.7, z + 0.08);
        obj.cuboid(low, high, 0.5);
    }
    obj.object("body");
    obj.material("suit");
    let (low, high) = b(-0.22, 0.65, -0.3, 0.22, 1.3, 0.3);
    obj.cuboid(low, high, 0.5);
    let (low, high) = b(-0.2, 1.32, -0.2, 0.2, 1.7, 0.2);
    obj.cuboid(low, high, 0.5);
    obj.object("arms");
    obj.material("joints");
    for z in [-0.38f32, 0.38] {
        let (low, high) = b(-0.07, 0.7, z - 0.07, 0.07, 1.25, z + 0.07);
        obj.cuboid(low, high, 0.5);
    }
    obj.object("visor");
    obj.material("visor");
    let (low, high) = b(0.2, 1.45, -0.15, 0.24, 1.6, 0.15);
    obj.cuboid(low, high, 0.5);
    obj.obj
}

const ISLAND_MTL: &str = "\
# A floating island's materials (chapter 10): grass on top, stone below.
newmtl grass
Kd 0.260 0.480 0.160
Ks 0.040 0.040 0.040
Ns 8

newmtl stone
Kd 0.520 0.460 0.400
Ks 0.050 0.050 0.050
Ns 8
map_Kd ../../textures/concrete/albedo.png
map_Bump ../../textures/concrete/normal.png
";

/// A flat polygon textured in metres / `tile` along its own first edge, so
/// that every facet of a rough surface gets the texture at its size.
fn facet(obj: &mut ObjWriter, points: &[Vec3], tile: f32) {
    let (origin, u_axis) = (points[0], (points[1] - points[0]).normalize());
    let v_axis = polygon_normal(points).cross(u_axis);
    obj.flat_polygon(points, |p| Vec2::new((p - origin).dot(u_axis), (p - origin).dot(v_axis)) / tile);
}

/// The seed's hovering island, about 6.6 m across and 4.4 m deep: a flat
/// grassy top at y = 0 with a ragged rim, a grass edge, and under it an
/// inverted cone of stone, pushed in and out by value noise, down to a
/// tip. Faceted (one normal per face), as the seed's low-poly models were.
fn island() -> String {
    let mut obj =
        ObjWriter::new("A floating island for chapter 10, written by `cargo xtask assets`.", Some("island.mtl"));
    const AROUND: usize = 14;
    // Ring 0 is the rim, ring 1 the foot of the grass edge, the last the tip.
    const RINGS: usize = 6;
    let ring = |k: usize, j: usize| {
        let angle = std::f32::consts::TAU * (k % AROUND) as f32 / AROUND as f32;
        let (sin, cos) = angle.sin_cos();
        let noise = |scale: f32, salt: f32| super::value_noise([cos * scale + salt, j as f32 * 0.7, sin * scale]);
        // The rim's radius depends on the angle only; the rings below
        // bulge in and out and sag by their own noise, and meet at the tip.
        let rim = 3.0 * (0.85 + 0.3 * super::value_noise([cos * 1.6 + 5.0, 0.0, sin * 1.6]));
        let (radius, y) = match j {
            0 => (rim, 0.0),
            1 => (rim * 0.97, -0.35),
            RINGS => (0.0, -4.4),
            _ => {
                let t = (j - 1) as f32 / (RINGS - 1) as f32;
                let bulge = 0.75 + 0.5 * noise(2.5, 13.0);
                (rim * 0.97 * (1.0 - t).powf(0.8) * bulge, -0.35 - 4.05 * t + 0.6 * (noise(3.0, 29.0) - 0.5))
            }
        };
        Vec3::new(radius * cos, y, -radius * sin)
    };
    obj.object("top");
    obj.material("grass");
    let rim: Vec<Vec3> = (0..AROUND).map(|k| ring(k, 0)).collect();
    obj.flat_polygon(&rim, |p| Vec2::new(p.x, -p.z) / 2.0);
    for k in 0..AROUND {
        facet(&mut obj, &[ring(k, 1), ring(k + 1, 1), ring(k + 1, 0), ring(k, 0)], 2.0);
    }
    obj.object("underside");
    obj.material("stone");
    for j in 1..RINGS {
        for k in 0..AROUND {
            if j + 1 == RINGS {
                facet(&mut obj, &[ring(k, j + 1), ring(k + 1, j), ring(k, j)], 2.0);
            } else {
                facet(&mut obj, &[ring(k, j + 1), ring(k + 1, j + 1), ring(k + 1, j), ring(k, j)], 2.0);
            }
        }
    }
    obj.obj
}

const SPHERE_MTL: &str = "\
# The low-poly sphere's material (chapter 10): glossy paint.
newmtl paint
Kd 0.150 0.350 0.750
Ks 0.600 0.600 0.600
Ns 48
";

/// The seed's low-poly sphere, 1 m across, standing on y = 0: 10 facets
/// around and 6 from pole to pole, each flat with its own normal.
fn sphere() -> String {
    let mut obj =
        ObjWriter::new("A low-poly sphere for chapter 10, written by `cargo xtask assets`.", Some("sphere.mtl"));
    const AROUND: usize = 10;
    const RINGS: usize = 6;
    let point = |k: usize, j: usize| {
        let (sin_lon, cos_lon) = (std::f32::consts::TAU * k as f32 / AROUND as f32).sin_cos();
        let (sin_lat, cos_lat) = (std::f32::consts::PI * j as f32 / RINGS as f32).sin_cos();
        Vec3::new(0.5 * sin_lat * cos_lon, 0.5 + 0.5 * cos_lat, -0.5 * sin_lat * sin_lon)
    };
    obj.object("sphere");
    obj.material("paint");
    for j in 0..RINGS {
        for k in 0..AROUND {
            // Counter-clockwise from outside; the poles' quads are triangles.
            let quad = [point(k, j), point(k, j + 1), point(k + 1, j + 1), point(k + 1, j)];
            let corners: Vec<Vec3> = match j {
                0 => vec![quad[0], quad[1], quad[2]],
                _ if j + 1 == RINGS => vec![quad[0], quad[1], quad[3]],
                _ => quad.to_vec(),
            };
            facet(&mut obj, &corners, 0.5);
        }
    }
    obj.obj
}

/// (folder, file stem, OBJ text, MTL text, what it is).
fn models() -> [(&'static str, String, &'static str, &'static str); 11] {
    [
        (
            "car",
            car(),
            CAR_MTL,
            "a car, 4.4 m: an extruded body and glass cabin (n-gon ends), four wheels written with relative indices, head and tail lights (`Ke`); body in metal panels",
        ),
        (
            "tower",
            tower(),
            TOWER_MTL,
            "an office tower, 100 m in three setbacks, facade, concrete roofs and a metal antenna (`map_Bump`, `bump` and `norm` each used once)",
        ),
        (
            "boat",
            boat(),
            BOAT_MTL,
            "the boat chapter 11 sails, 8 m: a hull lofted through 17 cross-sections, a stripe, an n-gon deck and transom, cabin and mast",
        ),
        (
            "sail",
            sail(),
            SAIL_MTL,
            "the boat's mainsail (chapter 11), in the boat's frame: a triangle of cloth 4.6 m up the mast and 4.3 m along the boom, 6 rows, both sides, its uvs its own coordinates (u along the foot, v up the luff); a wooden boom and a rope sheet",
        ),
        (
            "sailor",
            sailor(),
            SAILOR_MTL,
            "a sailor 1.6 m tall at the boat's helm (chapter 11), in the boat's frame: boxes for boots, legs, tunic, arms, hands and head, and a six-sided cap drooping aft; skin, tunic, trousers, hat and boots",
        ),
        (
            "tree",
            tree(),
            TREE_MTL,
            "a conifer, 4.5 m (chapter 10): a trunk and three tiers of foliage, surfaces of revolution",
        ),
        (
            "rock",
            rock(),
            ROCK_MTL,
            "a boulder, 1.6 m (chapter 10): a sphere displaced by value noise, concrete's texture tinted",
        ),
        ("crate", crate_model(), CRATE_MTL, "a wooden crate, 1 m (chapter 10)"),
        (
            "robot",
            robot(),
            ROBOT_MTL,
            "the player, a robot 1.7 m tall facing +x (chapter 10): legs, body, head, arms and a glowing visor",
        ),
        (
            "island",
            island(),
            ISLAND_MTL,
            "a floating island, 6.6 m across (chapter 10): a flat grassy top with a ragged rim over an inverted cone of stone pushed in and out by value noise, faceted",
        ),
        (
            "sphere",
            sphere(),
            SPHERE_MTL,
            "the seed's low-poly sphere, 1 m (chapter 10): 10 × 6 flat facets, glossy paint",
        ),
    ]
}

/// The provenance table's rows for these files.
pub fn provenance() -> String {
    models()
        .iter()
        .map(|(name, _, _, what)| {
            format!(
                "| `models/{name}/{name}.{{obj,mtl}}` | {what} | built from code in `xtask/src/assets/models.rs` |\n"
            )
        })
        .collect()
}

/// Writes every model and its materials under `dir`.
pub fn write(dir: &Path) -> anyhow::Result<()> {
    for (name, obj, mtl, _) in models() {
        let folder = dir.join(name);
        std::fs::create_dir_all(&folder)?;
        let obj_path = folder.join(format!("{name}.obj"));
        std::fs::write(&obj_path, obj).map_err(|e| anyhow::anyhow!("cannot write {}: {e}", obj_path.display()))?;
        let mtl_path = folder.join(format!("{name}.mtl"));
        std::fs::write(&mtl_path, mtl).map_err(|e| anyhow::anyhow!("cannot write {}: {e}", mtl_path.display()))?;
        println!("wrote {} and {}", obj_path.display(), mtl_path.display());
    }
    Ok(())
}

/// A sphere of about a million triangles (708 × 708 quads), for measuring
/// how big models load; not committed, written where the bench asks.
pub fn million_triangles(path: &Path) -> anyhow::Result<()> {
    let (columns, rows) = (708usize, 708usize);
    let mut obj = ObjWriter::new("About a million triangles: a UV sphere, for the chapter 09 bench.", None);
    obj.object("sphere");
    for row in 0..=rows {
        for column in 0..=columns {
            let (u, v) = (column as f32 / columns as f32, row as f32 / rows as f32);
            let (sin_lon, cos_lon) = (std::f32::consts::TAU * u).sin_cos();
            let (sin_lat, cos_lat) = (std::f32::consts::PI * v).sin_cos();
            let n = Vec3::new(sin_lat * sin_lon, cos_lat, sin_lat * cos_lon);
            obj.position(n);
            obj.uv(Vec2::new(u, 1.0 - v));
            obj.normal(if n.length() > 0.0 { n } else { Vec3::Y });
        }
    }
    let index = |column: usize, row: usize| row * (columns + 1) + column + 1;
    for row in 0..rows {
        for column in 0..columns {
            let quad = [index(column, row), index(column, row + 1), index(column + 1, row + 1), index(column + 1, row)];
            let corners: Vec<Corner> =
                quad.iter().map(|&i| Corner { position: i, uv: Some(i), normal: Some(i) }).collect();
            obj.face(&corners, false);
        }
    }
    obj.write(path)
}
