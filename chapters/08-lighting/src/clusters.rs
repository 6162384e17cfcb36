//! Clustered light culling: the view is cut into a grid of clusters (screen
//! tiles × slices of depth), and each cluster gets the list of the lights
//! that can reach it. A fragment loops over its cluster's list, not over
//! every light. The lists are built on the CPU each frame.

use common::Camera;
use common::glam::{Mat4, Vec3, Vec4Swizzles};

use crate::lights::{Light, LightKind};

// ANCHOR: grid
/// Clusters across, down, and deep: tiles of 20 × 20 pixels at 1280 × 720;
/// depth slices that grow with distance (each about 17 % deeper than the
/// one before), so that every cluster has the same proportions near and
/// far: about five times as deep as it is wide.
pub const GRID: [u32; 3] = [64, 36, 48];
pub const CLUSTERS: usize = (GRID[0] * GRID[1] * GRID[2]) as usize;

/// The depth slice a view-space distance falls in: slices are spaced
/// evenly in log(depth), from the near plane to the far plane.
pub fn slice(depth: f32, near: f32, far: f32) -> i32 {
    ((depth / near).ln() / (far / near).ln() * GRID[2] as f32).floor() as i32
}

/// The cluster a world position falls in, seen by `camera`, or `None` if it
/// is outside the view (then a shader loops over every light). The same
/// arithmetic as `cluster_at` in lights.wgsl.
pub fn cluster_of(camera: &Camera, world: Vec3) -> Option<usize> {
    let clip = camera.view_projection() * world.extend(1.0);
    let depth = -(camera.view() * world.extend(1.0)).z;
    if clip.w <= 0.0 || depth < camera.near || depth > camera.far {
        return None;
    }
    let ndc = clip.xy() / clip.w;
    if ndc.x.abs() > 1.0 || ndc.y.abs() > 1.0 {
        return None;
    }
    let x = (((ndc.x + 1.0) * 0.5 * GRID[0] as f32) as u32).min(GRID[0] - 1);
    let y = (((1.0 - ndc.y) * 0.5 * GRID[1] as f32) as u32).min(GRID[1] - 1);
    let z = slice(depth, camera.near, camera.far).clamp(0, GRID[2] as i32 - 1) as u32;
    Some(((z * GRID[1] + y) * GRID[0] + x) as usize)
}
// ANCHOR_END: grid

// ANCHOR: cull
/// For each cluster, where its list starts in `indices` and how long it is;
/// lists hold light indices in increasing order.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct ClusterLists {
    pub ranges: Vec<[u32; 2]>,
    pub indices: Vec<u32>,
}

// ANCHOR: cull_lists
/// Builds every cluster's list. Each light is tested against the clusters
/// inside the box its sphere of influence projects to (the depth slices its
/// sphere spans, and the tiles its bounding box covers, cut off at the near
/// plane so that every corner projects), and listed in those it may reach:
/// where the cluster's box comes within its range and, for a spot light,
/// reaches in front of it. Conservative: never left out where it shines.
pub fn cull(camera: &Camera, lights: &[Light]) -> ClusterLists {
    let view = camera.view();
    let projection = camera.projection();
    let boxes = cluster_boxes(camera);
    let mut listed: Vec<Vec<u32>> = Vec::with_capacity(lights.len());
    let mut counts = vec![0u32; CLUSTERS];
    for light in lights {
        let mut clusters = Vec::new();
        if let Some([xs, ys, zs]) = light_span(&view, &projection, camera, light) {
            let centre = view.transform_point3(light.position);
            let facing = match light.kind {
                LightKind::Point => None,
                LightKind::Spot { direction, .. } => Some(view.transform_vector3(direction)),
            };
            for z in zs {
                for y in ys.clone() {
                    for x in xs.clone() {
                        let cluster = ((z * GRID[1] + y) * GRID[0] + x) as usize;
                        if reaches(centre, light.range, facing, &boxes[cluster]) {
                            counts[cluster] += 1;
                            clusters.push(cluster as u32);
                        }
                    }
                }
            }
        }
        listed.push(clusters);
    }
    // Prefix sums: where each cluster's list starts.
    let mut ranges = Vec::with_capacity(CLUSTERS);
    let mut start = 0;
    for count in &counts {
        ranges.push([start, 0]);
        start += count;
    }
    let mut indices = vec![0u32; start as usize];
    for (light, clusters) in listed.iter().enumerate() {
        for &cluster in clusters {
            let range = &mut ranges[cluster as usize];
            indices[(range[0] + range[1]) as usize] = light as u32;
            range[1] += 1;
        }
    }
    ClusterLists { ranges, indices }
}

