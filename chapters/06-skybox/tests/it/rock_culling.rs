//! Chapter 05's rocks, culled by chunk (here with chapter 06's tests, see
//! `main.rs` for why): the rocks the chapter says it drew, against a count
//! made here from the scatter, chapter 03's chunk boxes and the camera's
//! frustum; and the indirect draw, which must draw the same picture in one call.

use common::book_figures::thousands;
use common::glam::Vec3;
use common::headless::{OFFSCREEN_FORMAT, capture};
use common::{Chapter, Target, wgpu};
use instancing::{InstancingChapter, rock_mesh, rocks_on_map, scatter};
use terrain::chunks::Aabb;
use terrain::culling::Frustum;
use terrain::heightfield::CHUNK_QUADS;

#[test]
fn the_default_view_draws_the_rocks_of_the_chunks_in_view_and_says_how_many() {
    let gpu = crate::plain_gpu();
    let target = Target { format: OFFSCREEN_FORMAT, width: 160, height: 90 };
    let mut chapter: InstancingChapter = common::chapter::create(gpu, target, &Default::default()).unwrap();
    let picture = |chapter: &mut InstancingChapter, name: &str| {
        let view = common::chapter::view_index::<InstancingChapter>(name).unwrap();
        chapter.select_view(view);
        capture(gpu, chapter, target, 0.0, view).unwrap()
    };
    let culled = picture(&mut chapter, "default");
    let calls = chapter.draw_calls;

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
        calls.rocks_drawn,
        calls.rocks
    );
    assert_eq!(rocks.len(), 1_000_000);
    assert_eq!(calls.rocks_drawn, in_view);
    assert!(in_view < 400_000, "most of the map is out of view");
    // And the bench's line says so.
    let line = chapter.stats(gpu);
    let said = format!("{} of 1,000,000 rocks drawn", thousands(in_view.into()));
    assert!(line.contains(&said), "`{line}` should say `{said}`");

    // Page 05 quotes the default view's figures.
    let page =
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../../book/src/05-instancing.md")).unwrap();
    for figure in [
        format!("**{} of the 1,000,000 rocks**", thousands(in_view.into())),
        format!("**in {} calls**", calls.rocks),
        format!("{} of the 4,096\ngroups", thousands(calls.rock_groups.into())),
    ] {
        assert!(page.contains(&figure), "page 05 should say `{figure}`");
    }

    // The same runs, drawn by one indirect call, are the same picture.
    let indirect = picture(&mut chapter, "multi-draw");
    assert_eq!(chapter.draw_calls.rocks_drawn, in_view);
    if gpu.device.features().contains(wgpu::Features::INDIRECT_FIRST_INSTANCE) {
        assert_eq!(chapter.draw_calls.rocks, 1);
    }
    assert_eq!(indirect, culled, "one indirect call draws what the runs drew");
}
