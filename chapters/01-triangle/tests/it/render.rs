//! The triangle renders where it should, at any size.

use common::headless::{RenderRequest, render_image};
use common::{Gpu, GpuNeeds};
use triangle::Triangle;

#[test]
fn triangle_covers_the_centre_and_not_the_corners() {
    let gpu = Gpu::headless(GpuNeeds::default()).expect("an adapter (lavapipe will do)");
    // An odd width exercises the readback's row padding.
    let image = render_image::<Triangle>(&gpu, &RenderRequest { width: 201, height: 101, time: 0.0, view: 0 }).unwrap();
    let background = *image.get_pixel(0, 0);
    for (x, y) in [(200, 0), (0, 100), (200, 100)] {
        assert_eq!(*image.get_pixel(x, y), background, "corner ({x}, {y})");
    }
    let centre = image.get_pixel(100, 50);
    assert_ne!(*centre, background);
    // Near the top vertex the colour is mostly red, near the bottom-left mostly green.
    let top = image.get_pixel(100, 20);
    assert!(top[0] > top[1] && top[0] > top[2], "{top:?}");
    let left = image.get_pixel(40, 75);
    assert!(left[1] > left[0] && left[1] > left[2], "{left:?}");
}

#[test]
fn flat_view_is_one_colour() {
    let gpu = Gpu::headless(GpuNeeds::default()).expect("an adapter (lavapipe will do)");
    let image = render_image::<Triangle>(&gpu, &RenderRequest { width: 160, height: 90, time: 0.0, view: 1 }).unwrap();
    let background = *image.get_pixel(0, 0);
    let mut colours: Vec<_> = image.pixels().filter(|p| **p != background).collect();
    // The triangle must be there: 1.4 wide at its base and 1.3 tall in clip
    // units, 0.91 of the 4 square units the picture spans, so 22.75 % of
    // its 14,400 pixels (3,276). The rasteriser covers the pixels whose
    // centres are inside; the edges, about 270 pixels long, can only move
    // that count by a few dozen pixels on any rasteriser: 1 %.
    let covered = colours.len();
    eprintln!("the flat triangle covers {covered} pixels");
    assert!(covered.abs_diff(3276) <= 33, "{covered} pixels covered, not 3,276");
    colours.dedup();
    // Anti-aliasing is off, so every covered pixel is exactly the first vertex's red.
    assert!(colours.iter().all(|p| p.0 == [255, 0, 0, 255]), "{:?}", &colours[..3.min(colours.len())]);
}