/// Whether a light at `centre` (view space) with `range` can reach into a
/// cluster's box: the box comes within the range of the centre, and, for a
/// spot light facing `facing`, some of the box lies in front of it (behind
/// a spot, its cone factor is exactly zero).
fn reaches(centre: Vec3, range: f32, facing: Option<Vec3>, (low, high): &(Vec3, Vec3)) -> bool {
    let nearest = centre.clamp(*low, *high);
    if nearest.distance_squared(centre) >= range * range {
        return false;
    }
    facing.is_none_or(|axis| {
        // The box's corner furthest along the axis, measured from the light.
        let corner = Vec3::select(axis.cmpge(Vec3::ZERO), *high, *low);
        axis.dot(corner - centre) > 0.0
    })
}
// ANCHOR_END: cull_lists

/// The clusters (x, y and z ranges) a light's sphere of influence may
/// touch, or `None` if it is outside the view altogether.
fn light_span(view: &Mat4, projection: &Mat4, camera: &Camera, light: &Light) -> Option<[std::ops::Range<u32>; 3]> {
    let centre = view.transform_point3(light.position);
    let (depth, r) = (-centre.z, light.range);
    if depth + r < camera.near || depth - r > camera.far {
        return None;
    }
    let z0 = slice((depth - r).max(camera.near), camera.near, camera.far).clamp(0, GRID[2] as i32 - 1) as u32;
    let z1 = slice((depth + r).min(camera.far), camera.near, camera.far).clamp(0, GRID[2] as i32 - 1) as u32;
    // The sphere's box in view space, without the part behind the near
    // plane (view space looks down −z, so "in front" is z < −near).
    let (near_z, far_z) = ((centre.z + r).min(-camera.near), centre.z - r);
    let (mut low, mut high) = (Vec3::splat(f32::INFINITY), Vec3::splat(f32::NEG_INFINITY));
    for corner in 0..8 {
        let x = centre.x + if corner & 1 == 0 { -r } else { r };
        let y = centre.y + if corner & 2 == 0 { -r } else { r };
        let z = if corner & 4 == 0 { near_z } else { far_z };
        let clip = *projection * Vec3::new(x, y, z).extend(1.0);
        let ndc = clip.xyz() / clip.w;
        low = low.min(ndc);
        high = high.max(ndc);
    }
    if high.x < -1.0 || low.x > 1.0 || high.y < -1.0 || low.y > 1.0 {
        return None;
    }
    let tile = |v: f32, n: u32| ((v.clamp(0.0, 0.999_999) * n as f32) as u32).min(n - 1);
    let (x0, x1) = (tile((low.x + 1.0) * 0.5, GRID[0]), tile((high.x + 1.0) * 0.5, GRID[0]));
    // Rows count down from the top of the screen, where y is +1.
    let (y0, y1) = (tile((1.0 - high.y) * 0.5, GRID[1]), tile((1.0 - low.y) * 0.5, GRID[1]));
    Some([x0..x1 + 1, y0..y1 + 1, z0..z1 + 1])
}
/// Every cluster's bounding box in view space, in cluster order.
fn cluster_boxes(camera: &Camera) -> Vec<(Vec3, Vec3)> {
    let (tan_y, tan_x) = ((camera.fov_y / 2.0).tan(), (camera.fov_y / 2.0).tan() * camera.aspect);
    let depth_at = |s: u32| camera.near * (camera.far / camera.near).powf(s as f32 / GRID[2] as f32);
    let mut boxes = Vec::with_capacity(CLUSTERS);
    for z in 0..GRID[2] {
        let (near, far) = (depth_at(z), depth_at(z + 1));
        for y in 0..GRID[1] {
            // NDC y runs up, tile rows run down.
            let (top, bottom) = (1.0 - 2.0 * y as f32 / GRID[1] as f32, 1.0 - 2.0 * (y + 1) as f32 / GRID[1] as f32);
            for x in 0..GRID[0] {
                let (left, right) =
                    (-1.0 + 2.0 * x as f32 / GRID[0] as f32, -1.0 + 2.0 * (x + 1) as f32 / GRID[0] as f32);
                let mut low = Vec3::splat(f32::INFINITY);
                let mut high = Vec3::splat(f32::NEG_INFINITY);
                for depth in [near, far] {
                    for (nx, ny) in [(left, top), (right, top), (left, bottom), (right, bottom)] {
                        let corner = Vec3::new(nx * depth * tan_x, ny * depth * tan_y, -depth);
                        low = low.min(corner);
                        high = high.max(corner);
                    }
                }
                boxes.push((low, high));
            }
        }
    }
    boxes
}
// ANCHOR_END: cull

