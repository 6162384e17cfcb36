//! The rocks grouped by terrain chunk: each chunk's rocks side by side in
//! the instance buffer, the groups stored nearest the start first, and the
//! runs of instances that a camera's frustum keeps (chapter 03's culling,
//! applied to the rocks).

use std::ops::Range;

use common::glam::{Vec2, Vec3};
use terrain::chunks::Aabb;
use terrain::culling::Frustum;
use terrain::heightfield::{CHUNK_QUADS, TerrainSettings};

use crate::rock_scatter::RockInstance;

/// One terrain chunk's rocks: where they lie in the instance buffer, and
/// the chunk's box grown so that it holds every one of them.
#[derive(Clone, Debug, PartialEq)]
pub struct RockGroup {
    /// The chunk's index, `cz × chunks_per_side + cx`, as chapter 03 numbers them.
    pub chunk: u32,
    pub instances: Range<u32>,
    pub bounds: Aabb,
}

/// The index of the chunk that world position (x, z) lies in; positions
/// off the map count in the nearest chunk on its edge.
pub fn chunk_of(settings: &TerrainSettings, x: f32, z: f32) -> u32 {
    let n = settings.chunks_per_side;
    let size = CHUNK_QUADS as f32 * settings.spacing;
    let cell = |v: f32| ((v / size).floor().max(0.0) as u32).min(n - 1);
    cell(z) * n + cell(x)
}

// ANCHOR: group_by_chunk
/// `rocks` sorted into one group per chunk of `chunk_bounds` (chapter 03's
/// boxes, row by row), each group's rocks side by side and in the order
/// the scatter made them. The groups are stored nearest `start` first, so
/// that the first n rocks of the buffer, which the rock-count slider draws,
/// are a disc of the plain around the start rather than a strip along the
/// map's far edge. Each chunk's box grows by `reach`, the most a rock
/// sticks out from where it stands, so no part of a rock lies outside its
/// group's box.
pub fn group_by_chunk(
    rocks: &[RockInstance],
    settings: &TerrainSettings,
    chunk_bounds: &[Aabb],
    reach: f32,
    start: Vec3,
) -> (Vec<RockInstance>, Vec<RockGroup>) {
    let centre = |chunk: u32| {
        let b = chunk_bounds[chunk as usize];
        Vec2::new(b.min.x + b.max.x, b.min.z + b.max.z) * 0.5
    };
    let from_start = |chunk: u32| centre(chunk).distance_squared(Vec2::new(start.x, start.z));
    let mut order: Vec<u32> = (0..chunk_bounds.len() as u32).collect();
    order.sort_by(|&a, &b| from_start(a).total_cmp(&from_start(b)).then(a.cmp(&b)));

    let mut by_chunk = vec![Vec::new(); chunk_bounds.len()];
    for rock in rocks {
        by_chunk[chunk_of(settings, rock.position[0], rock.position[2]) as usize].push(*rock);
    }
    let mut sorted = Vec::with_capacity(rocks.len());
    let grow = Vec3::splat(reach);
    let groups = order
        .into_iter()
        .map(|chunk| {
            let first = sorted.len() as u32;
            sorted.extend_from_slice(&by_chunk[chunk as usize]);
            let b = chunk_bounds[chunk as usize];
            RockGroup {
                chunk,
                instances: first..sorted.len() as u32,
                bounds: Aabb { min: b.min - grow, max: b.max + grow },
            }
        })
        .collect();
    (sorted, groups)
}
// ANCHOR_END: group_by_chunk

/// What one picture draws of the rocks.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct RockRuns {
    /// Ranges of instances, one instanced draw each: the kept groups, with
    /// groups next to each other in the buffer joined into one range.
    pub runs: Vec<Range<u32>>,
    /// Rocks in the runs.
    pub rocks: u32,
    /// Groups with rocks in the runs.
    pub groups: u32,
}

// ANCHOR: visible_runs
/// The instances to draw of the first `count` rocks in the buffer: those of
/// every group whose box `frustum` keeps (chapter 03's test, as for the
/// terrain's chunks), or all of them when there is no frustum.
pub fn visible_runs(groups: &[RockGroup], count: u32, frustum: Option<&Frustum>) -> RockRuns {
    let mut drawn = RockRuns::default();
    for group in groups {
        let run = group.instances.start..group.instances.end.min(count);
        if run.is_empty() || frustum.is_some_and(|f| !f.intersects(&group.bounds)) {
            continue;
        }
        drawn.rocks += run.len() as u32;
        drawn.groups += 1;
        match drawn.runs.last_mut() {
            Some(last) if last.end == run.start => last.end = run.end,
            _ => drawn.runs.push(run),
        }
    }
    drawn
}
// ANCHOR_END: visible_runs

