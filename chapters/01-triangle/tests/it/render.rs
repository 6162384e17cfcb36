//! The triangle renders where it should, at any size.

use common::headless::{RenderRequest, render_image};
use common::{Gpu, GpuNeeds};
use triangle::Triangle;

#[test]
fn triangle_covers_the_centre_and_not_the_corners() {
    let gpu = Gpu::headless(GpuNeeds::default()).expect("an adapter (lavapipe will do)");
    // An odd width exercises the readback's row padding.
    let image = render_image::<Triangle>(
        &gpu,
        &RenderRequest {
            width: 201,
            height: 101,
            time: 0.0,
            view: 0,
            camera: None,
            antialiasing: common::Antialiasing::Off,
        },
    )
    .unwrap();
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
    let image = render_image::<Triangle>(
        &gpu,
        &RenderRequest {
            width: 160,
            height: 90,
            time: 0.0,
            view: common::chapter::view_index::<Triangle>("flat").unwrap(),
            camera: None,
            antialiasing: common::Antialiasing::Off,
        },
    )
    .unwrap();
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

/// The overlay and the bench say the frame drew one triangle, in one draw,
/// in the pass the timer knows as `triangle`: the vertex buffer's corners
/// (`TRIANGLE`), three to a triangle, are the independent count.
#[test]
fn one_frame_draws_one_triangle() {
    use common::headless::{OFFSCREEN_FORMAT, Offscreen, draw_frame};
    use common::{Drawn, PassCount, PassTimer, Target};
    let gpu = Gpu::headless(GpuNeeds::default()).expect("an adapter (lavapipe will do)");
    let target = Target { format: OFFSCREEN_FORMAT, width: 64, height: 64, samples: 1 };
    let mut chapter = common::chapter::create::<Triangle>(&gpu, target, &Default::default()).unwrap();
    let offscreen = Offscreen::new(&gpu.device, target);
    let timer = PassTimer::off();
    let drawn = draw_frame(&gpu, &mut chapter, &offscreen.view, (0.0, 0), Default::default(), &timer);
    let triangles = (triangle::vertex::TRIANGLE.len() / 3) as u64;
    assert_eq!(triangles, 1);
    assert_eq!(drawn, [PassCount { pass: "triangle", drawn: Drawn::counted(1, triangles) }]);
    assert_eq!(timer.take_labels(), ["triangle"], "counted under the name the pass is timed by");
}

/// The triangle has no camera: `--camera` is a usage error (exit code 2)
/// that names the chapter, not a flag quietly ignored.
#[test]
fn a_chapter_without_a_camera_refuses_the_camera_flag() {
    let gpu = Gpu::headless(GpuNeeds::default()).expect("an adapter (lavapipe will do)");
    let place = "1,2,3,45,-10".parse().unwrap();
    let request = RenderRequest {
        width: 16,
        height: 16,
        time: 0.0,
        view: 0,
        camera: Some(place),
        antialiasing: common::Antialiasing::Off,
    };
    let error = render_image::<Triangle>(&gpu, &request).unwrap_err();
    assert!(error.is::<common::args::UsageError>(), "{error:#}");
    let text = format!("{error:#}");
    assert!(text.starts_with("--camera 1.00,2.00,3.00,45.00,-10.00: the triangle chapter has no camera"), "{text}");
    assert!(!text.contains('\n'), "one line: {text}");
}

/// Bad `--camera` values are refused while the flags are read, before any
/// GPU work, with clap's one-line error naming the flag and what it takes;
/// a place starting with a minus sign is a value, not a flag; `--help`
/// lists the flag.
#[test]
fn the_camera_flag_is_checked_with_the_others() {
    use common::args::Args;
    let parse = |value: &str| Args::parse_from_for::<Triangle>(["triangle", "--camera", value]);
    for (value, says) in [
        ("1,2,3", "3 values given; expected X,Y,Z,YAW,PITCH"),
        ("1,2,x,4,5", "Z 'x' is not a number"),
        ("1,2,3,NaN,5", "YAW is NaN, not a finite number"),
        ("0,10,0,0,-90", "PITCH -90° is steeper than ±89.99°"),
    ] {
        let error = parse(value).unwrap_err().to_string();
        let first = error.lines().next().unwrap_or_default();
        assert!(first.contains("--camera <X,Y,Z,YAW,PITCH>") && first.contains(says), "{value}: {error}");
    }
    let place = parse("-5,1.5,20,-135,-30").unwrap().camera.expect("a place");
    assert_eq!(place.position, common::glam::Vec3::new(-5.0, 1.5, 20.0));
    let help = Args::parse_from_for::<Triangle>(["triangle", "--help"]).unwrap_err().to_string();
    assert!(help.contains("--camera <X,Y,Z,YAW,PITCH>"), "{help}");
}

/// `--antialiasing` offers the post-process pass only in chapters that
/// have a post chain (08 to 11): here `post` is an error that names the
/// values this chapter takes.
#[test]
fn the_antialiasing_flag_names_the_values_this_chapter_takes() {
    use common::args::Args;
    let parse = |value: &str| Args::parse_from_for::<Triangle>(["triangle", "--antialiasing", value]);
    assert_eq!(parse("off").unwrap().antialiasing, common::Antialiasing::Off);
    let error = parse("post").unwrap_err().to_string();
    assert!(error.contains("invalid value 'post'") && error.contains("[possible values: off, msaa]"), "{error}");
}