#[cfg(test)]
mod tests {
    use super::*;
    use crate::lights::LightKind;
    use common::rng::Rng;

    fn camera() -> Camera {
        Camera {
            near: 0.5,
            far: 800.0,
            ..Camera::looking_at(Vec3::new(0.0, 20.0, 120.0), Vec3::new(10.0, 0.0, 0.0), 16.0 / 9.0)
        }
    }

    /// `count` lights over the city's square, ranges up to `max_range`
    /// metres; every third a spot light pointing some way or other.
    fn lights(count: usize, max_range: f32) -> Vec<Light> {
        let mut rng = Rng::new(3);
        (0..count)
            .map(|i| {
                let direction = Vec3::new(rng.range(-1.0, 1.0), rng.range(-1.0, 0.5), rng.range(-1.0, 1.0));
                let outer = rng.range(0.3, 1.4);
                Light {
                    position: Vec3::new(rng.range(-150.0, 150.0), rng.range(0.0, 40.0), rng.range(-150.0, 150.0)),
                    colour: Vec3::ONE,
                    range: rng.range(3.0, max_range),
                    kind: if i % 3 == 0 {
                        LightKind::Spot { direction: direction.normalize(), inner: outer * 0.6, outer }
                    } else {
                        LightKind::Point
                    },
                }
            })
            .collect()
    }

    // ANCHOR: culling_test
    /// The guarantee culling rests on: wherever a light can reach a point
    /// the camera sees, that light is in the point's cluster list.
    #[test]
    fn every_light_that_reaches_a_visible_point_is_in_its_cluster() {
        let (camera, lights) = (camera(), lights(300, 40.0));
        let lists = cull(&camera, &lights);
        let mut rng = Rng::new(11);
        let mut checked = 0;
        for _ in 0..20_000 {
            let point = Vec3::new(rng.range(-160.0, 160.0), rng.range(0.0, 50.0), rng.range(-160.0, 160.0));
            let Some(cluster) = cluster_of(&camera, point) else { continue };
            let [start, count] = lists.ranges[cluster];
            let listed = &lists.indices[start as usize..(start + count) as usize];
            for (i, light) in lights.iter().enumerate() {
                if light.reaching(point).length() > 0.0 {
                    assert!(listed.contains(&(i as u32)), "light {i} reaches {point} but is not in cluster {cluster}");
                    checked += 1;
                }
            }
        }
        assert!(checked > 1000, "only {checked} light–point pairs checked");
    }
    // ANCHOR_END: culling_test

    #[test]
    fn lists_are_in_increasing_order_and_far_shorter_than_all_lights() {
        // Lamp-like ranges: about one light reaches any given point.
        let lights = lights(1000, 15.0);
        let lists = cull(&camera(), &lights);
        let mut longest = 0;
        for [start, count] in &lists.ranges {
            let list = &lists.indices[*start as usize..(*start + *count) as usize];
            assert!(list.windows(2).all(|w| w[0] < w[1]), "a list out of order");
            longest = longest.max(list.len());
        }
        let average = lists.indices.len() as f32 / CLUSTERS as f32;
        assert!(average < 10.0 && longest < 100, "average {average}, longest {longest} of 1000 lights");
    }

    #[test]
    fn slices_cover_near_to_far_in_order() {
        let (near, far) = (0.5, 800.0);
        assert_eq!(slice(near, near, far), 0);
        assert_eq!(slice(far * 0.9999, near, far), GRID[2] as i32 - 1);
        let mut last = 0;
        for i in 0..1000 {
            let s = slice(near + i as f32, near, far);
            assert!(s >= last);
            last = s;
        }
    }

    #[test]
    fn points_behind_the_camera_or_off_screen_have_no_cluster() {
        let camera = camera();
        assert!(cluster_of(&camera, camera.position - camera.forward() * 10.0).is_none());
        assert!(cluster_of(&camera, camera.position + camera.right() * 1000.0).is_none());
        assert!(cluster_of(&camera, camera.position + camera.forward() * 50.0).is_some());
    }
}