#[cfg(test)]
mod tests {
    use super::*;
    use common::Camera;

    fn rock_at(x: f32, z: f32) -> RockInstance {
        RockInstance { position: [x, 0.0, z], yaw: 0.0, scale: [1.0; 3], shade: 0.5 }
    }

    /// 4 × 4 chunks of 64 m, flat, with a rock in the middle of each of
    /// them, two in chunk 5.
    fn little_world() -> (TerrainSettings, Vec<Aabb>, Vec<RockInstance>) {
        let settings = TerrainSettings { chunks_per_side: 4, ..Default::default() };
        let bounds = (0..16)
            .map(|i| {
                let min = Vec3::new((i % 4) as f32 * 64.0, 0.0, (i / 4) as f32 * 64.0);
                Aabb { min, max: min + Vec3::new(64.0, 1.0, 64.0) }
            })
            .collect();
        let mut rocks: Vec<_> =
            (0..16).map(|i| rock_at((i % 4) as f32 * 64.0 + 32.0, (i / 4) as f32 * 64.0 + 32.0)).collect();
        rocks.push(rock_at(64.0 + 10.0, 64.0 + 10.0));
        (settings, bounds, rocks)
    }

    #[test]
    fn every_rock_lands_in_its_own_chunks_group_nearest_the_start_first() {
        let (settings, bounds, rocks) = little_world();
        // The start is in chunk 5 (x 64..128, z 64..128).
        let (sorted, groups) = group_by_chunk(&rocks, &settings, &bounds, 2.0, Vec3::new(100.0, 0.0, 100.0));
        assert_eq!(sorted.len(), rocks.len());
        assert_eq!(groups[0].chunk, 5, "the start's own chunk comes first");
        assert_eq!(groups[0].instances, 0..2);
        let mut covered = 0;
        for group in &groups {
            assert_eq!(group.instances.start, covered, "groups are side by side");
            covered = group.instances.end;
            for rock in &sorted[group.instances.start as usize..group.instances.end as usize] {
                assert_eq!(chunk_of(&settings, rock.position[0], rock.position[2]), group.chunk);
            }
        }
        assert_eq!(covered as usize, rocks.len());
        // Each group's box is its chunk's, grown by the reach.
        assert_eq!(groups[0].bounds.min, bounds[5].min - Vec3::splat(2.0));
    }

    #[test]
    fn a_frustum_keeps_the_groups_ahead_and_a_count_cuts_the_last_one() {
        let (settings, bounds, rocks) = little_world();
        let (_, groups) = group_by_chunk(&rocks, &settings, &bounds, 2.0, Vec3::new(100.0, 0.0, 100.0));
        // Everything, with no frustum: one run.
        let all = visible_runs(&groups, 100, None);
        assert_eq!((all.runs.len(), all.runs[0].clone(), all.rocks, all.groups), (1, 0..17, 17, 16));
        // The first 3 rocks: chunk 5's two, and one of the next group's.
        let first = visible_runs(&groups, 3, None);
        assert_eq!((first.runs.len(), first.runs[0].clone(), first.rocks, first.groups), (1, 0..3, 3, 2));
        // Standing at the west edge looking east along the first row of
        // chunks (z 0..64), with a narrow view: only that row's groups.
        let mut camera = Camera::looking_at(Vec3::new(-10.0, 0.5, 32.0), Vec3::new(300.0, 0.5, 32.0), 1.0);
        camera.fov_y = 0.2;
        let frustum = Frustum::from_view_projection(camera.view_projection());
        let kept = visible_runs(&groups, 100, Some(&frustum));
        assert_eq!(kept.groups, 4, "{kept:?}");
        assert_eq!(kept.rocks, 4);
        let chunks: Vec<u32> = groups
            .iter()
            .filter(|g| kept.runs.iter().any(|r| r.contains(&g.instances.start)))
            .map(|g| g.chunk)
            .collect();
        let mut chunks = chunks;
        chunks.sort();
        assert_eq!(chunks, [0, 1, 2, 3]);
    }
}
