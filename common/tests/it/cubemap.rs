//! A bad cube face is reported by its file name and the reason.

use common::texture::{ColorSpace, cubemap};
use common::{Gpu, GpuNeeds};

fn png(width: u32, height: u32) -> Vec<u8> {
    let mut bytes = Vec::new();
    common::image::RgbaImage::new(width, height)
        .write_to(&mut std::io::Cursor::new(&mut bytes), common::image::ImageFormat::Png)
        .unwrap();
    bytes
}

#[test]
fn corrupt_and_misshapen_faces_are_named() {
    let gpu = Gpu::headless(GpuNeeds::default()).expect("an adapter (lavapipe will do)");
    let good = png(8, 8);
    let names = ["px.png", "nx.png", "py.png", "ny.png", "pz.png", "nz.png"];
    let faces = |bad: usize, bytes: &'static [u8]| {
        std::array::from_fn::<(&str, &[u8]), 6, _>(|i| (names[i], if i == bad { bytes } else { good.as_slice() }))
    };
    assert!(cubemap(&gpu.device, &gpu.queue, &faces(9, b""), ColorSpace::Srgb).is_ok());

    let error =
        cubemap(&gpu.device, &gpu.queue, &faces(2, b"\x89PNG\r\n\x1a\nbroken"), ColorSpace::Srgb).err().unwrap();
    assert!(format!("{error:#}").contains("py.png is not a readable PNG or JPEG"), "{error:#}");

    let wide: &'static [u8] = Box::leak(png(8, 4).into_boxed_slice());
    let error = cubemap(&gpu.device, &gpu.queue, &faces(4, wide), ColorSpace::Srgb).err().unwrap();
    assert!(error.to_string().contains("pz.png is 8x4, but cube faces must all be 8x8"), "{error}");
}
